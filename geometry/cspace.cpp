// geometry/cspace.cpp: grid classification and boundary location (thesis 8.1.1).
#include "geometry/cspace.hpp"

#include <algorithm>
#include <cmath>

namespace qm::geometry {

bool CSpaceResult::all_free() const {
    return std::none_of(blocked.begin(), blocked.end(), [](std::uint8_t b) { return b != 0; });
}

std::optional<std::string> check_request(const CSpaceRequest& r) {
    for (int k = 0; k < 2; ++k) {
        const auto& a = r.axes[static_cast<std::size_t>(k)];
        if (a.samples < 2) return "axis " + std::to_string(k) + " needs at least 2 samples";
        if (!(a.hi > a.lo) || !std::isfinite(a.lo) || !std::isfinite(a.hi))
            return "axis " + std::to_string(k) + " has an empty or infinite range";
    }
    if (!(r.boundary_tolerance > 0.0)) return "boundary tolerance must be positive";
    if (!(r.normal_zero_tolerance > 0.0) || !(r.normal_zero_tolerance < 1.0))
        return "normal zero tolerance must lie in (0, 1)";
    return std::nullopt;
}

Eigen::Vector2d wrap(const CSpaceRequest& r, Eigen::Vector2d q) noexcept {
    for (int k = 0; k < 2; ++k) {
        const auto& a = r.axes[static_cast<std::size_t>(k)];
        if (!a.periodic) continue;
        double t = std::fmod(q[k] - a.lo, a.span());
        if (t < 0) t += a.span();
        q[k] = a.lo + t;
    }
    return q;
}

Eigen::Vector2d difference(const CSpaceRequest& r, const Eigen::Vector2d& a, const Eigen::Vector2d& b) noexcept {
    Eigen::Vector2d d = b - a;
    for (int k = 0; k < 2; ++k) {
        const auto& ax = r.axes[static_cast<std::size_t>(k)];
        if (!ax.periodic) continue;
        d[k] = std::remainder(d[k], ax.span());
    }
    return d;
}

Eigen::Vector2d bisect_contact(const PairOracle& oracle, Eigen::Vector2d a, bool blocked_a, Eigen::Vector2d b,
                               double tolerance, std::uint64_t& calls) {
    // Invariant: blocked(a) == blocked_a and blocked(b) != blocked_a; the contact lies between.
    while ((b - a).norm() > tolerance) {
        const Eigen::Vector2d m = 0.5 * (a + b);
        if (m == a || m == b) break;  // the bracket is one ulp wide: no finer answer exists
        ++calls;
        if (oracle.blocked(m) == blocked_a)
            a = m;
        else
            b = m;
    }
    return 0.5 * (a + b);
}

namespace {

Eigen::Vector2d sample_point(const CSpaceRequest& r, int i, int j) {
    return {r.axes[0].sample(i), r.axes[1].sample(j)};
}

}  // namespace

CSpaceResult classify_cspace(const PairOracle& oracle, const CSpaceRequest& request) {
    CSpaceResult out;
    out.request = request;
    if (auto why = check_request(request)) {
        out.status = CSpaceStatus::bad_request;
        out.message = *why;
        return out;
    }
    const int n0 = request.axes[0].samples, n1 = request.axes[1].samples;
    out.blocked.resize(static_cast<std::size_t>(n0) * static_cast<std::size_t>(n1));
    for (int j = 0; j < n1; ++j)
        for (int i = 0; i < n0; ++i)
            out.blocked[static_cast<std::size_t>(i + n0 * j)] = oracle.blocked(sample_point(request, i, j)) ? 1 : 0;
    out.oracle_calls = out.blocked.size();

    // Every grid edge whose two samples differ brackets the contact boundary (8.1.1); bisect it.
    for (int axis = 0; axis < 2; ++axis) {
        const auto& ax = request.axes[static_cast<std::size_t>(axis)];
        const int last = ax.periodic ? ax.samples : ax.samples - 1;
        for (int j = 0; j < n1; ++j)
            for (int i = 0; i < n0; ++i) {
                const int idx = axis == 0 ? i : j;
                if (idx >= last) continue;
                const int i2 = axis == 0 ? (i + 1) % n0 : i, j2 = axis == 1 ? (j + 1) % n1 : j;
                const bool b1 = out.is_blocked(i, j), b2 = out.is_blocked(i2, j2);
                if (b1 == b2) continue;
                const Eigen::Vector2d a = sample_point(request, i, j);
                Eigen::Vector2d b = a;
                b[axis] = ax.sample(idx + 1);  // unwrapped (hi for the last), so bisection runs across the seam
                BoundaryPoint p;
                p.q = wrap(request, bisect_contact(oracle, a, b1, b, request.boundary_tolerance, out.oracle_calls));
                p.axis = axis;
                p.cell = {i, j};
                p.low_side_blocked = b1;
                Eigen::Vector2d n = oracle.free_normal(p.q);
                // The geometry's normal must point from the blocked sample to the free one along
                // this edge; if the oracle cannot tell, fall back to the edge direction.
                const double along = b1 ? 1.0 : -1.0;
                if (n.norm() == 0.0 || !n.allFinite()) {
                    n = Eigen::Vector2d::Zero();
                    n[axis] = along;
                }
                n.normalize();
                p.normal_contradicts_edge = n[axis] * along < -request.normal_zero_tolerance;
                // The same test along the normal itself: one that agrees with its edge can still
                // name the far surface across a sharp corner and point along the boundary into
                // blocked space (the escapement's pallet corner at grid 256). Probes a fiftieth of
                // a cell out find it so when the normal leads into blocked space and its opposite
                // into free space; at a concave corner of free space, where a sound normal runs
                // along the other wall, both probes are blocked.
                if (!p.normal_contradicts_edge) {
                    const double probe = std::min(request.axes[0].step(), request.axes[1].step()) / 50.0;
                    out.oracle_calls += 2;
                    p.normal_contradicts_edge = oracle.blocked(wrap(request, p.q + probe * n)) &&
                                                !oracle.blocked(wrap(request, p.q - probe * n));
                }
                p.normal = n;
                p.qual = qualitative(p.normal, request.normal_zero_tolerance);
                out.boundary.push_back(p);
            }
    }
    return out;
}

}  // namespace qm::geometry
