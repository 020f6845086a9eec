// geometry/place_vocabulary_builder.cpp: CSEGs, joins, FSDs, external divisions, full faces
// (thesis 4.2, 8.1.2, 8.1.6, 8.2.1).
#include "geometry/place_vocabulary_builder.hpp"

#include "geometry/cspace_boundary.hpp"
#include "geometry/detail/place_parts.hpp"
#include "qm/assert.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>

namespace qm::geometry {
namespace {

using detail::Division;
using detail::LineInfo;

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

    // Move q onto the boundary along direction n (cell-scaled), if the boundary is within a cell.
    Eigen::Vector2d project(const Eigen::Vector2d& q, Eigen::Vector2d n) {
        n = n.cwiseProduct(cell());
        if (n.norm() == 0) return q;
        n = n.normalized() * cell().norm();
        const bool lo = blocked(q - n), hi = blocked(q + n);
        if (lo == hi) return q;
        return bisect_contact(oracle, q - n, lo, q + n, r.boundary_tolerance, space.oracle_calls);
    }

    void make_chains(const std::vector<BoundaryChain>& traced);
    void absorb_short_runs(std::vector<ChainNode>& nodes, bool is_closed);
    void insert_normal_joins(std::size_t c);
    void collapse_point_runs(std::size_t c);
    Eigen::Vector2d corner(const ChainNode& a, const ChainNode& b);
    bool duplicate(const Division& d) const;
    void grow_fsds();
    bool runs_along_boundary(const Division& d, const CSpaceAxis& ax);
    void add_external_divisions();
    void end_on_boundary(Division& d, double t, JoinKind kind);
    void cross_divisions();
    void emit_csegs();
    void emit_divisions();
};

void Builder::make_chains(const std::vector<BoundaryChain>& traced) {
    for (const auto& t : traced) {
        std::vector<ChainNode> nodes;
        for (int k : t.points) {
            const auto& p = space.boundary[static_cast<std::size_t>(k)];
            nodes.push_back({p.q, k, std::nullopt, p.qual, p.normal});
        }
        absorb_short_runs(nodes, t.closed);
        chains.push_back(std::move(nodes));
        closed.push_back(t.closed);
    }
}

// 8.1.6: "interactions between small irregularities on surfaces may be ignored": a run of one
// normal class shorter than merge_epsilon, between two runs of one other class, takes that class.
void Builder::absorb_short_runs(std::vector<ChainNode>& nodes, bool is_closed) {
    if (request.merge_epsilon <= 0 || nodes.size() < 3) return;
    const std::size_t n = nodes.size();
    for (std::size_t start = 0; start < n;) {
        std::size_t end = start;
        double len = 0;
        while (end + 1 < n && nodes[end + 1].qual == nodes[start].qual) {
            len += difference(r, nodes[end].q, nodes[end + 1].q).norm();
            ++end;
        }
        const bool has_prev = start > 0 || is_closed, has_next = end + 1 < n || is_closed;
        if (has_prev && has_next && len < request.merge_epsilon) {
            const auto& before = nodes[(start + n - 1) % n].qual;
            const auto& after = nodes[(end + 1) % n].qual;
            if (before == after && before != nodes[start].qual)
                for (std::size_t k = start; k <= end; ++k) nodes[k].qual = before;
        }
        start = end + 1;
    }
}

// Where a join between boundary points a and b lies: the crossing of their tangent lines when
// the normals differ enough to make it well conditioned and it lies near them (a corner), moved
// onto the boundary along the mean normal.
Eigen::Vector2d Builder::corner(const ChainNode& a, const ChainNode& b) {
    const Eigen::Vector2d pb = a.q + difference(r, a.q, b.q);
    const Eigen::Vector2d mid = 0.5 * (a.q + pb);
    Eigen::Vector2d guess = mid;
    const double det = a.normal.x() * b.normal.y() - a.normal.y() * b.normal.x();
    if (std::abs(det) > 0.2) {
        Eigen::Matrix2d m;
        m << a.normal.x(), a.normal.y(), b.normal.x(), b.normal.y();
        const Eigen::Vector2d x = m.inverse() * Eigen::Vector2d(a.normal.dot(a.q), b.normal.dot(pb));
        if ((x - mid).cwiseQuotient(cell()).norm() < 1.5) guess = x;
    }
    return project(guess, a.normal + b.normal);
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
        v.places[j.value].concave = difference(r, m.q, after.q).dot(before.normal) > 0;
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
        const Eigen::Vector2d q = corner(a, b);
        const PlaceId j = add_join(JoinKind::normal_change, q, {a.qual, b.qual});
        // Def 29: concave if the CSEG beyond the join lies in the half plane of this side's normal.
        v.places[j.value].concave = difference(r, q, b.q).dot(a.normal) > 0;
        out.push_back({wrap(r, q), -1, j, a.qual, (a.normal + b.normal).normalized()});
    }
    if (!closed[c] && !out.empty()) {  // a chain leaving a translation axis' domain ends in a limit
        const auto first = out.front(), last = out.back();
        out.insert(out.begin(), {first.q, -1, add_join(JoinKind::limit, first.q, {first.qual}), first.qual, first.normal});
        out.push_back({last.q, -1, add_join(JoinKind::limit, last.q, {last.qual}), last.qual, last.normal});
    }
    nodes = std::move(out);
}

