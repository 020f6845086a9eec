// geometry/profile_pair_oracle.hpp
// Provides:   ProfilePairOracle, the exact PairOracle of two parts drawn with lines and arcs: a
//             configuration is blocked when the exact boundaries meet or one part lies inside the
//             other (placed_part.hpp), and the normal into free space is the gradient of their
//             exact distance. It is slower than FCL and serves as the independent check: the
//             tests compare FCL's classification with it, and the accuracy study measures FCL's
//             boundary error against it (no tessellation on this side).
// Ownership:  owns copies of both parts.
// Invariants: blocked() is a pure function of q; touching counts as blocked here, which moves
//             no boundary point (touching configurations have measure zero).
// Knows nothing of FCL, the ATMS or the engine.
#pragma once
#include "geometry/pair_oracle.hpp"
#include "geometry/part.hpp"
#include "geometry/placed_part.hpp"
#include <array>

namespace qm::geometry {

class ProfilePairOracle final : public PairOracle {
public:
    ProfilePairOracle(Part a, Part b) : parts_{std::move(a), std::move(b)} {}
    [[nodiscard]] bool blocked(const Eigen::Vector2d& q) const override;
    [[nodiscard]] Eigen::Vector2d free_normal(const Eigen::Vector2d& q) const override;
    [[nodiscard]] std::string fingerprint() const override;
    [[nodiscard]] double distance(const Eigen::Vector2d& q) const;
    [[nodiscard]] const Part& part(int which) const { return parts_[static_cast<std::size_t>(which)]; }

private:
    std::array<Part, 2> parts_;
};

// The gradient of the exact distance at q on the free side (central differences whose step grows
// while both probes overlap, so q may lie a little inside blocked space). Shared with the FCL
// oracle, whose normals come from the exact geometry, not from its tessellated meshes.
[[nodiscard]] Eigen::Vector2d exact_free_normal(const Part& a, const Part& b, const Eigen::Vector2d& q);

}  // namespace qm::geometry
