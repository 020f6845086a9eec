// tests/atms/consumer_test.cpp: consumers hear of every label that fills and every minimal nogood,
// only after propagation has finished, and may re-enter the Atms.
#include "atms/consumer.hpp"

#include "atms/atms.hpp"
#include "random_theory.hpp"
#include <algorithm>
#include <doctest/doctest.h>
#include <string>
#include <vector>

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

TEST_CASE("atms/consumer: events come after propagation, and a consumer may call justify") {
    Atms atms;
    const NodeId a = atms.add_assumption(DatumId{0});
    const NodeId x = atms.add_node(DatumId{0});
    const NodeId y = atms.add_node(DatumId{0});
    const NodeId z = atms.add_node(DatumId{0});
    atms.justify(InformantId{0}, {x}, y);  // y follows x
    struct Chain : Consumer {
        Atms* atms = nullptr;
        NodeId x, y, z;
        std::vector<std::string> log;
        void label_became_nonempty(NodeId n) override {
            if (n == y) log.push_back("y");
            if (n == z) log.push_back("z");
            if (n != x) return;
            // Propagation finished before we run: y already has its label.
            CHECK(atms->label(y).size() == 1);
            log.push_back("x");
            atms->justify(InformantId{1}, {y}, z);  // re-enter: this fills z
            log.push_back("x-done");
        }
    } chain;
    chain.atms = &atms;
    chain.x = x;
    chain.y = y;
    chain.z = z;
    atms.add_consumer(chain);
    atms.justify(InformantId{2}, {a}, x);
    // z's event is queued during x's and delivered after it, not inside it.
    CHECK(chain.log == std::vector<std::string>{"x", "x-done", "y", "z"});
}

TEST_CASE("atms/consumer: events on random theories: fills are announced, nogoods are minimal") {
    for (std::uint32_t seed = 1; seed <= 300; ++seed) {
        CAPTURE(seed);
        TheoryShape shape{6, 12, 25, seed % 2 == 0, 0};
        RandomTheory t(seed, shape);
        Recorder rec;
        rec.atms = &t.atms;
        t.atms.add_consumer(rec);
        std::vector<bool> was_nonempty;  // after the previous step
        for (std::uint32_t n = 0; n < t.atms.node_count(); ++n) was_nonempty.push_back(!t.atms.label(NodeId{n}).empty());
        while (true) {
            rec.filled.clear();
            const std::size_t before = t.atms.node_count();
            if (!t.add_next()) break;
            // An announced node holds now (Recorder checks it at delivery). It need not have been
            // empty before the step: a nogood may empty a label and the same propagation refill
            // it, a transition consumer.hpp says is announced too.
            for (NodeId n : rec.filled) CHECK_FALSE(t.atms.label(n).empty());
            was_nonempty.resize(t.atms.node_count(), false);
            for (std::uint32_t n = 0; n < t.atms.node_count(); ++n) {
                const bool now = !t.atms.label(NodeId{n}).empty();
                const bool announced = std::find(rec.filled.begin(), rec.filled.end(), NodeId{n}) != rec.filled.end();
                if (now && (n >= before || !was_nonempty[n])) CHECK(announced);
                was_nonempty[n] = now;
            }
        }
        // Every minimal nogood was announced; every announced env is nogood.
        for (EnvId g : t.atms.minimal_nogoods())
            CHECK(std::find(rec.nogoods.begin(), rec.nogoods.end(), g) != rec.nogoods.end());
        for (EnvId g : rec.nogoods) CHECK_FALSE(t.atms.is_consistent(g));
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
