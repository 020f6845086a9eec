#include "qm/diagnostics.hpp"
#include <doctest/doctest.h>
#include <sstream>

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
