// cli/scene_command.cpp: `qm-atms SCENE.def` (thesis chapters 6-7), its options and the interactive mode.
#include "scene_command.hpp"
#include "analysis/analysis.hpp"
#include "scene/direction_text.hpp"
#include "analysis/result_printer.hpp"
#include "scene/scene_parser.hpp"
#include "metric_command.hpp"
#include "query_text.hpp"
#include "rules_location.hpp"
#include <algorithm>
#include <cctype>
#include <charconv>
#include <fstream>
#include <iostream>
#include <optional>
#include <unistd.h>

namespace qm::cli {
namespace {

struct SceneOptions {
    std::string scene;
    bool json = false;
    bool interactive = false;
    std::optional<std::string> why;
    std::optional<std::size_t> situation;
    std::vector<std::string> given, without;
    std::optional<std::string> rules;
    std::optional<std::string> config;  // metric scenes: the configuration (cli/metric_command.hpp)
    std::size_t limit = 100000;
};

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

std::optional<std::size_t> positive(const std::string& s) {
    std::size_t v = 0;
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc{} || p != s.data() + s.size() || v == 0) return std::nullopt;
    return v;
}

// Whether situation s (from 1) has the contact or force q, the things `--without` and `whatif` take
// away. `Force OBJ` names every force on OBJ, scene-level ones included (they act in every situation);
// `Force OBJ CAUSE` only the force(s) of that cause on OBJ.
bool has_item(const scene::Scene& scene, std::size_t s, const scene::QueryFact& q) {
    const scene::Situation& situation = scene.situations[s - 1];
    if (q.kind == scene::QueryFact::Kind::contact)
        return std::any_of(situation.contacts.begin(), situation.contacts.end(), [&](const scene::Contact& c) {
            return (c.first == *q.first && c.second == *q.second) || (c.first == *q.second && c.second == *q.first);
        });
    auto on = [&](const scene::Force& f) { return f.object == *q.object && (!q.cause || f.cause == *q.cause); };
    return std::any_of(scene.forces.begin(), scene.forces.end(), on) ||
           std::any_of(situation.forces.begin(), situation.forces.end(), on);
}

// The contact or force in the scene's notation, for messages.
std::string item_text(const scene::Scene& scene, const scene::QueryFact& q) {
    if (q.kind == scene::QueryFact::Kind::contact)
        return "Contact (" + scene.surfaces[*q.first].name + " " + scene.surfaces[*q.second].name + ")";
    if (q.cause) return "force of cause '" + scene.causes[*q.cause].name + "' on '" + scene.objects[*q.object].name + "'";
    return "force on '" + scene.objects[*q.object].name + "'";
}

bool is_contact_or_force(const scene::QueryFact& q) {
    return q.kind == scene::QueryFact::Kind::contact || q.kind == scene::QueryFact::Kind::force;
}

std::optional<SceneOptions> parse(std::span<const std::string> args, std::ostream& err) {
    SceneOptions o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        auto value = [&](const char* what) -> std::optional<std::string> {
            if (i + 1 >= args.size()) {
                err << "qm-atms: error: " << a << " needs " << what << '\n';
                return std::nullopt;
            }
            return args[++i];
        };
        if (a == "--json") o.json = true;
        else if (a == "-i" || a == "--interactive") o.interactive = true;
        else if (a == "--why") {
            auto v = value("a fact, e.g. --why 'Rotational-Motion (follower (-))'");
            if (!v) return std::nullopt;
            if (o.why) {  // one explanation per run: a second --why would silently replace the first
                err << "qm-atms: error: --why is given twice ('" << *o.why << "', '" << *v << "'); ask one at a time, or use -i\n";
                return std::nullopt;
            }
            o.why = *v;
        } else if (a == "--situation") {
            auto v = value("a situation number (1 is the first)");
            if (!v) return std::nullopt;
            if (o.situation) {
                err << "qm-atms: error: --situation is given twice\n";
                return std::nullopt;
            }
            o.situation = positive(*v);
            if (!o.situation) {
                err << "qm-atms: error: --situation expects a number from 1, not '" << *v << "'\n";
                return std::nullopt;
            }
        } else if (a == "--given") {
            auto v = value("a motion, e.g. --given 'pallet (0 0) (+)'");
            if (!v) return std::nullopt;
            o.given.push_back(*v);
        } else if (a == "--without") {
            auto v = value("a contact or force, e.g. --without 'Contact tb block-b-m', --without 'Force block' or --without 'Force block wind'");
            if (!v) return std::nullopt;
            o.without.push_back(*v);
        } else if (a == "--rules") {
            auto v = value("a folder of .rules files");
            if (!v) return std::nullopt;
            o.rules = *v;
        } else if (a == "--config") {
            auto v = value("a configuration of a metric scene, e.g. --config 'wheel=12, pallets=-3'");
            if (!v) return std::nullopt;
            o.config = *v;
        } else if (a == "--limit") {
            auto v = value("a number of combinations");
            if (!v) return std::nullopt;
            auto n = positive(*v);
            if (!n) {
                err << "qm-atms: error: --limit expects a positive number, not '" << *v << "'\n";
                return std::nullopt;
            }
            o.limit = *n;
        } else if (!a.empty() && a[0] == '-') {
            err << "qm-atms: error: unknown option '" << a << "'\n";
            return std::nullopt;
        } else if (o.scene.empty()) {
            o.scene = a;
        } else {
            err << "qm-atms: error: more than one scene given ('" << o.scene << "', '" << a << "')\n";
            return std::nullopt;
        }
    }
    if (o.scene.empty()) {
        err << "qm-atms: error: no scene given\n";
        return std::nullopt;
    }
    if (o.interactive && o.why) {
        err << "qm-atms: error: -i answers queries itself: give --why or -i, not both\n";
        return std::nullopt;
    }
    return o;
}

