// tests/cli/limits_test.cpp: the resource limits and the uniform option errors of the command
// line, end to end through the built qm-atms. A program that counts for
// ever, 40 binary choice sets (2^40 interpretations), a scene analysed under a tiny limit and an
// envisionment beyond --max-states or --max-memory stop with `error: ... limit N reached while
// ...; raise it with --...` (the envisioner's saying how far it got), exit 2, an empty standard
// output and no output file; every option error names the option and what it expected (exact
// texts); a scene or rule file that starts with a UTF-8 byte-order mark reads as without it; a
// folder given as a scene says so.
#include "qm_atms_run.hpp"
#include "qm/address_sanitizer.hpp"
#include <doctest/doctest.h>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <regex>
#include <spawn.h>
#include <string>
#include <tuple>
#include <sys/resource.h>
#include <sys/wait.h>
#include <utility>
#include <vector>

using qm::test::qm_atms;

namespace {
const std::string dir = QM_BINARY_DIR;
const std::string src_dir = QM_SOURCE_DIR;

std::string write_rules(const std::string& name, const std::string& text) {
    const std::string path = dir + "/limits_test_" + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
}

const std::string grow = write_rules("grow.rules", "fact (n 0)\nrule grow\n  when (n ?x)\n  then (n (+ ?x 1))\n");

std::string choices(int n) {
    std::string text;
    for (int i = 1; i <= n; ++i) text += "fact (o " + std::to_string(i) + ")\n";
    return text + "rule pick\n  when (o ?x)\n  then [exactly one ?v in {a b}: assume (v ?x ?v)]\n";
}

// `qm-atms envision` with the tests' place cache, asked to write its graph to `limits_test.dot`
// and `limits_test.svg` (removed first, so that a file there after the run was written by it).
const std::string limit_dot = dir + "/limits_test.dot", limit_svg = dir + "/limits_test.svg";
qm::test::Run envision_with_files(const std::string& args) {
    for (const auto& f : {limit_dot, limit_svg}) std::filesystem::remove(f);
    return qm_atms("envision " + args + " --dot " + limit_dot + " --svg " + limit_svg + " --cache " + dir + "/envision-test-place-cache",
                   "limits");
}

bool any_graph_file() {
    for (const auto& f : {limit_dot, limit_svg})
        if (std::filesystem::exists(f) || std::filesystem::exists(f + ".part")) return true;
    return false;
}

// The message with its elapsed time, which differs from run to run, as `T`.
std::string with_time_as_t(const std::string& message) {
    return std::regex_replace(message, std::regex("\\(after [0-9]+\\.[0-9] s: "), "(after T s: ");
}
}  // namespace

TEST_CASE("cli/limits: a program that counts for ever stops at --max-facts, located at the rule, nothing written") {
    auto r = qm_atms("run " + grow + " --max-facts 1000 --json", "limits");
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err == grow + ":2:1: error: fact limit 1000 reached while firing rule 'grow'; raise it with --max-facts\n");
}

TEST_CASE("cli/limits: the default limits stop the runaway programs") {
#ifndef QM_SANITIZED_BUILD  // 500000 facts: seconds in Release, too long for a sanitizer build's test
    auto r = qm_atms("run " + grow, "limits");
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err == grow + ":2:1: error: fact limit 500000 reached while firing rule 'grow'; raise it with --max-facts\n");
#endif
    // 2^40 interpretations: stopped while they are enumerated (they were once all collected first).
    const std::string forty = write_rules("forty.rules", choices(40));
    auto c = qm_atms("run " + forty + " --max-environments 20000", "limits");
    CHECK(c.status == 2);
    CHECK(c.out.empty());
    CHECK(c.err == "qm-atms: error: environment limit 20000 reached while enumerating the interpretations of " + forty +
                       "; raise it with --max-environments\n");
}

