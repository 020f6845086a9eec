// tests/cli/explore_command_test.cpp: `qm-atms explore` end to end through the built executable
// (cli/explore_command.hpp): the page's three files, the page's files as in cli/explore/, and its
// data blob (schema qm-explore/1, docs/EXPLORER.md): it parses as JSON where it sits (no "</"
// ends the script element early), holds the vocabulary of `--places --json` place for place, and
// for every place its sample configuration in degrees or offsets with the parts' transforms there;
// bad input with exit status 2. tests/cli/explore_page_test.py checks the page in a browser.
#include "../support/json_value.hpp"
#include "qm_atms_run.hpp"

#include <doctest/doctest.h>
#include <filesystem>
#include <numbers>
#include <string>

using qm::test::Json;
using qm::test::metric_scene;
using qm::test::slurp;

namespace {

qm::test::Run run(const std::string& args) { return qm::test::qm_atms(args, "explore_test"); }

Json page_data(const std::string& html) {
    const std::string open = "<script id=\"qm-data\" type=\"application/json\">";
    const auto from = html.find(open);
    REQUIRE(from != std::string::npos);
    const auto to = html.find("</script>", from);
    const auto data = Json::parse(html.substr(from + open.size(), to - from - open.size()));
    REQUIRE(data);
    return *data;
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
    CHECK(data["schema"].string() == "qm-explore/1");
    CHECK(data["mechanism"].string() == "cam");
    CHECK(std::holds_alternative<std::nullptr_t>(data["envisionment"].value));  // --no-envision
    CHECK(data["chains"].array().empty());
    REQUIRE(data["pairs"].array().size() == 1);
    const Json& pair = data["pairs"].array()[0];
    CHECK(pair["parts"].array()[0].string() == "cam");
    CHECK(pair["parts"].array()[1].string() == "follower");
    CHECK(pair["units"].array()[0].string() == "degrees");
    CHECK(pair["units"].array()[1].string() == "length");
    CHECK(pair["cspace_svg"].string().rfind("<svg ", 0) == 0);
    CHECK(pair["drawing_svg"].string().find("data-part=\"follower\"") != std::string::npos);

    const auto places = run("--places " + metric_scene("cam.def") + " --json --no-cache");
    REQUIRE(places.status == 0);
    const auto doc = Json::parse(places.out);
    REQUIRE(doc);
    const auto& want = (*doc)["pairs"].array()[0]["vocabulary"];
    const auto& got = pair["vocabulary"];
    REQUIRE(got["places"].array().size() == want["places"].array().size());
    CHECK(got["adjacency"].array().size() == want["adjacency"].array().size());
    const auto& samples = pair["samples"].array();
    REQUIRE(samples.size() == want["places"].array().size());
    for (std::size_t k = 0; k < samples.size(); ++k) {
        const Json& p = want["places"].array()[k];
        CAPTURE(k);
        CHECK(got["places"].array()[k]["kind"].string() == p["kind"].string());
        CHECK(got["places"].array()[k]["points"].array().size() == p["points"].array().size());
        const std::string kind = p["kind"].string();
        if (kind == "fsd" || kind == "external-division") continue;  // their middles: explore_page_test.py
        const auto& pts = p["points"].array();
        const auto& q = pts[pts.size() / 2].array();
        const auto& config = samples[k]["config"].array();
        CHECK(config[0].number() == doctest::Approx(q[0].number() * 180 / std::numbers::pi));
        CHECK(config[1].number() == doctest::Approx(q[1].number()));
        CHECK(samples[k]["q"].array()[0].number() == doctest::Approx(q[0].number()));
        CHECK(samples[k]["transforms"].array()[0].string().rfind("rotate(", 0) == 0);
        CHECK(samples[k]["transforms"].array()[1].string().rfind("translate(0 ", 0) == 0);
        if (kind == "cseg") CHECK(samples[k]["contacts"].number() >= 1);
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
    const Json& env = data["envisionment"];
    CHECK(env["schema"].string() == "qm-envisionment/1");
    REQUIRE(data["chains"].array().size() == env["chains"].array().size());
    const Json& chain = data["chains"].array()[0];
    CHECK(chain["index"].number() == 1);
    CHECK(chain["drawing_svg"].string().find("data-part=\"cam\"") != std::string::npos);
    CHECK(chain["world_transform"].string().rfind("translate(", 0) == 0);
    for (const char* part : {"cam", "follower"})
        for (const char* sign : {"+", "-"}) CHECK(chain["arrows"][part][sign].string().find("data-motion=\"" + std::string(sign) + "\"") != std::string::npos);
    REQUIRE(chain["pairs"].array().size() == 1);
    CHECK(chain["pairs"].array()[0]["pair"].number() == 0);
    CHECK(chain["pairs"].array()[0]["contacts_svg"].array().size() == data["pairs"].array()[0]["samples"].array().size());
    // The described behaviour is `envision --path`'s answer.
    const auto path = run("envision " + metric_scene("cam.def") + " --cache " + cache + " --path '" + describe + "' --avoid 'cam=0'");
    REQUIRE(path.status == 0);
    REQUIRE(data["paths"].array().size() == 1);
    const Json& p = data["paths"].array()[0];
    CHECK(p["description"].string() == describe);
    CHECK(p["chain"].number() == 1);
    std::string ids;
    for (const auto& s : p["states"].array()) ids += "\n  #" + std::to_string(static_cast<int>(s.number())) + " ";
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
