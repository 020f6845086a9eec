// geometry/detail/full_faces.cpp: full faces (Def 32) as connected free samples not separated by
// a division. Faces are found by connectivity of free space, not by following paths of joins, so
// a face bordered by two unconnected surfaces (the piston of Figure 8.3) is one face.
#include "geometry/detail/place_parts.hpp"

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

FaceLocator::FaceLocator(const CSpaceResult& space, const std::vector<Division>& divisions,
                         const std::vector<std::pair<Eigen::Vector2d, Eigen::Vector2d>>& barriers)
    : space_(space), divisions_(divisions), n0_(space.request.axes[0].samples), n1_(space.request.axes[1].samples) {
    const auto& r = space.request;
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
        const double u = (v - axb.lo) / axb.step();
        // A division along a translation limit divides nothing (nor one beyond it).
        if (!axb.periodic && (u < on_line_cells || u > axb.samples - 1 - on_line_cells)) continue;
        int lower = static_cast<int>(std::floor(u + on_line_cells));
        if (axb.periodic) lower = ((lower % axb.samples) + axb.samples) % axb.samples;
        const double tol = on_line_cells * axa.step();
        for (int m = 0; m < axa.samples; ++m) {
            const double t = along(axa, d, axa.sample(m), tol);
            const int i = a == 0 ? m : lower, j = a == 0 ? lower : m;
            const bool cut = t >= -tol && t <= d.length + tol;
            // A sample on the division itself (a box's corner drawn on the grid, its FSDs along
            // grid lines) belongs to no face: which side it went to was rounding's choice.
            if (cut && std::abs(u - std::round(u)) <= on_line_cells) {
                const int k = static_cast<int>(std::lround(u)) % axb.samples;
                on_division_[static_cast<std::size_t>(a == 0 ? m + n0_ * k : k + n0_ * m)] = 1;
            }
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
    const auto& r = space_.request;
    for (const auto& [from, delta] : barriers)
        for (int k = 0; k < 2; ++k) {  // the grid lines q[k] = sample(m) the segment crosses
            const auto& ak = r.axes[static_cast<std::size_t>(k)];
            const auto& ao = r.axes[static_cast<std::size_t>(1 - k)];
            if (delta[k] == 0) continue;
            const double lo = std::min(from[k], from[k] + delta[k]), hi = std::max(from[k], from[k] + delta[k]);
            const int first = static_cast<int>(std::ceil((lo - ak.lo) / ak.step())), last = static_cast<int>(std::floor((hi - ak.lo) / ak.step()));
            for (int m = first; m <= last; ++m) {
                const double x = ak.lo + m * ak.step();
                if (x < lo || x > hi) continue;
                Eigen::Vector2d q = from + delta * ((x - from[k]) / delta[k]);
                q[k] = x;
                q = wrap(r, q);
                int line = static_cast<int>(std::lround((q[k] - ak.lo) / ak.step()));
                int o = static_cast<int>(std::floor((q[1 - k] - ao.lo) / ao.step()));
                if (ak.periodic) line = ((line % ak.samples) + ak.samples) % ak.samples;
                if (ao.periodic) o = ((o % ao.samples) + ao.samples) % ao.samples;
                if (line < 0 || line >= ak.samples || o < 0 || o >= ao.samples || (!ao.periodic && o >= ao.samples - 1)) continue;
                // The edge on grid line `line` (across axis k) from sample o along the other axis.
                const int i = k == 0 ? line : o, j = k == 0 ? o : line;
                cut_[1 - k][static_cast<std::size_t>(i + n0_ * j)] = 1;
            }
        }
}

int FaceLocator::label() {
    const auto& r = space_.request;
    const int total = n0_ * n1_;
    std::vector<int> parent(static_cast<std::size_t>(total));
    std::iota(parent.begin(), parent.end(), 0);
    for (int j = 0; j < n1_; ++j)
        for (int i = 0; i < n0_; ++i) {
            const int s = i + n0_ * j;
            if (space_.is_blocked(i, j) || on_division_[static_cast<std::size_t>(s)]) continue;
            for (int k = 0; k < 2; ++k) {
                const auto& ax = r.axes[static_cast<std::size_t>(k)];
                const int idx = k == 0 ? i : j;
                if (!ax.periodic && idx == ax.samples - 1) continue;
                const int i2 = k == 0 ? (i + 1) % n0_ : i, j2 = k == 1 ? (j + 1) % n1_ : j;
                if (space_.is_blocked(i2, j2) || on_division_[static_cast<std::size_t>(i2 + n0_ * j2)] || cut_[k][static_cast<std::size_t>(s)]) continue;
                parent[static_cast<std::size_t>(find_root(parent, s))] = find_root(parent, i2 + n0_ * j2);
            }
        }
    face_.assign(static_cast<std::size_t>(total), -1);
    std::vector<int> id_of_root(static_cast<std::size_t>(total), -1);
    int faces = 0;
    for (int s = 0; s < total; ++s) {
        if (space_.blocked[static_cast<std::size_t>(s)] || on_division_[static_cast<std::size_t>(s)]) continue;
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
bool FaceLocator::crosses_division(const Eigen::Vector2d& a, int i, int j) const {
    const auto& r = space_.request;
    const Eigen::Vector2d b(r.axes[0].sample(i), r.axes[1].sample(j));
    const Eigen::Vector2d step = difference(r, a, b);
    for (std::size_t k = 0; k < divisions_.size(); ++k) {
        const auto& d = divisions_[k];
        const int ax = d.axis, other = 1 - ax;
        const auto& axis = r.axes[static_cast<std::size_t>(ax)];
        // Sides as the cuts take them: within on_line_cells of the line is below it.
        const double on = on_line_cells * r.axes[static_cast<std::size_t>(other)].step(), tol = on_line_cells * axis.step();
        const double oa = across(r, d, a), ob = oa + step[other];
        if ((oa > on) == (ob > on)) continue;
        const double x = a[ax] + step[ax] * ((oa - on) / (oa - ob));
        const double t = along(axis, d, x, tol);
        if (t >= -tol && t <= d.length + tol) return true;
    }
    return false;
}

std::optional<int> FaceLocator::face_at(const Eigen::Vector2d& q) const {
    const auto& r = space_.request;
    const Eigen::Vector2d x = wrap(r, q);
    const int ci = static_cast<int>(std::floor((x[0] - r.axes[0].lo) / r.axes[0].step()));
    const int cj = static_cast<int>(std::floor((x[1] - r.axes[1].lo) / r.axes[1].step()));
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
                if (f < 0) continue;
                const Eigen::Vector2d s(r.axes[0].sample(i), r.axes[1].sample(j));
                if (crosses_division(x, i, j)) continue;
                const double dist = difference(r, x, s).cwiseQuotient(Eigen::Vector2d(r.axes[0].step(), r.axes[1].step())).norm();
                if (!best || dist < best_d) {
                    best = f;
                    best_d = dist;
                }
            }
    return best;
}

}  // namespace qm::geometry::detail
