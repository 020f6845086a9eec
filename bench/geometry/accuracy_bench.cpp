// bench/geometry/accuracy_bench.cpp: speed against error on the closed-form pairs (issue item 6).
// Table 1: the exact contact function as oracle, boundary tolerance varied (bisection error only).
// Table 2: the pairs tessellated to a chordal tolerance, exact 2-D polygon oracle, boundary
// tolerance 1e-9 (tessellation error dominates). Each row: largest boundary error (normal
// distance |f|/|grad f| and along the bracketing axis), wall time of the whole place vocabulary,
// place count. Usage: geometry_accuracy_bench [plot.svg]
#include "geometry/closed_form_pairs.hpp"
#include "geometry/place_vocabulary_builder.hpp"
#include "fcl_pair_oracle.hpp"

#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <vector>

using namespace qm::geometry;

namespace {

struct Row {
    std::string pair;
    double tess = 0, tol = 0, normal_err = 0, axis_err = 0, ms = 0;
    std::size_t places = 0, csegs = 0, joins = 0, faces = 0;
};

Row run(const ClosedFormPair& c, const PairOracle& oracle, double tess, double tol) {
    PlaceRequest req;
    req.cspace.axes = c.axes;
    req.cspace.boundary_tolerance = tol;
    const auto t0 = std::chrono::steady_clock::now();
    const auto res = build_place_vocabulary(oracle, req);
    const auto t1 = std::chrono::steady_clock::now();
    Row row{c.name, tess, tol, 0, 0, std::chrono::duration<double, std::milli>(t1 - t0).count(),
            res.vocabulary.places.size(), res.vocabulary.count(PlaceKind::cseg), res.vocabulary.count(PlaceKind::join),
            res.vocabulary.count(PlaceKind::face)};
    for (const auto& p : res.space.boundary) {
        row.normal_err = std::max(row.normal_err, c.exact.normal_distance(p.q));
        row.axis_err = std::max(row.axis_err, c.exact.crossing_error(p.q, p.axis));
    }
    return row;
}

void print(const std::vector<Row>& rows) {
    std::cout << "| pair | chordal tol | boundary tol | max normal error | max along-axis error | time ms | places | CSEGs | joins | faces |\n"
              << "|---|---|---|---|---|---|---|---|---|---|\n";
    for (const auto& r : rows)
        std::cout << "| " << r.pair << " | " << (r.tess > 0 ? std::to_string(r.tess).substr(0, 8) : std::string("exact")) << " | "
                  << std::setprecision(1) << std::scientific << r.tol << " | " << std::setprecision(2) << r.normal_err << " | "
                  << r.axis_err << " | " << std::fixed << std::setprecision(1) << r.ms << " | " << r.places << " | " << r.csegs
                  << " | " << r.joins << " | " << r.faces << " |\n";
}

// Log-log plot: max error against the tolerance setting (boundary tolerance for the exact
// oracle, chordal tolerance for the tessellated shapes), one polyline per pair and table; the
// grey diagonal is error = setting. Times are in the tables.
void plot(const std::vector<Row>& rows, const std::string& path) {
    std::ofstream os(path);
    const double W = 640, H = 420, m = 60;
    auto X = [&](double setting) { return m + (W - 2 * m) * (std::log10(setting) + 13) / 12; };  // 1e-13 .. 1e-1
    auto Y = [&](double e) { return H - m - (H - 2 * m) * (std::log10(std::max(e, 1e-14)) + 14) / 13; };  // 1e-14 .. 1e-1
    os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\">\n"
       << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<rect x=\"" << m << "\" y=\"" << m << "\" width=\"" << W - 2 * m
       << "\" height=\"" << H - 2 * m << "\" fill=\"none\" stroke=\"black\"/>\n";
    for (int e = -14; e <= -1; e += 2)
        os << "<text x=\"5\" y=\"" << Y(std::pow(10, e)) + 4 << "\" font-size=\"10\">1e" << e << "</text>\n";
    for (int t = -13; t <= -1; t += 2)
        os << "<text x=\"" << X(std::pow(10, t)) - 10 << "\" y=\"" << H - m + 15 << "\" font-size=\"10\">1e" << t << "</text>\n";
    os << "<line x1=\"" << X(1e-13) << "\" y1=\"" << Y(1e-13) << "\" x2=\"" << X(1e-1) << "\" y2=\"" << Y(1e-1)
       << "\" stroke=\"#aaaaaa\"/>\n";
    os << "<text x=\"" << W / 2 - 120 << "\" y=\"" << H - 15 << "\" font-size=\"12\">tolerance setting (boundary or chordal)</text>\n"
       << "<text x=\"" << m << "\" y=\"30\" font-size=\"12\">max boundary error (normal distance); solid: boundary tolerance, dashed: chordal tolerance</text>\n";
    const char* colours[] = {"#c00000", "#0060c0", "#008000", "#a000a0"};
    std::size_t k = 0;
    while (k < rows.size()) {
        std::size_t end = k;
        while (end < rows.size() && rows[end].pair == rows[k].pair && (rows[end].tess > 0) == (rows[k].tess > 0)) ++end;
        const int c = rows[k].pair == "bar-and-block" ? 0 : rows[k].pair == "disk-cam-and-follower" ? 1 : rows[k].pair == "two-disks" ? 2 : 3;
        os << "<polyline fill=\"none\" stroke=\"" << colours[c] << "\"" << (rows[k].tess > 0 ? " stroke-dasharray=\"5,3\"" : "")
           << " points=\"";
        auto setting = [&](const Row& r) { return r.tess > 0 ? r.tess : r.tol; };
        for (std::size_t i = k; i < end; ++i) os << X(setting(rows[i])) << ',' << Y(rows[i].normal_err) << ' ';
        os << "\"/>\n<text x=\"" << X(setting(rows[end - 1])) + 4 << "\" y=\"" << Y(rows[end - 1].normal_err) + (c - 1.5) * 9 << "\" font-size=\"9\" fill=\""
           << colours[c] << "\">" << rows[k].pair << "</text>\n";
        k = end;
    }
    os << "</svg>\n";
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<ClosedFormPair> pairs = {bar_and_block(), disk_cam_and_follower(), two_disks(), pin_in_slot()};
    std::vector<Row> rows;
    std::cout << "## Bisection only (exact contact function as oracle, 64 x 64 grid)\n\n";
    std::vector<Row> exact_rows;
    for (const auto& c : pairs)
        for (double tol : {1e-2, 1e-4, 1e-6, 1e-8, 1e-10, 1e-12}) exact_rows.push_back(run(c, c.exact, 0, tol));
    print(exact_rows);
    std::cout << "\n## Tessellation (exact 2-D polygon oracle, boundary tolerance 1e-9, 64 x 64 grid)\n\n";
    std::vector<Row> tess_rows;
    for (const auto& c : pairs)
        for (double tess : {3e-2, 1e-2, 3e-3, 1e-3, 3e-4, 1e-4}) {
            const auto oracle = c.tessellated(tess);
            tess_rows.push_back(run(c, oracle, tess, 1e-9));
        }
    print(tess_rows);
    std::cout << "\n## FCL (parts extruded to prisms, OBBRSS meshes, same tessellations; boundary tolerance 1e-9)\n\n";
    std::vector<Row> fcl_rows;
    for (const auto& c : pairs)
        for (double tess : {1e-2, 1e-3, 1e-4}) {
            const auto poly = c.tessellated(tess);
            const bench::FclPairOracle oracle(poly.part(0), poly.part(1));
            fcl_rows.push_back(run(c, oracle, tess, 1e-9));
        }
    print(fcl_rows);
    rows = exact_rows;
    rows.insert(rows.end(), tess_rows.begin(), tess_rows.end());
    if (argc > 1) plot(rows, argv[1]);
}
