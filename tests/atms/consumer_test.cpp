// tests/atms/consumer_test.cpp: consumers and on_first_label callbacks run exactly once per event,
// only after propagation has finished, and may re-enter the Atms.
#include "atms/consumer.hpp"

#include "atms/atms.hpp"
#include "random_theory.hpp"
#include <doctest/doctest.h>
#include <map>

using namespace qm::atms;
using namespace qm::atms::test;

namespace {
struct Recorder : Consumer {
    const Atms* atms = nullptr;
    std::vector<NodeId> filled;
    std::vector<EnvId> nogoods;
    void label_became_nonempty(NodeId n) override {
        REQUIRE(!atms->label(n).empty());
        filled.push_back(n);
    }
    void environment_became_nogood(EnvId e) override {
        REQUIRE(!atms->is_consistent(e));
        nogoods.push_back(e);
    }
};
}  // namespace

TEST_CASE("atms/consumer: on_first_label runs once, when the label first fills") {
    Atms atms;
    const NodeId a = atms.add_assumption(DatumId{0});
    const NodeId b = atms.add_assumption(DatumId{0});
    const NodeId x = atms.add_node(DatumId{0});
    int calls = 0;
    atms.on_first_label(x, [&](NodeId n) {
        CHECK(n == x);
        ++calls;
    });
    CHECK(calls == 0);
    atms.justify(InformantId{0}, {a}, x);
    CHECK(calls == 1);
    atms.justify(InformantId{0}, {b}, x);
    CHECK(calls == 1);
    // Registered while the label is non-empty: runs before on_first_label returns.
    int late = 0;
    atms.on_first_label(x, [&](NodeId) { ++late; });
    CHECK(late == 1);
    atms.justify(InformantId{0}, {a, b}, x);
    CHECK(calls == 1);
    CHECK(late == 1);
}

TEST_CASE("atms/consumer: callbacks run after propagation and may call justify") {
    Atms atms;
    const NodeId a = atms.add_assumption(DatumId{0});
    const NodeId x = atms.add_node(DatumId{0});
    const NodeId y = atms.add_node(DatumId{0});
    const NodeId z = atms.add_node(DatumId{0});
    atms.justify(InformantId{0}, {x}, y);  // y follows x
    std::vector<std::string> log;
    atms.on_first_label(x, [&](NodeId) {
        // Propagation finished before we run: y already has its label.
        CHECK(atms.label(y).size() == 1);
        log.push_back("x");
        atms.justify(InformantId{1}, {y}, z);  // re-enter: this fills z
        log.push_back("x-done");
    });
    atms.on_first_label(z, [&](NodeId) { log.push_back("z"); });
    atms.justify(InformantId{2}, {a}, x);
    // z's callback is queued during x's callback and runs after it, not inside it.
    CHECK(log == std::vector<std::string>{"x", "x-done", "z"});
}

TEST_CASE("atms/consumer: a label emptied by a nogood keeps its callback waiting") {
    Atms atms;
    const NodeId a = atms.add_assumption(DatumId{0});
    const NodeId b = atms.add_assumption(DatumId{0});
    const NodeId x = atms.add_node(DatumId{0});
    atms.justify(InformantId{0}, {a}, x);
    atms.add_nogood(InformantId{0}, {a});
    CHECK(atms.label(x).empty());
    int calls = 0;
    atms.on_first_label(x, [&](NodeId) { ++calls; });
    CHECK(calls == 0);
    atms.justify(InformantId{0}, {b}, x);
    CHECK(calls == 1);
}

TEST_CASE("atms/consumer: events on random theories: fills are transitions, nogoods are minimal") {
    for (std::uint32_t seed = 1; seed <= 200; ++seed) {
        CAPTURE(seed);
        RandomTheory t(seed, 6, 12, 25);
        Recorder rec;
        rec.atms = &t.atms;
        t.atms.add_consumer(rec);
        std::map<std::uint32_t, int> calls;
        for (std::uint32_t n = 0; n < t.atms.node_count(); ++n)
            if (NodeId{n} != t.atms.contradiction())
                t.atms.on_first_label(NodeId{n}, [&calls](NodeId m) { ++calls[m.value]; });
        std::vector<bool> was_nonempty(t.atms.node_count());
        for (std::uint32_t n = 0; n < t.atms.node_count(); ++n) was_nonempty[n] = !t.atms.label(NodeId{n}).empty();
        while (true) {
            rec.filled.clear();
            if (!t.add_next()) break;
            for (NodeId n : rec.filled) CHECK_FALSE(was_nonempty[n.value]);  // a real transition
            for (std::uint32_t n = 0; n < t.atms.node_count(); ++n) {
                const bool now = !t.atms.label(NodeId{n}).empty();
                const bool announced = std::find(rec.filled.begin(), rec.filled.end(), NodeId{n}) != rec.filled.end();
                if (now && !was_nonempty[n]) CHECK(announced);
                was_nonempty[n] = now;
            }
        }
        for (std::uint32_t n = 0; n < t.atms.node_count(); ++n) {
            CHECK(calls[n] <= 1);  // exactly once at most
            if (!t.atms.label(NodeId{n}).empty()) CHECK(calls[n] == 1);
        }
        // Every minimal nogood was announced; every announced env is nogood.
        for (EnvId g : t.atms.minimal_nogoods())
            CHECK(std::find(rec.nogoods.begin(), rec.nogoods.end(), g) != rec.nogoods.end());
        t.atms.remove_consumer(rec);
    }
}

TEST_CASE("atms/consumer: registration errors") {
    Atms atms;
    Recorder rec;
    rec.atms = &atms;
    atms.add_consumer(rec);
    CHECK_THROWS_AS(atms.add_consumer(rec), qm::InternalError);
    atms.remove_consumer(rec);
    CHECK_THROWS_AS(atms.remove_consumer(rec), qm::InternalError);
    CHECK_THROWS_AS(atms.on_first_label(atms.contradiction(), [](NodeId) {}), qm::InternalError);
    CHECK_THROWS_AS(atms.on_first_label(NodeId{99}, [](NodeId) {}), qm::InternalError);
    CHECK_THROWS_AS(atms.on_first_label(atms.add_node(DatumId{0}), nullptr), qm::InternalError);
}