// A direction that runs along a CSEG parallel to the axis (a box edge) is that CSEG, not an
// FSD: a little way along, a small step across it is blocked on one side. A tangent to a curved
// CSEG has left the curve by then, so it stays an FSD.
bool Builder::runs_along_boundary(const Division& d, const CSpaceAxis& ax) {
    const int other = 1 - d.axis;
    const double across = 16 * r.boundary_tolerance + 1e-9 * r.axes[static_cast<std::size_t>(other)].span();
    for (double t : {0.05 * ax.step(), 0.25 * ax.step()})
        for (double side : {-1.0, 1.0}) {
            Eigen::Vector2d q = d.at(t);
            q[other] += side * across;
            if (in_domain(q) && blocked(q)) return true;
        }
    return false;
}

// Two joins at the same height start the same division; keep one.
bool Builder::duplicate(const Division& d) const {
    const int other = 1 - d.axis;
    for (const auto& e : divisions) {
        if (e.axis != d.axis || std::abs(difference(r, e.start, d.start)[other]) > 8 * r.boundary_tolerance) continue;
        const auto& ax = r.axes[static_cast<std::size_t>(d.axis)];
        double t = e.dir * (d.start[d.axis] - e.start[e.axis]);
        if (ax.periodic) t = std::fmod(std::fmod(t, ax.span()) + ax.span(), ax.span());
        if (t >= -8 * r.boundary_tolerance && t <= e.length + 8 * r.boundary_tolerance && e.dir == d.dir) return true;
        if (e.length >= ax.span() && ax.periodic) return true;  // a loop covers the whole line
    }
    return false;
}

// Def 31: from each significant point follow each axis until the next contact.
void Builder::grow_fsds() {
    const std::size_t joins = v.places.size();
    for (std::size_t jp = 0; jp < joins; ++jp) {
        const Place& j = v.places[jp];
        if (j.kind != PlaceKind::join || j.join_kind != JoinKind::normal_change) continue;
        const Eigen::Vector2d origin = j.points.front();
        for (int axis = 0; axis < 2; ++axis)
            for (int dir : {1, -1}) {
                const auto& ax = r.axes[static_cast<std::size_t>(axis)];
                Division d{PlaceKind::fsd, axis, dir, origin, 0.0, {}, {{0.0, PlaceId{static_cast<std::uint32_t>(jp)}}}};
                const double first = std::max(8 * r.boundary_tolerance, 0.05 * ax.step());
                if (!in_domain(d.at(first)) || blocked(d.at(first))) continue;
                if (runs_along_boundary(d, ax) || duplicate(d)) continue;
                double t = first;
                bool ended = false;
                while (!ended) {
                    double next = t + ax.step();
                    if (ax.periodic && next >= ax.span()) {  // around the whole axis: ends where it began
                        if (dir < 0) break;                  // the + direction already covers the loop
                        d.length = ax.span();
                        d.joins.push_back({ax.span(), d.joins.front().second});
                        divisions.push_back(d);
                        ended = true;
                    } else if (!ax.periodic && !in_domain(d.at(next))) {
                        next = dir > 0 ? ax.hi - origin[axis] : origin[axis] - ax.lo;
                        d.length = next;
                        d.joins.push_back({next, add_join(JoinKind::limit, d.at(next), {})});
                        divisions.push_back(d);
                        ended = true;
                    } else if (blocked(d.at(next))) {
                        const Eigen::Vector2d e = bisect_contact(oracle, d.at(t), false, d.at(next), r.boundary_tolerance, space.oracle_calls);
                        d.length = std::abs(e[axis] - origin[axis]);
                        end_on_boundary(d, d.length, JoinKind::fsd_end);
                        divisions.push_back(d);
                        ended = true;
                    }
                    t = next;
                }
            }
    }
}

