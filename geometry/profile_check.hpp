// geometry/profile_check.hpp
// Provides:   check_profile(), which finds what makes a drawn profile unusable as the boundary of
//             a solid: too few segments, a segment of zero length, an arc whose
//             ends are not on one circle, a gap (the profile is open), or two segments that
//             cross, touch or double back (the profile intersects itself); and
//             check_profiles_apart(), which finds two profiles of one part that overlap.
// Ownership:  value results only.
// Invariants: a profile with no problem is closed and simple, so its enclosed area is nonzero
//             and counter_clockwise() orients it.
// Knows nothing of FCL, the ATMS or the engine; never prints: problems come back as text.
#pragma once
#include "geometry/profile.hpp"
#include <optional>
#include <string>
#include <vector>

namespace qm::geometry {

struct ProfileProblem {
    enum class Kind { too_few_segments, degenerate_segment, bad_arc, open, self_intersecting, overlapping_profiles };
    Kind kind = Kind::open;
    int segment = -1;       // the first segment concerned (0-based), or -1
    int other = -1;         // the second, or -1
    std::string message;    // a sentence for a diagnostic
};

// `eps` is the length below which two points are the same (e.g. 1e-9 x the part's size).
// Pre: eps > 0.
[[nodiscard]] std::optional<ProfileProblem> check_profile(const Profile& p, double eps);

// Two profiles of one part must neither cross nor lie one inside the other (a part is the union
// of its profiles; holes are not modelled). `other` names the second profile's index.
// Pre: every profile passed check_profile.
[[nodiscard]] std::optional<ProfileProblem> check_profiles_apart(const std::vector<Profile>& profiles, double eps);

// Is x strictly inside the closed profile (exact: crossings of a ray with lines and arcs)?
[[nodiscard]] bool inside(const Profile& p, const Eigen::Vector2d& x);

}  // namespace qm::geometry
