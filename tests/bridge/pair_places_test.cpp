// tests/bridge/pair_places_test.cpp: bridge/pair_places.hpp, the one place-vocabulary service: a
// vocabulary computed once is served from the cache (under the key of the pair's oracle, built
// only when needed) with the same place ids; the sampled space and the oracle when asked for;
// mechanism_places() gives every pair the ids pair_places() gives it, with its forces by place;
// parts that overlap as drawn are refused with the error `--emit-def` gives; the cache folder and
// a pair named `A--B`.
#include "bridge/pair_places.hpp"
#include "bridge/scene_at_config.hpp"
#include "geometry/fcl_pair_oracle.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"
#include <doctest/doctest.h>
#include <cstdlib>
#include <filesystem>
#include <sstream>

using namespace qm;
namespace g = qm::geometry;
namespace fs = std::filesystem;

namespace {

const char* const cam_text =
    "(Defmechanism cam\n"
    "  Settings ((grid 64 64))\n"
    "  Parts ((cam (disk-cam (radius 0.5) (eccentricity 0.2)) (rotation))\n"
    "         (follower (follower (width 2) (height 0.5)) (at 0 FOLLOWER) (translation (0 1) (limits -0.3 0.5))))\n"
    "  Pairs ((cam follower))\n"
    "  Forces ((motor cam (torque +)) (gravity follower (direction 0 -1))))\n";

// The cam and follower of scenarios/metric/cam.def with the follower drawn at height y.
g::Mechanism cam(const std::string& y) {
    std::string text = cam_text;
    text.replace(text.find("FOLLOWER"), 8, y);
    Diagnostics d;
    auto m = g::read_mechanism("cam.def", text, d);
    REQUIRE(m.has_value());
    return std::move(*m);
}

std::string diagnostics_text(const Diagnostics& d) {
    std::ostringstream os;
    d.print(os);
    return os.str();
}

g::PlaceCache fresh_cache(const std::string& name) {
    const fs::path dir = fs::path(QM_BINARY_DIR) / "pair-places-test" / name;
    fs::remove_all(dir);
    return g::PlaceCache(dir);
}

bool same_places(const g::PlaceVocabulary& a, const g::PlaceVocabulary& b) {
    if (a.places.size() != b.places.size() || a.adjacency != b.adjacency) return false;
    for (std::size_t i = 0; i < a.places.size(); ++i)
        if (a.places[i].kind != b.places[i].kind || a.places[i].normals != b.places[i].normals) return false;
    return true;
}

}  // namespace

TEST_CASE("bridge/pair_places: computed once, then served from the cache with the same ids, without the oracle") {
    const auto m = cam("0.5");
    const auto spec = g::kinematic_pairs(m).modelled.at(0);
    const auto cache = fresh_cache("served");
    Diagnostics d;
    const auto first = bridge::pair_places(m, spec, {.cache = &cache}, d);
    REQUIRE_MESSAGE(first.has_value(), diagnostics_text(d));
    CHECK(!first->from_cache);
    CHECK(first->name == "cam/follower");
    // Stored under the key of the pair's oracle, though none was kept.
    CHECK(first->oracle == nullptr);
    CHECK(fs::exists(cache.path_for(g::place_cache_material(*g::pair_oracle(m, spec), first->request))));
    const auto again = bridge::pair_places(m, spec, {.cache = &cache}, d);
    REQUIRE(again.has_value());
    CHECK(again->from_cache);
    CHECK(again->oracle == nullptr);
    CHECK(same_places(first->vocabulary, again->vocabulary));
    CHECK(d.items().empty());
    // Without a cache: computed, the same.
    const auto uncached = bridge::pair_places(m, spec, {}, d);
    REQUIRE(uncached.has_value());
    CHECK(!uncached->from_cache);
    CHECK(same_places(uncached->vocabulary, first->vocabulary));
}

