// geometry/place_vocabulary_builder.cpp: CSEGs, joins, FSDs, external divisions, full faces
// (thesis 4.2, 8.1.2, 8.1.6, 8.2.1).
#include "geometry/place_vocabulary_builder.hpp"

#include "geometry/cspace_boundary.hpp"
#include "geometry/detail/place_builder.hpp"
#include "geometry/detail/place_parts.hpp"
#include "qm/assert.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

namespace qm::geometry::detail {

// A point whose normal contradicted its crossing carries its neighbour's normal (adopt_neighbour_
// normals), right for its class but not for its tangent: at a needle's tip it lies on the other
// side, and the tangent through it with the adopted normal would cross the sound side's tangent
// off the tip, on the needle's side.
// The corner is taken from the nearest sound points of the two runs instead (up to 4 points out).
std::size_t Builder::sound_node(const std::vector<ChainNode>& nodes, std::size_t k, int step, bool is_closed) const {
    const std::size_t n = nodes.size();
    std::size_t j = k;
    for (int s = 0; s < 4; ++s) {
        const ChainNode& x = nodes[j];
        if (x.point < 0 || !space.boundary[static_cast<std::size_t>(x.point)].normal_contradicts_edge) return j;
        if (!is_closed && ((step < 0 && j == 0) || (step > 0 && j + 1 == n))) break;
        const std::size_t next = (j + n + static_cast<std::size_t>(step > 0 ? 1 : n - 1)) % n;
        if (next == k || nodes[next].join || !(nodes[next].qual == nodes[k].qual)) break;
        j = next;
    }
    return k;
}

// Where a join between boundary points a = nodes[k] and b (the next) lies: the crossing of
// their tangent lines when the normals differ enough to make it well conditioned and it lies
// near them (a corner: within 1.5 cells, or within 4 cells along each axis if the boundary is
// found on both tangent lines), moved onto the boundary along the mean normal. At a needle's
// tip the points next to it can carry the normal of the needle's other side (nearly opposite
// normals, no crossing to take); the secants through a cell or two of each run then stand in
// for the tangents, if the boundary is found on both.
Eigen::Vector2d Builder::corner(const std::vector<ChainNode>& nodes, std::size_t k_in, bool is_closed) {
    const std::size_t n = nodes.size();
    const std::size_t k = sound_node(nodes, k_in, -1, is_closed), k1 = sound_node(nodes, (k_in + 1) % n, 1, is_closed);
    const ChainNode& a = nodes[k];
    const ChainNode& b = nodes[k1];
    const Eigen::Vector2d pb = a.q + difference(r, a.q, b.q);
    const Eigen::Vector2d mid = 0.5 * (a.q + pb);
    auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& w) { return u.x() * w.y() - u.y() * w.x(); };
    auto crossing = [&](const Eigen::Vector2d& na, const Eigen::Vector2d& nb) {
        Eigen::Matrix2d m;
        m << na.x(), na.y(), nb.x(), nb.y();
        return Eigen::Vector2d(m.inverse() * Eigen::Vector2d(na.dot(a.q), nb.dot(pb)));
    };
    auto near = [&](const Eigen::Vector2d& x, const Eigen::Vector2d& na, const Eigen::Vector2d& nb, bool loose) {
        const Eigen::Vector2d off = (x - mid).cwiseQuotient(cell());
        return (loose && off.norm() < 1.5) ||
               (off.lpNorm<Eigen::Infinity>() < 4 && on_tangents(a.q, na, x) && on_tangents(pb, nb, x));
    };
    // Normals less than a right angle apart (in cells: angles in configuration units change with a
    // translation axis' length, and a scene scaled by 100 would take a cam's smooth top for a
    // corner): the change of class is found along the boundary, at a smooth extremum or a corner
    // alike. Sharper corners from the tangents' crossing.
    if (in_cells(a.normal).dot(in_cells(b.normal)) > 0) return normal_change(a, pb, b.normal);
    if (std::abs(cross(in_cells(a.normal), in_cells(b.normal))) > 0.2) {
        const Eigen::Vector2d x = crossing(a.normal, b.normal);
        if (!near(x, a.normal, b.normal, true)) return project(mid, a.normal + b.normal);
        return refine_corner(a.q, a.normal, a.qual, pb, b.normal, b.qual, project(x, a.normal + b.normal));
    }
    // The secant from the run's point a cell or two back (at most 4 points) to the run's end.
    auto secant = [&](std::size_t from, int step, const Eigen::Vector2d& normal) -> std::optional<Eigen::Vector2d> {
        std::size_t j = from;
        for (int s = 0; s < 4; ++s) {
            if (!is_closed && ((step < 0 && j == 0) || (step > 0 && j + 1 == n))) break;
            const std::size_t next = (j + n + static_cast<std::size_t>(step > 0 ? 1 : n - 1)) % n;
            if (next == from || nodes[next].point < 0 || nodes[next].join || !(nodes[next].qual == nodes[from].qual)) break;
            j = next;
            if (difference(r, nodes[from].q, nodes[j].q).cwiseQuotient(cell()).norm() >= 2) break;
        }
        const Eigen::Vector2d d = difference(r, nodes[from].q, nodes[j].q);
        if (d.cwiseQuotient(cell()).norm() < 0.5) return std::nullopt;
        Eigen::Vector2d s(-d.y(), d.x());
        s.normalize();
        return s.dot(normal) < 0 ? Eigen::Vector2d(-s) : s;
    };
    const auto sa = secant(k, -1, a.normal), sb = secant(k1, 1, b.normal);
    if (sa && sb && std::abs(cross(in_cells(*sa), in_cells(*sb))) > 0.2) {
        const Eigen::Vector2d x = crossing(*sa, *sb);
        if (near(x, *sa, *sb, false)) return project(x, *sa + *sb);
    }
    return project(mid, a.normal + b.normal);
}

