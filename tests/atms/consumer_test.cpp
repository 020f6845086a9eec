// tests/atms/consumer_test.cpp: consumers and on_first_label callbacks run exactly once per event,
// only after propagation has finished, and may re-enter the Atms.
#include "atms/consumer.hpp"

#include "atms/atms.hpp"
#include "random_theory.hpp"
#include <doctest/doctest.h>
#include <map>
#include <stdexcept>

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

TEST_CASE("atms/consumer: events on random theories: fills are announced, callbacks run once, nogoods are minimal") {
    for (std::uint32_t seed = 1; seed <= 300; ++seed) {
        CAPTURE(seed);
        TheoryShape shape{6, 12, 25, seed % 2 == 0, 0};
        RandomTheory t(seed, shape);
        Recorder rec;
        rec.atms = &t.atms;
        t.atms.add_consumer(rec);
        std::vector<int> calls;
        std::vector<bool> ever_in;      // the label was non-empty after some call returned
        std::vector<bool> was_nonempty;  // ... after the previous step
        // on_first_label for every node, registered as soon as the node exists. A callback must
        // find its node holding in some consistent environment when it runs.
        auto register_new = [&] {
            for (auto n = static_cast<std::uint32_t>(calls.size()); n < t.atms.node_count(); ++n) {
                const bool in = !t.atms.label(NodeId{n}).empty();
                calls.push_back(0);
                ever_in.push_back(in);
                was_nonempty.push_back(in);
                if (NodeId{n} == t.atms.contradiction()) continue;
                t.atms.on_first_label(NodeId{n}, [&calls, &t](NodeId m) {
                    CHECK_FALSE(t.atms.label(m).empty());
                    ++calls[m.value];
                });
            }
        };
        register_new();
        while (true) {
            rec.filled.clear();
            const std::size_t before = t.atms.node_count();
            if (!t.add_next()) break;
            // An announced node holds now (Recorder checks it at delivery). It need not have been
            // empty before the step: a nogood may empty a label and the same propagation refill
            // it, a transition consumer.hpp says is announced too.
            for (NodeId n : rec.filled) CHECK_FALSE(t.atms.label(n).empty());
            register_new();
            for (std::uint32_t n = 0; n < t.atms.node_count(); ++n) {
                const bool now = !t.atms.label(NodeId{n}).empty();
                const bool announced = std::find(rec.filled.begin(), rec.filled.end(), NodeId{n}) != rec.filled.end();
                if (now && (n >= before || !was_nonempty[n])) CHECK(announced);
                was_nonempty[n] = now;
                if (now) ever_in[n] = true;
                // Exactly once, and by the time the node was first seen in: never before, never again.
                CHECK(calls[n] == (ever_in[n] ? 1 : 0));
            }
        }
        // Every minimal nogood was announced; every announced env is nogood.
        for (EnvId g : t.atms.minimal_nogoods())
            CHECK(std::find(rec.nogoods.begin(), rec.nogoods.end(), g) != rec.nogoods.end());
        for (EnvId g : rec.nogoods) CHECK_FALSE(t.atms.is_consistent(g));
        t.atms.remove_consumer(rec);
    }
}

TEST_CASE("atms/consumer: a callback registered on a filled label that empties before delivery waits") {
    Atms atms;
    const NodeId a = atms.add_assumption(DatumId{0});
    const NodeId b = atms.add_assumption(DatumId{0});
    const NodeId x = atms.add_node(DatumId{0});
    const NodeId trigger = atms.add_node(DatumId{0});
    atms.justify(InformantId{0}, {a}, x);
    int calls = 0;
    atms.on_first_label(trigger, [&](NodeId) {
        // x holds now, so this callback is queued; the nogood below empties x before it is
        // delivered, and then x does not hold in any consistent environment.
        atms.on_first_label(x, [&](NodeId n) {
            CHECK_FALSE(atms.label(n).empty());
            ++calls;
        });
        atms.add_nogood(InformantId{1}, {a});
    });
    atms.justify(InformantId{2}, {b}, trigger);
    CHECK(atms.label(x).empty());
    CHECK(calls == 0);
    atms.justify(InformantId{3}, {b}, x);
    CHECK(calls == 1);
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

TEST_CASE("atms/consumer: a consumer removed by another's callback gets no more events") {
    // The consumer list is snapshotted per event; one removed (and destroyed) meanwhile must be
    // skipped, not called through a dangling pointer.
    Atms atms;
    const NodeId a = atms.add_assumption(DatumId{0});
    const NodeId x = atms.add_node(DatumId{0});
    Recorder second;
    second.atms = &atms;
    struct Remover : Consumer {
        Atms* atms = nullptr;
        Consumer* victim = nullptr;
        void label_became_nonempty(NodeId) override {
            if (victim) atms->remove_consumer(*victim);
            victim = nullptr;
        }
        void environment_became_nogood(EnvId) override {}
    } first;
    first.atms = &atms;
    first.victim = &second;
    atms.add_consumer(first);
    atms.add_consumer(second);
    atms.justify(InformantId{0}, {a}, x);
    CHECK(second.filled.empty());
}

TEST_CASE("atms/consumer: a throwing on_first_label callback loses none of the others") {
    Atms atms;
    const NodeId a = atms.add_assumption(DatumId{0});
    const NodeId x = atms.add_node(DatumId{0});
    std::vector<int> ran;
    atms.on_first_label(x, [&](NodeId) { ran.push_back(1); });
    atms.on_first_label(x, [&](NodeId) {
        ran.push_back(2);
        throw std::runtime_error("callback failed");
    });
    atms.on_first_label(x, [&](NodeId) { ran.push_back(3); });
    CHECK_THROWS_AS(atms.justify(InformantId{0}, {a}, x), std::runtime_error);
    CHECK(ran == std::vector<int>{1, 2});
    const NodeId b = atms.add_assumption(DatumId{0});  // any later call delivers the rest, once
    (void)b;
    atms.justify(InformantId{0}, {b}, x);
    CHECK(ran == std::vector<int>{1, 2, 3});
}
