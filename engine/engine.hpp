// engine/engine.hpp
// Provides:   Engine, the pattern-directed rule engine over an ATMS (an ATMoSphere analogue; the BPS
//             atre layered on atms). Every fact is an ATMS node; its label comes from the ATMS. Each
//             rule firing adds one justification from exactly the matched fact nodes to each
//             consequent, with the firing (rule, file:line, binding) as informant. `false` adds
//             nogoods; `assume` makes assumptions; `[exactly one ...]` declares choice sets.
//             The C++ API for drivers: add premises and assumptions, run (generically or relative
//             to a context environment), look up facts, nodes and labels, enumerate interpretations.
// Ownership:  an Engine owns its Atms, its facts and its values, and shares its compiled program
//             (shared_program.hpp: read only, so engines over one program may run in different
//             threads); ids it hands out (FactId, NodeId, EnvId, InformantId) are valid for its lifetime.
// Invariants: a rule never fires twice on the same binding (in the same context, for a rule with a
//             negation or aggregate); strata run in order; output order is deterministic.
// Semantics:  of `not`, aggregates and contexts: docs/RULES.md "## Semantics".
// Errors:     a rule that cannot be evaluated soundly (negation over an assumption-dependent fact
//             without a context, ...) or a builtin error is reported into the Diagnostics given to
//             run(), located at the condition; so is a choice set that shares an assumption with
//             another, different one (located at its `exactly one`, naming the other's location).
//             API misuse throws qm::InternalError.
// Knows nothing of mechanics.
#pragma once
#include "atms/atms.hpp"
#include "engine/agenda.hpp"
#include "engine/builtin_registry.hpp"
#include "engine/compiled_rule.hpp"
#include "engine/fact_store.hpp"
#include "engine/firing.hpp"
#include "engine/matcher.hpp"
#include "engine/run_options.hpp"
#include "engine/shared_program.hpp"
#include "engine/value_table.hpp"
#include "qm/diagnostics.hpp"
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <unordered_map>
#include <vector>

namespace qm::engine {

// The result of running relative to a context: the environment in which the context's conclusions
// hold (the context plus its closed-world assumption).
struct ContextRun {
    std::uint32_t context = 0;
    atms::EnvId environment{};             // C + {closed-world of C}
    atms::AssumptionId closed_world{};
};

class Engine final : private atms::Consumer {
public:
    Engine(CompiledProgram program, ValueTable values, const BuiltinRegistry& builtins = default_builtins());
    // Over a program shared with other engines. Pre: program is not null; values is the table the
    // program was compiled with (or a copy of it).
    Engine(std::shared_ptr<const SharedProgram> program, ValueTable values, const BuiltinRegistry& builtins = default_builtins());
    ~Engine() override;
    Engine(const Engine&) = delete;
    Engine& operator=(const Engine&) = delete;

    // ---- building -------------------------------------------------------------------------------
    [[nodiscard]] ValueTable& values() noexcept { return values_; }
    [[nodiscard]] const ValueTable& values() const noexcept { return values_; }
    // Pre: predicate is a symbol; no rule with a negation or aggregate has been evaluated yet
    // (a closed world, once used, must not grow: docs/RULES.md "## Semantics").
    // `where` is what explanations print as the fact's origin (e.g. the scene line it came from).
    FactId add_premise(ValueId predicate, std::span<const ValueId> args, SourceLocation where = {"<api>", 1, 1});
    FactId add_assumption(ValueId predicate, std::span<const ValueId> args, SourceLocation where = {"<api>", 1, 1});
    // A fact that holds wherever all of `from` hold (a driver's justification, e.g. a scene item
    // that holds in its situation). Pre: as add_premise; every id in from issued by this engine.
    FactId add_fact(ValueId predicate, std::span<const ValueId> args, std::span<const FactId> from,
                    SourceLocation where = {"<api>", 1, 1});

    // Bounds the facts and environments of this engine from now on (run_options.hpp). Reaching
    // one throws qm::LimitReached, naming the rule being fired or matched when one was; the
    // engine must then only be destroyed.
    void set_limits(const EngineLimits& limits);