// Where two curved sides meet, the crossing of the tangents at the last points of each lies off
// the corner by the sides' sag, and moved onto the boundary it sits on one side, short of the
// corner (a concave corner's extreme value would be missed by the faces' values, Def 34). Each
// point found replaces the last point of its side, bracketing the corner ever closer: the next
// is the new tangents' crossing, or, where that found the same side twice running (the other
// side's tangent stale), the bracket's middle moved onto the boundary.
Eigen::Vector2d Builder::refine_corner(Eigen::Vector2d pa, Eigen::Vector2d na, QualDirection qa, Eigen::Vector2d pb, Eigen::Vector2d nb,
                                       QualDirection qb, Eigen::Vector2d y) {
    auto crossing = [](const Eigen::Vector2d& p, const Eigen::Vector2d& n, const Eigen::Vector2d& q, const Eigen::Vector2d& m)
        -> std::optional<Eigen::Vector2d> {
        Eigen::Matrix2d mat;
        mat << n.x(), n.y(), m.x(), m.y();
        if (std::abs(mat.determinant()) < 1e-12 * n.norm() * m.norm()) return std::nullopt;
        return Eigen::Vector2d(mat.inverse() * Eigen::Vector2d(n.dot(p), m.dot(q)));
    };
    const Eigen::Vector2d first = y;
    int last_side = 0, repeats = 0;
    for (int i = 0; i < 64; ++i) {
        const Eigen::Vector2d n = oracle.free_normal(wrap(r, y));
        if (!(n.norm() > 0)) return y;
        const QualDirection q = qualitative(n, r.normal_zero_tolerance);
        const int side = q == qa ? 1 : (q == qb ? 2 : 0);
        if (side == 0) return y;  // at the corner itself
        (side == 1 ? pa : pb) = y;
        (side == 1 ? na : nb) = n.normalized();
        repeats = side == last_side ? repeats + 1 : 0;
        last_side = side;
        const Eigen::Vector2d gap = (pb - pa).cwiseQuotient(cell());
        if (gap.norm() < 1e-7) return y;
        if (gap.norm() > 8) return first;  // left the corner's neighbourhood
        const auto x = crossing(pa, na, pb, nb);
        const bool inside = x && ((*x - pa).cwiseQuotient(cell()).norm() < 4 * gap.norm() + 1e-7);
        y = project(repeats == 0 && inside ? *x : 0.5 * (pa + pb), na + nb);
    }
    return y;
}

