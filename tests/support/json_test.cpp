// tests/support/json_test.cpp: qm/json.hpp - the one JSON string writer. Its output must be a JSON
// string (RFC 8259 section 7) that a JSON parser (nlohmann/json) reads back to exactly the bytes
// written; and it must escape exactly `"`, `\` and the control characters, leaving every other
// byte (UTF-8 included) as it is.
#include "qm/json.hpp"
#include <doctest/doctest.h>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <sstream>
#include <string>

namespace {
// What a strict JSON parser reads the text as, if a string.
std::optional<std::string> decode(const std::string& j) {
    const auto v = nlohmann::json::parse(j, nullptr, /*allow_exceptions=*/false);
    if (!v.is_string()) return std::nullopt;  // a discarded value (a syntax error) is not a string
    return v.get<std::string>();
}
}  // namespace

TEST_CASE("support/json: the escapes, byte for byte") {
    CHECK(qm::json_string("") == "\"\"");
    CHECK(qm::json_string("a\"b\\c\n") == "\"a\\\"b\\\\c\\n\"");
    CHECK(qm::json_string("tab\there") == "\"tab\\there\"");
    CHECK(qm::json_string(std::string("\x01\x1f\r\b\f", 5)) == "\"\\u0001\\u001f\\u000d\\u0008\\u000c\"");
    CHECK(qm::json_string(std::string("nul\0end", 7)) == "\"nul\\u0000end\"");
    CHECK(qm::json_string("caf\xc3\xa9 / \x7f") == "\"caf\xc3\xa9 / \x7f\"");  // UTF-8, '/' and DEL as they are
    std::ostringstream os;
    qm::write_json_string(os, "q\"");
    CHECK(os.str() == "\"q\\\"\"");
}

TEST_CASE("support/json: inside an HTML script element, `</` cannot close it") {
    CHECK(qm::json_string("<svg></svg>", qm::Json::in_script) == "\"<svg><\\/svg>\"");
    CHECK(qm::json_string("a/b </", qm::Json::in_script) == "\"a/b <\\/\"");
    CHECK(qm::json_string("/x", qm::Json::in_script) == "\"/x\"");
    CHECK(qm::json_string("<svg></svg>") == "\"<svg></svg>\"");  // plain JSON leaves '/' alone
    // The escape is a JSON one: the text decodes back unchanged.
    CHECK(decode(qm::json_string("</script>\t</", qm::Json::in_script)) == std::optional<std::string>("</script>\t</"));
}

TEST_CASE("support/json: 2000 seeded random strings read back unchanged, with no raw control character") {
    std::mt19937 rng(20261201);
    // Bytes below 0x80 (bytes above are passed through, checked in the case above).
    std::uniform_int_distribution<int> byte(0, 0x7f), length(0, 40);
    for (int n = 0; n < 2000; ++n) {
        std::string s(static_cast<std::size_t>(length(rng)), ' ');
        for (char& c : s) c = static_cast<char>(byte(rng));
        const std::string j = qm::json_string(s);
        for (char c : j) REQUIRE(static_cast<unsigned char>(c) >= 0x20);
        const auto back = decode(j);
        REQUIRE(back);
        CHECK(*back == s);
    }
}
