// bench/geometry/escapement_bench.cpp: configuration space and place vocabulary of a scape wheel
// and anchor pair (docs/perf/geometry.md). Until the scene generators exist this uses simple
// shapes of its own: a 15-tooth sawtooth scape wheel about the origin and a two-pallet anchor
// about (0, 1.4). The wheel axis covers one tooth pitch, periodic (the one-period abstraction of
// 8.1.6); the anchor swings within +-0.35 rad. Target: < 1 s with boundary error < 1e-6 rad.
// Usage: geometry_escapement_bench [out.svg]
#include "geometry/cspace_svg.hpp"
#include "geometry/place_vocabulary_builder.hpp"
#include "geometry/polygon_pair.hpp"

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>
#include <numbers>

using namespace qm::geometry;

namespace {

Polygon scape_wheel(int teeth, double root, double tip) {
    Polygon p;
    const double pitch = 2 * std::numbers::pi / teeth;
    for (int i = 0; i < teeth; ++i) {
        const double a = i * pitch;
        p.emplace_back(root * std::cos(a), root * std::sin(a));
        p.emplace_back(tip * std::cos(a + 0.8 * pitch), tip * std::sin(a + 0.8 * pitch));
    }
    return p;
}

Polygon anchor() { return {{-0.45, 1.5}, {-0.4, 0.9}, {-0.3, 0.95}, {-0.2, 1.35}, {0.2, 1.35}, {0.3, 0.95}, {0.4, 0.9}, {0.45, 1.5}}; }

}  // namespace

int main(int argc, char** argv) {
    constexpr int teeth = 15;
    const PolygonPairOracle oracle({{scape_wheel(teeth, 0.85, 1.0)}, {PolygonDof::Kind::rotation, {0, 0}, {1, 0}}},
                                   {{anchor()}, {PolygonDof::Kind::rotation, {0, 1.4}, {1, 0}}});
    std::cout << "| grid | boundary tol (rad) | time ms | oracle calls | boundary pts | places | CSEGs | joins | FSDs | faces |\n"
              << "|---|---|---|---|---|---|---|---|---|---|\n";
    PlaceResult last;
    for (int grid : {32, 64, 128})
        for (double tol : {1e-4, 1e-6, 1e-8, 1e-10}) {
            PlaceRequest req;
            req.cspace.axes = {CSpaceAxis{0, 2 * std::numbers::pi / teeth, true, grid}, CSpaceAxis{-0.35, 0.35, false, grid}};
            req.cspace.boundary_tolerance = tol;
            const auto t0 = std::chrono::steady_clock::now();
            auto res = build_place_vocabulary(oracle, req);
            const auto t1 = std::chrono::steady_clock::now();
            const auto& v = res.vocabulary;
            std::cout << "| " << grid << " | " << tol << " | " << std::chrono::duration<double, std::milli>(t1 - t0).count() << " | "
                      << res.space.oracle_calls << " | " << res.space.boundary.size() << " | " << v.places.size() << " | "
                      << v.count(PlaceKind::cseg) << " | " << v.count(PlaceKind::join) << " | " << v.count(PlaceKind::fsd) << " | "
                      << v.count(PlaceKind::face) << " |\n";
            if (grid == 64 && tol == 1e-8) last = std::move(res);
        }
    // 8.2.1 / 9.2: gravity on the pallets flips where the anchor hangs straight (anchor angle 0);
    // the division is kept only where it crosses free space.
    {
        PlaceRequest req;
        req.cspace.axes = {CSpaceAxis{0, 2 * std::numbers::pi / teeth, true, 64}, CSpaceAxis{-0.35, 0.35, false, 64}};
        req.cspace.boundary_tolerance = 1e-8;
        req.external.push_back({1, 0.0, "gravity on the pallets flips"});
        const auto t0 = std::chrono::steady_clock::now();
        const auto res = build_place_vocabulary(oracle, req);
        const auto t1 = std::chrono::steady_clock::now();
        const auto& v = res.vocabulary;
        std::cout << "\nwith the external division anchor = 0 (64 grid, 1e-8): " << std::chrono::duration<double, std::milli>(t1 - t0).count()
                  << " ms, places " << v.places.size() << " (external-division pieces " << v.count(PlaceKind::external_division)
                  << ", faces " << v.count(PlaceKind::face) << ")\n";
    }
    if (argc > 1) {
        std::ofstream os(argv[1]);
        write_cspace_svg(os, last.space, last.vocabulary, {720, 540, "scape wheel (one pitch) x anchor, 64x64, tol 1e-8", true});
    }
}