// Def 29: a join at q between boundary points a and b (next along the chain) is concave if the
// CSEG beyond it lies in the open half plane of a's normal, i.e. (b - q) . n_a > 0. Where the two
// normals are nearly parallel (a smooth extremum, a shallow corner) b lies off the tangent line by
// the curve's rise over half a cell, which the tessellation's chordal error can exceed (the
// bottom of a cam's curve would come out convex at some grids); the turn of the normals from
// a to b, which come from the exact geometry, says the same thing there: the boundary bends
// towards free space (concave) when the normal turns the way that free space lies from the
// direction of travel.
bool Builder::concave(const ChainNode& a, const ChainNode& b, const Eigen::Vector2d& q) const {
    auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& w) { return u.x() * w.y() - u.y() * w.x(); };
    const double turn = cross(in_cells(a.normal), in_cells(b.normal));
    if (in_cells(a.normal).dot(in_cells(b.normal)) > 0 && std::abs(turn) <= 0.2 && std::abs(turn) > 1e-9) {
        const double free_side = cross(difference(r, a.q, b.q), a.normal);
        if (std::abs(free_side) > 0) return (turn > 0) == (free_side > 0);
    }
    return difference(r, q, b.q).dot(a.normal) > 0;
}

// Where the normal of a smooth CSEG (or of a shallow corner) passes from a's qualitative class to
// the next point's, which lies at pb with normal nb: bisection along the boundary between them on
// the class of the geometry's normal, to a ten-millionth of a cell. The top of a cam's curve is
// where its normal passes (0 +); the midpoint of the two points would lie up to half a cell from
// it, below the top, and the divisions from the join would depend on where the grid's columns
// fell.
Eigen::Vector2d Builder::normal_change(const ChainNode& a, const Eigen::Vector2d& pb, const Eigen::Vector2d& nb) {
    const Eigen::Vector2d along = a.normal + nb;
    Eigen::Vector2d lo = a.q, hi = pb;  // the class at lo is a's, at hi not
    for (int i = 0; i < 48 && (hi - lo).cwiseQuotient(cell()).norm() > 1e-7; ++i) {
        const Eigen::Vector2d m = project(0.5 * (lo + hi), along);
            (qualitative(oracle.free_normal(wrap(r, m)), r.normal_zero_tolerance) == a.qual ? lo : hi) = m;
    }
    return project(0.5 * (lo + hi), along);
}

// Whether the boundary follows the tangent line from boundary point p (normal n) to x: at the
// middle, a fiftieth of a cell along n is free and as far against it blocked. The tip of a
// blocked needle thinner than a cell lies further from the last crossings the grid sees than a
// cell or so; its two sides, straight near the tip, say where it is.
bool Builder::on_tangents(const Eigen::Vector2d& p, const Eigen::Vector2d& n, const Eigen::Vector2d& x) {
    const double scaled = n.cwiseQuotient(cell()).norm();
    if (!(scaled > 0)) return false;
    const Eigen::Vector2d o = n * (0.02 / scaled), m = 0.5 * (p + x);
    return in_domain(m + o) && in_domain(m - o) && !blocked(m + o) && blocked(m - o);
}

// A run of a normal with a zero component (e.g. (0 +)) shorter than half a grid cell, between
// two other normals, is where a curved CSEG's normal passes an axis: a point, not a segment.
// It becomes one join at the run's middle point (a straight join, Defs 29-30).
void Builder::collapse_point_runs(std::size_t c) {
    auto& nodes = chains[c];
    const std::size_t n = nodes.size();
    if (n < 3) return;
    const Eigen::Vector2d scale = cell().cwiseInverse();
    for (std::size_t start = 0; start < n;) {
        std::size_t end = start;
        while (end + 1 < n && nodes[end + 1].qual == nodes[start].qual) ++end;
        const std::size_t next = start;
        start = end + 1;
        const auto q = nodes[next].qual;
        if (q.s[0] != 0 && q.s[1] != 0) continue;
        if ((next == 0 || end + 1 == n) && !closed[c]) continue;
        if (next == 0 && end + 1 == n) continue;
        const auto& before = nodes[(next + n - 1) % n];
        const auto& after = nodes[(end + 1) % n];
        if (before.qual == q || after.qual == q || before.join || after.join) continue;
        double len = 0;
        for (std::size_t k = next; k < end; ++k) len += difference(r, nodes[k].q, nodes[k + 1].q).cwiseProduct(scale).norm();
        if (len >= 0.5) continue;
        auto& m = nodes[(next + end) / 2];
        const PlaceId j = add_join(JoinKind::normal_change, m.q, {before.qual, after.qual});
        v.places[j.value].concave = concave(before, after, m.q);
        for (std::size_t k = next; k <= end; ++k) nodes[k].point = -1;
        m.join = j;
        for (std::size_t k = next; k <= end; ++k)
            if (k != (next + end) / 2) nodes[k].qual = k < (next + end) / 2 ? before.qual : after.qual;
    }
    // Drop the collapsed run's other points (no boundary point, no join).
    std::erase_if(nodes, [](const ChainNode& x) { return x.point < 0 && !x.join; });
}

