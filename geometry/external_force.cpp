// geometry/external_force.cpp: forces that depend on a part's position (thesis 8.2.1, 9.2).
#include "geometry/external_force.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace qm::geometry {
namespace {

constexpr double two_pi = 2 * std::numbers::pi;

double wrap(double x) {
    double r = std::fmod(x, two_pi);
    if (r < 0) r += two_pi;
    return r >= two_pi ? 0.0 : r;
}

double cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return a.x() * b.y() - a.y() * b.x(); }

}  // namespace

bool force_active(const ExternalForce& f, const Part& part, double q) {
    if (!f.when) return true;
    const auto [lo, hi] = *f.when;
    if (part.rotates()) return wrap(q - lo) <= hi - lo;
    return q >= lo && q <= hi;
}

std::optional<Eigen::Vector2d> application_point(const ExternalForce& f, const Part& part, double q) {
    if (!f.at) return std::nullopt;
    return part.pose(q) * *f.at;
}

int torque_sign(const ExternalForce& f, const Part& part, double q, double zero_length) {
    if (!part.rotates()) return 0;
    if (f.kind == ExternalForce::Kind::torque) return f.torque_sign;
    const auto p = application_point(f, part, q);
    if (!p) return 0;  // applied at the centre of rotation
    // Moment arm: distance from the pivot to the line of action.
    const double arm = cross(*p - part.dof.pivot, f.direction.normalized());
    if (std::abs(arm) <= zero_length) return 0;
    return arm > 0 ? 1 : -1;
}

bool position_dependent(const ExternalForce& f, const Part& part) {
    return f.when.has_value() || (part.rotates() && f.kind == ExternalForce::Kind::push && f.at.has_value());
}

std::vector<ForceChange> force_changes(const ExternalForce& f, const Part& part) {
    std::vector<ForceChange> out;
    auto add = [&](double q, std::string what) {
        if (part.rotates()) q = wrap(q);
        else if (q < part.lo || q > part.hi) return;
        out.push_back({q, std::move(what)});
    };
    if (f.when) {
        add(f.when->first, "starts acting");
        if (!(part.rotates() && f.when->second - f.when->first >= two_pi)) add(f.when->second, "stops acting");
    }
    if (part.rotates() && f.kind == ExternalForce::Kind::push && f.at) {
        // The arm vector turns with the part; it is parallel to the force at two angles.
        const Eigen::Vector2d r = *f.at - part.dof.pivot;
        if (r.norm() > 0) {
            const double phi0 = std::atan2(r.y(), r.x()), theta = std::atan2(f.direction.y(), f.direction.x());
            add(theta - phi0, "torque changes sign");
            add(theta - phi0 + std::numbers::pi, "torque changes sign");
        }
    }
    std::sort(out.begin(), out.end(), [](const ForceChange& a, const ForceChange& b) { return a.q < b.q; });
    return out;
}

}  // namespace qm::geometry
