// tests/engine/rule_folder_test.cpp: engine/rule_folder.hpp. A folder gives its *.rules files in
// name order and says why it gives none; the files are read once into the spec the program was
// compiled from, with every error of every file and the law checks' warnings; a slice compiles
// from that spec to the rules slice_program() keeps.
#include "engine/program_slice.hpp"
#include "engine/rule_folder.hpp"
#include "engine/rule_spec_reader.hpp"
#include <doctest/doctest.h>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

using qm::Diagnostics;
using qm::Severity;
using namespace qm::engine;
namespace fs = std::filesystem;

namespace {

// A fresh folder under the build tree holding the given files (name -> text).
fs::path folder_of(const std::string& name, const std::vector<std::pair<std::string, std::string>>& files) {
    const fs::path dir = fs::path(QM_BINARY_DIR) / "rule-folder-test" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const auto& [file, text] : files) {
        fs::create_directories((dir / file).parent_path());
        std::ofstream(dir / file) << text;
    }
    return dir;
}

std::string printed(const Diagnostics& d) {
    std::ostringstream os;
    d.print(os);
    return os.str();
}

template <class Rules>
std::set<std::string> folder_rule_names(const Rules& rules) {
    std::set<std::string> out;
    for (const auto& r : rules) out.insert(r.name);
    return out;
}

const char* const program_text =
    "cite \"Definition 22\"\n"
    "input (link ?a ?b)\n"
    "output (chained ?a ?b)\n"
    "rule chain-link when (link ?a ?b) then (chained ?a ?b)\n"
    "rule chain-step when (chained ?a ?b) (link ?b ?c) then (chained ?a ?c)\n"
    "rule loop-out when (chained ?a ?a) then false\n";

}  // namespace

TEST_CASE("engine/rule_folder: a folder's .rules files directly in it, in name order") {
    const fs::path dir = folder_of("listing", {{"b.rules", ""}, {"a.rules", ""}, {"notes.txt", ""}, {"sub/c.rules", ""}});
    Diagnostics d;
    const auto files = rule_folder_files(dir, d);
    CHECK(d.items().empty());
    CHECK(files == std::vector<std::string>{(dir / "a.rules").string(), (dir / "b.rules").string()});
}

TEST_CASE("engine/rule_folder: a folder that gives no rule file says why, at the folder") {
    const fs::path empty = folder_of("empty", {{"notes.txt", ""}});
    const fs::path missing = fs::path(QM_BINARY_DIR) / "rule-folder-test" / "no-such-folder";
    const fs::path file = empty / "notes.txt";
    for (const auto& [path, why] : std::vector<std::pair<fs::path, std::string>>{
             {empty, "it holds none"}, {missing, "there is no such folder"}, {file, "it is a file, not a folder"}}) {
        CAPTURE(path);
        Diagnostics d;
        CHECK(rule_folder_files(path, d).empty());
        CHECK(printed(d) == path.string() + ":1:1: error: expected a folder of .rules files (the laws), but " + why + "\n");
        Diagnostics again;
        CHECK(!load_rule_folder(path, again).has_value());
        CHECK(printed(again) == printed(d));
    }
}

TEST_CASE("engine/rule_folder: the program keeps the spec it was compiled from, with its citations") {
    const fs::path dir = folder_of("program", {{"chains.rules", program_text}});
    Diagnostics d;
    const auto p = load_rule_folder(dir, d, LawCheckOptions{true, {}, {}});
    REQUIRE_MESSAGE(p.has_value(), printed(d));
    CHECK(d.items().empty());
    CHECK(p->spec.rules.size() == 3);
    CHECK(folder_rule_names(p->compiled.program.rules) == std::set<std::string>{"chain-link", "chain-step", "loop-out"});
    CHECK(p->compiled.citations.at((dir / "chains.rules").string()) == "Definition 22");
    // The spec is what reading the files gives.
    ProgramSpec again;
    Diagnostics read;
    read_rule_files(std::vector<std::string>{(dir / "chains.rules").string()}, again, read);
    CHECK(again.rules.size() == p->spec.rules.size());
    for (std::size_t i = 0; i < again.rules.size(); ++i) CHECK(again.rules[i].name == p->spec.rules[i].name);
}

TEST_CASE("engine/rule_folder: every error of every file, each with its line; warnings beside a program that loads") {
    const fs::path bad = folder_of("errors", {{"a.rules", "rule broken when (link ?a ?b then (chained ?a ?b)\n"},
                                              {"b.rules", "rule unbound when (link ?a ?b) then (chained ?a ?c)\n"}});
    Diagnostics d;
    CHECK(!load_rule_folder(bad, d).has_value());
    const std::string shown = printed(d);
    CHECK(shown.find((bad / "a.rules").string() + ":1:") != std::string::npos);
    CHECK(shown.find((bad / "b.rules").string() + ":1:") != std::string::npos);
    CHECK(shown.find("  rule unbound when") != std::string::npos);  // the source line is shown
    // An uncited law file is a warning when citations are required, and none otherwise.
    const fs::path uncited = folder_of("uncited", {{"a.rules", "input (link ?a ?b)\nrule copy when (link ?a ?b) then (chained ?a ?b)\n"}});
    Diagnostics warned, quiet;
    CHECK(load_rule_folder(uncited, warned, LawCheckOptions{true, {}, {}}).has_value());
    CHECK(warned.size() == 1);
    CHECK(warned.items().front().severity == Severity::warning);
    CHECK(load_rule_folder(uncited, quiet).has_value());
    CHECK(quiet.items().empty());
}

TEST_CASE("engine/rule_folder: a slice compiles from the spec read to the rules slice_program() keeps") {
    const fs::path dir = folder_of("slice", {{"chains.rules", program_text}});
    Diagnostics d;
    const auto p = load_rule_folder(dir, d);
    REQUIRE(p.has_value());
    for (const std::set<std::string>& outputs : {std::set<std::string>{}, std::set<std::string>{"chained"}}) {
        const ProgramSpec kept = slice_program(p->spec, {"link"}, outputs);
        const LoadedProgram slice = compile_slice(*p, {"link"}, outputs);
        std::set<std::string> names;
        for (const auto& r : kept.rules) names.insert(r.name);
        CHECK(folder_rule_names(slice.program.rules) == names);
    }
    // With no input nothing can fire.
    CHECK(compile_slice(*p, {}, {"chained"}).program.rules.empty());
}