TEST_CASE("cli/limits: a limit that is not reached changes nothing") {
    const std::string ten = write_rules("ten.rules", choices(10));
    auto free = qm_atms("run " + ten + " --json", "limits");
    REQUIRE(free.status == 0);
    CHECK(free.out.find("\"interpretations\"") != std::string::npos);
    auto bounded = qm_atms("run " + ten + " --json --max-facts 1000 --max-environments 100000 --max-memory 2G", "limits");
    CHECK(bounded.status == 0);
    CHECK(bounded.out == free.out);
    const std::string scene = src_dir + "/scenarios/alex/arch.def --rules " + src_dir + "/rules";
    auto analysed = qm_atms(scene + " --json", "limits");
    REQUIRE(analysed.status == 0);
    CHECK(qm_atms(scene + " --json --max-facts 100000 --max-environments 1000000", "limits").out == analysed.out);
}

TEST_CASE("cli/limits: a scene analysed under a tiny limit stops with exit 2 and writes nothing") {
    const std::string scene = src_dir + "/scenarios/alex/arch.def --rules " + src_dir + "/rules";
    for (const std::string& extra : {std::string(" --json"), std::string(""), std::string(" --why 'Translational-Freedom (cross-bar (+ +))'")}) {
        auto f = qm_atms(scene + extra + " --max-facts 10", "limits");
        CHECK(f.status == 2);
        CHECK(f.out.empty());
        CHECK(f.err.find("error: fact limit 10 reached while ") != std::string::npos);
        CHECK(f.err.ends_with("; raise it with --max-facts\n"));
        auto e = qm_atms(scene + extra + " --max-environments 10", "limits");
        CHECK(e.status == 2);
        CHECK(e.out.empty());
        CHECK(e.err.ends_with("environment limit 10 reached while analysing " + src_dir +
                              "/scenarios/alex/arch.def; raise it with --max-environments\n"));
    }
}

#ifndef QM_UNDER_ASAN  // AddressSanitizer reserves terabytes of address space: no --max-memory there
TEST_CASE("cli/limits: --max-memory stops a program that needs more, exit 2, nothing written") {
    auto r = qm_atms("run " + grow + " --max-facts 100000000 --max-memory 200M", "limits");
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK(r.err == "qm-atms: error: memory limit 200M reached while running " + grow + "; raise it with --max-memory\n");
}

// A small limit bounds the whole process: its peak resident memory, read for exactly this child by
// wait4, stays under the limit.
TEST_CASE("cli/limits: a small --max-memory still bounds the process") {
    posix_spawn_file_actions_t io;
    posix_spawn_file_actions_init(&io);
    posix_spawn_file_actions_addopen(&io, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&io, 2, "/dev/null", O_WRONLY, 0);
    const std::string exe = dir + "/cli/qm-atms";
    std::vector<std::string> args = {exe, "run", grow, "--max-facts", "100000000", "--max-memory", "96M"};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    pid_t pid = 0;
    REQUIRE(posix_spawn(&pid, exe.c_str(), &io, nullptr, argv.data(), environ) == 0);
    posix_spawn_file_actions_destroy(&io);
    int status = 0;
    rusage usage{};
    REQUIRE(wait4(pid, &status, 0, &usage) == pid);
    CHECK(WIFEXITED(status));
    CHECK(WEXITSTATUS(status) == 2);
    CHECK(usage.ru_maxrss < 96 * 1024);  // KiB
}
#endif

TEST_CASE("cli/limits: envision stops at --max-states over all chains, says how far it got, and writes nothing") {
    const std::string cam = src_dir + "/scenarios/metric/cam.def";
    auto r = envision_with_files(cam + " --max-states 10");
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK_FALSE(any_graph_file());
    CHECK(with_time_as_t(r.err) == "qm-atms: error: state limit 10 reached while finding the states of chain 1 of " + cam +
                                       " (after T s: 10 states and 0 transitions found); raise it with --max-states\n");
    // Chain 1 (a gear pair) has 3 states and 4 transitions; chain 2 reaches the limit, which is the
    // one given, not what chain 1 left of it.
    const std::string two = src_dir + "/tests/envision/scenes/two_chains.def";
    auto t = envision_with_files(two + " --max-states 10");
    CHECK(t.status == 2);
    CHECK(t.out.empty());
    CHECK_FALSE(any_graph_file());
    CHECK(with_time_as_t(t.err) == "qm-atms: error: state limit 10 reached while finding the states of chain 2 of " + two +
                                       " (after T s: 10 states and 4 transitions found); raise it with --max-states\n");
    // Exactly as many states as the limit: not reached, and both files are written.
    auto enough = envision_with_files(two + " --max-states 141");
    CHECK(enough.status == 0);
    CHECK(enough.out.find("summary: 2 chains, 141 states, ") != std::string::npos);
    CHECK(std::filesystem::exists(limit_dot));
    CHECK(std::filesystem::exists(limit_svg));
}

