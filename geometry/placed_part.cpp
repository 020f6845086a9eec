// geometry/placed_part.cpp: exact distance and overlap of two parts drawn with lines and arcs.
#include "geometry/placed_part.hpp"

#include "geometry/profile_check.hpp"
#include "geometry/segment_queries.hpp"

#include <algorithm>
#include <cmath>

namespace qm::geometry {

double Box::distance(const Box& o) const noexcept {
    const double dx = std::max({0.0, o.lo.x() - hi.x(), lo.x() - o.hi.x()});
    const double dy = std::max({0.0, o.lo.y() - hi.y(), lo.y() - o.hi.y()});
    return std::hypot(dx, dy);
}

PlacedPart place(const Part& part, double q) {
    PlacedPart out;
    const Eigen::Isometry2d pose = part.pose(q);
    for (const auto& profile : part.profiles) {
        out.profiles.push_back(transformed(profile, pose));
        auto& boxes = out.boxes.emplace_back();
        for (const auto& s : out.profiles.back().segments) {
            Box b;
            extend_bounds(Profile{{s}}, b.lo, b.hi);
            out.all.lo = out.all.lo.cwiseMin(b.lo);
            out.all.hi = out.all.hi.cwiseMax(b.hi);
            boxes.push_back(b);
        }
    }
    return out;
}

namespace {

double box_distance2(const Box& a, const Box& b) {
    const double dx = std::max({0.0, b.lo.x() - a.hi.x(), a.lo.x() - b.hi.x()});
    const double dy = std::max({0.0, b.lo.y() - a.hi.y(), a.lo.y() - b.hi.y()});
    return dx * dx + dy * dy;
}

// Calls f(d2, i, s, j, t) for every segment pair whose boxes are within `limit` of each other.
template <class F>
void for_box_pairs(const PlacedPart& a, const PlacedPart& b, double limit, F&& f) {
    const double l2 = limit * limit;
    for (std::size_t i = 0; i < a.profiles.size(); ++i)
        for (std::size_t s = 0; s < a.boxes[i].size(); ++s) {
            if (box_distance2(a.boxes[i][s], b.all) > l2) continue;
            for (std::size_t j = 0; j < b.profiles.size(); ++j)
                for (std::size_t t = 0; t < b.boxes[j].size(); ++t) {
                    const double d2 = box_distance2(a.boxes[i][s], b.boxes[j][t]);
                    if (d2 <= l2) f(d2, static_cast<int>(i), static_cast<int>(s), static_cast<int>(j), static_cast<int>(t));
                }
        }
}

const Segment& seg(const PlacedPart& p, int i, int s) { return p.profiles[static_cast<std::size_t>(i)].segments[static_cast<std::size_t>(s)]; }

bool contains_a_point_of(const PlacedPart& outer, const PlacedPart& inner) {
    const Eigen::Vector2d x = inner.profiles.front().segments.front().from;
    for (const auto& p : outer.profiles)
        if (inside(p, x)) return true;
    return false;
}

}  // namespace

double placed_distance(const PlacedPart& a, const PlacedPart& b) {
    if (a.profiles.empty() || b.profiles.empty()) return 1e300;
    // A first bound from the pair of nearest boxes, then every pair whose boxes are nearer than
    // the best distance so far: most pairs fall away at once.
    double nearest = 1e300;
    int ni = 0, ns = 0, nj = 0, nt = 0;
    for_box_pairs(a, b, 1e300, [&](double d2, int i, int s, int j, int t) {
        if (d2 < nearest) nearest = d2, ni = i, ns = s, nj = j, nt = t;
    });
    double best = segment_distance(seg(a, ni, ns), seg(b, nj, nt)).distance;
    if (best > 0)
        for_box_pairs(a, b, best, [&](double d2, int i, int s, int j, int t) {
            if (best > 0 && d2 < best * best) best = std::min(best, segment_distance(seg(a, i, s), seg(b, j, t)).distance);
        });
    if (best == 0 || contains_a_point_of(a, b) || contains_a_point_of(b, a)) return 0;
    return best;
}

bool placed_overlap(const PlacedPart& a, const PlacedPart& b) {
    if (a.profiles.empty() || b.profiles.empty() || a.all.distance(b.all) > 0) return false;
    bool meet = false;
    for_box_pairs(a, b, 0.0, [&](double, int i, int s, int j, int t) {
        if (meet) return;
        const auto x = intersections(seg(a, i, s), seg(b, j, t), 0.0);
        meet = x.overlap || !x.points.empty();
    });
    return meet || contains_a_point_of(a, b) || contains_a_point_of(b, a);
}

std::vector<SegmentPair> near_pairs(const PlacedPart& a, const PlacedPart& b, double radius) {
    std::vector<SegmentPair> out;
    for_box_pairs(a, b, radius, [&](double, int i, int s, int j, int t) { out.push_back({i, s, j, t}); });
    return out;
}

double distance_over(const PlacedPart& a, const PlacedPart& b, const std::vector<SegmentPair>& pairs) {
    double best = 1e300;
    for (const auto& p : pairs) {
        best = std::min(best, segment_distance(seg(a, p.i, p.s), seg(b, p.j, p.t)).distance);
        if (best == 0) break;
    }
    return best;
}

}  // namespace qm::geometry
