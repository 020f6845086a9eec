// geometry/profile.cpp: segments and closed profiles of lines and arcs (thesis 8.1.1 drawings).
#include "geometry/profile.hpp"

#include "qm/assert.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace qm::geometry {
namespace {

constexpr double two_pi = 2 * std::numbers::pi;

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// x mod 2 pi in [0, 2 pi).
double wrap_angle(double x) {
    double r = std::fmod(x, two_pi);
    if (r < 0) r += two_pi;
    return r >= two_pi ? 0.0 : r;
}

}  // namespace

double Segment::start_angle() const noexcept { return std::atan2(from.y() - centre.y(), from.x() - centre.x()); }

double Segment::sweep() const noexcept {
    if (!is_arc()) return 0.0;
    const double a0 = start_angle(), a1 = std::atan2(to.y() - centre.y(), to.x() - centre.x());
    double s = wrap_angle(ccw ? a1 - a0 : a0 - a1);
    if (s == 0.0) s = two_pi;  // from == to: the whole circle
    return ccw ? s : -s;
}

double Segment::length() const noexcept { return is_arc() ? radius() * std::abs(sweep()) : (to - from).norm(); }

Eigen::Vector2d Segment::point_at(double t) const noexcept {
    if (!is_arc()) return from + t * (to - from);
    if (t <= 0) return from;
    if (t >= 1) return to;
    const double a = start_angle() + t * sweep(), r = radius();
    return centre + r * Eigen::Vector2d(std::cos(a), std::sin(a));
}

Eigen::Vector2d Segment::tangent_at(double t) const noexcept {
    if (!is_arc()) {
        const Eigen::Vector2d d = to - from;
        const double n = d.norm();
        return n > 0 ? Eigen::Vector2d(d / n) : Eigen::Vector2d::Zero();
    }
    const double a = start_angle() + std::clamp(t, 0.0, 1.0) * sweep();
    const Eigen::Vector2d radial(std::cos(a), std::sin(a));
    return ccw ? Eigen::Vector2d(-radial.y(), radial.x()) : Eigen::Vector2d(radial.y(), -radial.x());
}

bool Segment::covers_angle(double angle, double slack) const noexcept {
    const double s = std::abs(sweep());
    const double d = wrap_angle(ccw ? angle - start_angle() : start_angle() - angle);
    return d <= s + slack || d >= two_pi - slack;
}

double Segment::param_of_angle(double angle) const noexcept {
    const double s = std::abs(sweep());
    double d = wrap_angle(ccw ? angle - start_angle() : start_angle() - angle);
    if (d > s && d > 0.5 * (s + two_pi)) d -= two_pi;  // just before the start
    return d / s;
}

double signed_area(const Profile& p) noexcept {
    // Green's theorem: half the integral of x dy - y dx; an arc contributes r^2 sweep + c x (to - from).
    double twice = 0;
    for (const auto& s : p.segments) {
        if (s.is_arc()) {
            const double r = s.radius();
            twice += r * r * s.sweep() + cross(s.centre, s.to - s.from);
        } else {
            twice += cross(s.from, s.to);
        }
    }
    return 0.5 * twice;
}

Profile reversed(const Profile& p) {
    Profile out;
    for (auto it = p.segments.rbegin(); it != p.segments.rend(); ++it) {
        Segment s = *it;
        std::swap(s.from, s.to);
        s.ccw = !s.ccw;
        out.segments.push_back(s);
    }
    return out;
}

Profile counter_clockwise(const Profile& p) { return signed_area(p) < 0 ? reversed(p) : p; }

Segment transformed(const Segment& s, const Eigen::Isometry2d& t) noexcept {
    Segment out = s;
    out.from = t * s.from;
    out.to = t * s.to;
    out.centre = t * s.centre;
    if (t.linear().determinant() < 0) out.ccw = !out.ccw;
    return out;
}

