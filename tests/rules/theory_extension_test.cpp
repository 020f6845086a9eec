// tests/rules/theory_extension_test.cpp: the theory is data. A copy of rules/ without the law of
// motion transfer (Table 3.2) lets the gear pair of Figure 7.12 turn every way (nine combinations
// instead of six); a new law file added to a copy changes the answer without recompiling; and the
// command line's --rules selects the folder.
#include "analysis/analysis.hpp"
#include "scene/scene_parser.hpp"
#include <cstdlib>
#include <doctest/doctest.h>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <sys/wait.h>

namespace fs = std::filesystem;
using namespace qm;

namespace {

fs::path copy_rules(const std::string& name) {
    const fs::path dir = fs::path(QM_BINARY_DIR) / ("rules_copy_" + name);
    fs::remove_all(dir);
    fs::create_directories(dir);
    // Recursive: the envisioner's laws live in rules/clock/, and a copy must carry the whole theory.
    fs::copy(fs::path(QM_SOURCE_DIR) / "rules", dir, fs::copy_options::recursive);
    return dir;
}

std::uint64_t gear_combinations(const fs::path& rules) {
    Diagnostics d;
    auto scene = scene::read_scene_file(std::string(QM_SOURCE_DIR) + "/scenarios/alex/gears.def", d);
    REQUIRE(scene.has_value());
    analysis::AnalysisOptions o;
    o.rules_directory = rules;
    auto a = analysis::analyse(*scene, o, d);
    if (!a) {
        std::ostringstream os;
        d.print(os);
        FAIL(os.str());
    }
    return a->situations()[0].combination_count();
}

std::string run(const std::string& args) {
    const std::string out = std::string(QM_BINARY_DIR) + "/theory_extension.out";
    const std::string cmd = "cd / && " + std::string(QM_BINARY_DIR) + "/cli/qm-atms " + args + " > " + out + " 2>&1";
    const int status = std::system(cmd.c_str());
    std::ifstream in(out);
    std::stringstream s;
    s << in.rdbuf();
    return std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + "\n" + s.str();
}

}  // namespace

TEST_CASE("rules/theory: the bundled laws give the gear pair six combinations (Figure 7.14)") {
    CHECK(gear_combinations(fs::path(QM_SOURCE_DIR) / "rules") == 6);
}

TEST_CASE("rules/theory: without the law of motion transfer the gear pair has nine combinations") {
    const fs::path dir = copy_rules("no_pushing");
    REQUIRE(fs::remove(dir / "motion_transfer.rules"));
    CHECK(gear_combinations(dir) == 9);
}

TEST_CASE("rules/theory: a new law file takes effect without recompiling") {
    const fs::path dir = copy_rules("one_way");
    std::ofstream(dir / "one_way_clutch.rules")
        << "# A one-way clutch on the follower's shaft: it never turns clockwise.\n"
           "rule one-way-clutch\n"
           "  when (rot-motion follower (-))\n"
           "  then false\n";
    CHECK(gear_combinations(dir) == 5);  // the six of Figure 7.14 less (driver (+), follower (-))
    // The command line finds the folder through --rules, whatever the working directory.
    const std::string scene = std::string(QM_SOURCE_DIR) + "/scenarios/alex/gears.def";
    const std::string out = run(scene + " --rules " + dir.string() + " --why 'Rotational-Motion (follower (-))'");
    CHECK(out.rfind("0\n", 0) == 0);
    CHECK(out.find("ruled out") != std::string::npos);
    CHECK(out.find("one-way-clutch") != std::string::npos);
}

TEST_CASE("rules/theory: a broken law file is bad input, located") {
    const fs::path dir = copy_rules("broken");
    std::ofstream(dir / "zz_broken.rules") << "rule half-written\n  when (rot-motion ?o\n";
    const std::string out = run(std::string(QM_SOURCE_DIR) + "/scenarios/alex/gears.def --rules " + dir.string());
    CHECK(out.rfind("2\n", 0) == 0);
    CHECK(out.find("zz_broken.rules:") != std::string::npos);
    // An empty folder is bad input too.
    const fs::path empty = fs::path(QM_BINARY_DIR) / "rules_copy_empty";
    fs::remove_all(empty);
    fs::create_directories(empty);
    CHECK(run(std::string(QM_SOURCE_DIR) + "/scenarios/alex/gears.def --rules " + empty.string()).rfind("2\n", 0) == 0);
}

TEST_CASE("rules/theory: the default laws are found from the executable, not the working directory") {
    const std::string out = run(std::string(QM_SOURCE_DIR) + "/scenarios/alex/gears.def --json");
    CHECK(out.rfind("0\n", 0) == 0);
    CHECK(out.find("\"scene\": \"gears\"") != std::string::npos);
}
