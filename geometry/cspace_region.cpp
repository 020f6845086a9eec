// geometry/cspace_region.cpp: the blocked region from the bisected boundary points, by marching
// squares (thesis 8.1.1: the boundary is what bisection found, the grid only brackets it).
#include "geometry/cspace_region.hpp"

#include "qm/assert.hpp"

#include <algorithm>
#include <array>

namespace qm::geometry {

double polygon_area(const Polygon& p) noexcept {
    double twice = 0.0;
    for (std::size_t k = 0; k < p.size(); ++k) {
        const auto& a = p[k];
        const auto& b = p[(k + 1) % p.size()];
        twice += a.x() * b.y() - b.x() * a.y();
    }
    return 0.5 * twice;
}

namespace {

// The boundary point on each grid edge that has one, by edge: (axis, i, j) -> index + 1, 0 for none.
class EdgePoints {
public:
    explicit EdgePoints(const CSpaceResult& space)
        : n0_(space.request.axes[0].samples), n1_(space.request.axes[1].samples),
          index_(2 * static_cast<std::size_t>(n0_) * static_cast<std::size_t>(n1_), 0) {
        for (std::size_t k = 0; k < space.boundary.size(); ++k) {
            const auto& p = space.boundary[k];
            index_[slot(p.axis, p.cell[0], p.cell[1])] = static_cast<int>(k) + 1;
        }
    }
    [[nodiscard]] int at(int axis, int i, int j) const { return index_[slot(axis, i, j)] - 1; }

private:
    [[nodiscard]] std::size_t slot(int axis, int i, int j) const {
        return static_cast<std::size_t>(axis) * static_cast<std::size_t>(n0_) * static_cast<std::size_t>(n1_) +
               static_cast<std::size_t>(i + n0_ * j);
    }
    int n0_, n1_;
    std::vector<int> index_;
};

}  // namespace

std::vector<Polygon> blocked_region(const PairOracle& oracle, const CSpaceResult& space) {
    QM_REQUIRE(space.status == CSpaceStatus::ok, "blocked_region needs a classified space");
    const auto& r = space.request;
    const auto& a0 = r.axes[0];
    const auto& a1 = r.axes[1];
    const int n0 = a0.samples, n1 = a1.samples;
    const int c0 = a0.periodic ? n0 : n0 - 1, c1 = a1.periodic ? n1 : n1 - 1;  // cells per axis
    const EdgePoints edges(space);
    std::vector<Polygon> out;
    for (int j = 0; j < c1; ++j) {
        // Cell sides from sample(i) alone, so neighbouring pieces share their sides exactly (a
        // side computed two ways would differ in the last bit and show as a seam in a picture).
        const double y = a1.sample(j), y1 = a1.sample(j + 1);
        int run = -1;  // first cell of the current run of wholly blocked cells
        auto flush = [&](int end) {  // the run covers cells [run, end)
            if (run < 0) return;
            const double x = a0.sample(run), x1 = a0.sample(end);
            out.push_back({{x, y}, {x1, y}, {x1, y1}, {x, y1}});
            run = -1;
        };
        for (int i = 0; i < c0; ++i) {
            const int i1 = (i + 1) % n0, j1 = (j + 1) % n1;
            const double x = a0.sample(i), x1 = a0.sample(i + 1);
            // Corners counter-clockwise; edge k runs from corner k to corner k + 1.
            const std::array<bool, 4> b{space.is_blocked(i, j), space.is_blocked(i1, j), space.is_blocked(i1, j1), space.is_blocked(i, j1)};
            const std::array<Eigen::Vector2d, 4> corner{Eigen::Vector2d(x, y), Eigen::Vector2d(x1, y), Eigen::Vector2d(x1, y1), Eigen::Vector2d(x, y1)};
            const int blocked = b[0] + b[1] + b[2] + b[3];
            if (blocked == 4) {
                if (run < 0) run = i;
                continue;
            }
            flush(i);
            if (blocked == 0) continue;
            // The crossing on edge k, unwrapped into the cell (a point on an edge across a periodic
            // seam was wrapped to the axis' start).
            auto crossing = [&](int k) {
                const int axis = k % 2 == 0 ? 0 : 1;
                const int at = axis == 0 ? edges.at(0, i, k == 0 ? j : j1) : edges.at(1, k == 1 ? i1 : i, j);
                QM_ASSERT(at >= 0, "an edge whose samples differ has a boundary point");
                Eigen::Vector2d q = corner[static_cast<std::size_t>(k)];
                const auto& ax = r.axes[static_cast<std::size_t>(axis)];
                const double start = axis == 0 ? x : y;
                double t = space.boundary[static_cast<std::size_t>(at)].q[axis] - start;
                if (ax.periodic && t < -0.5 * ax.step()) t += ax.span();
                q[axis] = start + std::clamp(t, 0.0, ax.step());
                return q;
            };
            if (blocked == 2 && b[0] == b[2]) {
                // Saddle: the boundary cuts off each corner whose state differs from the centre's.
                const bool centre = oracle.blocked({x + 0.5 * a0.step(), y + 0.5 * a1.step()});
                if (!centre) {
                    for (int k = 0; k < 4; ++k)
                        if (b[static_cast<std::size_t>(k)]) out.push_back({crossing((k + 3) % 4), corner[static_cast<std::size_t>(k)], crossing(k)});
                    continue;
                }
            }
            Polygon poly;
            for (int k = 0; k < 4; ++k) {
                if (b[static_cast<std::size_t>(k)]) poly.push_back(corner[static_cast<std::size_t>(k)]);
                if (b[static_cast<std::size_t>(k)] != b[static_cast<std::size_t>((k + 1) % 4)]) poly.push_back(crossing(k));
            }
            out.push_back(std::move(poly));
        }
        flush(c0);
    }
    return out;
}

}  // namespace qm::geometry
