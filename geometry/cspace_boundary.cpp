// geometry/cspace_boundary.cpp: marching squares on the classified grid (thesis 8.1.1-8.1.2).
#include "geometry/cspace_boundary.hpp"

#include "qm/assert.hpp"

#include <map>
#include <tuple>

namespace qm::geometry {

std::vector<BoundaryChain> trace_boundary(const PairOracle& oracle, const CSpaceResult& space) {
    QM_REQUIRE(space.status == CSpaceStatus::ok, "trace_boundary needs a classified space");
    const auto& r = space.request;
    const int n0 = r.axes[0].samples, n1 = r.axes[1].samples;
    std::map<std::tuple<int, int, int>, int> at_edge;  // (axis, i, j) -> boundary point
    for (std::size_t k = 0; k < space.boundary.size(); ++k) {
        const auto& p = space.boundary[k];
        at_edge[{p.axis, p.cell[0], p.cell[1]}] = static_cast<int>(k);
    }
    auto find = [&](int axis, int i, int j) -> int {
        auto it = at_edge.find({axis, i, j});
        return it == at_edge.end() ? -1 : it->second;
    };
    std::vector<std::array<int, 2>> nb(space.boundary.size(), {-1, -1});
    auto link = [&](int a, int b) {
        QM_ASSERT(a >= 0 && b >= 0, "marching squares links crossings only");
        for (int x : {a, b}) {
            auto& slot = nb[static_cast<std::size_t>(x)];
            (slot[0] < 0 ? slot[0] : slot[1]) = x == a ? b : a;
        }
    };
    const int c0 = r.axes[0].periodic ? n0 : n0 - 1, c1 = r.axes[1].periodic ? n1 : n1 - 1;
    for (int j = 0; j < c1; ++j)
        for (int i = 0; i < c0; ++i) {
            const int i1 = (i + 1) % n0, j1 = (j + 1) % n1;
            // Edges: bottom (axis 0 at (i,j)), right (axis 1 at (i1,j)), top (axis 0 at (i,j1)),
            // left (axis 1 at (i,j)). Each corner sits between two edges.
            const int bottom = find(0, i, j), right = find(1, i1, j), top = find(0, i, j1), left = find(1, i, j);
            const int count = (bottom >= 0) + (right >= 0) + (top >= 0) + (left >= 0);
            if (count == 2) {
                int e[2], m = 0;
                for (int x : {bottom, right, top, left})
                    if (x >= 0) e[m++] = x;
                link(e[0], e[1]);
            } else if (count == 4) {
                // Saddle: the boundary cuts off each corner whose state differs from the centre's.
                Eigen::Vector2d c(r.axes[0].sample(i) + 0.5 * r.axes[0].step(), r.axes[1].sample(j) + 0.5 * r.axes[1].step());
                const bool centre = oracle.blocked(c);
                if (space.is_blocked(i, j) != centre) link(bottom, left);
                if (space.is_blocked(i1, j) != centre) link(bottom, right);
                if (space.is_blocked(i1, j1) != centre) link(right, top);
                if (space.is_blocked(i, j1) != centre) link(top, left);
            }
        }
    std::vector<BoundaryChain> chains;
    std::vector<bool> used(space.boundary.size(), false);
    auto walk = [&](int start, BoundaryChain& chain) {
        int prev = -1, cur = start;
        while (cur >= 0 && !used[static_cast<std::size_t>(cur)]) {
            used[static_cast<std::size_t>(cur)] = true;
            chain.points.push_back(cur);
            const auto& s = nb[static_cast<std::size_t>(cur)];
            const int next = s[0] != prev ? s[0] : s[1];
            prev = cur;
            cur = next;
        }
        chain.closed = cur == start;
    };
    // Open chains first, from an end (a point with one neighbour), then the remaining cycles.
    for (std::size_t k = 0; k < nb.size(); ++k)
        if (!used[k] && (nb[k][0] < 0 || nb[k][1] < 0)) {
            BoundaryChain c;
            walk(static_cast<int>(k), c);
            c.closed = false;
            chains.push_back(std::move(c));
        }
    for (std::size_t k = 0; k < nb.size(); ++k)
        if (!used[k]) {
            BoundaryChain c;
            walk(static_cast<int>(k), c);
            chains.push_back(std::move(c));
        }
    return chains;
}

}  // namespace qm::geometry