// The interactive mode: queries against the loaded analysis, without reloading anything.
class Session {
public:
    Session(analysis::Analysis& analysis, bool json, std::ostream& out, std::ostream& err)
        : analysis_(analysis), json_(json), out_(out), err_(err) {}

    void run(std::istream& in) {
        const bool tty = isatty(STDIN_FILENO) && &in == &std::cin;
        std::string line;
        if (tty) out_ << "qm-atms: " << analysis_.scene().name << ", " << analysis_.situations().size()
                      << " situation(s). Type help.\n";
        for (;;) {
            if (tty) out_ << "qm-atms[" << situation_ << "]> " << std::flush;
            if (!std::getline(in, line)) break;
            if (!command(trim(line))) break;
            out_.flush();
        }
    }

private:
    static std::string trim(const std::string& s) {
        const auto b = s.find_first_not_of(" \t\r");
        if (b == std::string::npos) return {};
        return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
    }

    bool command(const std::string& line) {
        if (line.empty() || line[0] == '#') return true;
        const auto space = line.find(' ');
        const std::string verb = line.substr(0, space);
        const std::string rest = space == std::string::npos ? std::string() : trim(line.substr(space + 1));
        const scene::Scene& scene = analysis_.scene();
        const analysis::SituationResult& current = analysis_.situations()[situation_ - 1];
        Diagnostics d;
        if (verb == "quit" || verb == "exit") return false;
        if (verb == "help") out_ << help;
        else if (verb == "json") {
            json_ = rest.empty() ? !json_ : rest == "on";
            if (!rest.empty() && rest != "on" && rest != "off") err_ << "json: expected on or off\n";
            out_ << "json " << (json_ ? "on" : "off") << '\n';
        } else if (verb == "situation") {
            auto n = positive(rest);
            if (!n || *n > analysis_.situations().size())
                err_ << "situation: expected a number from 1 to " << analysis_.situations().size() << '\n';
            else situation_ = *n;
        } else if (verb == "freedom" || verb == "motions") {
            if (json_) {
                analysis::write_situation_json(out_, scene, current);
                out_ << '\n';
            } else if (verb == "freedom") analysis::print_freedom(out_, scene, current);
            else analysis::print_motions(out_, scene, current);
        } else if (verb == "why") {
            auto text = query_text(rest, "why", d);
            auto q = text ? scene::parse_query_fact(scene, *text, d, "why") : std::nullopt;
            if (q && is_contact_or_force(*q)) {
                d.error({"why", 1, 1}, "expected a motion or a freedom to explain (Translational-Motion, Rotational-Motion, "
                                       "Translational-Freedom, Rotational-Freedom), not a contact or force; "
                                       "`whatif` takes contacts and forces away");
                q.reset();
            }
            if (q)
                if (auto w = analysis_.why(*q, situation_, d)) json_ ? analysis::write_why_json(out_, *w) : analysis::print_why(out_, *w);
        } else if (verb == "given") {
            auto m = scene::parse_given(scene, rest, d, "given");
            if (m) show(analysis_.with_given(situation_, std::span<const scene::Motion>(&*m, 1), d));
        } else if (verb == "whatif") {
            std::vector<scene::QueryFact> without;
            std::size_t from = 0;
            std::string text = rest.rfind("without ", 0) == 0 ? rest.substr(8) : rest;
            while (from <= text.size()) {
                const auto semi = text.find(';', from);
                const std::string part = trim(text.substr(from, semi == std::string::npos ? std::string::npos : semi - from));
                if (auto q = scene::parse_query_fact(scene, part, d, "whatif")) {
                    if (!is_contact_or_force(*q))
                        d.error({"whatif", 1, 1}, "expected 'Contact A B' or 'Force OBJ [CAUSE]' to take away, but found '" + part + "'");
                    else if (!has_item(scene, situation_, *q))
                        d.error({"whatif", 1, 1}, "expected a contact or force of situation " + std::to_string(situation_) +
                                                      " to take away, but it has no " + item_text(scene, *q));
                    else without.push_back(*q);
                }
                if (semi == std::string::npos) break;
                from = semi + 1;
            }
            if (!d.has_errors()) show(analysis_.what_if(situation_, without, d));
        } else {
            err_ << "unknown command '" << verb << "' (type help)\n";
        }
        d.print(err_);
        return true;
    }

