// geometry/contact_place.hpp
// Provides:   contact_place(), the place vocabulary of a pair whose free space has no area: gears
//             drawn meshing with zero play, a part sliding on another along its whole axis (a
//             block on a table, Figure 2.3). The grid then sees no free sample (touching counts as
//             blocked, and a curve has measure zero), yet the parts can move while in contact.
//             Section 8.1.6 collapses a gap narrower than epsilon with the CSEGs bounding it into
//             one place; zero play is the limit of that, so the answer is the same single place: a
//             face marked gap, with the configuration-space normals of its contacts, where a motion
//             that keeps every contact (its qualitative dot product with each normal is not
//             definitely negative: the liberal bias of section 7.3) stays (interval), and every
//             other motion is constrained.
//             The contacts are those of the drawn configuration (each coordinate 0, clamped to its
//             axis); if the parts overlap there, or do not touch, there is no such place.
// Ownership:  returns values.
// Invariants: a returned vocabulary has exactly one place (a gap face) and one adjacency for each
//             of the eight non-zero motions, from the place to itself.
// Knows nothing of the ATMS or the engine; never prints.
#pragma once
#include "geometry/contact_detection.hpp"
#include "geometry/place_vocabulary_builder.hpp"
#include <optional>

namespace qm::geometry {

// Pre: the request's axes are the pair's (place_request()); contact tolerances positive.
[[nodiscard]] std::optional<PlaceVocabulary> contact_place(const FclPairOracle& pair, const PlaceRequest& request,
                                                           const ContactRequest& contact);

}  // namespace qm::geometry
