// geometry/detail/full_faces.cpp: full faces (Def 32) as connected free samples not separated by
// a division. Faces are found by connectivity of free space, not by following paths of joins, so
// a face bordered by two unconnected surfaces (the piston of Figure 8.3) is one face.
#include "geometry/detail/place_parts.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace qm::geometry::detail {
namespace {

int find_root(std::vector<int>& parent, int x) {
    while (parent[static_cast<std::size_t>(x)] != x) {
        parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
        x = parent[static_cast<std::size_t>(x)];
    }
    return x;
}

// Parameter of coordinate x along a division's axis; on a periodic axis in [-tol, span - tol), so
// that a point just before the start (by rounding) is at -0, not a period on.
double along(const CSpaceAxis& ax, const Division& d, double x, double tol) {
    double t = d.dir * (x - d.start[d.axis]);
    if (ax.periodic) {
        t = std::fmod(t, ax.span());
        if (t < 0) t += ax.span();
        if (t >= ax.span() - tol) t -= ax.span();
    }
    return t;
}

// Offset from a division's line across it (the other coordinate), on periodic axes the shortest.
double across(const CSpaceRequest& r, const Division& d, const Eigen::Vector2d& q) { return difference(r, d.start, q)[1 - d.axis]; }

}  // namespace

FaceGrid::FaceGrid(const PairOracle& oracle, const CSpaceResult& space, const std::array<std::vector<double>, 2>& features)
    : oracle_(oracle), space_(space) {
    const auto& r = space.request;
    std::array<std::vector<bool>, 2> inserted;
    for (std::size_t k = 0; k < 2; ++k) {
        const auto& ax = r.axes[k];
        auto& at = at_[k];
        for (int i = 0; i < ax.samples; ++i) at.push_back(ax.sample(i));
        // Feature coordinates in the axis (wrapped), sorted; on a periodic axis the first again a
        // period on, for the strip across the seam.
        std::vector<double> f;
        for (double x : features[k]) {
            if (ax.periodic) {
                x = std::fmod(x - ax.lo, ax.span());
                if (x < 0) x += ax.span();
                x += ax.lo;
            } else if (x < ax.lo || x > ax.hi) {
                continue;
            }
            f.push_back(x);
        }
        std::sort(f.begin(), f.end());
        if (ax.periodic && !f.empty()) f.push_back(f.front() + ax.span());
        // Features closer than a thousandth of a cell are one feature, as joins that close are one
        // join (a flat CSEG's two ends, found by bisection a few ten-millionths apart): a line
        // between them would lie in the boundary's own tolerance, its samples free by it.
        const double tiny = 1e-3 * ax.step();
        std::vector<double> extra;
        for (std::size_t a = 0; a + 1 < f.size(); ++a) {
            // Two features closer than a step: a line between them, whether or not a sample line
            // happens to fall there (so that the grid does not depend on where the drawing lies).
            const double lo = f[a], hi = f[a + 1];
            if (hi - lo <= tiny || hi - lo >= ax.step()) continue;
            double mid = 0.5 * (lo + hi);
            if (ax.periodic && mid >= ax.hi) mid -= ax.span();
            extra.push_back(mid);
        }
        std::vector<double> all = at;
        all.insert(all.end(), extra.begin(), extra.end());
        std::sort(all.begin(), all.end());
        all.erase(std::unique(all.begin(), all.end()), all.end());
        inserted[k].assign(all.size(), false);
        for (std::size_t i = 0; i < all.size(); ++i)
            inserted[k][i] = std::find(at.begin(), at.end(), all[i]) == at.end();
        at = std::move(all);
    }
    inserted_ = inserted;
    // Blocked: the configuration space's own samples where both lines are its, the oracle elsewhere.
    const int n0 = size(0), n1 = size(1);
    blocked_.assign(static_cast<std::size_t>(n0 * n1), 0);
    std::array<std::vector<int>, 2> original;
    for (std::size_t k = 0; k < 2; ++k) {
        original[k].assign(at_[k].size(), -1);
        int o = 0;
        for (std::size_t i = 0; i < at_[k].size(); ++i)
            if (!inserted[k][i]) original[k][i] = o++;
    }
    for (int j = 0; j < n1; ++j)
        for (int i = 0; i < n0; ++i) {
            const int oi = original[0][static_cast<std::size_t>(i)], oj = original[1][static_cast<std::size_t>(j)];
            blocked_[static_cast<std::size_t>(i + n0 * j)] = oi >= 0 && oj >= 0 ? space.is_blocked(oi, oj) : oracle.blocked(point(i, j));
        }
}

