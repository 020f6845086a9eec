// tests/envision/laws_test.cpp: the laws live in rule files, and the envisionment follows them:
// the laws' folder read as a program; a copy of rules/clock/ without the
// collision law (collision.rules) gives the escapement's envisionment without its collisions and
// changes nothing else; without the metric diagram's constraint (metric_constraint.rules) states the
// geometry blocks come back; a folder with no laws, or a law with an error, is a located error.
#include "envision_fixture.hpp"

#include <fstream>
#include <set>

using namespace qm;
using namespace qm::envision;
using namespace qm::envision::testing;
namespace fs = std::filesystem;

namespace {

// rules/clock/ copied into a fresh folder, without the files named.
fs::path laws_without(const std::string& name, const std::set<std::string>& dropped) {
    const fs::path dir = fs::path(QM_BINARY_DIR) / "envision-test-laws" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const auto& entry : fs::directory_iterator(rules_folder()))
        if (entry.path().extension() == ".rules" && !dropped.count(entry.path().filename().string()))
            fs::copy_file(entry.path(), dir / entry.path().filename());
    return dir;
}

using Edge = std::tuple<std::uint32_t, std::uint32_t, Duration>;
std::set<Edge> edges(const ChainEnvisionment& c, bool collisions) {
    std::set<Edge> out;
    for (const auto& t : c.transitions)
        if (((t.causes & Cause::collision) != 0) == collisions) out.insert({t.from.value, t.to.value, t.duration});
    return out;
}

// rules/clock/ copied into a fresh folder, with each text `from` in file `file` replaced by `to`.
fs::path laws_edited(const std::string& name, const std::string& file, const std::string& from, const std::string& to) {
    const fs::path dir = laws_without(name, {});
    std::ifstream in(dir / file);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    in.close();
    const auto at = text.find(from);
    REQUIRE_MESSAGE(at != std::string::npos, from);
    text.replace(at, from.size(), to);
    std::ofstream(dir / file) << text;
    return dir;
}

}  // namespace

TEST_CASE("envision/laws: which changes of place make a transition, and which arrivals are collisions, are the laws'") {
    // Without (place-change wrap) a gear pair turning round its one place (a face that wraps both
    // axes) has no transition to itself; without the collision law's (collision ...) no escapement
    // transition is caused by one; nothing else changes.
    const auto gears = mechanism("scenarios/clock/gear_pair.def");
    const auto& turning = envisioned_once("scenarios/clock/gear_pair.def");
    EnvisionOptions o;
    o.rules = laws_edited("no-wrap-change", "transition_order.rules", "fact (place-change wrap)", "");
    const auto no_wrap = envisioned(gears, o);
    std::size_t loops = 0;
    std::set<Edge> without_loops;
    for (const auto& t : turning.chains.at(0).transitions) {
        loops += t.from == t.to;
        if (t.from != t.to) without_loops.insert({t.from.value, t.to.value, t.duration});
    }
    REQUIRE(loops > 0);
    std::set<Edge> all_b;
    for (const auto& t : no_wrap.chains.at(0).transitions) all_b.insert({t.from.value, t.to.value, t.duration});
    CHECK(all_b == without_loops);
    const auto m = mechanism("scenarios/clock/escapement.def");
    const auto& a = envisioned_once("scenarios/clock/escapement.def").chains.at(0);
    o.rules = laws_edited("no-collision-cause", "collision.rules", "(arrival ?p ?place move ?v ?after) (collision ?p ?place ?v ?after)",
                          "(arrival ?p ?place move ?v ?after)");
    const auto no_cause = envisioned(m, o);
    const auto& c = no_cause.chains.at(0);
    CHECK(edges(c, true).empty());
    std::set<Edge> all_a = edges(a, true), all_c = edges(c, false);
    for (const auto& e : edges(a, false)) all_a.insert(e);
    CHECK(all_a == all_c);
}

