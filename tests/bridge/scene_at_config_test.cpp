// tests/bridge/scene_at_config_test.cpp: the contacts half of the bridge (bridge/scene_at_config.hpp):
// the scene model built directly from the geometry is a checked scene (printing it and reading it
// back gives it again, on every bundled metric scene at many configurations), it holds exactly the
// contacts the geometry detects, each item is located in the metric scene, and bad input is an error.
#include "bridge/scene_at_config.hpp"

#include "geometry/contact_detection.hpp"
#include "geometry/kinematic_pairs.hpp"
#include "geometry/metric_scene_parser.hpp"
#include "scene/scene_parser.hpp"
#include "scene/scene_printer.hpp"

#include <doctest/doctest.h>
#include <filesystem>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace g = qm::geometry;
namespace s = qm::scene;

std::vector<std::string> bundled_metric_scenes() {
    std::vector<std::string> out;
    for (const char* dir : {"scenarios/metric", "scenarios/clock"})
        for (const auto& e : std::filesystem::directory_iterator(std::string(QM_SOURCE_DIR) + "/" + dir))
            if (e.path().extension() == ".def") out.push_back(e.path().string());
    std::sort(out.begin(), out.end());
    return out;
}

g::Mechanism read_metric(const std::string& path) {
    qm::Diagnostics d;
    auto m = g::read_mechanism_file(path, d);
    std::ostringstream os;
    d.print(os);
    INFO(os.str());
    REQUIRE(m);
    return std::move(*m);
}

// The scene read back from its printed text.
std::optional<s::Scene> read_back(const s::Scene& scene, std::string& errors) {
    qm::Diagnostics d;
    auto again = s::read_scene("printed", s::print_scene(scene), d);
    std::ostringstream os;
    d.print(os);
    errors = os.str();
    return again;
}

// The invariants of scene/scene.hpp that the checker establishes.
void check_invariants(const s::Scene& scene) {
    bool corners = false;
    for (const s::Surface& f : scene.surfaces) {
        if (f.is_corner()) corners = true;
        else CHECK_FALSE(corners);  // faces before corners
    }
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i)
        for (s::SurfaceId id : scene.objects[s::ObjectId{i}].surfaces) CHECK(scene.surfaces[id].object == s::ObjectId{i});
}

// Configurations that put one pair's parts in contact: a coordinate of its first part, then the
// second part turned or slid (bisection on the pair's FCL distance) until they touch; the other
// parts stay as drawn (where they may overlap: a clock's gears are drawn unmeshed).
std::vector<g::Configuration> touching_configurations(const g::Mechanism& m, const g::PairSpec& pair, int count, std::mt19937& rng) {
    std::vector<g::Configuration> out;
    const g::Configuration drawn{std::vector<double>(m.parts.size(), 0.0)};
    const auto oracle = g::pair_oracle(m, pair);
    const auto request = g::place_request(m, pair);
    const auto& ax = request.cspace.axes;
    std::uniform_real_distribution<double> u0(ax[0].lo, ax[0].hi), u1(ax[1].lo, ax[1].hi);
    for (int k = 0; k < count * 50 && static_cast<int>(out.size()) < count; ++k) {
        Eigen::Vector2d free{u0(rng), u1(rng)}, blocked{free[0], u1(rng)};
        if (oracle->blocked(free) || !oracle->blocked(blocked)) continue;
        for (int i = 0; i < 60; ++i) {
            const Eigen::Vector2d mid = (free + blocked) / 2;
            (oracle->blocked(mid) ? blocked : free) = mid;
        }
        g::Configuration q = drawn;
        for (std::uint32_t p = 0; p < m.parts.size(); ++p) {
            if (m.same_shaft(g::PartId{p}, pair.a)) q.q[p] = free[0];
            if (m.same_shaft(g::PartId{p}, pair.b)) q.q[p] = free[1];
        }
        out.push_back(q);
    }
    return out;
}

}  // namespace

TEST_CASE("bridge/scene_at_config: every bundled metric scene, as drawn and touching, reads back from its printed text") {
    std::mt19937 rng(14);
    int scenes = 0, with_contacts = 0, with_corners = 0;
    for (const std::string& path : bundled_metric_scenes()) {
        CAPTURE(path);
        const g::Mechanism m = read_metric(path);
        // Every pair as drawn, and each pair alone at configurations where it touches.
        std::vector<std::pair<qm::bridge::SceneAtConfig, g::Configuration>> cases;
        cases.emplace_back(qm::bridge::SceneAtConfig(m), g::Configuration{std::vector<double>(m.parts.size(), 0.0)});
        for (const g::PairSpec& pair : g::kinematic_pairs(m).modelled)
            for (g::Configuration& q : touching_configurations(m, pair, 2, rng)) cases.emplace_back(qm::bridge::SceneAtConfig(m, {pair}), std::move(q));
        for (const auto& [at, q] : cases) {
            qm::Diagnostics d;
            const auto scene = at.at(q, d);
            if (!scene) continue;  // parts overlapping by more than the tolerance (as drawn, or at a bisected point)
            ++scenes;
            check_invariants(*scene);
            std::string errors;
            const auto again = read_back(*scene, errors);
            INFO(errors, s::print_scene(*scene));
            REQUIRE(again);
            CHECK(*again == *scene);
            if (!scene->situations.front().contacts.empty()) ++with_contacts;
            for (const s::Surface& f : scene->surfaces) with_corners += f.is_corner();
        }
    }
    CHECK(scenes > 40);
    CHECK(with_contacts > 20);
    CHECK(with_corners > 0);
}