TEST_CASE("bridge/pair_places: the sampled space is computed even when cached; the oracle and forces when asked") {
    const auto m = cam("0.5");
    const auto spec = g::kinematic_pairs(m).modelled.at(0);
    const auto cache = fresh_cache("space");
    Diagnostics d;
    REQUIRE(bridge::pair_places(m, spec, {.cache = &cache}, d).has_value());
    const auto pictured = bridge::pair_places(m, spec, {.cache = &cache, .space = true, .oracle = true, .forces = true}, d);
    REQUIRE(pictured.has_value());
    CHECK(!pictured->from_cache);
    CHECK(pictured->space.has_value());
    REQUIRE(pictured->oracle != nullptr);
    CHECK(pictured->oracle->fingerprint() == g::pair_fingerprint(m, spec));
    CHECK(pictured->forces.by_place.size() == pictured->vocabulary.places.size());
    CHECK(d.items().empty());
}

TEST_CASE("bridge/pair_places: mechanism_places gives each pair the ids pair_places gives it") {
    const auto m = cam("0.5");
    const auto cache = fresh_cache("mechanism");
    Diagnostics d;
    const auto all = bridge::mechanism_places(m, {.cache = &cache, .forces = true}, d);
    REQUIRE_MESSAGE(all.has_value(), diagnostics_text(d));
    const auto modelled = g::kinematic_pairs(m).modelled;
    REQUIRE(all->size() == modelled.size());
    for (std::size_t k = 0; k < modelled.size(); ++k) {
        const auto one = bridge::pair_places(m, modelled[k], {}, d);
        REQUIRE(one.has_value());
        CHECK(same_places((*all)[k].vocabulary, one->vocabulary));
        CHECK((*all)[k].forces.by_place.size() == one->vocabulary.places.size());
    }
}

TEST_CASE("bridge/pair_places: parts that overlap as drawn are refused as --emit-def refuses them") {
    const auto m = cam("0.3");  // the follower 0.2 inside the cam
    const auto spec = g::kinematic_pairs(m).modelled.at(0);
    Diagnostics emitted;
    CHECK(!bridge::scene_at_config(m, g::Configuration{std::vector<double>(m.parts.size(), 0.0)}, emitted).has_value());
    for (const bool cached : {false, true}) {
        const auto cache = fresh_cache("overlap");
        Diagnostics d;
        CHECK(!bridge::pair_places(m, spec, {.cache = cached ? &cache : nullptr}, d).has_value());
        CHECK(diagnostics_text(d) == diagnostics_text(emitted));
        Diagnostics all;
        CHECK(!bridge::mechanism_places(m, {.cache = cached ? &cache : nullptr}, all).has_value());
        CHECK(diagnostics_text(all) == diagnostics_text(emitted));
    }
    CHECK(diagnostics_text(emitted).find("cam.def:5:10: error: 'cam' and 'follower' overlap at this configuration by more than the contact "
                                "tolerance") != std::string::npos);
    CHECK(diagnostics_text(emitted).find("(as drawn)") != std::string::npos);
}

TEST_CASE("bridge/pair_places: the cache folder and a pair named A--B") {
    const auto m = cam("0.5");
    CHECK(bridge::find_pair(m, "cam--follower").has_value());
    CHECK(!bridge::find_pair(m, "follower--cam").has_value());
    CHECK(!bridge::open_place_cache(false, fs::path("/tmp")).has_value());
    CHECK(bridge::open_place_cache(true, fs::path("/tmp/x"))->directory() == fs::path("/tmp/x"));
    ::setenv("QM_PLACE_CACHE", "/tmp/qm-cache", 1);
    CHECK(bridge::default_place_cache() == fs::path("/tmp/qm-cache"));
    ::unsetenv("QM_PLACE_CACHE");
    const auto svg = bridge::cspace_svg_options(m, g::kinematic_pairs(m).modelled.at(0), 720, 540);
    CHECK(svg.title == "cam: cam (across) x follower (up)");
    CHECK(svg.axes[0].unit == g::AxisUnit::degrees);
    CHECK(svg.axes[1].unit == g::AxisUnit::length);
}
