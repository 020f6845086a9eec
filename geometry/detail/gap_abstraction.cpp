// geometry/detail/gap_abstraction.cpp: the gap abstraction of 8.1.6: "If the gap size between
// two parts is less than some epsilon a new place is created which is bounded on two sides,
// conceptually this eliminates the play between the two parts and collapses three distinct
// places into one. It is important that only gaps be eliminated this way and not blocked space."
#include "geometry/detail/place_parts.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <tuple>

namespace qm::geometry::detail {
namespace {

constexpr double unbounded = std::numeric_limits<double>::infinity();

// The free run through sample (i, j) of the faces' grid along `axis`, between the blocked samples
// that bound it: its lines (lo, hi), or nothing when the run reaches a translation limit or goes
// all the way round a periodic axis (unbounded).
std::optional<std::array<int, 2>> run_lines(const FaceGrid& grid, int i, int j, int axis) {
    const auto& ax = grid.request().axes[static_cast<std::size_t>(axis)];
    const int n = grid.size(axis);
    auto blocked_at = [&](int k) {
        if (ax.periodic) k = ((k % n) + n) % n;
        else if (k < 0 || k >= n) return true;
        return axis == 0 ? grid.blocked(k, j) : grid.blocked(i, k);
    };
    const int self = axis == 0 ? i : j;
    int lo = self, hi = self;
    while (!blocked_at(lo - 1)) {
        --lo;
        if (!ax.periodic && lo == 0) return std::nullopt;
        if (self - lo >= n) return std::nullopt;
    }
    while (!blocked_at(hi + 1)) {
        ++hi;
        if (!ax.periodic && hi == n - 1) return std::nullopt;
        if (hi - self >= n) return std::nullopt;
    }
    return std::array<int, 2>{lo, hi};
}

// The play of one part with the other held still through sample (i, j): the free run's ends
// bisected onto the contact boundary.
double free_run(const PairOracle& oracle, const FaceGrid& grid, int i, int j, int axis) {
    const auto run = run_lines(grid, i, j, axis);
    if (!run) return unbounded;
    auto point = [&](int k) {  // unwrapped along the axis
        Eigen::Vector2d q = grid.point(i, j);
        q[axis] = grid.unwrapped(axis, k);
        return q;
    };
    std::uint64_t calls = 0;
    const double tol = grid.request().boundary_tolerance;
    const Eigen::Vector2d a = bisect_contact(oracle, point((*run)[0] - 1), true, point((*run)[0]), tol, calls);
    const Eigen::Vector2d b = bisect_contact(oracle, point((*run)[1] + 1), true, point((*run)[1]), tol, calls);
    return b[axis] - a[axis];
}

// A face's gap: the widest, over its samples, of the narrower of the two free runs through it.
// Cheap bounds from the grid first (a run from line lo to line hi is longer than the lines' span
// and shorter than that of the blocked lines either side); bisection only when they do not decide.
bool narrower_than(const PairOracle& oracle, const FaceGrid& grid, const std::vector<std::array<int, 2>>& samples, double epsilon) {
    bool undecided = false;
    for (const auto& [i, j] : samples) {
        double upper = unbounded, lower = unbounded;
        for (int axis = 0; axis < 2; ++axis) {
            const auto run = run_lines(grid, i, j, axis);
            if (!run) continue;
            upper = std::min(upper, grid.unwrapped(axis, (*run)[1] + 1) - grid.unwrapped(axis, (*run)[0] - 1));
            lower = std::min(lower, grid.unwrapped(axis, (*run)[1]) - grid.unwrapped(axis, (*run)[0]));
        }
        if (lower >= epsilon) return false;
        undecided = undecided || upper >= epsilon;
    }
    if (!undecided) return true;
    for (const auto& [i, j] : samples)
        if (std::min(free_run(oracle, grid, i, j, 0), free_run(oracle, grid, i, j, 1)) >= epsilon) return false;
    return true;
}

}  // namespace

void collapse_gaps(const PairOracle& oracle, const FaceLocator& faces, const std::vector<PlaceId>& face_places, double epsilon,
                   PlaceVocabulary& v) {
    if (!(epsilon > 0)) return;
    const FaceGrid& grid = faces.grid();
    std::vector<std::vector<std::array<int, 2>>> samples(face_places.size());
    for (int j = 0; j < grid.size(1); ++j)
        for (int i = 0; i < grid.size(0); ++i)
            if (const int f = faces.face_of_sample(i, j); f >= 0) samples[static_cast<std::size_t>(f)].push_back({i, j});
    // Members of each collapsed gap: the face, the CSEGs whose free side it is, then the joins
    // and divisions that lead only to those.
    std::vector<int> group(v.places.size(), -1);
    int groups = 0;
    std::vector<PlaceId> group_face;
    for (std::size_t f = 0; f < face_places.size(); ++f) {
        if (!narrower_than(oracle, grid, samples[f], epsilon)) continue;
        const PlaceId face = face_places[f];
        // The play between the parts: a face with CSEGs on its free side. A strip between two
        // divisions alone divides free space, and is no gap.
        bool bordered = false;
        for (const auto& a : v.adjacency)
            bordered = bordered || (a.to == face && !a.constrained && v.at(a.from).kind == PlaceKind::cseg && group[a.from.value] < 0);
        if (!bordered) continue;
        group[face.value] = groups;
        for (const auto& a : v.adjacency)
            if (a.to == face && !a.constrained && v.at(a.from).kind == PlaceKind::cseg && group[a.from.value] < 0) group[a.from.value] = groups;
        group_face.push_back(face);
        ++groups;
    }
    if (groups == 0) return;
    for (const auto& p : v.places) {
        if (p.kind != PlaceKind::join && p.kind != PlaceKind::fsd && p.kind != PlaceKind::external_division) continue;
        std::set<int> reached;
        for (const auto& a : v.adjacency)
            if (a.from == p.id && a.to != p.id) reached.insert(group[a.to.value]);
        if (reached.size() == 1 && *reached.begin() >= 0) group[p.id.value] = *reached.begin();
    }
    // The new vocabulary: places outside the gaps in their order, then one place per gap: a
    // face marked `gap`, bounded by the normals of the CSEGs it absorbed.
    PlaceVocabulary out;
    std::vector<PlaceId> to(v.places.size());
    for (const auto& p : v.places) {
        if (group[p.id.value] >= 0) continue;
        to[p.id.value] = PlaceId{static_cast<std::uint32_t>(out.places.size())};
        out.places.push_back(p);
        out.places.back().id = to[p.id.value];
    }
    std::vector<PlaceId> gap_place(static_cast<std::size_t>(groups));
    for (int g = 0; g < groups; ++g) {
        Place p = v.at(group_face[static_cast<std::size_t>(g)]);
        p.id = gap_place[static_cast<std::size_t>(g)] = PlaceId{static_cast<std::uint32_t>(out.places.size())};
        p.gap = true;
        std::set<QualDirection> normals;
        for (const auto& q : v.places)
            if (group[q.id.value] == g && q.kind == PlaceKind::cseg) normals.insert(q.normals.begin(), q.normals.end());
        p.normals.assign(normals.begin(), normals.end());
        out.places.push_back(std::move(p));
    }
    for (const auto& q : v.places)
        if (group[q.id.value] >= 0) to[q.id.value] = gap_place[static_cast<std::size_t>(group[q.id.value])];
    // Transitions. From a place outside: its targets renamed (two members become one target;
    // it is instantaneous only if every transition it stands for was). From a gap: where its
    // members lead outside it; if nowhere, it stays, constrained if any member was (the
    // negligible play crossed, the motion meets blocked space) and over an interval otherwise.
    std::map<std::tuple<std::uint32_t, int, int, std::uint32_t>, Adjacency> merged;  // from, motion, to
    std::map<std::tuple<std::uint32_t, int, int>, bool> gap_constrained;
    for (const auto& a : v.adjacency) {
        const bool from_gap = group[a.from.value] >= 0;
        Adjacency b{to[a.from.value], to[a.to.value], a.motion, a.instantaneous, a.constrained};
        if (from_gap) {
            auto& c = gap_constrained[{b.from.value, a.motion.s[0], a.motion.s[1]}];
            c = c || a.constrained;
            if (b.to == b.from) continue;
        }
        const auto key = std::make_tuple(b.from.value, int{a.motion.s[0]}, int{a.motion.s[1]}, b.to.value);
        if (auto it = merged.find(key); it != merged.end()) {
            it->second.instantaneous = it->second.instantaneous && b.instantaneous;
            it->second.constrained = it->second.constrained && b.constrained;
        } else {
            merged.emplace(key, b);
        }
    }
    for (const auto& [key, constrained] : gap_constrained) {
        const auto& [from, s0, s1] = key;
        bool leaves = false;
        for (const auto& [k2, a] : merged) leaves = leaves || (a.from.value == from && a.motion.s[0] == s0 && a.motion.s[1] == s1);
        if (!leaves) {
            Adjacency stay{PlaceId{from}, PlaceId{from}, {}, false, constrained};
            stay.motion.s[0] = static_cast<std::int8_t>(s0);
            stay.motion.s[1] = static_cast<std::int8_t>(s1);
            merged.emplace(std::make_tuple(from, s0, s1, from), stay);
        }
    }
    for (const auto& [key, a] : merged) out.adjacency.push_back(a);  // by place, then motion
    v = std::move(out);
}

}  // namespace qm::geometry::detail
