// cli/explore_data.hpp
// Provides:   write_explore_data(), the data blob of the explorer page (schema qm-explore/1,
//             docs/EXPLORER.md): per kinematic pair its place vocabulary (qm-place-vocabulary/1,
//             the ids of `--places --json`), its configuration-space picture, a drawing of its
//             two parts, and for the parts as drawn and for every place the sample
//             configuration in the scene's units, the parts' SVG transforms there and the
//             contact marks there; the pairs that get no configuration space; and
//             "envisionment": null, the member the envisioner's qm-envisionment/1 will fill.
// Ownership:  writes to a caller's stream.
// Invariants: the text holds no "</" (written "<\/" inside strings), so it can sit inside an
//             HTML <script> element.
#pragma once
#include "pair_places.hpp"

#include "geometry/kinematic_pairs.hpp"
#include "geometry/mechanism.hpp"
#include <ostream>
#include <vector>

namespace qm::cli {

struct ExplorePair {
    qm::geometry::PairSpec pair;
    PairPlaces places;  // built with the sampled space
};

void write_explore_data(std::ostream& os, const qm::geometry::Mechanism& m, const std::vector<ExplorePair>& pairs,
                        const std::vector<qm::geometry::SkippedPair>& skipped);

}  // namespace qm::cli
