// support/qm/json.hpp
// Provides:   the one JSON string writer of the project: json_string() and write_json_string()
//             turn text into a JSON string literal (RFC 8259 section 7). Every JSON output (the
//             analysis of `qm-atms SCENE.def --json`, `qm-atms run --json`, `--places --json`, the
//             place vocabularies, the explorer's data) writes its strings through it.
// Rules:      `"` and `\` are escaped with a backslash; newline and tab as \n and \t; every other
//             control character (below 0x20) as \u00XX, lower-case hex; every other byte as is, so
//             UTF-8 text stays UTF-8 (the readers accept only ASCII names; the rule language's words
//             may hold other bytes, which are passed through unchanged). With Json::in_script (a
//             string inside an HTML <script> element: the explorer page's data), `</` is also
//             written `<\/`, so that the text cannot close the element (RFC 8259 allows `\/`).
// Ownership:  pure functions.
#pragma once
#include <cstddef>
#include <ostream>
#include <string>
#include <string_view>

namespace qm {

enum class Json : bool { plain, in_script };

// Appends the JSON string literal of `text` (quotes included) to `out`.
inline void append_json_string(std::string& out, std::string_view text, Json where = Json::plain) {
    static constexpr char hex[] = "0123456789abcdef";
    out += '"';
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        const auto u = static_cast<unsigned char>(c);
        if (c == '"') out += "\\\"";
        else if (c == '\\') out += "\\\\";
        else if (c == '\n') out += "\\n";
        else if (c == '\t') out += "\\t";
        else if (c == '/' && where == Json::in_script && i > 0 && text[i - 1] == '<') out += "\\/";
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

[[nodiscard]] inline std::string json_string(std::string_view text, Json where = Json::plain) {
    std::string out;
    out.reserve(text.size() + 2);
    append_json_string(out, text, where);
    return out;
}

inline void write_json_string(std::ostream& os, std::string_view text, Json where = Json::plain) {
    os << json_string(text, where);
}

}  // namespace qm
