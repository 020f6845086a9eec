// geometry/profile_pair_oracle.cpp: the exact lines-and-arcs oracle of a pair.
#include "geometry/profile_pair_oracle.hpp"

#include <algorithm>

namespace qm::geometry {

bool ProfilePairOracle::blocked(const Eigen::Vector2d& q) const { return placed_overlap(place(parts_[0], q[0]), place(parts_[1], q[1])); }

double ProfilePairOracle::distance(const Eigen::Vector2d& q) const { return placed_distance(place(parts_[0], q[0]), place(parts_[1], q[1])); }

Eigen::Vector2d ProfilePairOracle::free_normal(const Eigen::Vector2d& q) const { return exact_free_normal(parts_[0], parts_[1], q); }

std::string ProfilePairOracle::fingerprint() const {
    return "exact-profile-pair/1\n" + geometry::fingerprint(parts_[0]) + "\n" + geometry::fingerprint(parts_[1]);
}

namespace {

// Finite differences of the exact distance, one axis at a time; the step grows while both
// probes overlap. Used where the contact has no normal of its own (corner on corner).
Eigen::Vector2d difference_normal(const Part& a, const Part& b, const Eigen::Vector2d& q) {
    const std::array<const Part*, 2> parts{&a, &b};
    const PlacedPart at_a = place(a, q[0]), at_b = place(b, q[1]);
    const double d0 = placed_distance(at_a, at_b);
    Eigen::Vector2d g = Eigen::Vector2d::Zero();
    for (int k = 0; k < 2; ++k) {
        const Part& p = *parts[static_cast<std::size_t>(k)];
        if (p.fixed()) continue;
        const double scale = p.translates() ? std::max(p.size(), 1e-300) : 1.0;
        const double reach = p.rotates() ? p.reach() : 1.0;
        const PlacedPart& other = k == 0 ? at_b : at_a;
        std::vector<SegmentPair> near;
        double near_for = -1;
        for (double h = 1e-6; h < 1e-2; h *= 4) {
            const double step = h * scale, move = step * reach;
            if (move > near_for) {  // only pairs within d0 + 2 move can be nearest after the move
                near_for = 4 * move;
                near = near_pairs(at_a, at_b, d0 + 2 * near_for);
            }
            auto distance_at = [&](double dq) {
                const PlacedPart moved = place(p, q[k] + dq);
                return k == 0 ? distance_over(moved, other, near) : distance_over(other, moved, near);
            };
            const double plus = distance_at(step), minus = distance_at(-step);
            g[k] = (plus - minus) / (2 * step);
            if (plus > 0 || minus > 0) break;
        }
    }
    return g;
}

// Velocity of the world point x of part p per unit of its coordinate.
Eigen::Vector2d velocity(const Part& p, const Eigen::Vector2d& x) {
    if (p.rotates()) return {-(x - p.dof.pivot).y(), (x - p.dof.pivot).x()};
    if (p.translates()) return p.dof.axis;
    return Eigen::Vector2d::Zero();
}

}  // namespace

Eigen::Vector2d exact_free_normal(const Part& a, const Part& b, const Eigen::Vector2d& q) {
    // The gradient of the separation at the contact: with n the unit direction in which a
    // moves away from b there, d(separation) = n . (velocity of a's point dq0 - velocity of b's
    // point dq1). n comes from the exact features: the line between the nearest points when the
    // parts are apart, else the touching surfaces' normals (a configuration found on the
    // tessellated meshes may overlap the exact arcs by a chordal error). No finite difference:
    // a surface along an axis of rotation (an arc about the pivot) gives exactly 0.
    const PlacedPart at_a = place(a, q[0]), at_b = place(b, q[1]);
    const auto c = contact_direction(at_a, at_b, std::max({a.size(), b.size(), 1e-300}));
    if (!c.found) return difference_normal(a, b, q);  // corner exactly on corner
    return {c.n.dot(velocity(a, c.x)), -c.n.dot(velocity(b, c.x))};
}

}  // namespace qm::geometry
