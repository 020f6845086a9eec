// engine/rule_compiler.hpp
// Provides:   compile_program(), ProgramSpec -> CompiledProgram: interns constants, numbers each
//             rule's variables into slots, resolves builtins, checks what the runtime relies on, and
//             assigns strata (a predicate used under `not` or aggregated gets a lower stratum than
//             the rules that use it that way). load_program() reads, checks and compiles one .rules
//             file (rule_folder.hpp loads several, and a driver's folder).
// Errors:     located diagnostics (never throws for bad input): unknown builtin or wrong arity, a
//             test used as a function or vice versa, a non-ground top-level fact, a variable used
//             before it is bound (in a builtin test, a quantifier's set, a `for all` atom, a
//             consequent), an unstratifiable program (negation or aggregation through recursion).
// Knows nothing of the ATMS.
#pragma once
#include "engine/builtin_registry.hpp"
#include "engine/compiled_rule.hpp"
#include "engine/rule_spec.hpp"
#include "engine/value_table.hpp"
#include "qm/diagnostics.hpp"
#include <map>
#include <optional>
#include <span>
#include <string>

namespace qm::engine {
struct LoadedProgram {
    CompiledProgram program;
    ValueTable values;
    std::map<std::string, std::string> citations;  // file -> its `cite` texts (law_check.hpp); load only
};

// Empty (with diagnostics) if the program has errors.
[[nodiscard]] std::optional<LoadedProgram> compile_program(const ProgramSpec& spec, Diagnostics& diagnostics,
                                                           const BuiltinRegistry& builtins = default_builtins());
// Reads path (and its includes), checks and compiles it (rule_folder.hpp's load_rule_files() of
// one file). Every diagnostic carries its source line.
[[nodiscard]] std::optional<LoadedProgram> load_program(const std::string& path, Diagnostics& diagnostics);
}  // namespace qm::engine
