// geometry/mechanism_transform.cpp: a mechanism moved, turned and scaled as a whole.
#include "geometry/mechanism_transform.hpp"

#include "qm/assert.hpp"

#include <cmath>

namespace qm::geometry {

Mechanism transformed(const Mechanism& m, double scale, double turn, const Eigen::Vector2d& shift) {
    QM_REQUIRE(scale > 0 && std::isfinite(scale), "a scale must be positive and finite");
    const Eigen::Rotation2Dd rotation(turn);
    auto point = [&](const Eigen::Vector2d& x) -> Eigen::Vector2d { return scale * (rotation * x) + shift; };
    Mechanism out = m;
    for (auto& part : out.parts) {
        for (auto& profile : part.profiles)
            for (auto& s : profile.segments) {
                s.from = point(s.from);
                s.to = point(s.to);
                s.centre = point(s.centre);
            }
        part.dof.pivot = point(part.dof.pivot);
        part.dof.axis = rotation * part.dof.axis;
        part.lo *= scale;
        part.hi *= scale;
    }
    for (auto& f : out.forces) {
        f.direction = rotation * f.direction;
        if (f.at) f.at = point(*f.at);
        if (f.when && m.parts[f.part].translates()) f.when = std::make_pair(f.when->first * scale, f.when->second * scale);
    }
    return out;
}

}  // namespace qm::geometry
