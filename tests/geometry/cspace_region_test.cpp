// tests/geometry/cspace_region_test.cpp: the blocked region from the bisected boundary agrees with
// the oracle at random points farther than a small fraction of a cell from the exact boundary
// (whole grid cells shaded round blocked samples would disagree up to half a cell away), across a
// periodic seam and at saddle cells; its pieces are counter-clockwise and do not overlap (their
// areas add up to the exact area).
#include "geometry/closed_form_pairs.hpp"
#include "geometry/cspace.hpp"
#include "geometry/cspace_region.hpp"

#include <doctest/doctest.h>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

using namespace qm::geometry;

namespace {

bool inside(const Polygon& p, const Eigen::Vector2d& q) {  // ray casting
    bool in = false;
    for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
        if ((p[i].y() > q.y()) != (p[j].y() > q.y()) &&
            q.x() < (p[j].x() - p[i].x()) * (q.y() - p[i].y()) / (p[j].y() - p[i].y()) + p[i].x())
            in = !in;
    return in;
}

// Random points whose distance from the boundary (given as |f| / |grad f|) exceeds `margin`: in
// the region (taken modulo the periods) exactly when blocked. Returns how many were tested.
int agree(const AnalyticOracle& oracle, const CSpaceResult& space, const std::vector<Polygon>& region, double margin) {
    std::mt19937 rng(7);
    const auto& a = space.request.axes;
    std::uniform_real_distribution<double> u0(a[0].lo, a[0].hi), u1(a[1].lo, a[1].hi);
    int tested = 0;
    for (int k = 0; k < 4000; ++k) {
        const Eigen::Vector2d q(u0(rng), u1(rng));
        if (oracle.normal_distance(q) <= margin) continue;
        bool in = false;
        for (const auto& p : region)
            for (double shift : {0.0, a[0].periodic ? a[0].span() : 0.0})
                in = in || inside(p, q + Eigen::Vector2d(shift, 0));
        CAPTURE(q.transpose());
        CHECK(in == oracle.blocked(q));
        ++tested;
    }
    return tested;
}

void check_pieces(const std::vector<Polygon>& region) {
    for (const auto& p : region) {
        CHECK(p.size() >= 3);
        CHECK(polygon_area(p) > 0);
    }
}

AnalyticOracle disk(Eigen::Vector2d c, double r, double period = 0) {
    auto d = [=](const Eigen::Vector2d& q) {
        Eigen::Vector2d v = q - c;
        if (period > 0) v.x() -= period * std::round(v.x() / period);
        return v;
    };
    return AnalyticOracle("disk", [=](const Eigen::Vector2d& q) { return r * r - d(q).squaredNorm(); },
                          [=](const Eigen::Vector2d& q) { return Eigen::Vector2d(-2 * d(q)); });
}

}  // namespace

TEST_CASE("geometry/cspace_region: a disk of blocked space, to within a twentieth of a cell") {
    const auto oracle = disk({0.43, 0.57}, 0.27);
    CSpaceRequest req;
    req.axes = {CSpaceAxis{0, 1, false, 33}, CSpaceAxis{0, 1, false, 33}};
    const auto space = classify_cspace(oracle, req);
    const auto region = blocked_region(oracle, space);
    check_pieces(region);
    const double cell = 1.0 / 32;
    CHECK(agree(oracle, space, region, cell / 20) > 3000);
    double area = 0;
    for (const auto& p : region) area += polygon_area(p);
    // The polygon is inscribed: short of the disk by the chords' segments only.
    const double exact = std::numbers::pi * 0.27 * 0.27;
    CHECK(area <= exact);
    CHECK(area >= exact - 2 * std::numbers::pi * 0.27 * cell * cell / (8 * 0.27) * 2);
}

TEST_CASE("geometry/cspace_region: across the seam of a periodic axis") {
    const double period = 2 * std::numbers::pi;
    const auto oracle = disk({0.1, 0.5}, 0.35, period);  // straddles q0 = 0 = 2 pi
    CSpaceRequest req;
    req.axes = {CSpaceAxis{0, period, true, 64}, CSpaceAxis{0, 1, false, 41}};
    const auto space = classify_cspace(oracle, req);
    const auto region = blocked_region(oracle, space);
    check_pieces(region);
    for (const auto& p : region)
        for (const auto& v : p) {  // unwrapped: the pieces after the last sample end at 2 pi
            CHECK(v.x() >= 0);
            CHECK(v.x() <= period + 1e-12);
        }
    CHECK(agree(oracle, space, region, 0.01) > 3000);
}

TEST_CASE("geometry/cspace_region: saddle cells take the oracle's centre") {
    // Blocked in two opposite quadrants around a point inside a cell: that cell has four
    // crossings. Both ways of joining them occur, depending on which quadrants are blocked.
    for (int sense : {1, -1}) {
        CAPTURE(sense);
        const Eigen::Vector2d p(0.5123, 0.4871);
        const AnalyticOracle oracle("quadrants", [=](const Eigen::Vector2d& q) { return sense * (q.x() - p.x()) * (q.y() - p.y()); },
                                    [=](const Eigen::Vector2d& q) { return Eigen::Vector2d(sense * (q.y() - p.y()), sense * (q.x() - p.x())); });
        CSpaceRequest req;
        req.axes = {CSpaceAxis{0, 1, false, 21}, CSpaceAxis{0, 1, false, 21}};
        const auto space = classify_cspace(oracle, req);
        const auto region = blocked_region(oracle, space);
        check_pieces(region);
        std::mt19937 rng(3);
        std::uniform_real_distribution<double> u(0, 1);
        for (int k = 0; k < 3000; ++k) {  // away from the two lines, and from the saddle cell
            const Eigen::Vector2d q(u(rng), u(rng));
            if (std::abs(q.x() - p.x()) < 0.003 || std::abs(q.y() - p.y()) < 0.003 || (q - p).norm() < 0.08) continue;
            bool in = false;
            for (const auto& poly : region) in = in || inside(poly, q);
            CHECK(in == oracle.blocked(q));
        }
        // The saddle cell [0.5, 0.55] x [0.45, 0.5]: two triangles cut off the blocked corners when
        // its centre is free, one hexagon joins them when it is blocked.
        std::vector<std::size_t> in_cell;
        for (const auto& poly : region)
            if (std::all_of(poly.begin(), poly.end(), [](const Eigen::Vector2d& v) {
                    return v.x() >= 0.5 - 1e-12 && v.x() <= 0.55 + 1e-12 && v.y() >= 0.45 - 1e-12 && v.y() <= 0.5 + 1e-12;
                }))
                in_cell.push_back(poly.size());
        const bool centre_blocked = oracle.blocked({0.525, 0.475});
        CHECK(in_cell == (centre_blocked ? std::vector<std::size_t>{6} : std::vector<std::size_t>{3, 3}));
        double area = 0;
        for (const auto& poly : region) area += polygon_area(poly);
        const double exact = sense > 0 ? p.x() * p.y() + (1 - p.x()) * (1 - p.y()) : p.x() * (1 - p.y()) + (1 - p.x()) * p.y();
        CHECK(area == doctest::Approx(exact).epsilon(0.01));
    }
}
