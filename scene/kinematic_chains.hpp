// scene/kinematic_chains.hpp
// Provides:   kinematic_chains(), the kinematic chains of a set of objects (thesis section 2.4.3,
//             Definition 22; 8.1.4: "the transitive closure of kinematic pairs and common links"):
//             the connected components of the graph whose vertices are the objects (dense ids
//             0..count-1) and whose edges are the kinematic pairs and linkages given. Objects in
//             different chains cannot influence each other, so each chain is solved on its own. The
//             one computation of both drivers: the Alex driver's objects of a scene with the pairs in
//             contact (analysis/), the envisioner's parts of a mechanism with its modelled pairs and
//             shafts (envision/chain.hpp).
// Ownership:  returns values.
// Invariants: the chains partition the objects (an object in no pair is a chain of its own); each
//             chain is in ascending id order, and chains are ordered by their first object.
// Knows nothing of the engine, the ATMS or geometry: an object is only an id.
#pragma once
#include "qm/id.hpp"
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

namespace qm::scene {

// Pre (QM_REQUIRE): every id of `links` is below `count`.
[[nodiscard]] std::vector<std::vector<std::uint32_t>> kinematic_chains(std::size_t count,
                                                                       std::span<const std::pair<std::uint32_t, std::uint32_t>> links);

// The same over the strong ids of one table (scene::ObjectId, geometry::PartId).
template <class Tag>
[[nodiscard]] std::vector<std::vector<Id<Tag>>> kinematic_chains(std::size_t count, const std::vector<std::pair<Id<Tag>, Id<Tag>>>& links) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    edges.reserve(links.size());
    for (const auto& [a, b] : links) edges.emplace_back(a.value, b.value);
    std::vector<std::vector<Id<Tag>>> out;
    for (const auto& chain : kinematic_chains(count, edges)) {
        auto& c = out.emplace_back();
        for (std::uint32_t v : chain) c.push_back(Id<Tag>{v});
    }
    return out;
}

}  // namespace qm::scene
