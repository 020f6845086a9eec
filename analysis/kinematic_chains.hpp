// analysis/kinematic_chains.hpp
// Provides:   kinematic_chains(), the kinematic chains of a situation (thesis section 2.4.3,
//             Definition 22: the closure of kinematic pairs): the connected components of the graph
//             whose vertices are the scene's objects and whose edges are the pairs in contact and
//             the linkages. Objects in different chains cannot influence each other, so each chain
//             is solved on its own ("model only what a scene needs").
// Ownership:  returns values.
// Invariants: the chains partition the objects; each chain is in ascending id order, and chains
//             are ordered by their first object.
#pragma once
#include "analysis/fwd.hpp"
#include "scene/scene.hpp"
#include <span>
#include <utility>
#include <vector>

namespace qm::analysis {
[[nodiscard]] std::vector<std::vector<ObjectId>> kinematic_chains(std::size_t object_count,
                                                                  std::span<const std::pair<ObjectId, ObjectId>> pairs);
}  // namespace qm::analysis
