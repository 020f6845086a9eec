// geometry/detail/place_parts.hpp (internal)
// Provides:   the builder's intermediate geometry shared by its stages: divisions (FSDs and
//             external divisions as axis-parallel segments), line places with their end joins,
//             and FaceLocator, which names the full face containing a free configuration.
// Ownership:  values owned by one build_place_vocabulary() call.
#pragma once
#include "geometry/cspace.hpp"
#include "geometry/pair_oracle.hpp"
#include "geometry/place_vocabulary.hpp"
#include <optional>
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

class FaceLocator {
public:
    // `barriers` are segments (start, start to end) of the boundary next to its normal-change
    // joins, which grid edges between free samples must not cross (cut_along).
    FaceLocator(const CSpaceResult& space, const std::vector<Division>& divisions,
                const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>& barriers);
    // Labels the faces; returns the number of faces. face_of_sample() is valid afterwards.
    int label();
    [[nodiscard]] std::optional<int> face_at(const Eigen::Vector2d& q) const;
    [[nodiscard]] int face_of_sample(int i, int j) const { return face_[static_cast<std::size_t>(i + n0_ * j)]; }

private:
    // Does the segment from a to sample (i, j) cross a division?
    [[nodiscard]] bool crosses_division(const Eigen::Vector2d& a, int i, int j) const;
    void cut_along(const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>& barriers);
    const CSpaceResult& space_;
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

// 8.1.6: every full face narrower than epsilon (the free run through each of its samples along
// one axis or the other, i.e. the play of one part with the other held still) becomes, with the
// CSEGs bounding it and the joins and divisions that lead only to them, one face marked `gap`;
// transitions are renamed. Blocked space is never collapsed. No effect when epsilon is 0.
void collapse_gaps(const PairOracle& oracle, const CSpaceResult& space, const FaceLocator& faces,
                   const std::vector<PlaceId>& face_places, double epsilon, PlaceVocabulary& vocabulary);

}  // namespace qm::geometry::detail
