// engine/compiled_rule.hpp
// Provides:   the engine's executable form of a rule (CompiledRule) and of the program's top-level
//             facts, assumptions and preferences (CompiledProgram): variables are numbered slots, constants are
//             interned values, builtins are resolved to BuiltinIds. rule_compiler.hpp builds it from
//             E1's AST; the matcher and the engine only ever see this form.
// Ownership:  plain values owned by CompiledProgram.
// Invariants: every slot index is < CompiledRule::slot_count; conditions are evaluated in written
//             order (so `not` and aggregates see exactly the variables bound before them).
// Knows nothing of the ATMS.
#pragma once
#include "engine/fwd.hpp"
#include "engine/builtin_registry.hpp"
#include "engine/value.hpp"
#include "qm/diagnostics.hpp"
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace qm::engine {
using Slot = std::uint32_t;

struct CompiledTerm {
    enum class Kind : std::uint8_t { constant, variable, call } kind = Kind::constant;
    ValueId constant{};                // kind constant
    Slot slot = 0;                     // kind variable
    BuiltinId function{};              // kind call
    std::vector<CompiledTerm> args;    // kind call
};

struct CompiledAtom {
    ValueId predicate{};
    std::vector<CompiledTerm> args;
    SourceLocation where;
};

struct CompiledTest {
    BuiltinId test{};
    std::vector<CompiledTerm> args;
    SourceLocation where;
};

struct CompiledCondition {
    enum class Kind : std::uint8_t {
        match,       // atom: unify with an active fact
        test,        // test: a builtin test (`=` with an unbound variable on the left binds it)
        negation,    // atom: no fact of it holds (see docs/RULES.md "## Semantics")
        for_all,     // slot in set where tests: atoms, all must hold (each one an antecedent)
        exists,      // slot in set where tests: atoms, one firing per witness
        aggregate    // fold `function` over `value` of every fact matching atom, from start, into result
    } kind = Kind::match;
    CompiledAtom atom;                 // match, negation, aggregate
    CompiledTest test;                 // test
    Slot slot = 0;                     // for_all, exists: the quantified variable; aggregate: the result
    CompiledTerm set;                  // for_all, exists
    std::vector<CompiledTest> tests;   // for_all, exists
    std::vector<CompiledAtom> atoms;   // for_all, exists
    BuiltinId function{};              // aggregate
    CompiledTerm value;                // aggregate: the summed term (over the atom's variables)
    CompiledTerm start;                // aggregate
    std::vector<Slot> local_slots;     // aggregate: the atom's variables not bound before it
    SourceLocation where;
};

struct CompiledConsequent {
    enum class Kind : std::uint8_t {
        assert_atom,     // atom
        falsity,         // `false`: a nogood
        for_all_assert,  // slot in set where tests: atom (one assertion per element)
        assume_atom,     // `assume atom`
        exactly_one      // slot in set where tests: assume atom; a choice set
    } kind = Kind::assert_atom;
    CompiledAtom atom;
    Slot slot = 0;
    CompiledTerm set;
    std::vector<CompiledTest> tests;
    SourceLocation where;
};

struct CompiledRule {
    std::string name;
    SourceLocation where;
    std::vector<std::string> slot_names;      // "?x" per slot, for printing bindings
    std::vector<CompiledCondition> conditions;
    std::vector<CompiledConsequent> consequents;
    std::uint32_t stratum = 0;
    bool non_monotonic = false;               // has a negation or an aggregate
    [[nodiscard]] std::uint32_t slot_count() const noexcept {
        return static_cast<std::uint32_t>(slot_names.size());
    }
};

// A ground atom given at top level (`fact (...)` or `assume (...)`).
struct CompiledGroundAtom {
    ValueId predicate{};
    std::vector<ValueId> args;
    SourceLocation where;
};

// `prefer (c ?x ...) by (r ?x ... ?k) [up to N]` (docs/RULES.md "Preferences"): a fact of r ranks
// the member (c ...) of a choice set whose arguments it has at `key`; its rank is at `rank_at`.
struct CompiledPreference {
    ValueId choice{}, rank{};            // the predicates c and r
    std::vector<std::uint32_t> key;      // key[i]: where c's i-th argument is among r's
    std::uint32_t rank_at = 0;           // where the rank is among r's arguments
    std::optional<std::int64_t> up_to;   // a rank above counts as this
    SourceLocation where;
};

struct CompiledProgram {
    IdVector<RuleId, CompiledRule> rules;
    std::vector<CompiledGroundAtom> premises;
    std::vector<CompiledGroundAtom> assumptions;
    std::vector<CompiledPreference> preferences;
    std::uint32_t stratum_count = 1;
};
}  // namespace qm::engine
