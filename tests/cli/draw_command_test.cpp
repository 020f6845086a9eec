// tests/cli/draw_command_test.cpp: `qm-atms draw` end to end through the built executable
// (cli/draw_command.hpp): the parts at a CONFIG (their transforms are the configuration, the
// contact found there is marked with both surfaces' qualitative normals), the pair's parts at a
// place's sample configuration (the place of `--places --json`), a history of envisioned states
// (the answer of `envision --path`: one drawing per state, in order, titled with the state's name,
// the parts at the places' samples, one arrow per moving part pointing its way), a warning for parts
// drawn overlapping, and bad input with exit status 2.
#include "../support/program_json.hpp"
#include "qm_atms_run.hpp"

#include <doctest/doctest.h>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

using Json = nlohmann::json;
using Array = Json::array_t;
using qm::test::metric_scene;
using qm::test::slurp;

namespace {
using qm::test::count;

qm::test::Run draw(const std::string& args) { return qm::test::qm_atms("draw " + args, "draw_test"); }

std::string out_file(const std::string& name) { return std::string(QM_BINARY_DIR) + "/" + name; }

// The transform of the part's group.
std::string transform_of(const std::string& svg, const std::string& part) {
    const auto at = svg.find("data-part=\"" + part + "\" transform=\"");
    REQUIRE(at != std::string::npos);
    const auto from = svg.find("transform=\"", at) + 11;
    return svg.substr(from, svg.find('"', from) - from);
}

}  // namespace

TEST_CASE("cli/draw_command: the parts at a CONFIG, with the contact there") {
    // The cam's top is at 0.5 + 0.2 sin(30 deg) = 0.6: the follower, drawn at 0.5, rests on it at 0.1.
    const std::string file = out_file("draw_cam.svg");
    const auto r = draw(metric_scene("cam.def") + " --config 'cam=30, follower=0.1' --svg " + file);
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    const std::string svg = slurp(file);
    CHECK(transform_of(svg, "cam") == "rotate(30 0 0)");
    CHECK(transform_of(svg, "follower") == "translate(0 0.1)");
    CHECK(count(svg, "<g class=\"contact\">") == 1);
    CHECK(count(svg, ">(0 +)</text>") == 1);  // the cam's top
    CHECK(count(svg, ">(0 -)</text>") == 1);  // the follower's underside
    CHECK(svg.find("cam-s1 (surface, normal (0 +)) against follower-s1 (surface, normal (0 -))") != std::string::npos);
    const auto marks = svg.substr(svg.find("<g class=\"marks\">"), svg.find("<g class=\"contacts\">") - svg.find("<g class=\"marks\">"));
    CHECK(count(marks, "class=\"pivot\"") == 1);
    CHECK(count(marks, "class=\"translation-axis\"") == 1);
    // As drawn: nothing moved.
    CHECK(draw(metric_scene("cam.def") + " --svg " + file).status == 0);
    CHECK(transform_of(slurp(file), "cam") == "rotate(0 0 0)");
}

TEST_CASE("cli/draw_command: a pair's parts at the sample configuration of a place") {
    // One cache for --places and every draw: the vocabulary is built once (and the two agree on it).
    const std::string cache = std::string(QM_BINARY_DIR) + "/draw_test_cache";
    std::filesystem::remove_all(cache);
    const auto places = qm::test::qm_atms("--places " + metric_scene("escapement.def") + " --json --cache " + cache, "draw_test");
    REQUIRE(places.status == 0);
    const auto doc = qm::test::read_json(places.out);
    REQUIRE_FALSE(doc.is_discarded());
    const auto& vocabulary = doc.at("pairs").at(0).at("vocabulary");
    std::map<std::string, int> checked;  // three places of each kind (each draw is a process)
    for (const auto& p : vocabulary.at("places").get_ref<const Array&>()) {
        const std::string kind = p.at("kind").get<std::string>();
        if ((kind != "cseg" && kind != "join" && kind != "face") || checked[kind] == 3) continue;
        const auto& pts = p.at("points").get_ref<const Array&>();
        const auto& q = pts[pts.size() / 2].get_ref<const Array&>();  // place_sample.hpp: the middle point, a join's, a face's
        const int id = static_cast<int>(p.at("id").get<double>());
        const std::string file = out_file("draw_place.svg");
        const auto r = draw(metric_scene("escapement.def") + " --place scape-wheel--pallets:" + std::to_string(id) + " --svg " + file + " --cache " + cache);
        CAPTURE(id);
        REQUIRE(r.status == 0);
        const std::string svg = slurp(file);
        CHECK(svg.find("place " + std::to_string(id) + " (" + kind) != std::string::npos);
        for (auto [part, value] : {std::pair{"scape-wheel", q[0].get<double>()}, std::pair{"pallets", q[1].get<double>()}}) {
            const std::string t = transform_of(svg, part);
            CHECK(std::stod(t.substr(7)) == doctest::Approx(value * 180 / std::numbers::pi).epsilon(1e-9));
        }
        if (kind == "cseg") CHECK(count(svg, "<g class=\"contact\">") >= 1);  // touching on a CSEG
        if (kind == "face") CHECK(count(svg, "<g class=\"contact\">") == 0);
        ++checked[kind];
    }
    CHECK(checked == std::map<std::string, int>{{"cseg", 3}, {"face", 3}, {"join", 3}});
}

