// engine/rule_spec_reader.hpp
// Provides:   the front end of the rule language: read_rule_file() / read_rule_files() /
//             read_rule_text() parse rule files with the Spirit X3 parser (rule_parser.hpp), follow
//             `include "FILE"` (relative to the including file; each file is read once, in the place
//             of its first include) and append every fact, assumption and rule, in source order, to a
//             ProgramSpec (rule_parser_to_spec.hpp). load_program() (rule_compiler.hpp) then checks and
//             compiles it.
// Ownership:  the texts read are recorded in the optional SourceTexts, so that later diagnostics
//             (checker, compiler, engine) can be shown with their source line.
// Errors:     located diagnostics only, never an exception for bad input: every syntax error of every
//             file (the parser resumes at the next top-level item), an unreadable file, an include
//             cycle (at the `include`) and a missing included file (at its name).
// Knows nothing of the ATMS.
#pragma once
#include "engine/builtin_registry.hpp"
#include "engine/rule_parser_source.hpp"
#include "engine/rule_spec.hpp"
#include "qm/diagnostics.hpp"
#include <span>
#include <string>

namespace qm::engine {
// Appends the items of path (and of its includes) to spec.
void read_rule_file(const std::string& path, ProgramSpec& spec, Diagnostics& diagnostics,
                    const BuiltinRegistry& builtins = default_builtins(), SourceTexts* sources = nullptr);
// Reads several files into one spec, in the order given, as if each were included in turn (a file
// reached twice is read once).
void read_rule_files(std::span<const std::string> paths, ProgramSpec& spec, Diagnostics& diagnostics,
                     const BuiltinRegistry& builtins = default_builtins(), SourceTexts* sources = nullptr);
// Reads text as if it were the file `name` (includes resolved relative to name's directory).
void read_rule_text(const std::string& text, const std::string& name, ProgramSpec& spec, Diagnostics& diagnostics,
                    const BuiltinRegistry& builtins = default_builtins(), SourceTexts* sources = nullptr);
}  // namespace qm::engine
