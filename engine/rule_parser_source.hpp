// engine/rule_parser_source.hpp
// Provides:   SourceText (qm/source_text.hpp: the text of one rule file or command-line argument,
//             with line/column lookup and the line for the caret display); and SourceTexts, every file a load read, so that diagnostics reported after parsing (by the
//             checker, the compiler, the stratifier or the engine) can be shown with their source line.
// Ownership:  value types; SourceTexts owns its SourceTexts, keyed by the file name used in locations.
// Invariants: a column counts bytes from the start of the line (a tab is one column), as every
//             location of the rule language does.
// Knows nothing of the ATMS or of the grammar.
#pragma once
#include "qm/diagnostics.hpp"
#include "qm/source_text.hpp"
#include <algorithm>
#include <cstddef>
#include <map>
#include <string>
#include <vector>

namespace qm::engine {

using SourceText = qm::SourceText;  // qm/source_text.hpp

class SourceTexts {
public:
    void add(SourceText text) {
        std::string key = text.file().str();
        texts_.insert_or_assign(std::move(key), std::move(text));
    }
    [[nodiscard]] const SourceText* find(const std::string& file) const {
        auto it = texts_.find(file);
        return it == texts_.end() ? nullptr : &it->second;
    }
    // Every file read, by the name used in locations.
    [[nodiscard]] const std::map<std::string, SourceText>& texts() const noexcept { return texts_; }
    // Appends every diagnostic of `from` to `to`, giving each one that has no source line the line
    // it points at, when its file was read.
    void attach_lines(const Diagnostics& from, Diagnostics& to) const {
        for (const Diagnostic& d : from.items()) {
            const SourceText* t = d.source_line.empty() ? find(d.where.file.str()) : nullptr;
            if (t) to.add(d.severity, d.where, d.message, t->line(d.where.line), d.notes);
            else to.add(d);
        }
    }

private:
    std::map<std::string, SourceText> texts_;
};

}  // namespace qm::engine