// The division ends on a CSEG at parameter t: a join there splits that CSEG (8.1.2).
void Builder::end_on_boundary(Division& d, double t, JoinKind kind) {
    const Eigen::Vector2d e = wrap(r, d.at(t));
    const Eigen::Vector2d scale = cell().cwiseInverse();
    std::size_t best_c = 0, best_k = 0;
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t c = 0; c < chains.size(); ++c)
        for (std::size_t k = 0; k < chains[c].size(); ++k) {
            const double dist = difference(r, chains[c][k].q, e).cwiseProduct(scale).norm();
            if (dist < best) {
                best = dist;
                best_c = c;
                best_k = k;
            }
        }
    QualDirection qual;
    Eigen::Vector2d normal = Eigen::Vector2d::Zero();
    if (!chains.empty()) {
        qual = chains[best_c][best_k].qual;
        normal = chains[best_c][best_k].normal;
    }
    const PlaceId j = add_join(kind, e, {qual});
    d.joins.push_back({t, j});
    if (chains.empty()) return;
    // Insert next to the nearest node, on the side whose neighbour is closer to e.
    auto& nodes = chains[best_c];
    const std::size_t n = nodes.size();
    std::size_t pos = best_k + 1;
    if (best_k > 0 || closed[best_c]) {
        const auto& prev = nodes[(best_k + n - 1) % n];
        const auto& next = nodes[(best_k + 1) % n];
        if (difference(r, prev.q, e).cwiseProduct(scale).norm() < difference(r, next.q, e).cwiseProduct(scale).norm())
            pos = best_k == 0 ? n : best_k;
    }
    if (!closed[best_c]) pos = std::clamp<std::size_t>(pos, 1, n - 1);  // stay inside the limit joins
    nodes.insert(nodes.begin() + static_cast<std::ptrdiff_t>(pos), ChainNode{e, -1, j, qual, normal});
}

// 8.2.1 / 9.2: a position-dependent force divides places along a line; parts of the line in
// blocked space are ignored.
void Builder::add_external_divisions() {
    for (const auto& x : request.external) {
        const int axis = 1 - x.coordinate;
        const auto& ax = r.axes[static_cast<std::size_t>(axis)];
        Eigen::Vector2d q = Eigen::Vector2d::Zero();
        q[x.coordinate] = x.value;
        auto at = [&](int m) {
            Eigen::Vector2d p = q;
            p[axis] = ax.sample(m);
            return p;
        };
        const int n = ax.samples;
        std::vector<bool> b(static_cast<std::size_t>(n));
        for (int m = 0; m < n; ++m) b[static_cast<std::size_t>(m)] = blocked(at(m));
        const bool all_free = std::none_of(b.begin(), b.end(), [](bool y) { return y; });
        if (all_free) {
            Division d{PlaceKind::external_division, axis, 1, at(0), 0.0, x.label, {}};
            if (ax.periodic) {
                d.length = ax.span();
                const PlaceId j = add_join(JoinKind::crossing, at(0), {});
                d.joins = {{0.0, j}, {ax.span(), j}};
            } else {
                d.length = ax.span();
                d.joins = {{0.0, add_join(JoinKind::limit, at(0), {})}, {ax.span(), add_join(JoinKind::limit, at(n - 1), {})}};
            }
            divisions.push_back(d);
            continue;
        }
        // Each maximal free run of samples, extended to the contacts on both sides.
        const int stop = ax.periodic ? n : n - 1;
        for (int m = 0; m < stop; ++m) {
            const int m1 = (m + 1) % n;
            if (!(b[static_cast<std::size_t>(m)] && !b[static_cast<std::size_t>(m1)])) continue;
            Eigen::Vector2d lo = at(m), hi = lo;
            hi[axis] += ax.step();
            const Eigen::Vector2d s = bisect_contact(oracle, lo, true, hi, r.boundary_tolerance, space.oracle_calls);
            Division d{PlaceKind::external_division, axis, 1, s, 0.0, x.label, {}};
            d.joins.push_back({0.0, PlaceId{0}});
            end_on_boundary(d, 0.0, JoinKind::fsd_end);
            d.joins.erase(d.joins.begin());
            int k = m1;
            while (!b[static_cast<std::size_t>(k)] && (ax.periodic || k + 1 < n)) k = (k + 1) % n;
            if (b[static_cast<std::size_t>(k)]) {
                Eigen::Vector2d a2 = at((k + n - 1) % n), b2 = at(k);
                if (b2[axis] < a2[axis]) b2[axis] += ax.span();
                const Eigen::Vector2d e = bisect_contact(oracle, b2, true, a2, r.boundary_tolerance, space.oracle_calls);
                double len = e[axis] - s[axis];
                if (ax.periodic && len < 0) len += ax.span();
                d.length = len;
                end_on_boundary(d, len, JoinKind::fsd_end);
            } else {
                d.length = ax.hi - s[axis];
                d.joins.push_back({d.length, add_join(JoinKind::limit, at(n - 1), {})});
            }
            divisions.push_back(d);
        }
    }
}

