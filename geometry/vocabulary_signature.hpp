// geometry/vocabulary_signature.hpp
// Provides:   vocabulary_signature(), a text that two place vocabularies share when they are the
//             same up to the numbering of their places, adjacency included (a
//             vocabulary must not change with the grid, nor when the scene is moved, turned or
//             scaled). Each place starts from its own description (kind, join kind, normals as a
//             set, concavity, axis, label, gap flag); colour refinement (Weisfeiler-Leman) then
//             mixes in, round by round, the descriptions of the places it is adjacent to and from,
//             with each adjacency's motion and flags, until the partition stops splitting. The
//             signature is the sorted multiset of the final colours, prefixed by the counts of
//             each kind. Equal vocabularies always give equal signatures; different ones give
//             different signatures unless colour refinement cannot tell them apart (graphs that
//             are regular in every label, which place vocabularies with their many kinds of
//             places and eight motions are not in practice) or 64-bit hashes collide.
//             vocabulary_difference() says, for a report, how two signatures differ.
// Ownership:  values.
// Knows nothing of the ATMS or the engine.
#pragma once
#include "geometry/place_vocabulary.hpp"
#include <string>

namespace qm::geometry {

[[nodiscard]] std::string vocabulary_signature(const PlaceVocabulary& v);
// A short description of how two signatures differ (the counts line, and how many colours
// occur in one and not the other); empty if they are equal.
[[nodiscard]] std::string vocabulary_difference(const std::string& a, const std::string& b);
// Each place's own description, as used for the first colours (for messages).
[[nodiscard]] std::string place_description(const Place& p);

}  // namespace qm::geometry