    // ---- running --------------------------------------------------------------------------------
    // Runs every stratum to quiescence; `not` and aggregates are decided generically (a fact whose
    // label depends on assumptions makes them undecidable: a diagnostic). With options.max_steps,
    // the run stops when it has taken that many steps (a diagnostic; see run_options.hpp).
    void run(Diagnostics& diagnostics, const RunOptions& options = {});
    // Runs every stratum; `not` and aggregates are decided in the context environment C.
    // Pre: context was issued by atms().
    ContextRun run_in_context(atms::EnvId context, Diagnostics& diagnostics, const RunOptions& options = {});

    // ---- facts and labels -----------------------------------------------------------------------
    [[nodiscard]] const FactStore& facts() const noexcept { return facts_; }
    [[nodiscard]] std::optional<FactId> find(ValueId predicate, std::span<const ValueId> args) const;
    [[nodiscard]] std::span<const FactId> facts_of(ValueId predicate) const { return facts_.with_predicate(predicate); }
    [[nodiscard]] atms::NodeId node(FactId f) const;                          // Pre: f valid
    [[nodiscard]] std::optional<atms::AssumptionId> assumption(FactId f) const;  // if f was assumed
    [[nodiscard]] const std::vector<atms::EnvId>& label(FactId f) const { return atms_.label(node(f)); }
    [[nodiscard]] std::string print(FactId f) const;                          // "(queen 1 2)"
    // The fact (or closed-world marker) an assumption stands for, as text.
    [[nodiscard]] std::string print(atms::AssumptionId a) const;
    // The fact a node stands for; empty for the contradiction and closed-world nodes.
    [[nodiscard]] std::optional<FactId> fact_of(atms::NodeId n) const;
    [[nodiscard]] const atms::Atms& atms() const noexcept { return atms_; }
    [[nodiscard]] atms::Atms& atms() noexcept { return atms_; }

    // ---- choice sets and interpretations --------------------------------------------------------
    [[nodiscard]] const std::vector<std::vector<atms::AssumptionId>>& choice_sets() const noexcept { return choice_sets_; }
    // Choice set i's at-most-one constraint in the ATMS (Atms::add_at_most_one's record) and the
    // `exactly one` that declared it. Pre: i < choice_sets().size().
    [[nodiscard]] atms::JustId choice_set_constraint(std::size_t i) const { return choice_set_constraints_.at(i); }
    [[nodiscard]] const SourceLocation& choice_set_where(std::size_t i) const { return choice_set_where_.at(i); }
    [[nodiscard]] std::vector<atms::EnvId> interpretations();

    // ---- provenance -----------------------------------------------------------------------------
    [[nodiscard]] const CompiledProgram& program() const noexcept { return program_; }
    [[nodiscard]] const BuiltinRegistry& builtins() const noexcept { return builtins_; }
    [[nodiscard]] const Firing& firing(atms::InformantId i) const;  // Pre: i issued by this engine
    [[nodiscard]] std::size_t firing_count() const noexcept { return firings_.size(); }
    [[nodiscard]] std::size_t rule_firings() const noexcept { return rule_firings_; }

private:
    struct Datum {
        enum class Kind : std::uint8_t { fact, assumption_of_fact, closed_world } kind = Kind::fact;
        std::uint32_t index = 0;  // FactId or context index
    };
    struct FactNodes {
        atms::NodeId node;
        std::optional<atms::NodeId> assumption;
    };
    struct Context {
        atms::EnvId base;
        atms::NodeId node;
        atms::AssumptionId assumption;
        atms::EnvId environment;
        std::uint32_t assumptions_closed = 0;  // assumptions below this id have their nogood
    };

    void label_became_nonempty(atms::NodeId n) override;