// Joins where the qualitative normal changes (8.1.2), placed on the boundary between the two
// points, with Defs 29-30 deciding concave or convex.
void Builder::insert_normal_joins(std::size_t c) {
    collapse_point_runs(c);
    auto& nodes = chains[c];
    std::vector<ChainNode> out;
    const std::size_t n = nodes.size();
    for (std::size_t k = 0; k < n; ++k) {
        if (nodes[k].join) {  // a run collapsed to a join by collapse_point_runs
            out.push_back(nodes[k]);
            continue;
        }
        out.push_back(nodes[k]);
        if (k + 1 == n && !closed[c]) break;
        const auto& a = nodes[k];
        const auto& b = nodes[(k + 1) % n];
        if (a.qual == b.qual || b.join) continue;
        const Eigen::Vector2d q = corner(nodes, k, closed[c]);
        const PlaceId j = add_join(JoinKind::normal_change, q, {a.qual, b.qual});
        v.places[j.value].concave = concave(a, b, q);
        out.push_back({wrap(r, q), -1, j, a.qual, (a.normal + b.normal).normalized()});
    }
    if (!closed[c] && !out.empty()) {  // a chain leaving a translation axis' domain ends in a limit
        const auto first = out.front(), last = out.back();
        out.insert(out.begin(), {first.q, -1, add_join(JoinKind::limit, first.q, {first.qual}), first.qual, first.normal});
        out.push_back({last.q, -1, add_join(JoinKind::limit, last.q, {last.qual}), last.qual, last.normal});
    }
    nodes = std::move(out);
}

// Two joins closer than a boundary sample's spacing (a division's end a part of a cell from a
// corner) still have the boundary between them: a CSEG of the qualitative normal the first join
// hands on (Def 28), so that a motion from the face beside it meets a place there, not a gap.
void Builder::emit_between_joins(const ChainNode& a, const ChainNode& b) {
    const Eigen::Vector2d d = difference(r, a.q, b.q);
    const double same = std::max(1e-3, 8 * r.boundary_tolerance * cell().cwiseInverse().maxCoeff());
    if (a.join == b.join || d.cwiseQuotient(cell()).norm() <= same) return;
    const QualDirection qual = v.at(*a.join).normals.back();
    const Eigen::Vector2d guess = a.normal.norm() > 0 ? a.normal : b.normal;
    const Eigen::Vector2d mid = wrap(r, project(a.q + 0.5 * d, guess));
    Eigen::Vector2d normal = oracle.free_normal(mid);
    normal = normal.norm() > 0 ? Eigen::Vector2d(normal.normalized()) : guess;
    Place p;
    p.kind = PlaceKind::cseg;
    p.normals = {qual};
    p.points = {a.q, mid, b.q};
    const PlaceId id = add(std::move(p));
    // A slide along it goes from one join to the other: its tangent is their chord.
    lines.push_back(LineInfo{id, a.join, b.join, mid, normal, d.normalized(), false});
}

