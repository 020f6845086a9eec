// geometry/cspace.hpp
// Provides:   classify_cspace(): the configuration space of one kinematic pair (thesis Def 27,
//             8.1.1) sampled on a grid and classified blocked/free with a PairOracle, and its
//             contact boundary located to a requested tolerance by bracketing on grid edges and
//             bisection; each boundary point carries its normal into free space from the geometry.
// Ownership:  CSpaceResult is a value; it keeps no reference to the oracle.
// Invariants: in a result with status ok, boundary points lie on grid edges whose two samples
//             differ, within tolerance of the true boundary along that edge's axis; a periodic
//             axis wraps (its last sample is adjacent to its first).
// Knows nothing of the ATMS or the engine; never prints.
#pragma once
#include "geometry/pair_oracle.hpp"
#include "geometry/qualitative_sign.hpp"
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace qm::geometry {

// One degree of freedom of the pair: a rotation angle in radians or a translation offset.
struct CSpaceAxis {
    double lo = 0.0;
    double hi = 1.0;
    bool periodic = false;  // rotation axes wrap (period hi - lo, e.g. 2*pi or one tooth pitch)
    int samples = 64;       // grid samples along the axis (>= 2)
    bool stops = false;     // a non-periodic axis' ends are stops (its part meets its frame there):
                            // the place builder makes their free stretches `stop` places
    [[nodiscard]] double span() const noexcept { return hi - lo; }
    // Distance between neighbouring samples.
    [[nodiscard]] double step() const noexcept { return periodic ? span() / samples : span() / (samples - 1); }
    // Sample i; on a translation axis the last sample is hi itself, on a periodic axis sample
    // `samples` (the first, one period on) is hi: not lo + i step, which can land an ulp beyond
    // the limit, and a division running to the limit would then not be cut at its top.
    [[nodiscard]] double sample(int i) const noexcept {
        return i == (periodic ? samples : samples - 1) ? hi : lo + i * step();
    }
    // Sample i of a periodic axis counted on past its ends (i may be negative or beyond the last:
    // sample(i mod samples) plus the whole periods); sample(i) on a translation axis.
    [[nodiscard]] double unwrapped_sample(int i) const noexcept {
        if (!periodic) return sample(i);
        const int m = ((i % samples) + samples) % samples;
        return sample(m) + static_cast<double>((i - m) / samples) * span();
    }
};

struct CSpaceRequest {
    std::array<CSpaceAxis, 2> axes;
    double boundary_tolerance = 1e-9;  // bracket width along an axis at which bisection stops
    double normal_zero_tolerance = 1e-6;  // a unit normal component this small is qualitatively 0
};

enum class CSpaceStatus { ok, bad_request };

struct BoundaryPoint {
    Eigen::Vector2d q;            // configuration within tolerance of contact
    int axis = 0;                 // axis of the grid edge that bracketed it
    std::array<int, 2> cell{};    // the edge's first sample (grid indices)
    Eigen::Vector2d normal;       // unit normal into free space, from the geometry
    QualDirection qual;           // its qualitative direction
    bool low_side_blocked = false;  // the edge's first sample is blocked
    // The normal points back towards the edge's blocked sample, against the crossing itself:
    // the exact features nearest this configuration (found on the meshes) name another surface
    // (near a sharp corner, e.g. a pawl's tip on a tooth's tip). Its normal says nothing here;
    // the place builder gives the point its neighbours' along the boundary.
    bool normal_contradicts_edge = false;
};

struct CSpaceResult {
    CSpaceStatus status = CSpaceStatus::ok;
    std::string message;                 // why the request was refused (status != ok)
    CSpaceRequest request;
    std::vector<std::uint8_t> blocked;   // blocked[i + samples0 * j], 1 = blocked
    std::vector<BoundaryPoint> boundary;
    std::uint64_t oracle_calls = 0;      // blocked() evaluations
    [[nodiscard]] bool is_blocked(int i, int j) const {
        return blocked[static_cast<std::size_t>(i + request.axes[0].samples * j)] != 0;
    }
    [[nodiscard]] bool all_free() const;
};

// Pre: none; a bad request (samples < 2, empty axis, non-positive tolerance) is reported in the
// result's status, never thrown.
[[nodiscard]] CSpaceResult classify_cspace(const PairOracle& oracle, const CSpaceRequest& request);

// Checks a request; returns the reason it is bad, or nullopt.
[[nodiscard]] std::optional<std::string> check_request(const CSpaceRequest& request);

// Locate the contact on the segment from a (state blocked_a) to b (the other state) by bisection
// until the bracket is shorter than tolerance; returns the bracket's midpoint.
[[nodiscard]] Eigen::Vector2d bisect_contact(const PairOracle& oracle, Eigen::Vector2d a, bool blocked_a,
                                             Eigen::Vector2d b, double tolerance, std::uint64_t& calls);

// Wrap q into the axes' domain (periodic axes only).
[[nodiscard]] Eigen::Vector2d wrap(const CSpaceRequest& request, Eigen::Vector2d q) noexcept;
// Shortest difference b - a, taking periodic axes into account.
[[nodiscard]] Eigen::Vector2d difference(const CSpaceRequest& request, const Eigen::Vector2d& a,
                                         const Eigen::Vector2d& b) noexcept;

}  // namespace qm::geometry
