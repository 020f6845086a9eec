// bench/geometry/ear_clipping.hpp (benchmark only)
// Provides:   triangulate(), the triangles of a simple polygon by ear clipping, for the caps of
//             extruded prisms in fcl_mesh_bench.cpp, which measures what caps cost FCL (the
//             library's meshes are walls only: geometry/fcl_part_model.hpp).
// Ownership:  value results only.
// Invariants: for a simple counter-clockwise polygon of n >= 3 vertices: n - 2 triangles, each
//             counter-clockwise, whose areas sum to the polygon's area (tested).
// Knows nothing of FCL, the ATMS or the engine.
#pragma once
#include "geometry/polygon_pair.hpp"
#include "qm/assert.hpp"
#include <algorithm>
#include <array>
#include <vector>

// Only reflex vertices can lie inside an ear, so each ear test looks at the remaining reflex
// vertices. Pre: poly is simple and counter-clockwise with >= 3 vertices.
namespace qm::geometry::bench {
namespace {

double cross3(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    return (b - a).x() * (c - a).y() - (b - a).y() * (c - a).x();
}

// p in the closed triangle abc (counter-clockwise).
bool in_triangle(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
    return cross3(a, b, p) >= 0 && cross3(b, c, p) >= 0 && cross3(c, a, p) >= 0;
}

}  // namespace

inline std::vector<std::array<int, 3>> triangulate(const Polygon& poly) {
    const int n = static_cast<int>(poly.size());
    QM_REQUIRE(n >= 3, "triangulate needs three vertices");
    std::vector<int> prev(static_cast<std::size_t>(n)), next(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        prev[static_cast<std::size_t>(i)] = (i + n - 1) % n;
        next[static_cast<std::size_t>(i)] = (i + 1) % n;
    }
    auto P = [&](int i) -> const Eigen::Vector2d& { return poly[static_cast<std::size_t>(i)]; };
    auto convex = [&](int i) { return cross3(P(prev[static_cast<std::size_t>(i)]), P(i), P(next[static_cast<std::size_t>(i)])) > 0; };
    std::vector<char> removed(static_cast<std::size_t>(n), 0);
    std::vector<int> reflex;
    for (int i = 0; i < n; ++i)
        if (!convex(i)) reflex.push_back(i);
    auto is_ear = [&](int i) {
        if (!convex(i)) return false;
        const int a = prev[static_cast<std::size_t>(i)], c = next[static_cast<std::size_t>(i)];
        for (int r : reflex) {
            if (removed[static_cast<std::size_t>(r)] || r == a || r == i || r == c) continue;
            if (P(r) == P(a) || P(r) == P(c)) continue;  // a repeated vertex touching the ear's corner
            if (in_triangle(P(r), P(a), P(i), P(c))) return false;
        }
        return true;
    };
    std::vector<std::array<int, 3>> out;
    int left = n, cur = 0, since_last = 0;
    while (left > 3) {
        if (is_ear(cur) || since_last > left) {
            // since_last > left: no ear in a full round (rounding on a nearly degenerate
            // polygon); clipping the current vertex still terminates and covers the area.
            const int a = prev[static_cast<std::size_t>(cur)], c = next[static_cast<std::size_t>(cur)];
            out.push_back({a, cur, c});
            removed[static_cast<std::size_t>(cur)] = 1;
            next[static_cast<std::size_t>(a)] = c;
            prev[static_cast<std::size_t>(c)] = a;
            --left;
            since_last = 0;
            std::erase_if(reflex, [&](int r) { return removed[static_cast<std::size_t>(r)] || convex(r); });
            cur = a;
        } else {
            cur = next[static_cast<std::size_t>(cur)];
            ++since_last;
        }
    }
    out.push_back({prev[static_cast<std::size_t>(cur)], cur, next[static_cast<std::size_t>(cur)]});
    return out;
}

}  // namespace qm::geometry::bench
