// engine/why.hpp
// Provides:   why(), the explanation of a fact for drivers and `qm-atms run --why`: for a fact that
//             holds, one justification tree per label environment (ATMS explain); for a fact that is
//             ruled out (it has support, but every supporting environment is nogood), the minimal
//             nogoods that exclude it and the derivation of each. Every step names the informant:
//             the rule, its file:line and the binding of the firing (or "premise"/"assumption"),
//             and the `not` conditions the firing relied on.
// Ownership:  plain values, independent of the Engine once built.
// Knows nothing of mechanics.
#pragma once
#include "engine/engine.hpp"
#include "engine/run_report.hpp"
#include <string>
#include <vector>

namespace qm::engine {

struct WhyStep {
    std::string informant;                 // "rule same-column at queens4.rules:12", "premise at ..."
    std::vector<std::string> binding;      // "?r1 = 1", in slot order; bound slots only
    std::vector<std::string> antecedents;  // node texts; an assumption node reads "assume (f)"
    // The `not` conditions of the rule, under the firing's binding: "(penguin tweety)", a variable
    // local to the `not` kept as written: "(owns tweety ?x)". The firing relied on no fact matching
    // them (this is not an ATMS antecedent: see docs/RULES.md "## Semantics").
    std::vector<std::string> absent;
    std::string consequent;                // fact text, or "false"
};

struct Derivation {
    EnvText environment;                   // where it holds (or the nogood)
    std::vector<WhyStep> steps;            // leaves first
};

struct Why {
    enum class Status : std::uint8_t { holds, ruled_out, unsupported } status = Status::unsupported;
    std::string fact;
    std::vector<Derivation> derivations;   // holds: one per label environment
    std::vector<Derivation> nogoods;       // ruled_out: each excluding nogood and its derivation
};

// Pre: f issued by engine; the engine has been run.
[[nodiscard]] Why why(Engine& engine, FactId f);

// The `not` conditions of a rule firing under its binding, as WhyStep::absent gives them (empty for
// a firing that is not a rule's): the facts whose absence the firing relied on, for drivers that
// build their own explanations (the closed world is one assumption; these say what it was used for).
[[nodiscard]] std::vector<std::string> absent_conditions(Engine& engine, const Firing& firing);
}  // namespace qm::engine
