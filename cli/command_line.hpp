// cli/command_line.hpp
// Provides:   CommandLine, a reader of a command's arguments that words every option error the same
//             way (issue 19 item 4: each names the option and what it expected; a single-valued
//             option given twice is an error, not a silent replacement):
//               qm-atms: error: --limit expects a positive number, but nothing follows it
//               qm-atms: error: --limit expects a positive number, not 'ten'
//               qm-atms: error: --rules is given twice ('a', 'b'): give it once
//               qm-atms: error: unknown option '--lmit'
//             and positive(), a positive decimal number as options and the interactive mode take it.
// Ownership:  a CommandLine points into the caller's arguments and error stream for one parse.
#pragma once
#include <cstddef>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>

namespace qm::cli {

class CommandLine {
public:
    CommandLine(std::span<const std::string> args, std::ostream& err) : args_(args), err_(err) {}

    // Steps through the arguments: while (cl.next()) { cl.arg() ... }.
    [[nodiscard]] bool next() { return ++i_ < args_.size(); }
    [[nodiscard]] const std::string& arg() const { return args_[i_]; }
    [[nodiscard]] bool is_option() const { return !arg().empty() && arg()[0] == '-' && arg() != "-"; }

    // The argument after the current option, consumed; nullopt (reported: "OPTION expects WHAT,
    // but nothing follows it") at the end. `what` is e.g. "a positive number".
    [[nodiscard]] std::optional<std::string> value(std::string_view what);
    // The same for an option that may be given once: `slot` receives the value; false (reported)
    // when the value is missing or the option was given before.
    [[nodiscard]] bool single(std::optional<std::string>& slot, std::string_view what, std::string_view advice = {});
    // "OPTION expects WHAT, not 'VALUE'", for the option whose value was read last; returns false.
    bool bad_value(std::string_view what, const std::string& value);
    // "unknown option 'ARG'"; returns false.
    bool unknown();
    // "qm-atms: error: MESSAGE"; returns false.
    bool error(const std::string& message);

private:
    std::span<const std::string> args_;
    std::ostream& err_;
    std::size_t i_ = static_cast<std::size_t>(-1);
    std::string option_;  // the option whose value was read last
};

// A positive decimal number (no sign, no blanks); nullopt otherwise.
[[nodiscard]] std::optional<std::size_t> positive(std::string_view s);

}  // namespace qm::cli
