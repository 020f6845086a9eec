// tests/engine/rule_errors_test.cpp: golden diagnostics. Every tests/engine/errors/NAME.rules is
// loaded with load_program() (reader, checker, compiler, stratifier: the path `qm-atms run` takes);
// a case that loads without error is an error found when running, so it is run by an Engine as
// `qm-atms run` does, and its diagnostics get their source lines as there. The printed diagnostics,
// with the directory stripped from file names, must equal NAME.err exactly. One case per error
// class of docs/RULES.md "## Error messages". A case named warn_* is a program that loads and runs
// without error but with warnings (a rule that can never fire, an unused rule): its .err holds them.
// QM_WRITE_GOLDEN=1 rewrites the .err files.
#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_parser_source.hpp"
#include "../support/golden.hpp"
#include <doctest/doctest.h>
#include <filesystem>
#include <sstream>

using namespace qm::engine;

namespace {
std::string strip(std::string text, const std::string& prefix) {
    for (std::size_t at = text.find(prefix); at != std::string::npos; at = text.find(prefix, at))
        text.erase(at, prefix.size());
    return text;
}
}  // namespace

TEST_CASE("engine/rule_errors: every golden case gives exactly its expected diagnostics") {
    std::filesystem::path dir = std::string(QM_SOURCE_DIR) + "/tests/engine/errors";
    std::size_t cases = 0;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        if (entry.path().extension() != ".rules") continue;
        CAPTURE(entry.path().filename().string());
        qm::Diagnostics d;
        std::optional<LoadedProgram> p;
        const std::string file = entry.path().lexically_normal().string();
        CHECK_NOTHROW(p = load_program(file, d));
        qm::Diagnostics shown;
        const bool warnings_only = entry.path().filename().string().starts_with("warn_");
        if (p.has_value()) {  // an error of the run: the program itself reads, checks and compiles
            CHECK(!d.has_errors());
            shown = d;  // the load's warnings
            Engine e(std::move(p->program), std::move(p->values));
            qm::Diagnostics ran;
            CHECK_NOTHROW(e.run(ran));
            SourceTexts texts;
            texts.add(SourceText(file, qm::test::slurp(file)));
            texts.attach_lines(ran, shown);
        } else {
            shown = d;
        }
        if (warnings_only) {
            CHECK(!shown.has_errors());
            CHECK(!shown.items().empty());
        } else {
            CHECK(shown.has_errors());  // every other case is an erroneous program
        }
        std::ostringstream printed;
        shown.print(printed);
        std::string actual = strip(printed.str(), dir.lexically_normal().string() + "/");
        qm::test::check_golden(actual, std::filesystem::path(entry.path()).replace_extension(".err"));
        ++cases;
    }
    CHECK(cases >= 10);
}
