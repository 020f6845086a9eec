// cli/run_command.hpp
// Provides:   run_command(), the `qm-atms run PROGRAM.rules [--why 'FACT'] [--json]` command: loads and
//             runs a pure rule program and prints every fact with its label, the minimal nogoods and
//             the interpretations of the declared choice sets (or, with --json, exactly
//             {"facts": [...], "nogoods": [...], "interpretations": [...]}); --why prints the
//             justification tree of a fact or, if it is ruled out, the nogoods excluding it.
// Errors:     returns 2 for bad input (diagnostics written to err as file:line:col: error: ...),
//             0 otherwise. qm::InternalError propagates to main (exit 1).
#pragma once
#include <ostream>
#include <span>
#include <string>

namespace qm::cli {
// args: the arguments after `run`.
[[nodiscard]] int run_command(std::span<const std::string> args, std::ostream& out, std::ostream& err);
[[nodiscard]] std::string run_usage();
}  // namespace qm::cli
