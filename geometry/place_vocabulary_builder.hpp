// geometry/place_vocabulary_builder.hpp
// Provides:   build_place_vocabulary(): configuration space (cspace.hpp) -> boundary chains
//             (cspace_boundary.hpp) -> CSEGs grouped by qualitative normal and joins at normal
//             changes (8.1.2, Defs 28-30) -> free space divisions from every significant join
//             along each axis until the next contact (Def 31) -> external place divisions clipped
//             to free space (8.2.1, 9.2) -> crossings and FSD ends as joins -> full faces (Def 32)
//             -> adjacency under every motion (8.1.3, place_adjacency.hpp). The 8.1.6
//             abstractions are settings: one period (a periodic axis shorter than a full turn),
//             merge_epsilon (short runs of a different normal are absorbed), and CSEG grouping
//             by normal, which merges adjacent CSEGs with equal normals.
// Ownership:  the result is a value; the oracle is only used during the call.
// Knows nothing of the ATMS or the engine; never prints.
#pragma once
#include "geometry/cspace.hpp"
#include "geometry/pair_oracle.hpp"
#include "geometry/place_vocabulary.hpp"
#include <string>
#include <vector>

namespace qm::geometry {

// A line q[coordinate] == value where an external force changes (e.g. the pallets' gravity
// flips where they face up); it runs along the other axis and is ignored in blocked space.
struct ExternalDivision {
    int coordinate = 0;
    double value = 0.0;
    std::string label;
};

struct PlaceRequest {
    CSpaceRequest cspace;
    double merge_epsilon = 0.0;  // 8.1.6: a CSEG run shorter than this between two runs of one
                                 // normal takes their normal (0 = keep every run)
    double gap_epsilon = 0.0;    // 8.1.6: a full face narrower than this (configuration units)
                                 // is collapsed with its CSEGs into one place (0 = keep gaps)
    std::vector<ExternalDivision> external;
};

// incomplete: the built adjacency leaves some place without a next place or a constraint under
// some motion (a fault of the builder, not of the request: an internal error for the caller).
enum class PlaceStatus { ok, bad_request, incomplete };

struct PlaceResult {
    PlaceStatus status = PlaceStatus::ok;
    std::string message;
    CSpaceResult space;
    PlaceVocabulary vocabulary;
};

[[nodiscard]] PlaceResult build_place_vocabulary(const PairOracle& oracle, const PlaceRequest& request);

}  // namespace qm::geometry
