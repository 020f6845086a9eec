// geometry/place_adjacency.cpp: Adjacent facts under every motion direction (thesis 8.1.3).
// The five considerations of 8.1.3, in order:
//  (1) a line (CSEG or division) goes to the full face on the side its normal points to, for
//      every motion in that open half plane; a CSEG's motion into the opposite open half plane is
//      constrained (Law 2) and its next place is itself;
//  (2) motion along a line reaches the join at that end;
//  (3) a join goes to the faces that the motion's actual directions reach (sampled from the
//      geometry: the intersection of the half planes of the lines meeting there);
//  (4) lines and joins have no width across themselves, so leaving them is instantaneous; motion
//      along a line, and motion from a face, takes an interval;
//  (5) transitions from faces, and from joins to lines, come by reciprocity.
// Where the qualitative dot product with a CSEG normal is ambiguous, both the face and the
// slide along the CSEG are kept as possible next places (the thesis: "there may still be more
// than one possible next place").
#include "geometry/detail/place_parts.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <tuple>

namespace qm::geometry::detail {
namespace {

std::vector<QualDirection> motions() {
    std::vector<QualDirection> out;
    for (std::int8_t a = -1; a <= 1; ++a)
        for (std::int8_t b = -1; b <= 1; ++b)
            if (a != 0 || b != 0) out.push_back(QualDirection{{a, b}});
    return out;
}

// Actual directions (in cell units) covered by a qualitative motion.
std::vector<Eigen::Vector2d> actual_directions(QualDirection d) {
    if (d.s[0] == 0 || d.s[1] == 0) return {Eigen::Vector2d(d.s[0], d.s[1])};
    std::vector<Eigen::Vector2d> out;
    for (double deg : {10.0, 25.0, 45.0, 65.0, 80.0}) {
        const double a = deg * 3.14159265358979323846 / 180;
        out.emplace_back(d.s[0] * std::cos(a), d.s[1] * std::sin(a));
    }
    return out;
}

}  // namespace

// Does motion d from a join lead into free space, by the join's qualitative normals alone (the
// "intersection of the half planes of the normals" of 8.1.3)? Near a concave join (Def 29) free
// space is the intersection of the open half planes of the two CSEGs' normals, near a convex one
// (Def 30) their union; a join on one CSEG (a division's end) has that CSEG's half plane. A motion
// along a CSEG (dot product 0) is no way into free space there. Where a dot product is ambiguous
// the geometry must say (nullopt). Sampling alone decided before: at the bottom of a cam's curve,
// a motion along its tangent went to a face or not as the tessellation's chords fell at the
// sample a third of a cell out, which changed with the grid.
std::optional<bool> leads_into_free_space(const Place& join, QualDirection d) {
    if (join.normals.empty() || (join.join_kind == JoinKind::normal_change && !join.concave)) return std::nullopt;
    bool all_pos = true, any_pos = false, all_closed = true, any_closed = false;
    for (const auto n : join.normals) {
        const QualSign s = qdot(n, d);
        all_pos = all_pos && s == QualSign::pos;
        any_pos = any_pos || s == QualSign::pos;
        const bool closed = s == QualSign::neg || s == QualSign::zero;
        all_closed = all_closed && closed;
        any_closed = any_closed || closed;
    }
    const bool union_of_half_planes = join.join_kind == JoinKind::normal_change && !*join.concave;
    if (union_of_half_planes) {
        if (any_pos) return true;
        if (all_closed) return false;
    } else {
        if (all_pos) return true;
        if (any_closed) return false;
    }
    return std::nullopt;
}

void add_adjacency(const PairOracle& oracle, const CSpaceRequest& r, const std::vector<LineInfo>& lines,
                   const FaceLocator& faces, const std::vector<PlaceId>& face_places, PlaceVocabulary& v) {
    const Eigen::Vector2d cell(r.axes[0].step(), r.axes[1].step());
    std::set<std::tuple<std::uint32_t, std::uint32_t, QualDirection, bool, bool>> seen;
    std::vector<Adjacency> out;
    auto add = [&](PlaceId from, PlaceId to, QualDirection d, bool inst, bool constrained) {
        if (seen.insert({from.value, to.value, d, inst, constrained}).second) out.push_back({from, to, d, inst, constrained});
    };
    auto in_domain = [&](const Eigen::Vector2d& q) {
        for (int k = 0; k < 2; ++k) {
            const auto& a = r.axes[static_cast<std::size_t>(k)];
            const double slack = 1e-9 * a.span();  // points on a translation limit are inside
            if (!a.periodic && (q[k] < a.lo - slack || q[k] > a.hi + slack)) return false;
        }
        return true;
    };
    auto face_near = [&](const Eigen::Vector2d& q, Eigen::Vector2d dir_cells,
                         const Eigen::Vector2d& nudge = Eigen::Vector2d::Zero()) -> std::optional<PlaceId> {
        if (dir_cells.norm() == 0) return std::nullopt;
        const Eigen::Vector2d y = q + 0.3 * dir_cells.normalized().cwiseProduct(cell) + nudge;
        if (!in_domain(y) || oracle.blocked(wrap(r, y))) return std::nullopt;
        if (auto f = faces.face_at(y)) return face_places[static_cast<std::size_t>(*f)];
        return std::nullopt;
    };
    const auto all = motions();
    // (1), (2), (4) for lines.
    for (const auto& l : lines) {
        const Place& p = v.at(l.place);
        const QualDirection tangent = qualitative(l.tangent, r.normal_zero_tolerance);
        for (const auto d : all) {
            auto slide = [&] {
                const QualSign s = qdot(tangent, d);
                if (!l.start && !l.end) {
                    add(l.place, l.place, d, false, false);  // a loop with no joins: keeps sliding
                } else if (s == QualSign::pos && l.end) {
                    add(l.place, *l.end, d, false, false);
                } else if (s == QualSign::neg && l.start) {
                    add(l.place, *l.start, d, false, false);
                }
            };
            if (l.two_sided) {
                const int across = d.s[static_cast<std::size_t>(1 - p.axis)];
                if (across != 0) {
                    if (auto f = face_near(l.mid, across * l.normal.cwiseQuotient(cell))) add(l.place, *f, d, true, false);
                } else {
                    slide();
                }
                continue;
            }
            const QualSign s = qdot(p.normals.front(), d);
            if (s == QualSign::pos || s == QualSign::ambiguous)
                if (auto f = face_near(l.mid, l.normal.cwiseQuotient(cell))) add(l.place, *f, d, true, false);
            if (s == QualSign::neg) add(l.place, l.place, d, false, true);  // Law 2
            if (s == QualSign::zero || s == QualSign::ambiguous) slide();
        }
    }
    // (5) joins to lines by reciprocity.
    const std::vector<Adjacency> line_moves = out;
    for (const auto& a : line_moves)
        if (a.to != a.from && v.at(a.to).kind == PlaceKind::join) add(a.to, a.from, negated(a.motion), true, false);
    // (3) joins to faces. A join lies on the boundary only to within the bisection tolerance, on
    // either side of it; a motion straight along a CSEG through the join would then reach the
    // face or not by rounding. The sample is nudged a thousandth of a cell into blocked space
    // (against the mean of the join's normals), so such a motion counts as sliding, in every
    // drawing of the scene (moved, turned, scaled).
    // A motion straight along a division that leaves the join follows the division (reached by
    // reciprocity above); sampling it would land on the division's own line, in either face by
    // rounding.
    std::set<std::pair<std::uint32_t, QualDirection>> along_division;
    for (const auto& l : lines) {
        if (!l.two_sided) continue;
        if (l.start) along_division.insert({l.start->value, qualitative(l.tangent, r.normal_zero_tolerance)});
        if (l.end) along_division.insert({l.end->value, negated(qualitative(l.tangent, r.normal_zero_tolerance))});
    }
    for (const auto& p : v.places) {
        if (p.kind != PlaceKind::join) continue;
        Eigen::Vector2d mean = Eigen::Vector2d::Zero();
        for (const auto n : p.normals) mean += Eigen::Vector2d(n.s[0], n.s[1]).normalized();
        const Eigen::Vector2d nudge = mean.norm() > 1e-9 ? Eigen::Vector2d(-1e-3 * mean.normalized().cwiseProduct(cell)) : Eigen::Vector2d::Zero();
        for (const auto d : all) {
            bool any = std::any_of(out.begin(), out.end(), [&](const Adjacency& a) { return a.from == p.id && a.motion == d; });
            if (along_division.count({p.id.value, d})) {
                if (!any) add(p.id, p.id, d, false, true);
                continue;
            }
            const std::optional<bool> into_free = leads_into_free_space(p, d);
            if (into_free == false) {  // the normals close it: constrained, unless it slides along a line
                if (!any) add(p.id, p.id, d, false, true);
                continue;
            }
            bool found = false;
            for (const auto& dir : actual_directions(d))
                if (auto f = face_near(p.points.front(), dir, nudge)) {
                    add(p.id, *f, d, true, false);
                    found = true;
                }
            // The normals open it but the samples a third of a cell out were blocked: a motion
            // along one CSEG's tangent at a convex join, where the chords of the tessellation lie
            // within the curve's fall over that third of a cell. A little way out along the mean
            // normal the face is found.
            for (double out : {0.05, 0.15})
                if (!found && into_free == true)
                    for (const auto& dir : actual_directions(d))
                        if (auto f = face_near(p.points.front(), dir, -nudge * (out / 1e-3))) {
                            add(p.id, *f, d, true, false);
                            found = true;
                        }
            if (!any && !found) add(p.id, p.id, d, false, true);
        }
    }
    // (5) faces by reciprocity; a face that reaches nothing under a motion stays (e.g. it wraps).
    const std::vector<Adjacency> so_far = out;
    for (const auto& a : so_far)
        if (a.to != a.from && v.at(a.to).kind == PlaceKind::face) add(a.to, a.from, negated(a.motion), false, false);
    for (const auto f : face_places)
        for (const auto d : all) {
            const bool any = std::any_of(out.begin(), out.end(), [&](const Adjacency& a) { return a.from == f && a.motion == d; });
            if (!any) add(f, f, d, false, false);
        }
    std::sort(out.begin(), out.end(), [](const Adjacency& a, const Adjacency& b) {
        return std::tie(a.from, a.motion, a.to) < std::tie(b.from, b.motion, b.to);
    });
    v.adjacency = std::move(out);
}

}  // namespace qm::geometry::detail