    void show(const std::optional<analysis::SituationResult>& r) {
        if (!r) return;
        if (json_) {
            analysis::write_situation_json(out_, analysis_.scene(), *r);
            out_ << '\n';
        } else {
            analysis::print_situation(out_, analysis_.scene(), *r);
        }
    }

    static constexpr const char* help =
        "  situation N           ask about situation N from now on (1 is the first)\n"
        "  freedom               the free directions of every object\n"
        "  motions               every consistent combination of motions, and the stability verdict\n"
        "  why FACT              why a motion or freedom holds or was ruled out, e.g.\n"
        "                        why Rotational-Motion (follower (-))\n"
        "  given OBJ TRANS ROT   the situation with a current motion given, e.g. given pallet (0 0) (+)\n"
        "  whatif FACT[; FACT]   the situation with contacts or forces taken away, e.g.\n"
        "                        whatif Contact tb block-b-m; Force block\n"
        "  json [on|off]         answer in JSON (docs/OUTPUT.md)\n"
        "  help, quit\n";

    analysis::Analysis& analysis_;
    bool json_;
    std::size_t situation_ = 1;
    std::ostream& out_;
    std::ostream& err_;
};

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
    auto options = parse(args, err);
    if (!options) {
        err << scene_usage();
        return 2;
    }
    Diagnostics d;
    std::optional<scene::Scene> scene;
    if (is_metric_scene(options->scene)) {
        // A metric scene is analysed at a configuration, as the Alex scene --emit-def would write.
        scene = metric_scene_at(options->scene, options->config.value_or(""), d);
        if (scene && !d.items().empty()) {
            d.print(err);  // warnings (e.g. a contact an Alex scene cannot state)
            d = Diagnostics{};
        }
    } else {
        if (options->config) d.error({"--config", 1, 1}, "expected a metric scene (Defmechanism) with --config");
        scene = scene::read_scene_file(options->scene, d);
    }
    if (!scene || d.has_errors()) {
        d.print(err);
        return 2;
    }
    analysis::AnalysisOptions ao;
    ao.combination_limit = options->limit;
    std::vector<std::string> given_text;  // each --given as written, aligned with ao.given
    for (const auto& g : options->given)
        if (auto m = scene::parse_given(*scene, g, d, "--given")) {
            auto same = std::find_if(ao.given.begin(), ao.given.end(), [&](const scene::Motion& x) { return x.object == m->object; });
            if (same != ao.given.end()) {
                // One motion per object at a time (Law 1): the second would replace or contradict the first.
                d.error({"--given", 1, 1}, "expected one --given per object, but '" + scene->objects[m->object].name +
                                               "' is given twice ('" + given_text[static_cast<std::size_t>(same - ao.given.begin())] +
                                               "' and '" + g + "')");
                continue;
            }
            ao.given.push_back(*m);
            given_text.push_back(g);
        }
    // A --given motion replaces a Motion the scene gives the same object (a what-if, like --without),
    // said in a note at that Motion.
    if (!d.has_errors())
        for (std::size_t k = 0; k < ao.given.size(); ++k)
            for (std::size_t s = 0; s < scene->situations.size(); ++s)
                std::erase_if(scene->situations[s].motions, [&](const scene::Motion& m) {
                    if (m.object != ao.given[k].object) return false;
                    d.add({Severity::note, m.where,
                           "--given '" + given_text[k] + "' replaces this Motion (" + scene->objects[m.object].name + " " +
                               scene::thesis_text(m.translation) + " " + scene::thesis_text(m.rotation) + ") in situation " +
                               std::to_string(s + 1),
                           {}, {}});
                    return true;
                });
    const std::size_t situations = scene->situations.size();
    const std::size_t situation = options->situation.value_or(1);
    const bool situation_ok = situation <= situations;
    for (const auto& w : options->without)
        if (auto q = scene::parse_query_fact(*scene, w, d, "--without")) {
            // Taking away what is not there changes nothing: most likely a misspelt or misplaced item.
            bool present = false;
            for (std::size_t s = 1; s <= situations; ++s)
                if ((!options->situation || s == situation) && has_item(*scene, s, *q)) present = true;
            if (!is_contact_or_force(*q))
                d.error({"--without", 1, 1}, "expected 'Contact A B' or 'Force OBJ [CAUSE]' to take away, but found '" + w + "'");
            else if (!present && situation_ok)
                d.error({"--without", 1, 1}, "expected a contact or force of the scene to take away, but " +
                                                 (options->situation ? "situation " + std::to_string(situation) : std::string("no situation")) +
                                                 (options->situation ? " has no " : " has a ") + item_text(*scene, *q));
            else ao.without.push_back(*q);
        }
    std::optional<scene::QueryFact> why;
    if (options->why)
        if (auto text = query_text(*options->why, "--why", d)) why = scene::parse_query_fact(*scene, *text, d, "--why");
    if (situations == 0 && (options->why || options->situation || options->interactive))
        d.error({options->interactive ? "-i" : options->why ? "--why" : "--situation", 1, 1},
                "expected a scene with situations to ask about, but " + options->scene +
                                           " states none (no Defstates, Situation or CONTACT list)");
    else if ((options->why || options->situation) && !situation_ok)
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
        Session(*analysis, options->json, out, err).run(in);
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
    // The results are printed where they are (a scene with many combinations holds them once);
    // only a what-if, which adds a note, prints a copy.
    std::span<const analysis::SituationResult> shown = analysis->situations();
    if (options->situation) shown = shown.subspan(situation - 1, 1);
    std::vector<analysis::SituationResult> noted;
    if (!ao.without.empty()) {
        noted.assign(shown.begin(), shown.end());
        // A what-if says what it took away, as the interactive `whatif` does (docs/OUTPUT.md).
        for (analysis::SituationResult& r : noted) {
            std::string taken;
            for (const scene::QueryFact& q : ao.without)
                if (has_item(analysis->scene(), r.index, q))
                    taken += (taken.empty() ? "" : ", ") +
                             (q.kind == scene::QueryFact::Kind::contact ? item_text(analysis->scene(), q)
                              : q.cause                                ? "the " + item_text(analysis->scene(), q)
                                                                       : "every " + item_text(analysis->scene(), q));
            if (!taken.empty()) r.notes.insert(r.notes.begin(), "what-if: analysed without " + taken + " (--without)");
        }
        shown = noted;
    }
    // The JSON schema has no place for notes (docs/OUTPUT.md): a truncated enumeration is said on
    // standard error, so a program reading the JSON is not silently given a partial list.
    if (options->json)
        for (const analysis::SituationResult& r : shown)
            for (const std::string& n : r.notes) err << "qm-atms: note: situation " << r.index << ": " << n << '\n';
    options->json ? analysis::write_analysis_json(out, analysis->scene(), shown)
                  : analysis::print_analysis(out, analysis->scene(), shown);
    return 0;
}

}  // namespace qm::cli
