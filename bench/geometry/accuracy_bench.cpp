// bench/geometry/accuracy_bench.cpp: speed against error on the closed-form pairs
// (docs/ACCURACY.md). Each row builds the whole place vocabulary of one pair and measures:
// the largest boundary error against the closed form (normal distance |f| / |grad f|, and along
// the bracketing axis), how many boundary points got a qualitative normal other than the closed
// form's (sign errors), the wall time (median of `repeats` runs), and the place counts.
// Table 1: the exact contact function as oracle, boundary tolerance varied (bisection only).
// Table 2: the parts' arcs tessellated, exact 2-D polygon oracle, chordal tolerance varied.
// Table 3: FCL in the loop (geometry/fcl_pair_oracle.hpp): the parts drawn with lines and arcs,
//          meshed at a chordal tolerance, boundary tolerance 1e-9; chordal tolerance varied.
// Table 4: FCL, chordal tolerance 1e-7, boundary tolerance varied.
// Usage: geometry_accuracy_bench [plot.svg] [repeats]
#include "geometry/closed_form_pairs.hpp"
#include "geometry/fcl_pair_oracle.hpp"
#include "geometry/place_vocabulary_builder.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <vector>

using namespace qm::geometry;

namespace {

enum class Kind { bisection, polygon, fcl };

struct Row {
    std::string pair;
    Kind kind = Kind::bisection;
    double tess = 0, tol = 0, normal_err = 0, axis_err = 0, ms = 0;
    std::size_t sign_errors = 0, points = 0, places = 0, csegs = 0, joins = 0, faces = 0;
};

Row run(const ClosedFormPair& c, const PairOracle& oracle, Kind kind, double tess, double tol, int repeats) {
    PlaceRequest req;
    req.cspace.axes = c.axes;
    req.cspace.boundary_tolerance = tol;
    std::vector<double> times;
    PlaceResult res;
    for (int i = 0; i < repeats; ++i) {
        const auto t0 = std::chrono::steady_clock::now();
        res = build_place_vocabulary(oracle, req);
        const auto t1 = std::chrono::steady_clock::now();
        times.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
    }
    std::sort(times.begin(), times.end());
    Row row{c.name, kind, tess, tol, 0, 0, times[times.size() / 2], 0, res.space.boundary.size(), res.vocabulary.places.size(),
            res.vocabulary.count(PlaceKind::cseg), res.vocabulary.count(PlaceKind::join), res.vocabulary.count(PlaceKind::face)};
    for (const auto& p : res.space.boundary) {
        row.normal_err = std::max(row.normal_err, c.exact.normal_distance(p.q));
        row.axis_err = std::max(row.axis_err, c.exact.crossing_error(p.q, p.axis));
        if (p.qual != qualitative(c.exact.free_normal(p.q).normalized(), req.cspace.normal_zero_tolerance)) ++row.sign_errors;
    }
    return row;
}

void print(const std::vector<Row>& rows) {
    std::cout << "| pair | chordal tol | boundary tol | max normal error | max along-axis error | sign errors / points | time ms | places | CSEGs | joins | faces |\n"
              << "|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& r : rows) {
        std::cout << "| " << r.pair << " | ";
        if (r.tess > 0) std::cout << std::setprecision(0) << std::scientific << r.tess;
        else std::cout << "exact";
        std::cout << " | " << std::setprecision(0) << std::scientific << r.tol << " | " << std::setprecision(2) << r.normal_err << " | " << r.axis_err << " | "
                  << r.sign_errors << " / " << r.points << " | " << std::fixed << std::setprecision(1) << r.ms << " | " << r.places << " | "
                  << r.csegs << " | " << r.joins << " | " << r.faces << " |\n";
    }
}

