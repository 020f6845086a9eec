// support/qm/json.hpp
// Provides:   the one JSON string writer of the project: json_string() and write_json_string()
//             turn text into a JSON string literal (RFC 8259 section 7). Every JSON output (the
//             analysis of `qm-atms SCENE.def --json`, `qm-atms run --json`, `--places --json`, the
//             place vocabularies) writes its strings through it.
// Rules:      `"` and `\` are escaped with a backslash; newline and tab as \n and \t; every other
//             control character (below 0x20) as \u00XX, lower-case hex; every other byte as is, so
//             UTF-8 text stays UTF-8 (the readers accept only ASCII names; the rule language's words
//             may hold other bytes, which are passed through unchanged).
// Ownership:  pure functions.
#pragma once
#include <ostream>
#include <string>
#include <string_view>

namespace qm {

// Appends the JSON string literal of `text` (quotes included) to `out`.
inline void append_json_string(std::string& out, std::string_view text) {
    static constexpr char hex[] = "0123456789abcdef";
    out += '"';
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '"') out += "\\\"";
        else if (c == '\\') out += "\\\\";
        else if (c == '\n') out += "\\n";
        else if (c == '\t') out += "\\t";
        else if (u < 0x20) {
            out += "\\u00";
            out += hex[u >> 4];
            out += hex[u & 0xf];
        } else {
            out += c;
        }
    }
    out += '"';
}

[[nodiscard]] inline std::string json_string(std::string_view text) {
    std::string out;
    out.reserve(text.size() + 2);
    append_json_string(out, text);
    return out;
}

inline void write_json_string(std::ostream& os, std::string_view text) { os << json_string(text); }

}  // namespace qm
