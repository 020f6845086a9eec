// tests/cli/geometry_dispatch_test.cpp: the two executables of cli/ (cli/geometry_dispatch.hpp,
// docs/perf/startup.md). needs_geometry() on every kind of command line; then, through the built
// executables, each geometry command gives the same status, output and files run through the light
// qm-atms (which hands it to qm-atms-geometry) as run through qm-atms-geometry directly; a light
// qm-atms without qm-atms-geometry beside it does its own commands and refuses the others with
// exit status 1 and a message naming what is missing.
#include "geometry_dispatch.hpp"
#include "qm_atms_run.hpp"
#include <array>
#include <doctest/doctest.h>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace {

using qm::cli::is_metric_scene;
using qm::cli::needs_geometry;
using qm::test::metric_scene;

bool needs(std::vector<std::string> args) { return needs_geometry(args); }

std::string alex_scene(const std::string& name) { return std::string(QM_SOURCE_DIR) + "/scenarios/alex/" + name; }

std::string write_temp(const std::string& name, const std::string& text) {
    const std::string path = std::string(QM_BINARY_DIR) + "/geometry_dispatch_" + name;
    std::ofstream(path) << text;
    return path;
}

const std::string light = std::string(QM_BINARY_DIR) + "/cli/qm-atms";
const std::string full = std::string(QM_BINARY_DIR) + "/cli/qm-atms-geometry";

// The same command line through both executables: the same status, standard output and error.
void check_same(const std::string& args) {
    CAPTURE(args);
    const auto a = qm::test::run_executable(light, args, "geometry_dispatch_test");
    const auto b = qm::test::run_executable(full, args, "geometry_dispatch_test");
    CHECK(a.status == b.status);
    CHECK(a.out == b.out);
    CHECK(a.err == b.err);
}

}  // namespace

TEST_CASE("cli/geometry_dispatch: the commands that need the geometry stack, by their first argument") {
    const std::string cam = metric_scene("cam.def");
    CHECK(needs({"envision", cam}));
    CHECK(needs({"draw", cam, "--svg", "x.svg"}));
    CHECK(needs({"explore", cam, "-o", "out"}));
    CHECK(needs({"--emit-def", cam, "cam=30"}));
    CHECK(needs({"--places", cam}));
    CHECK(needs({"envision"}));  // its usage error is the full executable's
    CHECK_FALSE(needs({}));
    CHECK_FALSE(needs({"--help"}));
    CHECK_FALSE(needs({"-h"}));
    CHECK_FALSE(needs({"run", std::string(QM_SOURCE_DIR) + "/scenarios/rules/queens6.rules"}));
    CHECK_FALSE(needs({"check", std::string(QM_SOURCE_DIR) + "/rules"}));
}

TEST_CASE("cli/geometry_dispatch: a scene needs the geometry stack when its file is a metric scene") {
    const std::string cam = metric_scene("cam.def");
    CHECK(needs({cam}));
    CHECK(needs({cam, "--config", "cam=30, follower=0.1"}));
    CHECK(needs({"--json", cam, "-i"}));  // the scene found where the scene command finds it
    CHECK(needs({cam, "-i"}));            // a metric scene's session is delegated at its start
    CHECK_FALSE(needs({alex_scene("block.def")}));
    CHECK_FALSE(needs({alex_scene("gears.def"), "-i"}));  // an Alex scene's session stays light
    CHECK_FALSE(needs({alex_scene("block.def"), "--config", "cam=3"}));  // refused by the light one, as by the full one
    CHECK_FALSE(needs({std::string(QM_BINARY_DIR) + "/no-such-scene.def"}));  // an unreadable file: the light one says so
    CHECK_FALSE(needs({cam, "--frobnicate"}));  // a bad command line: the light one says so
    CHECK_FALSE(needs({cam, alex_scene("block.def")}));  // two scenes: refused as above
}

TEST_CASE("cli/geometry_dispatch: interactive_on_terminal is an Alex scene's -i reading a terminal") {
    using qm::cli::interactive_on_terminal;
    const std::string gears = alex_scene("gears.def");
    auto on = [](std::vector<std::string> args, bool terminal) { return interactive_on_terminal(args, terminal); };
    CHECK(on({gears, "-i"}, true));
    CHECK(on({gears, "--interactive", "--json"}, true));
    CHECK_FALSE(on({gears, "-i"}, false));  // a pipe or a file: the light executable reads it
    CHECK_FALSE(on({gears}, true));
    CHECK_FALSE(on({gears, "-i", "--bogus"}, true));  // rejected by the scene command itself
    CHECK_FALSE(on({"run", gears, "-i"}, true));
    CHECK_FALSE(on({"--help"}, true));
    CHECK_FALSE(on({}, true));
}

