// tests/engine/choice_set_test.cpp: what `[exactly one ...]` means (docs/RULES.md "## Semantics"),
// end to end from rule text: a choice set ranges over its assumptions only (a fact derived
// otherwise holds by that derivation, in every interpretation); an empty choice set is false, so
// the firing's antecedents become a nogood that explanations show; the same set declared twice is
// one set; the set is one ATMS at-most-one constraint whose pairs the report lists up to 64 members
// (a larger set as one summary line, also in JSON) and whose pair nogoods explain as the pairwise
// nogoods did, also in a set of 5,000. (Overlapping sets are a located error: golden case
// errors/choice_set_overlap.)
#include "engine/engine.hpp"
#include "engine/json_writer.hpp"
#include "engine/report_printer.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_spec_reader.hpp"
#include "engine/run_report.hpp"
#include "engine/why.hpp"
#include "run_rule_text.hpp"
#include <doctest/doctest.h>
#include <algorithm>
#include <memory>

using namespace qm::engine;

namespace {
std::unique_ptr<Engine> run(const std::string& text) {
    return test::run_rule_text(text, "c.rules");
}
FactId fact(Engine& e, const std::string& predicate, std::vector<ValueId> args) {
    auto f = e.find(e.values().symbol(predicate), args);
    REQUIRE(f.has_value());
    return *f;
}
}  // namespace

TEST_CASE("engine/engine: a choice set constrains its assumptions, not facts derived otherwise") {
    // (k 1) is also concluded outright, so it holds in every interpretation, including the one that
    // picks the assumption of (k 2): the choice is between the assumptions.
    auto e = run("fact (o a)\nrule c when (o ?x) then [exactly one ?k in {1 2}: assume (k ?k)] (k 1)\n");
    const RunReport r = make_report(*e);
    CHECK(r.interpretations == std::vector<EnvText>{{"(k 1)"}, {"(k 2)"}});
    const FactId k1 = fact(*e, "k", {e->values().integer(1)});
    const FactId k2 = fact(*e, "k", {e->values().integer(2)});
    CHECK(e->atms().is_true(e->node(k1)));
    for (qm::atms::EnvId i : e->interpretations()) {
        CHECK(e->atms().holds_in(e->node(k1), i));
        CHECK(e->atms().holds_in(e->node(k2), i) == (e->print(e->atms().env(i).assumptions()[0]) == "(k 2)"));
    }
}

TEST_CASE("engine/engine: an empty choice set makes the firing's antecedents a nogood") {
    auto e = run("fact (o a)\nrule c when (o ?x) then [exactly one ?k in {1 2} where (> ?k 5): assume (k ?k)]\n");
    CHECK(e->choice_sets().empty());
    CHECK(e->interpretations().empty());
    const RunReport r = make_report(*e);
    CHECK(r.nogoods == std::vector<EnvText>{EnvText{}});  // the empty environment: (o a) is a premise
    const Why w = why(*e, fact(*e, "o", {e->values().symbol("a")}));
    REQUIRE(w.status == Why::Status::ruled_out);
    REQUIRE(w.nogoods.size() == 1);
    REQUIRE(!w.nogoods[0].steps.empty());
    CHECK(w.nogoods[0].steps.back().consequent == "false");
    CHECK(w.nogoods[0].steps.back().informant == "rule c at c.rules:2");
    CHECK(w.nogoods[0].steps.back().binding == std::vector<std::string>{"?x = a"});
}

TEST_CASE("engine/engine: an empty choice set rules out only the environments where it fired") {
    // The empty set fires only where (o a) is assumed: that assumption becomes a nogood, and the
    // other choice set keeps its two interpretations (an empty set registered as a choice set left none).
    auto e = run("assume (o a)\nfact (p b)\n"
                 "rule c when (o ?x) then [exactly one ?k in {1 2} where (> ?k 5): assume (k ?k)]\n"
                 "rule m when (p ?y) then [exactly one ?m in {on off}: assume (mode ?m)]\n");
    const RunReport r = make_report(*e);
    CHECK(r.nogoods == std::vector<EnvText>{{"(o a)"}, {"(mode off)", "(mode on)"}});
    CHECK(r.interpretations == std::vector<EnvText>{{"(mode off)"}, {"(mode on)"}});
    CHECK(e->choice_sets().size() == 1);
}

