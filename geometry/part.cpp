// geometry/part.cpp: a part's size, tessellation and fingerprint.
#include "geometry/part.hpp"

#include <limits>
#include <sstream>

namespace qm::geometry {

double Part::size() const {
    const double big = std::numeric_limits<double>::infinity();
    Eigen::Vector2d lo(big, big), hi(-big, -big);
    for (const auto& p : profiles) extend_bounds(p, lo, hi);
    return profiles.empty() ? 0.0 : (hi - lo).norm();
}

double Part::reach() const {
    const double big = std::numeric_limits<double>::infinity();
    Eigen::Vector2d lo(big, big), hi(-big, -big);
    for (const auto& p : profiles) extend_bounds(p, lo, hi);
    const Eigen::Vector2d centre = rotates() ? dof.pivot : Eigen::Vector2d(0.5 * (lo + hi));
    double r = 0;
    for (const auto& p : profiles) r = std::max(r, geometry::reach(p, centre));
    return r;
}

PolygonPart tessellated(const Part& p, double chordal_tolerance) {
    PolygonPart out;
    out.dof = p.dof;
    for (const auto& profile : p.profiles) out.polygons.push_back(tessellate(profile, chordal_tolerance));
    return out;
}

std::string fingerprint(const Part& p) {
    std::ostringstream os;
    os << std::hexfloat << "part dof " << static_cast<int>(p.dof.kind) << ' ' << p.dof.pivot.x() << ' '
       << p.dof.pivot.y() << ' ' << p.dof.axis.x() << ' ' << p.dof.axis.y() << ' ' << p.lo << ' ' << p.hi << " symmetry "
       << p.symmetry;
    for (const auto& profile : p.profiles) {
        os << " profile";
        for (const auto& s : profile.segments) {
            os << (s.is_arc() ? (s.ccw ? " arc+ " : " arc- ") : " line ") << s.from.x() << ' ' << s.from.y() << ' ' << s.to.x()
               << ' ' << s.to.y();
            if (s.is_arc()) os << ' ' << s.centre.x() << ' ' << s.centre.y();
        }
    }
    return os.str();
}

}  // namespace qm::geometry