TEST_CASE("cli/draw_command: parts drawn overlapping are drawn, with a located warning") {
    // The anchor turned upside down overlaps the wheel.
    const std::string file = out_file("draw_overlap.svg");
    const auto r = draw(metric_scene("escapement.def") + " --config 'pallets=180' --svg " + file);
    CHECK(r.status == 0);
    CHECK(r.err.find("escapement.def:") != std::string::npos);
    CHECK(r.err.find(": warning: 'scape-wheel' and 'pallets' overlap at 'pallets=180' (drawn all the same)") != std::string::npos);
    CHECK(transform_of(slurp(file), "pallets").rfind("rotate(180 0 1.4)", 0) == 0);
}

TEST_CASE("cli/draw_command: bad input is refused with exit status 2") {
    const std::string cam = metric_scene("cam.def"), file = out_file("draw_bad.svg");
    auto refused = [&](const std::string& args, const std::string& message) {
        const auto r = draw(args);
        CAPTURE(args);
        CHECK(r.status == 2);
        CHECK(r.err.find(message) != std::string::npos);
    };
    refused(cam, "draw needs --svg FILE");
    refused("", "draw takes a metric scene");
    refused(cam + " --svg " + file + " --config 'cam=x'", "CONFIG:1:");
    refused(cam + " --svg " + file + " --config 'wheel=3'", "CONFIG:1:");
    refused(cam + " --svg " + file + " --place cam--follower:0 --config 'cam=3'", "one of --config, --place and --history");
    refused(cam + " --svg " + file + " --history '#1' --config 'cam=3'", "one of --config, --place and --history");
    refused(cam + " --svg " + file + " --history '#1' --columns 0", "--columns expects a number of drawings a row, 1 to 99, not '0'");
    refused(cam + " --svg " + file + " --place follower--cam:0", "--place takes PAIR:ID");
    refused(cam + " --svg " + file + " --place cam--follower", "--place takes PAIR:ID");
    refused(cam + " --svg " + file + " --place cam--follower:999 --no-cache", "has places 0 to");
    refused(cam + " --svg " + file + " --place cam--follower:-1 --no-cache", "has places 0 to");
    refused(cam + " --svg " + file + " --size 50x50", "--size expects WIDTHxHEIGHT, each 100 to 4000 pixels, not '50x50'");
    refused(cam + " --svg " + file + " --frobnicate", "unknown option '--frobnicate'");
    refused(cam + " --svg /nonexistent-dir/x.svg", "cannot write '/nonexistent-dir/x.svg'");
    refused(std::string(QM_SOURCE_DIR) + "/no-such.def --svg " + file, "no-such.def");
}

namespace {

// The lines "  #ID NAME   <- ..." of `envision --path`: the ids and names of the path's states.
std::vector<std::pair<std::string, std::string>> path_states(const std::string& text) {
    std::vector<std::pair<std::string, std::string>> out;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (line.rfind("  #", 0) != 0) continue;
        const auto space = line.find(' ', 3);
        auto name = line.substr(space + 1);
        name = name.substr(0, name.find("   <-"));
        out.emplace_back(line.substr(2, space - 2), name);
    }
    return out;
}

}  // namespace