    // engine.cpp
    atms::DatumId new_datum(Datum d);
    const SourceLocation* location(SourceLocation where);  // kept in locations_
    FactId intern_fact(ValueId predicate, std::span<const ValueId> args);
    atms::NodeId ensure_assumption(FactId f);
    atms::InformantId new_firing(Firing f);
    void note_if_in(FactId f);
    // engine_run.cpp
    void run_strata(std::optional<std::uint32_t> context, Diagnostics& diagnostics, const RunOptions& options);
    // Takes n steps of the run's RunOptions::max_steps; if they would exceed it, stops the run
    // instead (stop()) and returns false.
    bool spend(std::size_t n, const CompiledRule& rule, const SourceLocation& where, Diagnostics& diagnostics);
    // Ends the current run: nothing more is matched or fired; a diagnostic at where, naming rule.
    void stop(const CompiledRule& rule, const SourceLocation& where, Diagnostics& diagnostics);
    void match_rule(RuleId r, std::optional<Seed> seed, std::optional<std::uint32_t> context,
                    Diagnostics& diagnostics, const Binding* initial = nullptr);
    bool drain(std::uint32_t stratum, std::optional<std::uint32_t> context, Diagnostics& diagnostics);
    void log_active(FactId f);
    void match_fresh(RuleId r, std::span<const FactId> fresh, std::optional<std::uint32_t> context,
                     Diagnostics& diagnostics);
    void close_contexts();
    // engine_closed_world.cpp
    [[nodiscard]] ClosedWorldStatus status(FactId f, std::optional<std::uint32_t> context);  // may intern envs
    [[nodiscard]] std::string why_undecidable(FactId f, std::optional<std::uint32_t> context) const;
    // engine_consequents.cpp
    void execute(RuleInstance& instance, Diagnostics& diagnostics);  // may change instance.binding
    std::optional<FactId> instantiate(const CompiledAtom& atom, const Binding& b, Diagnostics& diagnostics);
    void assume_fact(FactId f, atms::InformantId why, std::span<const atms::NodeId> antecedents);
    void declare_choice_set(const CompiledConsequent& c, const CompiledRule& rule, atms::InformantId why,
                            std::span<const atms::NodeId> antecedents, std::vector<atms::AssumptionId> set,
                            Diagnostics& diagnostics);

    std::shared_ptr<const SharedProgram> shared_;
    const CompiledProgram& program_;                     // shared_->program
    ValueTable values_;
    const BuiltinRegistry& builtins_;
    std::optional<BuiltinId> equals_;                    // builtins_.find("="), for every Matcher
    atms::Atms atms_;
    FactStore facts_;
    IdVector<FactId, FactNodes> fact_nodes_;
    IdVector<atms::DatumId, Datum> datums_;
    std::vector<Firing> firings_;                        // indexed by InformantId
    std::vector<std::unique_ptr<const SourceLocation>> locations_;  // of the facts drivers added (Firing::where)
    const SourceLocation context_where_{"<context>", 1, 1};  // of the closed-world firings
    Agenda agenda_;
    MatchBuffers match_buffers_;                         // every match_rule()'s matcher's
    std::vector<atms::NodeId> scratch_ants_;             // execute()'s antecedent nodes
    std::vector<ValueId> scratch_args_;                  // instantiate()'s arguments
    std::vector<FactId> pending_activation_;             // label became non-empty, not yet logged
    IdVector<RuleId, std::uint8_t> rule_matched_;               // a full match has been done
    // Facts that became active since each rule was last matched, of predicates it matches (in a
    // `match` or a quantifier), in activation order; woken_ lists the rules with some, ascending.
    IdVector<RuleId, std::vector<FactId>> rule_fresh_;
    std::vector<RuleId> woken_;
    std::vector<std::vector<atms::AssumptionId>> choice_sets_;
    std::vector<SourceLocation> choice_set_where_;       // the `exactly one` that declared each set
    std::vector<atms::JustId> choice_set_constraints_;   // each set's at-most-one constraint
    std::set<std::vector<atms::AssumptionId>> choice_set_keys_;  // every set seen, sorted (also refused ones)
    std::map<atms::AssumptionId, std::uint32_t> choice_set_of_;  // the choice set of each member
    std::vector<bool> is_choice_assumption_;             // indexed by AssumptionId
    std::vector<Context> contexts_;
    bool closed_world_used_ = false;
    RunOptions options_;                                 // of the current run
    EngineLimits limits_;
    std::size_t steps_ = 0;                              // taken by the current run
    bool stopped_ = false;                               // the current run ran out of steps
    std::size_t rule_firings_ = 0;
};
}  // namespace qm::engine
