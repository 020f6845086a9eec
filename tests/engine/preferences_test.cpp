// tests/engine/preferences_test.cpp: the `prefer` declaration (docs/RULES.md "Preferences") from
// rule text: it reads, prints and is checked (malformed declarations are located errors), and
// engine/preferences.hpp ranks a choice set's members by the rank facts holding in an environment
// (the least rank, capped by `up to`; an unranked member after every ranked one; a set with no rank
// holding is unranked).
#include "engine/preferences.hpp"
#include "atms/preferred_interpretations.hpp"
#include "engine/rule_checker.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_printer.hpp"
#include "engine/rule_spec_reader.hpp"
#include <algorithm>
#include "run_rule_text.hpp"
#include <doctest/doctest.h>
#include <map>
#include <memory>
#include <optional>
#include <random>

using namespace qm::engine;

namespace {

const char* ranked_program = R"(fact (ranked a)
fact (ranked b)
fact (object a)
fact (object b)
fact (object c)
assume (windy)
rule choose
  when (object ?o)
  then [exactly one ?d in {n s e}: assume (go ?o ?d)]
rule north-is-near
  when (ranked ?o)
  then (near ?o n 0)
rule south-when-windy
  when (ranked ?o) (windy)
  then (near ?o s 1)
rule south-is-far
  when (ranked ?o)
  then (near ?o s 7)
prefer (go ?o ?d) by (near ?o ?d ?k) up to 5
)";

std::string errors_of(const std::string& text) {
    qm::Diagnostics d;
    ProgramSpec spec;
    read_rule_text(text, "p.rules", spec, d);
    (void)check_program(spec, d);
    std::string out;
    for (const auto& x : d.items()) out += to_string(x.where) + ": " + x.message + "\n";
    return out;
}
}  // namespace

TEST_CASE("engine/preferences: `prefer` reads, prints and passes the checker") {
    qm::Diagnostics d;
    ProgramSpec spec;
    read_rule_text(ranked_program, "p.rules", spec, d);
    CHECK(!d.has_errors());
    REQUIRE(spec.preferences.size() == 1);
    CHECK(spec.preferences[0].up_to == 5);
    CHECK(spec.preferences[0].where.line == 19);
    CHECK(check_program(spec, d));
    CHECK(print_program(spec).find("prefer (go ?o ?d) by (near ?o ?d ?k) up to 5\n") != std::string::npos);
    ProgramSpec again;
    read_rule_text("prefer (go ?o ?d) by (near ?k ?o ?d)\n", "q.rules", again, d);
    REQUIRE(again.preferences.size() == 1);
    CHECK(!again.preferences[0].up_to);
    CHECK(print_program(again) == "prefer (go ?o ?d) by (near ?k ?o ?d)\n");
}

TEST_CASE("engine/preferences: malformed declarations are located errors") {
    const std::string choose = "rule c\n  when (o ?o)\n  then [exactly one ?d in {n s}: assume (go ?o ?d)]\n";
    CHECK(errors_of(choose + "prefer (go ?o n) by (near ?o ?d ?k)\n").find("p.rules:4:15: `prefer`: the chosen atom's arguments must be distinct variables") == 0);
    CHECK(errors_of(choose + "prefer (go ?o ?d) by (near ?o ?k)\n").find("p.rules:4:22: `prefer`: the rank atom must have every variable of the chosen atom, but has no ?d") == 0);
    CHECK(errors_of(choose + "prefer (go ?o ?d) by (near ?o ?d)\n").find("the rank atom must have exactly one variable that the chosen atom does not have (the rank), but has 0") != std::string::npos);
    CHECK(errors_of(choose + "prefer (go ?o ?d) by (near ?o ?d 3)\n").find("the rank atom's arguments must be distinct variables") != std::string::npos);
    CHECK(errors_of(choose + "prefer (stay ?o ?d) by (near ?o ?d ?k)\n").find("p.rules:4:8: `prefer`: no `exactly one` assumes (stay ...)") == 0);
    {  // only a warning: the program is fine, the preference chooses nothing
        qm::Diagnostics d;
        ProgramSpec spec;
        read_rule_text(choose + "prefer (stay ?o ?d) by (near ?o ?d ?k)\n", "p.rules", spec, d);
        CHECK(check_program(spec, d));
        CHECK(!d.has_errors());
    }
    CHECK(errors_of(choose + "prefer (go ?o ?d) by (near ?o ?d ?k)\nprefer (go ?o ?d) by (far ?o ?d ?k)\n")
              .find("p.rules:5:8: `prefer`: (go ...) already has a preference at p.rules:4:1") == 0);
    CHECK(errors_of(choose + "prefer (go ?o) by (near ?o ?d ?k)\n").find("p.rules:4:8: predicate 'go' is used here with 1 argument(s)") == 0);
}

