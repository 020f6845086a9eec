// bridge/place_correlation.hpp
// Provides:   places_apart(), the metric half of Definition 34 (Correlation) for two kinematic
//             pairs that share a part's coordinate: the pairs of places, one of each, that cannot
//             hold at once because they cover disjoint values of that coordinate. Lines (CSEGs,
//             divisions) and joins cover what their points span (a line's polyline is dense:
//             boundary points a grid edge apart, a division's points at most a quarter period
//             apart, so consecutive points span the short way round); a face what it spans, from
//             its samples out to its bounding places (geometry::Place::covers). Coordinates are
//             compared only when both pairs' axes for the part are the same (same range, both
//             periodic or both bounded): a part seen over one tooth pitch in one pair and over a
//             full turn in the other is at one of several angles for each place, which this does
//             not follow.
//             places_go_round(): whether some places together cover every value of a periodic
//             axis (a coordinate kept within them that never covers some value cannot go round).
// Ownership:  values in, values out.
// Invariants: the result is sorted; a place is never apart from a place whose range it touches to
//             within `slack` (a millionth of the axis' span), so numerical noise never excludes a
//             real combination.
// Knows nothing of the ATMS or the engine.
#pragma once
#include "geometry/cspace.hpp"
#include "geometry/place_vocabulary.hpp"
#include <span>
#include <utility>
#include <vector>

namespace qm::bridge {

// Pre: axis_a / axis_b index the shared coordinate in a's / b's configuration space (0 or 1).
[[nodiscard]] std::vector<std::pair<geometry::PlaceId, geometry::PlaceId>> places_apart(
    const geometry::PlaceVocabulary& a, int axis_a, const geometry::CSpaceAxis& range_a,
    const geometry::PlaceVocabulary& b, int axis_b, const geometry::CSpaceAxis& range_b);

// Pre: every id names a place of v; axis is 0 or 1. A bounded axis never goes round; a place whose
// values are not known is taken to cover them all, so that `false` is never said wrongly.
[[nodiscard]] bool places_go_round(const geometry::PlaceVocabulary& v, std::span<const geometry::PlaceId> places, int axis,
                                   const geometry::CSpaceAxis& range);

}  // namespace qm::bridge
