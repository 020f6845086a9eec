// engine/matcher.hpp
// Provides:   Matcher, which enumerates the matches of a compiled rule's conditions against the
//             active facts, in written order (depth first, candidates in activation order, so the
//             output order is deterministic). A seed restricts one `match` condition to one fact:
//             the engine seeds with each newly active fact (semi-naive evaluation).
//             ClosedWorld is how the engine tells the matcher whether a fact holds for `not` and for
//             aggregates; the matcher itself never consults the ATMS.
// Ownership:  borrows the store, table and registry; holds no state between calls but the count of
//             steps taken against an optional limit (limit_steps()).
// Invariants: every match reports as antecedents exactly the facts its conditions used: one per
//             `match`, one per atom per element of a `for all`, the witness facts of an `exists`,
//             and the facts folded by an aggregate.
// Knows nothing of the ATMS.
#pragma once
#include "engine/binding.hpp"
#include "engine/compiled_rule.hpp"
#include "engine/fact_store.hpp"
#include "engine/match_plan.hpp"
#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>

namespace qm::engine {

enum class ClosedWorldStatus : std::uint8_t { holds, absent, undecidable };

struct ClosedWorld {
    // Whether the fact holds for the purpose of `not` and aggregates (see docs/RULES.md "## Semantics").
    std::function<ClosedWorldStatus(FactId)> status;
    // Why status() answered undecidable, for the diagnostic.
    std::function<std::string(FactId)> why_undecidable;
};

struct Seed {
    std::uint32_t condition;  // index of a `match` condition
    FactId fact;
};

// The working vectors of one match() call. A caller that matches again and again (an engine, once
// per seed fact) keeps one and hands it to its matchers, so that the vectors keep their capacity
// from one call to the next instead of growing from nothing each time. Contents are the matcher's.
struct MatchBuffers {
    Binding binding;
    std::vector<Slot> trail;
    std::vector<FactId> antecedents;
    std::vector<ValueId> scratch;
    std::vector<FactId> matched_at;
};

struct MatchError {
    SourceLocation where;
    std::string message;
};

class Matcher {
public:
    using OnMatch = std::function<void(const Binding&, std::span<const FactId> antecedents)>;
    using OnError = std::function<void(const MatchError&)>;

    Matcher(const FactStore& facts, ValueTable& values, const BuiltinRegistry& builtins,
            const ClosedWorld& closed_world);
    // The same with the id of builtins' `=` looked up by the caller (an engine makes a matcher for
    // every seed fact: the lookup by name showed in the profile). Pre: equals == builtins.find("=").
    Matcher(const FactStore& facts, ValueTable& values, const BuiltinRegistry& builtins,
            const ClosedWorld& closed_world, std::optional<BuiltinId> equals);
    // The same, match() working in buffers (borrowed; not used by another match at the same time).
    Matcher(const FactStore& facts, ValueTable& values, const BuiltinRegistry& builtins,
            const ClosedWorld& closed_world, std::optional<BuiltinId> equals, MatchBuffers& buffers);
    // Pre: plan is plan_matching(rule); a seed names a `match` condition of rule and an active
    // fact; `initial`, if given, has rule.slot_count() slots. Matching starts from `initial` (some
    // variables already bound).
    void match(const CompiledRule& rule, const MatchPlan& plan, std::optional<Seed> seed, const OnMatch& on_match,
               const OnError& on_error, const Binding* initial = nullptr);
    // Bounds the work of this matcher's match() calls: a step is one fact tried against an atom
    // (for a `match`, `exists`, `not` or aggregate) or one element of a quantifier's set. Once
    // `steps` are taken, matching stops where it is: no further match is reported.
    void limit_steps(std::size_t steps) noexcept { step_limit_ = steps; }
    [[nodiscard]] std::size_t steps() const noexcept { return steps_; }    // taken so far
    [[nodiscard]] bool stopped() const noexcept { return stopped_; }      // the limit was reached
    // The binding of the rule's variables that unifying `atom` (an atom inside a quantifier of the
    // rule whose quantified variable is `local`) with fact f gives, less `local`: a new fact can
    // complete a `for all` or an `exists` only for such bindings. Empty if they do not unify, or if
    // the atom has a function call that needs the quantified variable.
    [[nodiscard]] std::optional<Binding> prebind(const CompiledRule& rule, const CompiledAtom& atom, Slot local,
                                                 FactId f);

private:
    struct Run;
    const FactStore& facts_;
    ValueTable& values_;
    const BuiltinRegistry& builtins_;
    const ClosedWorld& closed_world_;
    std::optional<BuiltinId> equals_;
    MatchBuffers* buffers_ = nullptr;
    std::optional<std::size_t> step_limit_;
    std::size_t steps_ = 0;
    bool stopped_ = false;
};
}  // namespace qm::engine
