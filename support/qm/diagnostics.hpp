// support/qm/diagnostics.hpp
// Provides:   FileName (the name of an input, shared), SourceLocation (file, 1-based line and
//             column), Diagnostic (a located error or note) and Diagnostics, a sink that collects
//             them so one run reports every error in source order (STYLE.md section 6). Printing
//             is `file:line:col: error: msg`.
// Ownership:  value types. A FileName is made once per input (SourceText, source_text.hpp) and
//             every location read from that input shares it, so a location costs a pointer, not a
//             copy of the name. Library code reports into a Diagnostics& and never prints or exits;
//             only main() picks the exit status (2 for bad input).
// Bounds:     what a diagnostic keeps of its source line, and what print() writes, is bounded
//             whatever the input (a small scene with a surface duplicated many times must not
//             write megabytes): a line is kept only around the error
//             (excerpt_bytes, cut ends shown as `...`), control characters are shown as `?`, at
//             most PrintLimits::max_shown diagnostics are printed and then a count of the rest, and
//             print() writes everything in one call of the stream's write().
#pragma once
#include <algorithm>
#include <compare>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <ostream>
#include <string>
#include <string_view>
#include <vector>

namespace qm {

// Compares and prints as the name it holds; copies share it. Implicit from a string, so that a
// location can be written {"--why", 1, 1}.
class FileName {
public:
    FileName() = default;  // ""
    FileName(std::string name) : name_(std::make_shared<const std::string>(std::move(name))) {}
    FileName(const char* name) : FileName(std::string(name)) {}
    [[nodiscard]] const std::string& str() const noexcept {
        static const std::string none;
        return name_ ? *name_ : none;
    }
    [[nodiscard]] bool empty() const noexcept { return str().empty(); }
    friend bool operator==(const FileName& a, const FileName& b) noexcept { return a.name_ == b.name_ || a.str() == b.str(); }
    friend std::strong_ordering operator<=>(const FileName& a, const FileName& b) noexcept { return a.str() <=> b.str(); }
    friend std::ostream& operator<<(std::ostream& os, const FileName& f) { return os << f.str(); }

private:
    std::shared_ptr<const std::string> name_;
};

struct SourceLocation {
    FileName file;
    std::uint32_t line = 1;    // 1-based
    std::uint32_t column = 1;  // 1-based
    friend bool operator==(const SourceLocation&, const SourceLocation&) = default;
    friend auto operator<=>(const SourceLocation&, const SourceLocation&) = default;  // file, line, column
};

// "file:line:col", as diagnostics print a location.
[[nodiscard]] inline std::string to_string(const SourceLocation& w) {
    return w.file.str() + ':' + std::to_string(w.line) + ':' + std::to_string(w.column);
}

enum class Severity { error, warning, note };

struct Diagnostic {
    Severity severity = Severity::error;
    SourceLocation where;
    std::string message;
    std::string source_line;             // optional: the offending line (or an excerpt), printed with a caret
    std::vector<std::string> notes;      // printed as `note:` lines after the message
    std::uint32_t source_column = 1;     // the column of source_line's first byte (> 1 for an excerpt)
    bool source_continues = false;       // the line goes on after source_line (an excerpt)
};

// How much of a source line a diagnostic keeps: this many bytes at most, starting up to
// excerpt_before bytes before the column it points at.
inline constexpr std::size_t excerpt_bytes = 160;
inline constexpr std::size_t excerpt_before = 60;

// Where the excerpt of a line of n bytes starts, for a caret at its byte `at`.
[[nodiscard]] inline std::size_t excerpt_start(std::size_t n, std::size_t at) noexcept {
    return n <= excerpt_bytes ? 0 : std::min(at > excerpt_before ? at - excerpt_before : 0, n - excerpt_bytes);
}

// Keeps of d.source_line (whose first byte is at column d.source_column) only the excerpt around
// d.where.column; a no-op for a line that fits.
inline void trim_source_line(Diagnostic& d) {
    const std::size_t n = d.source_line.size();
    if (n <= excerpt_bytes) return;
    const std::size_t first = excerpt_start(n, d.where.column > d.source_column ? d.where.column - d.source_column : 0);
    d.source_continues = d.source_continues || first + excerpt_bytes < n;
    d.source_line = d.source_line.substr(first, excerpt_bytes);
    d.source_column += static_cast<std::uint32_t>(first);
}

// A diagnostic with an excerpt of `source_line` (the whole line at `where`, or empty): only the
// excerpt is copied, so a long line costs nothing per diagnostic.
[[nodiscard]] inline Diagnostic make_diagnostic(Severity severity, SourceLocation where, std::string message,
                                                std::string_view source_line = {}, std::vector<std::string> notes = {}) {
    Diagnostic d{severity, std::move(where), std::move(message), {}, std::move(notes), 1, false};
    const std::size_t first = excerpt_start(source_line.size(), d.where.column > 0 ? d.where.column - 1 : 0);
    d.source_line = std::string(source_line.substr(first, excerpt_bytes));
    d.source_column = static_cast<std::uint32_t>(first + 1);
    d.source_continues = first + excerpt_bytes < source_line.size();
    return d;
}

// How much print() writes.
struct PrintLimits {
    std::size_t max_shown = 100;  // diagnostics (with their notes); then one line counting the rest
};

class Diagnostics {
public:
    // `source_line` is the whole line at `where` (or empty): only an excerpt around the column is kept.
    void error(SourceLocation where, std::string message, std::string_view source_line = {}) {
        items_.push_back(make_diagnostic(Severity::error, std::move(where), std::move(message), source_line));
    }
    void add(Diagnostic d) {
        trim_source_line(d);
        items_.push_back(std::move(d));
    }
    void add(Severity severity, SourceLocation where, std::string message, std::string_view source_line,
             std::vector<std::string> notes = {}) {
        items_.push_back(make_diagnostic(severity, std::move(where), std::move(message), source_line, std::move(notes)));
    }
    [[nodiscard]] bool has_errors() const noexcept {
        return std::any_of(items_.begin(), items_.end(),
                           [](const Diagnostic& d) { return d.severity == Severity::error; });
    }
    [[nodiscard]] const std::vector<Diagnostic>& items() const noexcept { return items_; }
    [[nodiscard]] std::size_t size() const noexcept { return items_.size(); }

