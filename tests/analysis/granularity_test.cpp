// tests/analysis/granularity_test.cpp: one assumption per item or one per situation (analysis/granularity.hpp)
// changes how labels are kept, never the answers: both give the same freedom, motions and
// stability on every bundled scene and on a stack too tall for per-item labels to be cheap; and a
// "why" on the coarse analysis still names the contacts its reason rests on.
#include "analysis/analysis.hpp"
#include "scene/scene_parser.hpp"
#include <doctest/doctest.h>
#include <filesystem>
#include <sstream>

using namespace qm;

namespace {

analysis::Analysis analyse(const scene::Scene& scene, analysis::Granularity g) {
    analysis::AnalysisOptions o;
    o.rules_directory = std::string(QM_SOURCE_DIR) + "/rules";
    o.granularity = g;
    Diagnostics d;
    auto a = analysis::analyse(scene, o, d);
    if (!a) {
        std::ostringstream os;
        d.print(os);
        FAIL(os.str());
    }
    return std::move(*a);
}

void same(const analysis::SituationResult& a, const analysis::SituationResult& b) {
    REQUIRE(a.freedom.size() == b.freedom.size());
    for (std::uint32_t i = 0; i < a.freedom.size(); ++i) CHECK(a.freedom[scene::ObjectId{i}] == b.freedom[scene::ObjectId{i}]);
    CHECK(a.chains == b.chains);
    CHECK(a.stable == b.stable);
}

std::string stack(int n) {
    std::string s = "(Defscenario 2 stack Individuals (table";
    for (int i = 0; i < n; ++i) s += " b" + std::to_string(i);
    s += ") Surfaces ((table (tb (0 +) (0 0)))";
    for (int i = 0; i < n; ++i) {
        const std::string b = "b" + std::to_string(i);
        s += " (" + b + " (" + b + "-t-l (0 +) (+ -)) (" + b + "-t-m (0 +) (0 -)) (" + b + "-t-r (0 +) (- -)) (" + b +
             "-b-l (0 -) (+ +)) (" + b + "-b-m (0 -) (0 +)) (" + b + "-b-r (0 -) (- +)))";
    }
    s += ") Translational-Constraints ((table (?x ?y))) Rotational-Constraints ((table (?r))) Forces (";
    for (int i = 0; i < n; ++i) s += "(b" + std::to_string(i) + " (0 -) (0 0))";
    s += ")) (Defstates (";
    for (int i = 0; i < n; ++i) {
        const std::string b = "b" + std::to_string(i), below = i ? "b" + std::to_string(i - 1) : "";
        for (const char* side : {"l", "m", "r"})
            s += "(Contact " + (i ? below + "-t-" + side : std::string("tb")) + " " + b + "-b-" + side + ")";
    }
    return s + "))";
}

}  // namespace

TEST_CASE("analysis/granularity: per item and per situation agree on every bundled scene") {
    for (const auto& e : std::filesystem::directory_iterator(std::string(QM_SOURCE_DIR) + "/scenarios/alex")) {
        if (e.path().extension() != ".def") continue;
        CAPTURE(e.path().filename().string());
        Diagnostics d;
        auto scene = scene::read_scene_file(e.path().string(), d);
        REQUIRE(scene.has_value());
        analysis::Analysis fine = analyse(*scene, analysis::Granularity::item);
        analysis::Analysis coarse = analyse(*scene, analysis::Granularity::situation);
        REQUIRE(fine.situations().size() == coarse.situations().size());
        for (std::size_t i = 0; i < fine.situations().size(); ++i) same(fine.situations()[i], coarse.situations()[i]);
    }
}

TEST_CASE("analysis/granularity: a tall stack is analysed per situation by default, with the same answers") {
    Diagnostics d;
    auto scene = scene::read_scene("stack.def", stack(25), d);
    REQUIRE(scene.has_value());
    analysis::AnalysisOptions o;
    o.rules_directory = std::string(QM_SOURCE_DIR) + "/rules";
    auto automatic = analysis::analyse(*scene, o, d);  // 75 contacts + 25 forces: above the per-item limit
    REQUIRE(automatic.has_value());
    analysis::Analysis fine = analyse(*scene, analysis::Granularity::item);
    same(automatic->situations()[0], fine.situations()[0]);
    CHECK(automatic->situations()[0].stable);

    const scene::ObjectId top = *scene->find_object("b24");
    scene::QueryFact q{scene::QueryFact::Kind::translational_motion, top, {scene::Sign::zero, scene::Sign::minus}, {}, {}, {}};
    auto coarse = automatic->why(q, 1, d);
    REQUIRE(coarse.has_value());
    CHECK(coarse->status == analysis::WhyAnswer::Status::ruled_out);
    REQUIRE_FALSE(coarse->responsible_sets.empty());
    // A sufficient set: one contact under every block, no more than three per level.
    CHECK(coarse->responsible_sets.front().size() >= 25);
    CHECK(coarse->responsible_sets.front().size() <= 75);
    auto exact = fine.why(q, 1, d);
    REQUIRE(exact.has_value());
    CHECK(exact->status == analysis::WhyAnswer::Status::ruled_out);
    for (const auto& set : exact->responsible_sets) CHECK(set.size() >= 25);  // minimal: one per level at least
}
