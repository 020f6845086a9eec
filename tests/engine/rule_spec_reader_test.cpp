// tests/engine/rule_spec_reader_test.cpp: the front end (X3 parser + includes) never throws or
// crashes on arbitrary token soup (seeded random inputs built from the language's own tokens), and
// whatever it accepts the compiler either compiles or rejects with located diagnostics; includes are
// read once, relative to the including file, in the place of their first include; cycles, missing
// files and directories are located errors; the texts read are recorded for source lines.
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
                            "q", "=", "<", "range", "neg", "abs", "\"x.rules\"", "\n", "\n", "\n  ", "#c\n",
                            "\nrule", "\nfact", "\nassume", "\"", "\t", "\r\n"};
    std::mt19937 rng(17);
    std::size_t accepted = 0;
    for (int i = 0; i < 5000; ++i) {
        std::string text;
        int n = std::uniform_int_distribution<int>(0, 40)(rng);
        for (int k = 0; k < n; ++k) {
            text += tokens[std::uniform_int_distribution<std::size_t>(0, std::size(tokens) - 1)(rng)];
            if (std::uniform_int_distribution<int>(0, 3)(rng)) text += ' ';
        }
        CAPTURE(text);
        qm::Diagnostics d;
        ProgramSpec spec;
        CHECK_NOTHROW(read_rule_text(text, "soup.rules", spec, d));
        for (const auto& x : d.items()) {
            CHECK(x.where.line >= 1);
            CHECK(x.where.column >= 1);
            if (x.message.rfind("expected ", 0) == 0) CHECK(x.message.find(" but found ") != std::string::npos);
        }
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
    SourceTexts sources;
    read_rule_file(dir + "/main.rules", spec, d, default_builtins(), &sources);
    CHECK(!d.has_errors());
    REQUIRE(spec.facts.size() == 3);  // b once, then a, then m
    CHECK(spec.facts[0].predicate == "b");
    CHECK(spec.facts[1].predicate == "a");
    CHECK(spec.facts[2].predicate == "m");
    CHECK(spec.facts[0].where.file == dir + "/sub/b.rules");
    REQUIRE(sources.find(dir + "/sub/a.rules") != nullptr);
    CHECK(sources.find(dir + "/sub/a.rules")->line(2) == "fact (a)");

    // Several files given at once share the read-once rule.
    const std::string both[] = {dir + "/sub/a.rules", dir + "/sub/b.rules", dir + "/main.rules"};
    qm::Diagnostics d2;
    ProgramSpec s2;
    read_rule_files(both, s2, d2);
    CHECK(!d2.has_errors());
    REQUIRE(s2.facts.size() == 3);
    CHECK(s2.facts[0].predicate == "b");
    CHECK(s2.facts[1].predicate == "a");
    CHECK(s2.facts[2].predicate == "m");

    std::ofstream(dir + "/c1.rules") << "include \"c2.rules\"\n";
    std::ofstream(dir + "/c2.rules") << "fact (x)\ninclude \"c1.rules\"\n";
    qm::Diagnostics cyc;
    ProgramSpec s3;
    read_rule_file(dir + "/c1.rules", s3, cyc);
    REQUIRE(cyc.has_errors());
    CHECK(cyc.items().front().message == "include cycle: '" + dir + "/c1.rules' is already being read");
    CHECK(cyc.items().front().where.file == dir + "/c2.rules");
    CHECK(cyc.items().front().where.line == 2);
    CHECK(cyc.items().front().source_line == "include \"c1.rules\"");
}

TEST_CASE("engine/rule_spec_reader: an unreadable file or include is a located error") {
    std::string dir = std::string(QM_BINARY_DIR) + "/reader_test_missing";
    std::filesystem::create_directories(dir + "/folder.rules");
    std::ofstream(dir + "/main.rules") << "fact (a)\ninclude \"folder.rules\"\ninclude \"\"\ninclude \"gone.rules\"\n";
    qm::Diagnostics d;
    ProgramSpec spec;
    read_rule_file(dir + "/main.rules", spec, d);
    REQUIRE(d.size() == 3);
    CHECK(d.items()[0].message == "cannot open included file '" + dir + "/folder.rules': it is a directory, not a file");
    CHECK(d.items()[0].where.line == 2);
    CHECK(d.items()[0].where.column == 9);
    CHECK(d.items()[1].where.line == 3);
    CHECK(d.items()[2].message == "cannot open included file '" + dir + "/gone.rules': no such file");
    CHECK(spec.facts.size() == 1);
    qm::Diagnostics top;
    read_rule_file(dir + "/folder.rules", spec, top);
    REQUIRE(top.size() == 1);
    CHECK(top.items()[0].message == "cannot open rule file '" + dir + "/folder.rules': it is a directory, not a file");
}
