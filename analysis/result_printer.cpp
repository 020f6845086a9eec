// analysis/result_printer.cpp
#include "analysis/result_printer.hpp"
#include "scene/direction_text.hpp"
#include "qm/json.hpp"

namespace qm::analysis {
namespace {
using qm::json_string;

std::string plural(std::uint64_t n, const char* word) {
    return std::to_string(n) + " " + word + (n == 1 ? "" : "s");
}

void print_combination(std::ostream& os, const Scene& scene, const ChainMotions& chain, std::size_t c,
                       const std::string& indent) {
    for (std::size_t k = 0; k < chain.objects.size(); ++k) {
        const std::string& name = scene.objects[chain.objects[k]].name;
        os << indent << "Translational-Motion (" << name << ' ' << thesis_text(chain.combinations[c][k].translation) << ")\n";
        os << indent << "Rotational-Motion (" << name << ' ' << thesis_text(chain.combinations[c][k].rotation) << ")\n";
    }
}

}  // namespace

void print_freedom(std::ostream& os, const Scene& scene, const SituationResult& r) {
    os << "  Free directions\n";
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i)
        for (const Direction& d : r.freedom[ObjectId{i}].translation)
            os << "    Translational-Freedom (" << scene.objects[ObjectId{i}].name << ' ' << thesis_text(d) << ")\n";
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i)
        for (const Direction& d : r.freedom[ObjectId{i}].rotation)
            os << "    Rotational-Freedom (" << scene.objects[ObjectId{i}].name << ' ' << thesis_text(d) << ")\n";
}

namespace {

std::string count_text(std::uint64_t n, bool complete, const char* what) {
    return (complete ? "" : "at least ") +
           (n == UINT64_MAX ? std::string("more than 2^64 ") + what + "s" : plural(n, what));
}

// The heading names the set listed, in the thesis' words (Figure 7.14: "consistent combinations of
// motions"; section 6.2: the forces select among them), and counts the other set.
void print_motions_heading(std::ostream& os, const SituationResult& r, MotionSet shown) {
    const std::uint64_t selected = r.combination_count();
    const std::uint64_t kinematic = r.kinematic_count();
    if (shown == MotionSet::kinematic && !r.kinematic_computed) {
        os << "  Motions: the kinematically consistent combinations are not computed in a scene this large "
              "(start with --kinematic to compute them)";
        return;
    }
    if (shown == MotionSet::kinematic) {
        os << "  Motions: " << count_text(kinematic, r.kinematic_complete, "kinematically consistent combination")
           << " (blocking, pushing and given motions alone, before the forces choose; the forces select "
           << count_text(selected, r.complete, "combination") << ")";
        if (!r.kinematic_complete) os << ", the first shown (enumeration stopped at --limit)";
        return;
    }
    os << "  Motions: " << count_text(selected, r.complete, "consistent combination");
    if (!r.kinematic_computed)
        os << " selected by the forces (the kinematically consistent ones are not counted in a scene this large; "
              "--kinematic counts and lists them)";
    else if (r.complete && r.kinematic_complete && kinematic == selected)
        os << " (every kinematically consistent one: the forces rule none out)";
    else
        os << " selected by the forces, of " << count_text(kinematic, r.kinematic_complete, "kinematically consistent combination")
           << " (--kinematic lists them)";
    if (!r.complete) os << ", the first shown (enumeration stopped at --limit)";
}

void print_chains(std::ostream& os, const Scene& scene, const std::vector<ChainMotions>& chains) {
    if (chains.size() > 1) {
        os << " (" << chains.size() << " kinematic chains, solved separately:";
        for (std::size_t c = 0; c < chains.size(); ++c) os << (c ? " x " : " ") << chains[c].combinations.size();
        os << ")";
    }
    os << "\n";
    for (const ChainMotions& chain : chains) {
        std::string indent = "    ";
        if (chains.size() > 1) {
            os << "    Chain (";
            for (std::size_t k = 0; k < chain.objects.size(); ++k) os << (k ? " " : "") << scene.objects[chain.objects[k]].name;
            os << "): " << plural(chain.combinations.size(), "combination") << "\n";
            indent += "  ";
        }
        for (std::size_t c = 0; c < chain.combinations.size(); ++c) {
            if (chain.combinations.size() > 1) os << indent << "Combination " << c + 1 << "\n";
            print_combination(os, scene, chain, c, chain.combinations.size() > 1 ? indent + "  " : indent);
        }
    }
}

}  // namespace