double FaceGrid::coordinate(int k, int i) const noexcept {
    const auto& ax = space_.request.axes[static_cast<std::size_t>(k)];
    if (ax.periodic && i == size(k)) return ax.hi;
    return at_[static_cast<std::size_t>(k)][static_cast<std::size_t>(i)];
}

double FaceGrid::unwrapped(int k, int i) const noexcept {
    const auto& ax = space_.request.axes[static_cast<std::size_t>(k)];
    if (!ax.periodic) return coordinate(k, i);
    const int n = size(k);
    const int m = ((i % n) + n) % n;
    return coordinate(k, m) + static_cast<double>((i - m) / n) * ax.span();
}

int FaceGrid::below(int k, double x) const noexcept {
    const auto& at = at_[static_cast<std::size_t>(k)];
    const auto it = std::upper_bound(at.begin(), at.end(), x);
    return static_cast<int>(it - at.begin()) - 1;
}

FaceLocator::FaceLocator(const FaceGrid& grid, const std::vector<Division>& divisions,
                         const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>& barriers)
    : grid_(grid), divisions_(divisions), n0_(grid.size(0)), n1_(grid.size(1)) {
    const auto& r = grid.request();
    for (auto& c : cut_) c.assign(static_cast<std::size_t>(n0_ * n1_), 0);
    on_division_.assign(static_cast<std::size_t>(n0_ * n1_), 0);
    // A division along axis a at other coordinate v cuts each sample edge across v (along the
    // other axis b) whose position along a lies within the division, its ends included to
    // on_line_cells. A sample on the line (to on_line_cells) lies below it: the edge cut is the
    // one from that sample upwards.
    for (const auto& d : divisions_) {
        const int a = d.axis, b = 1 - a;
        const auto& axa = r.axes[static_cast<std::size_t>(a)];
        const auto& axb = r.axes[static_cast<std::size_t>(b)];
        const double v = wrap(r, d.start)[b];
        const double on = on_line_cells * grid.step(b);
        // A division along a translation limit divides nothing (nor one beyond it).
        if (!axb.periodic && (v < axb.lo + on || v > axb.hi - on)) continue;
        // On a periodic axis a division just below hi lies on the first line, a period on.
        const double vv = axb.periodic && v + on >= axb.hi ? v - axb.span() : v;
        const int lower = grid.below(b, vv + on);
        if (lower < 0) continue;
        const bool on_sample = std::abs(vv - grid.coordinate(b, lower)) <= on;
        const double tol = on_line_cells * grid.step(a);
        for (int m = 0; m < grid.size(a); ++m) {
            const double t = along(axa, d, grid.coordinate(a, m), tol);
            const int i = a == 0 ? m : lower, j = a == 0 ? lower : m;
            const bool cut = t >= -tol && t <= d.length + tol;
            // A sample on the division itself (a box's corner drawn on the grid, its FSDs along
            // grid lines) belongs to no face: which side it went to was rounding's choice.
            if (cut && on_sample) on_division_[static_cast<std::size_t>(i + n0_ * j)] = 1;
            if (cut) cut_[b][static_cast<std::size_t>(i + n0_ * j)] = 1;
        }
    }
    cut_along(barriers);
}

