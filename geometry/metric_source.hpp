// geometry/metric_source.hpp
// Provides:   MetricSource, the text of one input to the metric scene reader (a file or the
//             CONFIG argument) with 1-based line/column lookup and the source line for a caret,
//             and MetricPositions, which maps an AST node's position tag to its byte offset.
// Ownership:  value types.
// Why not alex's SourceText: geometry may not include alex/ (layering, docs/ARCHITECTURE.md);
// this is the same idea for the metric reader.
#pragma once
#include "qm/diagnostics.hpp"
#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace qm::geometry {

class MetricSource {
public:
    MetricSource(std::string file, std::string text) : file_(std::move(file)), text_(std::move(text)) {
        line_starts_.push_back(0);
        for (std::size_t i = 0; i < text_.size(); ++i)
            if (text_[i] == '\n') line_starts_.push_back(i + 1);
    }
    [[nodiscard]] const std::string& file() const noexcept { return file_; }
    [[nodiscard]] const std::string& text() const noexcept { return text_; }
    [[nodiscard]] SourceLocation locate(std::size_t offset) const {
        const std::size_t line = line_index(offset);
        return {file_, static_cast<std::uint32_t>(line + 1), static_cast<std::uint32_t>(std::min(offset, text_.size()) - line_starts_[line] + 1)};
    }
    // The line holding `offset`, without its newline.
    [[nodiscard]] std::string line_at(std::size_t offset) const {
        const std::size_t b = line_starts_[line_index(offset)];
        std::size_t e = text_.find('\n', b);
        if (e == std::string::npos) e = text_.size();
        if (e > b && text_[e - 1] == '\r') --e;
        return text_.substr(b, e - b);
    }
    // The line at a location this source produced (for diagnostics made after parsing).
    [[nodiscard]] std::string line_of(const SourceLocation& where) const {
        if (where.line == 0 || where.line > line_starts_.size()) return {};
        return line_at(line_starts_[where.line - 1]);
    }
    void error(Diagnostics& diags, std::size_t offset, std::string message) const {
        diags.error(locate(offset), std::move(message), line_at(offset));
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

}  // namespace qm::geometry
