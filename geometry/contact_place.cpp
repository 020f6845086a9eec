// geometry/contact_place.cpp: the single place of a pair that moves only in contact (8.1.6 with
// zero play). Each contact's normal in configuration space is the gradient of its gap: a point on
// part k moves with velocity v_k per unit of q_k (a turn about the pivot, or the axis), so the gap
// along part a's outward normal n grows at n.(v_b dq1 - v_a dq0).
#include "geometry/contact_place.hpp"

#include <algorithm>

namespace qm::geometry {
namespace {

// Velocity of a world point carried by the part, per unit of its coordinate.
Eigen::Vector2d point_velocity(const Part& p, const Eigen::Vector2d& x) {
    if (p.rotates()) return {-(x.y() - p.dof.pivot.y()), x.x() - p.dof.pivot.x()};
    if (p.translates()) return p.dof.axis;
    return Eigen::Vector2d::Zero();
}

// Part a's outward normal at the contact, pointing into part b: a surface's own normal, else the
// reverse of the surface it touches (a corner against a face, 3.1.1); two corners give none.
std::optional<Eigen::Vector2d> contact_normal(const Contact& c) {
    if (c.first.kind == FeatureKind::surface) return c.first.normal;
    if (c.second.kind == FeatureKind::surface) return Eigen::Vector2d(-c.second.normal);
    return std::nullopt;
}

double clamp_to(const CSpaceAxis& a, double x) { return a.periodic ? x : std::clamp(x, a.lo, a.hi); }

}  // namespace

std::optional<PlaceVocabulary> contact_place(const FclPairOracle& pair, const PlaceRequest& request, const ContactRequest& contact) {
    const Eigen::Vector2d q(clamp_to(request.cspace.axes[0], 0.0), clamp_to(request.cspace.axes[1], 0.0));
    const ContactResult found = detect_contacts(pair, q, contact);
    if (found.status != ContactStatus::ok || found.contacts.empty()) return std::nullopt;

    // The gap gradients, each relative to the pair's size so that the zero test is scale-free.
    const double scale = std::max({pair.part(0).size(), pair.part(1).size(), 1e-300});
    std::vector<QualDirection> normals;
    for (const Contact& c : found.contacts) {
        const auto n = contact_normal(c);
        if (!n) continue;
        const Eigen::Vector2d gradient(-n->dot(point_velocity(pair.part(0), c.first.point)),
                                       n->dot(point_velocity(pair.part(1), c.second.point)));
        if (gradient.norm() <= request.cspace.normal_zero_tolerance * scale) continue;  // slides freely
        const QualDirection d = qualitative(gradient, request.cspace.normal_zero_tolerance);
        if (std::find(normals.begin(), normals.end(), d) == normals.end()) normals.push_back(d);
    }
    std::sort(normals.begin(), normals.end());

    PlaceVocabulary v;
    Place p;
    p.id = PlaceId{0};
    p.kind = PlaceKind::face;
    p.gap = true;
    p.normals = normals;
    p.points = {q};
    v.places.push_back(p);
    for (std::int8_t s0 = -1; s0 <= 1; ++s0)
        for (std::int8_t s1 = -1; s1 <= 1; ++s1) {
            const QualDirection d{{s0, s1}};
            if (d == QualDirection{}) continue;
            const bool keeps = std::none_of(normals.begin(), normals.end(), [&](QualDirection n) { return qdot(n, d) == QualSign::neg; });
            v.adjacency.push_back({PlaceId{0}, PlaceId{0}, d, false, !keeps});
        }
    return v;
}

}  // namespace qm::geometry