TEST_CASE("engine/engine: the same choice set declared by two firings or two rules is one set") {
    auto e = run("fact (o a)\nfact (o b)\n"
                 "rule c when (o ?x) then [exactly one ?m in {on off}: assume (mode ?m)]\n"
                 "rule d when (o a) then [exactly one ?m in {off on}: assume (mode ?m)]\n");
    CHECK(e->choice_sets().size() == 1);
    CHECK(e->interpretations().size() == 2);
}

namespace {
std::string range_set(int members) {
    return "fact (o a)\nrule c when (o ?x) then [exactly one ?k in (range 1 " + std::to_string(members) +
           "): assume (k ?k)]\n";
}
}  // namespace

TEST_CASE("engine/engine: a choice set is one ATMS constraint, whose pairs the report lists up to 64 members") {
    // 64 members: every pair listed, as if each pair were a nogood of its own.
    auto small = run(range_set(64));
    CHECK(small->atms().justifications(small->atms().contradiction()).empty());
    const RunReport r = make_report(*small);
    CHECK(r.nogoods.size() == 64 * 63 / 2);
    CHECK(std::find(r.nogoods.begin(), r.nogoods.end(), EnvText{"(k 1)", "(k 64)"}) != r.nogoods.end());
    CHECK(r.unlisted.empty());
    CHECK(r.interpretations.size() == 64);
    CHECK(to_json(r).find("unlisted_choice_sets") == std::string::npos);
    // 65 members, one of them ruled out by a rule: summarised, with the pairs of the other 64.
    auto large = run(range_set(65) + "rule no when (k 7) then false\n");
    const RunReport s = make_report(*large);
    CHECK(s.nogoods == std::vector<EnvText>{{"(k 7)"}});
    REQUIRE(s.unlisted.size() == 1);
    CHECK(s.unlisted[0].members.size() == 65);
    CHECK(s.unlisted[0].members.front() == "(k 1)");
    CHECK(s.unlisted[0].members.back() == "(k 65)");
    CHECK(s.unlisted[0].where == "c.rules:2:25");
    CHECK(s.unlisted[0].nogoods == 64 * 63 / 2);
    CHECK(s.interpretations.size() == 64);
    CHECK(print_report(s).find("  any two of the 65 assumptions {(k 1), (k 2), (k 3), ..., (k 65)} of the choice set at "
                               "c.rules:2:25 (2016 nogoods, not listed)\n") != std::string::npos);
    CHECK(to_json(s).find(", \"unlisted_choice_sets\": [{\"choice_set\": [\"(k 1)\", \"(k 2)\", ") != std::string::npos);
    CHECK(to_json(s).find("\"at\": \"c.rules:2:25\", \"nogoods\": 2016}], \"interpretations\": ") != std::string::npos);
}

TEST_CASE("engine/engine: a fact needing two members of a choice set is ruled out by their pair, explained as before") {
    for (int members : {3, 5000}) {
        CAPTURE(members);
        auto e = run(range_set(members) + "rule both when (k 1) (k 3) then (both)\n");
        const Why w = why(*e, fact(*e, "both", {}));
        REQUIRE(w.status == Why::Status::ruled_out);
        REQUIRE(w.nogoods.size() == 1);
        CHECK(w.nogoods[0].environment == EnvText{"(k 1)", "(k 3)"});
        REQUIRE(w.nogoods[0].steps.size() == 1);
        const WhyStep& step = w.nogoods[0].steps[0];
        CHECK(step.consequent == "false");
        CHECK(step.informant == "rule c at c.rules:2");
        CHECK(step.binding == std::vector<std::string>{"?x = a"});
        CHECK(step.antecedents == std::vector<std::string>{"assume (k 1)", "assume (k 3)"});
    }
}