// The boundary next to a normal-change join (a tip, a corner) is the chain from the join to its
// neighbouring boundary points, which may lie cells away at a needle's apex. A grid edge crossing
// one of those segments passes through the blocked tip, even when both its samples are free (the
// tip thinner than a cell): it does not connect. The tip of the ratchet's needle between two
// samples at 80 x 320 joined the faces either side of it; the top of a cam's curve between two
// columns, under the division rising from it, the faces either side of that.
void FaceLocator::cut_along(const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>& barriers) {
    const auto& r = grid_.request();
    for (const auto& [from, delta] : barriers)
        for (int k = 0; k < 2; ++k) {  // the grid lines q[k] = coordinate(k, m) the segment crosses
            const auto& ak = r.axes[static_cast<std::size_t>(k)];
            const auto& ao = r.axes[static_cast<std::size_t>(1 - k)];
            if (delta[k] == 0) continue;
            const double lo = std::min(from[k], from[k] + delta[k]), hi = std::max(from[k], from[k] + delta[k]);
            const int nk = grid_.size(k), no = grid_.size(1 - k);
            // Lines over the unwrapped range: whole periods apart on a periodic axis.
            const double base = ak.periodic ? std::floor((lo - ak.lo) / ak.span()) : 0.0;
            for (int m = static_cast<int>(base) * nk - 1; m <= (static_cast<int>(base) + 2) * nk; ++m) {
                if (!ak.periodic && (m < 0 || m >= nk)) continue;
                const double x = grid_.unwrapped(k, m);
                if (x < lo || x > hi) continue;
                Eigen::Vector2d q = from + delta * ((x - from[k]) / delta[k]);
                q[k] = x;
                q = wrap(r, q);
                int line = ak.periodic ? ((m % nk) + nk) % nk : m;
                int o = grid_.below(1 - k, q[1 - k]);
                if (ao.periodic && o < 0) o = no - 1;
                if (line < 0 || line >= nk || o < 0 || o >= no || (!ao.periodic && o >= no - 1)) continue;
                // A barrier through a sample (one on the boundary, inserted between two joins
                // whose straight line the barrier is) touches the edges from it, and crosses none.
                const double on = on_line_cells * grid_.step(1 - k);
                if (std::abs(q[1 - k] - grid_.coordinate(1 - k, o)) <= on || std::abs(grid_.coordinate(1 - k, o + 1) - q[1 - k]) <= on) continue;
                // The edge passes through blocked space beside the crossing (the tip, on one side of
                // a chord that runs along its flank), or the barrier, a chord across free space (a
                // strip thinner than a cell under a join), separates nothing there.
                bool through = false;
                for (const double f : {0.0, 1e-4, 1e-3, 1e-2, 0.05, 0.1, 0.2})
                    for (const double sign : {-1.0, 1.0}) {
                        Eigen::Vector2d y = q;
                        y[1 - k] += sign * f * grid_.step(1 - k);
                        const bool on_edge = y[1 - k] >= grid_.coordinate(1 - k, o) && y[1 - k] <= grid_.coordinate(1 - k, o + 1);
                        through = through || (on_edge && grid_.oracle().blocked(wrap(r, y)));
                    }
                if (!through) continue;
                // The edge on grid line `line` (across axis k) from sample o along the other axis.
                const int i = k == 0 ? line : o, j = k == 0 ? o : line;
                cut_[1 - k][static_cast<std::size_t>(i + n0_ * j)] = 1;
            }
        }
}

int FaceLocator::label() {
    const auto& r = grid_.request();
    const int total = n0_ * n1_;
    std::vector<int> parent(static_cast<std::size_t>(total));
    std::iota(parent.begin(), parent.end(), 0);
    for (int j = 0; j < n1_; ++j)
        for (int i = 0; i < n0_; ++i) {
            const int s = i + n0_ * j;
            if (grid_.blocked(i, j) || on_division_[static_cast<std::size_t>(s)]) continue;
            for (int k = 0; k < 2; ++k) {
                const auto& ax = r.axes[static_cast<std::size_t>(k)];
                const int idx = k == 0 ? i : j;
                if (!ax.periodic && idx == grid_.size(k) - 1) continue;
                const int i2 = k == 0 ? (i + 1) % n0_ : i, j2 = k == 1 ? (j + 1) % n1_ : j;
                if (grid_.blocked(i2, j2) || on_division_[static_cast<std::size_t>(i2 + n0_ * j2)] || cut_[k][static_cast<std::size_t>(s)]) continue;
                parent[static_cast<std::size_t>(find_root(parent, s))] = find_root(parent, i2 + n0_ * j2);
            }
        }
    face_.assign(static_cast<std::size_t>(total), -1);
    std::vector<int> id_of_root(static_cast<std::size_t>(total), -1);
    // Faces numbered in the order of their first sample of the configuration space's own grid,
    // then those only inserted lines see: the numbers do not depend on the lines inserted.
    int faces = 0;
    for (const bool sampled_only : {true, false})
        for (int s = 0; s < total; ++s) {
            const int i = s % n0_, j = s / n0_;
            if (grid_.blocked(i, j) || on_division_[static_cast<std::size_t>(s)]) continue;
            if (sampled_only && !(grid_.sampled(0, i) && grid_.sampled(1, j))) continue;
            const int root = find_root(parent, s);
            if (id_of_root[static_cast<std::size_t>(root)] < 0) id_of_root[static_cast<std::size_t>(root)] = faces++;
            face_[static_cast<std::size_t>(s)] = id_of_root[static_cast<std::size_t>(root)];
        }
    return faces;
}

