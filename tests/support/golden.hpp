// tests/support/golden.hpp: test helper (not a test): slurp(), the whole text of a file ("" when it
// cannot be read), and check_golden(), a test's output against its golden file, which
// QM_WRITE_GOLDEN=1 (re)writes first (review the diff before committing).
#pragma once
#include "qm/file_text.hpp"
#include <doctest/doctest.h>
#include <cstdlib>
#include <fstream>
#include <string>

namespace qm::test {

inline std::string slurp(const std::string& path) { return read_file_text(path).text.value_or(""); }

inline void check_golden(const std::string& actual, const std::string& golden) {
    if (std::getenv("QM_WRITE_GOLDEN")) std::ofstream(golden, std::ios::binary) << actual;
    INFO(golden);
    const auto expected = read_file_text(golden);
    REQUIRE(expected.text.has_value());
    CHECK(actual == *expected.text);
}

}  // namespace qm::test