// Crossings of divisions along different axes are joins (8.1.2) that split both.
void Builder::cross_divisions() {
    for (std::size_t a = 0; a < divisions.size(); ++a)
        for (std::size_t b = a + 1; b < divisions.size(); ++b) {
            auto& da = divisions[a];
            auto& db = divisions[b];
            if (da.axis == db.axis) continue;
            auto param = [&](const Division& d, double x) {
                const auto& ax = r.axes[static_cast<std::size_t>(d.axis)];
                double t = d.dir * (x - d.start[d.axis]);
                if (ax.periodic) t = std::fmod(std::fmod(t, ax.span()) + ax.span(), ax.span());
                return t;
            };
            const double ta = param(da, db.start[da.axis]);
            const double tb = param(db, da.start[db.axis]);
            const double eps = 4 * r.boundary_tolerance;
            if (ta <= eps || ta >= da.length - eps || tb <= eps || tb >= db.length - eps) continue;
            const PlaceId j = add_join(JoinKind::crossing, da.at(ta), {});
            da.joins.push_back({ta, j});
            db.joins.push_back({tb, j});
        }
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
            if (pts.empty()) return;
            Place p;
            p.kind = PlaceKind::cseg;
            p.normals = {nodes[pts.front()].qual};
            if (from) p.points.push_back(nodes[*from].q);
            for (auto k : pts) p.points.push_back(nodes[k].q);
            if (to) p.points.push_back(nodes[*to].q);
            const PlaceId id = add(std::move(p));
            const auto& m = nodes[pts[pts.size() / 2]];
            LineInfo li{id, from ? nodes[*from].join : std::nullopt, to ? nodes[*to].join : std::nullopt, m.q,
                        m.normal, Eigen::Vector2d(-m.normal.y(), m.normal.x()), false};
            // Orient the tangent from the start join towards the end join.
            if (pts.size() >= 2) {
                const Eigen::Vector2d chord = difference(r, nodes[pts.front()].q, nodes[pts.back()].q);
                if (li.tangent.dot(chord) < 0) li.tangent = -li.tangent;
            }
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
            p.points = {wrap(r, d.at(t0)), wrap(r, d.at(t1))};
            const PlaceId id = add(std::move(p));
            Eigen::Vector2d tangent = Eigen::Vector2d::Zero();
            tangent[d.axis] = d.dir;
            Eigen::Vector2d normal = Eigen::Vector2d::Zero();
            normal[1 - d.axis] = 1;
            lines.push_back({id, d.joins[i].second, d.joins[i + 1].second, wrap(r, d.at(0.5 * (t0 + t1))), normal, tangent, true});
        }
    }
}

}  // namespace

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
    if (!(request.merge_epsilon >= 0)) {
        out.status = PlaceStatus::bad_request;
        out.message = "merge epsilon must not be negative";
        return out;
    }
    Builder b{oracle, request, request.cspace, out.space, out.vocabulary, {}, {}, {}, {}};
    b.make_chains(trace_boundary(oracle, out.space));
    for (std::size_t c = 0; c < b.chains.size(); ++c) b.insert_normal_joins(c);
    b.grow_fsds();
    b.add_external_divisions();
    b.cross_divisions();
    b.emit_csegs();
    b.emit_divisions();
    detail::FaceLocator faces(out.space, b.divisions);
    const int n_faces = faces.label();
    std::vector<PlaceId> face_places;
    std::vector<int> size(static_cast<std::size_t>(n_faces), 0);
    std::vector<Eigen::Vector2d> sample(static_cast<std::size_t>(n_faces));
    const auto& r = request.cspace;
    // A face's representative sample: the one nearest the mean of its samples (for labels).
    std::vector<Eigen::Vector2d> sum(static_cast<std::size_t>(n_faces), Eigen::Vector2d::Zero());
    for (int pass = 0; pass < 2; ++pass)
        for (int j = 0; j < r.axes[1].samples; ++j)
            for (int i = 0; i < r.axes[0].samples; ++i) {
                const int f = faces.face_of_sample(i, j);
                if (f < 0) continue;
                const auto fi = static_cast<std::size_t>(f);
                const Eigen::Vector2d x(r.axes[0].sample(i), r.axes[1].sample(j));
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
    return out;
}

}  // namespace qm::geometry
