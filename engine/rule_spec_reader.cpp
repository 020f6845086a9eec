// engine/rule_spec_reader.cpp: files, includes and the order of items.
#include "engine/rule_spec_reader.hpp"
#include "engine/rule_parser.hpp"
#include "engine/rule_parser_to_spec.hpp"
#include "qm/file_text.hpp"
#include <filesystem>
#include <optional>
#include <set>

namespace qm::engine {
namespace {


std::string normal(const std::string& path) { return std::filesystem::path(path).lexically_normal().string(); }

class Reader {
public:
    Reader(ProgramSpec& spec, Diagnostics& diagnostics, const BuiltinRegistry& builtins, SourceTexts* sources)
        : spec_(spec), diagnostics_(diagnostics), builtins_(builtins), sources_(sources) {}

    // Reads a file named on the command line (not included by another).
    void top_file(const std::string& path) {
        const std::string key = normal(path);
        if (read_.count(key)) return;
        FileText file = read_file_text(key);
        if (!file.text) {
            diagnostics_.error({path, 1, 1}, "cannot open rule file '" + path + "': " + file.why_not);
            return;
        }
        text_of(key, std::move(*file.text));
    }

    // Reads `text` as the file `key` (a normalised path), unless it was read already.
    void text_of(const std::string& key, std::string text) {
        if (read_.count(key)) return;
        read_.insert(key);
        open_.insert(key);
        SourceText src(key, std::move(text));
        for (const ast::Item& item : parse_rule_items(src, builtins_, diagnostics_)) {
            if (const auto* inc = boost::get<ast::Include>(&item)) include(*inc, src);
            else add_item_to_spec(item, src, spec_);
        }
        open_.erase(key);
        if (sources_) sources_->add(std::move(src));  // the text is moved, not copied: read once
    }

private:
    void include(const ast::Include& inc, const SourceText& from) {
        const std::string target =
            normal((std::filesystem::path(from.file().str()).parent_path() / inc.file.text).string());
        if (open_.count(target)) {
            diagnostics_.error(from.locate(static_cast<std::size_t>(inc.id_first)),
                               "include cycle: '" + target + "' is already being read",
                               from.line_at(static_cast<std::size_t>(inc.id_first)));
            return;
        }
        if (read_.count(target)) return;  // each file is read once
        FileText file = inc.file.text.empty() ? FileText{std::nullopt, "no file named"} : read_file_text(target);
        if (!file.text) {
            diagnostics_.error(from.locate(static_cast<std::size_t>(inc.file.id_first)),
                               "cannot open included file '" + target + "': " + file.why_not,
                               from.line_at(static_cast<std::size_t>(inc.file.id_first)));
            return;
        }
        text_of(target, std::move(*file.text));
    }

    ProgramSpec& spec_;
    Diagnostics& diagnostics_;
    const BuiltinRegistry& builtins_;
    SourceTexts* sources_;
    std::set<std::string> read_;  // every file read (or being read)
    std::set<std::string> open_;  // the chain of includes being read now
};

}  // namespace

void read_rule_files(std::span<const std::string> paths, ProgramSpec& spec, Diagnostics& diagnostics,
                     const BuiltinRegistry& builtins, SourceTexts* sources) {
    Reader reader(spec, diagnostics, builtins, sources);
    for (const auto& p : paths) reader.top_file(p);
}

void read_rule_file(const std::string& path, ProgramSpec& spec, Diagnostics& diagnostics,
                    const BuiltinRegistry& builtins, SourceTexts* sources) {
    read_rule_files(std::span<const std::string>(&path, 1), spec, diagnostics, builtins, sources);
}

void read_rule_text(const std::string& text, const std::string& name, ProgramSpec& spec, Diagnostics& diagnostics,
                    const BuiltinRegistry& builtins, SourceTexts* sources) {
    Reader reader(spec, diagnostics, builtins, sources);
    reader.text_of(normal(name), text);
}

}  // namespace qm::engine
