// cli/line_editing_absent.cpp: open_line_editing() (cli/line_editor.hpp) in the light qm-atms, which
// is linked statically (docs/perf/startup.md) and so cannot load libedit (a shared library needing
// the shared C library). main hands a session on a terminal to qm-atms-geometry before it starts
// (cli/geometry_command.hpp, terminal_session), so no command line reaches this; were one to, the
// session would still work, with the prompt and no editing.
#include "line_editor.hpp"

namespace qm::cli {

std::unique_ptr<LineEditing> open_line_editing(std::ostream& err) {
    err << "qm-atms: note: no line editing (this executable is linked statically; qm-atms-geometry has it)\n";
    return nullptr;
}

}  // namespace qm::cli