// Log-log plot: max normal error against the tolerance setting varied (boundary tolerance for
// bisection-only and the FCL boundary sweep, chordal tolerance for tessellation). Solid:
// bisection only; dashed: exact polygon oracle on the tessellation; dotted: FCL. The grey
// diagonal is error = setting.
void plot(const std::vector<Row>& rows, const std::vector<int>& series_ends, const std::string& path) {
    std::ofstream os(path);
    const double W = 680, H = 440, m = 60;
    auto X = [&](double setting) { return m + (W - 2 * m) * (std::log10(setting) + 13) / 12; };        // 1e-13 .. 1e-1
    auto Y = [&](double e) { return H - m - (H - 2 * m) * (std::log10(std::max(e, 1e-14)) + 14) / 13; };  // 1e-14 .. 1e-1
    os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\">\n"
       << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<rect x=\"" << m << "\" y=\"" << m << "\" width=\"" << W - 2 * m
       << "\" height=\"" << H - 2 * m << "\" fill=\"none\" stroke=\"black\"/>\n";
    for (int e = -14; e <= -1; e += 2) os << "<text x=\"5\" y=\"" << Y(std::pow(10, e)) + 4 << "\" font-size=\"10\">1e" << e << "</text>\n";
    for (int t = -13; t <= -1; t += 2) os << "<text x=\"" << X(std::pow(10, t)) - 10 << "\" y=\"" << H - m + 15 << "\" font-size=\"10\">1e" << t << "</text>\n";
    os << "<line x1=\"" << X(1e-13) << "\" y1=\"" << Y(1e-13) << "\" x2=\"" << X(1e-1) << "\" y2=\"" << Y(1e-1) << "\" stroke=\"#aaaaaa\"/>\n";
    os << "<text x=\"" << W / 2 - 150 << "\" y=\"" << H - 15 << "\" font-size=\"12\">tolerance setting varied (boundary or chordal)</text>\n"
       << "<text x=\"" << m << "\" y=\"22\" font-size=\"12\">max boundary error (normal distance), per pair</text>\n"
       << "<text x=\"" << m << "\" y=\"40\" font-size=\"11\">solid: bisection only; dashed: polygon oracle, chordal; dotted: FCL, chordal; dash-dot: FCL, boundary</text>\n";
    const char* colours[] = {"#c00000", "#0060c0", "#008000", "#a000a0"};
    std::size_t k = 0;
    for (std::size_t s = 0; s < series_ends.size(); ++s) {
        const std::size_t end = static_cast<std::size_t>(series_ends[s]);
        const auto& first = rows[k];
        const int c = first.pair == "bar-and-block" ? 0 : first.pair == "disk-cam-and-follower" ? 1 : first.pair == "two-disks" ? 2 : 3;
        const bool chordal_axis = first.kind != Kind::bisection && first.tess != rows[end - 1].tess;
        const char* dash = first.kind == Kind::bisection ? "" : first.kind == Kind::polygon ? " stroke-dasharray=\"6,3\"" : chordal_axis ? " stroke-dasharray=\"2,2\"" : " stroke-dasharray=\"8,3,2,3\"";
        os << "<polyline fill=\"none\" stroke=\"" << colours[c] << "\"" << dash << " points=\"";
        for (std::size_t i = k; i < end; ++i) os << X(chordal_axis ? rows[i].tess : rows[i].tol) << ',' << Y(rows[i].normal_err) << ' ';
        os << "\"/>\n";
        if (first.kind == Kind::bisection)
            os << "<text x=\"" << X(rows[end - 1].tol) + 4 << "\" y=\"" << Y(rows[end - 1].normal_err) + (c - 1.5) * 9 << "\" font-size=\"9\" fill=\""
               << colours[c] << "\">" << first.pair << "</text>\n";
        k = end;
    }
    os << "</svg>\n";
}

}  // namespace

int main(int argc, char** argv) {
    const int repeats = argc > 2 ? std::max(1, std::atoi(argv[2])) : 3;
    const std::vector<ClosedFormPair> pairs = {bar_and_block(), disk_cam_and_follower(), two_disks(), pin_in_slot()};
    std::vector<Row> all;
    std::vector<int> ends;
    auto table = [&](const char* title, auto body) {
        std::cout << "\n## " << title << "\n\n";
        std::vector<Row> rows;
        for (const auto& c : pairs) {
            body(c, rows);
            ends.push_back(static_cast<int>(all.size() + rows.size()));
        }
        print(rows);
        all.insert(all.end(), rows.begin(), rows.end());
    };
    std::cout << "64 x 64 grid; time is the median of " << repeats << " runs of the whole place vocabulary\n";
    table("Bisection only (the exact contact function as oracle)", [&](const ClosedFormPair& c, std::vector<Row>& rows) {
        for (double tol : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) rows.push_back(run(c, c.exact, Kind::bisection, 0, tol, repeats));
    });
    table("Tessellation, exact 2-D polygon oracle (boundary tolerance 1e-9)", [&](const ClosedFormPair& c, std::vector<Row>& rows) {
        for (double tess : {1e-2, 1e-3, 1e-4, 1e-5}) {
            const auto oracle = c.tessellated(tess);
            rows.push_back(run(c, oracle, Kind::polygon, tess, 1e-9, repeats));
        }
    });
    table("FCL: parts meshed at a chordal tolerance (boundary tolerance 1e-9)", [&](const ClosedFormPair& c, std::vector<Row>& rows) {
        for (double tess : {1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7}) {
            const FclPairOracle oracle(c.parts[0], c.parts[1], tess);
            rows.push_back(run(c, oracle, Kind::fcl, tess, 1e-9, repeats));
        }
    });
    table("FCL: chordal tolerance 1e-7, boundary tolerance varied", [&](const ClosedFormPair& c, std::vector<Row>& rows) {
        const FclPairOracle oracle(c.parts[0], c.parts[1], 1e-7);
        for (double tol : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10}) rows.push_back(run(c, oracle, Kind::fcl, 1e-7, tol, repeats));
    });
    if (argc > 1) plot(all, ends, argv[1]);
}
