// engine/rule_folder.hpp
// Provides:   the one way a driver loads its rule program: rule_folder_files() lists a folder's
//             *.rules files; load_rule_files() reads them once into a ProgramSpec (the front end,
//             rule_spec_reader.hpp), checks it (rule_checker.hpp, predicate_check.hpp and, with law
//             options, law_check.hpp) and compiles it, keeping the spec beside the program so that
//             compile_slice() can compile any part of it (program_slice.hpp) without reading the
//             files again.
// Ownership:  CheckedProgram owns its spec and its compiled program (values, not shared).
// Errors:     located diagnostics, never an exception for bad input: a folder that cannot give rule
//             files (no such folder, a file, unreadable, no .rules file in it), every syntax error of
//             every file and every error of the checks and the compiler, each with its source line;
//             warnings beside a program that loads.
// Knows nothing of the ATMS or of any particular program: which laws there are is the folder's.
#pragma once
#include "engine/law_check.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_spec.hpp"
#include "qm/diagnostics.hpp"
#include <filesystem>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <vector>

namespace qm::engine {

// A program that read, checked and compiled without error.
struct CheckedProgram {
    ProgramSpec spec;        // as read: every file's items in load order
    LoadedProgram compiled;  // the whole program
};

// Every *.rules file directly in `folder`, in name order; empty, with an error at the folder saying
// why, when there is none.
[[nodiscard]] std::vector<std::string> rule_folder_files(const std::filesystem::path& folder, Diagnostics& diagnostics);

// Several files (say every file of a folder) as one program, in the order given; a file included by
// several of them is read once. Where predicates come from is checked only when no file has a syntax
// error (an item a syntax error dropped may be the one that states a predicate).
[[nodiscard]] std::optional<CheckedProgram> load_rule_files(std::span<const std::string> paths, Diagnostics& diagnostics,
                                                            const LawCheckOptions& laws = {});
// rule_folder_files(), then load_rule_files().
[[nodiscard]] std::optional<CheckedProgram> load_rule_folder(const std::filesystem::path& folder, Diagnostics& diagnostics,
                                                             const LawCheckOptions& laws = {});

// The part of the program that matters for `outputs` given facts of `inputs` (slice_program()),
// compiled. A part of a program that compiled compiles: a failure is an InternalError.
[[nodiscard]] LoadedProgram compile_slice(const CheckedProgram& program, const std::set<std::string>& inputs,
                                          const std::set<std::string>& outputs);

}  // namespace qm::engine