    // Sorted by file, line, column; stable so equal locations keep report order.
    [[nodiscard]] std::vector<Diagnostic> sorted() const {
        auto out = items_;
        std::stable_sort(out.begin(), out.end(), [](const Diagnostic& a, const Diagnostic& b) { return a.where < b.where; });
        return out;
    }

    // Writes the first limits.max_shown diagnostics in source order, each with its excerpt and
    // caret and its notes, then `note: N more errors (and M more warnings and notes) not shown`.
    void print(std::ostream& os, const PrintLimits& limits = {}) const {
        std::vector<const Diagnostic*> order;
        order.reserve(items_.size());
        for (const Diagnostic& d : items_) order.push_back(&d);
        std::stable_sort(order.begin(), order.end(), [](const Diagnostic* a, const Diagnostic* b) { return a->where < b->where; });
        std::string out;
        std::size_t errors_left = 0, others_left = 0;
        for (std::size_t i = 0; i < order.size(); ++i) {
            if (i < limits.max_shown) append(out, *order[i]);
            else ++(order[i]->severity == Severity::error ? errors_left : others_left);
        }
        if (errors_left + others_left > 0) {
            out += "note: ";
            if (errors_left > 0) out += std::to_string(errors_left) + (errors_left == 1 ? " more error" : " more errors");
            if (errors_left > 0 && others_left > 0) out += " and ";
            if (others_left > 0) out += std::to_string(others_left) + " more warnings and notes";
            out += " not shown (the first " + std::to_string(limits.max_shown) + " are)\n";
        }
        os.write(out.data(), static_cast<std::streamsize>(out.size()));
    }

private:
    static void append_printable(std::string& out, std::string_view s) {
        for (char c : s) {
            const auto u = static_cast<unsigned char>(c);
            out += (u < 0x20 && c != '\t') || u == 0x7f ? '?' : c;
        }
    }
    static void append(std::string& out, const Diagnostic& d) {
        const std::string at = to_string(d.where) + ": ";
        out += at;
        out += d.severity == Severity::error ? "error" : d.severity == Severity::warning ? "warning" : "note";
        out += ": ";
        out += d.message;
        out += '\n';
        if (!d.source_line.empty()) {
            const bool cut_before = d.source_column > 1;
            out += cut_before ? "  ..." : "  ";
            append_printable(out, d.source_line);
            out += d.source_continues ? "...\n" : "\n";
            out.append(cut_before ? 5 : 2, ' ');
            // The caret's indent copies the excerpt's tabs, so that it lines up however tabs are shown.
            const std::size_t indent = d.where.column > d.source_column ? d.where.column - d.source_column : 0;
            for (std::size_t c = 0; c < indent; ++c) out += c < d.source_line.size() && d.source_line[c] == '\t' ? '\t' : ' ';
            out += "^\n";
        }
        for (const std::string& n : d.notes) out += at + "note: " + n + '\n';
    }

    std::vector<Diagnostic> items_;
};

}  // namespace qm
