// cli/line_editor.hpp
// Provides:   LineInput, where the interactive mode (cli/session.hpp) reads its commands: from a
//             terminal through libedit (BSD editline, Debian package libedit-dev; its readline
//             interface): a prompt, line editing (arrows, Ctrl-A/E, ...) and a history recalled
//             with Up/Down; from anything else (a pipe, a file, a test's stream) line by line with
//             no prompt, so a script's output holds only the answers. The editing functions come
//             from open_line_editing(), defined once per executable (docs/perf/startup.md):
//             qm-atms-geometry loads libedit when a terminal is read, not at start-up
//             (cli/line_editing_libedit.cpp); the light qm-atms, linked statically, cannot load a
//             shared library and hands a terminal's session to qm-atms-geometry before one starts
//             (cli/geometry_command.hpp, terminal_session), so its open_line_editing()
//             (cli/line_editing_absent.cpp) is reached by no command line. Without editing, a
//             terminal gets the prompt without editing, after a note on standard error.
// Ownership:  a LineInput borrows the stream it reads; one terminal LineInput at a time (libedit's
//             readline interface keeps global state).
// Errors:     none: the end of the input (Ctrl-D on a terminal) is an empty optional.
#pragma once
#include <istream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>

namespace qm::cli {

// libedit's readline interface, the three functions a session calls.
struct LineEditing {
    char* (*readline)(const char* prompt) = nullptr;
    int (*add_history)(const char* line) = nullptr;
    void (*using_history)() = nullptr;
};

// The line editing of this executable, or null after a note on err saying why there is none.
[[nodiscard]] std::unique_ptr<LineEditing> open_line_editing(std::ostream& err);

class LineInput {
public:
    // A terminal when `in` is std::cin and standard input is a terminal.
    LineInput(std::istream& in, std::ostream& out);
    ~LineInput();
    LineInput(const LineInput&) = delete;
    LineInput& operator=(const LineInput&) = delete;
    [[nodiscard]] bool terminal() const noexcept { return terminal_; }
    // The next line without its newline, after showing `prompt` on a terminal; a non-blank line
    // read from a terminal joins the history. At the end of a terminal's input a newline is
    // written, so the shell's prompt starts on a line of its own.
    [[nodiscard]] std::optional<std::string> next(const std::string& prompt);

private:
    std::istream& in_;
    std::ostream& out_;
    bool terminal_ = false;
    std::unique_ptr<LineEditing> editline_;  // opened for a terminal
};

}  // namespace qm::cli
