// tests/analysis/scene_vocabulary_test.cpp: the Alex driver's declaration to the laws. The
// predicates it asserts (scene/vocabulary.hpp `asserted`) are exactly the `input` items of
// rules/scene_facts.rules, and those it reads back (`read_back`) exactly its `output` items, so the
// rule checker (engine/predicate_check.hpp) knows every fact the driver gives the laws and every
// conclusion it reads; and the bundled laws load with no warning at all.
#include "analysis/analysis.hpp"
#include "engine/rule_folder.hpp"
#include "engine/rule_spec_reader.hpp"
#include "scene/vocabulary.hpp"
#include <doctest/doctest.h>
#include <set>
#include <sstream>
#include <string>

namespace v = qm::scene::vocabulary;

namespace {
std::set<std::string> predicates(const std::vector<qm::engine::AtomSpec>& atoms) {
    std::set<std::string> out;
    for (const auto& a : atoms) out.insert(a.predicate);
    return out;
}
template <class Names>
std::set<std::string> strings(const Names& names) {
    return {names.begin(), names.end()};
}
}  // namespace

TEST_CASE("analysis/scene_vocabulary: rules/scene_facts.rules declares what the driver asserts and reads") {
    qm::engine::ProgramSpec spec;
    qm::Diagnostics d;
    qm::engine::read_rule_file(std::string(QM_SOURCE_DIR) + "/rules/scene_facts.rules", spec, d);
    REQUIRE(!d.has_errors());
    CHECK(predicates(spec.inputs) == strings(v::asserted));
    CHECK(predicates(spec.outputs) == strings(v::read_back));
    CHECK(spec.inputs.size() == v::asserted.size());
    CHECK(spec.outputs.size() == v::read_back.size());
}

TEST_CASE("analysis/scene_vocabulary: the bundled laws load with no error and no warning, for 2-D and 3-D scenes") {
    for (std::size_t dims : {2, 3}) {
        CAPTURE(dims);
        qm::Diagnostics d;
        const auto files = qm::engine::rule_folder_files(std::string(QM_SOURCE_DIR) + "/rules", d);
        auto program = qm::engine::load_rule_files(files, d, qm::analysis::law_check_options(dims, "a scene"));
        std::ostringstream shown;
        d.print(shown);
        CHECK_MESSAGE(d.items().empty(), shown.str());
        REQUIRE(program.has_value());
        // Every law file with a rule cites the thesis; the driver's declaration file too.
        CHECK(program->compiled.citations.size() == files.size());
    }
}
