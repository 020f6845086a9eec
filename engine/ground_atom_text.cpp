// engine/ground_atom_text.cpp: a small recursive-descent reader for ground atoms (the full language
// is parsed by E1's Spirit X3 grammar; a ground atom needs only constants).
#include "engine/ground_atom_text.hpp"
#include <cctype>

namespace qm::engine {
namespace {

bool symbol_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '*' || c == '.';
}
bool sign_char(char c) { return c == '+' || c == '0' || c == '-' || c == '?'; }

struct Reader {
    std::string_view text;
    ValueTable& values;
    std::size_t pos = 0;
    std::string error;
    std::size_t error_pos = 0;

    void skip() {
        while (pos < text.size() && std::isspace(static_cast<unsigned char>(text[pos]))) ++pos;
    }
    bool fail(std::string message) {
        if (error.empty()) {
            error = std::move(message);
            error_pos = pos;
        }
        return false;
    }
    bool at_end() const { return pos >= text.size(); }
    // A lone sign: + 0 - ? not followed by a symbol character (so "-3" and "0a" are not signs).
    bool lone_sign(std::size_t p) const {
        return p < text.size() && sign_char(text[p]) && (p + 1 >= text.size() || !symbol_char(text[p + 1]) || text[p + 1] == '-');
    }

    // A parenthesised list of signs: a direction. Pre: text[pos] == '('.
    bool direction_ahead() const {
        std::size_t p = pos + 1;
        bool any = false;
        for (;;) {
            while (p < text.size() && std::isspace(static_cast<unsigned char>(text[p]))) ++p;
            if (p < text.size() && text[p] == ')') return any;
            if (p >= text.size() || !sign_char(text[p])) return false;
            if (p + 1 < text.size() && symbol_char(text[p + 1])) return false;
            any = true;
            ++p;
        }
    }

    std::optional<ValueId> value() {
        skip();
        if (at_end()) return fail("expected a value but found the end"), std::nullopt;
        char c = text[pos];
        if (c == '(') {
            if (!direction_ahead()) return fail("expected a direction of signs like (+ 0 -)"), std::nullopt;
            ++pos;
            std::string signs;
            for (skip(); text[pos] != ')'; skip()) signs += text[pos++];
            ++pos;
            return values.direction(signs);
        }
        if (c == '{') {
            ++pos;
            std::vector<ValueId> elements;
            for (skip(); !at_end() && text[pos] != '}'; skip()) {
                auto v = value();
                if (!v) return std::nullopt;
                elements.push_back(*v);
            }
            if (at_end()) return fail("expected '}'"), std::nullopt;
            ++pos;
            return values.set(std::move(elements));
        }
        std::size_t start = pos;
        if (c == '-' || std::isdigit(static_cast<unsigned char>(c))) {
            std::size_t p = pos + (c == '-' ? 1 : 0);
            std::size_t digits = p;
            while (p < text.size() && std::isdigit(static_cast<unsigned char>(text[p]))) ++p;
            if (p > digits && (p >= text.size() || !symbol_char(text[p]))) {
                try {
                    std::int64_t v = std::stoll(std::string(text.substr(start, p - start)));
                    pos = p;
                    return values.integer(v);
                } catch (const std::out_of_range&) {
                    return fail("integer out of range"), std::nullopt;
                }
            }
        }
        if (!std::isalpha(static_cast<unsigned char>(c))) return fail("expected a value"), std::nullopt;
        while (pos < text.size() && symbol_char(text[pos])) ++pos;
        return values.symbol(text.substr(start, pos - start));
    }

    std::optional<GroundAtom> atom() {
        skip();
        if (at_end() || text[pos] != '(') return fail("expected '(' to start a fact"), std::nullopt;
        ++pos;
        skip();
        std::size_t start = pos;
        if (at_end() || !std::isalpha(static_cast<unsigned char>(text[pos])))
            return fail("expected a predicate name"), std::nullopt;
        while (pos < text.size() && symbol_char(text[pos])) ++pos;
        GroundAtom a{values.symbol(text.substr(start, pos - start)), {}};
        for (skip(); !at_end() && text[pos] != ')'; skip()) {
            auto v = value();
            if (!v) return std::nullopt;
            a.args.push_back(*v);
        }
        if (at_end()) return fail("expected ')' to end the fact"), std::nullopt;
        ++pos;
        skip();
        if (!at_end()) return fail("unexpected text after the fact"), std::nullopt;
        return a;
    }
};

}  // namespace

GroundAtomParse parse_ground_atom(std::string_view text, ValueTable& values) {
    Reader r{text, values, 0, {}, 0};
    GroundAtomParse out;
    out.atom = r.atom();
    if (!out.atom) {
        out.error = r.error;
        out.column = static_cast<std::uint32_t>(r.error_pos + 1);
    }
    return out;
}

}  // namespace qm::engine
