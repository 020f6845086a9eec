// envision/chain.hpp
// Provides:   Chain and kinematic_chains(): the kinematic chains of a mechanism (thesis 8.1.4: "the
//             transitive closure of kinematic pairs and common links"; Def 22), those of
//             scene/kinematic_chains.hpp over the parts with the modelled pairs and the shafts
//             (linkages) as links, each with its pairs. Each chain is envisioned on its own (9.1.3:
//             the clock's ratchet apart from its train); a part in no pair and on no shaft with a
//             paired part is in no chain.
// Ownership:  value types.
// Invariants: every modelled pair is in exactly one chain; chains are ordered by their first pair
//             (declaration order); within a chain the pairs are in breadth-first order from its
//             first pair (8.2.3: "we traverse adjacent kinematic pairs of the place vector in order,
//             as defined by the linkage relation"), and the objects in order of first appearance (a
//             pair's first part, its shaft-mates, its second part, its shaft-mates).
#pragma once
#include "bridge/place_facts.hpp"
#include "geometry/mechanism.hpp"
#include <cstddef>
#include <span>
#include <vector>

namespace qm::envision {

struct Chain {
    std::size_t index = 0;                   // 0-based position among the chains
    std::vector<std::size_t> pairs;          // indices into the mechanism's modelled pairs
    std::vector<geometry::PartId> objects;   // the parts of the chain
    // Position of a part among the objects. Pre: the part is in the chain.
    [[nodiscard]] std::size_t object_index(geometry::PartId p) const;
};

[[nodiscard]] std::vector<Chain> kinematic_chains(const geometry::Mechanism& m, std::span<const bridge::PairPlaces> pairs);

}  // namespace qm::envision
