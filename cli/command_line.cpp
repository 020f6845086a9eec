// cli/command_line.cpp: the wording of command-line errors (cli/command_line.hpp).
#include "command_line.hpp"
#include <charconv>

namespace qm::cli {

std::optional<std::string> CommandLine::value(std::string_view what) {
    option_ = arg();
    if (i_ + 1 >= args_.size()) {
        error(arg() + " expects " + std::string(what) + ", but nothing follows it");
        return std::nullopt;
    }
    return args_[++i_];
}

bool CommandLine::single(std::optional<std::string>& slot, std::string_view what, std::string_view advice) {
    const std::string option = arg();
    auto v = value(what);
    if (!v) return false;
    if (slot) {
        return error(option + " is given twice ('" + *slot + "', '" + *v + "'): " +
                     (advice.empty() ? std::string("give it once") : std::string(advice)));
    }
    slot = std::move(*v);
    return true;
}

bool CommandLine::bad_value(std::string_view what, const std::string& value) {
    return error(option_ + " expects " + std::string(what) + ", not '" + value + "'");
}

bool CommandLine::unknown() { return error("unknown option '" + arg() + "'"); }

bool CommandLine::error(const std::string& message) {
    err_ << "qm-atms: error: " + message + "\n";
    return false;
}

std::optional<std::size_t> positive(std::string_view s) {
    std::size_t v = 0;
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc{} || p != s.data() + s.size() || v == 0) return std::nullopt;
    return v;
}

}  // namespace qm::cli
