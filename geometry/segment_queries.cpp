// geometry/segment_queries.cpp: closest points, distances and intersections of lines and arcs.
#include "geometry/segment_queries.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace qm::geometry {
namespace {

double perp_dot(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

double angle_of(const Eigen::Vector2d& v) { return std::atan2(v.y(), v.x()); }

// Parameter on the line segment s of its point nearest p (clamped).
double line_param(const Segment& s, const Eigen::Vector2d& p) {
    const Eigen::Vector2d d = s.to - s.from;
    const double l2 = d.squaredNorm();
    return l2 > 0 ? std::clamp((p - s.from).dot(d) / l2, 0.0, 1.0) : 0.0;
}

void add_point(Intersections& out, const Segment& a, const Segment& b, const Eigen::Vector2d& x, double eps) {
    for (const auto& q : out.points)
        if ((q.point - x).norm() <= eps) return;  // a tangent touch found twice
    out.points.push_back({closest_point(a, x).t, closest_point(b, x).t, x});
}

// Is x on segment s, within eps?
bool on_segment(const Segment& s, const Eigen::Vector2d& x, double eps) { return closest_point(s, x).distance <= eps; }

void line_line(const Segment& a, const Segment& b, double eps, Intersections& out) {
    const Eigen::Vector2d da = a.to - a.from, db = b.to - b.from;
    const double den = perp_dot(da, db);
    const double la = da.norm(), lb = db.norm();
    if (std::abs(den) <= eps * 1e-3 * std::max(la, lb) || std::abs(den) <= 1e-12 * la * lb) {
        // Parallel: collinear if b's ends are on a's line.
        if (std::abs(perp_dot(da, b.from - a.from)) > eps * la) return;
        std::vector<Eigen::Vector2d> shared;
        for (const auto& x : {a.from, a.to})
            if (on_segment(b, x, eps)) shared.push_back(x);
        for (const auto& x : {b.from, b.to})
            if (on_segment(a, x, eps)) shared.push_back(x);
        // A common piece of positive length holds a point of one strictly inside the other: an
        // end point away from the other's ends, or the midpoint (equal segments).
        auto strictly_inside = [eps](const Segment& s, const Eigen::Vector2d& x) {
            return on_segment(s, x, eps) && (x - s.from).norm() > eps && (x - s.to).norm() > eps;
        };
        for (const auto& x : {a.from, a.to, Eigen::Vector2d(0.5 * (a.from + a.to))})
            out.overlap = out.overlap || strictly_inside(b, x);
        for (const auto& x : {b.from, b.to, Eigen::Vector2d(0.5 * (b.from + b.to))})
            out.overlap = out.overlap || strictly_inside(a, x);
        for (const auto& x : shared) add_point(out, a, b, x, eps);
        return;
    }
    const double t = perp_dot(b.from - a.from, db) / den, u = perp_dot(b.from - a.from, da) / den;
    const double ta = eps / std::max(la, 1e-300), tb = eps / std::max(lb, 1e-300);
    if (t >= -ta && t <= 1 + ta && u >= -tb && u <= 1 + tb) add_point(out, a, b, a.from + std::clamp(t, 0.0, 1.0) * da, eps);
}

void line_arc(const Segment& l, const Segment& c, double eps, Intersections& out) {
    const Eigen::Vector2d d = l.to - l.from;
    const double len = d.norm();
    if (len == 0) return;
    const Eigen::Vector2d u = d / len;
    const double r = c.radius();
    // Foot of the centre on the line, and the half chord length there.
    const double s0 = (c.centre - l.from).dot(u);
    const Eigen::Vector2d foot = l.from + s0 * u;
    const double h = (c.centre - foot).norm();
    if (h > r + eps) return;
    const double half = h >= r ? 0.0 : std::sqrt(r * r - h * h);
    for (double s : {s0 - half, s0 + half}) {
        if (s < -eps || s > len + eps) continue;
        const Eigen::Vector2d x = l.from + std::clamp(s, 0.0, len) * u;
        if (c.covers_angle(angle_of(x - c.centre), eps / r)) add_point(out, l, c, x, eps);
    }
}

void arc_arc(const Segment& a, const Segment& b, double eps, Intersections& out) {
    const double ra = a.radius(), rb = b.radius();
    const Eigen::Vector2d d = b.centre - a.centre;
    const double dist = d.norm();
    if (dist <= eps && std::abs(ra - rb) <= eps) {
        // One circle: pieces in common (endpoints of each on the other).
        std::vector<Eigen::Vector2d> shared;
        for (const auto& x : {a.from, a.to})
            if (b.covers_angle(angle_of(x - b.centre), eps / rb)) shared.push_back(x);
        for (const auto& x : {b.from, b.to})
            if (a.covers_angle(angle_of(x - a.centre), eps / ra)) shared.push_back(x);
        // As for collinear lines: a common arc holds an end or the midpoint of one strictly
        // inside the other (two half circles share only their ends).
        auto strictly_inside = [eps](const Segment& s, const Eigen::Vector2d& x) {
            return s.covers_angle(angle_of(x - s.centre)) && (x - s.from).norm() > eps && (x - s.to).norm() > eps;
        };
        for (const auto& x : {a.from, a.to, a.point_at(0.5)}) out.overlap = out.overlap || strictly_inside(b, x);
        for (const auto& x : {b.from, b.to, b.point_at(0.5)}) out.overlap = out.overlap || strictly_inside(a, x);
        for (const auto& x : shared) add_point(out, a, b, x, eps);
        return;
    }
    if (dist > ra + rb + eps || dist < std::abs(ra - rb) - eps || dist == 0) return;
    // Distance from a's centre along d to the chord of intersection, and the half chord.
    const double x = (dist * dist + ra * ra - rb * rb) / (2 * dist);
    const double h2 = ra * ra - x * x;
    const double h = h2 > 0 ? std::sqrt(h2) : 0.0;
    const Eigen::Vector2d u = d / dist, n(-u.y(), u.x());
    for (double sgn : {-1.0, 1.0}) {
        const Eigen::Vector2d p = a.centre + x * u + sgn * h * n;
        if (a.covers_angle(angle_of(p - a.centre), eps / ra) && b.covers_angle(angle_of(p - b.centre), eps / rb))
            add_point(out, a, b, p, eps);
    }
}

}  // namespace

ClosestPoint closest_point(const Segment& s, const Eigen::Vector2d& p) noexcept {
    ClosestPoint out;
    if (!s.is_arc()) {
        out.t = line_param(s, p);
        out.point = s.from + out.t * (s.to - s.from);
    } else {
        const Eigen::Vector2d v = p - s.centre;
        const double a = v.norm() > 0 ? angle_of(v) : s.start_angle();
        if (s.covers_angle(a)) {
            out.t = std::clamp(s.param_of_angle(a), 0.0, 1.0);
            out.point = s.centre + s.radius() * Eigen::Vector2d(std::cos(a), std::sin(a));
        } else if ((s.from - p).norm() <= (s.to - p).norm()) {
            out.t = 0;
            out.point = s.from;
        } else {
            out.t = 1;
            out.point = s.to;
        }
    }
    out.distance = (out.point - p).norm();
    return out;
}

Intersections intersections(const Segment& a, const Segment& b, double eps) {
    Intersections out;
    if (!a.is_arc() && !b.is_arc()) {
        line_line(a, b, eps, out);
    } else if (!a.is_arc()) {
        line_arc(a, b, eps, out);
    } else if (!b.is_arc()) {
        line_arc(b, a, eps, out);
        for (auto& x : out.points) std::swap(x.ta, x.tb);
    } else {
        arc_arc(a, b, eps, out);
    }
    for (auto& x : out.points) {  // parameters from the segment each belongs to
        x.ta = closest_point(a, x.point).t;
        x.tb = closest_point(b, x.point).t;
    }
    return out;
}

SegmentDistance segment_distance(const Segment& a, const Segment& b) {
    SegmentDistance best;
    best.distance = std::numeric_limits<double>::infinity();
    auto consider = [&](const Eigen::Vector2d& pa, const Eigen::Vector2d& pb) {
        const double d = (pa - pb).norm();
        if (d < best.distance) {
            best.distance = d;
            best.pa = pa;
            best.pb = pb;
        }
    };
    const auto meet = intersections(a, b, 0.0);
    if (!meet.points.empty()) consider(meet.points.front().point, meet.points.front().point);
    // Otherwise the minimum is at an end point of one segment against the other, or (for arcs)
    // at points where the connecting line is normal to both curves: through a circle's centre.
    for (const auto& x : {b.from, b.to}) consider(closest_point(a, x).point, x);
    for (const auto& x : {a.from, a.to}) consider(x, closest_point(b, x).point);
    auto circle_points = [](const Segment& arc, const Eigen::Vector2d& dir, std::vector<Eigen::Vector2d>& out) {
        if (dir.norm() == 0) return;
        const Eigen::Vector2d u = dir.normalized();
        for (double sgn : {-1.0, 1.0}) {
            const Eigen::Vector2d x = arc.centre + sgn * arc.radius() * u;
            if (arc.covers_angle(angle_of(x - arc.centre))) out.push_back(x);
        }
    };
    if (a.is_arc() && b.is_arc()) {
        std::vector<Eigen::Vector2d> pa, pb;
        circle_points(a, b.centre - a.centre, pa);
        circle_points(b, a.centre - b.centre, pb);
        for (const auto& x : pa)
            for (const auto& y : pb) consider(x, y);
    } else if (a.is_arc() != b.is_arc()) {
        const Segment& arc = a.is_arc() ? a : b;
        const Segment& line = a.is_arc() ? b : a;
        const Eigen::Vector2d foot = line.from + line_param(line, arc.centre) * (line.to - line.from);
        std::vector<Eigen::Vector2d> pc;
        circle_points(arc, foot - arc.centre, pc);
        for (const auto& x : pc) {
            const Eigen::Vector2d on_line = closest_point(line, x).point;
            if (a.is_arc()) consider(x, on_line);
            else consider(on_line, x);
        }
    }
    best.ta = closest_point(a, best.pa).t;
    best.tb = closest_point(b, best.pb).t;
    return best;
}

}  // namespace qm::geometry