// Does the segment from a to sample (i, j) cross a division? Sides are taken as the cuts take
// them: a point within on_line_cells of a division's line is on its lower side (the cuts' row is
// floor(u + on_line_cells)), whatever the sign of a near-zero offset; a sample that close to the
// line is in no face at all (above). Deciding it by the sign of a zero offset put a point a third
// of a cell to the upper side into the lower face (the cam at grid 64, the division from the top of
// its curve at q0 = pi/2: a face with no way out under (- 0), and a join reaching the face across
// the division).
bool FaceLocator::crosses_division(const Eigen::Vector2d& a, int i, int j) const { return crosses_division(a, grid_.point(i, j), false); }

bool FaceLocator::crosses_division(const Eigen::Vector2d& a, const Eigen::Vector2d& b, bool leaving) const {
    const auto& r = grid_.request();
    const Eigen::Vector2d step = difference(r, a, b);
    for (std::size_t k = 0; k < divisions_.size(); ++k) {
        const auto& d = divisions_[k];
        const int ax = d.axis, other = 1 - ax;
        const auto& axis = r.axes[static_cast<std::size_t>(ax)];
        // Sides as the cuts take them: within on_line_cells of the line is below it.
        const double on = on_line_cells * grid_.step(other), tol = on_line_cells * axis.step();
        const double oa = across(r, d, a), ob = oa + step[other];
        if (leaving && std::abs(oa) <= on && along(axis, d, a[ax], tol) >= -tol && along(axis, d, a[ax], tol) <= d.length + tol) continue;
        if ((oa > on) == (ob > on)) continue;
        const double x = a[ax] + step[ax] * ((oa - on) / (oa - ob));
        const double t = along(axis, d, x, tol);
        if (t >= -tol && t <= d.length + tol) return true;
    }
    return false;
}

std::optional<Eigen::Vector2d> FaceLocator::division_crossing(const Eigen::Vector2d& a, const Eigen::Vector2d& b) const {
    const auto& r = grid_.request();
    const Eigen::Vector2d step = difference(r, a, b);
    std::optional<double> first;
    for (const auto& d : divisions_) {
        const int ax = d.axis, other = 1 - ax;
        const auto& axis = r.axes[static_cast<std::size_t>(ax)];
        const double on = on_line_cells * grid_.step(other), tol = on_line_cells * axis.step();
        const double oa = across(r, d, a), ob = oa + step[other];
        if (std::abs(oa) <= on && along(axis, d, a[ax], tol) >= -tol && along(axis, d, a[ax], tol) <= d.length + tol) continue;  // leaving it
        if ((oa > on) == (ob > on)) continue;
        const double s = (oa - on) / (oa - ob);
        const double t = along(axis, d, a[ax] + step[ax] * s, tol);
        if (t >= -tol && t <= d.length + tol && (!first || s < *first)) first = s;
    }
    if (!first) return std::nullopt;
    return Eigen::Vector2d(a + *first * step);
}

std::optional<int> FaceLocator::face_at(const Eigen::Vector2d& q, bool sampled_only) const {
    const auto& r = grid_.request();
    const Eigen::Vector2d x = wrap(r, q);
    const int ci = grid_.below(0, x[0]), cj = grid_.below(1, x[1]);
    std::optional<int> best;
    double best_d = 0;
    for (int radius = 1; radius <= 3 && !best; ++radius)
        for (int dj = 1 - radius; dj <= radius; ++dj)
            for (int di = 1 - radius; di <= radius; ++di) {
                int i = ci + di, j = cj + dj;
                if (r.axes[0].periodic) i = (i % n0_ + n0_) % n0_;
                if (r.axes[1].periodic) j = (j % n1_ + n1_) % n1_;
                if (i < 0 || j < 0 || i >= n0_ || j >= n1_) continue;
                const int f = face_of_sample(i, j);
                if (f < 0 || (sampled_only && !(grid_.sampled(0, i) && grid_.sampled(1, j)))) continue;
                if (crosses_division(x, i, j)) continue;
                const Eigen::Vector2d s = grid_.point(i, j);
                const double dist = difference(r, x, s).cwiseQuotient(Eigen::Vector2d(grid_.step(0), grid_.step(1))).norm();
                if (!best || dist < best_d) {
                    best = f;
                    best_d = dist;
                }
            }
    return best;
}

}  // namespace qm::geometry::detail
