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

// Parameter of coordinate x along a division's axis, in [0, span) on periodic axes.
double along(const CSpaceAxis& ax, const Division& d, double x) {
    double t = d.dir * (x - d.start[d.axis]);
    if (ax.periodic) {
        t = std::fmod(t, ax.span());
        if (t < 0) t += ax.span();
    }
    return t;
}

}  // namespace

FaceLocator::FaceLocator(const CSpaceResult& space, const std::vector<Division>& divisions)
    : space_(space), divisions_(divisions), n0_(space.request.axes[0].samples), n1_(space.request.axes[1].samples) {
    const auto& r = space.request;
    for (auto& c : cut_) c.assign(static_cast<std::size_t>(n0_ * n1_), 0);
    // A division along axis a at other coordinate v cuts each sample edge across v (along the
    // other axis b) whose position along a lies within the division.
    for (const auto& d : divisions_) {
        const int a = d.axis, b = 1 - a;
        const auto& axa = r.axes[static_cast<std::size_t>(a)];
        const auto& axb = r.axes[static_cast<std::size_t>(b)];
        const double v = wrap(r, d.start)[b];
        const int lower = static_cast<int>(std::floor((v - axb.lo) / axb.step()));
        lower_.push_back(lower);
        if (lower < 0 || lower >= axb.samples) continue;
        if (!axb.periodic && lower == axb.samples - 1) continue;
        for (int m = 0; m < axa.samples; ++m) {
            const double t = along(axa, d, axa.sample(m));
            if (t < 0 || t > d.length) continue;
            const int i = a == 0 ? m : lower, j = a == 0 ? lower : m;
            cut_[b][static_cast<std::size_t>(i + n0_ * j)] = 1;
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
            if (space_.is_blocked(i, j)) continue;
            const int s = i + n0_ * j;
            for (int k = 0; k < 2; ++k) {
                const auto& ax = r.axes[static_cast<std::size_t>(k)];
                const int idx = k == 0 ? i : j;
                if (!ax.periodic && idx == ax.samples - 1) continue;
                const int i2 = k == 0 ? (i + 1) % n0_ : i, j2 = k == 1 ? (j + 1) % n1_ : j;
                if (space_.is_blocked(i2, j2) || cut_[k][static_cast<std::size_t>(s)]) continue;
                parent[static_cast<std::size_t>(find_root(parent, s))] = find_root(parent, i2 + n0_ * j2);
            }
        }
    face_.assign(static_cast<std::size_t>(total), -1);
    std::vector<int> id_of_root(static_cast<std::size_t>(total), -1);
    int faces = 0;
    for (int s = 0; s < total; ++s) {
        if (space_.blocked[static_cast<std::size_t>(s)]) continue;
        const int root = find_root(parent, s);
        if (id_of_root[static_cast<std::size_t>(root)] < 0) id_of_root[static_cast<std::size_t>(root)] = faces++;
        face_[static_cast<std::size_t>(s)] = id_of_root[static_cast<std::size_t>(root)];
    }
    return faces;
}

// A sample on a division's line (a division from a join at a grid coordinate: the top of a cam
// curve at q0 = pi/2 on a grid of 64) lies on the side the cuts put it, the lower one when
// floor() gives its own index: deciding it by the sign of a zero offset, as before, put a
// point a third of a cell to the upper side into the lower face (the cam at grid 64: a face
// with no way out under (- 0), and a join reaching the face across the division).
bool FaceLocator::crosses_division(const Eigen::Vector2d& a, int i, int j) const {
    const auto& r = space_.request;
    const Eigen::Vector2d b(r.axes[0].sample(i), r.axes[1].sample(j));
    const Eigen::Vector2d step = difference(r, a, b);
    for (std::size_t k = 0; k < divisions_.size(); ++k) {
        const auto& d = divisions_[k];
        const int ax = d.axis, other = 1 - ax;
        // Signed offsets of a and b from the division's line in the other coordinate.
        const double oa = difference(r, d.start, a)[other];
        double ob = oa + step[other];
        const auto& axo = r.axes[static_cast<std::size_t>(other)];
        if (std::abs(ob) <= 1e-9 * axo.step()) ob = (other == 0 ? i : j) == lower_[k] ? -1.0 : 1.0;
        if ((oa > 0) == (ob > 0) || oa == 0) continue;
        const double x = a[ax] + step[ax] * (oa / (oa - ob));
        const double t = along(r.axes[static_cast<std::size_t>(ax)], d, x);
        if (t >= 0 && t <= d.length) return true;
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
