// tests/cli/run_command_test.cpp: `qm-atms run` end to end through the built executable: exit
// statuses (0 ok, 2 bad input), the JSON shape, --why, and the other argument forms of main.
#include <cstdio>
#include <cstdlib>
#include <doctest/doctest.h>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace {

struct Result {
    int status = -1;
    std::string out, err;
};

std::string slurp(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

Result qm_atms(const std::string& args) {
    static int counter = 0;
    std::string base = std::string(QM_BINARY_DIR) + "/cli_test_" + std::to_string(++counter);
    std::string cmd = std::string(QM_BINARY_DIR) + "/cli/qm-atms " + args + " >" + base + ".out 2>" + base + ".err";
    int raw = std::system(cmd.c_str());
    Result r;
    r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
    r.out = slurp(base + ".out");
    r.err = slurp(base + ".err");
    std::remove((base + ".out").c_str());
    std::remove((base + ".err").c_str());
    return r;
}

std::string write_temp(const std::string& name, const std::string& text) {
    std::string path = std::string(QM_BINARY_DIR) + "/" + name;
    std::ofstream(path) << text;
    return path;
}

std::string scenario(const std::string& name) { return std::string(QM_SOURCE_DIR) + "/scenarios/rules/" + name; }

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

}  // namespace

TEST_CASE("cli/run_command: --json prints exactly the agreed object") {
    Result r = qm_atms("run " + scenario("queens6.rules") + " --json");
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    REQUIRE(r.out.rfind("{\"facts\": [{\"fact\": \"(queen 1 1)\", \"label\": [[\"(queen 1 1)\"]]}", 0) == 0);
    auto nogoods = r.out.find("], \"nogoods\": [[");
    auto interpretations = r.out.find("]], \"interpretations\": [[");
    REQUIRE(nogoods != std::string::npos);
    REQUIRE(interpretations != std::string::npos);
    CHECK(r.out.substr(r.out.size() - 3) == "]}\n");
    // 6-queens has 4 solutions of 6 queens each.
    std::string tail = r.out.substr(interpretations + std::string("]], \"interpretations\": ").size());
    CHECK(count(tail, "[\"(queen 1 ") == 4);
    CHECK(count(tail, "\"(queen ") == 24);
    // Deterministic: a second run prints the same bytes.
    CHECK(qm_atms("run " + scenario("queens6.rules") + " --json").out == r.out);
}

TEST_CASE("cli/run_command: --why explains a fact and a ruled-out fact") {
    Result holds = qm_atms("run " + scenario("queens4.rules") + " --why '(queen 1 2)'");
    CHECK(holds.status == 0);
    CHECK(holds.out.find("(queen 1 2) holds") == 0);
    CHECK(holds.out.find("rule place at ") != std::string::npos);
    CHECK(holds.out.find("{?r = 1, ?c = 2}: (row 1), assume (queen 1 2)") != std::string::npos);
    Result out = qm_atms("run " + scenario("polybox.rules") + " --why '(value f 12)'");
    CHECK(out.status == 0);
    CHECK(out.out.find("(value f 12) is ruled out") == 0);
    CHECK(out.out.find("nogood {(mode a1 ok), (mode m1 ok), (mode m2 ok)}") != std::string::npos);
    CHECK(out.out.find("rule one-value-per-wire at ") != std::string::npos);
    Result bad = qm_atms("run " + scenario("queens4.rules") + " --why 'queen 1 2'");
    CHECK(bad.status == 2);
    CHECK(bad.err.find("--why:1:1: error: expected '(' to start a fact") == 0);
}

TEST_CASE("cli/run_command: bad input exits 2 with located diagnostics") {
    std::string syntax = write_temp("cli_bad_syntax.rules", "fact (p 1)\nrule r when (p ?x) then (q ?y)\nfact q\n");
    Result r = qm_atms("run " + syntax);
    CHECK(r.status == 2);
    CHECK(r.err.find(syntax + ":3:6: error: expected '(' but found 'q'") != std::string::npos);
    std::string negation = write_temp("cli_bad_negation.rules",
                                      "fact (bird opus)\nassume (penguin opus)\n"
                                      "rule flies when (bird ?b) not (penguin ?b) then (flies ?b)\n");
    Result n = qm_atms("run " + negation);
    CHECK(n.status == 2);
    CHECK(n.err.find(negation + ":3:31: error: rule 'flies': cannot decide (penguin opus)") == 0);
    CHECK(qm_atms("run /no/such/file.rules").status == 2);
    CHECK(qm_atms("run " + scenario("queens4.rules") + " --bogus").status == 2);
    CHECK(qm_atms("run").status == 2);
}

TEST_CASE("cli/run_command: --help, no arguments and scene files") {
    Result help = qm_atms("--help");
    CHECK(help.status == 0);
    CHECK(help.out.find("usage: qm-atms") == 0);
    CHECK(qm_atms("").status == 2);
    Result scene = qm_atms("scene.def");
    CHECK(scene.status == 2);
    CHECK(scene.err.find("scene.def") != std::string::npos);  // a missing scene file is bad input
}