void print_motions(std::ostream& os, const Scene& scene, const SituationResult& r, MotionSet shown) {
    const std::uint64_t total = r.combination_count();
    print_motions_heading(os, r, shown);
    print_chains(os, scene, shown == MotionSet::kinematic ? r.kinematic : r.chains);
    os << "  Stable: " << (r.stable ? "yes (the only possible motions are zero)" : total == 0 ? "no (no consistent motion)" : "no") << "\n";
}

void print_situation(std::ostream& os, const Scene& scene, const SituationResult& r, MotionSet shown) {
    os << "Situation " << r.index << "\n";
    print_freedom(os, scene, r);
    print_motions(os, scene, r, shown);
    for (const std::string& n : r.notes) os << "  Note: " << n << "\n";
}

void print_analysis(std::ostream& os, const Scene& scene, std::span<const SituationResult> results, MotionSet shown) {
    // The header describes the scene; `--situation N` shows fewer results than it has situations.
    os << "Scene " << scene.name << " (" << scene.dimensions << "-D, " << plural(scene.objects.size(), "object") << ", "
       << plural(scene.situations.size(), "situation") << ")\n";
    if (scene.situations.empty()) os << "\nNo situations: the scene states no contacts or forces to analyse (Defstates)\n";
    for (const SituationResult& r : results) {
        os << '\n';
        print_situation(os, scene, r, shown);
    }
}

void write_situation_json(std::ostream& os, const Scene& scene, const SituationResult& r, MotionSet shown) {
    os << "{\"index\": " << r.index << ", \"freedom\": {";
    for (std::uint32_t i = 0; i < scene.objects.size(); ++i) {
        const Freedom& f = r.freedom[ObjectId{i}];
        os << (i ? ", " : "") << json_string(scene.objects[ObjectId{i}].name) << ": {\"translation\": [";
        for (std::size_t k = 0; k < f.translation.size(); ++k) os << (k ? ", " : "") << json_string(thesis_text(f.translation[k]));
        os << "], \"rotation\": [";
        for (std::size_t k = 0; k < f.rotation.size(); ++k) os << (k ? ", " : "") << json_string(thesis_text(f.rotation[k]));
        os << "]}";
    }
    os << "}, \"motions\": [";
    bool first = true;
    for_each_combination(shown == MotionSet::kinematic ? r.kinematic : r.chains, [&](const SceneMotion& m) {
        os << (first ? "" : ", ") << '{';
        first = false;
        for (std::uint32_t i = 0; i < scene.objects.size(); ++i)
            os << (i ? ", " : "") << json_string(scene.objects[ObjectId{i}].name) << ": {\"translation\": "
               << json_string(thesis_text(m[ObjectId{i}].translation)) << ", \"rotation\": "
               << json_string(thesis_text(m[ObjectId{i}].rotation)) << '}';
        os << '}';
        return true;
    });
    os << "], \"motion_set\": " << (shown == MotionSet::kinematic ? "\"kinematic\"" : "\"selected\"")
       << ", \"combinations\": {\"selected\": " << r.combination_count() << ", \"selected_complete\": " << (r.complete ? "true" : "false")
       << ", \"kinematic\": ";
    if (r.kinematic_computed) os << r.kinematic_count();
    else os << "null";
    os << ", \"kinematic_complete\": " << (r.kinematic_computed && r.kinematic_complete ? "true" : "false")
       << "}, \"stable\": " << (r.stable ? "true" : "false") << '}';
}

void write_analysis_json(std::ostream& os, const Scene& scene, std::span<const SituationResult> results, MotionSet shown) {
    os << "{\"scene\": " << json_string(scene.name) << ", \"dimensions\": " << scene.dimensions << ", \"situations\": [";
    for (std::size_t i = 0; i < results.size(); ++i) {
        if (i) os << ", ";
        write_situation_json(os, scene, results[i], shown);
    }
    os << "]}\n";
}

}  // namespace qm::analysis
