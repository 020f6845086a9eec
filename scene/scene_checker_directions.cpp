// scene/scene_checker_directions.cpp: the leaves of the scene checker (scene/detail/scene_checker.hpp):
// located errors, sign tokens and qualitative directions (section 2.1, Definitions 1-2; the
// arities of Table 2.1), and the small text helpers the other scene_checker*.cpp files share.
#include "scene/detail/scene_checker.hpp"

#include <algorithm>
#include <cctype>

namespace qm::scene::detail {

std::string lower(const std::string& s) {
    std::string out = s;
    for (char& c : out) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return out;
}

std::string plural(std::size_t n, const char* word) { return std::to_string(n) + " " + word + (n == 1 ? "" : "s"); }

std::string line_column(const SourceLocation& l) {
    return "line " + std::to_string(l.line) + ", column " + std::to_string(l.column);
}

SourceLocation CheckContext::where(const ast::x3::position_tagged& node) const {
    return src_.locate(pos_.offset_of(node));
}

void CheckContext::error(const ast::x3::position_tagged& node, std::string message, std::vector<std::string> notes) {
    const std::size_t off = pos_.offset_of(node);
    diags_.add(Severity::error, src_.locate(off), std::move(message), src_.line_at(off), std::move(notes));
    ++errors_;
}

void CheckContext::warning(const ast::x3::position_tagged& node, std::string message) {
    const std::size_t off = pos_.offset_of(node);
    diags_.add(Severity::warning, src_.locate(off), std::move(message), src_.line_at(off));
}

std::string CheckContext::text_of(const ast::SignToken& t) const {
    const std::string& text = src_.text();
    const std::size_t off = pos_.offset_of(t);
    return off < text.size() ? text.substr(off, t.length) : std::string();
}

std::optional<PatternSlot> CheckContext::slot(const ast::SignToken& t, bool allow_variable) {
    const std::string s = text_of(t);
    if (s == "+") return PatternSlot{Sign::plus, {}};
    if (s == "0") return PatternSlot{Sign::zero, {}};
    if (s == "-") return PatternSlot{Sign::minus, {}};
    if (s.size() > 1 && s[0] == '?') {
        const bool ok_name = std::all_of(s.begin() + 1, s.end(), [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
        });
        if (!ok_name) {
            error(t, "bad variable '" + s + "': a variable is '?' followed by letters, digits, '-' or '_'");
        } else if (!allow_variable) {
            error(t, "variable '" + s + "' is allowed only in constraint entries; write a sign '+', '0' or '-'");
        } else {
            return PatternSlot{std::nullopt, lower(s.substr(1))};
        }
        return std::nullopt;
    }
    if (s == "--")
        error(t, "bad sign '--': a sign is '+', '0' or '-' (the thesis' OCR prints '-' as '--'; write '-')");
    else if (s.size() > 1 && s.find_first_not_of("+-0") == std::string::npos)
        error(t, "bad sign '" + s + "': a sign is one of '+', '0', '-'; separate the signs of a direction by blanks");
    else
        error(t, "bad sign '" + s + "': expected '+', '0' or '-'");
    return std::nullopt;
}

std::optional<DirectionPattern> CheckContext::pattern(const ast::Direction& d, std::size_t arity,
                                                      const std::string& role, bool allow_variables) {
    DirectionPattern out;
    bool ok = true;
    for (const auto& t : d.parts) {
        auto s = slot(t, allow_variables);
        if (s) out.push_back(*s);
        else ok = false;
    }
    if (ok && d.parts.size() != arity) {
        error(d, role + " needs " + plural(arity, "sign") + " in a " + std::to_string(dims_) + "-D scene but has " +
                     std::to_string(d.parts.size()));
        ok = false;
    }
    return ok ? std::optional(out) : std::nullopt;
}

std::optional<Direction> CheckContext::direction(const ast::Direction& d, std::size_t arity, const std::string& role) {
    auto p = pattern(d, arity, role, false);
    if (!p) return std::nullopt;
    Direction out;
    for (const auto& s : *p) out.push_back(*s.sign);
    return out;
}

}  // namespace qm::scene::detail
