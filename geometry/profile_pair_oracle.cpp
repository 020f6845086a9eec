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
    Eigen::Vector2d g = Eigen::Vector2d::Zero();
    for (int k = 0; k < 2; ++k) {
        const Part& p = *parts[static_cast<std::size_t>(k)];
        if (p.fixed()) continue;
        // Steps in configuration units: radians, or lengths scaled by the part.
        const double scale = p.translates() ? std::max(p.size(), 1e-300) : 1.0;
        const PlacedPart other = place(*parts[static_cast<std::size_t>(1 - k)], q[1 - k]);
        for (double h = 1e-6; h < 1e-2; h *= 4) {
            const double step = h * scale;
            const double plus = placed_distance(k == 0 ? place(p, q[0] + step) : other, k == 0 ? other : place(p, q[1] + step));
            const double minus = placed_distance(k == 0 ? place(p, q[0] - step) : other, k == 0 ? other : place(p, q[1] - step));
            g[k] = (plus - minus) / (2 * step);
            if (plus > 0 || minus > 0) break;
        }
    }
    return g;
}

}  // namespace qm::geometry