TEST_CASE("cli/draw_command: a history, a drawing per state") {
    // The cam turning one way while its follower rises and falls (ENVISION.md, 9.4).
    const std::string cam = std::string(QM_SOURCE_DIR) + "/scenarios/clock/cam.def";
    const std::string cache = std::string(QM_BINARY_DIR) + "/draw_test_history_cache";
    const auto path = qm::test::qm_atms("envision " + cam + " --cache " + cache +
                                            " --path 'cam=+ follower=+ ; cam=+ follower=- ; cam=+ follower=+' --avoid 'cam=0' --avoid 'cam=-'",
                                        "draw_test");
    REQUIRE(path.status == 0);
    const auto states = path_states(path.out);
    REQUIRE(states.size() >= 3);
    const auto places = qm::test::qm_atms("--places " + cam + " --json --cache " + cache, "draw_test");
    REQUIRE(places.status == 0);
    const auto doc = qm::test::read_json(places.out);
    REQUIRE_FALSE(doc.is_discarded());
    const auto& vocabulary = doc.at("pairs").at(0).at("vocabulary").at("places").get_ref<const Array&>();
    std::string ids;
    for (const auto& [id, name] : states) ids += id + " ";
    const std::string file = out_file("draw_history.svg");
    const auto r = draw(cam + " --history '" + ids + "' --columns 3 --svg " + file + " --cache " + cache);
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    const std::string svg = slurp(file);
    CHECK(count(svg, "<svg class=\"history-state\"") == states.size());
    std::size_t at = 0;
    for (std::size_t k = 0; k < states.size(); ++k) {
        const auto& [id, name] = states[k];
        CAPTURE(name);
        // The state's name above its drawing, in the history's order.
        at = svg.find("<text class=\"state-name\"", at + 1);
        REQUIRE(at != std::string::npos);
        const auto nested = svg.find("<svg class=\"history-state\" data-state=\"" + id.substr(1) + "\"", at);
        REQUIRE(nested != std::string::npos);
        CHECK(nested < svg.find("<text class=\"state-name\"", at + 1));
        const auto end = svg.find("</svg>", nested);
        const std::string panel = svg.substr(at, end - at);
        CHECK(panel.find(std::to_string(k + 1) + ". " + id + " " + name) != std::string::npos);
        if (k > 0) CHECK(panel.find("after an") != std::string::npos);  // the transition that led here
        // "cam/follower-P CAM FOLLOWER": the cam at the place's sample, an arrow per moving part.
        const std::size_t place = std::stoul(name.substr(name.find('-') + 1));
        const auto& p = vocabulary.at(place);
        const std::string kind = p.at("kind").get<std::string>();
        if (!((kind == "fsd" || kind == "external-division") && p.at("points").get_ref<const Array&>().size() == 2)) {
            const auto& pts = p.at("points").get_ref<const Array&>();
            const double want = pts[pts.size() / 2].at(0).get<double>() * 180 / std::numbers::pi;
            CHECK(std::stod(transform_of(panel, "cam").substr(7)) == doctest::Approx(want).epsilon(1e-9));
        }
        const char cam_motion = name[name.size() - 3], follower_motion = name[name.size() - 1];
        CHECK(cam_motion == '+');
        CHECK(count(panel, "class=\"motion\"") == std::size_t(cam_motion != '0') + std::size_t(follower_motion != '0'));
        CHECK(panel.find("data-part=\"cam\" data-motion=\"+\"") != std::string::npos);
        if (follower_motion != '0')
            CHECK(panel.find(std::string("data-part=\"follower\" data-motion=\"") + follower_motion + "\"") != std::string::npos);
    }
    // Bad histories.
    const auto skip = draw(cam + " --history '" + states[0].first + " " + states[2].first + "' --svg " + file + " --cache " + cache);
    CHECK(skip.status == 2);
    CHECK(skip.err.find("--history:1:") != std::string::npos);
    CHECK(skip.err.find("no transition from " + states[0].first + " to " + states[2].first) != std::string::npos);
    CHECK(draw(cam + " --history '#999999' --svg " + file + " --cache " + cache).status == 2);
    CHECK(draw(cam + " --history ' ' --svg " + file + " --cache " + cache).err.find("expected the states of a history") != std::string::npos);
}
