// cli/check_command.cpp: `qm-atms check` (cli/check_command.hpp).
#include "check_command.hpp"
#include "command_options.hpp"
#include "analysis/analysis.hpp"
#include "engine/rule_folder.hpp"
#include "rules_location.hpp"
#include <algorithm>
#include <filesystem>
#include <optional>

namespace qm::cli {
namespace {

std::string plural(std::size_t n, const char* word) { return std::to_string(n) + " " + word + (n == 1 ? "" : "s"); }

}  // namespace

const char* check_usage() noexcept {
    return "usage: qm-atms check [RULES-DIR | FILE.rules]... [--dimensions 2|3]\n"
           "  checks rule files without running them: errors, unknown predicates, rules that can never\n"
           "  fire or are unused, citations of the laws; a folder is read as laws (every *.rules in it)\n"
           "  --dimensions N  also warn about directions a scene of N dimensions cannot match\n"
           "  (no path: the laws qm-atms uses; exit 2 on an error, 0 otherwise)\n";
}

int check_command(std::span<const std::string> args, std::ostream& out, std::ostream& err) {
    std::vector<std::string> paths;
    std::optional<std::size_t> dimensions;
    {
        CommandOptions cl(check_usage());
        std::optional<std::string> given;
        cl.positionals(paths);
        cl.single("--dimensions", "2 or 3", given);
        if (auto status = cl.parse(args, out, err)) return *status;
        if (given && *given != "2" && *given != "3") return cl.bad_value(err, "--dimensions", *given);
        if (given) dimensions = static_cast<std::size_t>((*given)[0] - '0');
    }
    Diagnostics d;
    if (paths.empty()) {
        if (auto dir = default_rules_directory()) paths.push_back(dir->string());
        else d.error({"check", 1, 1}, "expected a folder of laws: none installed beside qm-atms; give RULES-DIR");
    }
    // A folder is a driver's laws: its files must cite the thesis. Files named alone are programs.
    std::vector<std::string> files;
    bool laws = false;
    for (const std::string& p : paths) {
        std::error_code ec;
        if (std::filesystem::is_directory(p, ec)) {
            laws = true;
            for (std::string& f : engine::rule_folder_files(p, d)) files.push_back(std::move(f));
        } else {
            files.push_back(p);
        }
    }
    std::optional<engine::CheckedProgram> program;
    if (!d.has_errors()) {
        engine::LawCheckOptions options = analysis::law_check_options(dimensions, "the scene (--dimensions " + (dimensions ? std::to_string(*dimensions) : std::string()) + ")");
        options.require_citations = laws;
        program = engine::load_rule_files(files, d, options);
    }
    d.print(err);
    const std::size_t errors = static_cast<std::size_t>(std::count_if(d.items().begin(), d.items().end(), [](const Diagnostic& x) {
        return x.severity == Severity::error;
    }));
    const std::size_t warnings = static_cast<std::size_t>(std::count_if(d.items().begin(), d.items().end(), [](const Diagnostic& x) {
        return x.severity == Severity::warning;
    }));
    out << "checked " << plural(files.size(), "file");
    if (program) out << ", " << plural(program->compiled.program.rules.size(), "rule");
    out << ": " << (errors ? plural(errors, "error") : std::string("no errors")) << ", "
        << (warnings ? plural(warnings, "warning") : std::string("no warnings")) << '\n';
    return errors ? 2 : 0;
}

}  // namespace qm::cli
