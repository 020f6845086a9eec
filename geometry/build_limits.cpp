// geometry/build_limits.cpp: the measures of a part that the build limits bound.
#include "geometry/build_limits.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace qm::geometry {

double chords_needed(const Part& p, double chordal_tolerance) noexcept {
    double n = 0;
    for (const auto& profile : p.profiles)
        for (const auto& s : profile.segments)
            if (s.is_arc()) n += chord_count(s.radius(), s.sweep(), chordal_tolerance);
    return n;
}

double coordinate_magnitude(const Part& p) noexcept {
    const double big = std::numeric_limits<double>::infinity();
    Eigen::Vector2d lo(big, big), hi(-big, -big);
    for (const auto& profile : p.profiles) extend_bounds(profile, lo, hi);
    if (p.profiles.empty()) return 0.0;
    const double drawn = std::max({std::abs(lo.x()), std::abs(lo.y()), std::abs(hi.x()), std::abs(hi.y())});
    if (p.rotates()) return std::max(std::abs(p.dof.pivot.x()), std::abs(p.dof.pivot.y())) + p.reach();
    if (p.translates()) return drawn + std::max(std::abs(p.lo), std::abs(p.hi));
    return drawn;
}

double least_resolvable_length(double magnitude) noexcept {
    return min_tolerance_ulps * std::numeric_limits<double>::epsilon() * std::max(magnitude, std::numeric_limits<double>::min());
}

double chordal_tolerance_for_limit(const Part& p, double relative, double pair_size) noexcept {
    // The count falls as the tolerance grows: bisect (in log space) for the least tolerance at
    // which it fits, to a millionth.
    if (chords_needed(p, relative * pair_size) <= max_chords_per_part) return relative;
    double lo = relative, hi = 2 * relative;
    while (chords_needed(p, hi * pair_size) > max_chords_per_part && hi < 1e300) hi *= 2;
    while (hi / lo > 1 + 1e-6) {
        const double mid = std::sqrt(lo * hi);
        (chords_needed(p, mid * pair_size) > max_chords_per_part ? lo : hi) = mid;
    }
    return hi;
}

}  // namespace qm::geometry
