// cli/scene_command.cpp: `qm-atms SCENE.def` (thesis chapters 6-7): reads the scene (Alex or metric),
// checks the options against it, analyses it and prints or answers. The options are read in
// cli/scene_options.cpp, --given/--without checked and applied in scene/what_if.cpp, the
// interactive mode is cli/session.cpp.
#include "scene_command.hpp"
#include "analysis/analysis.hpp"
#include "analysis/result_printer.hpp"
#include "analysis/why_printer.hpp"
#include "bridge/scene_at_config.hpp"
#include "query_text.hpp"
#include "rules_location.hpp"
#include "scene/scene_parser.hpp"
#include "scene/what_if.hpp"
#include "scene_options.hpp"
#include "qm/file_text.hpp"
#include "qm/source_text.hpp"
#include "session.hpp"
#include <cctype>
#include <charconv>
#include <optional>
#include <sstream>

namespace qm::cli {
namespace {

// The scene of options.scene: a metric scene at --config, else an Alex scene. Errors in d.
std::optional<scene::Scene> load_scene(const SceneOptions& options, Diagnostics& d,
                                       std::ostream& err) {
    FileText file = read_file_text(options.scene);
    if (!file.text) {
        d.error({options.scene, 1, 1}, "cannot read scene file '" + options.scene + "': " + file.why_not);
        return std::nullopt;
    }
    if (is_metric_scene(*file.text)) {
        // A metric scene is analysed at a configuration, as the Alex scene --emit-def writes it.
        auto scene = bridge::read_scene_at_config(options.scene, options.config.value_or(""), d);
        if (scene && !d.items().empty()) {
            d.print(err);  // warnings (e.g. a contact an Alex scene cannot state)
            d = Diagnostics{};
        }
        return scene;
    }
    if (options.config) d.error({"--config", 1, 1}, "expected a metric scene (Defmechanism) with --config");
    return scene::read_scene(options.scene, std::move(*file.text), d);
}

// --situation N against a scene of `situations` situations, located like every other
// out-of-range value of a command-line query.
std::optional<std::size_t> check_situation(const std::string& text, std::size_t situations, Diagnostics& d) {
    long long n = 0;
    const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    const bool number = ec == std::errc{} && p == text.data() + text.size() && !text.empty();
    if (number && n >= 1 && static_cast<unsigned long long>(n) <= situations) return static_cast<std::size_t>(n);
    d.error({"--situation", 1, 1}, "expected a situation from 1 to " + std::to_string(situations) + ", but found " +
                                       (number ? std::to_string(n) : "'" + text + "'"));
    return std::nullopt;
}

// The results as asked: every situation or --situation's, each what-if result saying what it took
// away (docs/OUTPUT.md); JSON has no place for notes, so they go to standard error there.
void print_results(const analysis::Analysis& analysis, const SceneOptions& options, std::span<const scene::QueryFact> without,
                   std::span<const std::vector<std::string>> added, std::ostream& out, std::ostream& err) {
    // The results are printed where they are (a scene with many combinations holds them once);
    // only a what-if, which adds a note, prints a copy.
    std::span<const analysis::SituationResult> shown = analysis.situations();
    if (options.situation) shown = shown.subspan(*options.situation - 1, 1);
    std::vector<analysis::SituationResult> noted;
    if (!without.empty() || !options.with.empty()) {
        noted.assign(shown.begin(), shown.end());
        for (analysis::SituationResult& r : noted) {
            if (std::string note = scene::with_note(added[r.index - 1]); !note.empty()) r.notes.insert(r.notes.begin(), std::move(note));
            if (std::string note = scene::what_if_note(analysis.scene(), r.index, without); !note.empty())
                r.notes.insert(r.notes.begin(), std::move(note));
        }
        shown = noted;
    }
    // A truncated enumeration is said on standard error with --json, so a program reading the
    // JSON is not silently given a partial list.
    if (options.json)
        for (const analysis::SituationResult& r : shown)
            for (const std::string& n : r.notes) err << "qm-atms: note: situation " << r.index << ": " << n << '\n';
    const auto set = options.kinematic ? analysis::MotionSet::kinematic : analysis::MotionSet::selected;
    options.json ? analysis::write_analysis_json(out, analysis.scene(), shown, set)
                 : analysis::print_analysis(out, analysis.scene(), shown, set);
}

}  // namespace

bool is_metric_scene(std::string_view text) {
    std::size_t i = text.starts_with(SourceText::byte_order_mark) ? SourceText::byte_order_mark.size() : 0;
    for (;;) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        if (i >= text.size() || text[i] != ';') break;
        while (i < text.size() && text[i] != '\n') ++i;
    }
    if (i >= text.size() || text[i] != '(') return false;
    for (++i; i < text.size() && std::isspace(static_cast<unsigned char>(text[i]));) ++i;
    std::string word;
    for (; i < text.size() && std::isalnum(static_cast<unsigned char>(text[i])) && word.size() < 12; ++i)
        word += static_cast<char>(std::tolower(static_cast<unsigned char>(text[i])));
    return word == "defmechanism";
}

