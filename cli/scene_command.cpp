// cli/scene_command.cpp: `qm-atms SCENE.def` (thesis chapters 6-7): reads the scene (Alex or metric),
// checks the options against it, analyses it and prints or answers. The options are read in
// cli/scene_options.cpp, --given/--without checked and applied in scene/what_if.cpp, the
// interactive mode is cli/session.cpp.
#include "scene_command.hpp"
#include "analysis/analysis.hpp"
#include "analysis/result_printer.hpp"
#include "bridge/scene_at_config.hpp"
#include "query_text.hpp"
#include "rules_location.hpp"
#include "scene/scene_parser.hpp"
#include "scene/what_if.hpp"
#include "scene_options.hpp"
#include "session.hpp"
#include <cctype>
#include <fstream>
#include <optional>

namespace qm::cli {
namespace {

// A metric scene (docs/METRIC_SCENE_FORMAT.md) opens with `(Defmechanism`, after blanks and `;`
// comments; an Alex scene does not.
bool is_metric_scene(const std::string& path) {
    std::ifstream in(path);
    std::string word;
    char c = 0;
    while (in.get(c)) {
        if (c == ';') {
            std::string rest;
            std::getline(in, rest);
        } else if (!std::isspace(static_cast<unsigned char>(c))) {
            if (c != '(') return false;
            while (in.get(c) && std::isspace(static_cast<unsigned char>(c))) {
            }
            do word += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            while (in.get(c) && std::isalnum(static_cast<unsigned char>(c)));
            return word == "defmechanism";
        }
    }
    return false;
}

// The scene of options.scene: a metric scene at --config, else an Alex scene. Errors in d.
std::optional<scene::Scene> load_scene(const SceneOptions& options, Diagnostics& d, std::ostream& err) {
    if (is_metric_scene(options.scene)) {
        // A metric scene is analysed at a configuration, as the Alex scene --emit-def writes it.
        auto scene = bridge::read_scene_at_config(options.scene, options.config.value_or(""), d);
        if (scene && !d.items().empty()) {
            d.print(err);  // warnings (e.g. a contact an Alex scene cannot state)
            d = Diagnostics{};
        }
        return scene;
    }
    if (options.config) d.error({"--config", 1, 1}, "expected a metric scene (Defmechanism) with --config");
    return scene::read_scene_file(options.scene, d);
}

// The results as asked: every situation or --situation's, each what-if result saying what it took
// away (docs/OUTPUT.md); JSON has no place for notes, so they go to standard error there.
void print_results(const analysis::Analysis& analysis, const SceneOptions& options, std::span<const scene::QueryFact> without,
                   std::ostream& out, std::ostream& err) {
    // The results are printed where they are (a scene with many combinations holds them once);
    // only a what-if, which adds a note, prints a copy.
    std::span<const analysis::SituationResult> shown = analysis.situations();
    if (options.situation) shown = shown.subspan(*options.situation - 1, 1);
    std::vector<analysis::SituationResult> noted;
    if (!without.empty()) {
        noted.assign(shown.begin(), shown.end());
        for (analysis::SituationResult& r : noted)
            if (std::string note = scene::what_if_note(analysis.scene(), r.index, without); !note.empty())
                r.notes.insert(r.notes.begin(), std::move(note));
        shown = noted;
    }
    // A truncated enumeration is said on standard error with --json, so a program reading the
    // JSON is not silently given a partial list.
    if (options.json)
        for (const analysis::SituationResult& r : shown)
            for (const std::string& n : r.notes) err << "qm-atms: note: situation " << r.index << ": " << n << '\n';
    options.json ? analysis::write_analysis_json(out, analysis.scene(), shown)
                 : analysis::print_analysis(out, analysis.scene(), shown);
}

}  // namespace

const char* scene_usage() noexcept {
    return "usage: qm-atms SCENE.def [--json] [--why FACT [--situation N]] [--given 'OBJ TRANS ROT']...\n"
           "                         [--without 'Contact A B' | 'Force OBJ [CAUSE]']... [--rules DIR] [--limit N] [-i]\n"
           "                         [--config 'PART=VALUE, ...']   (a metric scene, at that configuration)\n"
           "  prints, for every situation, the free directions, every consistent combination of motions\n"
           "  and whether the structure is stable (thesis chapters 6-7)\n"
           "  --json          the same as JSON (docs/OUTPUT.md)\n"
           "  --why FACT      why a motion or freedom holds or was ruled out, e.g.\n"
           "                  --why 'Rotational-Motion (follower (-))' (situation 1 unless --situation N)\n"
           "  --given M       a current motion added to every situation, e.g. --given 'pallet (0 0) (+)'\n"
           "  --without F     take a contact or force away in every situation (what if): 'Contact A B',\n"
           "                  'Force OBJ' (every force on OBJ, gravity included) or 'Force OBJ CAUSE'\n"
           "  --rules DIR     the folder of laws (default: the rules/ installed with qm-atms)\n"
           "  --limit N       stop enumerating a chain's combinations after N (default 100000)\n"
           "  -i              answer queries typed on standard input (type help)\n"
           "  --config C      a metric scene (docs/METRIC_SCENE_FORMAT.md) is analysed at configuration C,\n"
           "                  e.g. 'wheel=12, pallets=-3' (degrees or lengths; parts not named stay as drawn)\n";
}

int scene_command(std::span<const std::string> args, std::istream& in, std::ostream& out, std::ostream& err) {
    auto options = parse_scene_options(args, err);
    if (!options) {
        err << scene_usage();
        return 2;
    }
    Diagnostics d;
    std::optional<scene::Scene> scene = load_scene(*options, d, err);
    if (!scene || d.has_errors()) {
        d.print(err);
        return 2;
    }
    analysis::AnalysisOptions ao;
    ao.combination_limit = options->limit;
    ao.given = scene::read_givens(*scene, options->given, d);
    // A --given motion replaces a Motion the scene gives the same object (a what-if, like --without),
    // said in a note at that Motion.
    if (!d.has_errors()) scene::replace_given_motions(*scene, ao.given, options->given, d);
    const std::size_t situations = scene->situations.size();
    const std::size_t situation = options->situation.value_or(1);
    ao.without = scene::read_withouts(*scene, options->without, options->situation, d);
    std::optional<scene::QueryFact> why;
    if (options->why)
        if (auto text = query_text(*options->why, "--why", d)) why = scene::parse_query_fact(*scene, *text, d, "--why");
    if (situations == 0 && (options->why || options->situation || options->interactive))
        d.error({options->interactive ? "-i" : options->why ? "--why" : "--situation", 1, 1},
                "expected a scene with situations to ask about, but " + options->scene +
                    " states none (no Defstates, Situation or CONTACT list)");
    else if ((options->why || options->situation) && situation > situations)
        d.error({"--situation", 1, 1}, "expected a situation from 1 to " + std::to_string(situations) + ", but found " +
                                           std::to_string(situation));
    if (options->rules) ao.rules_directory = *options->rules;
    else if (auto dir = default_rules_directory()) ao.rules_directory = *dir;
    else d.error({"--rules", 1, 1}, "expected the folder of laws: none installed beside qm-atms; give --rules DIR");
    d.print(err);  // errors, or notes (a --given replacing a scene's Motion)
    if (d.has_errors()) return 2;
    d = Diagnostics{};
    auto analysis = analysis::analyse(*scene, ao, d);
    if (!analysis) {
        d.print(err);
        return 2;
    }
    // Contacts the laws cannot use (a corner against a surface it cannot touch, Def 25): warned, located.
    Diagnostics inert;
    for (std::size_t s = 1; s <= analysis->situations().size(); ++s)
        if (!options->situation || s == situation)
            for (Diagnostic& w : analysis->inert_contacts(s)) inert.add(std::move(w));
    inert.print(err);
    if (options->interactive) {
        run_session(*analysis, options->json, in, out, err);
        return 0;
    }
    if (why) {
        auto w = analysis->why(*why, situation, d);
        if (!w) {
            d.print(err);
            return 2;
        }
        options->json ? analysis::write_why_json(out, *w) : analysis::print_why(out, *w);
        return 0;
    }
    print_results(*analysis, *options, ao.without, out, err);
    return 0;
}

}  // namespace qm::cli
