// engine/rule_compiler.hpp
// Provides:   compile_program(), ProgramSpec -> CompiledProgram: interns constants, numbers each
//             rule's variables into slots, resolves builtins, checks what the runtime relies on, and
//             assigns strata (a predicate used under `not` or aggregated gets a lower stratum than
//             the rules that use it that way). load_program() reads a .rules file with the front end
//             (rule_spec_reader.hpp), checks it (rule_checker.hpp) and compiles it.
// Errors:     located diagnostics (never throws for bad input): unknown builtin or wrong arity, a
//             test used as a function or vice versa, a non-ground top-level fact, a variable used
//             before it is bound (in a builtin test, a quantifier's set, a `for all` atom, a
//             consequent), an unstratifiable program (negation or aggregation through recursion).
// Knows nothing of the ATMS.
#pragma once
#include "engine/builtin_registry.hpp"
#include "engine/compiled_rule.hpp"
#include "engine/law_check.hpp"
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
// Reads path (and its includes), checks and compiles it. Every diagnostic carries its source line.
[[nodiscard]] std::optional<LoadedProgram> load_program(const std::string& path, Diagnostics& diagnostics);
// Loads several files (e.g. every law file of rules/) into one program, in the order given; a file
// included by several of them is read once. Also where predicates come from (predicate_check.hpp;
// skipped after a syntax error, which may have dropped a predicate's source) and, with law options,
// the checks of law_check.hpp.
// Warnings go into diagnostics beside a program that loads.
[[nodiscard]] std::optional<LoadedProgram> load_programs(std::span<const std::string> paths, Diagnostics& diagnostics,
                                                         const LawCheckOptions& laws = {});
// The same, and gives every file the load read (those named and those they include), each with
// the text it was read with, for diagnostics that quote a source line.
class SourceTexts;
[[nodiscard]] std::optional<LoadedProgram> load_programs(std::span<const std::string> paths, Diagnostics& diagnostics,
                                                         const LawCheckOptions& laws, SourceTexts& sources);
}  // namespace qm::engine
