// geometry/detail/free_space_divisions.cpp: FSDs (Def 31), external place divisions (8.2.1,
// 9.2) and their crossings (8.1.2).
#include "geometry/detail/place_builder.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <limits>

namespace qm::geometry::detail {

// A direction that runs along a CSEG parallel to the axis (a box edge) is that CSEG, not an
// FSD: a quarter and a twentieth of a cell along, a small step across it is blocked on one side
// at both. A tangent to a curved CSEG has left the curve by the quarter, so it stays an FSD. The
// step across is a thousandth of a cell at least: a flat CSEG found on tessellated parts wobbles
// by the chordal error, far more than the bisection tolerance.
bool Builder::runs_along_boundary(const Division& d, const CSpaceAxis& ax) {
    const int other = 1 - d.axis;
    const double across = std::max(16 * r.boundary_tolerance + 1e-9 * r.axes[static_cast<std::size_t>(other)].span(), 1e-3 * cell()[other]);
    for (double side : {-1.0, 1.0}) {
        bool both = true;
        for (double t : {0.05 * ax.step(), 0.25 * ax.step()}) {
            Eigen::Vector2d q = d.at(t);
            q[other] += side * across;
            both = both && in_domain(q) && blocked(q);
        }
        if (both) return true;
    }
    return false;
}

// Two joins at the same height start the same division; keep one. "The same height" is within
// a thousandth of a cell (or the bisection tolerance, if coarser): two divisions nearer than
// that bound no face the grid can see.
bool Builder::duplicate(const Division& d) const {
    const int other = 1 - d.axis;
    const double same = std::max(8 * r.boundary_tolerance, 1e-3 * cell()[other]);
    for (const auto& e : divisions) {
        if (e.axis != d.axis || std::abs(difference(r, e.start, d.start)[other]) > same) continue;
        const auto& ax = r.axes[static_cast<std::size_t>(d.axis)];
        double t = e.dir * (d.start[d.axis] - e.start[e.axis]);
        if (ax.periodic) t = std::fmod(std::fmod(t, ax.span()) + ax.span(), ax.span());
        if (t >= -same && t <= e.length + same && e.dir == d.dir) return true;
        // Starting at e's far end and running back along it (the division from a convex join up
        // to a concave one above it, and the one from there down): e itself.
        if (e.dir == -d.dir && std::abs(t - e.length) <= same && !(e.length >= ax.span() && ax.periodic)) return true;
        if (e.length >= ax.span() && ax.periodic) return true;  // a loop covers the whole line
    }
    return false;
}

// Def 31: from each significant point follow each axis until the next contact.
void Builder::grow_fsds() {
    const std::size_t joins = v.places.size();
    std::vector<Eigen::Vector2d> mean_normal(joins, Eigen::Vector2d::Zero());  // of each join on a chain
    for (const auto& nodes : chains)
        for (const auto& node : nodes)
            if (node.join && node.join->value < joins) mean_normal[node.join->value] = node.normal;
    for (std::size_t jp = 0; jp < joins; ++jp) {
        const Place j = v.places[jp];  // a copy: joins are added below
        if (j.kind != PlaceKind::join || j.join_kind != JoinKind::normal_change) continue;
        const Eigen::Vector2d origin = j.points.front();
        for (int axis = 0; axis < 2; ++axis)
            for (int dir : {1, -1}) {
                const auto& ax = r.axes[static_cast<std::size_t>(axis)];
                Division d{PlaceKind::fsd, axis, dir, origin, 0.0, {}, {{0.0, PlaceId{static_cast<std::uint32_t>(jp)}}}};
                // The join's normals first: a direction they close (along the tangent at the
                // bottom of a concave curve, into a corner) starts no division, whatever the
                // tessellation's chords leave free a twentieth of a cell out.
                QualDirection along;
                along.s[static_cast<std::size_t>(axis)] = static_cast<std::int8_t>(dir);
                const std::optional<bool> opens = leads_into_free_space(j, along);
                if (opens == false) continue;
                // A division the normals open along the boundary's tangent (the side of a convex
                // bulge where it is parallel to the axis) runs, for a cell or so, within the
                // tessellation's error of the boundary found on the meshes: probes on the line
                // through the join met the meshes by chance (the ratchet's bulge at 128 x 1024 lost
                // both its divisions). It runs a twentieth of a cell off the join, into
                // free space, instead.
                const Eigen::Vector2d m = in_cells(mean_normal[jp]);
                const int other = 1 - axis;
                if (opens == true && m.norm() > 0.5 && std::abs(m[axis]) < 0.2)
                    d.start[other] += (m[other] > 0 ? 1 : -1) * 0.05 * r.axes[static_cast<std::size_t>(other)].step();
                const double first = std::max(8 * r.boundary_tolerance, 0.05 * ax.step());
                if (!in_domain(d.at(first)) || blocked(d.at(first))) continue;
                if (runs_along_boundary(d, ax) || duplicate(d)) continue;
                double t = first;
                bool ended = false;
                while (!ended) {
                    double next = t + ax.step();
                    // Around the whole axis, it ends where it began: a loop (once: the other
                    // direction finds it a duplicate). Either direction may be the one that goes
                    // round: from a join at the top of a curve, the tangent meets the curve again
                    // at once on one side, by a hair, and which side depends on rounding.
                    auto loop = [&] {
                        d.length = ax.span();
                        d.joins.resize(1);
                        d.joins.push_back({ax.span(), d.joins.front().second});
                        divisions.push_back(d);
                        ended = true;
                    };
                    if (ax.periodic && next >= ax.span()) {
                        loop();
                    } else if (!ax.periodic && !in_domain(d.at(next))) {
                        next = dir > 0 ? ax.hi - origin[axis] : origin[axis] - ax.lo;
                        d.length = next;
                        d.joins.push_back({next, add_join(JoinKind::limit, d.at(next), {})});
                        divisions.push_back(d);
                        ended = true;
                    } else if (blocked(d.at(next))) {
                        const Eigen::Vector2d e = bisect_contact(oracle, d.at(t), false, d.at(next), r.boundary_tolerance, space.oracle_calls);
                        d.length = std::abs(e[axis] - origin[axis]);
                        // Meeting the boundary within half a cell of its join, the division is
                        // the join's own CSEG seen along its tangent (at a smooth extremum, once
                        // tessellation has rounded it into chords), not a division of free
                        // space: the grid resolves nothing that narrow anyway. Going round a
                        // periodic axis to within half a cell of its join, it is a loop.
                        if (ax.periodic && d.length > ax.span() - 0.5 * ax.step()) {
                            if (!duplicate(d)) loop();
                        } else if (d.length >= 0.5 * ax.step()) {
                            end_on_boundary(d, d.length, JoinKind::fsd_end);
                            divisions.push_back(d);
                        }
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
    // Ending on a join already there (to a thousandth of a cell, or the bisection's tolerance), it
    // ends at that join: a second join beside it, 2e-9 away, went before or after it along the
    // chain by rounding (the Scotch yoke's divisions between its two joins at q0 = 0).
    const double same = std::max(1e-3, 8 * r.boundary_tolerance * scale.maxCoeff());
    for (const auto& nodes : chains)
        for (const auto& node : nodes)
            if (node.join && difference(r, node.q, e).cwiseProduct(scale).norm() <= same) {
                d.joins.push_back({t, *node.join});
                return;
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
    // Insert next to the nearest node, on the side of it that e lies towards along the chain.
    // Which neighbour is nearer says nothing where the nodes are closer together than their
    // neighbours: a join put on the far side of its nearest point cuts no CSEG (the boundary
    // points between two joins make the CSEG), and a face beside the CSEG then seems to span it all.
    auto& nodes = chains[best_c];
    const std::size_t n = nodes.size();
    std::size_t pos = best_k + 1;
    if (best_k > 0 || closed[best_c]) {
        const Eigen::Vector2d to_e = difference(r, nodes[best_k].q, e).cwiseProduct(scale);
        auto towards = [&](std::size_t k) {
            const Eigen::Vector2d to_k = difference(r, nodes[best_k].q, nodes[k].q).cwiseProduct(scale);
            return to_k.norm() > 0 ? to_e.dot(to_k.normalized()) : 0.0;
        };
        const bool has_next = closed[best_c] || best_k + 1 < n;
        if (!has_next || towards((best_k + n - 1) % n) > towards((best_k + 1) % n)) pos = best_k == 0 ? n : best_k;
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
        // Each maximal free run of samples, extended to the contacts on both sides, or to the axis'
        // limits on a non-periodic axis (a run may be free at either end).
        auto finish = [&](Division& d, const Eigen::Vector2d& s, int first_free) {
            int k = first_free;
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
        };
        if (!ax.periodic && !b[0]) {
            Division d{PlaceKind::external_division, axis, 1, at(0), 0.0, x.label, {}};
            d.joins.push_back({0.0, add_join(JoinKind::limit, at(0), {})});
            finish(d, at(0), 0);
        }
        const int stop = ax.periodic ? n : n - 1;
        for (int m = 0; m < stop; ++m) {
            const int m1 = (m + 1) % n;
            if (!(b[static_cast<std::size_t>(m)] && !b[static_cast<std::size_t>(m1)])) continue;
            Eigen::Vector2d lo = at(m), hi = lo;
            hi[axis] = ax.sample(m + 1);  // unwrapped: hi itself past the last sample of a periodic axis
            const Eigen::Vector2d s = bisect_contact(oracle, lo, true, hi, r.boundary_tolerance, space.oracle_calls);
            Division d{PlaceKind::external_division, axis, 1, s, 0.0, x.label, {}};
            d.joins.push_back({0.0, PlaceId{0}});
            end_on_boundary(d, 0.0, JoinKind::fsd_end);
            d.joins.erase(d.joins.begin());
            finish(d, s, m1);
        }
    }
}

// Crossings of divisions along different axes are joins (8.1.2) that split both; a division
// ending on another's line splits that one (meet).
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
            // Within a tenth of a cell of an end is at the end: a tangent division runs a twentieth
            // of a cell off its join (grow_fsds), and the division ending at that join crossed it
            // there or not by rounding (the Scotch yoke at odd grids).
            const double ea = std::max(4 * r.boundary_tolerance, 0.1 * r.axes[static_cast<std::size_t>(da.axis)].step());
            const double eb = std::max(4 * r.boundary_tolerance, 0.1 * r.axes[static_cast<std::size_t>(db.axis)].step());
            const bool a_inside = ta > ea && ta < da.length - ea, b_inside = tb > eb && tb < db.length - eb;
            if (a_inside && b_inside) {
                const PlaceId j = add_join(JoinKind::crossing, da.at(ta), {});
                da.joins.push_back({ta, j});
                db.joins.push_back({tb, j});
            } else if (a_inside) {
                meet(da, ta, db, tb, eb);
            } else if (b_inside) {
                meet(db, tb, da, ta, ea);
            }
        }
}

// A division that ends on another one's line (a T-junction) splits it there, at the join it ends
// at: the faces either side of that end border different pieces of the line it meets, and a
// line's piece borders one face on each side (8.1.2), so no two faces meet with no place between.
// `through` is crossed at its parameter t; `ending` meets its line at its parameter u, which is
// at one of its ends if within `near` of it (a periodic axis' parameter is within a period).
void Builder::meet(Division& through, double t, const Division& ending, double u, double near) {
    const auto& ax = r.axes[static_cast<std::size_t>(ending.axis)];
    const bool at_start = std::abs(u) <= near || (ax.periodic && u >= ax.span() - near);
    const bool at_end = std::abs(u - ending.length) <= near;
    if ((!at_start && !at_end) || ending.joins.empty()) return;
    const auto by_param = [](const auto& x, const auto& y) { return x.first < y.first; };
    const auto end = at_start ? std::min_element(ending.joins.begin(), ending.joins.end(), by_param)
                              : std::max_element(ending.joins.begin(), ending.joins.end(), by_param);
    const PlaceId j = end->second;
    if (std::none_of(through.joins.begin(), through.joins.end(), [&](const auto& x) { return x.second == j; }))
        through.joins.push_back({t, j});
}

}  // namespace qm::geometry::detail
