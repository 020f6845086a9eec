// geometry/polygon_pair.cpp: exact 2-D overlap and distance of polygon sets.
#include "geometry/polygon_pair.hpp"

#include "qm/assert.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace qm::geometry {
namespace {

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

// Proper crossing of open segments pq and rs (endpoints touching does not count).
bool segments_cross(const Eigen::Vector2d& p, const Eigen::Vector2d& q, const Eigen::Vector2d& r,
                    const Eigen::Vector2d& s) {
    const double d1 = cross(q - p, r - p), d2 = cross(q - p, s - p);
    const double d3 = cross(s - r, p - r), d4 = cross(s - r, q - r);
    return ((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0));
}

// Strictly inside (even-odd rule); points on the boundary may go either way, which only moves a
// contact by rounding error.
bool inside(const Polygon& poly, const Eigen::Vector2d& x) {
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const auto& a = poly[i];
        const auto& b = poly[j];
        if ((a.y() > x.y()) != (b.y() > x.y())) {
            const double t = (x.y() - a.y()) / (b.y() - a.y());
            if (x.x() < a.x() + t * (b.x() - a.x())) in = !in;
        }
    }
    return in;
}

double point_segment(const Eigen::Vector2d& x, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    const Eigen::Vector2d ab = b - a;
    const double l2 = ab.squaredNorm();
    const double t = l2 > 0 ? std::clamp((x - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
    return (a + t * ab - x).norm();
}

bool pair_overlaps(const Polygon& a, const Polygon& b) {
    for (std::size_t i = 0; i < a.size(); ++i)
        for (std::size_t j = 0; j < b.size(); ++j)
            if (segments_cross(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()])) return true;
    // No crossing: overlap only if one contains the other (test midpoints of edges, which are
    // robust when vertices touch the other boundary).
    auto mid_inside = [](const Polygon& p, const Polygon& q) {
        for (std::size_t i = 0; i < p.size(); ++i)
            if (inside(q, 0.5 * (p[i] + p[(i + 1) % p.size()]))) return true;
        return false;
    };
    return mid_inside(a, b) || mid_inside(b, a);
}

double radius_of(const PolygonPart& p) {
    double r = 0;
    for (const auto& poly : p.polygons)
        for (const auto& v : poly) r = std::max(r, (v - (p.dof.kind == PolygonDof::Kind::rotation ? p.dof.pivot : Eigen::Vector2d::Zero().eval())).norm());
    return r;
}

}  // namespace

Eigen::Isometry2d pose_at(const PolygonDof& dof, double q) {
    Eigen::Isometry2d t = Eigen::Isometry2d::Identity();
    switch (dof.kind) {
        case PolygonDof::Kind::fixed: break;
        case PolygonDof::Kind::rotation:
            t.translate(dof.pivot);
            t.rotate(q);
            t.translate(-dof.pivot);
            break;
        case PolygonDof::Kind::translation: t.translate(q * dof.axis); break;
    }
    return t;
}

bool polygons_overlap(const std::vector<Polygon>& a, const std::vector<Polygon>& b) {
    for (const auto& pa : a)
        for (const auto& pb : b)
            if (pair_overlaps(pa, pb)) return true;
    return false;
}

double polygons_distance(const std::vector<Polygon>& a, const std::vector<Polygon>& b) {
    if (polygons_overlap(a, b)) return 0.0;
    double d = std::numeric_limits<double>::infinity();
    for (const auto& pa : a)
        for (const auto& pb : b)
            for (std::size_t i = 0; i < pa.size(); ++i)
                for (std::size_t j = 0; j < pb.size(); ++j) {
                    const auto &a0 = pa[i], &a1 = pa[(i + 1) % pa.size()];
                    const auto &b0 = pb[j], &b1 = pb[(j + 1) % pb.size()];
                    d = std::min({d, point_segment(a0, b0, b1), point_segment(a1, b0, b1), point_segment(b0, a0, a1),
                                  point_segment(b1, a0, a1)});
                }
    return d;
}

PolygonPairOracle::PolygonPairOracle(PolygonPart a, PolygonPart b) : parts_{std::move(a), std::move(b)} {
    for (int k = 0; k < 2; ++k) {
        for (const auto& poly : parts_[k].polygons) QM_REQUIRE(poly.size() >= 3, "a polygon needs 3 vertices");
        radius_[k] = radius_of(parts_[k]);
    }
}

std::vector<Polygon> PolygonPairOracle::placed(int which, double q) const {
    const auto& part = parts_[which];
    const Eigen::Isometry2d t = pose_at(part.dof, q);
    std::vector<Polygon> out = part.polygons;
    for (auto& poly : out)
        for (auto& v : poly) v = t * v;
    return out;
}

bool PolygonPairOracle::blocked(const Eigen::Vector2d& q) const {
    const Eigen::Vector2d ca = pose_at(parts_[0].dof, q[0]) *
                               (parts_[0].dof.kind == PolygonDof::Kind::rotation ? parts_[0].dof.pivot : Eigen::Vector2d::Zero().eval());
    const Eigen::Vector2d cb = pose_at(parts_[1].dof, q[1]) *
                               (parts_[1].dof.kind == PolygonDof::Kind::rotation ? parts_[1].dof.pivot : Eigen::Vector2d::Zero().eval());
    if ((ca - cb).norm() > radius_[0] + radius_[1]) return false;
    return polygons_overlap(placed(0, q[0]), placed(1, q[1]));
}

double PolygonPairOracle::distance(const Eigen::Vector2d& q) const {
    return polygons_distance(placed(0, q[0]), placed(1, q[1]));
}

Eigen::Vector2d PolygonPairOracle::free_normal(const Eigen::Vector2d& q) const {
    // The distance is 0 inside blocked space, so a one-sided difference on the side that grows is
    // used per axis: d(q + h) - d(q - h) keeps the right sign even when one side overlaps.
    // When q lies a little inside blocked space (within the boundary tolerance) both probes may
    // overlap; the step then grows until one side is free, so the sign never falls back to 0.
    Eigen::Vector2d g;
    for (int k = 0; k < 2; ++k) {
        g[k] = 0;
        for (double h = 1e-6; h < 1e-2; h *= 4) {
            Eigen::Vector2d e = Eigen::Vector2d::Zero();
            e[k] = h;
            const double plus = distance(q + e), minus = distance(q - e);
            g[k] = (plus - minus) / (2 * h);
            if (plus > 0 || minus > 0) break;
        }
    }
    return g;
}

std::string PolygonPairOracle::fingerprint() const {
    std::ostringstream os;
    os.precision(17);
    os << "polygon-pair";
    for (const auto& part : parts_) {
        os << " part " << static_cast<int>(part.dof.kind) << ' ' << part.dof.pivot.transpose() << ' '
           << part.dof.axis.transpose();
        for (const auto& poly : part.polygons) {
            os << " poly";
            for (const auto& v : poly) os << ' ' << v.x() << ' ' << v.y();
        }
    }
    return os.str();
}

}  // namespace qm::geometry
