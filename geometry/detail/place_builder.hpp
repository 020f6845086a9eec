// geometry/detail/place_builder.hpp (internal)
// Provides:   Builder, the state of one build_place_vocabulary() call shared by its stages:
//             boundary chains with their joins (place_vocabulary_builder.cpp) and divisions
//             (free_space_divisions.cpp).
// Ownership:  references the caller's oracle, request and result for the duration of the call.
#pragma once
#include "geometry/cspace.hpp"
#include "geometry/detail/place_parts.hpp"
#include "geometry/pair_oracle.hpp"
#include "geometry/place_vocabulary.hpp"
#include "geometry/place_vocabulary_builder.hpp"
#include "geometry/cspace_boundary.hpp"
#include <cmath>
#include <optional>
#include <vector>

namespace qm::geometry::detail {


// A node along a boundary chain: a boundary point or a join placed between two of them.
struct ChainNode {
    Eigen::Vector2d q;
    int point = -1;                  // index into space.boundary, or -1 for a join
    std::optional<PlaceId> join;
    QualDirection qual;              // boundary points: their normal class
    Eigen::Vector2d normal = Eigen::Vector2d::Zero();
};

struct Builder {
    const PairOracle& oracle;
    const PlaceRequest& request;
    const CSpaceRequest& r;
    CSpaceResult& space;
    PlaceVocabulary& v;
    std::vector<std::vector<ChainNode>> chains;
    std::vector<bool> closed;
    std::vector<Division> divisions;
    std::vector<LineInfo> lines;

    [[nodiscard]] Eigen::Vector2d cell() const { return {r.axes[0].step(), r.axes[1].step()}; }
    // A normal (a covector) in cell units, unit length: angles between normals measured on the
    // grid, the same whatever a translation axis' length (the scene scaled).
    [[nodiscard]] Eigen::Vector2d in_cells(const Eigen::Vector2d& n) const {
        const Eigen::Vector2d c = n.cwiseProduct(cell());
        return c.norm() > 0 ? Eigen::Vector2d(c.normalized()) : c;
    }
    [[nodiscard]] bool in_domain(const Eigen::Vector2d& q) const {
        for (int k = 0; k < 2; ++k) {
            const auto& a = r.axes[static_cast<std::size_t>(k)];
            const double slack = 1e-9 * a.span();  // points on a translation limit are inside
            if (!a.periodic && (q[k] < a.lo - slack || q[k] > a.hi + slack)) return false;
        }
        return true;
    }
    bool blocked(const Eigen::Vector2d& q) {
        ++space.oracle_calls;
        return oracle.blocked(wrap(r, q));
    }
    PlaceId add(Place p) {
        p.id = PlaceId{static_cast<std::uint32_t>(v.places.size())};
        v.places.push_back(std::move(p));
        return v.places.back().id;
    }
    PlaceId add_join(JoinKind kind, const Eigen::Vector2d& q, std::vector<QualDirection> normals) {
        Place p;
        p.kind = PlaceKind::join;
        p.join_kind = kind;
        p.points = {wrap(r, q)};
        p.normals = std::move(normals);
        return add(std::move(p));
    }

    // Move q onto the boundary along direction n, if the boundary is within a cell diagonal (the
    // reach is measured in cells, the direction is n's own). Scaling the direction by the cell
    // would tilt it on cells that are not square: at the tip of a thin blocked needle (the
    // ratchet's pawl tip past a tooth tip) the tilted line leaves the needle's axis and meets its
    // side below the tip. Along the sides' mean normal, the needle's axis, it meets the tip itself.
    Eigen::Vector2d project(const Eigen::Vector2d& q, Eigen::Vector2d n) {
        const double scaled = n.cwiseQuotient(cell()).norm();
        if (!(scaled > 0)) return q;
        n *= std::sqrt(2.0) / scaled;
        const bool lo = blocked(q - n), hi = blocked(q + n);
        if (lo == hi) return q;
        return bisect_contact(oracle, q - n, lo, q + n, r.boundary_tolerance, space.oracle_calls);
    }

    void make_chains(const std::vector<BoundaryChain>& traced);
    void absorb_short_runs(std::vector<ChainNode>& nodes, bool is_closed);
    void absorb_unresolved_runs(std::vector<ChainNode>& nodes, bool is_closed);
    void adopt_neighbour_normals(std::vector<ChainNode>& nodes, const std::vector<int>& points, bool is_closed);
    void insert_normal_joins(std::size_t c);
    void insert_joins_and_drop_tip_islands();
    [[nodiscard]] bool small_island(std::size_t c) const;
    void collapse_point_runs(std::size_t c);
    Eigen::Vector2d corner(const std::vector<ChainNode>& nodes, std::size_t k, bool is_closed);
    [[nodiscard]] std::size_t sound_node(const std::vector<ChainNode>& nodes, std::size_t k, int step, bool is_closed) const;
    Eigen::Vector2d normal_change(const ChainNode& a, const Eigen::Vector2d& pb, const Eigen::Vector2d& nb);
    Eigen::Vector2d refine_corner(Eigen::Vector2d pa, Eigen::Vector2d na, QualDirection qa, Eigen::Vector2d pb, Eigen::Vector2d nb,
                                  QualDirection qb, Eigen::Vector2d y);
    [[nodiscard]] bool concave(const ChainNode& a, const ChainNode& b, const Eigen::Vector2d& q) const;
    bool on_tangents(const Eigen::Vector2d& p, const Eigen::Vector2d& n, const Eigen::Vector2d& x);
    bool duplicate(const Division& d) const;
    void grow_fsds();
    bool runs_along_boundary(const Division& d, const CSpaceAxis& ax);
    void add_external_divisions();
    void end_on_boundary(Division& d, double t, JoinKind kind);
    void cross_divisions();
    // A T-junction: `ending` meets the line of `through` (at t along it) at one of its ends.
    void meet(Division& through, double t, const Division& ending, double u, double near);
    [[nodiscard]] std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> barriers_at_joins() const;
    // Where along each axis the free space may be divided: the divisions' lines and the joins
    // (where a CSEG turns back along an axis its normal changes, so its turning points are joins
    // too): for the faces' grid, FaceGrid.
    [[nodiscard]] std::array<std::vector<double>, 2> feature_coordinates() const;
    void add_stops();
    void emit_csegs();
    void emit_between_joins(const ChainNode& a, const ChainNode& b);
    void emit_divisions();
};

}  // namespace qm::geometry::detail
