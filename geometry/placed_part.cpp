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

ContactDirection contact_direction(const PlacedPart& a, const PlacedPart& b, double scale) {
    ContactDirection out;
    const double d = placed_distance(a, b);
    if (d > 1e-9 * scale) {
        double best = 1e300;
        for_box_pairs(a, b, d, [&](double d2, int i, int s, int j, int t) {
            if (d2 > best * best) return;
            const auto sd = segment_distance(seg(a, i, s), seg(b, j, t));
            if (sd.distance < best) {
                best = sd.distance;
                out = {(sd.pa - sd.pb) / sd.distance, 0.5 * (sd.pa + sd.pb), true};
            }
        });
        return out;
    }
    double deepest = -1;
    const double limit = 1e-3 * scale;  // overlaps this shallow are touching within a tolerance
    auto consider = [&](double depth, const Eigen::Vector2d& n, const Eigen::Vector2d& x) {
        if (depth > deepest && depth <= limit && n.norm() > 0.5) {
            deepest = depth;
            out = {n.normalized(), x, true};
        }
    };
    // A vertex e of `inner`'s segment lying on the inner side of `outer` (a segment of the other
    // part) near its interior: depth and the other's outward normal there.
    auto vertex_in = [&](const Segment& outer, const Eigen::Vector2d& e, double sign) {
        const auto cp = closest_point(outer, e);
        if (cp.t <= 1e-9 || cp.t >= 1 - 1e-9) return;
        const Eigen::Vector2d out_n = outer.outward_normal_at(cp.t);
        if ((e - cp.point).dot(out_n) < 0) consider(cp.distance, sign * out_n, e);
    };
    std::vector<Eigen::Vector2d> crossings;  // all of them, for a lens spanning two segments
    for_box_pairs(a, b, 0.0, [&](double, int i, int s, int j, int t) {
        const Segment& x = seg(a, i, s);
        const Segment& y = seg(b, j, t);
        const auto meet = intersections(x, y, 0.0);
        if (meet.points.empty()) return;
        for (const auto& m : meet.points)
            if (std::none_of(crossings.begin(), crossings.end(), [&](const Eigen::Vector2d& c) { return (c - m.point).norm() <= 1e-12 * scale; }))
                crossings.push_back(m.point);
        for (const auto& e : {x.from, x.to}) vertex_in(y, e, 1.0);   // a's vertex in b: a leaves along b's normal
        for (const auto& e : {y.from, y.to}) vertex_in(x, e, -1.0);  // b's vertex in a: a leaves against its own normal
        if (meet.points.size() >= 2) {
            const Eigen::Vector2d mid = 0.5 * (meet.points[0].point + meet.points[1].point);
            const auto ca = closest_point(x, mid), cb = closest_point(y, mid);
            consider((ca.point - cb.point).norm(), y.outward_normal_at(cb.t) - x.outward_normal_at(ca.t), mid);
        } else if (deepest < 0) {
            // One crossing and no vertex inside: the surfaces' normals where they cross, leaving
            // out a side whose crossing is at its end (a corner).
            const auto& m = meet.points.front();
            Eigen::Vector2d n = Eigen::Vector2d::Zero();
            if (m.tb > 1e-9 && m.tb < 1 - 1e-9) n += y.outward_normal_at(m.tb);
            if (m.ta > 1e-9 && m.ta < 1 - 1e-9) n -= x.outward_normal_at(m.ta);
            if (n.norm() > 0.5) out = {n.normalized(), m.point, true};
        }
    });
    // One lens whose two crossings lie on different segments: its middle, as for a chord crossing
    // one segment. A circle's two half arcs meet at a smooth vertex; where that vertex lay in the
    // lens it was taken for the deepest point, on the far side of the lens' middle from the
    // pivot at the bottom of a cam's curve, and the normal's sign flipped there.
    if (crossings.size() == 2) {
        const Eigen::Vector2d mid = 0.5 * (crossings[0] + crossings[1]);
        auto nearest = [&](const PlacedPart& p) {
            std::pair<double, Eigen::Vector2d> best{1e300, Eigen::Vector2d::Zero()};
            for (const auto& profile : p.profiles)
                for (const auto& sg : profile.segments) {
                    const auto cp = closest_point(sg, mid);
                    if (cp.distance < best.first) best = {cp.distance, sg.outward_normal_at(cp.t)};
                }
            return best;
        };
        const auto [da, na] = nearest(a);
        const auto [db, nb] = nearest(b);
        consider(da + db, nb - na, mid);
    }
    return out;
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
