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

Eigen::Vector2d exact_free_normal(const Part& a, const Part& b, const Eigen::Vector2d& q) {
    const std::array<const Part*, 2> parts{&a, &b};
    const PlacedPart at_a = place(a, q[0]), at_b = place(b, q[1]);
    const double d0 = placed_distance(at_a, at_b);
    Eigen::Vector2d g = Eigen::Vector2d::Zero();
    for (int k = 0; k < 2; ++k) {
        const Part& p = *parts[static_cast<std::size_t>(k)];
        if (p.fixed()) continue;
        // Steps in configuration units: radians, or lengths scaled by the part. A step moves no
        // point of the part farther than `reach` times it.
        const double scale = p.translates() ? std::max(p.size(), 1e-300) : 1.0;
        const double reach = p.rotates() ? p.reach() : 1.0;
        const PlacedPart& other = k == 0 ? at_b : at_a;
        std::vector<SegmentPair> near;
        double near_for = -1;  // the largest move `near` is valid for
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

}  // namespace qm::geometry
