// tests/fuzz/engine_rules_fuzz.cpp: libFuzzer target for the rule language front end
// (engine/rule_spec_reader.hpp over the X3 parser of engine/rule_parser.hpp), the checker, the
// compiler and the engine, on arbitrary bytes read as a rule file. Properties checked (abort on
// violation):
//   - no exception escapes reading, checking, compiling or running (an InternalError is a bug);
//   - every diagnostic is located (line and column >= 1) and every syntax error reads
//     `expected ... but found ...` with its source line;
//   - a program that reads without error prints (rule_printer.hpp) to text that reads back to the
//     same spec, and printing that is a fixed point;
//   - compile_program() returns a program exactly when it reports no error;
//   - a compiled program runs (Engine::run, bounded by RunOptions::max_steps, so it always ends)
//     with located diagnostics only; after it, every fact that holds is explained by why() in each
//     of its label environments (the ATMS's explain checks the derivation), the report is built
//     and written as JSON (interpretations only when the choice sets have few combinations: their
//     number can be exponential, which is the question asked, not a bug);
//   - the same bytes as a `--why` fact (ground_atom_text.hpp): a result exactly when no error.
// Includes are resolved in a sandbox directory made at start-up (a.rules, b.rules including a.rules,
// c.rules including itself); inputs naming an absolute path or `..` are skipped, so the fuzzer never
// opens files outside it.
// Assertions are on in every object of a fuzz build, whatever its type (cmake/QmDefaults.cmake):
// BOOST_ASSERT guards Spirit's preconditions, QM_ASSERT the model's.
#include "engine/builtin_registry.hpp"
#include "engine/engine.hpp"
#include "engine/ground_atom_text.hpp"
#include "engine/json_writer.hpp"
#include "engine/rule_checker.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_printer.hpp"
#include "engine/rule_spec_reader.hpp"
#include "engine/run_report.hpp"
#include "engine/why.hpp"

// The runtime: the engine, its matcher and agenda, the builtins, explanations and reports.

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

// Runs a compiled program with a bounded amount of work and checks what it gives. An escaping
// exception (an InternalError is a failed precondition: a bug) reaches libFuzzer as a crash.
void run_program(qm::engine::LoadedProgram loaded) {
    using namespace qm::engine;
    // Ample for the bundled programs (queens8 takes 5,984 steps, polybox 167), small enough that
    // an input ends quickly.
    constexpr std::size_t max_steps = 100000;
    Engine e(std::move(loaded.program), std::move(loaded.values));
    qm::Diagnostics ran;
    RunOptions options;
    options.max_steps = max_steps;
    e.run(ran, options);
    check_located(ran);
    // Every fact that holds is derivable in each of its label environments (explain checks it).
    std::size_t explained = 0;
    for (FactId f : facts_in_order(e)) {
        if (++explained > 16) break;
        const Why w = why(e, f);
        if ((w.status == Why::Status::holds) != !e.label(f).empty()) std::abort();
        if (w.status == Why::Status::holds && w.derivations.size() != e.label(f).size()) std::abort();
        (void)to_json(w);
    }
    // The interpretations are enumerated only when the choice sets allow few combinations.
    double combinations = 1;
    for (const auto& set : e.choice_sets()) combinations *= static_cast<double>(set.size());
    if (combinations <= 4096) {
        const RunReport report = make_report(e);
        (void)to_json(report);
        for (qm::atms::EnvId i : e.interpretations())
            for (const auto& set : e.choice_sets()) {
                std::size_t picked = 0;
                for (qm::atms::AssumptionId a : set) picked += e.atms().env(i).contains(a) ? 1 : 0;
                if (picked != 1) std::abort();  // exactly one of every choice set
            }
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

    if (program) run_program(std::move(*program));

    ValueTable values;
    auto atom = parse_ground_atom(text.substr(0, 256), values);
    if (atom.atom.has_value() == !atom.error.empty()) std::abort();
    return 0;
}
