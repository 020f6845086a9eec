// tests/envision/envision_fixture.hpp: a bundled mechanism read, its pairs' place vocabularies
// (cached in the build tree), and the envisioner's laws, for the envisioner's tests.
#pragma once
#include "envision/envisionment.hpp"
#include "bridge/pair_places.hpp"
#include "geometry/metric_scene_parser.hpp"
#include <doctest/doctest.h>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>

namespace qm::envision::testing {

inline std::filesystem::path source(const std::string& relative) { return std::filesystem::path(QM_SOURCE_DIR) / relative; }
inline std::filesystem::path rules_folder() { return source("rules/clock"); }
inline const geometry::PlaceCache& test_cache() {
    static const geometry::PlaceCache cache(std::filesystem::path(QM_BINARY_DIR) / "envision-test-place-cache");
    return cache;
}

inline std::string printed(const Diagnostics& d) {
    std::ostringstream os;
    d.print(os);
    return os.str();
}

inline geometry::Mechanism mechanism(const std::string& relative) {
    Diagnostics d;
    auto m = geometry::read_mechanism_file(source(relative).string(), d);
    REQUIRE_MESSAGE(m.has_value(), printed(d));
    return std::move(*m);
}

inline std::vector<bridge::PairPlaces> pairs_of(const geometry::Mechanism& m) {
    Diagnostics d;
    auto p = bridge::mechanism_places(m, {.cache = &test_cache(), .forces = true}, d);
    REQUIRE_MESSAGE(p.has_value(), printed(d));
    return std::move(*p);
}

inline Envisionment envisioned(const geometry::Mechanism& m, const EnvisionOptions& given = {}) {
    EnvisionOptions o = given;
    if (o.rules.empty()) o.rules = rules_folder();
    if (!o.cache) o.cache = &test_cache();
    Diagnostics d;
    auto e = qm::envision::envision(m, o, d);
    REQUIRE_MESSAGE(e.has_value(), printed(d));
    return std::move(*e);
}

// The envisionment of a bundled mechanism with the default laws, computed once per test program.
inline const Envisionment& envisioned_once(const std::string& relative) {
    static std::map<std::string, std::pair<geometry::Mechanism, Envisionment>> done;
    auto it = done.find(relative);
    if (it == done.end()) {
        auto m = mechanism(relative);
        auto e = envisioned(m);
        it = done.emplace(relative, std::pair{std::move(m), std::move(e)}).first;
    }
    return it->second.second;
}

// The bundled metric mechanisms the envisioner is checked on.
inline const std::vector<std::string>& bundled() {
    static const std::vector<std::string> all{"scenarios/metric/escapement.def", "scenarios/metric/ratchet.def",
                                              "scenarios/metric/scotch_yoke.def", "scenarios/metric/cam.def",
                                              "scenarios/metric/gear_train.def", "scenarios/clock/escapement.def",
                                              "scenarios/clock/ratchet.def", "scenarios/clock/scotch_yoke.def",
                                              "scenarios/clock/cam.def", "scenarios/clock/cam_free.def",
                                              "scenarios/clock/gear_pair.def", "scenarios/clock/gear_train.def",
                                              "tests/envision/scenes/pendulum_stops.def", "tests/envision/scenes/two_chains.def",
                                              "tests/envision/scenes/square_cam.def"};
    return all;
}

// Whether the chain has a transition from a to b (with one of the causes in `cause`, if given).
inline bool has_transition(const ChainEnvisionment& c, StateId a, StateId b, std::uint8_t cause = 0) {
    for (const auto& t : c.transitions)
        if (t.from == a && t.to == b && (cause == 0 || (t.causes & cause) != 0)) return true;
    return false;
}

// Every consecutive pair of a path is a transition.
inline bool path_follows_transitions(const ChainEnvisionment& c, const std::vector<StateId>& path) {
    for (std::size_t k = 1; k < path.size(); ++k)
        if (!has_transition(c, path[k - 1], path[k])) return false;
    return true;
}

// The index of the behavioural cycle holding s, or SIZE_MAX.
inline std::size_t cycle_of(const ChainEnvisionment& c, StateId s) {
    for (std::size_t k = 0; k < c.graph.cycles.size(); ++k)
        for (const StateId x : c.graph.cycles[k])
            if (x == s) return k;
    return SIZE_MAX;
}

}  // namespace qm::envision::testing
