// engine/ground_atom_text.hpp
// Provides:   parse_ground_atom(), which reads one ground atom written in the rule language's own
//             notation (the X3 grammar of rule_parser.hpp, so it accepts exactly what a rule file
//             accepts as a fact), e.g. "(queen 1 2)", "(trans-motion block (+ 0))",
//             "(s {(+ 0) (0 +)})", for `qm-atms run --why 'FACT'` and for drivers that name facts as text.
// Ownership:  interns the values it reads into the given ValueTable.
// Errors:     bad text (a syntax error, a variable, a function call) gives a message
//             `expected ... but found ...` and a 1-based column; it never throws.
// Knows nothing of the ATMS.
#pragma once
#include "engine/value_table.hpp"
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace qm::engine {
struct GroundAtom {
    ValueId predicate;
    std::vector<ValueId> args;
};

struct GroundAtomParse {
    std::optional<GroundAtom> atom;  // set on success
    std::string error;               // otherwise: what was wrong
    std::uint32_t column = 1;        // and where (1-based; the text is one line)
};

[[nodiscard]] GroundAtomParse parse_ground_atom(std::string_view text, ValueTable& values);
}  // namespace qm::engine