TEST_CASE("bridge/scene_at_config: the contacts are the geometry's, once each, between the pair's objects") {
    const g::Mechanism m = read_metric(std::string(QM_SOURCE_DIR) + "/scenarios/metric/escapement.def");
    qm::Diagnostics cd;
    const auto q = g::parse_configuration(m, "scape-wheel=12.0983, pallets=-1.2840", cd);
    REQUIRE(q);
    qm::Diagnostics d;
    const auto scene = qm::bridge::scene_at_config(m, *q, d);
    REQUIRE(scene);
    CHECK(d.items().empty());
    const auto pair = g::kinematic_pairs(m).modelled.front();
    const auto r = g::detect_contacts(*g::pair_oracle(m, pair), {q->at(pair.a), q->at(pair.b)},
                                      {m.settings.contact_tolerance, m.settings.normal_zero_tolerance});
    REQUIRE(r.contacts.size() == 1);
    REQUIRE(scene->situations.front().contacts.size() == 1);
    const s::Contact& c = scene->situations.front().contacts.front();
    CHECK(scene->objects[scene->surfaces[c.first].object].name == "scape-wheel");
    CHECK(scene->objects[scene->surfaces[c.second].object].name == "pallets");
    CHECK(scene->surfaces[c.first].is_corner() == (r.contacts.front().first.kind == g::FeatureKind::corner));
    // Located in the metric scene: the contact at the pair, the objects at their parts, the forces
    // at their declarations.
    CHECK(c.where == pair.where);
    CHECK(scene->objects[s::ObjectId{0}].where == m.part_where[0]);
    REQUIRE(scene->situations.front().forces.size() == 2);
    CHECK(scene->situations.front().forces[0].where == m.forces[0].where);
    CHECK(c.where.file == m.where.file);
}

TEST_CASE("bridge/scene_at_config: SceneAtConfig takes only the pairs it is given") {
    const g::Mechanism m = read_metric(std::string(QM_SOURCE_DIR) + "/scenarios/metric/gear_train.def");
    qm::Diagnostics cd;
    const auto q = g::parse_configuration(m, "gear-1=1.0875, gear-3=-0.8586", cd);
    REQUIRE(q);
    const auto pairs = g::kinematic_pairs(m).modelled;
    REQUIRE(pairs.size() == 2);
    qm::Diagnostics d;
    const auto all = qm::bridge::scene_at_config(m, *q, d);
    REQUIRE(all);
    std::set<std::string> objects_in_contact;
    for (const auto& c : all->situations.front().contacts)
        for (s::SurfaceId id : {c.first, c.second}) objects_in_contact.insert(all->objects[all->surfaces[id].object].name);
    CHECK(objects_in_contact == std::set<std::string>{"gear-1", "gear-2", "gear-3"});
    const auto one = qm::bridge::SceneAtConfig(m, {pairs.front()}).at(*q, d);
    REQUIRE(one);
    CHECK_FALSE(one->situations.front().contacts.empty());
    for (const auto& c : one->situations.front().contacts)
        for (s::SurfaceId id : {c.first, c.second}) CHECK(one->objects[one->surfaces[id].object].name != "gear-3");
    CHECK(one->objects.size() == all->objects.size());  // every part is still an object
}

TEST_CASE("bridge/scene_at_config: parts overlapping at the configuration are an error at the pair, the CONFIG printable") {
    qm::Diagnostics d;
    const auto scene = qm::bridge::read_scene_at_config(std::string(QM_SOURCE_DIR) + "/scenarios/metric/cam.def", "cam=30,\nfollower=0", d);
    CHECK_FALSE(scene);
    REQUIRE(d.items().size() == 1);
    CHECK(d.items()[0].where.line == 8);
    CHECK(d.items()[0].message.find("overlap at this configuration") != std::string::npos);
    CHECK(d.items()[0].message.find("(CONFIG 'cam=30,\\nfollower=0')") != std::string::npos);
    qm::Diagnostics bad;
    CHECK_FALSE(qm::bridge::read_scene_at_config(std::string(QM_SOURCE_DIR) + "/scenarios/metric/cam.def", "wheel=2", bad));
    CHECK(bad.has_errors());
    qm::Diagnostics missing;
    CHECK_FALSE(qm::bridge::read_scene_at_config(std::string(QM_BINARY_DIR) + "/no-such-scene.def", "", missing));
    CHECK(missing.has_errors());
}
