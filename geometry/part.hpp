// geometry/part.hpp
// Provides:   Part, one rigid part of a metric scene (thesis 8.1.1: a drawing whose "boundary
//             consists of straight line segments and arcs", with "the center of rotation or a
//             vector parallel to the translational motion"): its closed profiles as drawn, its
//             single degree of freedom (fixed; rotation about a pivot, counter-clockwise
//             positive, wrapping at 360 degrees; translation along a unit axis within limits),
//             and its rotational symmetry (the one-period abstraction of 8.1.6). Also its pose
//             at a coordinate, its size, a tessellated copy for the polygon oracle, and a stable
//             text fingerprint for the place cache.
// Ownership:  a value type owning its profiles.
// Invariants: profiles are closed, simple, counter-clockwise and apart (profile_check.hpp);
//             a translation axis has unit length and lo < hi; symmetry >= 1, and the profiles
//             turned by 2 pi / symmetry about the pivot are the same profiles.
// Knows nothing of FCL, the ATMS or the engine.
#pragma once
#include "geometry/polygon_pair.hpp"
#include "geometry/profile.hpp"
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace qm::geometry {

struct Part {
    std::string name;
    std::vector<Profile> profiles;  // world coordinates at coordinate 0 (as drawn)
    PolygonDof dof;                 // kind, pivot (rotation), unit axis (translation)
    double lo = 0.0, hi = 0.0;      // translation limits: offsets along the axis from the drawing
    int symmetry = 1;               // n-fold rotational symmetry about dof.pivot

    [[nodiscard]] bool rotates() const noexcept { return dof.kind == PolygonDof::Kind::rotation; }
    [[nodiscard]] bool translates() const noexcept { return dof.kind == PolygonDof::Kind::translation; }
    [[nodiscard]] bool fixed() const noexcept { return dof.kind == PolygonDof::Kind::fixed; }
    // Rigid motion taking the drawing to coordinate q (radians or offset along the axis).
    [[nodiscard]] Eigen::Isometry2d pose(double q) const { return pose_at(dof, q); }
    // Diagonal of the drawing's bounding box: the length tolerances are relative to.
    [[nodiscard]] double size() const;
    // Largest distance of the drawing from the pivot (rotation) or from its bounding box centre.
    [[nodiscard]] double reach() const;
};

// The chordal tolerance in lengths for a tolerance relative to the part's size.
[[nodiscard]] inline double absolute_chordal_tolerance(const Part& p, double relative) { return relative * p.size(); }
// The part for the exact polygon oracle: every arc replaced by chords within `chordal_tolerance`.
[[nodiscard]] PolygonPart tessellated(const Part& p, double chordal_tolerance);
// Exact text of the geometry and the degree of freedom (hexfloat), for cache keys. The name is
// left out, so the same pair in another mechanism reuses its cached vocabulary (8.1.3).
[[nodiscard]] std::string fingerprint(const Part& p);

}  // namespace qm::geometry
