// tests/engine/engine_limits_test.cpp: EngineLimits (engine/run_options.hpp) bound the facts an
// engine holds and the environments its ATMS interns. A program that would count
// for ever stops with qm::LimitReached naming the rule being fired and its location; the bounds
// are exact (a program that holds N facts, or needs E environments, runs at a limit of N or E and
// stops at N - 1 or E - 1), measured against the same program run without limits.
#include "engine/run_report.hpp"
#include "run_rule_text.hpp"
#include "qm/limit_reached.hpp"
#include <doctest/doctest.h>
#include <memory>
#include <optional>
#include <string>

using namespace qm::engine;

namespace {
std::unique_ptr<Engine> engine_for(const std::string& text, EngineLimits limits = {}) {
    auto e = test::engine_for(text, "limits.rules");
    e->set_limits(limits);
    return e;
}

// The limit reached by running `text` under `limits`, or nullopt when the run finished.
std::optional<qm::LimitReached> reached(const std::string& text, EngineLimits limits) {
    auto e = engine_for(text, limits);
    qm::Diagnostics d;
    try {
        e->run(d);
        (void)make_report(*e);  // enumerating the interpretations interns environments too
    } catch (const qm::LimitReached& l) {
        return l;
    }
    CHECK(!d.has_errors());
    return std::nullopt;
}

const std::string counting = "fact (n 0)\nrule grow\n  when (n ?x)\n  then (n (+ ?x 1))\n";
}  // namespace

TEST_CASE("engine/limits: a program that counts for ever stops at the fact limit, naming the rule") {
    auto l = reached(counting, {1000, std::nullopt});
    REQUIRE(l.has_value());
    CHECK(l->kind == qm::LimitReached::Kind::facts);
    CHECK(l->limit == 1000);
    CHECK(l->doing == "firing rule 'grow'");
    REQUIRE(l->where.has_value());
    CHECK(l->where->file == "limits.rules");
    CHECK(l->where->line == 2);
    CHECK(l->where->column == 1);
}

TEST_CASE("engine/limits: the fact limit is exact") {
    // Counts to 40: 41 facts (n 0) .. (n 40).
    const std::string bounded = "fact (n 0)\nrule grow\n  when (n ?x) (< ?x 40)\n  then (n (+ ?x 1))\n";
    auto free = engine_for(bounded);
    qm::Diagnostics d;
    free->run(d);
    REQUIRE(!d.has_errors());
    const std::size_t facts = free->facts().size();
    CHECK(facts == 41);
    CHECK(!reached(bounded, {facts, std::nullopt}).has_value());
    auto l = reached(bounded, {facts - 1, std::nullopt});
    REQUIRE(l.has_value());
    CHECK(l->kind == qm::LimitReached::Kind::facts);
}

TEST_CASE("engine/limits: the environment limit is exact, also while the interpretations are enumerated") {
    // Eight binary choice sets: 2^8 interpretations, each an environment of eight assumptions.
    std::string program;
    for (int i = 1; i <= 8; ++i) program += "fact (o " + std::to_string(i) + ")\n";
    program += "rule pick\n  when (o ?x)\n  then [exactly one ?v in {a b}: assume (v ?x ?v)]\n";
    auto free = engine_for(program);
    qm::Diagnostics d;
    free->run(d);
    REQUIRE(!d.has_errors());
    const RunReport report = make_report(*free);
    CHECK(report.interpretations.size() == 256);
    const std::size_t environments = free->atms().environment_count();
    CHECK(environments >= 256);
    CHECK(!reached(program, {std::nullopt, environments}).has_value());
    auto l = reached(program, {std::nullopt, environments - 1});
    REQUIRE(l.has_value());
    CHECK(l->kind == qm::LimitReached::Kind::environments);
    CHECK(l->limit == environments - 1);
    // A limit far below what the run itself needs is reached while firing the choice rule.
    auto early = reached(program, {std::nullopt, 4});
    REQUIRE(early.has_value());
    CHECK(early->doing == "firing rule 'pick'");
}
