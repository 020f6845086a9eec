// geometry/closed_form_pairs.cpp: the four closed-form pairs of the accuracy study.
#include "geometry/closed_form_pairs.hpp"

#include "qm/assert.hpp"

#include <cmath>
#include <numbers>

namespace qm::geometry {
namespace {

constexpr double pi = std::numbers::pi;

Polygon rectangle(double x0, double y0, double x1, double y1) { return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}; }

Part part(std::vector<Profile> profiles, PolygonDof dof, const CSpaceAxis& axis) {
    Part p;
    p.name = "part";
    for (auto& x : profiles) p.profiles.push_back(counter_clockwise(x));
    p.dof = dof;
    p.lo = axis.lo;
    p.hi = axis.hi;
    return p;
}

// The stadium of stadium() below, exactly: two lines and two half circles.
Profile stadium_profile(double length, double r) {
    return Profile{{Segment::line({0, -r}, {length, -r}), Segment::arc({length, -r}, {length, r}, {length, 0}, true),
                    Segment::line({length, r}, {0, r}), Segment::arc({0, r}, {0, -r}, {0, 0}, true)}};
}

CSpaceAxis rotation_axis() { return CSpaceAxis{-pi, pi, true, 64}; }
CSpaceAxis translation_axis(double lo, double hi) { return CSpaceAxis{lo, hi, false, 64}; }

// A stadium (bar with round ends) from (0,0) to (length,0), half-width r, arcs tessellated.
Polygon stadium(double length, double r, double chordal_tolerance) {
    const int n = std::max(2, static_cast<int>(std::ceil(pi / (2 * std::acos(std::max(-1.0, 1 - chordal_tolerance / r))))));
    Polygon p;
    for (int i = 0; i <= n; ++i) {  // right cap, from -90 to +90 degrees
        const double a = -pi / 2 + pi * i / n;
        p.emplace_back(length + r * std::cos(a), r * std::sin(a));
    }
    for (int i = 0; i <= n; ++i) {  // left cap, from 90 to 270 degrees
        const double a = pi / 2 + pi * i / n;
        p.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    return p;
}

}  // namespace

Polygon tessellated_circle(const Eigen::Vector2d& centre, double radius, double chordal_tolerance) {
    QM_REQUIRE(radius > 0 && chordal_tolerance > 0, "radius and chordal tolerance must be positive");
    // A chord of half-angle a deviates radius*(1 - cos a) from its arc.
    const double a = std::acos(std::max(-1.0, 1 - chordal_tolerance / radius));
    const int n = std::max(3, static_cast<int>(std::ceil(pi / a)));
    Polygon p;
    for (int i = 0; i < n; ++i) {
        const double t = 2 * pi * i / n;
        p.push_back(centre + radius * Eigen::Vector2d(std::cos(t), std::sin(t)));
    }
    return p;
}

double AnalyticOracle::crossing_error(const Eigen::Vector2d& q, int axis) const {
    Eigen::Vector2d x = q;
    for (int it = 0; it < 100; ++it) {
        const double fx = f_(x);
        const double g = grad_(x)[axis];
        if (g == 0.0) break;
        const double dx = fx / g;
        x[axis] -= dx;
        if (std::abs(dx) < 1e-16 * (1 + std::abs(x[axis]))) break;
    }
    return std::abs(x[axis] - q[axis]);
}

// Bar (stadium of length L, half-width r) turning about the origin against a block whose face
// x = s translates along x: f = max(L cos q0, 0) + r - s.
ClosedFormPair bar_and_block() {
    static constexpr double L = 1.0, r = 0.1;
    AnalyticOracle exact(
        "bar-and-block",
        [](const Eigen::Vector2d& q) { return std::max(L * std::cos(q[0]), 0.0) + r - q[1]; },
        [](const Eigen::Vector2d& q) {
            return Eigen::Vector2d(std::cos(q[0]) > 0 ? -L * std::sin(q[0]) : 0.0, -1.0);
        });
    auto tess = [](double tol) {
        PolygonPart bar{{stadium(L, r, tol)}, {PolygonDof::Kind::rotation, {0, 0}, {1, 0}}};
        PolygonPart block{{rectangle(0, -3, 3, 3)}, {PolygonDof::Kind::translation, {0, 0}, {1, 0}}};
        return PolygonPairOracle(bar, block);
    };
    const std::array<CSpaceAxis, 2> axes{rotation_axis(), translation_axis(0.6, 1.3)};
    return {"bar-and-block", exact, axes, tess,
            {part({stadium_profile(L, r)}, {PolygonDof::Kind::rotation, {0, 0}, {1, 0}}, axes[0]),
             part({polygon_profile(rectangle(0, -3, 3, 3))}, {PolygonDof::Kind::translation, {0, 0}, {1, 0}}, axes[1])}};
}

// Disk cam (radius R, centre at eccentricity e from the pivot) under a flat follower whose lower
// face y = h translates along y: f = e sin q0 + R - h.
ClosedFormPair disk_cam_and_follower() {
    static constexpr double R = 0.5, e = 0.2;
    AnalyticOracle exact(
        "disk-cam-and-follower", [](const Eigen::Vector2d& q) { return e * std::sin(q[0]) + R - q[1]; },
        [](const Eigen::Vector2d& q) { return Eigen::Vector2d(e * std::cos(q[0]), -1.0); });
    auto tess = [](double tol) {
        PolygonPart cam{{tessellated_circle({e, 0}, R, tol)}, {PolygonDof::Kind::rotation, {0, 0}, {1, 0}}};
        PolygonPart follower{{rectangle(-2, 0, 2, 1)}, {PolygonDof::Kind::translation, {0, 0}, {0, 1}}};
        return PolygonPairOracle(cam, follower);
    };
    const std::array<CSpaceAxis, 2> axes{rotation_axis(), translation_axis(0.2, 1.0)};
    return {"disk-cam-and-follower", exact, axes, tess,
            {part({circle_profile({e, 0}, R)}, {PolygonDof::Kind::rotation, {0, 0}, {1, 0}}, axes[0]),
             part({polygon_profile(rectangle(-2, 0, 2, 1))}, {PolygonDof::Kind::translation, {0, 0}, {0, 1}}, axes[1])}};
}

// Two eccentric disks on pivots (0,0) and (D,0): f = Ra + Rb - |cA(q0) - cB(q1)|.
ClosedFormPair two_disks() {
    static constexpr double Ra = 0.5, ea = 0.3, Rb = 0.4, eb = 0.3, D = 1.4;
    auto ca = [](double t) { return Eigen::Vector2d(ea * std::cos(t), ea * std::sin(t)); };
    auto cb = [](double t) { return Eigen::Vector2d(D + eb * std::cos(t), eb * std::sin(t)); };
    AnalyticOracle exact(
        "two-disks", [=](const Eigen::Vector2d& q) { return Ra + Rb - (ca(q[0]) - cb(q[1])).norm(); },
        [=](const Eigen::Vector2d& q) {
            const Eigen::Vector2d d = ca(q[0]) - cb(q[1]);
            const Eigen::Vector2d u = d / d.norm();
            const Eigen::Vector2d va(-ea * std::sin(q[0]), ea * std::cos(q[0]));
            const Eigen::Vector2d vb(-eb * std::sin(q[1]), eb * std::cos(q[1]));
            return Eigen::Vector2d(-u.dot(va), u.dot(vb));
        });
    auto tess = [](double tol) {
        PolygonPart a{{tessellated_circle({ea, 0}, Ra, tol)}, {PolygonDof::Kind::rotation, {0, 0}, {1, 0}}};
        PolygonPart b{{tessellated_circle({D + eb, 0}, Rb, tol)}, {PolygonDof::Kind::rotation, {D, 0}, {1, 0}}};
        return PolygonPairOracle(a, b);
    };
    const std::array<CSpaceAxis, 2> axes{rotation_axis(), rotation_axis()};
    return {"two-disks", exact, axes, tess,
            {part({circle_profile({ea, 0}, Ra)}, {PolygonDof::Kind::rotation, {0, 0}, {1, 0}}, axes[0]),
             part({circle_profile({D + eb, 0}, Rb)}, {PolygonDof::Kind::rotation, {D, 0}, {1, 0}}, axes[1])}};
}

// Crank pin (radius r at crank radius c) in the vertical slot (width w) of a yoke translating
// along x: free iff |c cos q0 - s| <= w/2 - r, f = |c cos q0 - s| + r - w/2.
ClosedFormPair pin_in_slot() {
    static constexpr double c = 0.6, r = 0.1, w = 0.3;
    AnalyticOracle exact(
        "pin-in-slot", [](const Eigen::Vector2d& q) { return std::abs(c * std::cos(q[0]) - q[1]) + r - w / 2; },
        [](const Eigen::Vector2d& q) {
            const double sg = c * std::cos(q[0]) - q[1] >= 0 ? 1.0 : -1.0;
            return Eigen::Vector2d(-sg * c * std::sin(q[0]), -sg);
        });
    auto tess = [](double tol) {
        PolygonPart pin{{tessellated_circle({c, 0}, r, tol)}, {PolygonDof::Kind::rotation, {0, 0}, {1, 0}}};
        PolygonPart yoke{{rectangle(-w / 2 - 3, -2, -w / 2, 2), rectangle(w / 2, -2, w / 2 + 3, 2)},
                         {PolygonDof::Kind::translation, {0, 0}, {1, 0}}};
        return PolygonPairOracle(pin, yoke);
    };
    const std::array<CSpaceAxis, 2> axes{rotation_axis(), translation_axis(-0.8, 0.8)};
    return {"pin-in-slot", exact, axes, tess,
            {part({circle_profile({c, 0}, r)}, {PolygonDof::Kind::rotation, {0, 0}, {1, 0}}, axes[0]),
             part({polygon_profile(rectangle(-w / 2 - 3, -2, -w / 2, 2)), polygon_profile(rectangle(w / 2, -2, w / 2 + 3, 2))},
                  {PolygonDof::Kind::translation, {0, 0}, {1, 0}}, axes[1])}};
}

}  // namespace qm::geometry
