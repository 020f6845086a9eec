// cli/envision_command.cpp: `qm-atms envision` (docs/ENVISION.md).
#include "envision_command.hpp"
#include "command_options.hpp"
#include "geometry_usage.hpp"
#include "bridge/pair_places.hpp"
#include "graph_svg.hpp"
#include "progress_bar.hpp"
#include "resource_limits.hpp"
#include "rules_location.hpp"

#include "envision/envisionment.hpp"
#include "envision/behaviour_query.hpp"
#include "envision/dot_printer.hpp"
#include "envision/json_printer.hpp"
#include "envision/state_query.hpp"
#include "envision/state_report.hpp"
#include "envision/table_printer.hpp"
#include "envision/text_printer.hpp"
#include "envision/verify.hpp"
#include "envision/why_not.hpp"
#include "geometry/metric_scene_parser.hpp"

#include <filesystem>
#include <fstream>
#include <new>
#include <optional>
#include <sstream>
#include <unistd.h>

namespace qm::cli {
namespace g = qm::geometry;
namespace ev = qm::envision;

namespace {

struct Options {
    std::string scene;
    bool table = false, json = false, stats = false, verify = false, use_cache = true;
    std::size_t max_states = 1'000'000;
    std::optional<std::filesystem::path> cache, rules;
    std::vector<std::string> without;
    std::optional<std::string> next, previous, from, path, why_not;
    std::vector<std::string> avoid;
    std::optional<std::filesystem::path> dot, svg;
    ResourceLimits limits;  // --max-memory (the engines' fact and environment limits are not the envisioner's)
};

int usage_error(std::ostream& err, const std::string& what) {
    err << "qm-atms: " << what << "\n" << envision_usage();
    return 2;
}

std::optional<std::size_t> count_of(const std::string& s) {
    if (s.empty() || s.size() > 12 || s.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    return static_cast<std::size_t>(std::stoull(s));
}

// `Force PART [CAUSE]`, located in the option's text on error.
std::optional<bridge::ForceRef> parse_without(const g::Mechanism& m, const std::string& text, Diagnostics& diags) {
    std::vector<std::pair<std::string, std::size_t>> words;
    for (std::size_t i = 0; i < text.size();) {
        while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        const std::size_t start = i;
        while (i < text.size() && !std::isspace(static_cast<unsigned char>(text[i]))) ++i;
        if (i > start) words.emplace_back(text.substr(start, i - start), start + 1);
    }
    auto error = [&](std::size_t column, const std::string& message) {
        diags.error({"--without", 1, static_cast<std::uint32_t>(column)}, message, text);
        return std::nullopt;
    };
    auto lower = [](std::string s) {
        for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        return s;
    };
    if (words.empty() || lower(words[0].first) != "force")
        return error(words.empty() ? 1 : words[0].second, "expected 'Force PART [CAUSE]' (an external force to take away)");
    if (words.size() < 2 || words.size() > 3) return error(words[0].second, "expected 'Force PART [CAUSE]': a part, and optionally a cause");
    const auto part = m.find_part(lower(words[1].first));
    if (!part) return error(words[1].second, "unknown part '" + words[1].first + "'");
    bridge::ForceRef ref{*part, std::nullopt};
    bool any = false, cause_found = false;
    for (const auto& f : m.forces) {
        if (f.part != *part) continue;
        any = true;
        cause_found = cause_found || (words.size() == 3 && f.cause == lower(words[2].first));
    }
    if (!any) return error(words[1].second, "no external force acts on '" + words[1].first + "'");
    if (words.size() == 3) {
        if (!cause_found) return error(words[2].second, "no force of cause '" + words[2].first + "' acts on '" + words[1].first + "'");
        ref.cause = lower(words[2].first);
    }
    return ref;
}

// Writes text to path whole, or not at all (a file beside it, renamed).
bool write_whole(const std::filesystem::path& path, const std::string& text, std::ostream& err) {
    const std::filesystem::path part = path.string() + ".part";
    {
        std::ofstream os(part);
        os << text;
        if (!os) {
            err << "qm-atms: cannot write '" << path.string() << "'\n";
            return false;
        }
    }
    std::error_code ec;
    std::filesystem::rename(part, path, ec);
    if (ec) err << "qm-atms: cannot write '" << path.string() << "': " << ec.message() << '\n';
    return !ec;
}

// The graph laid out and drawn by Graphviz's library (cli/graph_svg.hpp), for the file at path.
std::optional<std::string> render_svg(const std::filesystem::path& path, const std::string& graph, std::ostream& err) {
    GraphSvg drawn = graph_svg(graph);
    if (!drawn.svg) err << "qm-atms: cannot draw '" << path.string() << "': " << drawn.why_not << '\n';
    return std::move(drawn.svg);
}

// The command line (usage in cli/geometry_usage.cpp). nullopt: `o` read; otherwise the exit status
// to return (0 after --help or --version). An option that would change nothing is refused.
std::optional<int> parse_options(std::span<const std::string> args, Options& o, std::ostream& out, std::ostream& err) {
    CommandOptions cl(envision_usage());
    std::vector<std::string> scenes;
    std::optional<std::string> max_states, cache, rules, dot, svg;
    bool no_cache = false;
    cl.positionals(scenes);
    cl.flag("--table", o.table);
    cl.flag("--json", o.json);
    cl.flag("--stats", o.stats);
    cl.flag("--verify", o.verify);
    cl.single("--max-states", "a positive whole number", max_states);
    declare_memory_option(cl, o.limits);
    cl.repeated("--without", "an external force to take away, e.g. --without 'Force follower' or --without 'Force follower spring'",
                o.without);
    cl.single("--from", "a state, e.g. --from '#3'", o.from);
    cl.single("--next", "a state, e.g. --next '#3' or --next 'cam/follower-1 + 0'", o.next, "ask one at a time");
    cl.single("--previous", "a state, e.g. --previous '#3'", o.previous, "ask one at a time");
    cl.single("--path", "a behaviour, e.g. --path 'follower=+; follower=-'", o.path, "ask one at a time");
    cl.repeated("--avoid", "a state description to avoid, e.g. --avoid 'cam=0'", o.avoid);
    cl.single("--why-not", "a transition, e.g. --why-not '#3 -> #4'", o.why_not, "ask one at a time");
    cl.single("--dot", "a file to write the graph to", dot);
    cl.single("--svg", "a file to draw the graph in (SVG)", svg);
    cl.place_cache(cache, no_cache);
    cl.single("--rules", "a folder of .rules files (the Clock laws)", rules);
    if (auto status = cl.parse(args, out, err)) return status;
    if (auto status = read_limit_options(cl, o.limits, err)) return status;
    if (scenes.empty()) return cl.error(err, "envision takes a metric scene");
    if (scenes.size() > 1) return cl.error(err, "envision takes one metric scene, not '" + scenes[0] + "' and '" + scenes[1] + "'");
    o.scene = scenes[0];
    if (max_states) {
        const auto n = count_of(*max_states);
        if (!n || *n == 0) return cl.bad_value(err, "--max-states", *max_states);
        o.max_states = *n;
    }
    o.use_cache = !no_cache;
    if (cache) o.cache = *cache;
    if (rules) o.rules = *rules;
    if (dot) o.dot = *dot;
    if (svg) o.svg = *svg;
    if (o.table && o.json) return cl.error(err, "--table and --json are two different outputs: give one");
    if (!o.avoid.empty() && !o.path) return cl.error(err, "--avoid goes with --path");
    // A question is answered in text about the whole envisionment: the options that shape the
    // envisionment printed without one would change nothing.
    const char* question = o.next ? "--next" : o.previous ? "--previous" : o.path ? "--path" : o.why_not ? "--why-not" : nullptr;
    if (question)
        for (const auto& [given, option] : {std::pair{o.json, "--json"}, std::pair{o.table, "--table"}, std::pair{o.from.has_value(), "--from"},
                                            std::pair{dot.has_value(), "--dot"}, std::pair{svg.has_value(), "--svg"}, std::pair{o.verify, "--verify"}})
            if (given)
                return cl.error(err, std::string(question) + " answers a question in text, and " + option +
                                         " shapes only the envisionment printed without one: give one or the other");
    return std::nullopt;
}

// --stats: where the time went, on standard error.
void print_stats(const ev::Envisionment& e, std::ostream& err) {
    err << "places: " << e.seconds_places << " s\n";
    for (const auto& c : e.chains)
        err << "chain " << c.chain.index + 1 << ": states " << c.seconds_states << " s, transitions " << c.seconds_transitions
            << " s, nogoods " << c.nogoods << '\n';
}

// --next, --previous, --path, --why-not: each answered in turn; 2 after a bad question.
int answer_questions(const Options& o, const g::Mechanism& m, const ev::Envisionment& e, const ev::EnvisionOptions& options,
                     std::ostream& text, Diagnostics& diags) {
    for (const auto& [option, value] : {std::pair{"--next", o.next}, std::pair{"--previous", o.previous}}) {
        if (!value) continue;
        const auto s = ev::find_state(e, *value, option, diags);
        if (!s) return 2;
        if (std::string(option) == "--next") {
            if (!ev::write_next(text, m, e, *s, options, diags)) return 2;
        } else {
            ev::write_previous(text, e, *s);
        }
    }
    if (o.path) {
        const auto b = ev::parse_behaviour(e, *o.path, "--path", o.avoid, diags);
        if (!b) return 2;
        ev::write_behaviour(text, e, *b, ev::find_behaviour(e, *b));
    }
    if (o.why_not && !ev::write_why_not(text, m, e, options, *o.why_not, diags)) return 2;
    return 0;
}

// Everything after the options: the envisionment, then the answer, made whole before any of it is
// written (so that a limit reached on the way leaves no file and nothing on `out`).
int envision_and_answer(const Options& o, ProgressBar& bar, std::ostream& out, std::ostream& err) {
    Diagnostics diags;
    const auto m = g::read_mechanism_file(o.scene, diags);
    if (!m) return bad_input(diags, err);
    ev::EnvisionOptions options;
    for (const auto& w : o.without)
        if (auto ref = parse_without(*m, w, diags)) options.without.push_back(*ref);
    if (diags.has_errors()) return bad_input(diags, err);
    if (o.rules) {
        options.rules = *o.rules;
    } else if (const auto dir = default_rules_directory()) {
        options.rules = *dir / "clock";
    } else {
        return usage_error(err, "cannot find the laws (rules/clock): give --rules DIR or set QM_ATMS_RULES");
    }
    const std::optional<g::PlaceCache> cache = bridge::open_place_cache(o.use_cache, o.cache);
    options.cache = cache ? &*cache : nullptr;
    options.max_states = o.max_states;
    options.from = o.from;  // the states it leads to, found on the fly
    if (o.next && !o.previous && !o.path && !o.why_not) {  // one state's transitions answer it
        options.from = o.next;
        options.from_only = true;
    }
    options.progress = [&bar](const ev::Progress& p) { bar(p); };
    auto e = ev::envision(*m, options, diags);
    bar.envisioned();
    diags.print(err);
    if (!e || diags.has_errors()) return 2;
    std::ostringstream text;
    if (o.next || o.previous || o.path || o.why_not) {
        const int status = answer_questions(o, *m, *e, options, text, diags);
        diags.print(err);
        if (status != 0) return status;
        out << text.str();
        if (o.stats) print_stats(*e, err);
        return 0;
    }
    std::ostringstream graph;
    if (o.dot || o.svg) ev::write_dot(graph, *e);
    std::optional<std::string> svg;
    if (o.svg) {
        svg = render_svg(*o.svg, graph.str(), err);
        if (!svg) return 2;
    }
    if (o.json) ev::write_json(text, *m, *e);
    else if (o.table) ev::write_table(text, *m, *e);
    else ev::write_text(text, *m, *e);
    // --verify: the invariants of envision/verify.hpp; a broken one is the laws' failure (exit 1).
    const auto problems = o.verify ? ev::verify(*m, *e) : std::vector<std::string>{};
    if (o.dot && !write_whole(*o.dot, graph.str(), err)) return 2;
    if (svg && !write_whole(*o.svg, *svg, err)) return 2;
    out << text.str();
    if (o.stats) print_stats(*e, err);
    if (o.verify) {
        for (const auto& p : problems) err << "qm-atms: verify: " << p << '\n';
        if (!problems.empty()) return 1;
        err << "qm-atms: verify: every invariant holds (terminal states are jams, cycles can repeat, moving states lead on)\n";
    }
    return 0;
}

}  // namespace

int envision_command(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
    Options o;
    if (auto status = parse_options(args, o, out, err)) return *status;
    apply_memory_limit(o.limits);
    // A limit (--max-states, --max-memory) ends the run with what it had found, and nothing written.
    ProgressBar bar(isatty(STDERR_FILENO) == 1);
    try {
        return envision_and_answer(o, bar, out, err);
    } catch (LimitReached& limit) {
        bar.clear();
        limit.doing = bar.run_so_far(o.scene);
        err << limit_message(limit, "");
        return 2;
    } catch (const std::bad_alloc&) {
        const auto message = memory_limit_message(bar.run_so_far(o.scene));
        if (!message) throw;
        bar.clear();
        err << *message;
        return 2;
    }
}

}  // namespace qm::cli
