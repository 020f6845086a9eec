// cli/explore_data.hpp
// Provides:   write_explore_data(), the data blob of the explorer page (schema qm-explore/1,
//             docs/EXPLORER.md): per kinematic pair its place vocabulary (qm-place-vocabulary/1,
//             the ids of `--places --json`), its configuration-space picture, a drawing of its
//             two parts, and for the parts as drawn and for every place the sample
//             configuration in the scene's units, the parts' SVG transforms there and the
//             contact marks there; the pairs that get no configuration space; the envisionment
//             (qm-envisionment/1, as `envision --json` writes it, or null) and for each of its
//             chains a drawing of its parts, the arrows of their motions and each pair's contact
//             marks at each place in that drawing (cli/state_drawing.hpp composes a state's
//             configuration the same way); and the described behaviours asked for (--path).
// Ownership:  writes to a caller's stream.
// Invariants: the text holds no "</" (written "<\/" inside strings), so it can sit inside an
//             HTML <script> element.
#pragma once
#include "bridge/pair_places.hpp"

#include "envision/envisionment.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/mechanism.hpp"
#include <ostream>
#include <vector>

namespace qm::cli {

struct ExplorePair {
    qm::geometry::PairSpec pair;
    qm::bridge::PairPlaces places;  // built with the sampled space and the oracle
};

// A described behaviour's answer (envision/behaviour_query.hpp), a history the page can play.
struct ExplorePath {
    std::string description;
    std::size_t chain = 0;                       // index into Envisionment::chains
    std::vector<qm::envision::StateId> states;   // the path, or empty when there is none
};

// envisionment: null when not asked for (`--no-envision`).
void write_explore_data(std::ostream& os, const qm::geometry::Mechanism& m, const std::vector<ExplorePair>& pairs,
                        const std::vector<qm::geometry::SkippedPair>& skipped, const qm::envision::Envisionment* envisionment,
                        const std::vector<ExplorePath>& paths);

}  // namespace qm::cli