TEST_CASE("engine/preferences: a syntax error in `prefer` is located") {
    qm::Diagnostics d;
    ProgramSpec spec;
    read_rule_text("prefer (go ?o ?d) (near ?o ?d ?k)\n", "p.rules", spec, d);
    REQUIRE(d.has_errors());
    CHECK(d.items()[0].message.find("expected 'by'") == 0);
    CHECK(d.items()[0].where.column == 19);
    qm::Diagnostics e;
    read_rule_text("prefer (go ?o ?d) by (near ?o ?d ?k) up 3\n", "p.rules", spec, e);
    REQUIRE(e.has_errors());
    CHECK(e.items()[0].message.find("expected 'to'") == 0);
}

TEST_CASE("engine/preferences: ranks by the rank facts holding in an environment") {
    const auto engine = test::run_rule_text(ranked_program, "p.rules");
    Engine& e = *engine;
    REQUIRE(e.choice_sets().size() == 3);
    // Which set is whose, and which member stands for which direction.
    std::map<std::string, std::vector<qm::atms::AssumptionId>> set_of;
    for (const auto& set : e.choice_sets()) set_of[e.print(set.front()).substr(4, 1)] = set;
    auto ranks_by_text = [&](const std::string& object, qm::atms::EnvId env) {
        std::map<std::string, std::int64_t> out;
        const auto& set = set_of.at(object);
        auto r = choice_set_ranks(e, set, env);
        if (!r) return out;
        REQUIRE(r->size() == set.size());
        for (std::size_t i = 0; i < set.size(); ++i) out[e.print(set[i])] = (*r)[i];
        return out;
    };
    const qm::atms::EnvId none = e.atms().environment(std::vector<qm::atms::AssumptionId>{});
    auto windy_fact = e.find(e.values().symbol("windy"), {});
    REQUIRE(windy_fact);
    const qm::atms::EnvId windy = e.atms().environment({*e.assumption(*windy_fact)});
    // North 0; south 7 capped at 5; east unranked, after the farthest ranked (5).
    CHECK(ranks_by_text("a", none) == std::map<std::string, std::int64_t>{{"(go a n)", 0}, {"(go a s)", 5}, {"(go a e)", 6}});
    // Windy: south's least rank is 1.
    CHECK(ranks_by_text("b", windy) == std::map<std::string, std::int64_t>{{"(go b n)", 0}, {"(go b s)", 1}, {"(go b e)", 2}});
    CHECK(ranks_by_text("c", windy).empty());  // no rank fact: not ranked
    // The rank facts of a member, in any environment.
    std::vector<qm::atms::AssumptionId> south;
    for (auto a : set_of.at("a"))
        if (e.print(a) == "(go a s)") south.push_back(a);
    REQUIRE(south.size() == 1);
    std::vector<std::string> texts;
    for (FactId f : rank_facts(e, south[0])) texts.push_back(e.print(f));
    std::sort(texts.begin(), texts.end());
    CHECK(texts == std::vector<std::string>{"(near a s 1)", "(near a s 7)"});
    CHECK(rank_facts(e, *e.assumption(*windy_fact)).empty());  // not a chosen fact
}

TEST_CASE("engine/preferences: docs/RULES.md's vane, with the generic query over interpretations") {
    const char* vane = R"(fact (vane v)
assume (blocked-north)
rule points
  when (vane ?x)
  then [exactly one ?d in {n e s w}: assume (points ?x ?d)]
rule nearest-to-the-wind
  when (vane ?x)
  then (near ?x n 0) (near ?x e 1) (near ?x w 1) (near ?x s 5)
rule blocked
  when (points ?x n) (blocked-north)
  then false
prefer (points ?x ?d) by (near ?x ?d ?k) up to 2
)";
    const auto engine = test::run_rule_text(vane, "vane.rules");
    Engine& e = *engine;
    REQUIRE(e.choice_sets().size() == 1);
    const auto& set = e.choice_sets()[0];
    auto preferred = [&](qm::atms::EnvId base) {
        auto ranks = choice_set_ranks(e, set, base);
        REQUIRE(ranks.has_value());
        const std::vector<qm::atms::RankedChoiceSet> ranked{{set, *ranks}};
        std::vector<std::string> out;
        qm::atms::for_each_preferred_interpretation(e.atms(), ranked, {}, base, [&](const qm::atms::Environment& env) {
            for (auto a : set)
                if (env.contains(a)) out.push_back(e.print(a));
            return true;
        });
        std::sort(out.begin(), out.end());
        return out;
    };
    auto blocked = e.find(e.values().symbol("blocked-north"), {});
    REQUIRE(blocked);
    CHECK(preferred(e.atms().environment(std::vector<qm::atms::AssumptionId>{})) == std::vector<std::string>{"(points v n)"});
    CHECK(preferred(e.atms().environment({*e.assumption(*blocked)})) ==
          std::vector<std::string>{"(points v e)", "(points v w)"});
}

