// geometry/detail/place_parts.hpp (internal)
// Provides:   the builder's intermediate geometry shared by its stages: divisions (FSDs and
//             external divisions as axis-parallel segments), line places with their end joins,
//             and FaceLocator, which names the full face containing a free configuration.
// Ownership:  values owned by one build_place_vocabulary() call.
#pragma once
#include "geometry/cspace.hpp"
#include "geometry/pair_oracle.hpp"
#include "geometry/place_vocabulary.hpp"
#include <array>
#include <optional>
#include <string>
#include <vector>

namespace qm::geometry::detail {

// An axis-parallel segment from `start` running `length` along axis `axis` in direction `dir`.
struct Division {
    PlaceKind kind = PlaceKind::fsd;
    int axis = 0;
    int dir = 1;
    Eigen::Vector2d start;
    double length = 0.0;
    std::string label;
    std::vector<std::pair<double, PlaceId>> joins;  // (parameter along, join place), incl. both ends
    [[nodiscard]] Eigen::Vector2d at(double t) const {
        Eigen::Vector2d p = start;
        p[axis] += dir * t;
        return p;
    }
};

// A CSEG or division piece between two joins (either may be absent on a loop).
struct LineInfo {
    PlaceId place{0};
    std::optional<PlaceId> start, end;
    Eigen::Vector2d mid;     // a point in the middle of the piece
    Eigen::Vector2d normal;  // CSEG: unit normal into free space; division: unit normal of one side
    Eigen::Vector2d tangent; // unit direction from start towards end at mid
    bool two_sided = false;  // divisions have free space on both sides
};

// Which side of a division a configuration lies on must not depend on rounding:
// one within this many cells of a division's line counts as on it (a grid sample there belongs to
// no face; another point to the lower side: the line passes just above it), and a division's ends
// reach this much further.
inline constexpr double on_line_cells = 1e-6;

// The grid the faces are found on: the configuration space's samples plus, along each axis, a
// line between every two neighbouring feature coordinates (divisions, joins) closer than a step,
// so that a strip thinner than a grid step (two divisions close together, a division just past a
// corner's peak) has samples of its own, wherever the drawing lies on the grid.
class FaceGrid {
public:
    // `features[k]`: coordinates along axis k where the free space may be divided.
    FaceGrid(const PairOracle& oracle, const CSpaceResult& space, const std::array<std::vector<double>, 2>& features);
    [[nodiscard]] const CSpaceRequest& request() const noexcept { return space_.request; }
    [[nodiscard]] int size(int k) const noexcept { return static_cast<int>(at_[static_cast<std::size_t>(k)].size()); }
    // Line i of axis k; on a periodic axis line size(k) is hi (the first, a period on).
    [[nodiscard]] double coordinate(int k, int i) const noexcept;
    // Line i of a periodic axis counted on past its ends; coordinate(k, i) on a translation axis.
    [[nodiscard]] double unwrapped(int k, int i) const noexcept;
    // The last line at or below x (x within the axis, wrapped on a periodic one); -1 below lo.
    [[nodiscard]] int below(int k, double x) const noexcept;
    [[nodiscard]] bool blocked(int i, int j) const { return blocked_[static_cast<std::size_t>(i + size(0) * j)] != 0; }
    [[nodiscard]] Eigen::Vector2d point(int i, int j) const { return {coordinate(0, i), coordinate(1, j)}; }
    // Whether line i of axis k is one of the configuration space's own samples (not inserted).
    [[nodiscard]] bool sampled(int k, int i) const { return !inserted_[static_cast<std::size_t>(k)][static_cast<std::size_t>(i)]; }
    // The uniform grid's step along axis k (tolerances are measured in it).
    [[nodiscard]] double step(int k) const noexcept { return space_.request.axes[static_cast<std::size_t>(k)].step(); }
    // The pair's geometry, for configurations off the grid (it outlives the grid).
    [[nodiscard]] const PairOracle& oracle() const noexcept { return oracle_; }

private:
    const PairOracle& oracle_;
    const CSpaceResult& space_;
    std::array<std::vector<double>, 2> at_;
    std::array<std::vector<bool>, 2> inserted_;
    std::vector<std::uint8_t> blocked_;
};

class FaceLocator {
public:
    // `barriers` are segments (start, start to end) of the boundary next to its normal-change
    // joins, which grid edges between free samples must not cross (cut_along).
    FaceLocator(const FaceGrid& grid, const std::vector<Division>& divisions,
                const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>& barriers);
    // Labels the faces; returns the number of faces. face_of_sample() is valid afterwards.
    int label();
    // The face of the nearest sample to q on its side of every division; `sampled_only`: among
    // the configuration space's own samples (a probe from a join: the lines inserted between
    // close features lie too near the boundary to say which side a join's neighbourhood is on).
    [[nodiscard]] std::optional<int> face_at(const Eigen::Vector2d& q, bool sampled_only = false) const;
    // Does the segment from a to b cross a division? `leaving`: not counting a division a lies on.
    [[nodiscard]] bool crosses_division(const Eigen::Vector2d& a, const Eigen::Vector2d& b, bool leaving) const;
    // Where the segment from a to b first crosses a division, if it does (one a lies on, it leaves).
    [[nodiscard]] std::optional<Eigen::Vector2d> division_crossing(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const;
    [[nodiscard]] int face_of_sample(int i, int j) const { return face_[static_cast<std::size_t>(i + n0_ * j)]; }
    [[nodiscard]] const FaceGrid& grid() const noexcept { return grid_; }

private:
    // Does the segment from a to sample (i, j) cross a division?
    [[nodiscard]] bool crosses_division(const Eigen::Vector2d& a, int i, int j) const;
    void cut_along(const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>& barriers);
    const FaceGrid& grid_;
    const std::vector<Division>& divisions_;
    int n0_, n1_;
    std::vector<std::uint8_t> cut_[2];  // cut_[k][s]: edge from sample s along axis k is cut
    std::vector<std::uint8_t> on_division_;  // the sample lies on a division (to on_line_cells)
    std::vector<int> face_;             // -1 for blocked samples and samples on a division
};

// Does motion d from a join lead into free space, by its qualitative normals alone (8.1.3's
// half planes: their intersection at a concave join, their union at a convex one, the one CSEG's
// at a division's end)? nullopt where a dot product is ambiguous, or the join has no normals: the
// geometry must say. Used for the joins' adjacency and for where divisions start (Def 31).
[[nodiscard]] std::optional<bool> leads_into_free_space(const Place& join, QualDirection d);

// Adjacency of every place under every motion direction (8.1.3); appends to vocabulary.
void add_adjacency(const PairOracle& oracle, const CSpaceRequest& request, const std::vector<LineInfo>& lines,
                   const FaceLocator& faces, const std::vector<PlaceId>& face_places, PlaceVocabulary& vocabulary);

// Def 34: each face's values of each coordinate (Place::covers), from the rows of its samples and
// the stretches of its bounding places beside it (after add_adjacency, which names them).
void set_face_covers(const FaceLocator& faces, const std::vector<PlaceId>& face_places, PlaceVocabulary& vocabulary);

// Why the vocabulary is incomplete, if it is: a place with neither a next place nor a constraint
// under some motion, or a place other than a face at the end of an axis without stops that leads
// only back to itself under a motion along a bounded axis.
[[nodiscard]] std::optional<std::string> incompleteness(const CSpaceRequest& request, const PlaceVocabulary& vocabulary);

// 8.1.6: every full face narrower than epsilon (the free run through each of its samples along
// one axis or the other, i.e. the play of one part with the other held still) becomes, with the
// CSEGs bounding it and the joins and divisions that lead only to them, one face marked `gap`;
// transitions are renamed. Blocked space is never collapsed. No effect when epsilon is 0.
void collapse_gaps(const PairOracle& oracle, const FaceLocator& faces,
                   const std::vector<PlaceId>& face_places, double epsilon, PlaceVocabulary& vocabulary);

}  // namespace qm::geometry::detail
