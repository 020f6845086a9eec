// geometry/detail/face_covers.cpp: the values of each coordinate that a full face spans
// (Place::covers), by which Def 34 correlates the places of two pairs that share a part.
// A face is connected and open, so along an axis it spans an interval (an arc of a periodic axis)
// whose ends lie on its boundary: its CSEGs, divisions, stops and joins (Def 32). Its samples'
// rows give the inside; the stretches of its bounding lines beside it give the ends, and a CSEG
// turns back along an axis only at a join (its normal crosses the axis there, 8.1.2), so the
// lines' points suffice.
#include "geometry/detail/place_parts.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace qm::geometry::detail {
namespace {

// Whether line or join p lies beside face f somewhere: a corner of the faces' grid cell holding
// one of its points (taken at most half a step apart along it) is a sample of f.
bool beside(const FaceLocator& faces, int f, const Place& p) {
    const FaceGrid& g = faces.grid();
    const CSpaceRequest& r = g.request();
    auto at = [&](const Eigen::Vector2d& x) {
        const Eigen::Vector2d w = wrap(r, x);
        std::array<std::array<int, 2>, 2> lines{};
        for (int k = 0; k < 2; ++k) {
            const int n = g.size(k);
            const int i = std::clamp(g.below(k, w[k]), 0, n - 1);
            lines[static_cast<std::size_t>(k)] = {i, r.axes[static_cast<std::size_t>(k)].periodic ? (i + 1) % n : std::min(i + 1, n - 1)};
        }
        for (const int i : lines[0])
            for (const int j : lines[1])
                if (faces.face_of_sample(i, j) == f) return true;
        return false;
    };
    const Eigen::Vector2d half(r.axes[0].step() / 2, r.axes[1].step() / 2);
    if (p.points.empty()) return false;
    if (at(p.points.front())) return true;
    for (std::size_t i = 0; i + 1 < p.points.size(); ++i) {
        const Eigen::Vector2d d = difference(r, p.points[i], p.points[i + 1]);
        const int m = std::max(1, static_cast<int>(std::ceil(d.cwiseQuotient(half).lpNorm<Eigen::Infinity>())));
        for (int s = 1; s <= m; ++s)
            if (at(p.points[i] + d * s / m)) return true;
    }
    return false;
}

// The values of axis k that a face spans, from the rows of the faces' grid that hold its samples
// and the places adjacent to it (its boundary, 8.1.3).
std::vector<Span> covered_values(const FaceGrid& grid, int k, const std::vector<bool>& rows, const std::vector<std::pair<const Place*, bool>>& boundary) {
    const auto& axis = grid.request().axes[static_cast<std::size_t>(k)];
    const int n = grid.size(k);
    const double step = axis.step(), wide = 2 * step, period = axis.span();
    if (std::all_of(rows.begin(), rows.end(), [](bool x) { return x; })) return {{axis.lo, axis.hi}};
    std::vector<std::array<double, 2>> runs;  // the coordinates of each run's first and last row
    for (int a = 0; a < n;) {
        if (!rows[static_cast<std::size_t>(a)]) {
            ++a;
            continue;
        }
        int b = a;
        while (b + 1 < n && rows[static_cast<std::size_t>(b + 1)]) ++b;
        runs.push_back({grid.coordinate(k, a), grid.coordinate(k, b)});
        a = b + 1;
    }
    // On a periodic axis a run through the last row goes on from the first, a period on.
    if (axis.periodic && runs.size() > 1 && rows.front() && rows.back()) {
        runs.front()[0] = runs.back()[0] - period;
        runs.pop_back();
    }
    const int copies = axis.periodic ? 1 : 0;
    auto near_runs = [&](double x) {
        for (const auto& [a, b] : runs)
            for (int c = -copies; c <= copies; ++c)
                if (x + c * period >= a - wide && x + c * period <= b + wide) return true;
        return false;
    };
    // The boundary's values: the whole of each CSEG and stop (one face lies on its free side all
    // along), each join, a division across the axis (its one value), and the points of a division
    // along it within two steps of the rows (it may run on past the face, met by another division
    // from the face's side, so that it borders other faces further on).
    std::vector<Span> bound;
    for (const auto& [p, whole] : boundary) {
        const bool division = p->kind == PlaceKind::fsd || p->kind == PlaceKind::external_division;
        if (!whole || (division && p->axis == k)) {
            for (const auto& q : p->points)
                if (near_runs(q[k])) bound.push_back({q[k], q[k]});
            continue;
        }
        if (p->points.size() == 1) bound.push_back({p->points.front()[k], p->points.front()[k]});
        for (std::size_t i = 0; i + 1 < p->points.size(); ++i) {
            const double x = p->points[i][k];
            const double y = axis.periodic ? x + std::remainder(p->points[i + 1][k] - x, period) : p->points[i + 1][k];
            bound.push_back({std::min(x, y), std::max(x, y)});
        }
    }
    // A run's end reaches on to the farthest boundary value within two steps beyond it (the face
    // goes on between the rows); where nothing of its boundary lies there, nor runs on through
    // it, the face is taken to reach the two steps, as far as a face between rows ever was.
    auto reach = [&](double x, int dir) {
        double best = x;
        bool found = false;
        for (const auto& s : bound)
            for (const double y : {s.lo, s.hi}) {
                double d = dir * (y - x);
                if (axis.periodic) d = std::fmod(std::fmod(d, period) + period, period);
                if (!(d > 0 && d <= wide)) continue;
                best = dir > 0 ? std::max(best, x + d) : std::min(best, x - d);
                found = true;
            }
        for (const auto& s : bound)
            for (int c = -copies; c <= copies && !found; ++c)
                found = dir > 0 ? (s.lo + c * period <= x && s.hi + c * period > x + wide)
                                : (s.hi + c * period >= x && s.lo + c * period < x - wide);
        return found ? best : x + dir * wide;
    };
    // The boundary's values are taken as they are, with no margin: two pairs' faces whose values
    // only touch at a corner share no configuration (Def 34), and a margin would correlate them.
    std::vector<Span> out;
    for (const auto& [a, b] : runs) out.push_back({reach(a, -1), reach(b, +1)});
    out.insert(out.end(), bound.begin(), bound.end());
    if (!axis.periodic) {  // one interval, within the axis
        Span hull{axis.hi, axis.lo};
        for (const auto& s : out) hull = {std::min(hull.lo, s.lo), std::max(hull.hi, s.hi)};
        return {{std::max(hull.lo, axis.lo), std::min(hull.hi, axis.hi)}};
    }
    for (auto& s : out) {
        const double shift = std::floor((s.lo - axis.lo) / period) * period;
        s.lo -= shift;
        s.hi -= shift;
    }
    std::sort(out.begin(), out.end(), [](const Span& x, const Span& y) { return x.lo < y.lo; });
    // Values no row falls between are the face's where its boundary lies on both sides (at a
    // value between, the face goes all the way round the other axis, and a row there would hold
    // its samples), so gaps up to a step are closed; rows are at most a step apart.
    const double bridge = step * (1 + 1e-6);
    std::vector<Span> merged;
    for (const auto& s : out) {
        if (!merged.empty() && s.lo <= merged.back().hi + bridge) merged.back().hi = std::max(merged.back().hi, s.hi);
        else merged.push_back(s);
    }
    // Round the seam: the last intervals may reach the first, and through it the next ones.
    while (merged.size() > 1 && merged.back().hi + bridge >= merged.front().lo + period) {
        merged.front() = {merged.back().lo - period, std::max(merged.front().hi, merged.back().hi - period)};
        merged.pop_back();
        while (merged.size() > 1 && merged[1].lo <= merged.front().hi + bridge) {
            merged.front().hi = std::max(merged.front().hi, merged[1].hi);
            merged.erase(merged.begin() + 1);
        }
    }
    for (const auto& s : merged)
        if (s.hi - s.lo + bridge >= period) return {{axis.lo, axis.hi}};
    return merged;
}

}  // namespace