TEST_CASE("cli/geometry_dispatch: is_metric_scene reads past a byte-order mark, blanks and comments") {
    CHECK(is_metric_scene("(Defmechanism cam)"));
    CHECK(is_metric_scene("\xEF\xBB\xBF; a comment\n  ; another\n\n( DEFMECHANISM cam)"));
    CHECK_FALSE(is_metric_scene("(Defscene block)"));
    CHECK_FALSE(is_metric_scene("; (Defmechanism in a comment)\n(Defscene block)"));
    CHECK_FALSE(is_metric_scene(""));
    CHECK_FALSE(is_metric_scene("Defmechanism"));
    CHECK_FALSE(is_metric_scene("(Defmech"));
}

TEST_CASE("cli/geometry_dispatch: each geometry command is the same through qm-atms as through qm-atms-geometry") {
    const std::string cam = metric_scene("cam.def");
    const std::string cache = std::string(QM_BINARY_DIR) + "/geometry-dispatch-place-cache";
    // The place cache is filled first: `--places` says which pairs came from it.
    REQUIRE(qm::test::run_executable(full, "--places " + cam + " --cache " + cache, "geometry_dispatch_test").status == 0);
    check_same("--emit-def " + cam + " 'cam=30, follower=0.1'");
    check_same("--places " + cam + " --json --cache " + cache);
    check_same("--places " + cam + " --no-cache");
    check_same("envision " + cam + " --cache " + cache);
    check_same("envision " + cam + " --table --cache " + cache);
    check_same(cam + " --config 'cam=30, follower=0.1' --json");
    check_same(cam + " --config 'nosuch=3'");  // bad input: exit 2, the same located error
    check_same("--places " + cam + " --colour");
    check_same("envision");
    check_same("draw");
    check_same("explore " + cam);
    const std::string input = write_temp("session.txt", "motions\nwhy Rotational-Motion (cam (+))\n");
    check_same(cam + " --config 'cam=30, follower=0.1' -i <" + input);  // a metric scene's session
}

TEST_CASE("cli/geometry_dispatch: draw and explore write the same files through qm-atms as through qm-atms-geometry") {
    const std::string cam = metric_scene("cam.def");
    const std::string dir = std::string(QM_BINARY_DIR) + "/geometry_dispatch_files";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::array<std::string, 2> exes{light, full};
    for (int k = 0; k < 2; ++k) {
        const std::string n = std::to_string(k);
        const auto d = qm::test::run_executable(exes[k], "draw " + cam + " --config 'cam=30, follower=0.1' --svg " + dir + "/draw" + n + ".svg",
                                                "geometry_dispatch_test");
        CHECK(d.status == 0);
        const auto e = qm::test::run_executable(exes[k], "explore " + cam + " -o " + dir + "/explore" + n + " --no-cache", "geometry_dispatch_test");
        CHECK(e.status == 0);
    }
    const std::string drawn = qm::test::slurp(dir + "/draw0.svg");
    CHECK(drawn.find("<svg") != std::string::npos);
    CHECK(drawn == qm::test::slurp(dir + "/draw1.svg"));
    const std::string page = qm::test::slurp(dir + "/explore0/index.html");
    CHECK(page.find("qm-explore/1") != std::string::npos);
    CHECK(page == qm::test::slurp(dir + "/explore1/index.html"));
}

TEST_CASE("cli/geometry_dispatch: a light qm-atms without qm-atms-geometry beside it") {
    const std::string dir = std::string(QM_BINARY_DIR) + "/geometry_dispatch_alone";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    const std::string alone = dir + "/qm-atms";
    std::filesystem::copy_file(light, alone);
    // Its own commands work as before: an Alex scene (the laws of this tree), --help.
    const auto block = qm::test::run_executable(alone, alex_scene("block.def"), "geometry_dispatch_test");
    CHECK(block.status == 0);
    CHECK(block.out == qm::test::run_executable(light, alex_scene("block.def"), "geometry_dispatch_test").out);
    CHECK(qm::test::run_executable(alone, "--help", "geometry_dispatch_test").status == 0);
    // A geometry command: exit 1, nothing on standard output, the missing executable named.
    for (const std::string& args : {"envision " + metric_scene("cam.def"), metric_scene("cam.def") + " --config 'cam=30'"}) {
        CAPTURE(args);
        const auto r = qm::test::run_executable(alone, args, "geometry_dispatch_test");
        CHECK(r.status == 1);
        CHECK(r.out.empty());
        CHECK(r.err.find("cannot run '" + dir + "/qm-atms-geometry': No such file or directory") != std::string::npos);
    }
}
