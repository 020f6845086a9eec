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

void print_tree(std::ostream& os, const Derivation& d, const std::string& indent) {
    os << indent << d.fact;
    if (d.shown_above) {
        os << "  (derived above)\n";
        return;
    }
    if (!d.law.empty()) os << "  <= " << d.law;
    if (!d.source.empty()) os << (d.law.empty() ? "  from " : " at ") << d.source;
    if (!d.bindings.empty()) {
        os << "  {";
        for (std::size_t i = 0; i < d.bindings.size(); ++i) os << (i ? ", " : "") << d.bindings[i];
        os << '}';
    }
    os << '\n';
    for (const Derivation& f : d.from) print_tree(os, f, indent + "    ");
}

void write_strings(std::ostream& os, const std::vector<std::string>& xs) {
    os << '[';
    for (std::size_t i = 0; i < xs.size(); ++i) os << (i ? ", " : "") << json_string(xs[i]);
    os << ']';
}

void write_tree(std::ostream& os, const Derivation& d) {
    os << "{\"fact\": " << json_string(d.fact) << ", \"law\": " << json_string(d.law)
       << ", \"source\": " << json_string(d.source) << ", \"bindings\": ";
    write_strings(os, d.bindings);
    os << ", \"shown_above\": " << (d.shown_above ? "true" : "false") << ", \"from\": [";
    for (std::size_t i = 0; i < d.from.size(); ++i) {
        if (i) os << ", ";
        write_tree(os, d.from[i]);
    }
    os << "]}";
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

void print_motions(std::ostream& os, const Scene& scene, const SituationResult& r) {
    const std::uint64_t total = r.combination_count();
    os << "  Motions: " << (r.complete ? "" : "at least ")
       << (total == UINT64_MAX ? std::string("more than 2^64 combinations") : plural(total, "consistent combination"));
    if (!r.complete) os << ", the first shown (enumeration stopped at --limit)";
    if (r.chains.size() > 1) {
        os << " (" << r.chains.size() << " kinematic chains, solved separately:";
        for (std::size_t c = 0; c < r.chains.size(); ++c) os << (c ? " x " : " ") << r.chains[c].combinations.size();
        os << ")";
    }
    os << "\n";
    for (const ChainMotions& chain : r.chains) {
        std::string indent = "    ";
        if (r.chains.size() > 1) {
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
    os << "  Stable: " << (r.stable ? "yes (the only possible motions are zero)" : total == 0 ? "no (no consistent motion)" : "no") << "\n";
}

void print_situation(std::ostream& os, const Scene& scene, const SituationResult& r) {
    os << "Situation " << r.index << "\n";
    print_freedom(os, scene, r);
    print_motions(os, scene, r);
    for (const std::string& n : r.notes) os << "  Note: " << n << "\n";
}

void print_analysis(std::ostream& os, const Scene& scene, std::span<const SituationResult> results) {
    // The header describes the scene; `--situation N` shows fewer results than it has situations.
    os << "Scene " << scene.name << " (" << scene.dimensions << "-D, " << plural(scene.objects.size(), "object") << ", "
       << plural(scene.situations.size(), "situation") << ")\n";
    if (scene.situations.empty()) os << "\nNo situations: the scene states no contacts or forces to analyse (Defstates)\n";
    for (const SituationResult& r : results) {
        os << '\n';
        print_situation(os, scene, r);
    }
}

void print_why(std::ostream& os, const WhyAnswer& w) {
    os << w.query << " in situation " << w.situation << ": "
       << (w.status == WhyAnswer::Status::holds ? "holds" : "ruled out") << "\n";
    for (const std::string& n : w.notes) os << "  " << n << "\n";
    for (std::size_t i = 0; i < w.exclusions.size(); ++i) {
        const Exclusion& x = w.exclusions[i];
        os << "  " << (w.exclusions.size() > 1 ? "Reason " + std::to_string(i + 1) : std::string("Reason"));
        if (x.responsible.empty()) {
            os << ": the scene's description alone (no contact, force or given motion)\n";
        } else {
            os << ": resting on {";
            for (std::size_t k = 0; k < x.responsible.size(); ++k) os << (k ? ", " : "") << x.responsible[k];
            os << "}\n";
        }
        print_tree(os, x.derivation, "    ");
    }
    if (!w.responsible_sets.empty()) {
        os << (w.responsible_minimal ? "  Responsible (contacts, forces and given motions; the minimal sets, each suffices):\n"
                                     : "  Responsible (contacts, forces and given motions; a set that suffices, maybe not minimal):\n");
        for (const auto& set : w.responsible_sets) {
            if (set.empty()) {
                os << "    {} (the scene's description alone)\n";
                continue;
            }
            os << "    {";
            for (std::size_t k = 0; k < set.size(); ++k) os << (k ? ", " : "") << set[k];
            os << "}\n";
        }
    }
}

void write_situation_json(std::ostream& os, const Scene& scene, const SituationResult& r) {
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
    r.for_each_combination([&](const SceneMotion& m) {
        os << (first ? "" : ", ") << '{';
        first = false;
        for (std::uint32_t i = 0; i < scene.objects.size(); ++i)
            os << (i ? ", " : "") << json_string(scene.objects[ObjectId{i}].name) << ": {\"translation\": "
               << json_string(thesis_text(m[ObjectId{i}].translation)) << ", \"rotation\": "
               << json_string(thesis_text(m[ObjectId{i}].rotation)) << '}';
        os << '}';
        return true;
    });
    os << "], \"stable\": " << (r.stable ? "true" : "false") << '}';
}

void write_analysis_json(std::ostream& os, const Scene& scene, std::span<const SituationResult> results) {
    os << "{\"scene\": " << json_string(scene.name) << ", \"dimensions\": " << scene.dimensions << ", \"situations\": [";
    for (std::size_t i = 0; i < results.size(); ++i) {
        if (i) os << ", ";
        write_situation_json(os, scene, results[i]);
    }
    os << "]}\n";
}

void write_why_json(std::ostream& os, const WhyAnswer& w) {
    os << "{\"query\": " << json_string(w.query) << ", \"situation\": " << w.situation << ", \"status\": "
       << (w.status == WhyAnswer::Status::holds ? "\"holds\"" : "\"ruled-out\"") << ", \"notes\": ";
    write_strings(os, w.notes);
    os << ", \"exclusions\": [";
    for (std::size_t i = 0; i < w.exclusions.size(); ++i) {
        os << (i ? ", " : "") << "{\"responsible\": ";
        write_strings(os, w.exclusions[i].responsible);
        os << ", \"derivation\": ";
        write_tree(os, w.exclusions[i].derivation);
        os << '}';
    }
    os << "], \"responsible_sets\": [";
    for (std::size_t i = 0; i < w.responsible_sets.size(); ++i) {
        if (i) os << ", ";
        write_strings(os, w.responsible_sets[i]);
    }
    os << "], \"responsible_minimal\": " << (w.responsible_minimal ? "true" : "false") << "}\n";
}

}  // namespace qm::analysis