void Builder::emit_csegs() {
    for (std::size_t c = 0; c < chains.size(); ++c) {
        const auto& nodes = chains[c];
        const std::size_t n = nodes.size();
        std::vector<std::size_t> cuts;
        for (std::size_t k = 0; k < n; ++k)
            if (nodes[k].join) cuts.push_back(k);
        auto emit = [&](std::optional<std::size_t> from, std::vector<std::size_t> members, std::optional<std::size_t> to) {
            std::vector<std::size_t> pts;
            for (auto k : members)
                if (nodes[k].point >= 0) pts.push_back(k);
            if (pts.empty()) {
                if (from && to) emit_between_joins(nodes[*from], nodes[*to]);
                return;
            }
            Place p;
            p.kind = PlaceKind::cseg;
            p.normals = {nodes[pts.front()].qual};
            if (from) p.points.push_back(nodes[*from].q);
            for (auto k : pts) p.points.push_back(nodes[k].q);
            if (to) p.points.push_back(nodes[*to].q);
            // The tangent runs from the start join towards the end join: along the points, step by
            // step (a CSEG may run more than half round a periodic axis, where the short way
            // between its ends is the other way), joins included (one boundary point between them
            // says no direction by itself).
            Eigen::Vector2d chord = Eigen::Vector2d::Zero();
            for (std::size_t k = 0; k + 1 < p.points.size(); ++k) chord += difference(r, p.points[k], p.points[k + 1]);
            const PlaceId id = add(std::move(p));
            const auto& m = nodes[pts[pts.size() / 2]];
            LineInfo li{id, from ? nodes[*from].join : std::nullopt, to ? nodes[*to].join : std::nullopt, m.q,
                        m.normal, Eigen::Vector2d(-m.normal.y(), m.normal.x()), false};
            if (li.tangent.dot(chord) < 0) li.tangent = -li.tangent;
            lines.push_back(li);
        };
        if (cuts.empty()) {  // a closed boundary of one normal: one CSEG, no joins
            std::vector<std::size_t> all(n);
            for (std::size_t k = 0; k < n; ++k) all[k] = k;
            emit(std::nullopt, all, std::nullopt);
            continue;
        }
        const std::size_t pieces = closed[c] ? cuts.size() : cuts.size() - 1;
        for (std::size_t i = 0; i < pieces; ++i) {
            const std::size_t a = cuts[i], b = cuts[(i + 1) % cuts.size()];
            std::vector<std::size_t> members;
            for (std::size_t k = (a + 1) % n; k != b; k = (k + 1) % n) members.push_back(k);
            emit(a, members, b);
        }
    }
}

void Builder::emit_divisions() {
    for (auto& d : divisions) {
        std::sort(d.joins.begin(), d.joins.end(), [](const auto& x, const auto& y) { return x.first < y.first; });
        for (std::size_t i = 0; i + 1 < d.joins.size(); ++i) {
            const double t0 = d.joins[i].first, t1 = d.joins[i + 1].first;
            if (t1 - t0 <= 0) continue;
            Place p;
            p.kind = d.kind;
            p.axis = d.axis;
            p.label = d.label;
            // On a periodic axis the two ends alone do not say which way round the division
            // runs (a piece can be half the period or longer), so it carries points at most a
            // quarter period apart, in its own direction.
            const auto& ax = r.axes[static_cast<std::size_t>(d.axis)];
            const int steps = ax.periodic ? std::max(2, static_cast<int>(std::ceil(4 * (t1 - t0) / ax.span()))) : 1;
            for (int k = 0; k <= steps; ++k) p.points.push_back(wrap(r, d.at(t0 + (t1 - t0) * k / steps)));
            const PlaceId id = add(std::move(p));
            Eigen::Vector2d tangent = Eigen::Vector2d::Zero();
            tangent[d.axis] = d.dir;
            Eigen::Vector2d normal = Eigen::Vector2d::Zero();
            normal[1 - d.axis] = 1;
            lines.push_back({id, d.joins[i].second, d.joins[i + 1].second, wrap(r, d.at(0.5 * (t0 + t1))), normal, tangent, true});
        }
    }
}

std::array<std::vector<double>, 2> Builder::feature_coordinates() const {
    std::array<std::vector<double>, 2> out;
    for (const auto& d : divisions) out[static_cast<std::size_t>(1 - d.axis)].push_back(d.start[1 - d.axis]);
    for (const auto& p : v.places)
        if (p.kind == PlaceKind::join)
            for (std::size_t k = 0; k < 2; ++k) out[k].push_back(p.points.front()[static_cast<Eigen::Index>(k)]);
    return out;
}

}  // namespace qm::geometry::detail

