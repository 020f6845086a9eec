// geometry/kinematic_pairs.hpp
// Provides:   the kinematic pairs of a mechanism that get a configuration space (thesis Def 20:
//             parts form a pair "if they have surface contact or their motion envelopes
//             intersect"; the user names the pairs, 8.1 Figure 8.1 step 1, else every two parts
//             not on one shaft are candidates), and for each pair the FCL oracle and the place
//             request: axes from the parts' degrees of freedom (a rotation wraps at 2 pi, or at one
//             period of its n-fold symmetry, 8.1.6; a window; a translation's limits; a fixed
//             part's coordinate is a dummy periodic axis), tolerances from the settings, and the
//             external place divisions of the forces on either part's shaft (8.2.1).
// Ownership:  values; the oracle is owned by the caller (unique_ptr).
// Invariants: a modelled pair's motion envelopes intersect; a part whose shaft carries a
//             position-dependent force keeps its full turn (one period would lose the division).
// Knows nothing of the ATMS or the engine.
#pragma once
#include "geometry/fcl_pair_oracle.hpp"
#include "geometry/mechanism.hpp"
#include "geometry/place_vocabulary_builder.hpp"
#include <memory>
#include <string>
#include <vector>

namespace qm::geometry {

struct SkippedPair {
    PartId a{0}, b{0};
    std::string reason;
    SourceLocation where;  // of the declared pair, or of the mechanism
};

struct PairSelection {
    std::vector<PairSpec> modelled;
    std::vector<SkippedPair> skipped;  // declared pairs whose envelopes never meet
};

[[nodiscard]] PairSelection kinematic_pairs(const Mechanism& m);
// Are the modelled pairs' grids within max_grid_samples together (build_limits.hpp)? If not, an
// error located at the pair with the largest grid, naming the grid setting, goes to diags.
[[nodiscard]] bool check_grid_limit(const Mechanism& m, const PairSelection& selection, Diagnostics& diags);

// The chordal tolerance (a length) for the pair: the setting times the smaller part's size.
[[nodiscard]] double pair_chordal_tolerance(const Mechanism& m, const PairSpec& pair);
// Pre: the pair's parts have profiles.
[[nodiscard]] std::unique_ptr<FclPairOracle> pair_oracle(const Mechanism& m, const PairSpec& pair);
// pair_oracle(m, pair)'s fingerprint, without building its meshes (a place cache key).
[[nodiscard]] std::string pair_fingerprint(const Mechanism& m, const PairSpec& pair);
[[nodiscard]] PlaceRequest place_request(const Mechanism& m, const PairSpec& pair);

}  // namespace qm::geometry
