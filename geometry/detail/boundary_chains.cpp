// geometry/detail/boundary_chains.cpp: the boundary chains of one build (thesis 8.1.2) before
// their CSEGs are cut: normals adopted where they contradict their crossing, short runs absorbed
// (8.1.6, and what the grid cannot resolve), joins inserted with the blocked islands at tips
// dropped, and the segments next to joins that grid edges may not cross (FaceLocator).
#include "geometry/detail/place_builder.hpp"

#include <algorithm>
#include <cmath>

namespace qm::geometry::detail {

void Builder::make_chains(const std::vector<BoundaryChain>& traced) {
    for (const auto& t : traced) {
        std::vector<ChainNode> nodes;
        for (int k : t.points) {
            const auto& p = space.boundary[static_cast<std::size_t>(k)];
            nodes.push_back({p.q, k, std::nullopt, p.qual, p.normal});
        }
        adopt_neighbour_normals(nodes, t.points, t.closed);
        absorb_short_runs(nodes, t.closed);
        absorb_unresolved_runs(nodes, t.closed);
        chains.push_back(std::move(nodes));
        closed.push_back(t.closed);
    }
}

// A point whose normal contradicts its own crossing (BoundaryPoint::normal_contradicts_edge)
// takes the normal of the nearest point before it along the chain that has a sound one (after
// it, at a chain's open start). Flipping such normals instead is wrong where the far surface is
// not parallel to the near one; left alone, each would start a CSEG of a cell or less and two
// joins, the more of them the finer the grid (docs/ACCURACY.md, "Place count against grid").
void Builder::adopt_neighbour_normals(std::vector<ChainNode>& nodes, const std::vector<int>& points, bool is_closed) {
    const std::size_t n = nodes.size();
    auto sound = [&](std::size_t k) { return !space.boundary[static_cast<std::size_t>(points[k])].normal_contradicts_edge; };
    std::size_t good = n;
    for (std::size_t k = 0; k < n; ++k)
        if (sound(k)) {
            good = k;
            break;
        }
    if (good == n) return;  // nothing sound to take from
    std::vector<ChainNode> fixed = nodes;
    for (std::size_t k = 0; k < n; ++k) {
        if (sound(k)) continue;
        std::optional<std::size_t> from;
        for (std::size_t s = 1; s < n && !from; ++s) {  // backwards first
            if (!is_closed && s > k) break;
            const std::size_t j = (k + n - s) % n;
            if (sound(j)) from = j;
        }
        for (std::size_t s = 1; s < n && !from; ++s) {  // then forwards
            if (!is_closed && k + s >= n) break;
            const std::size_t j = (k + s) % n;
            if (sound(j)) from = j;
        }
        if (!from) continue;
        fixed[k].qual = nodes[*from].qual;
        fixed[k].normal = nodes[*from].normal;
    }
    nodes = std::move(fixed);
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

// What the grid cannot resolve: a run of one normal class less than half a cell long (a single
// boundary point, or two close together) between two runs of one other class is a feature
// narrower than a cell, seen at some grids and not at others: it takes its neighbours' class.
// At the tip of the ratchet's blocked needle the normals of the few points near the apex can
// alternate so. A run of a class with a zero component between two different
// classes is the other case, a normal passing an axis direction (collapse_point_runs).
void Builder::absorb_unresolved_runs(std::vector<ChainNode>& nodes, bool is_closed) {
    const std::size_t n = nodes.size();
    if (n < 3) return;
    const Eigen::Vector2d scale = cell().cwiseInverse();
    for (std::size_t start = 0; start < n;) {
        std::size_t end = start;
        double len = 0;
        while (end + 1 < n && nodes[end + 1].qual == nodes[start].qual) {
            len += difference(r, nodes[end].q, nodes[end + 1].q).cwiseProduct(scale).norm();
            ++end;
        }
        const bool has_prev = start > 0 || is_closed, has_next = end + 1 < n || is_closed;
        if (has_prev && has_next && len < 0.5 && end + 1 - start < n) {
            const auto& before = nodes[(start + n - 1) % n];
            const auto& after = nodes[(end + 1) % n];
            if (before.qual == after.qual && before.qual != nodes[start].qual)
                for (std::size_t k = start; k <= end; ++k) {
                    nodes[k].qual = before.qual;
                    nodes[k].normal = before.normal;
                }
        }
        start = end + 1;
    }
}

// A blocked island of a cell or two next to a normal-change join of another chain is that
// feature's tip, thinner than a cell, whose samples the grid saw apart from the rest (the
// ratchet's needle at 100 x 400: one blocked sample two columns from the needle, its own CSEG and
// joins). Its chain is dropped after the other chains' joins are placed (the apex join
// is found on the needle's tangents beyond it, corner()); its samples stay blocked (8.1.6: blocked
// space is never eliminated). Islands elsewhere keep their places.
void Builder::insert_joins_and_drop_tip_islands() {
    const Eigen::Vector2d scale = cell().cwiseInverse();
    std::vector<bool> small(chains.size(), false);
    for (std::size_t c = 0; c < chains.size(); ++c) small[c] = small_island(c);
    std::vector<std::pair<Eigen::Vector2d, std::size_t>> tips;  // normal-change joins and their chain
    for (std::size_t c = 0; c < chains.size(); ++c) {
        if (small[c]) continue;
        const std::size_t before = v.places.size();
        insert_normal_joins(c);
        for (std::size_t p = before; p < v.places.size(); ++p)
            if (v.places[p].join_kind == JoinKind::normal_change) tips.push_back({v.places[p].points.front(), c});
    }
    std::vector<std::vector<ChainNode>> kept;
    std::vector<bool> kept_closed;
    for (std::size_t c = 0; c < chains.size(); ++c) {
        if (small[c]) {
            Eigen::Vector2d centre = Eigen::Vector2d::Zero();
            for (const auto& node : chains[c]) centre += difference(r, chains[c].front().q, node.q);
            centre = chains[c].front().q + centre / static_cast<double>(chains[c].size());
            const bool at_tip = std::any_of(tips.begin(), tips.end(), [&](const auto& t) {
                return difference(r, t.first, centre).cwiseProduct(scale).norm() <= 2.0;
            });
            if (at_tip) continue;
        }
        kept.push_back(std::move(chains[c]));
        kept_closed.push_back(closed[c]);
    }
    chains = std::move(kept);
    closed = std::move(kept_closed);
    for (std::size_t c = 0; c < chains.size(); ++c)  // the islands kept get their joins now
        if (std::none_of(chains[c].begin(), chains[c].end(), [](const ChainNode& x) { return x.join.has_value(); }) && small_island(c))
            insert_normal_joins(c);
}

bool Builder::small_island(std::size_t c) const {
    if (!closed[c] || chains[c].empty()) return false;
    const Eigen::Vector2d scale = cell().cwiseInverse();
    Eigen::Vector2d lo = Eigen::Vector2d::Zero(), hi = Eigen::Vector2d::Zero();
    for (const auto& node : chains[c]) {
        const Eigen::Vector2d d = difference(r, chains[c].front().q, node.q).cwiseProduct(scale);
        lo = lo.cwiseMin(d);
        hi = hi.cwiseMax(d);
    }
    return (hi - lo).maxCoeff() <= 2.0;
}

// The boundary either side of each normal-change join, as segments from the join to its
// neighbouring nodes along the chain (FaceLocator: grid edges may not cross them).
std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> Builder::barriers_at_joins() const {
    std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>> out;
    for (std::size_t c = 0; c < chains.size(); ++c) {
        const auto& nodes = chains[c];
        const std::size_t n = nodes.size();
        for (std::size_t k = 0; k < n; ++k) {
            if (!nodes[k].join || v.at(*nodes[k].join).join_kind != JoinKind::normal_change) continue;
            if (k > 0 || closed[c]) out.emplace_back(nodes[k].q, difference(r, nodes[k].q, nodes[(k + n - 1) % n].q));
            if (k + 1 < n || closed[c]) out.emplace_back(nodes[k].q, difference(r, nodes[k].q, nodes[(k + 1) % n].q));
        }
    }
    return out;
}

}  // namespace qm::geometry::detail