// A rank table (choice_set_rank_table) against brute force: random distance tables between a few
// reference assumptions and the members of a choice set; in each subset of the references, a
// member's rank is its least distance to a reference in the subset (capped by `up to`), a member
// with none ranks after the farthest ranked one, and a set with no rank is all 0.
TEST_CASE("engine/preferences: a rank table over reference assumptions equals brute force") {
    const std::vector<std::string> dirs{"n", "e", "s"};
    std::mt19937 rng(38);
    for (int round = 0; round < 60; ++round) {
        const std::int64_t cap = 1 + static_cast<std::int64_t>(rng() % 4);
        std::map<std::pair<std::size_t, std::size_t>, std::int64_t> dist;  // (reference, member) -> distance
        std::string text = "fact (object a)\nrule choose\n  when (object ?o)\n  then [exactly one ?d in {n e s}: assume (go ?o ?d)]\n";
        for (std::size_t r = 0; r < dirs.size(); ++r) {
            text += "assume (allow a " + dirs[r] + ")\n";
            for (std::size_t m = 0; m < dirs.size(); ++m)
                if (rng() % 3 != 0) {
                    dist[{r, m}] = static_cast<std::int64_t>(rng() % 6);
                    text += "fact (dist " + dirs[r] + " " + dirs[m] + " " + std::to_string(dist[{r, m}]) + ")\n";
                }
        }
        text += "rule near\n  when (allow ?o ?r) (dist ?r ?d ?k)\n  then (near ?o ?d ?k)\n";
        text += "prefer (go ?o ?d) by (near ?o ?d ?k) up to " + std::to_string(cap) + "\n";
        const auto engine = test::run_rule_text(text, "t.rules");
        Engine& e = *engine;
        REQUIRE(e.choice_sets().size() == 1);
        const auto& set = e.choice_sets()[0];
        const CompiledPreference* pref = choosing_preference(e, set);
        REQUIRE(pref != nullptr);
        CHECK(pref->where.file == "t.rules");
        std::vector<qm::atms::AssumptionId> refs;
        for (const auto& r : dirs) {
            const std::vector<ValueId> args{e.values().symbol("a"), e.values().symbol(r)};
            const auto f = e.find(e.values().symbol("allow"), args);
            REQUIRE(f);
            refs.push_back(*e.assumption(*f));
        }
        std::vector<std::size_t> member_dir;  // set[i] is (go a dirs[member_dir[i]])
        for (auto a : set)
            for (std::size_t m = 0; m < dirs.size(); ++m)
                if (e.print(a) == "(go a " + dirs[m] + ")") member_dir.push_back(m);
        REQUIRE(member_dir.size() == set.size());
        const auto table = choice_set_rank_table(e, set, refs);
        REQUIRE(table.size() == 8);
        for (std::size_t mask = 0; mask < 8; ++mask) {
            std::vector<std::optional<std::int64_t>> rank(set.size());
            for (std::size_t i = 0; i < set.size(); ++i)
                for (std::size_t r = 0; r < dirs.size(); ++r) {
                    const auto it = dist.find({r, member_dir[i]});
                    if (!(mask >> r & 1U) || it == dist.end()) continue;
                    const std::int64_t k = std::min(it->second, cap);
                    rank[i] = rank[i] ? std::min(*rank[i], k) : k;
                }
            std::int64_t farthest = -1;
            for (const auto& r : rank)
                if (r) farthest = std::max(farthest, *r);
            std::vector<std::int64_t> expected;
            for (const auto& r : rank) expected.push_back(farthest < 0 ? 0 : r ? *r : farthest + 1);
            CHECK(table[mask] == expected);
        }
    }
    // A set no preference chooses among has no declaration.
    const auto engine = test::run_rule_text("fact (object a)\nrule choose\n  when (object ?o)\n  then [exactly one ?d in {n e}: assume (go ?o ?d)]\n", "u.rules");
    Engine& e = *engine;
    REQUIRE(e.choice_sets().size() == 1);
    CHECK(choosing_preference(e, e.choice_sets()[0]) == nullptr);
    CHECK(choice_set_rank_table(e, e.choice_sets()[0], {}) == std::vector<std::vector<std::int64_t>>{{0, 0}});
}
