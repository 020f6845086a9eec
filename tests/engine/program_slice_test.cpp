// tests/engine/program_slice_test.cpp: engine/program_slice.hpp. On seeded random programs (rules
// with positive atoms, `not`, aggregates, `false`, chains through derived predicates) and random
// facts of the input predicates (premises and assumptions), an engine over the slice derives, for
// every output predicate, the same facts with the same labels, and the same nogoods, as an engine
// over the whole program, run in the context of every assumption; hand-made cases show what is
// kept and what is left out.
#include "engine/engine.hpp"
#include "engine/program_slice.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_spec_reader.hpp"
#include <doctest/doctest.h>
#include <map>
#include <random>
#include <set>
#include <sstream>

using qm::Diagnostics;
using namespace qm::engine;

namespace {

ProgramSpec spec_of(const std::string& text) {
    ProgramSpec spec;
    Diagnostics d;
    read_rule_text(text, "slice.rules", spec, d);
    REQUIRE(!d.has_errors());
    return spec;
}

std::set<std::string> rule_names(const ProgramSpec& s) {
    std::set<std::string> out;
    for (const auto& r : s.rules) out.insert(r.name);
    return out;
}

// Every fact of the output predicates with its label, and the minimal nogoods, as text.
std::map<std::string, std::string> outcome(const ProgramSpec& spec, const std::vector<std::pair<std::string, bool>>& inputs,
                                           const std::set<std::string>& outputs) {
    Diagnostics d;
    auto program = compile_program(spec, d);
    REQUIRE(program.has_value());
    Engine e(std::move(program->program), std::move(program->values));
    std::vector<qm::atms::AssumptionId> assumed;
    for (const auto& [text, assumption] : inputs) {
        const auto open = text.find(' ');
        const ValueId predicate = e.values().symbol(text.substr(1, open - 1));
        const ValueId arg = e.values().symbol(text.substr(open + 1, text.size() - open - 2));
        const std::vector<ValueId> args{arg};
        if (assumption) assumed.push_back(*e.assumption(e.add_assumption(predicate, args)));
        else e.add_premise(predicate, args);
    }
    const auto run = e.run_in_context(e.atms().environment(assumed), d);
    REQUIRE(!d.has_errors());
    std::map<std::string, std::string> out;
    for (std::uint32_t i = 0; i < e.facts().size(); ++i) {
        const FactId f{i};
        if (!outputs.count(e.values().print(e.facts().fact(f).predicate))) continue;
        if (!e.atms().holds_in(e.node(f), run.environment)) continue;
        std::set<std::string> label;
        for (const auto env : e.label(f)) {
            std::string s;
            for (const auto a : e.atms().env(env).assumptions()) s += e.print(a) + " ";
            label.insert(s);
        }
        std::string text;
        for (const auto& s : label) text += "{" + s + "}";
        out[e.print(f)] = text;
    }
    std::set<std::string> nogoods;
    for (const auto env : e.atms().minimal_nogoods()) {
        std::string s;
        for (const auto a : e.atms().env(env).assumptions()) s += e.print(a) + " ";
        nogoods.insert(s);
    }
    for (const auto& n : nogoods) out["nogood " + n] = "";
    return out;
}

}  // namespace

TEST_CASE("engine/program_slice: what is kept") {
    const auto spec = spec_of(
        "fact (k a)\n"
        "fact (unused b)\n"
        "rule fires when (in ?x) (k ?x) then (mid ?x)\n"
        "rule wanted when (mid ?x) not (blocked ?x) then (out ?x)\n"
        "rule blocks when (in ?x) then (blocked ?x)\n"
        "rule never when (nothing ?x) then (out ?x)\n"
        "rule unread when (in ?x) then (side ?x)\n"
        "rule counts when [sum ?x over (absent ?x) with max start 0 as ?n] then (total ?n)\n"
        "rule nogood when (in ?x) (side ?x) then false\n");
    const auto s = slice_program(spec, {"in"}, {"out", "total"});
    // `never` needs facts of `nothing`, which nothing gives; `unread` concludes what only `nogood`
    // reads, and `nogood` may make environments nogood, so both stay.
    CHECK(rule_names(s) == std::set<std::string>{"fires", "wanted", "blocks", "unread", "counts", "nogood"});
    REQUIRE(s.facts.size() == 1);
    CHECK(s.facts[0].predicate == "k");
    CHECK(slice_program(spec, {"in"}, {}).rules.size() == 2);  // only the nogood and what it reads
    CHECK(slice_program(spec, {}, {"out"}).rules.empty());
}