#ifndef QM_UNDER_ASAN
TEST_CASE("cli/limits: envision stops at --max-memory, says how far it got, and writes nothing") {
    // The escapement with its train has far more states than 40M of address space holds; which
    // phase the memory runs out in depends on the machine's libraries, so any is accepted.
    const std::string train = src_dir + "/scenarios/clock/escapement_train.def";
    // The pairs' vocabularies are cached first, so that the limit is met by the states and
    // transitions rather than by the geometry.
    const auto cached = envision_with_files(train + " --max-states 1");
    REQUIRE(cached.status == 2);
    CHECK(cached.err.find("state limit 1 reached while finding the states of chain 1") != std::string::npos);
    auto r = envision_with_files(train + " --max-memory 40M");
    CHECK(r.status == 2);
    CHECK(r.out.empty());
    CHECK_FALSE(any_graph_file());
    const std::regex message("qm-atms: error: memory limit 40M reached while (making the place vocabularies|finding the (states|transitions) "
                             "of chain 1) of " + train + R"( \(after [0-9]+\.[0-9] s: [0-9]+ states and [0-9]+ transitions found\); )"
                             "raise it with --max-memory\n");
    CHECK_MESSAGE(std::regex_match(r.err, message), r.err);
}
#endif

TEST_CASE("cli/limits: envision's limits, when not reached, change nothing") {
    const std::string cam = src_dir + "/scenarios/metric/cam.def --json --cache " + dir + "/envision-test-place-cache";
    auto free = qm_atms("envision " + cam, "limits");
    REQUIRE(free.status == 0);
    auto bounded = qm_atms("envision " + cam + " --max-states 138 --max-memory 2G", "limits");
    CHECK(bounded.status == 0);
    CHECK(bounded.out == free.out);
    CHECK(bounded.err == free.err);
}

TEST_CASE("cli/options: every option error names the option and what it expected") {
    const std::string scene = src_dir + "/scenarios/alex/arch.def";
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"run", "no program given"},
        {"run x.rules --max-facts", "--max-facts expects a positive number, but nothing follows it"},
        {"run x.rules --max-facts ten", "--max-facts expects a positive number, not 'ten'"},
        {"run x.rules --max-facts 0", "--max-facts expects a positive number, not '0'"},
        {"run x.rules --max-environments -5", "--max-environments expects a positive number, not '-5'"},
        {"run x.rules --max-facts 5 --max-facts 6", "--max-facts is given twice ('5', '6'): give it once"},
        {"run x.rules --max-memory 4Q", "--max-memory expects a size like 4G, 512M or 2000000000 (bytes), not '4Q'"},
        {"run x.rules --max-memory 0", "--max-memory expects a size like 4G, 512M or 2000000000 (bytes), not '0'"},
        {"run x.rules --max-memory 512M --max-memory 1G", "--max-memory is given twice ('512M', '1G'): give it once"},
        {"run x.rules --why a --why b", "--why is given twice ('a', 'b'): ask one at a time"},
        {"run x.rules --why", "--why expects a fact, e.g. --why '(queen 1 2)', but nothing follows it"},
        {"run x.rules --lmit 3", "unknown option '--lmit'"},
        {"run x.rules y.rules", "more than one program given ('x.rules', 'y.rules')"},
        {scene + " --limit", "--limit expects a positive number of combinations, but nothing follows it"},
        {scene + " --limit 0", "--limit expects a positive number of combinations, not '0'"},
        {scene + " --limit 3 --limit 4", "--limit is given twice ('3', '4'): give it once"},
        {scene + " --rules a --rules b", "--rules is given twice ('a', 'b'): give it once"},
        {scene + " --config a --config b", "--config is given twice ('a', 'b'): give it once"},
        {scene + " --situation 1 --situation 2", "--situation is given twice ('1', '2'): give it once"},
        {scene + " --max-facts 1 --max-facts 1", "--max-facts is given twice ('1', '1'): give it once"},
        {scene + " --bogus", "unknown option '--bogus'"},
        {"envision x.def --max-memory 4Q", "--max-memory expects a size like 4G, 512M or 2000000000 (bytes), not '4Q'"},
        {"envision x.def --max-memory 1G --max-memory 2G", "--max-memory is given twice ('1G', '2G'): give it once"},
        {"envision x.def --max-facts 10", "unknown option '--max-facts'"},
    };
    for (const auto& [args, message] : cases) {
        CAPTURE(args);
        auto r = qm_atms(args, "options");
        CHECK(r.status == 2);
        CHECK(r.out.empty());
        CHECK(r.err.rfind("qm-atms: error: " + message + "\n", 0) == 0);
    }
}

