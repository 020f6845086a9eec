// engine/engine.cpp: building the engine's facts and nodes; queries.
#include "engine/engine.hpp"
#include "qm/assert.hpp"
#include "qm/limit_reached.hpp"
#include <algorithm>

namespace qm::engine {

namespace {
std::shared_ptr<const SharedProgram> not_null(std::shared_ptr<const SharedProgram> p) {
    QM_REQUIRE(p != nullptr, "an engine needs a program");
    return p;
}
}  // namespace

Engine::Engine(CompiledProgram program, ValueTable values, const BuiltinRegistry& builtins)
    : Engine(share_program(std::move(program)), std::move(values), builtins) {}

Engine::Engine(std::shared_ptr<const SharedProgram> program, ValueTable values, const BuiltinRegistry& builtins)
    : shared_(not_null(std::move(program))),
      program_(shared_->program),
      values_(std::move(values)),
      builtins_(builtins),
      equals_(builtins.find("=")) {
    atms_.add_consumer(*this);
    rule_fresh_.reserve(program_.rules.size());
    rule_matched_.reserve(program_.rules.size());
    for (std::size_t i = 0; i < program_.rules.size(); ++i) {
        rule_fresh_.push_back({});
        rule_matched_.push_back(0);
    }
    for (const auto& p : program_.premises) {
        FactId f = intern_fact(p.predicate, p.args);
        Firing why{Firing::Kind::premise, std::nullopt, {}, std::nullopt, &p.where};
        atms_.justify(new_firing(std::move(why)), std::span<const atms::NodeId>{}, fact_nodes_[f].node);
        note_if_in(f);
    }
    for (const auto& a : program_.assumptions) {
        FactId f = intern_fact(a.predicate, a.args);
        Firing why{Firing::Kind::assumption, std::nullopt, {}, std::nullopt, &a.where};
        assume_fact(f, new_firing(std::move(why)), {});
        note_if_in(f);
    }
}

Engine::~Engine() { atms_.remove_consumer(*this); }

void Engine::set_limits(const EngineLimits& limits) {
    limits_ = limits;
    atms_.limit_environments(limits.max_environments);
}

atms::DatumId Engine::new_datum(Datum d) { return datums_.push_back(d); }

// Drivers add many facts from one place (a bridge, a scene line): consecutive equal locations are
// kept once.
const SourceLocation* Engine::location(SourceLocation where) {
    if (locations_.empty() || !(*locations_.back() == where)) locations_.push_back(std::make_unique<const SourceLocation>(std::move(where)));
    return locations_.back().get();
}

atms::InformantId Engine::new_firing(Firing f) {
    firings_.push_back(std::move(f));
    return atms::InformantId{static_cast<std::uint32_t>(firings_.size() - 1)};
}

FactId Engine::intern_fact(ValueId predicate, std::span<const ValueId> args) {
    QM_REQUIRE(values_.value(predicate).kind == ValueKind::symbol, "a predicate is a symbol");
    auto [f, fresh] = facts_.intern(predicate, args);
    // Checked after interning (one lookup): the store then holds a fact without a node, but an
    // engine that threw is only destroyed (set_limits).
    if (fresh && limits_.max_facts && facts_.size() > *limits_.max_facts)
        throw LimitReached(LimitReached::Kind::facts, *limits_.max_facts);
    if (fresh) {
        atms::NodeId n = atms_.add_node(new_datum({Datum::Kind::fact, f.value}));
        [[maybe_unused]] FactId check = fact_nodes_.push_back(FactNodes{n, std::nullopt});
        QM_ASSERT(check == f, "fact ids and fact node records stay aligned");
    }
    return f;
}

// The assumption node standing for f (created on first use), kept apart from f's own node so that
// `assume` with antecedents can justify f from {assumption} + antecedents: f then holds wherever
// the assumption and the antecedents hold (BPS assume! inside a rule).
atms::NodeId Engine::ensure_assumption(FactId f) {
    FactNodes& nodes = fact_nodes_[f];
    if (!nodes.assumption) {
        nodes.assumption = atms_.add_assumption(new_datum({Datum::Kind::assumption_of_fact, f.value}));
        auto a = atms_.assumption_of(*nodes.assumption);
        QM_ASSERT(a.has_value(), "an assumption node has an assumption");
        if (is_choice_assumption_.size() <= a->value) is_choice_assumption_.resize(a->value + 1, false);
    }
    return *nodes.assumption;
}

void Engine::assume_fact(FactId f, atms::InformantId why, std::span<const atms::NodeId> antecedents) {
    atms::NodeId a = ensure_assumption(f);
    std::vector<atms::NodeId> ants(antecedents.begin(), antecedents.end());
    ants.push_back(a);
    atms_.justify(why, ants, fact_nodes_[f].node);
}

FactId Engine::add_premise(ValueId predicate, std::span<const ValueId> args, SourceLocation where) {
    QM_REQUIRE(!closed_world_used_, "premises cannot be added after `not` or an aggregate was evaluated");
    FactId f = intern_fact(predicate, args);
    Firing why{Firing::Kind::premise, std::nullopt, {}, std::nullopt, location(std::move(where))};
    atms_.justify(new_firing(std::move(why)), std::span<const atms::NodeId>{}, fact_nodes_[f].node);
    note_if_in(f);
    return f;
}

FactId Engine::add_assumption(ValueId predicate, std::span<const ValueId> args, SourceLocation where) {
    QM_REQUIRE(!closed_world_used_, "assumptions cannot be added after `not` or an aggregate was evaluated");
    FactId f = intern_fact(predicate, args);
    Firing why{Firing::Kind::assumption, std::nullopt, {}, std::nullopt, location(std::move(where))};
    assume_fact(f, new_firing(std::move(why)), {});
    note_if_in(f);
    return f;
}

FactId Engine::add_fact(ValueId predicate, std::span<const ValueId> args, std::span<const FactId> from,
                        SourceLocation where) {
    QM_REQUIRE(!closed_world_used_, "facts cannot be added after `not` or an aggregate was evaluated");
    for (FactId a : from) QM_REQUIRE(fact_nodes_.contains(a), "fact id out of range");
    FactId f = intern_fact(predicate, args);
    std::vector<atms::NodeId> antecedents;
    for (FactId a : from) antecedents.push_back(fact_nodes_[a].node);
    Firing why{Firing::Kind::premise, std::nullopt, {}, std::nullopt, location(std::move(where))};
    atms_.justify(new_firing(std::move(why)), antecedents, fact_nodes_[f].node);
    note_if_in(f);
    return f;
}

void Engine::label_became_nonempty(atms::NodeId n) {
    const Datum& d = datums_[atms_.datum(n)];
    if (d.kind != Datum::Kind::fact) return;
    pending_activation_.push_back(FactId{d.index});
}

// Events for nodes created already holding may or may not be delivered; activation is idempotent.
void Engine::note_if_in(FactId f) {
    if (atms_.is_in(fact_nodes_[f].node)) pending_activation_.push_back(f);
}

std::optional<FactId> Engine::find(ValueId predicate, std::span<const ValueId> args) const {
    return facts_.find(predicate, args);
}

atms::NodeId Engine::node(FactId f) const {
    QM_REQUIRE(fact_nodes_.contains(f), "fact id out of range");
    return fact_nodes_[f].node;
}

std::optional<atms::AssumptionId> Engine::assumption(FactId f) const {
    QM_REQUIRE(fact_nodes_.contains(f), "fact id out of range");
    if (!fact_nodes_[f].assumption) return std::nullopt;
    return atms_.assumption_of(*fact_nodes_[f].assumption);
}

std::string Engine::print(FactId f) const {
    const Fact& fact = facts_.fact(f);
    std::string out = "(" + values_.print(fact.predicate);
    for (ValueId a : fact.args) out += " " + values_.print(a);
    return out + ")";
}

std::string Engine::print(atms::AssumptionId a) const {
    const Datum& d = datums_[atms_.datum(atms_.node_of(a))];
    if (d.kind == Datum::Kind::closed_world) return "(closed-world " + std::to_string(d.index) + ")";
    return print(FactId{d.index});
}

std::optional<FactId> Engine::fact_of(atms::NodeId n) const {
    if (n == atms_.contradiction()) return std::nullopt;
    const Datum& d = datums_[atms_.datum(n)];
    if (d.kind == Datum::Kind::closed_world) return std::nullopt;
    return FactId{d.index};
}

std::vector<atms::EnvId> Engine::interpretations() { return atms_.interpretations(choice_sets_); }

const Firing& Engine::firing(atms::InformantId i) const {
    QM_REQUIRE(i.value < firings_.size(), "informant id out of range");
    return firings_[i.value];
}

}  // namespace qm::engine
