// geometry/build_limits.cpp: the measures of a part that the build limits bound (issue 19 item 1).
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
    // Chords go as 1 / sqrt(tolerance); step up from that estimate until the count fits.
    const double n = chords_needed(p, relative * pair_size);
    double r = n > max_chords_per_part ? relative * (n / max_chords_per_part) * (n / max_chords_per_part) : relative;
    for (int i = 0; i < 64 && chords_needed(p, r * pair_size) > max_chords_per_part; ++i) r *= 1.1;
    return r;
}

}  // namespace qm::geometry
