// support/qm/source_text.hpp
// Provides:   SourceText, the text of one input (a file, or a command-line argument) with byte
//             offset -> 1-based line/column lookup and the whole line for the caret display of a
//             diagnostic (qm/diagnostics.hpp). Every reader of the project (scenes, metric scenes,
//             rule files) locates its errors through it.
// Ownership:  a value type owning its text; the file name is made once here and shared by every
//             location locate() gives (qm/diagnostics.hpp, FileName).
// Invariants: a column counts bytes from the start of the line (a tab is one column); offsets past
//             the end are clamped to the end. A UTF-8 byte-order mark at the start of the text (which
//             some editors write) is not part of it: every reader sees the text after it, and columns
//             of the first line count from there.
#pragma once
#include "qm/diagnostics.hpp"
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace qm {

class SourceText {
public:
    SourceText(FileName file, std::string text) : file_(std::move(file)), text_(std::move(text)) {
        if (text_.starts_with(byte_order_mark)) text_.erase(0, byte_order_mark.size());
        line_starts_.push_back(0);
        for (std::size_t i = 0; i < text_.size(); ++i)
            if (text_[i] == '\n') line_starts_.push_back(i + 1);
    }
    [[nodiscard]] const FileName& file() const noexcept { return file_; }
    [[nodiscard]] const std::string& text() const noexcept { return text_; }
    [[nodiscard]] SourceLocation locate(std::size_t offset) const {
        const std::size_t line = line_index(offset);
        return {file_, static_cast<std::uint32_t>(line + 1),
                static_cast<std::uint32_t>(std::min(offset, text_.size()) - line_starts_[line] + 1)};
    }
    // The whole line holding `offset`, without its line end (a view into the text).
    [[nodiscard]] std::string_view line_at(std::size_t offset) const {
        return line(static_cast<std::uint32_t>(line_index(offset) + 1));
    }
    // Line number n (1-based), a view into the text; empty if there is no such line.
    [[nodiscard]] std::string_view line(std::uint32_t n) const {
        if (n == 0 || n > line_starts_.size()) return {};
        const std::size_t b = line_starts_[n - 1];
        std::size_t e = text_.find('\n', b);
        if (e == std::string::npos) e = text_.size();
        if (e > b && text_[e - 1] == '\r') --e;
        return std::string_view(text_).substr(b, e - b);
    }
    // The line of a location this text produced (for diagnostics made after parsing).
    [[nodiscard]] std::string_view line_of(const SourceLocation& where) const { return line(where.line); }
    // An error at `offset`, with (an excerpt of) its line for the caret.
    void error(Diagnostics& diags, std::size_t offset, std::string message) const {
        diags.error(locate(offset), std::move(message), line_at(offset));
    }

    static constexpr std::string_view byte_order_mark = "\xEF\xBB\xBF";

private:
    [[nodiscard]] std::size_t line_index(std::size_t offset) const {
        auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), std::min(offset, text_.size()));
        return static_cast<std::size_t>(it - line_starts_.begin()) - 1;
    }
    FileName file_;
    std::string text_;
    std::vector<std::size_t> line_starts_;
};

}  // namespace qm
