// tests/cli/check_command_test.cpp: rule files checked like code through the
// built executable: `qm-atms check` on the bundled laws (clean), on small law folders whose
// diagnostics are golden files (tests/cli/check/NAME/ with the exact standard error in NAME.err,
// the folder's path written RULES/), and on copies of rules/ with the slips of the hand the issue
// names (a misspelt predicate and a misspelt builtin test are errors that stop an analysis; a 3-D
// direction in a law run on a 2-D scene is a located warning). QM_WRITE_GOLDEN=1 rewrites the .err files.
#include "qm_atms_run.hpp"
#include <doctest/doctest.h>
#include <fstream>
#include <regex>
#include <string>

using qm::test::qm_atms;

namespace {

const std::string source = QM_SOURCE_DIR;

std::string replace_all(std::string text, const std::string& from, const std::string& to) {
    for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

std::string mutated_rules(const std::string& tag, const std::string& file, const std::string& from, const std::string& to) {
    return qm::test::mutated_rules("rules", "check_" + tag, file, from, to);
}

void check_golden(const std::string& name, const std::string& err) {
    const std::string golden = source + "/tests/cli/check/" + name + ".err";
    const std::string actual = replace_all(err, source + "/tests/cli/check/" + name + "/", "RULES/");
    qm::test::check_golden(actual, golden);
}

}  // namespace

TEST_CASE("cli/check: the bundled laws have no error and no warning, in 2-D and 3-D") {
    for (const char* dims : {"", " --dimensions 2", " --dimensions 3"}) {
        CAPTURE(dims);
        auto r = qm_atms("check " + source + "/rules" + dims, "check");
        CHECK(r.status == 0);
        CHECK(r.err == "");
        CHECK(std::regex_search(r.out, std::regex("^checked [0-9]+ files, [0-9]+ rules: no errors, no warnings\n$")));
    }
    // The envisioner's laws (chapters 5 and 8) too: every file cites the thesis.
    auto clock = qm_atms("check " + source + "/rules/clock", "check");
    CHECK(clock.status == 0);
    CHECK(clock.err == "");
    CHECK(std::regex_search(clock.out, std::regex("no errors, no warnings\n$")));
    // With no path: the laws qm-atms uses.
    auto r = qm_atms("check", "check");
    CHECK(r.status == 0);
    CHECK(r.out.find("no errors, no warnings") != std::string::npos);
}

TEST_CASE("cli/check: a misspelt predicate or builtin test is a located error with 'did you mean' (golden)") {
    auto r = qm_atms("check " + source + "/tests/cli/check/typo", "check");
    CHECK(r.status == 2);
    CHECK(r.out == "checked 2 files: 2 errors, no warnings\n");  // a program with errors is not compiled: no rule count
    check_golden("typo", r.err);
}

TEST_CASE("cli/check: warnings: citations, direction arity, unused and never-firing rules (golden)") {
    auto r = qm_atms("check " + source + "/tests/cli/check/warnings --dimensions 2", "check");
    CHECK(r.status == 0);
    CHECK(r.out == "checked 4 files, 6 rules: no errors, 6 warnings\n");
    check_golden("warnings", r.err);
    // A 3-D scene: the 3-D directions are fine, the three 2-D ones ((0 -) twice, (0 0)) are not.
    auto r3 = qm_atms("check " + source + "/tests/cli/check/warnings --dimensions 3", "check");
    CHECK(r3.out == "checked 4 files, 6 rules: no errors, 7 warnings\n");
    CHECK(r3.err.find("(0 0 +)") == std::string::npos);
    // Files named alone are programs, not laws: no citation is asked for.
    auto one = qm_atms("check " + source + "/tests/cli/check/warnings/uncited.rules " + source +
                           "/tests/cli/check/warnings/scene.rules",
                       "check");
    CHECK(one.status == 0);
    CHECK(one.err.find("cite") == std::string::npos);
}

TEST_CASE("cli/check: the issue's slips in rules/ stop the analysis instead of changing its answer") {
    const std::string scene = source + "/scenarios/alex/gears.def";
    SUBCASE("open-half-plain for open-half-plane in a condition of motion_transfer.rules") {
        const std::string dir = mutated_rules("plain", "motion_transfer.rules", "(open-half-plane (neg ?normals) ?d1)",
                                              "(open-half-plain (neg ?normals) ?d1)");
        auto c = qm_atms("check " + dir, "check");
        CHECK(c.status == 2);
        CHECK(c.err.find("motion_transfer.rules:") != std::string::npos);
        CHECK(c.err.find("error: unknown predicate 'open-half-plain', used in a condition of rule 'pushing-by-translation'") !=
              std::string::npos);
        CHECK(c.err.find("did you mean 'open-half-plane' (a builtin test)?") != std::string::npos);
        auto a = qm_atms(scene + " --rules " + dir, "check");
        CHECK(a.status == 2);
        CHECK(a.out == "");
        CHECK(a.err.find("did you mean 'open-half-plane' (a builtin test)?") != std::string::npos);
    }
    SUBCASE("surfce for surface") {
        const std::string dir = mutated_rules("surfce", "contact_constraint.rules", "(surface ?obj ?q) (dimensions ?n)\n  then [for all ?d2",
                                              "(surfce ?obj ?q) (dimensions ?n)\n  then [for all ?d2");
        auto c = qm_atms("check " + dir, "check");
        CHECK(c.status == 2);
        CHECK(c.err.find("unknown predicate 'surfce'") != std::string::npos);
        CHECK(c.err.find("did you mean 'surface'?") != std::string::npos);
    }
    SUBCASE("a 3-D direction in a law run on a 2-D scene: a located warning; the answer is unchanged") {
        const std::string dir = mutated_rules("arity", "", "", "");
        std::ofstream(dir + "/extra.rules") << "cite \"section 3.1, Table 3.1\"\n\nrule down-in-space\n"
                                               "  when (trans-constraint ?o (0 0 -))\n  then (trans-constraint ?o (0 -))\n";
        auto a = qm_atms(scene + " --rules " + dir, "check");
        auto plain = qm_atms(scene, "check");
        CHECK(a.status == 0);
        CHECK(a.out == plain.out);
        CHECK(a.err.find(dir + "/extra.rules:4:29: warning: the direction (0 0 -) has 3 signs, but scene 'gears' is 2-D: its "
                               "translations have 2 signs and its rotations 1: it can match none of them") != std::string::npos);
        auto three = qm_atms(source + "/scenarios/alex/block_3d.def --rules " + dir, "check");
        CHECK(three.status == 0);
        CHECK(three.err.find("extra.rules:5:29: warning: the direction (0 -) has 2 signs, but scene") != std::string::npos);
    }
}
