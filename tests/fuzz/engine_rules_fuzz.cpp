// tests/fuzz/engine_rules_fuzz.cpp: libFuzzer target for the rule language front end
// (engine/rule_spec_reader.hpp over the X3 parser of engine/rule_parser.hpp), the checker and the
// compiler, on arbitrary bytes read as a rule file. Properties checked (abort on violation):
//   - no exception escapes reading, checking or compiling;
//   - every diagnostic is located (line and column >= 1) and every syntax error reads
//     `expected ... but found ...` with its source line;
//   - a program that reads without error prints (rule_printer.hpp) to text that reads back to the
//     same spec, and printing that is a fixed point;
//   - compile_program() returns a program exactly when it reports no error;
//   - the same bytes as a `--why` fact (ground_atom_text.hpp): a result exactly when no error.
// Includes are resolved in a sandbox directory made at start-up (a.rules, b.rules including a.rules,
// c.rules including itself); inputs naming an absolute path or `..` are skipped, so the fuzzer never
// opens files outside it.
// Assertions on, whatever the build type (the fuzz build may define NDEBUG): BOOST_ASSERT guards
// Spirit's preconditions (x3's character classes abort on bytes >= 0x80, which the readers avoid
// through qm/x3_ascii.hpp), and QM_ASSERT the model's. Before any include, so that all see it.
#undef NDEBUG
#ifndef QM_ENABLE_ASSERTS
#define QM_ENABLE_ASSERTS 1
#endif
#include "engine/builtin_registry.hpp"
#include "engine/ground_atom_text.hpp"
#include "engine/rule_checker.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_printer.hpp"
#include "engine/rule_spec_reader.hpp"

// The fuzz build instruments only this target, not the qm_engine library it links, so libFuzzer
// would be blind to the front end's branches. Compiling the front end's sources into this TU
// instruments them; the linker then takes no object from libqm_engine.a for these symbols.
#include "engine/ground_atom_text.cpp"
#include "engine/rule_checker.cpp"
#include "engine/rule_compiler.cpp"
#include "engine/rule_parser.cpp"
#include "engine/rule_parser_error_handler.cpp"
#include "engine/rule_parser_to_spec.cpp"
#include "engine/rule_printer.cpp"
#include "engine/rule_spec_reader.cpp"
#include "engine/stratify_rules.cpp"

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

std::string sandbox;

bool same(const qm::engine::TermSpec& a, const qm::engine::TermSpec& b);
bool same(const std::vector<qm::engine::TermSpec>& a, const std::vector<qm::engine::TermSpec>& b) {
    if (a.size() != b.size()) return false;
    for (std::size_t i = 0; i < a.size(); ++i)
        if (!same(a[i], b[i])) return false;
    return true;
}
bool same(const qm::engine::TermSpec& a, const qm::engine::TermSpec& b) {
    return a.kind == b.kind && a.text == b.text && a.integer == b.integer && same(a.args, b.args);
}

void check_located(const qm::Diagnostics& d) {
    for (const qm::Diagnostic& x : d.items()) {
        if (x.where.line < 1 || x.where.column < 1 || x.where.file.empty()) std::abort();
        if (x.message.rfind("expected ", 0) == 0 &&
            (x.message.find(" but found ") == std::string::npos || x.source_line.empty()))
            std::abort();
    }
}

}  // namespace

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    sandbox = (std::filesystem::temp_directory_path() / ("qm-engine-rules-fuzz-" + std::to_string(::getpid()))).string();
    std::filesystem::create_directories(sandbox);
    std::ofstream(sandbox + "/a.rules") << "fact (p a)\nrule r\n  when (p ?x)\n  then (q ?x)\n";
    std::ofstream(sandbox + "/b.rules") << "include \"a.rules\"\nassume (p b)\n";
    std::ofstream(sandbox + "/c.rules") << "include \"c.rules\"\n";
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace qm::engine;
    const std::string text(reinterpret_cast<const char*>(data), size);
    if (text.find("\"/") != std::string::npos || text.find("..") != std::string::npos) return 0;

    qm::Diagnostics read;
    ProgramSpec spec;
    read_rule_text(text, sandbox + "/fuzz.rules", spec, read);
    check_located(read);
    if (!read.has_errors()) {
        const std::string printed = print_program(spec);
        qm::Diagnostics again;
        ProgramSpec back;
        read_rule_text(printed, sandbox + "/printed.rules", back, again);
        if (again.has_errors() || print_program(back) != printed) std::abort();
        if (back.facts.size() != spec.facts.size() || back.rules.size() != spec.rules.size()) std::abort();
        for (std::size_t i = 0; i < spec.facts.size(); ++i)
            if (back.facts[i].predicate != spec.facts[i].predicate || !same(back.facts[i].args, spec.facts[i].args))
                std::abort();
    }
    qm::Diagnostics checked, compiled;
    if (check_program(spec, checked) == checked.has_errors()) std::abort();
    auto program = compile_program(spec, compiled);
    check_located(checked);
    check_located(compiled);
    if (program.has_value() == compiled.has_errors()) std::abort();

    ValueTable values;
    auto atom = parse_ground_atom(text.substr(0, 256), values);
    if (atom.atom.has_value() == !atom.error.empty()) std::abort();
    return 0;
}
