// geometry/fcl_pair_oracle.cpp: FCL collision and distance as the metric diagram of a pair.
#include "geometry/fcl_pair_oracle.hpp"

#include "geometry/profile_pair_oracle.hpp"
#include "qm/assert.hpp"

#include <algorithm>
#include <limits>
#include <numbers>
#include <sstream>

namespace qm::geometry {
namespace {

double pair_height(const Part& a, const Part& b) { return std::max({a.size(), b.size(), 1e-300}); }

Eigen::Vector2d centre_of(const Part& p) {
    if (p.rotates()) return p.dof.pivot;
    const double big = std::numeric_limits<double>::infinity();
    Eigen::Vector2d lo(big, big), hi(-big, -big);
    for (const auto& profile : p.profiles) extend_bounds(profile, lo, hi);
    return 0.5 * (lo + hi);
}

}  // namespace

FclPairOracle::FclPairOracle(const Part& a, const Part& b, double chordal_tolerance)
    : models_{FclPartModel(a, chordal_tolerance, pair_height(a, b)), FclPartModel(b, chordal_tolerance, pair_height(a, b))},
      chordal_tolerance_(chordal_tolerance) {
    for (int k = 0; k < 2; ++k) {
        const Part& p = part(k);
        centre_[static_cast<std::size_t>(k)] = centre_of(p);
        reach_[static_cast<std::size_t>(k)] = 0;
        for (const auto& profile : p.profiles)
            reach_[static_cast<std::size_t>(k)] = std::max(reach_[static_cast<std::size_t>(k)], reach(profile, centre_[static_cast<std::size_t>(k)]));
    }
}

bool FclPairOracle::far_apart(const Eigen::Vector2d& q) const {
    // Bounding circles about each part's centre, moved with it: a cheap reject before FCL.
    const Eigen::Vector2d ca = part(0).pose(q[0]) * centre_[0], cb = part(1).pose(q[1]) * centre_[1];
    return (ca - cb).norm() > (reach_[0] + reach_[1]) * (1 + 1e-12) + 2 * chordal_tolerance_;
}

bool FclPairOracle::blocked(const Eigen::Vector2d& q) const {
    if (far_apart(q)) return false;
    ++calls_;
    return fcl_collide(models_[0], q[0], models_[1], q[1]);
}

double FclPairOracle::signed_distance(const Eigen::Vector2d& q) const {
    ++calls_;
    if (fcl_collide(models_[0], q[0], models_[1], q[1])) return -1.0;
    return fcl_distance(models_[0], q[0], models_[1], q[1]);
}

bool FclPairOracle::separable_within(const Eigen::Vector2d& q, double depth) const {
    for (double r : {1.0, 0.25})
        for (int i = 0; i < 32; ++i) {
            const double a = 2 * std::numbers::pi * i / 32;
            ++calls_;
            if (!fcl_collide(models_[0], q[0], models_[1], q[1], r * depth * Eigen::Vector2d(std::cos(a), std::sin(a)))) return true;
        }
    return false;
}

double FclPairOracle::coordinate_scale(int which) const {
    const Part& p = part(which);
    return p.translates() ? std::max(p.size(), 1e-300) : 1.0;
}

Eigen::Vector2d FclPairOracle::free_normal(const Eigen::Vector2d& q) const {
    // From the exact lines and arcs, not the meshes: a chord's slope would make a surface drawn
    // along an axis (a wheel's root land, turning about its centre) flicker between signs.
    return exact_free_normal(part(0), part(1), q);
}

std::string FclPairOracle::fingerprint() const { return fingerprint_of(part(0), part(1), chordal_tolerance_); }

std::string FclPairOracle::fingerprint_of(const Part& a, const Part& b, double chordal_tolerance) {
    std::ostringstream os;
    os << std::hexfloat << "fcl-pair/1 chordal " << chordal_tolerance << '\n'
       << geometry::fingerprint(a) << '\n'
       << geometry::fingerprint(b);
    return os.str();
}

}  // namespace qm::geometry
