// cli/check_command.hpp
// Provides:   check_command(), `qm-atms check [RULES-DIR | FILE.rules]... [--dimensions 2|3]`: reads
//             rule files as a program (a folder: every *.rules file directly in it, as the laws,
//             which must cite the thesis) and reports what the loaders report, without running
//             anything: syntax and semantic errors, unknown predicates ("did you mean"), rules that
//             can never fire or are unused, missing citations and, with --dimensions, direction
//             literals no scene of that many dimensions can match (docs/RULES.md "Checks").
//             With no path, the laws qm-atms would use (cli/rules_location.hpp).
// Errors:     diagnostics on err; returns 2 when there is an error (bad input), else 0 (warnings
//             alone do not fail); a one-line summary on out.
#pragma once
#include <ostream>
#include <span>
#include <string>

namespace qm::cli {
// args: the arguments after `check`.
[[nodiscard]] int check_command(std::span<const std::string> args, std::ostream& out, std::ostream& err);
[[nodiscard]] const char* check_usage() noexcept;
}  // namespace qm::cli
