// geometry/placed_part.cpp: exact distance and overlap of two parts drawn with lines and arcs.
#include "geometry/placed_part.hpp"

#include "geometry/profile_check.hpp"
#include "geometry/segment_queries.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>

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

// Segment pairs in order of their boxes' distance, so the search can stop early.
std::vector<std::tuple<double, int, int, int, int>> by_box_distance(const PlacedPart& a, const PlacedPart& b, double limit) {
    std::vector<std::tuple<double, int, int, int, int>> out;
    for (std::size_t i = 0; i < a.profiles.size(); ++i)
        for (std::size_t s = 0; s < a.boxes[i].size(); ++s) {
            if (a.boxes[i][s].distance(b.all) > limit) continue;
            for (std::size_t j = 0; j < b.profiles.size(); ++j)
                for (std::size_t t = 0; t < b.boxes[j].size(); ++t) {
                    const double d = a.boxes[i][s].distance(b.boxes[j][t]);
                    if (d <= limit) out.emplace_back(d, static_cast<int>(i), static_cast<int>(s), static_cast<int>(j), static_cast<int>(t));
                }
        }
    std::sort(out.begin(), out.end());
    return out;
}

bool contains_a_point_of(const PlacedPart& outer, const PlacedPart& inner) {
    const Eigen::Vector2d x = inner.profiles.front().segments.front().from;
    for (const auto& p : outer.profiles)
        if (inside(p, x)) return true;
    return false;
}

}  // namespace

double placed_distance(const PlacedPart& a, const PlacedPart& b) {
    if (a.profiles.empty() || b.profiles.empty()) return 1e300;
    double best = 1e300;
    for (const auto& [box, i, s, j, t] : by_box_distance(a, b, 1e300)) {
        if (box >= best) break;
        best = std::min(best, segment_distance(a.profiles[static_cast<std::size_t>(i)].segments[static_cast<std::size_t>(s)],
                                               b.profiles[static_cast<std::size_t>(j)].segments[static_cast<std::size_t>(t)])
                                  .distance);
        if (best == 0) return 0;
    }
    if (contains_a_point_of(a, b) || contains_a_point_of(b, a)) return 0;
    return best;
}

bool placed_overlap(const PlacedPart& a, const PlacedPart& b) {
    if (a.profiles.empty() || b.profiles.empty() || a.all.distance(b.all) > 0) return false;
    for (const auto& [box, i, s, j, t] : by_box_distance(a, b, 0.0)) {
        const auto meet = intersections(a.profiles[static_cast<std::size_t>(i)].segments[static_cast<std::size_t>(s)],
                                        b.profiles[static_cast<std::size_t>(j)].segments[static_cast<std::size_t>(t)], 0.0);
        if (meet.overlap || !meet.points.empty()) return true;
    }
    return contains_a_point_of(a, b) || contains_a_point_of(b, a);
}

}  // namespace qm::geometry
