// tests/cli/explore_command_test.cpp: `qm-atms explore` end to end through the built executable
// (cli/explore_command.hpp): the page's three files, the page's files as in cli/explore/, and its
// data blob (schema qm-explore/1, docs/EXPLORER.md): it parses as JSON where it sits (no "</"
// ends the script element early), holds the vocabulary of `--places --json` place for place, and
// for every place its sample configuration in degrees or offsets with the parts' transforms there;
// bad input with exit status 2. tests/cli/explore_page_test.py checks the page in a browser.
#include "../support/program_json.hpp"
#include "qm_atms_run.hpp"

#include <doctest/doctest.h>
#include <filesystem>
#include <numbers>
#include <string>

using Json = nlohmann::json;
using Array = Json::array_t;
using qm::test::metric_scene;
using qm::test::slurp;

namespace {

qm::test::Run run(const std::string& args) { return qm::test::qm_atms(args, "explore_test"); }

Json page_data(const std::string& html) {
    const std::string open = "<script id=\"qm-data\" type=\"application/json\">";
    const auto from = html.find(open);
    REQUIRE(from != std::string::npos);
    const auto to = html.find("</script>", from);
    const auto data = qm::test::read_json(html.substr(from + open.size(), to - from - open.size()));
    REQUIRE_FALSE(data.is_discarded());
    return data;
}

}  // namespace

TEST_CASE("cli/explore_command: the page, its files and its data") {
    const std::string dir = std::string(QM_BINARY_DIR) + "/explore_test_page";
    std::filesystem::remove_all(dir);
    const auto r = run("explore " + metric_scene("cam.def") + " -o " + dir + " --no-cache --no-envision");
    CHECK(r.status == 0);
    CHECK(r.err.empty());
    CHECK(r.out == "wrote " + dir + "/index.html (1 pair)\n");
    for (const char* name : {"explore.js", "envision.js", "explore.css"})
        CHECK(slurp(dir + "/" + name) == slurp(std::string(QM_SOURCE_DIR) + "/cli/explore/" + name));
    const Json data = page_data(slurp(dir + "/index.html"));
    CHECK(data.at("schema").get<std::string>() == "qm-explore/1");
    CHECK(data.at("mechanism").get<std::string>() == "cam");
    CHECK(data.at("envisionment").is_null());  // --no-envision
    CHECK(data.at("chains").get_ref<const Array&>().empty());
    REQUIRE(data.at("pairs").get_ref<const Array&>().size() == 1);
    const Json& pair = data.at("pairs").at(0);
    CHECK(pair.at("parts").at(0).get<std::string>() == "cam");
    CHECK(pair.at("parts").at(1).get<std::string>() == "follower");
    CHECK(pair.at("units").at(0).get<std::string>() == "degrees");
    CHECK(pair.at("units").at(1).get<std::string>() == "length");
    CHECK(pair.at("cspace_svg").get<std::string>().rfind("<svg ", 0) == 0);
    CHECK(pair.at("drawing_svg").get<std::string>().find("data-part=\"follower\"") != std::string::npos);

    const auto places = run("--places " + metric_scene("cam.def") + " --json --no-cache");
    REQUIRE(places.status == 0);
    const auto doc = qm::test::read_json(places.out);
    REQUIRE_FALSE(doc.is_discarded());
    const auto& want = doc.at("pairs").at(0).at("vocabulary");
    const auto& got = pair.at("vocabulary");
    REQUIRE(got.at("places").get_ref<const Array&>().size() == want.at("places").get_ref<const Array&>().size());
    CHECK(got.at("adjacency").get_ref<const Array&>().size() == want.at("adjacency").get_ref<const Array&>().size());
    const auto& samples = pair.at("samples").get_ref<const Array&>();
    REQUIRE(samples.size() == want.at("places").get_ref<const Array&>().size());
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const Json& p = want.at("places").at(k);
        CAPTURE(k);
        CHECK(got.at("places").at(k).at("kind").get<std::string>() == p.at("kind").get<std::string>());
        CHECK(got.at("places").at(k).at("points").get_ref<const Array&>().size() == p.at("points").get_ref<const Array&>().size());
        const std::string kind = p.at("kind").get<std::string>();
        if (kind == "fsd" || kind == "external-division") continue;  // their middles: explore_page_test.py
        const auto& pts = p.at("points").get_ref<const Array&>();
        const auto& q = pts[pts.size() / 2].get_ref<const Array&>();
        const auto& config = samples[k].at("config").get_ref<const Array&>();
        CHECK(config[0].get<double>() == doctest::Approx(q[0].get<double>() * 180 / std::numbers::pi));
        CHECK(config[1].get<double>() == doctest::Approx(q[1].get<double>()));
        CHECK(samples[k].at("q").at(0).get<double>() == doctest::Approx(q[0].get<double>()));
        CHECK(samples[k].at("transforms").at(0).get<std::string>().rfind("rotate(", 0) == 0);
        CHECK(samples[k].at("transforms").at(1).get<std::string>().rfind("translate(0 ", 0) == 0);
        if (kind == "cseg") CHECK(samples[k].at("contacts").get<double>() >= 1);
    }
}

