// bridge/place_forces.cpp: external forces by place (thesis 8.2.1).
#include "bridge/place_forces.hpp"
#include "geometry/external_force.hpp"
#include "geometry/qualitative_sign.hpp"
#include "qm/assert.hpp"

namespace qm::bridge {
namespace g = qm::geometry;

namespace {

// The sign of force f along its part's coordinate q.
int sign_at(const g::Mechanism& m, const g::ExternalForce& f, double q) {
    const g::Part& part = m.parts[f.part];
    if (part.fixed() || !g::force_active(f, part, q)) return 0;
    if (part.rotates() && f.kind == g::ExternalForce::Kind::torque) return f.torque_sign;  // (no arm to measure)
    if (part.rotates()) return g::torque_sign(f, part, q, m.settings.contact_tolerance * part.size());
    if (f.kind != g::ExternalForce::Kind::push) return 0;
    // A push on a sliding part: its projection on the axis (components within the normal zero
    // tolerance of the axis' normal count as none, as the geometry's qualitative normals do).
    const double along = f.direction.normalized().dot(part.dof.axis.normalized());
    return g::tolerant_sign(along, m.settings.normal_zero_tolerance);
}

}  // namespace

std::vector<PlaceForce> constant_forces(const g::Mechanism& m) {
    std::vector<PlaceForce> out;
    for (const auto& f : m.forces) {
        if (g::position_dependent(f, m.parts[f.part])) continue;
        const int s = sign_at(m, f, 0.0);
        if (s != 0) out.push_back({f.part, f.cause, s});
    }
    return out;
}

PairForces pair_forces(const g::Mechanism& m, const g::PairSpec& pair, const g::PlaceVocabulary& vocabulary) {
    PairForces out;
    out.by_place.resize(vocabulary.places.size());
    for (const auto& f : m.forces) {
        if (!g::position_dependent(f, m.parts[f.part])) continue;
        int axis = -1;
        if (m.same_shaft(pair.a, f.part)) axis = 0;
        else if (m.same_shaft(pair.b, f.part)) axis = 1;
        if (axis < 0) continue;
        for (const auto& place : vocabulary.places) {
            int sign = 0;
            for (const auto& point : place.points) {
                const int s = sign_at(m, f, point[axis]);
                if (s == 0) continue;
                if (sign != 0 && sign != s)
                    throw InternalError("the force of cause '" + f.cause + "' on '" + m.parts[f.part].name +
                                        "' changes sign within place " + std::to_string(place.id.value) + " of pair " +
                                        m.parts[pair.a].name + " " + m.parts[pair.b].name +
                                        ": the external divisions do not cut the space where it changes (8.2.1)");
                sign = s;
            }
            out.by_place[place.id.value].push_back({f.part, f.cause, sign});
        }
    }
    return out;
}

}  // namespace qm::bridge
