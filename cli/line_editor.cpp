// cli/line_editor.cpp: cli/line_editor.hpp, on libedit's readline interface.
#include "line_editor.hpp"
#include <cstdlib>
#include <editline/readline.h>
#include <iostream>
#include <unistd.h>

namespace qm::cli {

LineInput::LineInput(std::istream& in, std::ostream& out)
    : in_(in), out_(out), terminal_(&in == &std::cin && isatty(STDIN_FILENO) != 0) {
    if (terminal_) ::using_history();
}

std::optional<std::string> LineInput::next(const std::string& prompt) {
    if (!terminal_) {
        std::string line;
        if (!std::getline(in_, line)) return std::nullopt;
        return line;
    }
    out_.flush();  // what was printed before the prompt, which libedit writes to the terminal itself
    char* raw = ::readline(prompt.c_str());
    if (raw == nullptr) {  // Ctrl-D
        out_ << '\n';
        out_.flush();
        return std::nullopt;
    }
    std::string line(raw);
    std::free(raw);
    if (line.find_first_not_of(" \t") != std::string::npos) ::add_history(line.c_str());
    return line;
}

}  // namespace qm::cli
