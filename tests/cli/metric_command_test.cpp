// tests/cli/metric_command_test.cpp: `qm-atms --emit-def` and `qm-atms --places` end to end through the
// built executable (cli/metric_command.hpp): the Alex scene of a metric scene at a configuration
// (contacts with their surfaces' normals and origin directions, corners, linkages as one body,
// constraints of sliding parts, the forces acting there), located errors with exit status 2,
// and place vocabularies as text, JSON and SVG, reused from the on-disk cache; parts that overlap as
// drawn are refused alike by every command that takes places.
#include "qm_atms_run.hpp"
#include <cstdio>
#include <cstdlib>
#include "../support/program_json.hpp"
#include <doctest/doctest.h>
#include <regex>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace {
using qm::test::write_temp;
using qm::test::count;
using qm::test::metric_scene;

using Array = nlohmann::json::array_t;
using Result = qm::test::Run;
using qm::test::slurp;

Result metric_run(const std::string& args) { return qm::test::qm_atms(args, "metric_test"); }


const std::string table_top =
    "(Defmechanism table-top\n"
    "  Parts ((table (block (width 4) (height 1)) (at 0 -0.5) (fixed))\n"
    "         (block (block) (at 0 0.5) (rotation))\n"
    "         (slider (polygon (0 -0.5) (0.5 0) (0 0.5) (-0.5 0)) (at 1.5 0.5) (translation (0 1) (limits 0 1)))))\n";

}  // namespace

TEST_CASE("cli/metric_command: --emit-def writes the Alex scene at a configuration (the cam touching its follower)") {
    // The cam's top is at 0.5 + 0.2 sin(30 deg) = 0.6: the follower, drawn at 0.5, rests on it at 0.1.
    const Result r = metric_run("--emit-def " + metric_scene("cam.def") + " 'cam=30, follower=0.1'");
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    CHECK(r.out ==
          "; Alex scene of " + metric_scene("cam.def") + " at 'cam=30, follower=0.1' (qm-atms --emit-def)\n"
          "(Defscenario 2 cam\n"
          "  Individuals (cam follower)\n"
          "  Descriptions ((rigid-ob cam)(rigid-ob follower))\n"
          "  Surfaces (\n"
          "    (cam\n"
          "      (cam-s1 (0 +) (- -)))\n"  // the cam's top, normal up, its pivot down-left
          "    (follower\n"
          "      (follower-s1 (0 -) (0 0))))\n"  // a sliding part has no centre of rotation
          "  Translational-Constraints ((cam (?x ?y))(follower (- -) (- 0) (- +) (+ -) (+ 0) (+ +)))\n"
          "  Rotational-Constraints ((follower (?r)))\n"
          "  Forces ())\n"
          "(Defstates\n"
          "  ((Contact cam-s1 follower-s1)\n"
          "   (Force cam (0 +) (- 0) motor)\n"
          "   (Force follower (0 -) (0 0) gravity)))\n");
    // Lifted clear of the cam there is no contact; the forces still act.
    const Result lifted = metric_run("--emit-def " + metric_scene("cam.def") + " 'cam=30, follower=0.2'");
    CHECK(lifted.status == 0);
    CHECK(count(lifted.out, "Contact") == 0);
    CHECK(count(lifted.out, "(Force ") == 2);
}

TEST_CASE("cli/metric_command: a block on a table touches at both ends of its bottom, with distinct origin directions") {
    const Result r = metric_run("--emit-def " + write_temp("table_top.def", table_top));
    CHECK(r.status == 0);
    CHECK(r.out.find("(block-s1 (0 -) (+ +))") != std::string::npos);  // bottom-left: the pivot is up and right
    CHECK(r.out.find("(block-s1-2 (0 -) (- +))") != std::string::npos);
    CHECK(r.out.find("(table-s3 (0 +) (0 0))") != std::string::npos);  // fixed: no centre of rotation
    CHECK(r.out.find("(Contact table-s3 block-s1)") != std::string::npos);
    CHECK(r.out.find("(Contact table-s3 block-s1-2)") != std::string::npos);
    // The slider stands on its lower limit: moving down past it is constrained too.
    CHECK(r.out.find("(slider (- -) (- 0) (- +) (0 -) (+ -) (+ 0) (+ +))") != std::string::npos);
    // Its corner resting on the table: an Alex corner between its two lower sides (Def 18); the
    // laws give it the reverse of the table's normal (3.1.1, rules/corners.rules).
    const Result down = metric_run("--emit-def " + write_temp("table_top.def", table_top) + " 'block=0, slider=0'");
    CHECK(down.status == 0);
    CHECK(down.out.find("(slider-s4 (- -) (0 0))") != std::string::npos);
    CHECK(down.out.find("(slider-s1 (+ -) (0 0))") != std::string::npos);
    CHECK(down.out.find("(slider-c1 slider-s4 slider-s1 (0 0))") != std::string::npos);
    CHECK(down.out.find("(Contact table-s3 slider-c1)") != std::string::npos);
    const Result up = metric_run("--emit-def " + write_temp("table_top.def", table_top) + " 'slider=1'");
    CHECK(up.out.find("(slider (- -) (- 0) (- +) (0 -) (+ -) (+ 0) (+ +))") == std::string::npos);  // off its lower limit
    CHECK(up.out.find("(slider (- -) (- 0) (- +) (0 +) (+ -) (+ 0) (+ +))") != std::string::npos);  // on its upper one
}

