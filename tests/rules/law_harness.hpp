// tests/rules/law_harness.hpp: runs some of the law files of rules/ on a small hand-written set of
// facts (the rule language's `fact` items) and answers questions about the result: which facts
// hold, which environments are nogood, the interpretations of the choice sets.
#pragma once
#include "engine/engine.hpp"
#include "engine/ground_atom_text.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_spec_reader.hpp"
#include <doctest/doctest.h>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

namespace qm::test {

// `input (p ?a1 .. ?an)` for every predicate rules/ declares as input or output or concludes.
inline const std::vector<std::string>& theory_inputs() {
    static const std::vector<std::string> lines = [] {
        std::vector<std::string> files;
        for (const auto& e : std::filesystem::directory_iterator(std::string(QM_SOURCE_DIR) + "/rules"))
            if (e.path().extension() == ".rules") files.push_back(e.path().string());
        engine::ProgramSpec spec;
        Diagnostics d;
        engine::read_rule_files(files, spec, d);
        std::set<std::string> out;
        auto add = [&](const engine::AtomSpec& a) {
            std::string line = "input (" + a.predicate;
            for (std::size_t i = 0; i < a.args.size(); ++i) line += " ?a" + std::to_string(i);
            out.insert(line + ")");
        };
        for (const auto& a : spec.inputs) add(a);
        for (const auto& a : spec.outputs) add(a);
        for (const auto& r : spec.rules)
            for (const auto& c : r.consequents)
                if (c.kind != engine::ConsequentSpec::Kind::falsity) add(c.atom);
        return std::vector<std::string>(out.begin(), out.end());
    }();
    return lines;
}

class Laws {
public:
    // laws: file names in rules/ ("contact.rules"); facts: rule-language text (fact ... lines).
    Laws(std::vector<std::string> laws, const std::string& facts) {
        static int counter = 0;
        // Test executables run in parallel: the process id keeps their files apart.
        const std::string path = std::string(QM_BINARY_DIR) + "/law_test_" + std::to_string(::getpid()) + "_" +
                                 std::to_string(++counter) + ".rules";
        {
            std::ofstream out(path);
            for (const auto& l : laws) out << "include \"" << QM_SOURCE_DIR << "/rules/" << l << "\"\n";
            // The rule checker must know where the facts of a law's conditions come from. A few
            // laws alone are part of the theory: what the driver asserts (rules/scene_facts.rules),
            // and what the laws left out conclude (motions, freedoms, touches, pushes), come in as
            // inputs, which a test's facts may state.
            for (const std::string& line : theory_inputs()) out << line << '\n';
            out << facts << '\n';
        }
        Diagnostics d;
        auto loaded = engine::load_program(path, d);
        if (!loaded) {
            std::ostringstream os;
            d.print(os);
            FAIL("laws do not load: " << os.str());
        }
        engine_ = std::make_unique<engine::Engine>(std::move(loaded->program), std::move(loaded->values));
        engine_->run(d);
        if (d.has_errors()) {
            std::ostringstream os;
            d.print(os);
            FAIL("laws do not run: " << os.str());
        }
    }

    engine::Engine& engine() { return *engine_; }

    // The fact written as in the rule language, e.g. "(trans-constraint block (0 -))".
    [[nodiscard]] std::optional<engine::FactId> fact(const std::string& text) {
        auto parsed = engine::parse_ground_atom(text, engine_->values());
        REQUIRE_MESSAGE(parsed.atom.has_value(), text);
        return engine_->find(parsed.atom->predicate, parsed.atom->args);
    }
    // Holds in some consistent environment (for facts derived from premises only: holds outright).
    [[nodiscard]] bool holds(const std::string& text) {
        auto f = fact(text);
        return f && engine_->atms().is_in(engine_->node(*f));
    }
    // Every fact of a predicate that holds, printed.
    [[nodiscard]] std::set<std::string> all(const std::string& predicate) {
        std::set<std::string> out;
        for (engine::FactId f : engine_->facts_of(engine_->values().symbol(predicate)))
            if (engine_->atms().is_in(engine_->node(f))) out.insert(engine_->print(f));
        return out;
    }
    // The minimal nogoods, each printed as a sorted set of assumption texts.
    [[nodiscard]] std::set<std::set<std::string>> nogoods() {
        std::set<std::set<std::string>> out;
        for (atms::EnvId e : engine_->atms().minimal_nogoods()) out.insert(texts(e));
        return out;
    }
    // Minimal nogoods that mention no two assumptions of one choice set (Law 1's own exclusions).
    [[nodiscard]] std::set<std::set<std::string>> law_nogoods() {
        std::set<std::set<std::string>> out;
        for (atms::EnvId e : engine_->atms().minimal_nogoods()) {
            bool pairwise = false;
            for (const auto& set : engine_->choice_sets()) {
                int n = 0;
                for (atms::AssumptionId a : set) n += engine_->atms().env(e).contains(a);
                pairwise |= n > 1;
            }
            if (!pairwise) out.insert(texts(e));
        }
        return out;
    }
    [[nodiscard]] std::set<std::set<std::string>> interpretations() {
        std::set<std::set<std::string>> out;
        for (atms::EnvId e : engine_->interpretations()) out.insert(texts(e));
        return out;
    }

private:
    std::set<std::string> texts(atms::EnvId e) {
        std::set<std::string> out;
        for (atms::AssumptionId a : engine_->atms().env(e).assumptions()) out.insert(engine_->print(a));
        return out;
    }
    std::unique_ptr<engine::Engine> engine_;
};

// Facts for a fixed object: every non-zero translation and rotation is constrained by the frame.
inline std::string fixed(const std::string& object, int dimensions = 2) {
    std::string out;
    const char* s[] = {"+", "0", "-"};
    if (dimensions == 2) {
        for (auto x : s)
            for (auto y : s) out += "fact (frame-trans-constraint " + object + " (" + x + " " + y + "))\n";
        for (auto r : s) out += "fact (frame-rot-constraint " + object + " (" + r + "))\n";
    }
    return out;
}
// A pinned object: every translation constrained, rotation free.
inline std::string pinned(const std::string& object) {
    std::string out;
    const char* s[] = {"+", "0", "-"};
    for (auto x : s)
        for (auto y : s) out += "fact (frame-trans-constraint " + object + " (" + x + " " + y + "))\n";
    return out;
}

}  // namespace qm::test
