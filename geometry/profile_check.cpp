// geometry/profile_check.cpp: closed, simple profiles (open or self-intersecting profiles are
// bad input).
#include "geometry/profile_check.hpp"

#include "geometry/segment_queries.hpp"
#include "qm/assert.hpp"

#include <cmath>
#include <sstream>

namespace qm::geometry {
namespace {

std::string point_text(const Eigen::Vector2d& x) {
    std::ostringstream os;
    os.precision(6);
    os << '(' << x.x() << ' ' << x.y() << ')';
    return os.str();
}

ProfileProblem problem(ProfileProblem::Kind k, int a, int b, std::string msg) { return {k, a, b, std::move(msg)}; }

}  // namespace

std::optional<ProfileProblem> check_profile(const Profile& p, double eps) {
    QM_REQUIRE(eps > 0, "check_profile needs a positive eps");
    const auto& s = p.segments;
    const int n = static_cast<int>(s.size());
    if (n < 2 || (n == 2 && !s[0].is_arc() && !s[1].is_arc()))
        return problem(ProfileProblem::Kind::too_few_segments, -1, -1, "a profile needs at least two segments enclosing an area");
    for (int i = 0; i < n; ++i) {
        const auto& x = s[static_cast<std::size_t>(i)];
        if ((x.to - x.from).norm() <= eps && !(x.is_arc() && x.radius() > eps))
            return problem(ProfileProblem::Kind::degenerate_segment, i, -1, "segment " + std::to_string(i + 1) + " has zero length");
        if (x.is_arc()) {
            const double r0 = (x.from - x.centre).norm(), r1 = (x.to - x.centre).norm();
            if (r0 <= eps || std::abs(r0 - r1) > std::max(eps, 1e-6 * r0))  // ends on one circle, to 1e-6 relative
                return problem(ProfileProblem::Kind::bad_arc, i, -1,
                               "arc " + std::to_string(i + 1) + " does not lie on one circle: its ends are " + std::to_string(r0) +
                                   " and " + std::to_string(r1) + " from its centre");
            if ((x.to - x.from).norm() <= eps)
                return problem(ProfileProblem::Kind::degenerate_segment, i, -1,
                               "arc " + std::to_string(i + 1) + " ends where it begins; write a circle as two arcs");
        }
    }
    for (int i = 0; i < n; ++i) {
        const auto& a = s[static_cast<std::size_t>(i)];
        const auto& b = s[static_cast<std::size_t>((i + 1) % n)];
        if ((a.to - b.from).norm() > eps)
            return problem(ProfileProblem::Kind::open, i, (i + 1) % n,
                           "the profile is open: segment " + std::to_string(i + 1) + " ends at " + point_text(a.to) + " but segment " +
                               std::to_string((i + 1) % n + 1) + " begins at " + point_text(b.from));
    }
    // Two segments may share only the vertices where they join (far from them: 1e3 eps, since
    // two segments meeting at a sharp angle stay within eps of each other near their vertex).
    const double near = 1e3 * eps;
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j) {
            const auto& a = s[static_cast<std::size_t>(i)];
            const auto& b = s[static_cast<std::size_t>(j)];
            const auto meet = intersections(a, b, eps);
            const std::string which = "segments " + std::to_string(i + 1) + " and " + std::to_string(j + 1);
            if (meet.overlap)
                return problem(ProfileProblem::Kind::self_intersecting, i, j, "the profile intersects itself: " + which + " run along each other");
            std::vector<Eigen::Vector2d> shared;
            if (j == i + 1) shared.push_back(a.to);
            if (i == 0 && j == n - 1) shared.push_back(a.from);
            for (const auto& x : meet.points) {
                bool at_vertex = false;
                for (const auto& v : shared) at_vertex = at_vertex || (x.point - v).norm() <= near;
                if (!at_vertex)
                    return problem(ProfileProblem::Kind::self_intersecting, i, j,
                                   "the profile intersects itself: " + which + " meet at " + point_text(x.point));
            }
        }
    if (std::abs(signed_area(p)) <= eps * eps)
        return problem(ProfileProblem::Kind::self_intersecting, -1, -1, "the profile encloses no area");
    return std::nullopt;
}

std::optional<ProfileProblem> check_profiles_apart(const std::vector<Profile>& profiles, double eps) {
    for (std::size_t i = 0; i < profiles.size(); ++i)
        for (std::size_t j = i + 1; j < profiles.size(); ++j) {
            const auto& a = profiles[i];
            const auto& b = profiles[j];
            const std::string which = "profiles " + std::to_string(i + 1) + " and " + std::to_string(j + 1);
            for (const auto& x : a.segments)
                for (const auto& y : b.segments) {
                    const auto meet = intersections(x, y, eps);
                    if (meet.overlap || !meet.points.empty())
                        return ProfileProblem{ProfileProblem::Kind::overlapping_profiles, static_cast<int>(i), static_cast<int>(j),
                                              which + " of the part meet at " +
                                                  point_text(meet.points.empty() ? x.from : meet.points.front().point) +
                                                  "; a part's profiles must be apart (holes are not modelled)"};
                }
            if (inside(b, a.segments.front().from) || inside(a, b.segments.front().from))
                return ProfileProblem{ProfileProblem::Kind::overlapping_profiles, static_cast<int>(i), static_cast<int>(j),
                                      "one of " + which + " lies inside the other; a part's profiles must be apart (holes are not modelled)"};
        }
    return std::nullopt;
}

bool inside(const Profile& p, const Eigen::Vector2d& x) {
    // Crossings of a ray in a direction no drawn edge is likely to have: a tangent or vertex hit
    // is then a measure-zero event.
    Eigen::Vector2d lo = x, hi = x;
    extend_bounds(p, lo, hi);
    const double len = 4 * ((hi - lo).norm() + 1.0);
    const Segment ray = Segment::line(x, x + len * Eigen::Vector2d(std::cos(0.3719), std::sin(0.3719)));
    int crossings = 0;
    std::vector<Eigen::Vector2d> seen;
    for (const auto& s : p.segments)
        for (const auto& m : intersections(s, ray, 0.0).points) {
            bool dup = false;
            for (const auto& y : seen) dup = dup || (y - m.point).norm() <= 1e-12 * len;
            if (dup) continue;
            seen.push_back(m.point);
            ++crossings;
        }
    return crossings % 2 == 1;
}

}  // namespace qm::geometry
