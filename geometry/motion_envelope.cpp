// geometry/motion_envelope.cpp: Def 20 motion envelopes as disks and capsules.
#include "geometry/motion_envelope.hpp"

#include "qm/assert.hpp"

#include <algorithm>
#include <cmath>

namespace qm::geometry {
namespace {

double point_segment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Eigen::Vector2d ab = b - a;
    const double l2 = ab.squaredNorm();
    const double t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    return (a + t * ab - p).norm();
}

double cross(const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); }

double segment_segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c, const Eigen::Vector2d& d) {
    const double d1 = cross(b - a, c - a), d2 = cross(b - a, d - a), d3 = cross(d - c, a - c), d4 = cross(d - c, b - c);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 0.0;
    return std::min({point_segment(a, c, d), point_segment(b, c, d), point_segment(c, a, b), point_segment(d, a, b)});
}

}  // namespace

MotionEnvelope envelope_of(const PolygonPart& part, double lo, double hi) {
    QM_REQUIRE(lo <= hi, "translation range must not be empty");
    // Centre: the pivot for a rotation, else the vertices' bounding-box centre.
    Eigen::Vector2d mn(1e300, 1e300), mx(-1e300, -1e300);
    for (const auto& poly : part.polygons)
        for (const auto& v : poly) {
            mn = mn.cwiseMin(v);
            mx = mx.cwiseMax(v);
        }
    const Eigen::Vector2d centre = part.dof.kind == PolygonDof::Kind::rotation ? part.dof.pivot : Eigen::Vector2d(0.5 * (mn + mx));
    double r = 0;
    for (const auto& poly : part.polygons)
        for (const auto& v : poly) r = std::max(r, (v - centre).norm());
    MotionEnvelope e{centre, centre, r};
    if (part.dof.kind == PolygonDof::Kind::translation) {
        e.a = centre + lo * part.dof.axis;
        e.b = centre + hi * part.dof.axis;
    }
    return e;
}

bool envelopes_intersect(const MotionEnvelope& x, const MotionEnvelope& y) noexcept {
    return segment_segment(x.a, x.b, y.a, y.b) <= x.radius + y.radius;
}

}  // namespace qm::geometry
