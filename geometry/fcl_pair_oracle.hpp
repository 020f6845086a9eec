// geometry/fcl_pair_oracle.hpp
// Provides:   FclPairOracle, the PairOracle of a kinematic pair of parts answered by FCL:
//             blocked(q) is FCL's collision test on the two extruded meshes
//             (fcl_part_model.hpp) placed at the pair's configuration q = (q0, q1), i.e. the sign
//             of their signed distance, so grid classification and boundary bisection both run
//             on FCL; free_normal(q) is the gradient of the exact distance of the parts' lines and
//             arcs on the free side (profile_pair_oracle.hpp): the normal into free space taken
//             from the geometry, not from the grid, and not from the chords of the meshes.
// Ownership:  owns copies of both parts and their FCL models.
// Invariants: blocked() is a pure function of q, periodic in a rotation coordinate (2 pi); a
//             fixed part ignores its coordinate. The fingerprint names the exact geometry, the
//             degrees of freedom and the chordal tolerance, so a cached vocabulary is reused only
//             for the same pair and settings.
// Knows nothing of the ATMS or the engine. The exact polygon oracle (polygon_pair.hpp) on the
// same tessellation is the independent check of this oracle in the tests.
#pragma once
#include "geometry/fcl_part_model.hpp"
#include "geometry/pair_oracle.hpp"
#include "geometry/part.hpp"
#include <array>
#include <atomic>
#include <string>

namespace qm::geometry {

class FclPairOracle final : public PairOracle {
public:
    // Pre: chordal_tolerance > 0 (a length); both parts have profiles.
    FclPairOracle(const Part& a, const Part& b, double chordal_tolerance);
    [[nodiscard]] bool blocked(const Eigen::Vector2d& q) const override;
    [[nodiscard]] Eigen::Vector2d free_normal(const Eigen::Vector2d& q) const override;
    [[nodiscard]] std::string fingerprint() const override;
    // The fingerprint of the oracle these arguments would build, without building its meshes (a
    // place cache can be consulted before paying for them).
    [[nodiscard]] static std::string fingerprint_of(const Part& a, const Part& b, double chordal_tolerance);
    // FCL's distance between the placed parts when apart; -1 when FCL reports a collision (a
    // mesh pair gives no penetration depth, only the sign).
    [[nodiscard]] double signed_distance(const Eigen::Vector2d& q) const;
    // Does moving the first part by some translation of length `depth` (probed in 32 directions,
    // and at a quarter of it) part them? An estimate of "penetration depth <= depth", whatever
    // the parts' degrees of freedom.
    [[nodiscard]] bool separable_within(const Eigen::Vector2d& q, double depth) const;
    // Pre: which is 0 or 1.
    [[nodiscard]] const FclPartModel& model(int which) const { return models_[static_cast<std::size_t>(which)]; }
    [[nodiscard]] const Part& part(int which) const { return models_[static_cast<std::size_t>(which)].part(); }
    // Configuration units per length along coordinate k: 1 for a rotation, the part's size for a
    // translation (finite-difference steps and tolerances scale with it).
    [[nodiscard]] double coordinate_scale(int which) const;
    [[nodiscard]] std::uint64_t fcl_calls() const noexcept { return calls_.load(); }

private:
    [[nodiscard]] bool far_apart(const Eigen::Vector2d& q) const;
    std::array<FclPartModel, 2> models_;
    double chordal_tolerance_;
    std::array<double, 2> reach_{};  // about the pose's centre (pivot or bounding box centre)
    std::array<Eigen::Vector2d, 2> centre_;
    mutable std::atomic<std::uint64_t> calls_{0};
};

}  // namespace qm::geometry
