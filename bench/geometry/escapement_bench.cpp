// bench/geometry/escapement_bench.cpp: the escapement pair of scenarios/metric/escapement.def (scape
// wheel and anchor pallets) with FCL in the loop (docs/perf/geometry.md; target: configuration
// space and place vocabulary in under 1 s with boundary error under 1e-6 rad). For each setting of
// chordal tolerance, boundary tolerance and grid: the wall time of the whole place vocabulary
// (median of `repeats` runs), FCL calls, boundary points, place counts, and the boundary error
// against the exact lines-and-arcs oracle (profile_pair_oracle.hpp): each boundary point is
// compared with the exact crossing of its grid edge (bisection on the exact oracle to 1e-14);
// "normal" is that difference times the exact normal's component along the edge (the distance to
// the exact boundary, first order), "along" the difference itself.
// Usage: geometry_escapement_bench SCENE [out.svg] [repeats]
#include "geometry/cspace_svg.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"
#include "geometry/place_vocabulary_builder.hpp"
#include "geometry/profile_pair_oracle.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>

using namespace qm::geometry;

namespace {

struct Errors {
    double normal = 0, along = 0;
    int unmatched = 0;  // edges the exact geometry does not cross (tangencies within the tessellation)
};

Errors boundary_errors(const PlaceResult& res, const ProfilePairOracle& exact) {
    Errors e;
    const auto& r = res.space.request;
    for (const auto& p : res.space.boundary) {
        Eigen::Vector2d a(r.axes[0].sample(p.cell[0]), r.axes[1].sample(p.cell[1])), b = a;
        b[p.axis] += r.axes[static_cast<std::size_t>(p.axis)].step();
        const bool ba = exact.blocked(wrap(r, a)), bb = exact.blocked(wrap(r, b));
        if (ba == bb) {
            ++e.unmatched;
            continue;
        }
        std::uint64_t calls = 0;
        const Eigen::Vector2d x = wrap(r, bisect_contact(exact, a, ba, b, 1e-14, calls));
        const double along = std::abs(difference(r, x, p.q)[p.axis]);
        const Eigen::Vector2d n = exact.free_normal(x).normalized();
        e.along = std::max(e.along, along);
        e.normal = std::max(e.normal, along * std::abs(n[p.axis]));
    }
    return e;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: geometry_escapement_bench SCENE [out.svg] [repeats]\n";
        return 2;
    }
    const int repeats = argc > 3 ? std::max(1, std::atoi(argv[3])) : 3;
    qm::Diagnostics diags;
    const auto m = read_mechanism_file(argv[1], diags);
    diags.print(std::cerr);
    if (!m) return 2;
    const auto pair = kinematic_pairs(*m).modelled.at(0);
    const Part& wheel = m->parts[pair.a];
    const Part& pallets = m->parts[pair.b];
    const ProfilePairOracle exact(wheel, pallets);
    const double size = std::min(wheel.size(), pallets.size());
    std::cout << "| grid | chordal tol (x size) | boundary tol (rad) | time ms | FCL calls | boundary pts | max normal error (rad) | max along-edge error (rad) | unmatched | places | CSEGs | joins | FSDs | faces |\n"
              << "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    PlaceResult picture;
    std::unique_ptr<FclPairOracle> picture_oracle;  // resolves the picture's saddle cells
    struct Setting {
        int grid;
        double chordal, tol;
    };
    std::vector<Setting> settings;
    for (double chordal : {1e-4, 1e-5, 1e-6, 1e-7})
        for (double tol : {1e-6, 1e-8, 1e-10}) settings.push_back({64, chordal, tol});
    for (int grid : {32, 128}) settings.push_back({grid, 1e-6, 1e-8});
    for (const auto& s : settings) {
        Mechanism mech = *m;
        mech.settings.chordal_tolerance = s.chordal;
        mech.settings.boundary_tolerance = s.tol;
        mech.settings.grid = {s.grid, s.grid};
        PairSpec spec = pair;
        spec.grid.reset();
        std::vector<double> times;
        PlaceResult res;
        std::uint64_t calls = 0;
        for (int i = 0; i < repeats; ++i) {
            const auto t0 = std::chrono::steady_clock::now();
            const auto oracle = pair_oracle(mech, spec);  // meshing is part of the cost
            res = build_place_vocabulary(*oracle, place_request(mech, spec));
            const auto t1 = std::chrono::steady_clock::now();
            times.push_back(std::chrono::duration<double, std::milli>(t1 - t0).count());
            calls = oracle->fcl_calls();
        }
        std::sort(times.begin(), times.end());
        const auto e = boundary_errors(res, exact);
        const auto& v = res.vocabulary;
        std::cout << "| " << s.grid << " | " << s.chordal << " | " << s.tol << " | " << times[times.size() / 2] << " | " << calls << " | "
                  << res.space.boundary.size() << " | " << e.normal << " | " << e.along << " | " << e.unmatched << " | " << v.places.size()
                  << " | " << v.count(PlaceKind::cseg) << " | " << v.count(PlaceKind::join) << " | " << v.count(PlaceKind::fsd) << " | "
                  << v.count(PlaceKind::face) << " |\n";
        if (s.grid == 64 && s.chordal == 1e-6 && s.tol == 1e-8) {
            picture = res;
            picture_oracle = pair_oracle(mech, spec);
        }
    }
    std::cout << "\n(chordal tolerance x size = " << size << " is the length; external divisions: "
              << picture.vocabulary.count(PlaceKind::external_division) << " pieces)\n";
    if (argc > 2) {
        std::ofstream os(argv[2]);
        write_cspace_svg(os, *picture_oracle, picture.space, picture.vocabulary,
                         {720, 540, "escapement, FCL, 64x64, 1e-8 rad", true, true,
                          {SvgAxis{"scape-wheel", AxisUnit::degrees}, SvgAxis{"pallets", AxisUnit::degrees}}});
    }
}