TEST_CASE("engine/program_slice: a slice keeps the preferences on what it concludes, and their ranks") {
    const auto spec = spec_of(
        "rule points when (vane ?x) then [exactly one ?d in {n e}: assume (points ?x ?d)]\n"
        "rule nearest when (vane ?x) then (near ?x n 0) (near ?x e 1)\n"
        "rule gusts when (vane ?x) then (gust ?x)\n"
        "prefer (points ?x ?d) by (near ?x ?d ?k) up to 2\n"
        "prefer (gust ?x) by (gustiness ?x ?k)\n"
        "fact (gustiness v 1)\n");
    const auto s = slice_program(spec, {"vane"}, {"points"});
    // The ranks are read by no rule, only by the preference; `gust` is not concluded in the slice.
    CHECK(rule_names(s) == std::set<std::string>{"points", "nearest"});
    REQUIRE(s.preferences.size() == 1);
    CHECK(s.preferences[0].choice.predicate == "points");
    CHECK(s.preferences[0].up_to == 2);
    CHECK(s.facts.empty());
    // Asked for gusts, the other preference and the fact of its ranks come along.
    const auto g = slice_program(spec, {"vane"}, {"gust"});
    CHECK(rule_names(g) == std::set<std::string>{"gusts"});
    REQUIRE(g.preferences.size() == 1);
    CHECK(g.preferences[0].choice.predicate == "gust");
    REQUIRE(g.facts.size() == 1);
    CHECK(g.facts[0].predicate == "gustiness");
    CHECK(slice_program(spec, {}, {"points"}).preferences.empty());  // nothing concludes points
}

TEST_CASE("engine/program_slice: the slice derives the outputs of the whole program, labels and nogoods included") {
    std::mt19937 rng(13);
    const std::vector<std::string> inputs{"i0", "i1"}, derived{"d0", "d1", "d2", "d3", "d4"};
    auto pick = [&](const std::vector<std::string>& v) { return v[std::uniform_int_distribution<std::size_t>(0, v.size() - 1)(rng)]; };
    auto coin = [&](int n) { return std::uniform_int_distribution<int>(0, n - 1)(rng) == 0; };
    std::size_t compared = 0, dropped = 0, ranked = 0;
    for (int round = 0; round < 150; ++round) {
        std::ostringstream text;
        if (coin(2)) text << "fact (d4 a)\n";
        // Stratified: a rule concluding d_k reads d_j (j <= k) and, under `not` or an aggregate,
        // only d_j with j < k (or an input), so every program compiles.
        const int rules = std::uniform_int_distribution<int>(2, 9)(rng);
        for (int r = 0; r < rules; ++r) {
            const bool nogood = coin(6);
            const std::size_t k = std::uniform_int_distribution<std::size_t>(0, derived.size() - 1)(rng);
            std::vector<std::string> up_to = inputs, below = inputs;
            up_to.push_back("n0");
            for (std::size_t j = 0; j < derived.size(); ++j) {
                if (nogood || j <= k) up_to.push_back(derived[j]);
                if (nogood || j < k) below.push_back(derived[j]);
            }
            text << "rule r" << r << " when (" << pick(up_to) << " ?x)";
            if (coin(2)) text << " (" << pick(up_to) << " ?x)";
            if (coin(3)) text << " not (" << pick(below) << " ?x)";
            if (coin(5)) text << " [sum ?y over (" << pick(below) << " ?y) with max start 0 as ?m]";
            if (nogood) text << " then false\n";
            else text << " then (" << derived[k] << " ?x)\n";
        }
        // Half the programs prefer among the facts of a derived predicate by ranks that only the
        // preference reads (no rule does).
        std::string chosen;
        if (coin(2)) {
            chosen = pick(derived);
            std::vector<std::string> all = inputs;
            all.insert(all.end(), derived.begin(), derived.end());
            for (int r = 0; r < 2; ++r) text << "rule rank" << r << " when (" << pick(all) << " ?x) then (rank ?x " << r << ")\n";
            text << "prefer (" << chosen << " ?x) by (rank ?x ?k)\n";
        }
        const auto spec = spec_of(text.str());
        std::set<std::string> outputs;
        for (const auto& d : derived)
            if (coin(2)) outputs.insert(d);
        const auto slice = slice_program(spec, {inputs.begin(), inputs.end()}, outputs);
        dropped += spec.rules.size() - slice.rules.size();
        // Where the slice concludes the chosen predicate (an output here), the preference and the
        // ranks it reads are kept.
        bool concludes_chosen = false;
        for (const auto& r : slice.rules)
            for (const auto& c : r.consequents) concludes_chosen |= c.kind != ConsequentSpec::Kind::falsity && c.atom.predicate == chosen;
        std::set<std::string> compared_predicates = outputs;
        if (outputs.count(chosen) && concludes_chosen) {
            CHECK(slice.preferences.size() == 1);
            compared_predicates.insert("rank");
            ++ranked;
        }
        std::vector<std::pair<std::string, bool>> facts;
        for (const auto& p : inputs)
            for (const char* c : {"a", "b"})
                if (!coin(3)) facts.push_back({"(" + p + " " + c + ")", coin(2)});
        CAPTURE(text.str());
        CHECK(outcome(slice, facts, compared_predicates) == outcome(spec, facts, compared_predicates));
        ++compared;
    }
    MESSAGE(compared << " random programs compared (" << ranked << " with a preference on an output); " << dropped
                     << " rules left out of their slices");
    CHECK(dropped > 0);
    CHECK(ranked > 0);
}
