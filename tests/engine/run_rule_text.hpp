// tests/engine/run_rule_text.hpp
// Test helper (not a test): a rule program given as text, read as if from `file` (for the
// locations rules and diagnostics carry); compiled (engine_for) and run (run_rule_text), no
// diagnostic expected (doctest REQUIREs it). An Engine can be neither copied nor moved, hence the
// pointer.
#pragma once
#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/rule_spec_reader.hpp"
#include <doctest/doctest.h>
#include <memory>
#include <string>

namespace qm::engine::test {

inline std::unique_ptr<Engine> engine_for(const std::string& text, const std::string& file) {
    qm::Diagnostics d;
    ProgramSpec spec;
    read_rule_text(text, file, spec, d);
    auto p = compile_program(spec, d);
    REQUIRE(p.has_value());
    return std::make_unique<Engine>(std::move(p->program), std::move(p->values));
}

inline std::unique_ptr<Engine> run_rule_text(const std::string& text, const std::string& file) {
    auto e = engine_for(text, file);
    qm::Diagnostics d;
    e->run(d);
    REQUIRE(!d.has_errors());
    return e;
}

}  // namespace qm::engine::test
