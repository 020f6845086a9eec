// tests/envision/envisionment_test.cpp: the envisioner (envision/envisionment.hpp) on every bundled
// metric mechanism against the independent checker (envision_checker.hpp, written from the thesis
// and docs/LAWS.md without the rule files): the states equal the brute-force product of places and
// motions filtered by Law 2, linkage, fixed parts and Def 34; the transitions out of every state
// equal the checker's recomputation; and every transition obeys the adjacency, Laws 3-4, Table 5.1
// and the collision law as stated directly.
#include "envision/json_printer.hpp"
#include "envision_checker.hpp"
#include "envision_fixture.hpp"

using namespace qm;
using namespace qm::envision;
using namespace qm::envision::testing;
namespace g = qm::geometry;

namespace {

checker::Key key_of(const State& s) {
    checker::Key k;
    for (const auto p : s.places) k.places.push_back(p.value);
    k.motions = s.motions;
    return k;
}

std::string text_of(const checker::Key& k) {
    std::string out;
    for (const auto p : k.places) out += std::to_string(p) + " ";
    for (const auto m : k.motions) out += m > 0 ? "+" : m < 0 ? "-" : "0";
    return out;
}

}  // namespace

TEST_CASE("envision/envisionment: states are the brute-force product filtered by the thesis' constraints") {
    for (const auto& file : bundled()) {
        CAPTURE(file);
        const auto m = mechanism(file);
        const auto& e = envisioned_once(file);
        for (const auto& c : e.chains) {
            const checker::Checker check(m, e.pairs, c.chain);
            const auto expected = check.states();
            std::set<checker::Key> got;
            for (const State& s : c.states.states()) got.insert(key_of(s));
            CHECK(got.size() == c.states.size());  // no state twice
            CHECK(got == expected);
            MESSAGE(file << " chain " << c.chain.index + 1 << ": " << got.size() << " states");
        }
    }
}

TEST_CASE("envision/envisionment: transitions equal the independent checker's, state by state") {
    for (const auto& file : bundled()) {
        CAPTURE(file);
        const auto m = mechanism(file);
        const auto& e = envisioned_once(file);
        for (const auto& c : e.chains) {
            const checker::Checker check(m, e.pairs, c.chain);
            const auto all = check.states();
            std::size_t edges = 0;
            for (std::uint32_t i = 0; i < c.states.size(); ++i) {
                const State& s = c.states[StateId{i}];
                const auto k = key_of(s);
                CAPTURE(text_of(k));
                CHECK(s.net_force == check.net_force(k));
                std::set<checker::Edge> got;
                for (const auto& t : c.transitions)
                    if (t.from.value == i) got.insert({key_of(c.states[t.to]), t.duration == Duration::instant, t.causes});
                const auto expected = check.successors(k, all);
                for (const auto& x : expected)
                    if (!got.count(x)) FAIL_CHECK("missing transition to " << text_of(x.to) << (x.instant ? " (instant)" : " (interval)") << " causes " << int(x.causes));
                for (const auto& x : got)
                    if (!expected.count(x)) FAIL_CHECK("extra transition to " << text_of(x.to) << (x.instant ? " (instant)" : " (interval)") << " causes " << int(x.causes));
                edges += got.size();
            }
            CHECK(edges == c.transitions.size());
            MESSAGE(file << ": " << c.states.size() << " states, " << c.transitions.size() << " transitions, " << c.graph.cycles.size()
                         << " cycles, " << c.graph.terminal.size() << " terminal");
        }
    }
}

TEST_CASE("envision/envisionment: every transition follows the adjacency and Laws 3-4") {
    for (const auto& file : bundled()) {
        CAPTURE(file);
        const auto m = mechanism(file);
        const auto& e = envisioned_once(file);
        for (const auto& c : e.chains) {
            for (const auto& t : c.transitions) {
                const State& from = c.states[t.from];
                const State& to = c.states[t.to];
                bool moved = false;
                for (std::size_t k = 0; k < c.chain.pairs.size(); ++k) {
                    const auto& pair = e.pairs[c.chain.pairs[k]];
                    if (from.places[k] == to.places[k]) continue;
                    moved = true;
                    const g::QualDirection v{{from.motions[c.chain.object_index(pair.spec.a)], from.motions[c.chain.object_index(pair.spec.b)]}};
                    // 8.1.3: the next place is adjacent under the motion, and the transition lasts an
                    // instant exactly when the place has no width in that motion (Law 3).
                    const auto it = std::find_if(pair.vocabulary.adjacency.begin(), pair.vocabulary.adjacency.end(), [&](const g::Adjacency& a) {
                        return a.from == from.places[k] && a.to == to.places[k] && a.motion == v && !a.constrained;
                    });
                    REQUIRE(it != pair.vocabulary.adjacency.end());
                    CHECK(it->instantaneous == (t.duration == Duration::instant));
                    CHECK((t.causes & Cause::kinematic) != 0);
                }
                // 8.3.3: a change of place and a change of motion by a force do not happen together.
                if (moved) CHECK((t.causes & Cause::dynamic) == 0);
                // A change of motion with no change of place is dynamic, or a collision with a stop.
                if (!moved && from.motions != to.motions) CHECK((t.causes & (Cause::dynamic | Cause::collision)) != 0);
                if (t.from == t.to) CHECK(t.duration == Duration::interval);
            }
        }
    }
}

TEST_CASE("envision/envisionment: the output is the same on every run (stable ids), with one worker or two") {
    const auto m = mechanism("scenarios/metric/escapement.def");
    EnvisionOptions one, two;
    one.threads = 1;
    two.threads = 2;
    std::ostringstream a, b, c;
    write_json(a, m, envisioned(m, one));
    write_json(b, m, envisioned(m, two));
    write_json(c, m, envisioned(m, two));
    CHECK(a.str() == b.str());
    CHECK(b.str() == c.str());
}
