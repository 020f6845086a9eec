// tests/support/json_value.hpp: a small strict JSON reader (RFC 8259) for tests that check the JSON
// the program prints (objects, arrays, strings with escapes, numbers, true/false/null).
// parse() returns nullopt on any syntax error or trailing garbage.
#pragma once
#include <cctype>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace qm::test {

struct Json {
    using Object = std::map<std::string, Json>;
    using Array = std::vector<Json>;
    std::variant<std::nullptr_t, bool, double, std::string, Array, Object> value;
    std::vector<std::string> keys = {};  // an object's keys, in the order read

    [[nodiscard]] bool is_object() const { return std::holds_alternative<Object>(value); }
    [[nodiscard]] bool is_array() const { return std::holds_alternative<Array>(value); }
    [[nodiscard]] bool is_string() const { return std::holds_alternative<std::string>(value); }
    [[nodiscard]] bool is_number() const { return std::holds_alternative<double>(value); }
    [[nodiscard]] bool is_bool() const { return std::holds_alternative<bool>(value); }
    [[nodiscard]] const Object& object() const { return std::get<Object>(value); }
    [[nodiscard]] const Array& array() const { return std::get<Array>(value); }
    [[nodiscard]] const std::string& string() const { return std::get<std::string>(value); }
    [[nodiscard]] double number() const { return std::get<double>(value); }
    [[nodiscard]] bool boolean() const { return std::get<bool>(value); }
    [[nodiscard]] const Json& operator[](const std::string& key) const { return object().at(key); }
    [[nodiscard]] bool has(const std::string& key) const { return is_object() && object().count(key) > 0; }

    static std::optional<Json> parse(std::string_view text) {
        Reader r{text, 0};
        auto v = r.value();
        r.blanks();
        if (!v || r.at != text.size()) return std::nullopt;
        return v;
    }

private:
    struct Reader {
        std::string_view s;
        std::size_t at;
        void blanks() {
            while (at < s.size() && std::isspace(static_cast<unsigned char>(s[at]))) ++at;
        }
        bool eat(char c) {
            blanks();
            if (at < s.size() && s[at] == c) {
                ++at;
                return true;
            }
            return false;
        }
        bool word(std::string_view w) {
            if (s.substr(at, w.size()) != w) return false;
            at += w.size();
            return true;
        }
        std::optional<std::string> string() {
            if (!eat('"')) return std::nullopt;
            std::string out;
            while (at < s.size() && s[at] != '"') {
                char c = s[at++];
                if (static_cast<unsigned char>(c) < 0x20) return std::nullopt;
                if (c != '\\') {
                    out += c;
                    continue;
                }
                if (at >= s.size()) return std::nullopt;
                char e = s[at++];
                switch (e) {
                    case '"': case '\\': case '/': out += e; break;
                    case 'n': out += '\n'; break;
                    case 't': out += '\t'; break;
                    case 'r': out += '\r'; break;
                    case 'b': out += '\b'; break;
                    case 'f': out += '\f'; break;
                    case 'u': {  // a code point below 0x80 as itself, any other as '?'
                        if (at + 4 > s.size()) return std::nullopt;
                        for (int k = 0; k < 4; ++k)
                            if (!std::isxdigit(static_cast<unsigned char>(s[at + k]))) return std::nullopt;
                        const unsigned long v = std::stoul(std::string(s.substr(at, 4)), nullptr, 16);
                        out += v < 0x80 ? static_cast<char>(v) : '?';
                        at += 4;
                        break;
                    }
                    default: return std::nullopt;
                }
            }
            if (at >= s.size()) return std::nullopt;
            ++at;
            return out;
        }
        std::optional<Json> value() {
            blanks();
            if (at >= s.size()) return std::nullopt;
            const char c = s[at];
            if (c == '{') {
                ++at;
                Json o{Object{}};
                if (eat('}')) return o;
                do {
                    auto k = string();
                    if (!k || !eat(':')) return std::nullopt;
                    auto v = value();
                    if (!v || o.has(*k)) return std::nullopt;
                    o.keys.push_back(*k);
                    std::get<Object>(o.value).emplace(std::move(*k), std::move(*v));
                } while (eat(','));
                if (!eat('}')) return std::nullopt;
                return o;
            }
            if (c == '[') {
                ++at;
                Array a;
                if (eat(']')) return Json{a};
                do {
                    auto v = value();
                    if (!v) return std::nullopt;
                    a.push_back(std::move(*v));
                } while (eat(','));
                if (!eat(']')) return std::nullopt;
                return Json{std::move(a)};
            }
            if (c == '"') {
                auto str = string();
                if (!str) return std::nullopt;
                return Json{std::move(*str)};
            }
            if (word("true")) return Json{true};
            if (word("false")) return Json{false};
            if (word("null")) return Json{nullptr};
            const std::size_t begin = at;
            if (at < s.size() && s[at] == '-') ++at;
            while (at < s.size() && (std::isdigit(static_cast<unsigned char>(s[at])) || s[at] == '.' || s[at] == 'e' ||
                                     s[at] == 'E' || s[at] == '+' || s[at] == '-'))
                ++at;
            if (at == begin) return std::nullopt;
            try {
                return Json{std::stod(std::string(s.substr(begin, at - begin)))};
            } catch (...) {
                return std::nullopt;
            }
        }
    };
};

}  // namespace qm::test