TEST_CASE("cli/metric_command: corner against corner is written as two Alex corners (Def 26)") {
    const std::string tips =
        "(Defmechanism tips\n"
        "  Parts ((upper (polygon (0 -0.5) (0.5 0) (0 0.5) (-0.5 0)) (at 0 0.5) (translation (0 1) (limits -1 1)))\n"
        "         (lower (polygon (0 -0.5) (0.5 0) (0 0.5) (-0.5 0)) (at 0 -0.5) (rotation))))\n";
    const Result r = metric_run("--emit-def " + write_temp("tips.def", tips));
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    CHECK(r.out.find("(upper-c1 upper-s4 upper-s1 (0 0))") != std::string::npos);
    CHECK(r.out.find("(lower-c3 lower-s2 lower-s3 (0 -))") != std::string::npos);
    CHECK(r.out.find("(Contact upper-c1 lower-c3)") != std::string::npos);
    // The laws decide the contact (rules/corners.rules): the upper tip, which slides only
    // vertically, moves down only if it pushes the pivoted lower diamond round.
    const Result a = metric_run(write_temp("tips.def", tips) + " --json");
    CHECK(a.status == 0);
    auto doc = qm::test::read_json(a.out);
    REQUIRE_FALSE(doc.is_discarded());
    bool falls = false;
    for (const auto& m : doc.at("situations").at(0).at("motions").get_ref<const Array&>())
        if (m.at("upper").at("translation").get<std::string>() == "(0 -)") {
            falls = true;
            CHECK(m.at("lower").at("rotation").get<std::string>() != "(0)");
        }
    CHECK(falls);
}

TEST_CASE("cli/metric_command: parts on one shaft are one Alex object; undeclared pairs are not looked at") {
    // gear-1 turned onto gear-2's teeth, and gear-3 back onto pinion-2's (gear-2 and pinion-2 stay
    // as drawn: one coordinate for the shaft).
    const Result r = metric_run("--emit-def " + metric_scene("gear_train.def") + " 'gear-1=1.0875, gear-3=-0.8586'");
    CHECK(r.status == 0);
    CHECK(r.out.find("Individuals (gear-1 gear-2 gear-3)") != std::string::npos);  // pinion-2 rides on gear-2
    const auto group = r.out.substr(r.out.find("    (gear-2\n"), r.out.find("    (gear-3\n") - r.out.find("    (gear-2\n"));
    CHECK(group.find("(pinion-2-") != std::string::npos);  // its surfaces belong to the shaft's object
    CHECK(count(r.out, "(Force gear-1 (0 +) (- 0) spring)") == 1);
    // Every contact names a gear-1 surface with a gear-2 one, or a pinion-2 surface (on object
    // gear-2) with a gear-3 one: only the declared pairs.
    std::istringstream lines(r.out);
    int contacts = 0;
    for (std::string line; std::getline(lines, line);) {
        if (line.find("(Contact ") == std::string::npos) continue;
        ++contacts;
        const bool first = line.find("gear-1-") != std::string::npos && line.find("gear-2-") != std::string::npos;
        const bool second = line.find("pinion-2-") != std::string::npos && line.find("gear-3-") != std::string::npos;
        CHECK((first || second));
    }
    CHECK(contacts >= 1);
}

