// tests/bridge/place_facts_test.cpp: bridge/place_facts.hpp's contract on a bundled mechanism:
// every place becomes its kind, normals, concavity and gap facts, every adjacency its `adjacent`
// fact with the right duration word, the choice set source lists every place id, and the options
// select one place and one motion; parts, shafts, causes and the external forces' assumptions.
#include "bridge/clock_vocabulary.hpp"
#include "bridge/place_facts.hpp"
#include "engine/rule_compiler.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"
#include <doctest/doctest.h>
#include <filesystem>
#include <sstream>

using namespace qm;
namespace g = qm::geometry;
namespace c = qm::bridge::clock;

namespace {

g::Mechanism read(const std::string& relative) {
    Diagnostics d;
    auto m = g::read_mechanism_file((std::filesystem::path(QM_SOURCE_DIR) / relative).string(), d);
    REQUIRE(m.has_value());
    return std::move(*m);
}

bridge::PairPlaces pair_of(const g::Mechanism& m) {
    const auto spec = g::kinematic_pairs(m).modelled.at(0);
    bridge::PairPlaces p;
    p.name = bridge::pair_symbol(m.parts[spec.a].name, m.parts[spec.b].name);
    p.spec = spec;
    p.request = g::place_request(m, spec);
    p.vocabulary = g::build_place_vocabulary(*g::pair_oracle(m, spec), p.request).vocabulary;
    p.forces = bridge::pair_forces(m, spec, p.vocabulary);
    return p;
}

std::unique_ptr<engine::Engine> empty_engine() {
    Diagnostics d;
    engine::ProgramSpec spec;
    auto program = engine::compile_program(spec, d);
    REQUIRE(program.has_value());
    return std::make_unique<engine::Engine>(std::move(program->program), std::move(program->values));
}

std::size_t count(engine::Engine& e, const char* predicate) { return e.facts_of(e.values().symbol(predicate)).size(); }

}  // namespace

TEST_CASE("bridge/place_facts: a pair's places and adjacency as facts") {
    const auto m = read("scenarios/metric/escapement.def");
    const auto pair = pair_of(m);
    const auto& v = pair.vocabulary;
    auto e = empty_engine();
    bridge::PlaceFactOptions all;
    all.choice = true;
    bridge::assert_pair(*e, m, pair, all);
    CHECK(count(*e, c::pair) == 1);
    CHECK(count(*e, c::axis) == 2);
    CHECK(count(*e, c::pair_places) == 1);
    CHECK(count(*e, c::place_kind) == v.places.size());
    CHECK(count(*e, c::join_kind) == v.count(g::PlaceKind::join));
    std::size_t normals = 0, with_normals = 0, concavity = 0, gaps = 0;
    for (const auto& p : v.places) {
        normals += p.normals.size();
        with_normals += !p.normals.empty();
        concavity += p.kind == g::PlaceKind::join && p.concave.has_value();
        gaps += p.gap;
    }
    CHECK(count(*e, c::place_normals) == with_normals);
    CHECK(count(*e, c::place_normal) <= normals);  // a join's two equal normals are one fact
    CHECK(count(*e, c::join_concave) + count(*e, c::join_convex) == concavity);
    CHECK(count(*e, c::gap_place) == gaps);
    CHECK(count(*e, c::adjacent) == v.adjacency.size());
    // Each adjacency with its duration word, and the pair's axes.
    std::ostringstream text;
    for (const auto f : e->facts_of(e->values().symbol(c::adjacent))) text << e->print(f) << '\n';
    for (const auto& a : v.adjacency) {
        const std::string word = a.constrained ? "constrained" : a.instantaneous ? "instant" : "interval";
        const std::string fact = "(adjacent scape-wheel/pallets " + std::to_string(a.from.value) + " " + std::to_string(a.to.value) + " " +
                                 g::to_string(a.motion) + " " + word + ")";
        CHECK(text.str().find(fact) != std::string::npos);
    }
    CHECK(e->find(e->values().symbol(c::axis), std::vector{e->values().symbol("scape-wheel/pallets"), e->values().integer(1),
                                                           e->values().symbol("periodic")}));
    CHECK(e->find(e->values().symbol(c::axis), std::vector{e->values().symbol("scape-wheel/pallets"), e->values().integer(2),
                                                           e->values().symbol("bounded")}));  // the window
    // Gravity on the pallets by place: one fact per place.
    CHECK(count(*e, c::force_sign_at) == v.places.size());
}

TEST_CASE("bridge/place_facts: one place and one motion; parts, shafts, forces") {
    const auto m = read("scenarios/metric/escapement.def");
    const auto pair = pair_of(m);
    const g::QualDirection motion{{1, -1}};
    auto e = empty_engine();
    bridge::PlaceFactOptions one;
    one.only = g::PlaceId{12};
    one.motion = motion;
    bridge::assert_pair(*e, m, pair, one);
    CHECK(count(*e, c::pair_places) == 0);
    CHECK(count(*e, c::place_kind) == 1);
    std::size_t expected = 0;
    for (const auto& a : pair.vocabulary.adjacency) expected += a.from == g::PlaceId{12} && a.motion == motion;
    CHECK(count(*e, c::adjacent) == expected);
    const std::vector<g::PartId> parts{pair.spec.a, pair.spec.b};
    bridge::assert_parts(*e, m, parts, true);
    CHECK(count(*e, c::clock_object) == 2);
    CHECK(count(*e, c::possible_motions) == 2);
    CHECK(count(*e, c::fixed_part) == 0);
    const auto assumed = bridge::assert_forces(*e, m, parts, bridge::ForceFacts::assumptions, {});
    CHECK(assumed.size() == 2);  // the spring on the wheel, gravity on the pallets
    for (const auto f : assumed) CHECK(e->assumption(f).has_value());
    CHECK(count(*e, c::cause) == 2);
    CHECK(count(*e, c::constant_force) == 1);  // the spring's torque
    const bridge::ForceRef without[] = {{pair.spec.b, std::nullopt}};
    auto e2 = empty_engine();
    CHECK(bridge::assert_forces(*e2, m, parts, bridge::ForceFacts::assumptions, without).size() == 1);
}
