// cli/run_command.cpp
#include "run_command.hpp"
#include "engine/engine.hpp"
#include "engine/ground_atom_text.hpp"
#include "engine/json_writer.hpp"
#include "engine/report_printer.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_parser_source.hpp"
#include "engine/run_report.hpp"
#include "engine/why.hpp"
#include "engine/why_printer.hpp"
#include "resource_limits.hpp"
#include <fstream>
#include <optional>
#include <sstream>

namespace qm::cli {
namespace {

struct RunOptions {
    std::string program;
    std::optional<std::string> why;
    bool json = false;
    ResourceLimits limits;  // --max-facts, --max-environments, --max-memory
};

// nullopt: `o` read; otherwise the exit status to return (0 after --help or --version).
std::optional<int> parse(std::span<const std::string> args, RunOptions& o, std::ostream& out, std::ostream& err) {
    CommandOptions cl(run_usage());
    std::vector<std::string> programs;
    cl.positionals(programs);
    cl.flag("--json", o.json);
    // One explanation per run: a second --why would silently replace the first.
    cl.single("--why", "a fact, e.g. --why '(queen 1 2)'", o.why, "ask one at a time");
    declare_limit_options(cl, o.limits);
    if (auto status = cl.parse(args, out, err)) return status;
    if (auto status = read_limit_options(cl, o.limits, err)) return status;
    if (programs.empty()) return cl.error(err, "no program given");
    if (programs.size() > 1) return cl.error(err, "more than one program given ('" + programs[0] + "', '" + programs[1] + "')");
    o.program = programs[0];
    return std::nullopt;
}

// Prints diagnostics, each with the source line it points at: those of loading carry theirs already;
// the engine's (e.g. an undecidable `not`) get it here from the rule file.
void print_diagnostics(const Diagnostics& diagnostics, std::ostream& err) {
    engine::SourceTexts texts;
    for (const Diagnostic& d : diagnostics.items()) {
        if (!d.source_line.empty() || texts.find(d.where.file.str())) continue;
        std::ifstream in(d.where.file.str(), std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        texts.add(engine::SourceText(d.where.file, text.str()));
    }
    Diagnostics shown;
    texts.attach_lines(diagnostics, shown);
    shown.print(err);
}

}  // namespace

std::string run_usage() {
    return "usage: qm-atms run PROGRAM.rules [--why 'FACT'] [--json]\n"
           "  runs a rule program; prints each fact with its label, the minimal nogoods and the\n"
           "  interpretations of the declared choice sets\n"
           "  --why 'FACT'  explain FACT, e.g. '(queen 1 2)': its justifications, or the nogoods ruling it out\n"
           "  --json        print {\"facts\": [...], \"nogoods\": [...], \"interpretations\": [...]};\n"
           "                with --why, the explanation as JSON (docs/RULES.md)\n" +
           std::string(limits_usage());
}

int run_command(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
    std::optional<RunOptions> options(std::in_place);
    if (auto status = parse(args, *options, out, err)) return *status;
    apply_memory_limit(options->limits);
    Diagnostics diagnostics;
    auto loaded = engine::load_program(options->program, diagnostics);
    if (!loaded || diagnostics.has_errors()) {
        print_diagnostics(diagnostics, err);
        return 2;
    }
    print_diagnostics(diagnostics, err);  // warnings (a rule that can never fire, ...)
    diagnostics = Diagnostics{};
    engine::Engine e(std::move(loaded->program), std::move(loaded->values));
    e.set_limits(options->limits.engine_limits());
    e.run(diagnostics);
    if (diagnostics.has_errors()) {
        print_diagnostics(diagnostics, err);
        return 2;
    }
    if (options->why) {
        auto parsed = engine::parse_ground_atom(*options->why, e.values());
        if (!parsed.atom) {
            Diagnostics bad;
            bad.error({"--why", 1, parsed.column}, parsed.error, *options->why);
            bad.print(err);
            return 2;
        }
        auto f = e.find(parsed.atom->predicate, parsed.atom->args);
        if (!f) {
            if (options->json) {
                engine::Why none;  // unsupported: nothing concludes it; the fact in canonical notation
                none.fact = "(" + e.values().print(parsed.atom->predicate);
                for (engine::ValueId a : parsed.atom->args) none.fact += " " + e.values().print(a);
                none.fact += ")";
                out << engine::to_json(none) << '\n';
            } else {
                out << *options->why << " is not a fact of this program (no rule concludes it)\n";
            }
            return 0;
        }
        const engine::Why answer = engine::why(e, *f);
        if (options->json) out << engine::to_json(answer) << '\n';
        else out << engine::print_why(answer);
        return 0;
    }
    engine::RunReport report;
    try {
        report = engine::make_report(e);
    } catch (LimitReached& limit) {
        if (limit.doing.empty()) limit.doing = "enumerating the interpretations of " + options->program;
        throw;
    }
    if (options->json) out << engine::to_json(report) << '\n';
    else out << engine::print_report(report);
    return 0;
}

}  // namespace qm::cli
