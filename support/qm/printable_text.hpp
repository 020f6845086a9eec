// support/qm/printable_text.hpp
// Provides:   printable_text(), user text (a path, a CONFIG, an option's value) made safe to put in
//             one line of our output: inside a `;` comment of an emitted scene, or a message.
// Rules:      a control character (below 0x20, and 0x7f) is written as an escape: \n, \r, \t, or
//             \xNN (two lower-case hex digits); a backslash as \\ (so the escapes are unambiguous);
//             every other byte, UTF-8 included, as it is. The result holds no line break, so a
//             comment or a message stays on its line, and the text can be told from it.
// Ownership:  a pure function.
#pragma once
#include <string>
#include <string_view>

namespace qm {

[[nodiscard]] inline std::string printable_text(std::string_view text) {
    static constexpr char hex[] = "0123456789abcdef";
    std::string out;
    out.reserve(text.size());
    for (const char ch : text) {
        const auto c = static_cast<unsigned char>(ch);
        if (c == '\\') out += "\\\\";
        else if (c == '\n') out += "\\n";
        else if (c == '\r') out += "\\r";
        else if (c == '\t') out += "\\t";
        else if (c < 0x20 || c == 0x7f) out += {'\\', 'x', hex[c >> 4], hex[c & 0xf]};
        else out += ch;
    }
    return out;
}

}  // namespace qm
