// cli/line_editor.cpp: cli/line_editor.hpp on libedit's readline interface.
// libedit is opened (dlopen) only when a session reads a terminal: linked, it and the libraries it
// needs (libtinfo, libbsd, libmd) were loaded and relocated at every start of qm-atms, a quarter of
// the instructions of `qm-atms --help` once FCL was gone (docs/perf/startup.md), for the one mode
// that uses it. QM_LIBEDIT_SONAME is the name the build linked against (cli/CMakeLists.txt).
#include "line_editor.hpp"
#include <cstdio>
#include <cstdlib>
#include <dlfcn.h>
#include <editline/readline.h>
#include <iostream>
#include <unistd.h>

namespace qm::cli {

// The three functions of libedit's readline interface the session calls, typed by its header.
struct LineInput::Editline {
    decltype(&::readline) readline = nullptr;
    decltype(&::add_history) add_history = nullptr;
    decltype(&::using_history) using_history = nullptr;

    // Empty when libedit cannot be opened; the library then stays loaded for the process (it keeps
    // global state and, inside readline(), signal handlers: never unloaded).
    static std::unique_ptr<Editline> open() {
        void* lib = ::dlopen(QM_LIBEDIT_SONAME, RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
        if (lib == nullptr) return nullptr;
        auto e = std::make_unique<Editline>();
        e->readline = reinterpret_cast<decltype(&::readline)>(::dlsym(lib, "readline"));
        e->add_history = reinterpret_cast<decltype(&::add_history)>(::dlsym(lib, "add_history"));
        e->using_history = reinterpret_cast<decltype(&::using_history)>(::dlsym(lib, "using_history"));
        if (!e->readline || !e->add_history || !e->using_history) return nullptr;
        return e;
    }
};

LineInput::LineInput(std::istream& in, std::ostream& out)
    : in_(in), out_(out), terminal_(&in == &std::cin && isatty(STDIN_FILENO) != 0) {
    if (!terminal_) return;
    editline_ = Editline::open();
    if (editline_) editline_->using_history();
    else std::cerr << "qm-atms: note: no line editing (cannot open " << QM_LIBEDIT_SONAME << ": " << ::dlerror() << ")\n";
}

LineInput::~LineInput() = default;

std::optional<std::string> LineInput::next(const std::string& prompt) {
    if (!terminal_ || !editline_) {
        if (terminal_) out_ << prompt << std::flush;  // a terminal without libedit: the prompt, no editing
        std::string line;
        if (!std::getline(in_, line)) return std::nullopt;
        return line;
    }
    out_.flush();  // what was printed before the prompt, which libedit writes to the terminal itself
    char* raw = editline_->readline(prompt.c_str());
    if (raw == nullptr) {  // Ctrl-D
        out_ << '\n';
        out_.flush();
        return std::nullopt;
    }
    std::string line(raw);
    std::free(raw);
    if (line.find_first_not_of(" \t") != std::string::npos) editline_->add_history(line.c_str());
    return line;
}

}  // namespace qm::cli