void set_face_covers(const FaceLocator& faces, const std::vector<PlaceId>& face_places, PlaceVocabulary& v) {
    const FaceGrid& grid = faces.grid();
    const std::size_t n_faces = face_places.size();
    std::array<std::vector<std::vector<bool>>, 2> rows;
    for (std::size_t k = 0; k < 2; ++k)
        rows[k].assign(n_faces, std::vector<bool>(static_cast<std::size_t>(grid.size(static_cast<int>(k))), false));
    for (int j = 0; j < grid.size(1); ++j)
        for (int i = 0; i < grid.size(0); ++i)
            if (const int f = faces.face_of_sample(i, j); f >= 0) {
                rows[0][static_cast<std::size_t>(f)][static_cast<std::size_t>(i)] = true;
                rows[1][static_cast<std::size_t>(f)][static_cast<std::size_t>(j)] = true;
            }
    // The places adjacent to each face either way (8.1.3), other than faces: its boundary.
    std::vector<int> face_of(v.places.size(), -1);
    for (std::size_t f = 0; f < n_faces; ++f) face_of[face_places[f].value] = static_cast<int>(f);
    std::vector<std::vector<std::uint32_t>> near(n_faces);
    std::vector<std::array<std::vector<Span>, 2>> covers(n_faces);
    for (const auto& a : v.adjacency)
        for (const auto& [face, other] : {std::pair{a.from, a.to}, std::pair{a.to, a.from}})
            if (face_of[face.value] >= 0 && v.at(other).kind != PlaceKind::face) near[static_cast<std::size_t>(face_of[face.value])].push_back(other.value);
    for (std::size_t f = 0; f < n_faces; ++f) {
        std::sort(near[f].begin(), near[f].end());
        near[f].erase(std::unique(near[f].begin(), near[f].end()), near[f].end());
        std::vector<std::pair<const Place*, bool>> boundary;
        for (const auto id : near[f]) boundary.emplace_back(&v.places[id], beside(faces, static_cast<int>(f), v.places[id]));
        for (std::size_t k = 0; k < 2; ++k) covers[f][k] = covered_values(grid, static_cast<int>(k), rows[k][f], boundary);
    }
    for (std::size_t f = 0; f < n_faces; ++f) v.places[face_places[f].value].covers = std::move(covers[f]);
}

}  // namespace qm::geometry::detail
