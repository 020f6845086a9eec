// engine/rule_spec.hpp
// Provides:   ProgramSpec, a neutral, parser-independent description of a rule program (names are
//             still text, variables still names). rule_compiler.hpp turns it into a CompiledProgram;
//             rule_parser_to_spec.hpp fills it from the X3 parser's AST. Keeping this seam lets the
//             compiler be tested without the parser and keeps the parser's types out of the runtime.
// Ownership:  plain values.
// Knows nothing of the ATMS.
#pragma once
#include "qm/diagnostics.hpp"
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace qm::engine {

struct TermSpec {
    enum class Kind : std::uint8_t { symbol, integer, variable, direction, call, set } kind = Kind::symbol;
    std::string text;             // symbol name; variable name (without '?'); direction signs "+0-?"; call name
    std::int64_t integer = 0;
    std::vector<TermSpec> args;   // call arguments; set elements
    SourceLocation where;
};

struct AtomSpec {
    std::string predicate;
    std::vector<TermSpec> args;
    SourceLocation where;
};

struct TestSpec {
    std::string name;
    std::vector<TermSpec> args;
    SourceLocation where;
};

struct ConditionSpec {
    enum class Kind : std::uint8_t { atom, test, negation, for_all, exists, aggregate } kind = Kind::atom;
    AtomSpec atom;                // atom, negation, aggregate
    TestSpec test;                // test
    std::string variable;         // for_all, exists: the quantified variable; aggregate: the result
    TermSpec set;                 // for_all, exists
    std::vector<TestSpec> tests;  // for_all, exists
    std::vector<AtomSpec> atoms;  // for_all, exists
    std::string function;         // aggregate
    TermSpec value;               // aggregate: the summed term
    TermSpec start;               // aggregate
    SourceLocation where;
};

struct ConsequentSpec {
    enum class Kind : std::uint8_t { atom, falsity, for_all, assume, exactly_one } kind = Kind::atom;
    AtomSpec atom;
    std::string variable;         // for_all, exactly_one
    TermSpec set;
    std::vector<TestSpec> tests;
    SourceLocation where;
};

struct RuleSpec {
    std::string name;
    SourceLocation where;
    std::vector<ConditionSpec> conditions;
    std::vector<ConsequentSpec> consequents;
};

// `cite "TEXT"`: the thesis section, table, definition or law a file encodes (docs/RULES.md).
struct CitationSpec {
    std::string text;
    SourceLocation where;
};

// `prefer (c ?x ...) by (r ?x ... ?k) [up to N]` (docs/RULES.md "Preferences"): among
// interpretations, prefer those whose picks of c's choice sets rank lower by r, Pareto over the
// choice sets; a rank above N counts as N.
struct PreferenceSpec {
    AtomSpec choice;
    AtomSpec rank;
    std::optional<std::int64_t> up_to;
    SourceLocation where;
};

struct ProgramSpec {
    std::vector<RuleSpec> rules;
    std::vector<AtomSpec> facts;
    std::vector<AtomSpec> assumptions;
    // `input (p ?x ...)`: facts of p come from outside the program (a driver asserts them), so a
    // condition on p is not a misspelling; `output (p ?x ...)`: a driver reads p back, so a rule
    // concluding p is used (docs/RULES.md "Declarations"). Arguments are variables, for the reader.
    std::vector<AtomSpec> inputs;
    std::vector<AtomSpec> outputs;
    std::vector<CitationSpec> citations;  // in reading order; a file may cite more than once
    std::vector<PreferenceSpec> preferences;
};
}  // namespace qm::engine
