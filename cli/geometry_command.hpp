// cli/geometry_command.hpp
// Provides:   geometry_command(), which runs a command line that needs the geometry stack
//             (needs_geometry(), cli/geometry_dispatch.hpp). It has two definitions, one linked
//             into each executable built from cli/ (docs/perf/startup.md):
//               - cli/geometry_command.cpp, in qm-atms-geometry: the command itself (envision,
//                 draw, explore, --emit-def, --places, or the analysis of a metric scene);
//               - cli/geometry_delegate.cpp, in the light qm-atms: replaces the process with the
//                 qm-atms-geometry found in the same folder as the running executable
//                 (/proc/self/exe), with the same argv, environment and standard streams, so the
//                 user sees one command whose output, errors and exit status are the full one's.
//             terminal_session(), which runs the interactive session of a scene read from a terminal
//             (interactive_on_terminal(), cli/geometry_dispatch.hpp), is defined the same two ways:
//             qm-atms-geometry runs the scene command, whose session edits lines with libedit;
//             the light qm-atms, linked statically so that it starts as fast as a process can
//             (docs/perf/startup.md), cannot load libedit and replaces itself with qm-atms-geometry
//             as for a geometry command: the person at the terminal gets line editing and history.
// Errors:     as the commands' (2 for bad input, diagnostics on err); the delegate returns 1 with
//             a message on err when qm-atms-geometry cannot be started (missing, not executable) for
//             a geometry command; for a terminal's session it notes that and runs the session
//             itself, without line editing.
//             qm::InternalError and resource limits propagate to main, which names `doing`.
#pragma once
#include <istream>
#include <ostream>
#include <span>
#include <string>

namespace qm::cli {

// argv: main's, argv[0] the program name; args: argv[1..] as strings; doing: what is being done,
// for main's internal-error messages.
[[nodiscard]] int geometry_command(char** argv, std::span<const std::string> args, std::istream& in, std::ostream& out,
                                   std::ostream& err, std::string& doing);
[[nodiscard]] int terminal_session(char** argv, std::span<const std::string> args, std::istream& in, std::ostream& out,
                                   std::ostream& err, std::string& doing);

}  // namespace qm::cli
