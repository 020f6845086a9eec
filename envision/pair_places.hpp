// envision/pair_places.hpp
// Provides:   load_pair_places(), the place vocabulary of every kinematic pair of a mechanism (Def
//             20, thesis 8.1 Figure 8.1 steps 2-3), from the on-disk cache when the same pair and
//             settings were computed before (8.1.3: "Place vocabulary representations of kinematic
//             pairs may be precomputed ... and then stored"), with the forces by place beside it.
//             A pair drawn meshing with zero play gets the single gap place (docs/PLACES.md, "Zero
//             play").
// Errors:     bad input, located at the pair (or the mechanism): a mechanism with no kinematic
//             pair; a declared pair whose parts can never touch (motion envelopes apart) or whose
//             whole configuration space is one free place; a pair with no free space that is not
//             drawn in contact. Nothing is returned then.
// Knows no law.
#pragma once
#include "bridge/place_facts.hpp"
#include "geometry/mechanism.hpp"
#include "geometry/place_cache.hpp"
#include "qm/diagnostics.hpp"
#include <optional>
#include <vector>

namespace qm::envision {

[[nodiscard]] std::optional<std::vector<bridge::PairPlaces>> load_pair_places(const geometry::Mechanism& m,
                                                                              const geometry::PlaceCache* cache,
                                                                              Diagnostics& diagnostics);

}  // namespace qm::envision
