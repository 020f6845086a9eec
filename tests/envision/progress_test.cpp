// tests/envision/progress_test.cpp: what the envisioner reports while it works
// (envision/progress.hpp): each phase of each chain opens and closes with a report, the closing
// counts are the chain's own, every report comes from the calling thread, and the state limit over
// all chains stops the run with qm::LimitReached after a report of exactly the states found.
#include "envision_fixture.hpp"
#include "qm/limit_reached.hpp"
#include <thread>
#include <vector>

using namespace qm::envision;
using namespace qm::envision::testing;

namespace {

struct ProgressLog {
    std::vector<Progress> reports;
    bool other_thread = false;
};

EnvisionOptions options_logging_to(ProgressLog& log) {
    EnvisionOptions o;
    o.rules = rules_folder();
    o.cache = &test_cache();
    o.threads = 2;
    o.progress = [&log, caller = std::this_thread::get_id()](const Progress& p) {
        log.reports.push_back(p);
        log.other_thread = log.other_thread || std::this_thread::get_id() != caller;
    };
    return o;
}

// The reports of one phase of one chain.
std::vector<Progress> reports_of(const ProgressLog& log, Progress::Phase phase, std::size_t chain) {
    std::vector<Progress> out;
    for (const auto& p : log.reports)
        if (p.phase == phase && p.chain == chain) out.push_back(p);
    return out;
}

}  // namespace

TEST_CASE("envision/progress: every phase of every chain opens with nothing found and closes with the chain's counts") {
    // escapement: one chain of 1378 states, enough for reports in between; two_chains: two chains.
    for (const std::string file : {"scenarios/clock/escapement.def", "tests/envision/scenes/two_chains.def"}) {
        CAPTURE(file);
        const auto m = mechanism(file);
        ProgressLog log;
        Diagnostics d;
        const auto e = qm::envision::envision(m, options_logging_to(log), d);
        REQUIRE_MESSAGE(e.has_value(), printed(d));
        REQUIRE_FALSE(log.reports.empty());
        CHECK(log.reports.front().phase == Progress::Phase::places);
        CHECK_FALSE(log.other_thread);
        for (const auto& c : e->chains) {
            const std::size_t chain = c.chain.index + 1;
            CAPTURE(chain);
            const auto states = reports_of(log, Progress::Phase::states, chain);
            REQUIRE(states.size() >= 2);
            CHECK(states.front().states == 0);
            CHECK(states.back().states == c.states.size());
            const auto transitions = reports_of(log, Progress::Phase::transitions, chain);
            REQUIRE(transitions.size() >= 2);
            CHECK(transitions.front().done == 0);
            CHECK(transitions.front().transitions == 0);
            CHECK(transitions.back().done == c.states.size());
            CHECK(transitions.back().transitions == c.transitions.size());
            for (std::size_t i = 1; i < transitions.size(); ++i) {
                CHECK(transitions[i].states == c.states.size());
                CHECK(transitions[i].done >= transitions[i - 1].done);
                CHECK(transitions[i].transitions >= transitions[i - 1].transitions);
            }
        }
        if (file.ends_with("escapement.def")) CHECK(reports_of(log, Progress::Phase::transitions, 1).size() > 2);
    }
}

TEST_CASE("envision/progress: the state limit counts all chains and stops with a report of the states found") {
    // two_chains: chain 1 (a gear pair) has 3 states, chain 2 (the cam) 138.
    const auto m = mechanism("tests/envision/scenes/two_chains.def");
    for (const std::size_t limit : {std::size_t{10}, std::size_t{140}}) {
        CAPTURE(limit);
        ProgressLog log;
        EnvisionOptions o = options_logging_to(log);
        o.max_states = limit;
        Diagnostics d;
        try {
            (void)qm::envision::envision(m, o, d);
            FAIL("no limit reached");
        } catch (const qm::LimitReached& reached) {
            CHECK(reached.kind == qm::LimitReached::Kind::states);
            CHECK(reached.limit == limit);
        }
        REQUIRE_FALSE(log.reports.empty());
        const Progress& last = log.reports.back();
        CHECK(last.phase == Progress::Phase::states);
        CHECK(last.chain == 2);
        CHECK(last.states == limit - 3);
        CHECK(reports_of(log, Progress::Phase::transitions, 1).back().transitions == 4);
    }
    ProgressLog log;
    EnvisionOptions o = options_logging_to(log);
    o.max_states = 141;  // exactly the states there are
    Diagnostics d;
    const auto e = qm::envision::envision(m, o, d);
    REQUIRE_MESSAGE(e.has_value(), printed(d));
    CHECK(e->chains.size() == 2);
}