namespace qm::geometry {

PlaceResult build_place_vocabulary(const PairOracle& oracle, const PlaceRequest& request) {
    PlaceResult out;
    out.space = classify_cspace(oracle, request.cspace);
    if (out.space.status != CSpaceStatus::ok) {
        out.status = PlaceStatus::bad_request;
        out.message = out.space.message;
        return out;
    }
    for (const auto& x : request.external)
        if (x.coordinate != 0 && x.coordinate != 1) {
            out.status = PlaceStatus::bad_request;
            out.message = "external division '" + x.label + "' names no configuration coordinate";
            return out;
        }
    if (!(request.merge_epsilon >= 0) || !(request.gap_epsilon >= 0)) {
        out.status = PlaceStatus::bad_request;
        out.message = "merge and gap epsilons must not be negative";
        return out;
    }
    detail::Builder b{oracle, request, request.cspace, out.space, out.vocabulary, {}, {}, {}, {}};
    b.make_chains(trace_boundary(oracle, out.space));
    b.insert_joins_and_drop_tip_islands();
    b.grow_fsds();
    b.add_external_divisions();
    b.cross_divisions();
    b.emit_csegs();
    b.emit_divisions();
    b.add_stops();
    const detail::FaceGrid grid(oracle, out.space, b.feature_coordinates());
    detail::FaceLocator faces(grid, b.divisions, b.barriers_at_joins());
    const int n_faces = faces.label();
    std::vector<PlaceId> face_places;
    std::vector<int> size(static_cast<std::size_t>(n_faces), 0);
    std::vector<Eigen::Vector2d> sample(static_cast<std::size_t>(n_faces));
    const auto& r = request.cspace;
    // A face's representative sample: the one nearest the mean of its samples (for labels), and
    // its size, counted on the configuration space's own grid where the face has samples there
    // (a strip between close features only on the lines inserted for it).
    std::vector<Eigen::Vector2d> sum(static_cast<std::size_t>(n_faces), Eigen::Vector2d::Zero());
    std::vector<bool> sampled(static_cast<std::size_t>(n_faces), false);
    for (int j = 0; j < grid.size(1); ++j)
        for (int i = 0; i < grid.size(0); ++i)
            if (const int f = faces.face_of_sample(i, j); f >= 0 && grid.sampled(0, i) && grid.sampled(1, j)) sampled[static_cast<std::size_t>(f)] = true;
    for (int pass = 0; pass < 2; ++pass)
        for (int j = 0; j < grid.size(1); ++j)
            for (int i = 0; i < grid.size(0); ++i) {
                const int f = faces.face_of_sample(i, j);
                if (f < 0) continue;
                const auto fi = static_cast<std::size_t>(f);
                if (sampled[fi] && !(grid.sampled(0, i) && grid.sampled(1, j))) continue;
                const Eigen::Vector2d x = grid.point(i, j);
                if (pass == 0) {
                    ++size[fi];
                    sum[fi] += x;
                    sample[fi] = x;
                } else if ((x - sum[fi] / size[fi]).norm() < (sample[fi] - sum[fi] / size[fi]).norm()) {
                    sample[fi] = x;
                }
            }
    for (int f = 0; f < n_faces; ++f) {
        Place p;
        p.kind = PlaceKind::face;
        p.points = {sample[static_cast<std::size_t>(f)]};
        p.extent = size[static_cast<std::size_t>(f)];
        face_places.push_back(b.add(std::move(p)));
    }
    detail::add_adjacency(oracle, r, b.lines, faces, face_places, out.vocabulary);
    // A gap collapsed below keeps its face's values: the CSEGs it absorbs bound that face.
    detail::set_face_covers(faces, face_places, out.vocabulary);
    detail::collapse_gaps(oracle, faces, face_places, request.gap_epsilon, out.vocabulary);
    if (const auto why = detail::incompleteness(request.cspace, out.vocabulary)) {
        out.status = PlaceStatus::incomplete;
        out.message = "the grid (" + std::to_string(request.cspace.axes[0].samples) + " x " + std::to_string(request.cspace.axes[1].samples) +
                      ") left " + *why;
    }
    return out;
}

}  // namespace qm::geometry