TEST_CASE("envision/laws: deleting the collision law removes the escapement's collisions and nothing else") {
    const auto m = mechanism("scenarios/metric/escapement.def");
    const auto& full = envisioned_once("scenarios/metric/escapement.def");
    EnvisionOptions o;
    o.rules = laws_without("no-collision", {"collision.rules"});
    const auto without = envisioned(m, o);
    REQUIRE(full.chains.size() == 1);
    REQUIRE(without.chains.size() == 1);
    const auto& a = full.chains[0];
    const auto& b = without.chains[0];
    CHECK(a.states.size() == b.states.size());  // the states do not depend on collisions
    CHECK(!edges(a, true).empty());
    CHECK(edges(b, true).empty());
    CHECK(edges(a, false) == edges(b, false));
    MESSAGE("escapement: " << edges(a, true).size() << " collision transitions of " << a.transitions.size() << " go with the law");
}

TEST_CASE("envision/laws: the settling of a step is the settling law's: deleting it changes the transitions, not the states") {
    // rules/clock/settling.rules makes a collision's outcome and a must-change motion hard; the C++
    // holds neither (envision/successors.cpp looks the law's table up), so without the file the
    // escapement goes on differently from the same states.
    const auto m = mechanism("scenarios/metric/escapement.def");
    const auto& full = envisioned_once("scenarios/metric/escapement.def");
    EnvisionOptions o;
    o.rules = laws_without("no-settling", {"settling.rules"});
    const auto loose = envisioned(m, o);
    const auto& a = full.chains[0];
    const auto& b = loose.chains[0];
    CHECK(a.states.size() == b.states.size());
    std::set<Edge> with_law = edges(a, true), without_law = edges(b, true);
    for (const auto& e : edges(a, false)) with_law.insert(e);
    for (const auto& e : edges(b, false)) without_law.insert(e);
    CHECK(with_law != without_law);
    for (std::size_t o = 0; o < b.chain.objects.size(); ++o) CHECK(b.tables.settling(o, 1, 1, 0, true, 1) == 0);
}

TEST_CASE("envision/laws: without the metric diagram's constraint, states the geometry blocks come back") {
    // The clock's ratchet: a place where the normals alone allow a motion that the metric diagram
    // blocks (docs/LAWS.md, Law 2 comparison); on the other bundled mechanisms the two agree.
    const auto m = mechanism("scenarios/clock/ratchet.def");
    const auto& full = envisioned_once("scenarios/clock/ratchet.def");
    EnvisionOptions o;
    o.rules = laws_without("no-metric", {"metric_constraint.rules"});
    const auto loose = envisioned(m, o);
    CHECK(loose.chains[0].states.size() > full.chains[0].states.size());
    for (const State& s : full.chains[0].states.states()) CHECK(loose.chains[0].states.find(s).has_value());
}

TEST_CASE("envision/laws: an empty folder or a broken law is a located error") {
    const auto m = mechanism("scenarios/metric/cam.def");
    EnvisionOptions o;
    o.cache = &test_cache();
    o.rules = laws_without("none", {});
    for (const auto& entry : fs::directory_iterator(o.rules)) fs::remove(entry.path());
    Diagnostics d;
    CHECK(!qm::envision::envision(m, o, d).has_value());
    CHECK(printed(d).find("expected a folder of .rules files") != std::string::npos);

    o.rules = laws_without("broken", {});
    std::ofstream(o.rules / "zz_broken.rules") << "rule broken\n  when (pair ?p ?a\n  then (x)\n";
    Diagnostics d2;
    CHECK(!qm::envision::envision(m, o, d2).has_value());
    CHECK(printed(d2).find("zz_broken.rules:3:11: error: expected a term or ')' to close the '(' at 2:8") != std::string::npos);

    // Laws that leave a pair without a choice of place: said, not a crash. The rule checker
    // (engine/predicate_check.hpp) finds it first: the laws use `at`, which no law left concludes.
    o.rules = laws_without("no-states", {"states.rules"});
    Diagnostics d3;
    CHECK(!qm::envision::envision(m, o, d3).has_value());
    CHECK(printed(d3).find("error: unknown predicate 'at'") != std::string::npos);
}
