// cli/geometry_dispatch.hpp
// Provides:   needs_geometry(), which of the two executables built from cli/ runs a command line
//             (docs/perf/startup.md). `qm-atms` is light: the engine, the Alex scene language and
//             analysis, the rule checker; it links none of the geometry stack (FCL, geometry/,
//             bridge/, envision/), whose loading alone cost 17.7 M of the 18.1 M instructions of
//             `qm-atms --help` (libfcl's 29,183 BIND_NOW relocations). `qm-atms-geometry` is built
//             from the same sources with the geometry stack; the light one hands it every command
//             line that needs geometry, unchanged (cli/geometry_command.hpp), so users see one
//             command. needs_geometry() is true for:
//               - `envision`, `draw`, `explore`, `--emit-def`, `--places` (the first argument);
//               - a scene analysis (`qm-atms SCENE [options]`, with -i too) whose scene file is a
//                 metric scene: it opens with `(Defmechanism` (is_metric_scene(); --config is only
//                 valid there). The interactive session of an Alex scene needs no geometry:
//                 its queries (cli/session.hpp) work on the loaded analysis and cannot open a
//                 metric scene (read from a terminal it is handed on all the same, for its line
//                 editing: interactive_on_terminal() below).
//             and false for everything else: `run`, `check`, `--help`, an Alex scene, and a command
//             line the light executable rejects anyway (a bad option, an unreadable scene file),
//             whose message is the same text in both.
//             interactive_on_terminal(): a scene analysis with -i whose standard input is a
//             terminal (not a metric scene: needs_geometry() is asked first). The light qm-atms is
//             linked statically and cannot load libedit, so it hands such a session to
//             qm-atms-geometry too (terminal_session(), cli/geometry_command.hpp); a session read
//             from a pipe or a file (no editing) stays light.
// Errors:     none: a file that cannot be read is left to the command that reads it.
#pragma once
#include <span>
#include <string>
#include <string_view>

namespace qm::cli {

// args: the command line without the program name (argv[1..]).
[[nodiscard]] bool needs_geometry(std::span<const std::string> args);

// input_is_terminal: whether standard input is a terminal (isatty), given so that tests can ask both.
[[nodiscard]] bool interactive_on_terminal(std::span<const std::string> args, bool input_is_terminal);

// A metric scene (docs/METRIC_SCENE_FORMAT.md) opens with `(Defmechanism`, after a byte-order mark,
// blanks and `;` comments (the name in any case); an Alex scene (docs/SCENE_FORMAT.md) does not.
[[nodiscard]] bool is_metric_scene(std::string_view text);

}  // namespace qm::cli
