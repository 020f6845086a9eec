// geometry/part_svg.hpp
// Provides:   drawings of parts at a configuration in the look of the configuration-space
//             pictures (cspace_svg.hpp), as the thesis draws the parts at a place (Figures
//             9.11-9.13, 9.26, 9.36): each part's outlines as drawn (lines and SVG arcs, exact)
//             inside a group whose transform is the part's pose at its coordinate; pivots and
//             translation axes (with their limits) marked; contacts marked with the outward
//             normals of the surfaces in contact and their qualitative directions (Defs 17-19);
//             each part's motion as an arrow, the way the thesis' histories show it (Figures
//             9.25, 9.27, 9.28: curved about a pivot, straight along a slide); a legend. The
//             pieces are offered separately for the explorer page, which moves
//             the parts by changing their groups' transforms and swaps the contact marks.
// Ownership:  values; DrawnPart points at a Part its caller owns for the call.
// Invariants: the world is shown with x right and y up at one scale on both axes; a frame
//             holds every drawn part anywhere along its motion, so one frame serves every
//             configuration. A part's group is <g class="part" data-part="NAME" transform=...>
//             holding its outline path in world coordinates as drawn (coordinate 0); the
//             contact marks are <g class="contacts">; the motion arrows are
//             <g class="motion" data-part="NAME" data-motion="+|-" transform=...> in world
//             coordinates inside <g class="motions"> (the world's transform), each carrying its
//             part's transform so that it moves with the part.
// Knows nothing of the ATMS or the engine.
#pragma once
#include "geometry/part.hpp"
#include <Eigen/Core>
#include <array>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace qm::geometry {

// World box -> pixel box, centred, one scale, y flipped.
struct DrawingFrame {
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();  // world point at the pixel box' centre
    Eigen::Vector2d pixel_centre = Eigen::Vector2d::Zero();
    double scale = 1.0;  // pixels per world unit
    [[nodiscard]] Eigen::Vector2d pixel(const Eigen::Vector2d& world) const;
    // The SVG transform from world coordinates to pixels.
    [[nodiscard]] std::string world_transform() const;
};

// The world box a part can occupy anywhere along its motion: a disk of its reach about the
// pivot, the drawing swept along a translation's limits, or the drawing itself.
void extend_motion_bounds(const Part& p, Eigen::Vector2d& lo, Eigen::Vector2d& hi);

// The part's pose at coordinate q as an SVG transform in world coordinates: "rotate(DEG X Y)"
// (counter-clockwise in the world), "translate(DX DY)", or "" for a fixed part.
[[nodiscard]] std::string part_transform(const Part& p, double q);
// The part's outlines as drawn (coordinate 0) as SVG path data: M, L, A (arcs exact), Z.
[[nodiscard]] std::string outline_path(const Part& p);

struct DrawnPart {
    const Part* part = nullptr;
    double q = 0.0;  // its coordinate: radians or offset along the axis
    int motion = 0;  // its motion's sign (counter-clockwise or along the axis positive); 0: no arrow
};

// A contact between two drawn parts: its point and, for each side that touches with a surface
// (not a corner), the surface's outward normal in the world.
struct ContactMark {
    Eigen::Vector2d point = Eigen::Vector2d::Zero();
    std::array<std::size_t, 2> parts{0, 0};  // indices into the drawing's parts
    std::array<std::optional<Eigen::Vector2d>, 2> normals;
    std::string note;  // shown on hover (an SVG <title>)
};

struct DrawingOptions {
    int width = 640;
    int height = 480;
    std::string title;
    bool legend = true;
    double normal_zero_tolerance = 1e-6;  // a normal component this small is qualitatively 0
};

// The frame the drawing of these parts uses (the same for every configuration of them).
[[nodiscard]] DrawingFrame parts_frame(const std::vector<DrawnPart>& parts, const DrawingOptions& options);
// The contact marks alone, as <g class="contacts">...</g>, for a frame from parts_frame().
void write_contact_marks(std::ostream& os, const DrawingFrame& frame, const std::vector<DrawnPart>& parts,
                         const std::vector<ContactMark>& contacts, const DrawingOptions& options);
// The arrow of a part's motion (sign +1 or -1) at coordinate q, in world coordinates, for a frame
// of `scale` pixels per world unit: an arc about the pivot, or a straight arrow along the axis
// beside the part's centre; nothing for a fixed part or a sign 0.
[[nodiscard]] std::string motion_arrow(const Part& p, double q, int sign, double scale);
// The whole picture. Pre: every DrawnPart points at a part with profiles.
void write_parts_svg(std::ostream& os, const std::vector<DrawnPart>& parts, const std::vector<ContactMark>& contacts,
                     const DrawingOptions& options);

}  // namespace qm::geometry