TEST_CASE("cli/metric_command: parts that overlap as drawn are refused by every command that takes places, as by --emit-def") {
    // One error, the golden tests/cli/overlap/cam_overlap.err, from the place service
    // (bridge/pair_places.hpp) that --places, draw --place, draw --history, explore and envision share.
    const std::string folder = std::string(QM_SOURCE_DIR) + "/tests/cli/overlap";
    const std::string golden = slurp(folder + "/cam_overlap.err");
    REQUIRE(!golden.empty());
    const std::string out = std::string(QM_BINARY_DIR) + "/overlap_test";
    for (const std::string& args : std::vector<std::string>{"--emit-def cam_overlap.def", "--places cam_overlap.def --no-cache",
                                   "draw cam_overlap.def --place cam--follower:0 --svg " + out + ".svg --no-cache",
                                   "draw cam_overlap.def --history '#1' --svg " + out + ".svg --no-cache",
                                   "explore cam_overlap.def -o " + out + " --no-cache", "envision cam_overlap.def --no-cache"}) {
        CAPTURE(args);
        const Result r = qm::test::qm_atms(args, "metric_test", {std::nullopt, folder});
        CHECK(r.status == 2);
        CHECK(r.out.empty());
        CHECK(r.err == golden);
    }
    // Drawn as drawn, the overlap is what the picture shows: a warning.
    const Result drawn = qm::test::qm_atms("draw cam_overlap.def --svg " + out + ".svg", "metric_test", {std::nullopt, folder});
    CHECK(drawn.status == 0);
    CHECK(drawn.err.find("cam_overlap.def:7:10: warning: 'cam' and 'follower' overlap at the drawn configuration") == 0);
}

TEST_CASE("cli/metric_command: bad input is located, exit status 2") {
    Result r = metric_run("--emit-def " + metric_scene("cam.def") + " 'cam=30, follower=0'");
    CHECK(r.status == 2);
    CHECK(r.err.find("cam.def:8:10: error: 'cam' and 'follower' overlap at this configuration") != std::string::npos);
    CHECK(r.err.find("    Pairs ((cam follower))\n           ^\n") != std::string::npos);
    r = metric_run("--emit-def " + metric_scene("cam.def") + " 'cam=30, wheel=2'");
    CHECK(r.status == 2);
    CHECK(r.err == "CONFIG:1:9: error: unknown part 'wheel'; the moving parts are cam, follower\n  cam=30, wheel=2\n          ^\n");
    r = metric_run("--emit-def " + metric_scene("cam.def") + " 'follower=9'");
    CHECK(r.status == 2);
    CHECK(r.err.find("outside its limits") != std::string::npos);
    r = metric_run("--emit-def " + write_temp("open.def", "(Defmechanism open Parts ((p (profile (0 0) (line 1 0) (line 1 1) (line 0 2)) (fixed))))"));
    CHECK(r.status == 2);
    CHECK(r.err.find("open.def:1:67: error: part 'p': the profile is open") != std::string::npos);
    r = metric_run("--places " + write_temp("pairs.def", "(Defmechanism p Parts ((a (block) (rotation))) Pairs ((a b)))"));
    CHECK(r.status == 2);
    CHECK(r.err.find("pairs.def:1:58: error: unknown part 'b'") != std::string::npos);
    r = metric_run("--places " + std::string(QM_BINARY_DIR) + "/no-such-file.def");
    CHECK(r.status == 2);
    CHECK(r.err.find("cannot read metric scene file") != std::string::npos);
    r = metric_run("--emit-def");
    CHECK(r.status == 2);
    const Result help = metric_run("--help");
    CHECK(help.status == 0);
    CHECK(help.out.find("--emit-def METRIC-SCENE") != std::string::npos);
    CHECK(help.out.find("--places METRIC-SCENE") != std::string::npos);
}

