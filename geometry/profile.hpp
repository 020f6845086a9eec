// geometry/profile.hpp
// Provides:   Segment (a straight line or a circular arc between two points) and Profile, a
//             closed 2-D boundary made of segments, as the thesis' drawings are ("the boundary
//             of a part consists of straight line segments and arcs", 8.1.1); point, tangent and
//             outward normal along a segment, the enclosed area, orientation, rigid motion, and
//             tessellation to a stated chordal tolerance (for FCL meshes and the polygon oracle).
// Ownership:  value types.
// Invariants: an arc's two end points lie on its circle (the constructor in the scene checker
//             and the generators guarantee it); a Profile used by a Part is closed (each
//             segment ends where the next begins) and counter-clockwise, so the solid lies to
//             the left of the direction of travel and the outward normal to the right.
// Knows nothing of FCL, the ATMS or the engine.
#pragma once
#include "geometry/polygon_pair.hpp"
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <vector>

namespace qm::geometry {

struct Segment {
    enum class Kind { line, arc } kind = Kind::line;
    Eigen::Vector2d from = Eigen::Vector2d::Zero();
    Eigen::Vector2d to = Eigen::Vector2d::Zero();
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // arc only
    bool ccw = true;                                   // arc only: sense of travel about the centre

    [[nodiscard]] static Segment line(Eigen::Vector2d a, Eigen::Vector2d b) { return {Kind::line, a, b, Eigen::Vector2d::Zero(), true}; }
    [[nodiscard]] static Segment arc(Eigen::Vector2d a, Eigen::Vector2d b, Eigen::Vector2d c, bool ccw) {
        return {Kind::arc, a, b, c, ccw};
    }
    [[nodiscard]] bool is_arc() const noexcept { return kind == Kind::arc; }
    [[nodiscard]] double radius() const noexcept { return (from - centre).norm(); }
    // Angle of `from` about the centre, and the signed sweep to `to` (ccw > 0), |sweep| in (0, 2 pi].
    [[nodiscard]] double start_angle() const noexcept;
    [[nodiscard]] double sweep() const noexcept;
    [[nodiscard]] double length() const noexcept;
    // t in [0, 1] along the segment (by arc length).
    [[nodiscard]] Eigen::Vector2d point_at(double t) const noexcept;
    // Unit direction of travel at t.
    [[nodiscard]] Eigen::Vector2d tangent_at(double t) const noexcept;
    // Unit outward normal at t for a counter-clockwise profile: the tangent turned clockwise.
    [[nodiscard]] Eigen::Vector2d outward_normal_at(double t) const noexcept {
        const Eigen::Vector2d d = tangent_at(t);
        return {d.y(), -d.x()};
    }
    // Is the angle (about the centre) on this arc, within `slack` radians?
    [[nodiscard]] bool covers_angle(double angle, double slack = 0.0) const noexcept;
    // Parameter t of the arc point at `angle` (meaningful when covers_angle).
    [[nodiscard]] double param_of_angle(double angle) const noexcept;
};

struct Profile {
    std::vector<Segment> segments;
};

// The signed area enclosed (counter-clockwise positive), exact for arcs.
[[nodiscard]] double signed_area(const Profile& p) noexcept;
// The same boundary traversed the other way.
[[nodiscard]] Profile reversed(const Profile& p);
// Counter-clockwise copy (reversed if the area is negative).
[[nodiscard]] Profile counter_clockwise(const Profile& p);
[[nodiscard]] Segment transformed(const Segment& s, const Eigen::Isometry2d& t) noexcept;
[[nodiscard]] Profile transformed(const Profile& p, const Eigen::Isometry2d& t);
// Largest distance from `centre` to the profile (exact for arcs).
[[nodiscard]] double reach(const Profile& p, const Eigen::Vector2d& centre) noexcept;
// Axis-aligned bounds (exact for arcs): min and max corner.
void extend_bounds(const Profile& p, Eigen::Vector2d& lo, Eigen::Vector2d& hi) noexcept;
// A circle as two half arcs, counter-clockwise. Pre: radius > 0.
[[nodiscard]] Profile circle_profile(const Eigen::Vector2d& centre, double radius);
// A closed polygon (last vertex joins the first) as line segments. Pre: >= 3 vertices.
[[nodiscard]] Profile polygon_profile(const std::vector<Eigen::Vector2d>& vertices);

// Number of chords an arc of radius r and sweep |s| needs so that no chord is farther than
// `chordal_tolerance` from the arc (sagitta r (1 - cos(s / 2n))). Pre: chordal_tolerance > 0 and
// the answer is at most max_chords_per_arc (the scene checker's least tolerance keeps it so).
inline constexpr double max_chords_per_arc = 1e6;
[[nodiscard]] int chords_for(double radius, double sweep, double chordal_tolerance);
// The same count without preconditions, as a double (+inf for a tolerance that is not positive):
// what the scene checker compares with the build limits (build_limits.hpp) before any is built.
[[nodiscard]] double chord_count(double radius, double sweep, double chordal_tolerance) noexcept;
// Vertices of the profile with every arc replaced by chords within `chordal_tolerance` of it.
// Every vertex lies on the exact boundary; segment i begins at index first_vertex[i].
// Pre: chordal_tolerance > 0.
[[nodiscard]] Polygon tessellate(const Profile& p, double chordal_tolerance, std::vector<int>* first_vertex = nullptr);

}  // namespace qm::geometry
