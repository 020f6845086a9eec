// tests/scenarios/scenario_support.hpp: loads a bundled scene and analyses it with the laws of rules/.
#pragma once
#include "analysis/analysis.hpp"
#include "scene/direction_text.hpp"
#include "scene/scene_parser.hpp"
#include <doctest/doctest.h>
#include <set>
#include <sstream>
#include <string>

namespace qm::test {

inline scene::Scene load_scene(const std::string& name) {
    Diagnostics d;
    auto s = scene::read_scene_file(std::string(QM_SOURCE_DIR) + "/scenarios/alex/" + name, d);
    if (!s) {
        std::ostringstream os;
        d.print(os);
        FAIL("scene does not load: " << os.str());
    }
    return *s;
}

inline analysis::Analysis analyse(const scene::Scene& scene, analysis::AnalysisOptions options = {}) {
    if (options.rules_directory.empty()) options.rules_directory = std::string(QM_SOURCE_DIR) + "/rules";
    Diagnostics d;
    auto a = analysis::analyse(scene, options, d);
    if (!a) {
        std::ostringstream os;
        d.print(os);
        FAIL("analysis fails: " << os.str());
    }
    return std::move(*a);
}

inline scene::ObjectId object(const scene::Scene& s, const std::string& name) {
    auto o = s.find_object(name);
    REQUIRE(o.has_value());
    return *o;
}

// Directions as the thesis writes them: "(+ 0)".
inline std::set<std::string> texts(const std::vector<scene::Direction>& ds) {
    std::set<std::string> out;
    for (const auto& d : ds) out.insert(scene::thesis_text(d));
    return out;
}

// Every combination of the whole scene as "obj T R; obj T R; ..." in object order.
inline std::set<std::string> combinations(const scene::Scene& scene, const analysis::SituationResult& r) {
    std::set<std::string> out;
    r.for_each_combination([&](const analysis::SceneMotion& m) {
        std::string line;
        for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
            const scene::ObjectId o{i};
            line += (i ? "; " : "") + scene.objects[o].name + " " + scene::thesis_text(m[o].translation) + " " +
                    scene::thesis_text(m[o].rotation);
        }
        out.insert(line);
        return true;
    });
    return out;
}

}  // namespace qm::test
