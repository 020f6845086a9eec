// geometry/closed_form_pairs.hpp
// Provides:   the closed-form test pairs of the accuracy study: a bar turning
//             against a block, a circular disk cam against a flat follower, two eccentric disks,
//             and a crank pin in a slotted yoke. Each pair comes as an AnalyticOracle (the exact
//             contact function f, blocked iff f > 0, with its gradient), as polygons tessellated
//             to a chordal tolerance, and as the two parts drawn with lines and arcs (for the FCL
//             oracle), together with its configuration-space axes.
// Ownership:  value types; AnalyticOracle holds std::functions owning their parameters.
// Knows nothing of FCL, the ATMS or the engine.
#pragma once
#include "geometry/cspace.hpp"
#include "geometry/pair_oracle.hpp"
#include "geometry/part.hpp"
#include "geometry/polygon_pair.hpp"
#include <array>
#include <cmath>
#include <functional>
#include <string>

namespace qm::geometry {

class AnalyticOracle final : public PairOracle {
public:
    using Field = std::function<double(const Eigen::Vector2d&)>;
    using Gradient = std::function<Eigen::Vector2d(const Eigen::Vector2d&)>;
    AnalyticOracle(std::string name, Field f, Gradient grad) : name_(std::move(name)), f_(std::move(f)), grad_(std::move(grad)) {}
    [[nodiscard]] bool blocked(const Eigen::Vector2d& q) const override { return f_(q) > 0.0; }
    [[nodiscard]] Eigen::Vector2d free_normal(const Eigen::Vector2d& q) const override { return -grad_(q); }
    [[nodiscard]] std::string fingerprint() const override { return "analytic " + name_; }
    [[nodiscard]] double value(const Eigen::Vector2d& q) const { return f_(q); }
    // Distance along `axis` from q to the nearest zero of f (Newton's method on the axis line);
    // the exact error of a boundary point bracketed along that axis.
    [[nodiscard]] double crossing_error(const Eigen::Vector2d& q, int axis) const;
    // First-order distance from q to the contact boundary, |f| / |grad f| (configuration units).
    [[nodiscard]] double normal_distance(const Eigen::Vector2d& q) const { return std::abs(f_(q)) / grad_(q).norm(); }

private:
    std::string name_;
    Field f_;
    Gradient grad_;
};

struct ClosedFormPair {
    std::string name;
    AnalyticOracle exact;
    std::array<CSpaceAxis, 2> axes;
    // The same pair with every arc tessellated to the chordal tolerance.
    std::function<PolygonPairOracle(double chordal_tolerance)> tessellated;
    // The two parts, drawn exactly with lines and arcs (q0 drives the first, q1 the second).
    std::array<Part, 2> parts;
};

[[nodiscard]] ClosedFormPair bar_and_block();
[[nodiscard]] ClosedFormPair disk_cam_and_follower();
[[nodiscard]] ClosedFormPair two_disks();
[[nodiscard]] ClosedFormPair pin_in_slot();

// A circle as a polygon whose vertices lie on it and whose chords deviate at most `chordal_tolerance`.
// Pre: radius > 0, chordal_tolerance > 0.
[[nodiscard]] Polygon tessellated_circle(const Eigen::Vector2d& centre, double radius, double chordal_tolerance);

}  // namespace qm::geometry
