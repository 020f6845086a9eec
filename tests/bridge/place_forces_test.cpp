// tests/bridge/place_forces_test.cpp: forces by place (bridge/place_forces.hpp, thesis 8.2.1)
// against the geometry's own torque sign, sampled densely: at every point of every line and at
// points between consecutive polyline points, a position-dependent force has the sign its place
// was given (or none, at the division itself); a constant force is the spring's torque.
#include "bridge/place_forces.hpp"
#include "geometry/external_force.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"
#include <doctest/doctest.h>
#include <filesystem>

using namespace qm;
namespace g = qm::geometry;

TEST_CASE("bridge/place_forces: gravity's sign at every place agrees with the torque sign along the place") {
    for (const char* file : {"scenarios/metric/escapement.def", "scenarios/metric/ratchet.def"}) {
        CAPTURE(file);
        Diagnostics d;
        const auto m = g::read_mechanism_file((std::filesystem::path(QM_SOURCE_DIR) / file).string(), d);
        REQUIRE(m.has_value());
        const auto spec = g::kinematic_pairs(*m).modelled.at(0);
        const auto request = g::place_request(*m, spec);
        const auto v = g::build_place_vocabulary(*g::pair_oracle(*m, spec), request).vocabulary;
        const auto forces = bridge::pair_forces(*m, spec, v);
        REQUIRE(forces.by_place.size() == v.places.size());
        const auto& gravity = m->forces.back();  // (gravity PART ...) is the scene's last force
        const g::Part& part = m->parts[gravity.part];
        const double zero = m->settings.contact_tolerance * part.size();
        std::size_t plus = 0, minus = 0, none = 0;
        for (const auto& p : v.places) {
            REQUIRE(forces.by_place[p.id.value].size() == 1);
            const int sign = forces.by_place[p.id.value][0].sign;
            (sign > 0 ? plus : sign < 0 ? minus : none) += 1;
            for (std::size_t i = 0; i < p.points.size(); ++i) {
                std::vector<double> qs{p.points[i][1]};
                if (i + 1 < p.points.size() && std::abs(p.points[i + 1][1] - p.points[i][1]) < 1.0)
                    qs.push_back(0.5 * (p.points[i][1] + p.points[i + 1][1]));
                for (const double q : qs) {
                    const int s = g::torque_sign(gravity, part, q, zero);
                    CHECK((s == 0 || s == sign));
                }
            }
            if (p.kind == g::PlaceKind::external_division) CHECK(sign == 0);
        }
        CHECK(plus > 0);
        CHECK(minus > 0);
        const auto constant = bridge::constant_forces(*m);
        REQUIRE(constant.size() == 1);  // the spring's torque on the wheel
        CHECK(constant[0].cause == "spring");
    }
}
