// support/qm/diagnostics.hpp
// Provides:   SourceLocation (file, 1-based line and column), Diagnostic (a located error or
//             note) and Diagnostics, a sink that collects them so one run reports every error
//             in source order (STYLE.md section 6). Printing is `file:line:col: error: msg`.
// Ownership:  value types. Library code reports into a Diagnostics& and never prints or exits;
//             only main() picks the exit status (2 for bad input).
#pragma once
#include <algorithm>
#include <cstdint>
#include <ostream>
#include <string>
#include <tuple>
#include <vector>

namespace qm {

struct SourceLocation {
    std::string file;
    std::uint32_t line = 1;    // 1-based
    std::uint32_t column = 1;  // 1-based
    friend bool operator==(const SourceLocation&, const SourceLocation&) = default;
};

enum class Severity { error, warning, note };

struct Diagnostic {
    Severity severity = Severity::error;
    SourceLocation where;
    std::string message;
    std::string source_line;             // optional: the offending line, printed with a caret
    std::vector<std::string> notes;      // printed as `note:` lines after the message
};

class Diagnostics {
public:
    void error(SourceLocation where, std::string message, std::string source_line = {}) {
        items_.push_back({Severity::error, std::move(where), std::move(message), std::move(source_line), {}});
    }
    void add(Diagnostic d) { items_.push_back(std::move(d)); }
    [[nodiscard]] bool has_errors() const noexcept {
        return std::any_of(items_.begin(), items_.end(),
                           [](const Diagnostic& d) { return d.severity == Severity::error; });
    }
    [[nodiscard]] const std::vector<Diagnostic>& items() const noexcept { return items_; }
    [[nodiscard]] std::size_t size() const noexcept { return items_.size(); }

    // Sorted by file, line, column; stable so equal locations keep report order.
    [[nodiscard]] std::vector<Diagnostic> sorted() const {
        auto out = items_;
        std::stable_sort(out.begin(), out.end(), [](const Diagnostic& a, const Diagnostic& b) {
            return std::tie(a.where.file, a.where.line, a.where.column) <
                   std::tie(b.where.file, b.where.line, b.where.column);
        });
        return out;
    }

    void print(std::ostream& os) const {
        for (const auto& d : sorted()) {
            os << d.where.file << ':' << d.where.line << ':' << d.where.column << ": "
               << (d.severity == Severity::error ? "error" : d.severity == Severity::warning ? "warning" : "note")
               << ": " << d.message << '\n';
            if (!d.source_line.empty()) {
                os << "  " << d.source_line << '\n' << "  ";
                for (std::uint32_t c = 1; c < d.where.column; ++c)
                    os << (c - 1 < d.source_line.size() && d.source_line[c - 1] == '\t' ? '\t' : ' ');
                os << "^\n";
            }
            for (const auto& n : d.notes) os << d.where.file << ':' << d.where.line << ':' << d.where.column << ": note: " << n << '\n';
        }
    }

private:
    std::vector<Diagnostic> items_;
};

}  // namespace qm
