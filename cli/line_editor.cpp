// cli/line_editor.cpp: cli/line_editor.hpp. The editing functions are the executable's
// (open_line_editing: cli/line_editing_libedit.cpp in qm-atms-geometry, cli/line_editing_absent.cpp
// in the light qm-atms).
#include "line_editor.hpp"
#include <cstdlib>
#include <iostream>
#include <unistd.h>

namespace qm::cli {

LineInput::LineInput(std::istream& in, std::ostream& out)
    : in_(in), out_(out), terminal_(&in == &std::cin && isatty(STDIN_FILENO) != 0) {
    if (!terminal_) return;
    editline_ = open_line_editing(std::cerr);
    if (editline_) editline_->using_history();
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
