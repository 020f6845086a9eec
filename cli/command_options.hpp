// cli/command_options.hpp
// Provides:   CommandOptions, one command's command line read by CLI11: its flags, single-valued and
//             repeatable options and positional arguments, each declared with what it expects, and
//             parse(), which answers --help (the command's usage, on out) and --version
//             (version_text()) and words every error one way, followed by the usage (exit 2):
//               qm-atms: error: --limit expects a positive number of combinations, but nothing follows it
//               qm-atms: error: --rules is given twice ('a', 'b'): give it once
//               qm-atms: error: unknown option '--lmit'; did you mean '--limit'?
//               qm-atms: error: --json takes no value, but is given 'yes'
//             CLI11 reads the words (`--opt value`, `--opt=value`, `-i`, and `--` before arguments
//             that begin with '-'); the wording, "did you mean" (qm/spelling.hpp) and "given
//             twice" are ours, as CLI11 2.1 has neither. A value is taken as given, even one that
//             begins with '-' (`--max-environments -5` is a bad number, not an unknown option).
//             positive(): a positive decimal number, as options and the interactive mode take it.
// Ownership:  the targets given to the declarations are the caller's; they must outlive parse(),
//             which writes them. CLI11 is included by command_options.cpp only.
#pragma once
#include "qm/diagnostics.hpp"
#include <cstddef>
#include <memory>
#include <optional>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace qm::cli {

class CommandOptions {
public:
    // usage: printed by --help and after an error; a usage line as the top-level usage lists it
    // (indented to follow "usage: ") is printed as the command's own, "usage: qm-atms ...".
    explicit CommandOptions(std::string usage);
    ~CommandOptions();
    CommandOptions(const CommandOptions&) = delete;
    CommandOptions& operator=(const CommandOptions&) = delete;

    // names: "--json", or "-i,--interactive". Given more than once is the same as once.
    void flag(const std::string& names, bool& target);
    // what: e.g. "a positive number"; advice: what to do instead of giving it twice ("give it once").
    void single(const std::string& name, std::string what, std::optional<std::string>& target, std::string advice = {});
    void repeated(const std::string& name, std::string what, std::vector<std::string>& target);
    // Every argument that is not an option, in order (the command checks how many it takes).
    void positionals(std::vector<std::string>& target);
    // The place cache's two options, `--cache DIR` and `--no-cache` (bridge/pair_places.hpp); parse()
    // refuses both at once.
    void place_cache(std::optional<std::string>& dir, bool& no_cache);
    // Options that name other commands when they come first (`--places`), proposed for a misspelt first argument.
    void first_may_be(std::vector<std::string> names);

    // nullopt: read, the targets written; otherwise the exit status to return at once: 0 after
    // --help or --version, 2 after an error (reported on err with the usage).
    [[nodiscard]] std::optional<int> parse(std::span<const std::string> args, std::ostream& out, std::ostream& err);

    // For the checks a command makes after parse(): "qm-atms: error: MESSAGE" and the usage; returns 2.
    int error(std::ostream& err, const std::string& message) const;
    // "OPTION expects WHAT, not 'VALUE'", with the option's declared `what`; returns 2.
    int bad_value(std::ostream& err, const std::string& option, const std::string& value) const;
    [[nodiscard]] const std::string& usage() const noexcept { return usage_; }

private:
    struct Parser;
    std::string usage_;
    std::unique_ptr<Parser> parser_;
};

// "qm-atms VERSION" (the CMake project's version), as --version prints it.
[[nodiscard]] std::string version_text();

// Bad input found after parse() (a scene that does not read, say): prints the diagnostics and
// returns 2, its exit status.
int bad_input(const Diagnostics& diagnostics, std::ostream& err);

// A positive decimal number (no sign, no blanks); nullopt otherwise.
[[nodiscard]] std::optional<std::size_t> positive(std::string_view s);

}  // namespace qm::cli
