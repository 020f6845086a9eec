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
#include <array>
#include <cmath>
#include <limits>
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

// Distance from q to a place's polyline (a join: its point), the short way round periodic axes.
double distance_to(const CSpaceRequest& r, const Place& p, const Eigen::Vector2d& q) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < p.points.size(); ++k) {
        const Eigen::Vector2d a = difference(r, q, p.points[k]);  // from q to the point
        if (k + 1 == p.points.size()) {
            best = std::min(best, a.norm());
            break;
        }
        const Eigen::Vector2d ab = difference(r, p.points[k], p.points[k + 1]);
        const double len2 = ab.squaredNorm();
        const double t = len2 > 0 ? std::clamp(-a.dot(ab) / len2, 0.0, 1.0) : 0.0;
        best = std::min(best, (a + t * ab).norm());
    }
    return best;
}

// Whether motion d can go round and round in face f without leaving it: a whole row of its
// samples round a periodic axis along d's one component, or, for a motion along both axes, whole
// rows round both.
bool wraps(const FaceLocator& faces, int f, QualDirection d) {
    const FaceGrid& g = faces.grid();
    for (int k = 0; k < 2; ++k) {
        if (d.s[static_cast<std::size_t>(k)] == 0) continue;
        if (!g.request().axes[static_cast<std::size_t>(k)].periodic) return false;
        bool whole = false;
        for (int m = 0; m < g.size(1 - k) && !whole; ++m) {
            whole = true;
            for (int i = 0; i < g.size(k) && whole; ++i) whole = (k == 0 ? faces.face_of_sample(i, m) : faces.face_of_sample(m, i)) == f;
        }
        if (!whole) return false;
    }
    return true;
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

// The division (divisions) or the CSEG, join or stop (else) nearest q, other than `not_this`.
std::optional<PlaceId> nearest_line(const CSpaceRequest& r, const PlaceVocabulary& v, const Eigen::Vector2d& q, bool divisions,
                                    std::optional<PlaceId> not_this = std::nullopt) {
    std::optional<PlaceId> best;
    double best_d = 0;
    for (const auto& p : v.places) {
        const bool division = p.kind == PlaceKind::fsd || p.kind == PlaceKind::external_division;
        const bool contact = p.kind == PlaceKind::cseg || p.kind == PlaceKind::join || p.kind == PlaceKind::stop;
        if ((divisions && !division) || (!divisions && !contact) || p.points.empty() || p.id == not_this) continue;
        const double dist = distance_to(r, p, q);
        if (!best || dist < best_d) {
            best = p.id;
            best_d = dist;
        }
    }
    return best;
}

// What a motion from line `from` at q along `step` (a third of a cell) meets first across a strip
// with no samples: the division crossed, the CSEG, join or stop where the parts meet, or the face
// it comes to, going on a step at a time for a few cells.
std::optional<PlaceId> line_beyond(const PairOracle& oracle, const CSpaceRequest& r, const FaceLocator& faces, const PlaceVocabulary& v,
                                   const std::vector<PlaceId>& face_places, PlaceId from, const Eigen::Vector2d& q,
                                   const Eigen::Vector2d& step) {
    Eigen::Vector2d last = q;
    for (int k = 1; k <= 10; ++k) {
        const Eigen::Vector2d y = q + k * step;
        if (const auto x = faces.division_crossing(q, y)) return nearest_line(r, v, *x, true, from);
        for (int a = 0; a < 2; ++a) {
            const auto& ax = r.axes[static_cast<std::size_t>(a)];
            if (!ax.periodic && (y[a] < ax.lo || y[a] > ax.hi)) return std::nullopt;  // the end of the axis: no place
        }
        if (oracle.blocked(wrap(r, y))) {
            std::uint64_t calls = 0;
            return nearest_line(r, v, bisect_contact(oracle, y, true, last, r.boundary_tolerance, calls), false, from);
        }
        if (const auto f = faces.face_at(y)) return face_places[static_cast<std::size_t>(*f)];
        last = y;
    }
    return std::nullopt;
}

// The places face f's samples first meet moving along d, one grid step at a time: the division
// piece crossed, the CSEG, join or stop nearest where the parts meet (blocked space, or the end
// of a bounded axis), or the line nearest a neighbour that lies on a division.
std::set<PlaceId> reached_by_walking(const PairOracle& oracle, const CSpaceRequest& r, const FaceLocator& faces, int f, QualDirection d,
                                     const PlaceVocabulary& v) {
    const FaceGrid& g = faces.grid();
    std::set<PlaceId> out;
    auto nearest = [&](const Eigen::Vector2d& q, bool divisions) { return nearest_line(r, v, q, divisions); };
    const int n0 = g.size(0), n1 = g.size(1);
    for (int j = 0; j < n1; ++j)
        for (int i = 0; i < n0; ++i) {
            if (faces.face_of_sample(i, j) != f) continue;
            int ni = i + d.s[0], nj = j + d.s[1];
            const Eigen::Vector2d p = g.point(i, j);
            bool beyond = false;  // past the end of a bounded axis
            Eigen::Vector2d q = p;
            for (int k = 0; k < 2; ++k) {
                const int n = g.size(k);
                int& idx = k == 0 ? ni : nj;
                const auto& ax = r.axes[static_cast<std::size_t>(k)];
                if (idx >= 0 && idx < n) {
                    q[k] = g.coordinate(k, idx);
                } else if (ax.periodic) {
                    q[k] = g.unwrapped(k, idx);
                    idx = (idx % n + n) % n;
                } else {
                    beyond = true;
                    q[k] = idx < 0 ? ax.lo : ax.hi;
                }
            }
            if (beyond) {  // the end of the axis: a stop there, if the axis has them
                if (const auto x = faces.division_crossing(p, q)) {
                    if (const auto to = nearest(*x, true)) out.insert(*to);
                } else {
                    std::optional<PlaceId> stop;
                    double best = 0;
                    for (const auto& place : v.places)
                        if (place.kind == PlaceKind::stop && (!stop || distance_to(r, place, q) < best)) {
                            stop = place.id;
                            best = distance_to(r, place, q);
                        }
                    if (stop) out.insert(*stop);
                }
                continue;
            }
            if (faces.face_of_sample(ni, nj) == f) continue;
            if (const auto x = faces.division_crossing(p, q)) {
                if (const auto to = nearest(*x, true)) out.insert(*to);
            } else if (g.blocked(ni, nj)) {
                std::uint64_t calls = 0;
                const Eigen::Vector2d c = bisect_contact(oracle, q, true, p, r.boundary_tolerance, calls);
                if (const auto to = nearest(c, false)) out.insert(*to);
            } else if (const auto to = nearest(q, true)) {
                out.insert(*to);  // a neighbour on a division, in no face
            }
        }
    return out;
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
    // from_line: a probe from a line, which may be shortened; any_sample: the face of a sample on
    // a line inserted between close features counts too (see below).
    auto face_near = [&](const Eigen::Vector2d& q, Eigen::Vector2d dir_cells, const Eigen::Vector2d& nudge = Eigen::Vector2d::Zero(),
                         bool from_line = false, bool any_sample = false) -> std::optional<PlaceId> {
        if (dir_cells.norm() == 0) return std::nullopt;
        // A third of a cell out; where that crosses a division or meets blocked space, the
        // nearest strip short of it that is a face (two divisions, or a division and a contact,
        // closer than a cell: the strip between them), else as far as a third of a cell all the
        // same (a sliver with no samples is no place).
        const auto at = [&](double t) -> std::optional<std::optional<PlaceId>> {
            const Eigen::Vector2d y = q + t * dir_cells.normalized().cwiseProduct(cell) + nudge.cwiseProduct(cell);
            if (!in_domain(y) || oracle.blocked(wrap(r, y))) return std::optional<PlaceId>{};
            // The configuration space's own samples first; the lines inserted between close
            // features lie near the boundary, so a join whose normals leave the motion in doubt
            // does not use them to decide which side its neighbourhood is on.
            if (auto f = faces.face_at(y, true)) return std::optional<PlaceId>{face_places[static_cast<std::size_t>(*f)]};
            if (any_sample)
                if (auto f = faces.face_at(y)) return std::optional<PlaceId>{face_places[static_cast<std::size_t>(*f)]};
            return std::nullopt;
        };
        const Eigen::Vector2d far = q + 0.3 * dir_cells.normalized().cwiseProduct(cell) + nudge.cwiseProduct(cell);
        // (From a line only: at a join a shorter probe would find the free side of the
        // boundary's own tolerance, not a face.)
        if (from_line && (faces.crosses_division(q, far, true) || !in_domain(far) || oracle.blocked(wrap(r, far))))
            for (double t = 0.1; t > 1e-4; t /= 3) {
                const Eigen::Vector2d y = q + t * dir_cells.normalized().cwiseProduct(cell) + nudge.cwiseProduct(cell);
                if (faces.crosses_division(q, y, true)) continue;
                const auto f = at(t);
                if (f && *f) return *f;
                if (!f) break;  // free, in no face: as far as a third of a cell
            }
        if (const auto f = at(0.3)) return *f;
        return std::nullopt;
    };
    const auto all = motions();
    // The face beside a line on the side `side` (cells), probed from its middle, or where that
    // finds none (a face thinner than the probe there), from points along it.
    auto faces_beside = [&](const LineInfo& l, const Place& p, const Eigen::Vector2d& side) {
        std::vector<PlaceId> found;
        std::vector<Eigen::Vector2d> from{l.mid};
        if (p.points.size() >= 2) {
            double length = 0;
            for (std::size_t k = 0; k + 1 < p.points.size(); ++k) length += difference(r, p.points[k], p.points[k + 1]).norm();
            for (const double fraction : {0.125, 0.375, 0.625, 0.875}) {
                double left = fraction * length;
                for (std::size_t k = 0; k + 1 < p.points.size(); ++k) {
                    const Eigen::Vector2d ab = difference(r, p.points[k], p.points[k + 1]);
                    if (left <= ab.norm() || k + 2 == p.points.size()) {
                        from.push_back(p.points[k] + ab * (ab.norm() > 0 ? std::min(1.0, left / ab.norm()) : 0.0));
                        break;
                    }
                    left -= ab.norm();
                }
            }
        }
        for (const auto& q : from) {
            if (auto f = face_near(q, side, Eigen::Vector2d::Zero(), true, true))
                if (std::find(found.begin(), found.end(), *f) == found.end()) found.push_back(*f);
            if (!found.empty()) break;  // the middle's face, or the first found along the line
        }
        // No face on that side anywhere along it: a free strip too thin for any sample (between
        // two divisions, or a division and a contact). The motion crosses it to what bounds it.
        if (found.empty())
            if (const auto to = line_beyond(oracle, r, faces, v, face_places, l.place, l.mid, 0.3 * side.normalized().cwiseProduct(cell)))
                found.push_back(*to);
        return found;
    };
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
                    for (const PlaceId f : faces_beside(l, p, across * l.normal.cwiseQuotient(cell))) add(l.place, f, d, true, false);
                } else {
                    slide();
                }
                continue;
            }
            const QualSign s = qdot(p.normals.front(), d);
            if (s == QualSign::pos || s == QualSign::ambiguous)
                for (const PlaceId f : faces_beside(l, p, l.normal.cwiseQuotient(cell))) add(l.place, f, d, true, false);
            if (s == QualSign::neg) add(l.place, l.place, d, false, true);  // Law 2
            if (s == QualSign::zero || s == QualSign::ambiguous) slide();
        }
    }
    // (5) joins to lines by reciprocity. A division that passes a contact's join (it is cut at
    // that join where another division ends on it) runs off the boundary by a little: the motion
    // along it from the join is the join's own to decide, by its normals.
    const std::vector<Adjacency> line_moves = out;
    for (const auto& a : line_moves) {
        if (a.to == a.from || v.at(a.to).kind != PlaceKind::join) continue;
        const PlaceKind from = v.at(a.from).kind;
        const bool division = from == PlaceKind::fsd || from == PlaceKind::external_division;
        if (division && leads_into_free_space(v.at(a.to), negated(a.motion)) == false) continue;
        add(a.to, a.from, negated(a.motion), true, false);
    }
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
        const Eigen::Vector2d nudge = mean.norm() > 1e-9 ? Eigen::Vector2d(-1e-3 * mean.normalized()) : Eigen::Vector2d::Zero();  // in cells
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
            // Where the normals leave it in doubt, a face only the inserted samples see counts if
            // the way to it is free all along (open space, not the boundary's own tolerance).
            if (!found && !into_free)
                for (const auto& dir : actual_directions(d)) {
                    bool open = true;
                    for (int k = 1; k <= 6 && open; ++k) {
                        const Eigen::Vector2d y = p.points.front() + (0.05 * k) * dir.normalized().cwiseProduct(cell) + nudge.cwiseProduct(cell);
                        open = in_domain(y) && !oracle.blocked(wrap(r, y));
                    }
                    if (open)
                        if (auto f = face_near(p.points.front(), dir, nudge, false, true)) {
                            add(p.id, *f, d, true, false);
                            found = true;
                        }
                }
            for (double out : {0.05, 0.15})
                if (!found && into_free == true)
                    for (const auto& dir : actual_directions(d))
                        if (auto f = face_near(p.points.front(), dir, -nudge * (out / 1e-3), false, true)) {
                            add(p.id, *f, d, true, false);
                            found = true;
                        }
            // Two divisions crossing lie in free space, and a join whose normals open the motion
            // leads into it: a motion the probes saw blocked meets a contact closer than they
            // reach, and goes there; it is never blocked at the join.
            if (!any && !found && (p.join_kind == JoinKind::crossing || into_free == true))
                for (const auto& dir : actual_directions(d))
                    if (const auto to = line_beyond(oracle, r, faces, v, face_places, p.id, p.points.front(), 0.03 * dir.normalized().cwiseProduct(cell))) {
                        add(p.id, *to, d, true, false);
                        found = true;
                    }
            if (!any && !found) add(p.id, p.id, d, false, true);
        }
    }
    // (5) faces by reciprocity. A face that reaches nothing that way under a motion either goes
    // round a periodic axis and stays (a wrap), or leads where its samples first meet something
    // moving so on the faces' grid: the division crossed, or the CSEG, join or stop where the
    // parts meet (a face thinner than the probes from its lines, or reached by none of them).
    const std::vector<Adjacency> so_far = out;
    for (const auto& a : so_far)
        if (a.to != a.from && v.at(a.to).kind == PlaceKind::face) add(a.to, a.from, negated(a.motion), false, false);
    std::vector<bool> thin(face_places.size(), false);
    {
        const FaceGrid& g = faces.grid();
        std::vector<std::array<std::set<int>, 2>> lines(face_places.size());
        for (int j = 0; j < g.size(1); ++j)
            for (int i = 0; i < g.size(0); ++i)
                if (const int f = faces.face_of_sample(i, j); f >= 0) {
                    lines[static_cast<std::size_t>(f)][0].insert(i);
                    lines[static_cast<std::size_t>(f)][1].insert(j);
                }
        // Thinner than a grid step along an axis: all its samples on lines inserted between close
        // features, or on one of the configuration space's own.
        for (std::size_t f = 0; f < face_places.size(); ++f)
            for (int k = 0; k < 2; ++k) {
                const auto& ks = lines[f][static_cast<std::size_t>(k)];
                if (!ks.empty() && g.coordinate(k, *ks.rbegin()) - g.coordinate(k, *ks.begin()) < r.axes[static_cast<std::size_t>(k)].step())
                    thin[f] = true;
            }
    }
    for (std::size_t f = 0; f < face_places.size(); ++f)
        for (const auto d : all) {
            const PlaceId face = face_places[f];
            const bool any = std::any_of(out.begin(), out.end(), [&](const Adjacency& a) { return a.from == face && a.motion == d; });
            // A face thinner than a grid step (a sliver between close lines) is one the probes from its
            // lines may pass by: what its samples meet is added to what they found.
            if (any && thin[f]) {
                for (const PlaceId to : reached_by_walking(oracle, r, faces, static_cast<int>(f), d, v)) add(face, to, d, false, false);
                continue;
            }
            if (any) continue;
            if (wraps(faces, static_cast<int>(f), d)) {
                add(face, face, d, false, false);
                continue;
            }
            const auto reached = reached_by_walking(oracle, r, faces, static_cast<int>(f), d, v);
            for (const PlaceId to : reached) add(face, to, d, false, false);
            if (reached.empty()) add(face, face, d, false, false);  // the end of an axis without stops
        }
    std::sort(out.begin(), out.end(), [](const Adjacency& a, const Adjacency& b) {
        return std::tie(a.from, a.motion, a.to) < std::tie(b.from, b.motion, b.to);
    });
    v.adjacency = std::move(out);
}

std::optional<std::string> incompleteness(const CSpaceRequest& r, const PlaceVocabulary& v) {
    std::vector<std::vector<const Adjacency*>> from(v.places.size());
    for (const auto& a : v.adjacency) from[a.from.value].push_back(&a);
    for (const auto& p : v.places)
        for (const auto d : motions()) {
            bool any = false, elsewhere = false, constrained = false;
            for (const Adjacency* a : from[p.id.value])
                if (a->motion == d) {
                    any = true;
                    elsewhere = elsewhere || a->to != p.id;
                    constrained = constrained || a->constrained;
                }
            const std::string where = "place " + std::to_string(p.id.value) + " (" + to_string(p.kind) + ") under motion " + to_string(d);
            if (!any) return where + " has neither a next place nor a constraint";
            bool bounded_stops = false;
            for (std::size_t k = 0; k < 2; ++k) bounded_stops = bounded_stops || (d.s[k] != 0 && !r.axes[k].periodic && r.axes[k].stops);
            if (!elsewhere && !constrained && bounded_stops)
                return where + " leads only back to itself, along an axis that ends in stops";
        }
    return std::nullopt;
}

}  // namespace qm::geometry::detail
