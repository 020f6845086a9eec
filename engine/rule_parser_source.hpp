// engine/rule_parser_source.hpp
// Provides:   SourceText, the text of one rule file (or of a command-line argument) with byte offset
//             -> 1-based line/column lookup and the whole line for the caret display; and
//             SourceTexts, every file a load read, so that diagnostics reported after parsing (by the
//             checker, the compiler, the stratifier or the engine) can be shown with their source line.
// Ownership:  value types; SourceTexts owns its SourceTexts, keyed by the file name used in locations.
// Invariants: a column counts bytes from the start of the line (a tab is one column), as every
//             location of the rule language does.
// Knows nothing of the ATMS or of the grammar.
#pragma once
#include "qm/diagnostics.hpp"
#include <algorithm>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace qm::engine {

class SourceText {
public:
    SourceText(std::string file, std::string text) : file_(std::move(file)), text_(std::move(text)) {
        line_starts_.push_back(0);
        for (std::size_t i = 0; i < text_.size(); ++i)
            if (text_[i] == '\n') line_starts_.push_back(i + 1);
    }
    [[nodiscard]] const std::string& file() const noexcept { return file_; }
    [[nodiscard]] const std::string& text() const noexcept { return text_; }
    // Offsets past the end are clamped to the end.
    [[nodiscard]] SourceLocation locate(std::size_t offset) const {
        const std::size_t line = line_index(offset);
        return {file_, static_cast<std::uint32_t>(line + 1),
                static_cast<std::uint32_t>(std::min(offset, text_.size()) - line_starts_[line] + 1)};
    }
    // The whole line holding `offset`, without its line end.
    [[nodiscard]] std::string line_at(std::size_t offset) const { return line(line_index(offset) + 1); }
    // Line number n (1-based); empty if there is no such line.
    [[nodiscard]] std::string line(std::uint32_t n) const {
        if (n == 0 || n > line_starts_.size()) return {};
        const std::size_t b = line_starts_[n - 1];
        std::size_t e = text_.find('\n', b);
        if (e == std::string::npos) e = text_.size();
        if (e > b && text_[e - 1] == '\r') --e;
        return text_.substr(b, e - b);
    }

private:
    [[nodiscard]] std::size_t line_index(std::size_t offset) const {
        auto it = std::upper_bound(line_starts_.begin(), line_starts_.end(), std::min(offset, text_.size()));
        return static_cast<std::size_t>(it - line_starts_.begin()) - 1;
    }
    std::string file_;
    std::string text_;
    std::vector<std::size_t> line_starts_;
};

class SourceTexts {
public:
    void add(SourceText text) {
        std::string key = text.file();
        texts_.insert_or_assign(std::move(key), std::move(text));
    }
    [[nodiscard]] const SourceText* find(const std::string& file) const {
        auto it = texts_.find(file);
        return it == texts_.end() ? nullptr : &it->second;
    }
    // Appends every diagnostic of `from` to `to`, giving each one that has no source line the line
    // it points at, when its file was read.
    void attach_lines(const Diagnostics& from, Diagnostics& to) const {
        for (Diagnostic d : from.items()) {
            if (d.source_line.empty())
                if (const SourceText* t = find(d.where.file)) d.source_line = t->line(d.where.line);
            to.add(std::move(d));
        }
    }

private:
    std::map<std::string, SourceText> texts_;
};

}  // namespace qm::engine