TEST_CASE("cli/options: --situation out of range is located however it is wrong") {
    const std::string scene = src_dir + "/scenarios/alex/arch.def --rules " + src_dir + "/rules";
    for (const auto& [value, found] : std::vector<std::pair<std::string, std::string>>{
             {"0", "0"}, {"-1", "-1"}, {"999", "999"}, {"abc", "'abc'"}, {"1x", "'1x'"}}) {
        auto r = qm_atms(scene + " --situation " + value, "options");
        CHECK(r.status == 2);
        CHECK(r.err == "--situation:1:1: error: expected a situation from 1 to 1, but found " + found + "\n");
    }
}

TEST_CASE("cli/files: a folder or a missing file says so; a file given as the rules folder too") {
    auto folder = qm_atms(src_dir + "/scenarios", "files");
    CHECK(folder.status == 2);
    CHECK(folder.err == src_dir + "/scenarios:1:1: error: cannot read scene file '" + src_dir + "/scenarios': it is a directory, not a file\n");
    auto missing = qm_atms(dir + "/no_such_scene.def", "files");
    CHECK(missing.status == 2);
    CHECK(missing.err == dir + "/no_such_scene.def:1:1: error: cannot read scene file '" + dir + "/no_such_scene.def': no such file\n");
    const std::string scene = src_dir + "/scenarios/alex/arch.def";
    auto rules_file = qm_atms(scene + " --rules " + scene, "files");
    CHECK(rules_file.status == 2);
    CHECK(rules_file.err == scene + ":1:1: error: expected a folder of .rules files (the laws), but it is a file, not a folder\n");
    auto no_rules = qm_atms(scene + " --rules " + dir + "/no_such_folder", "files");
    CHECK(no_rules.err == dir + "/no_such_folder:1:1: error: expected a folder of .rules files (the laws), but there is no such folder\n");
    auto empty = qm_atms(scene + " --rules " + src_dir + "/docs", "files");
    CHECK(empty.err == src_dir + "/docs:1:1: error: expected a folder of .rules files (the laws), but it holds none\n");
}

TEST_CASE("cli/files: a UTF-8 byte-order mark at the start of a scene, metric scene or rule file is accepted") {
    const std::string rules = " --rules " + src_dir + "/rules --json";
    for (const auto& [command, file, options] : {std::tuple{"", "scenarios/alex/arch.def", rules},
                                                 std::tuple{"", "scenarios/alex/block_stack.def", rules},
                                                 std::tuple{"", "scenarios/metric/cam.def", rules},
                                                 std::tuple{"run ", "scenarios/rules/queens5.rules", std::string(" --json")}}) {
        CAPTURE(file);
        const std::string original = src_dir + "/" + file;
        const std::string marked = write_rules("bom_" + original.substr(original.rfind('/') + 1), "\xEF\xBB\xBF" + qm::test::slurp(original));
        auto a = qm_atms(command + original + options, "files"), b = qm_atms(command + marked + options, "files");
        REQUIRE(a.status == 0);
        CHECK(b.status == 0);
        CHECK(b.out == a.out);
        CHECK(b.err == a.err);
    }
}