TEST_CASE("cli/metric_command: --places prints each pair's vocabulary, reuses the cache, writes JSON and SVG") {
    const std::string cache = std::string(QM_BINARY_DIR) + "/metric_test_cache";
    std::filesystem::remove_all(cache);
    const Result first = metric_run("--places " + metric_scene("scotch_yoke.def") + " --cache " + cache);
    CHECK(first.status == 0);
    CHECK(first.out.find("mechanism scotch-yoke: 1 kinematic pair\n") == 0);
    CHECK(first.out.find("pair crank yoke (q0 = crank: rotation 0..360 degrees periodic; q1 = yoke: translation -1.4..0.2)\n") != std::string::npos);
    CHECK(first.out.find("from cache") == std::string::npos);
    CHECK(count(first.out, "\nplace ") > 10);
    CHECK(count(first.out, "(adjacent ") > 50);
    const Result second = metric_run("--places " + metric_scene("scotch_yoke.def") + " --cache " + cache);
    CHECK(second.out.find(") from cache\n") != std::string::npos);
    // The same vocabulary, whether computed or read back.
    CHECK(second.out.substr(second.out.find("places ")) == first.out.substr(first.out.find("places ")));
    const Result json = metric_run("--places " + metric_scene("scotch_yoke.def") + " --json --cache " + cache);
    CHECK(json.status == 0);
    CHECK(json.out.find("{\"schema\":\"qm-metric-places/1\",\"mechanism\":\"scotch-yoke\",\"pairs\":[{\"parts\":[\"crank\",\"yoke\"],\"from_cache\":true,"
                        "\"vocabulary\":{\"schema\":\"qm-place-vocabulary/1\"") == 0);
    CHECK(json.out.find("],\"skipped\":[],\"linkages\":[]}\n") != std::string::npos);
    const std::string svg = std::string(QM_BINARY_DIR) + "/metric_test_svg";
    std::filesystem::remove_all(svg);
    const Result pictures = metric_run("--places " + metric_scene("gear_train.def") + " --no-cache --svg " + svg);
    CHECK(pictures.status == 0);
    CHECK(pictures.out.find("linkage gear-2 pinion-2\n") != std::string::npos);
    CHECK(slurp(svg + "/gear-1--gear-2.svg").find("<svg") != std::string::npos);
    CHECK(slurp(svg + "/pinion-2--gear-3.svg").find("<svg") != std::string::npos);
    // A declared pair that can never touch gets no configuration space (Def 20).
    const Result far = metric_run("--places " + write_temp("far.def", "(Defmechanism far Parts ((a (disk-cam) (rotation)) (b (disk-cam) (at 9 0) (rotation))) Pairs ((a b)))") +
                               " --no-cache");
    CHECK(far.status == 0);
    CHECK(far.out.find("no configuration space for a b: their motion envelopes do not intersect, so they never touch (Def 20)") != std::string::npos);
}

// A coordinate a person reads is one they can type. The text of --places gives a
// rotation in degrees, as --config and --emit-def take it: a join place's point, typed back as a
// configuration, puts the two parts in contact; the JSON keeps radians and says so per axis.
TEST_CASE("cli/metric_command: --places prints rotations in degrees, the unit --emit-def and --config take") {
    const Result text = metric_run("--places " + metric_scene("scotch_yoke.def") + " --no-cache");
    REQUIRE(text.status == 0);
    const Result json = metric_run("--places " + metric_scene("scotch_yoke.def") + " --no-cache --json");
    REQUIRE(json.status == 0);
    CHECK(json.out.find("\"periodic\":true,\"samples\":64,\"unit\":\"radian\"}") != std::string::npos);
    CHECK(json.out.find("\"samples\":64,\"unit\":\"length\"}") != std::string::npos);
    const std::regex place(R"(place (\d+) join [^\n]* at \(([-0-9.e]+) ([-0-9.e]+)\)\n)");
    std::size_t checked = 0, beyond_a_radian = 0;
    for (auto it = std::sregex_iterator(text.out.begin(), text.out.end(), place); it != std::sregex_iterator() && checked < 6;
         ++it, ++checked) {
        const std::string id = (*it)[1], crank = (*it)[2], yoke = (*it)[3];
        CAPTURE(id);
        // The same point in the JSON, in radians.
        const std::regex point("\\{\"id\":" + id + ",[^\\n]*\"points\":\\[\\[([-0-9.e]+),");
        std::smatch m;
        REQUIRE(std::regex_search(json.out, m, point));
        CHECK(std::stod(crank) == doctest::Approx(std::stod(m[1]) * 180.0 / 3.14159265358979323846).epsilon(1e-5));
        if (std::stod(crank) > 6.3) ++beyond_a_radian;
        const Result at = metric_run("--emit-def " + metric_scene("scotch_yoke.def") + " 'crank=" + crank + ", yoke=" + yoke + "'");
        CHECK(at.status == 0);
        CHECK(at.out.find("(Contact crank-") != std::string::npos);
    }
    CHECK(checked == 6);
    CHECK(beyond_a_radian > 0);  // read as radians, these would be other configurations
}
