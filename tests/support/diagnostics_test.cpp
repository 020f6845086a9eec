#include "qm/diagnostics.hpp"
#include <doctest/doctest.h>
#include "qm/source_text.hpp"
#include <random>
#include <sstream>
#include <string>

TEST_CASE("support/diagnostics: printed sorted by location with a caret") {
    qm::Diagnostics d;
    d.error({"b.def", 3, 4}, "expected ')'", "(a b");
    d.error({"a.def", 10, 1}, "unknown surface 'x'");
    d.error({"a.def", 2, 7}, "duplicate name 'block'");
    CHECK(d.has_errors());
    std::ostringstream os;
    d.print(os);
    CHECK(os.str() ==
          "a.def:2:7: error: duplicate name 'block'\n"
          "a.def:10:1: error: unknown surface 'x'\n"
          "b.def:3:4: error: expected ')'\n"
          "  (a b\n"
          "     ^\n");
}

TEST_CASE("support/diagnostics: empty sink has no errors") {
    qm::Diagnostics d;
    CHECK_FALSE(d.has_errors());
    CHECK(d.size() == 0);
}

namespace {
// Counts the calls that put characters into a stream: print() makes one.
struct CountingBuf : std::stringbuf {
    int calls = 0;
    bool inside = false;  // the stringbuf's own xsputn grows its buffer through overflow
    std::streamsize xsputn(const char* s, std::streamsize n) override {
        ++calls;
        inside = true;
        const std::streamsize r = std::stringbuf::xsputn(s, n);
        inside = false;
        return r;
    }
    int_type overflow(int_type c) override {
        if (!inside) ++calls;
        return std::stringbuf::overflow(c);
    }
};
}  // namespace

TEST_CASE("support/diagnostics: a long line is shown as an excerpt whose caret points at the same character") {
    std::mt19937 rng(19);
    for (int trial = 0; trial < 300; ++trial) {
        const std::size_t n = 1 + rng() % 2000;
        std::string line(n, ' ');
        for (char& c : line) c = static_cast<char>('a' + rng() % 26);
        const auto column = static_cast<std::uint32_t>(1 + rng() % n);
        qm::Diagnostics d;
        d.error({"f", 1, column}, "m", line);
        std::ostringstream os;
        d.print(os);
        const std::string out = os.str();
        // Three lines: the message, the excerpt, the caret.
        const std::size_t l1 = out.find('\n'), l2 = out.find('\n', l1 + 1);
        REQUIRE(l2 != std::string::npos);
        const std::string shown = out.substr(l1 + 1, l2 - l1 - 1), caret = out.substr(l2 + 1);
        CHECK(shown.size() <= 5 + qm::excerpt_bytes + 3);
        if (n <= qm::excerpt_bytes) CHECK(shown == "  " + line);
        REQUIRE(caret.size() >= 2);
        CHECK(caret.substr(caret.size() - 2) == "^\n");
        const std::size_t at = caret.size() - 2;
        REQUIRE(at < shown.size());
        CHECK(shown[at] == line[column - 1]);
        CHECK((shown.rfind("  ...", 0) == 0) == (column > qm::excerpt_before + 1 && n > qm::excerpt_bytes));
    }
}

TEST_CASE("support/diagnostics: control characters are shown as '?', and at most max_shown diagnostics in one write") {
    qm::Diagnostics d;
    for (std::uint32_t i = 1; i <= 250; ++i) d.error({"f", i, 1}, "e", "a\x01" "b\tc");
    d.add(qm::Severity::warning, {"f", 251, 1}, "w", "");
    CountingBuf buf;
    std::ostream os(&buf);
    d.print(os);
    CHECK(buf.calls == 1);
    const std::string out = buf.str();
    std::size_t shown = 0;
    for (std::size_t p = out.find(": error: "); p != std::string::npos; p = out.find(": error: ", p + 1)) ++shown;
    CHECK(shown == 100);
    CHECK(out.find("  a?b\tc\n") != std::string::npos);
    CHECK(out.ends_with("\nnote: 150 more errors and 1 more warnings and notes not shown (the first 100 are)\n"));
}

TEST_CASE("support/source_text: a UTF-8 byte-order mark is not part of the text") {
    const qm::SourceText with("f", "\xEF\xBB\xBF(a b)\n(c)");
    const qm::SourceText without("f", "(a b)\n(c)");
    CHECK(with.text() == without.text());
    CHECK(with.locate(1).column == 2);
    CHECK(with.line(1) == "(a b)");
    // Only at the start: elsewhere the bytes are text (and the reader's to refuse).
    const qm::SourceText inner("f", "(a)\xEF\xBB\xBF");
    CHECK(inner.text().size() == 6);
}

TEST_CASE("support/diagnostics: the locations of one text share its file name, and compare by name") {
    const qm::SourceText src("scene.def", "a\nb\n");
    const qm::SourceLocation a = src.locate(0), b = src.locate(2);
    CHECK(&a.file.str() == &b.file.str());  // one name, not a copy per location
    CHECK(a == qm::SourceLocation{"scene.def", 1, 1});
    CHECK(b == qm::SourceLocation{std::string("scene.def"), 2, 1});
    CHECK(a < b);
    CHECK(qm::SourceLocation{"a.def", 9, 9} < a);
    CHECK(qm::to_string(b) == "scene.def:2:1");
    CHECK(qm::FileName().str().empty());
}