Profile transformed(const Profile& p, const Eigen::Isometry2d& t) {
    Profile out;
    out.segments.reserve(p.segments.size());
    for (const auto& s : p.segments) out.segments.push_back(transformed(s, t));
    return out;
}

double reach(const Profile& p, const Eigen::Vector2d& c) noexcept {
    double r = 0;
    for (const auto& s : p.segments) {
        r = std::max({r, (s.from - c).norm(), (s.to - c).norm()});
        if (s.is_arc()) {
            // The farthest point of a circle from c lies on the line through c and the centre.
            const Eigen::Vector2d d = s.centre - c;
            const double a = d.norm() > 0 ? std::atan2(d.y(), d.x()) : s.start_angle();
            if (s.covers_angle(a)) r = std::max(r, d.norm() + s.radius());
        }
    }
    return r;
}

void extend_bounds(const Profile& p, Eigen::Vector2d& lo, Eigen::Vector2d& hi) noexcept {
    for (const auto& s : p.segments) {
        for (const auto& x : {s.from, s.to}) {
            lo = lo.cwiseMin(x);
            hi = hi.cwiseMax(x);
        }
        if (!s.is_arc()) continue;
        for (int k = 0; k < 4; ++k) {  // the arc's extreme points at 0, 90, 180, 270 degrees
            const double a = k * std::numbers::pi / 2;
            if (!s.covers_angle(a)) continue;
            const Eigen::Vector2d x = s.centre + s.radius() * Eigen::Vector2d(std::cos(a), std::sin(a));
            lo = lo.cwiseMin(x);
            hi = hi.cwiseMax(x);
        }
    }
}

Profile circle_profile(const Eigen::Vector2d& c, double r) {
    QM_REQUIRE(r > 0, "a circle needs a positive radius");
    const Eigen::Vector2d e(r, 0);
    return Profile{{Segment::arc(c + e, c - e, c, true), Segment::arc(c - e, c + e, c, true)}};
}

Profile polygon_profile(const std::vector<Eigen::Vector2d>& v) {
    QM_REQUIRE(v.size() >= 3, "a polygon needs three vertices");
    Profile p;
    for (std::size_t i = 0; i < v.size(); ++i) p.segments.push_back(Segment::line(v[i], v[(i + 1) % v.size()]));
    return p;
}

double chord_count(double radius, double sweep, double chordal_tolerance) noexcept {
    if (!(chordal_tolerance > 0)) return std::numeric_limits<double>::infinity();
    if (chordal_tolerance >= radius) return std::max(1.0, std::ceil(std::abs(sweep) / (2 * std::numbers::pi / 3)));
    // A chord of half-angle h deviates r (1 - cos h) = 2 r sin^2(h/2) from its arc; the sine form
    // keeps h exact where 1 - tolerance/r rounds to 1.
    const double h = 2 * std::asin(std::sqrt(chordal_tolerance / (2 * radius)));
    return std::max(1.0, std::ceil(std::abs(sweep) / (2 * h)));
}

int chords_for(double radius, double sweep, double chordal_tolerance) {
    QM_REQUIRE(chordal_tolerance > 0, "chordal tolerance must be positive");
    const double n = chord_count(radius, sweep, chordal_tolerance);
    QM_REQUIRE(n <= max_chords_per_arc, "chordal tolerance too fine for this arc (more than a million chords)");
    return static_cast<int>(n);
}

Polygon tessellate(const Profile& p, double chordal_tolerance, std::vector<int>* first_vertex) {
    Polygon out;
    if (first_vertex) first_vertex->clear();
    for (const auto& s : p.segments) {
        if (first_vertex) first_vertex->push_back(static_cast<int>(out.size()));
        out.push_back(s.from);
        if (!s.is_arc()) continue;
        const int n = chords_for(s.radius(), s.sweep(), chordal_tolerance);
        for (int i = 1; i < n; ++i) out.push_back(s.point_at(static_cast<double>(i) / n));
    }
    return out;
}

}  // namespace qm::geometry
