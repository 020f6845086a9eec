// tests/engine/rule_spec_reader_test.cpp: the interim reader never throws or crashes on arbitrary
// token soup (seeded random inputs built from the language's own tokens), and whatever it accepts
// the compiler either compiles or rejects with located diagnostics.
#include "engine/rule_compiler.hpp"
#include "engine/rule_spec_reader.hpp"
#include <doctest/doctest.h>
#include <filesystem>
#include <fstream>
#include <random>

using namespace qm::engine;

TEST_CASE("engine/rule_spec_reader: random token soup gives diagnostics, never an exception") {
    const char* tokens[] = {"rule", "fact", "assume", "include", "when", "then", "not", "false", "(", ")", "[",
                            "]", "{", "}", ":", "for", "all", "exists", "exactly", "one", "in", "where", "and",
                            "sum", "over", "with", "start", "as", "?x", "?y", "?", "+", "-", "0", "1", "42", "p",
                            "q", "=", "<", "range", "neg", "abs", "\"x.rules\"", "\n", "\n", "\n  ", "#c\n"};
    std::mt19937 rng(17);
    std::size_t accepted = 0;
    for (int i = 0; i < 3000; ++i) {
        std::string text;
        int n = std::uniform_int_distribution<int>(0, 40)(rng);
        for (int k = 0; k < n; ++k) {
            text += tokens[std::uniform_int_distribution<std::size_t>(0, std::size(tokens) - 1)(rng)];
            text += ' ';
        }
        qm::Diagnostics d;
        ProgramSpec spec;
        CHECK_NOTHROW(read_rule_text(text, "soup.rules", spec, d));
        for (const auto& x : d.items()) CHECK(x.where.line >= 1);
        if (d.has_errors()) continue;
        std::optional<LoadedProgram> p;
        CHECK_NOTHROW(p = compile_program(spec, d));
        CHECK(p.has_value() != d.has_errors());
        accepted += p.has_value();
    }
    CHECK(accepted > 0);  // the soup does produce some valid programs
}

TEST_CASE("engine/rule_spec_reader: includes are read once, relative to the including file, cycles reported") {
    std::string dir = std::string(QM_BINARY_DIR) + "/reader_test";
    std::filesystem::create_directories(dir + "/sub");
    std::ofstream(dir + "/main.rules") << "include \"sub/a.rules\"\ninclude \"sub/b.rules\"\nfact (m)\n";
    std::ofstream(dir + "/sub/a.rules") << "include \"b.rules\"\nfact (a)\n";
    std::ofstream(dir + "/sub/b.rules") << "fact (b)\n";
    qm::Diagnostics d;
    ProgramSpec spec;
    read_rule_file(dir + "/main.rules", spec, d);
    CHECK(!d.has_errors());
    REQUIRE(spec.facts.size() == 3);  // b once, then a, then m
    CHECK(spec.facts[0].predicate == "b");
    CHECK(spec.facts[1].predicate == "a");
    CHECK(spec.facts[2].predicate == "m");

    std::ofstream(dir + "/c1.rules") << "include \"c2.rules\"\n";
    std::ofstream(dir + "/c2.rules") << "fact (x)\ninclude \"c1.rules\"\n";
    qm::Diagnostics cyc;
    ProgramSpec s2;
    read_rule_file(dir + "/c1.rules", s2, cyc);
    REQUIRE(cyc.has_errors());
    CHECK(cyc.items().front().message.find("include cycle") == 0);
    CHECK(cyc.items().front().where.line == 2);
}
