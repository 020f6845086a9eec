// geometry/build_limits.hpp
// Provides:   the bounds on what the geometry builds for a metric scene (no crash, ever),
//             and the measures a scene is checked against them with, where it is
//             read (metric_scene_checker.hpp) and after its kinematic pairs are chosen:
//             - a part's size: at least min_part_size, so that lengths, their squares and the
//               tolerances taken relative to them stay normal doubles;
//             - precision: the absolute chordal and contact tolerances of a part's pairs are at
//               least min_tolerance_ulps units in the last place of the coordinates the part
//               reaches as it moves (a tiny part drawn far from the origin has no resolvable
//               outline there);
//             - chords: the arcs of one part, cut into chords for FCL at its pairs' chordal
//               tolerance (relative to the smaller part of the pair), at most max_chords_per_part;
//               FCL's BVH takes about 1.1 KB per chord (docs/METRIC_SCENE_FORMAT.md);
//             - grid samples: all modelled pairs' grids together at most max_grid_samples.
// Ownership:  pure functions of values.
// Invariants: a scene that passes these checks builds FCL models whose preconditions hold
//             (chordal tolerance positive and normal, chords per arc within max_chords_per_arc).
// Knows nothing of FCL, the ATMS or the engine.
#pragma once
#include "geometry/part.hpp"
#include <cstdint>

namespace qm::geometry {

inline constexpr double min_part_size = 1e-60;
inline constexpr double min_tolerance_ulps = 16;
inline constexpr double max_chords_per_part = 262144;  // 2^18: about 0.3 GB of FCL BVH per part
inline constexpr std::uint64_t max_grid_samples = std::uint64_t{4096} * 4096;

// Chords the part's arcs are cut into at an absolute chordal tolerance (tessellate(), profile.hpp),
// straight segments not counted; +inf if the tolerance is not positive. No preconditions.
[[nodiscard]] double chords_needed(const Part& p, double chordal_tolerance) noexcept;
// The largest coordinate magnitude the part's outline reaches at any coordinate of its degree of
// freedom (a bound: pivot distance plus reach for a rotation, the limits added for a translation).
[[nodiscard]] double coordinate_magnitude(const Part& p) noexcept;
// The least absolute tolerance that double arithmetic resolves on coordinates of that magnitude.
[[nodiscard]] double least_resolvable_length(double magnitude) noexcept;
// The least relative chordal tolerance (to a millionth) at which the part needs at most
// max_chords_per_part chords, when its pairs' smaller part has size `pair_size`; `relative`
// itself if that is enough.
[[nodiscard]] double chordal_tolerance_for_limit(const Part& p, double relative, double pair_size) noexcept;

}  // namespace qm::geometry
