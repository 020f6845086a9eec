// engine/rule_folder.cpp: rule files read once, checked, compiled whole and in slices.
#include "engine/rule_folder.hpp"
#include "engine/predicate_check.hpp"
#include "engine/program_slice.hpp"
#include "engine/rule_checker.hpp"
#include "engine/rule_spec_reader.hpp"
#include "qm/assert.hpp"
#include <algorithm>
#include <system_error>

namespace qm::engine {

std::vector<std::string> rule_folder_files(const std::filesystem::path& folder, Diagnostics& diagnostics) {
    std::error_code ec;
    std::vector<std::string> files;
    // Why the folder gives no rules, in words a user can act on.
    auto refuse = [&](const std::string& why) {
        diagnostics.error({folder.string(), 1, 1}, "expected a folder of .rules files (the laws), but " + why);
        return std::vector<std::string>{};
    };
    const std::filesystem::file_status st = std::filesystem::status(folder, ec);
    if (ec && ec != std::errc::no_such_file_or_directory) return refuse("it cannot be read: " + ec.message());
    if (!std::filesystem::exists(st)) return refuse("there is no such folder");
    if (!std::filesystem::is_directory(st)) return refuse("it is a file, not a folder");
    std::filesystem::directory_iterator it(folder, ec), end;
    if (ec) return refuse("it cannot be read: " + ec.message());
    for (; it != end; it.increment(ec)) {
        if (ec) return refuse("it cannot be read: " + ec.message());
        if (it->is_regular_file(ec) && it->path().extension() == ".rules") files.push_back(it->path().string());
    }
    if (files.empty()) return refuse("it holds none");
    std::sort(files.begin(), files.end());
    return files;
}

std::optional<CheckedProgram> load_rule_files(std::span<const std::string> paths, Diagnostics& diagnostics,
                                              const LawCheckOptions& laws) {
    CheckedProgram out;
    SourceTexts sources;
    Diagnostics read;
    read_rule_files(paths, out.spec, read, default_builtins(), &sources);
    // A syntax error drops only its own item, so the items that were read are still checked and
    // compiled: one run reports the syntax errors and the semantic errors of everything else, each
    // with the source line it points at.
    Diagnostics found;
    bool checked = check_program(out.spec, found);
    // Where predicates come from is checked only on a whole program: an item a syntax error dropped
    // may be the one that states a predicate, which would make every use of it look misspelt.
    if (!read.has_errors()) checked = check_predicates(out.spec, found) && checked;
    auto program = compile_program(out.spec, found);
    check_laws(out.spec, laws, found);
    sources.attach_lines(read, diagnostics);
    sources.attach_lines(found, diagnostics);
    if (read.has_errors() || !checked || found.has_errors() || !program) return std::nullopt;
    program->citations = citations(out.spec);
    out.compiled = std::move(*program);
    return out;
}

std::optional<CheckedProgram> load_rule_folder(const std::filesystem::path& folder, Diagnostics& diagnostics,
                                               const LawCheckOptions& laws) {
    const std::vector<std::string> files = rule_folder_files(folder, diagnostics);
    if (files.empty()) return std::nullopt;
    return load_rule_files(files, diagnostics, laws);
}

LoadedProgram compile_slice(const CheckedProgram& program, const std::set<std::string>& inputs, const std::set<std::string>& outputs) {
    Diagnostics d;
    auto slice = compile_program(slice_program(program.spec, inputs, outputs), d);
    if (!slice) throw InternalError("a slice of a program that compiles does not compile: " +
                                    (d.items().empty() ? std::string() : d.items().front().message));
    return std::move(*slice);
}

}  // namespace qm::engine
