// engine/program_slice.hpp
// Provides:   slice_program(), the part of a rule program that matters for some outputs given the
//             predicates a driver will assert: a rule is kept when it can fire (every predicate of
//             its positive atoms and `exists` atoms can have facts: asserted, a fact or assumption of
//             the program, or concluded by a rule that can fire; `not`, `for all` and aggregates do
//             not need facts to hold) and it concludes an output, a predicate a kept rule reads
//             (under `not` and aggregates too), or `false`. A `prefer` declaration is kept when a
//             kept rule concludes or assumes its chosen predicate; its rank predicate is then read
//             (the preference query reads it), so the rules concluding the ranks are kept too. The
//             program's facts and assumptions of the predicates kept rules and preferences read are
//             kept. Rules and preferences keep their order, rules their names; a driver that makes
//             many small engines over one program (one per state) pays only for the rules that can
//             matter there.
// Ownership:  values in, a value out.
// Invariants: for every output predicate, an engine over the slice derives the same facts with the
//             same labels as one over the whole program from any facts of the input predicates
//             (a rule left out can never fire, or nothing it concludes is read), and where an
//             output is a preference's chosen predicate, the same rank facts, so the same preferred
//             interpretations; tested in tests/engine/program_slice_test.cpp.
// Knows nothing of the ATMS or of any particular program.
#pragma once
#include "engine/rule_spec.hpp"
#include <set>
#include <string>

namespace qm::engine {

[[nodiscard]] ProgramSpec slice_program(const ProgramSpec& program, const std::set<std::string>& inputs,
                                        const std::set<std::string>& outputs);

}  // namespace qm::engine