std::string scene_usage() {
    return "usage: qm-atms SCENE.def [--json] [--kinematic] [--why FACT [--situation N] [--full]] [--given 'OBJ TRANS ROT']...\n"
           "                         [--without 'Contact A B' | 'Force OBJ [CAUSE]']... [--with 'Contact A B' | 'Force OBJ DIR ORIGIN [CAUSE]']...\n"
           "                         [--rules DIR] [--limit N] [-i]\n"
           "                         [--config 'PART=VALUE, ...']   (a metric scene, at that configuration)\n"
           "  prints, for every situation, the free directions, every consistent combination of motions\n"
           "  and whether the structure is stable (thesis chapters 6-7)\n"
           "  --json          the same as JSON (docs/OUTPUT.md)\n"
           "  --kinematic     list every kinematically consistent combination (blocking, pushing and given\n"
           "                  motions alone, before the forces choose) instead of those the forces select\n"
           "  --why FACT      why a motion or freedom holds or was ruled out, e.g.\n"
           "                  --why 'Rotational-Motion (follower (-))' (situation 1 unless --situation N)\n"
           "  --full          with --why: every reason and every step of its derivation (by default the\n"
           "                  first reasons, trees cut a few steps down, saying what was left out)\n"
           "  --given M       a current motion added to every situation, e.g. --given 'pallet (0 0) (+)'\n"
           "  --without F     take a contact or force away in every situation (what if): 'Contact A B',\n"
           "                  'Force OBJ' (every force on OBJ, gravity included) or 'Force OBJ CAUSE'\n"
           "  --with F        add a contact or force to every situation (what if): 'Contact A B' or\n"
           "                  'Force OBJ DIR ORIGIN [CAUSE]', e.g. --with 'Force block (+ 0) (0 0) push'\n"
           "  --rules DIR     the folder of laws (default: the rules/ installed with qm-atms)\n"
           "  --limit N       stop enumerating a chain's combinations after N (default 100000)\n"
           "  -i              answer queries typed on standard input (type help)\n"
           "  --config C      a metric scene (docs/METRIC_SCENE_FORMAT.md) is analysed at configuration C,\n"
           "                  e.g. 'wheel=12, pallets=-3' (degrees or lengths; parts not named stay as drawn)\n" +
           std::string(limits_usage());
}

int scene_command(std::span<const std::string> args, std::istream& in, std::ostream& out, std::ostream& err) {
    std::optional<SceneOptions> options(std::in_place);
    if (auto status = parse_scene_options(args, *options, out, err)) return *status;
    apply_memory_limit(options->limits);
    Diagnostics d;
    std::optional<scene::Scene> scene = load_scene(*options, d, err);
    if (!scene || d.has_errors()) return bad_input(d, err);
    analysis::AnalysisOptions ao;
    ao.combination_limit = options->limit;
    ao.kinematic = options->kinematic;
    ao.limits = options->limits.engine_limits();
    ao.given = scene::read_givens(*scene, options->given, d);
    // A --given motion replaces a Motion the scene gives the same object (a what-if, like --without),
    // said in a note at that Motion.
    if (!d.has_errors()) scene::replace_given_motions(*scene, ao.given, options->given, d);
    const std::size_t situations = scene->situations.size();
    if (options->situation_text && situations > 0) options->situation = check_situation(*options->situation_text, situations, d);
    const std::size_t situation = options->situation.value_or(1);
    ao.without = scene::read_withouts(*scene, options->without, options->situation, d);
    // --with adds contacts and forces to the scene before it is analysed (to situation N only with
    // --situation N): each situation's result notes what it was given.
    std::vector<std::vector<std::string>> added(situations);
    if (!options->with.empty() && (!options->situation || situation <= situations)) {
        const scene::Additions additions = scene::read_withs(*scene, options->with, options->situation, d);
        if (!d.has_errors()) added = scene::add_to_scene(*scene, additions, options->situation.value_or(0));
    }
    std::optional<scene::QueryFact> why;
    if (options->why)
        if (auto text = query_text(*options->why, "--why", d)) why = scene::parse_query_fact(*scene, *text, d, "--why");
    if (situations == 0 && (options->why || options->situation_text || options->interactive))
        d.error({options->interactive ? "-i" : options->why ? "--why" : "--situation", 1, 1},
                "expected a scene with situations to ask about, but " + options->scene +
                    " states none (no Defstates, Situation or CONTACT list)");
    if (options->rules) ao.rules_directory = *options->rules;
    else if (auto dir = default_rules_directory()) ao.rules_directory = *dir;
    else d.error({"--rules", 1, 1}, "expected the folder of laws: none installed beside qm-atms; give --rules DIR");
    d.print(err);  // errors, or notes (a --given replacing a scene's Motion)
    if (d.has_errors()) return 2;
    d = Diagnostics{};
    auto analysed = analysis::analyse(*scene, ao, d);
    d.print(err);  // errors, or warnings about the laws (engine/law_check.hpp, engine/predicate_check.hpp)
    if (!analysed) return 2;
    d = Diagnostics{};
    // Contacts the laws cannot use (a corner against a surface it cannot touch, Def 25): warned, located.
    Diagnostics inert;
    for (std::size_t s = 1; s <= analysed->situations().size(); ++s)
        if (!options->situation || s == situation)
            for (Diagnostic& w : analysed->inert_contacts(s)) inert.add(std::move(w));
    inert.print(err);
    if (options->interactive) {
        run_session(*analysed, options->json, situation, in, out, err);
        return 0;
    }
    // The answer is written whole or not at all: a limit reached while it is being made
    // (qm/limit_reached.hpp, --max-memory) leaves standard output empty.
    std::ostringstream answer;
    if (why) {
        auto w = analysed->why(*why, situation, d);
        if (!w) return bad_input(d, err);
        options->json ? analysis::write_why_json(answer, *w) : analysis::print_why(answer, *w, {.full = options->full});
    } else {
        print_results(*analysed, *options, ao.without, added, answer, err);
    }
    out << answer.str();
    return 0;
}

}  // namespace qm::cli
