// engine/rule_spec_reader.hpp
// Provides:   read_rule_file(), a small recursive-descent reader of the agreed rule syntax (the
//             "starting point" of docs/RULES.md) straight into a ProgramSpec, following `include`s
//             relative to the including file. It is the runtime's interim front end, used by
//             load_program() while E1's Spirit X3 parser and loader (engine/rule_parser.*,
//             engine/program_loader.*) are not in the tree; once they are, load_program() should
//             parse with them and convert the AST to a ProgramSpec instead.
// Layout:     a top-level item (`include`, `fact`, `assume`, `rule`) starts in column 1; a rule's
//             conditions and consequents continue on indented lines. This is what separates a
//             consequent `assume (...)` from a following top-level `assume (...)`.
// Errors:     located diagnostics `expected ... but found ...`; reading resumes at the next top-level
//             item, so one run reports several errors. Include cycles and missing files are located
//             at the `include`. Never throws for bad input.
// Knows nothing of the ATMS.
#pragma once
#include "engine/builtin_registry.hpp"
#include "engine/rule_spec.hpp"
#include "qm/diagnostics.hpp"
#include <string>

namespace qm::engine {
// Appends the items of path (and its includes, each read once) to spec.
void read_rule_file(const std::string& path, ProgramSpec& spec, Diagnostics& diagnostics,
                    const BuiltinRegistry& builtins = default_builtins());
// Reads text as if it were the file `name` (includes resolved relative to name's directory).
void read_rule_text(const std::string& text, const std::string& name, ProgramSpec& spec, Diagnostics& diagnostics,
                    const BuiltinRegistry& builtins = default_builtins());
}  // namespace qm::engine
