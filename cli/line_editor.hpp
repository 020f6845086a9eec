// cli/line_editor.hpp
// Provides:   LineInput, where the interactive mode (cli/session.hpp) reads its commands: from a
//             terminal through libedit (BSD editline, Debian package libedit-dev; its readline
//             interface): a prompt, line editing (arrows, Ctrl-A/E, ...) and a history recalled
//             with Up/Down; from anything else (a pipe, a file, a test's stream) line by line with
//             no prompt, so a script's output holds only the answers.
// Ownership:  a LineInput borrows the stream it reads; one terminal LineInput at a time (libedit's
//             readline interface keeps global state).
// Errors:     none: the end of the input (Ctrl-D on a terminal) is an empty optional.
#pragma once
#include <istream>
#include <optional>
#include <ostream>
#include <string>

namespace qm::cli {

class LineInput {
public:
    // A terminal when `in` is std::cin and standard input is a terminal.
    LineInput(std::istream& in, std::ostream& out);
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
};

}  // namespace qm::cli
