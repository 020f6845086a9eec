// cli/line_editing_libedit.cpp: open_line_editing() (cli/line_editor.hpp) in qm-atms-geometry: libedit,
// opened (dlopen) only when a session reads a terminal. Linked, it and the libraries it needs
// (libtinfo, libbsd, libmd) were loaded and relocated at every start, a quarter of the instructions
// of `qm-atms --help` once FCL was gone (docs/perf/startup.md), for the one mode that uses it.
// QM_LIBEDIT_SONAME is the name the build found (cli/CMakeLists.txt).
#include "line_editor.hpp"
#include <dlfcn.h>
#include <editline/readline.h>
#include <type_traits>

namespace qm::cli {

// LineEditing's members are typed as libedit's header declares them.
static_assert(std::is_same_v<decltype(LineEditing::readline), decltype(&::readline)>);
static_assert(std::is_same_v<decltype(LineEditing::add_history), decltype(&::add_history)>);
static_assert(std::is_same_v<decltype(LineEditing::using_history), decltype(&::using_history)>);

// The library stays loaded for the process (it keeps global state and, inside readline(), signal
// handlers: never unloaded).
std::unique_ptr<LineEditing> open_line_editing(std::ostream& err) {
    void* lib = ::dlopen(QM_LIBEDIT_SONAME, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    auto e = std::make_unique<LineEditing>();
    if (lib != nullptr) {
        e->readline = reinterpret_cast<decltype(&::readline)>(::dlsym(lib, "readline"));
        e->add_history = reinterpret_cast<decltype(&::add_history)>(::dlsym(lib, "add_history"));
        e->using_history = reinterpret_cast<decltype(&::using_history)>(::dlsym(lib, "using_history"));
        if (e->readline && e->add_history && e->using_history) return e;
    }
    const char* why = ::dlerror();
    err << "qm-atms: note: no line editing (cannot open " << QM_LIBEDIT_SONAME << ": " << (why ? why : "no readline interface")
        << ")\n";
    return nullptr;
}

}  // namespace qm::cli