TEST_CASE("cli/explore_command: the envisionment in the page is `envision --json`'s, with the chains drawn") {
    const std::string dir = std::string(QM_BINARY_DIR) + "/explore_test_envision";
    const std::string cache = std::string(QM_BINARY_DIR) + "/explore_test_cache";
    std::filesystem::remove_all(dir);
    const std::string describe = "cam=+ follower=+ ; cam=+ follower=-";
    const auto r = run("explore " + metric_scene("cam.def") + " -o " + dir + " --cache " + cache + " --path '" + describe + "' --avoid 'cam=0'");
    REQUIRE(r.status == 0);
    CHECK(r.err.empty());
    const auto json = run("envision " + metric_scene("cam.def") + " --json --cache " + cache);
    REQUIRE(json.status == 0);
    CHECK(r.out.find("(1 pair, 1 chain, ") != std::string::npos);
    // The same text: the page holds the envisioner's JSON as it is.
    const std::string html = slurp(dir + "/index.html");
    const auto from = html.find("\"envisionment\":") + 15;
    CHECK(html.substr(from, json.out.size() - 1) + "\n" == json.out);
    const Json data = page_data(html);
    const Json& env = data.at("envisionment");
    CHECK(env.at("schema").get<std::string>() == "qm-envisionment/1");
    REQUIRE(data.at("chains").get_ref<const Array&>().size() == env.at("chains").get_ref<const Array&>().size());
    const Json& chain = data.at("chains").at(0);
    CHECK(chain.at("index").get<double>() == 1);
    CHECK(chain.at("drawing_svg").get<std::string>().find("data-part=\"cam\"") != std::string::npos);
    CHECK(chain.at("world_transform").get<std::string>().rfind("translate(", 0) == 0);
    for (const char* part : {"cam", "follower"})
        for (const char* sign : {"+", "-"}) CHECK(chain.at("arrows").at(part).at(sign).get<std::string>().find("data-motion=\"" + std::string(sign) + "\"") != std::string::npos);
    REQUIRE(chain.at("pairs").get_ref<const Array&>().size() == 1);
    CHECK(chain.at("pairs").at(0).at("pair").get<double>() == 0);
    CHECK(chain.at("pairs").at(0).at("contacts_svg").get_ref<const Array&>().size() == data.at("pairs").at(0).at("samples").get_ref<const Array&>().size());
    // The described behaviour is `envision --path`'s answer.
    const auto path = run("envision " + metric_scene("cam.def") + " --cache " + cache + " --path '" + describe + "' --avoid 'cam=0'");
    REQUIRE(path.status == 0);
    REQUIRE(data.at("paths").get_ref<const Array&>().size() == 1);
    const Json& p = data.at("paths").at(0);
    CHECK(p.at("description").get<std::string>() == describe);
    CHECK(p.at("chain").get<double>() == 1);
    std::string ids;
    for (const auto& s : p.at("states").get_ref<const Array&>()) ids += "\n  #" + std::to_string(static_cast<int>(s.get<double>())) + " ";
    std::string want;
    for (auto at = path.out.find("\n  #"); at != std::string::npos; at = path.out.find("\n  #", at + 1))
        want += path.out.substr(at, path.out.find(' ', at + 4) - at + 1);
    CHECK(!want.empty());
    CHECK(ids == want);
}

TEST_CASE("cli/explore_command: bad input is refused with exit status 2") {
    CHECK(run("explore " + metric_scene("cam.def") + " -o x --no-envision --path '#1'").err.find("which --no-envision leaves out") != std::string::npos);
    CHECK(run("explore " + metric_scene("cam.def") + " -o x --avoid 'cam=0'").err.find("--avoid goes with --path") != std::string::npos);
    CHECK(run("explore").status == 2);
    CHECK(run("explore " + metric_scene("cam.def")).err.find("explore needs -o DIR") != std::string::npos);
    CHECK(run("explore " + metric_scene("cam.def") + " -o").status == 2);
    const auto missing = run("explore " + std::string(QM_SOURCE_DIR) + "/no-such.def -o " + std::string(QM_BINARY_DIR) + "/explore_none");
    CHECK(missing.status == 2);
    CHECK(missing.err.find("no-such.def") != std::string::npos);
    CHECK(run("explore " + metric_scene("cam.def") + " -o /proc/no-such-folder --no-cache --no-envision").status == 2);
}
