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
#include <fstream>
#include <optional>
#include <sstream>

namespace qm::cli {
namespace {

struct RunOptions {
    std::string program;
    std::optional<std::string> why;
    bool json = false;
};

std::optional<RunOptions> parse(std::span<const std::string> args, std::ostream& err) {
    RunOptions o;
    for (std::size_t i = 0; i < args.size(); ++i) {
        const std::string& a = args[i];
        if (a == "--json") {
            o.json = true;
        } else if (a == "--why") {
            if (i + 1 >= args.size()) {
                err << "qm-atms: error: --why needs a fact, e.g. --why '(queen 1 2)'\n";
                return std::nullopt;
            }
            if (o.why) {  // one explanation per run: a second --why would silently replace the first
                err << "qm-atms: error: --why is given twice ('" << *o.why << "', '" << args[i + 1] << "')\n";
                return std::nullopt;
            }
            o.why = args[++i];
        } else if (!a.empty() && a[0] == '-') {
            err << "qm-atms: error: unknown option '" << a << "'\n";
            return std::nullopt;
        } else if (o.program.empty()) {
            o.program = a;
        } else {
            err << "qm-atms: error: more than one program given ('" << o.program << "', '" << a << "')\n";
            return std::nullopt;
        }
    }
    if (o.program.empty()) {
        err << "qm-atms: error: no program given\n";
        return std::nullopt;
    }
    return o;
}

// Prints diagnostics, each with the source line it points at: those of loading carry theirs already;
// the engine's (e.g. an undecidable `not`) get it here from the rule file.
void print_diagnostics(const Diagnostics& diagnostics, std::ostream& err) {
    engine::SourceTexts texts;
    for (const Diagnostic& d : diagnostics.items()) {
        if (!d.source_line.empty() || texts.find(d.where.file)) continue;
        std::ifstream in(d.where.file, std::ios::binary);
        std::stringstream text;
        text << in.rdbuf();
        texts.add(engine::SourceText(d.where.file, text.str()));
    }
    Diagnostics shown;
    texts.attach_lines(diagnostics, shown);
    shown.print(err);
}

}  // namespace

const char* run_usage() noexcept {
    return "usage: qm-atms run PROGRAM.rules [--why 'FACT'] [--json]\n"
           "  runs a rule program; prints each fact with its label, the minimal nogoods and the\n"
           "  interpretations of the declared choice sets\n"
           "  --why 'FACT'  explain FACT, e.g. '(queen 1 2)': its justifications, or the nogoods ruling it out\n"
           "  --json        print {\"facts\": [...], \"nogoods\": [...], \"interpretations\": [...]};\n"
           "                with --why, the explanation as JSON (docs/RULES.md)\n";
}

int run_command(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
    auto options = parse(args, err);
    if (!options) {
        err << run_usage();
        return 2;
    }
    Diagnostics diagnostics;
    auto loaded = engine::load_program(options->program, diagnostics);
    if (!loaded || diagnostics.has_errors()) {
        print_diagnostics(diagnostics, err);
        return 2;
    }
    print_diagnostics(diagnostics, err);  // warnings (a rule that can never fire, ...)
    diagnostics = Diagnostics{};
    engine::Engine e(std::move(loaded->program), std::move(loaded->values));
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
    engine::RunReport report = engine::make_report(e);
    if (options->json) out << engine::to_json(report) << '\n';
    else out << engine::print_report(report);
    return 0;
}

}  // namespace qm::cli
