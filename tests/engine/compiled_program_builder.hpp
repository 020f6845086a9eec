// tests/engine/compiled_program_builder.hpp
// Test helper (not a test): builds CompiledPrograms directly, without the parser, so engine tests
// can generate random rule programs and check the engine against a brute-force oracle.
#pragma once
#include "engine/compiled_rule.hpp"
#include "engine/value_table.hpp"
#include <string>
#include <vector>

namespace qm::engine::test {

inline CompiledTerm var(Slot s) {
    CompiledTerm t;
    t.kind = CompiledTerm::Kind::variable;
    t.slot = s;
    return t;
}
inline CompiledTerm constant(ValueId v) {
    CompiledTerm t;
    t.kind = CompiledTerm::Kind::constant;
    t.constant = v;
    return t;
}
inline CompiledTerm call(const BuiltinRegistry& b, const std::string& name, std::vector<CompiledTerm> args) {
    CompiledTerm t;
    t.kind = CompiledTerm::Kind::call;
    t.function = *b.find(name);
    t.args = std::move(args);
    return t;
}
inline CompiledAtom atom(ValueTable& v, const std::string& predicate, std::vector<CompiledTerm> args) {
    return CompiledAtom{v.symbol(predicate), std::move(args), SourceLocation{"test.rules", 1, 1}};
}
inline CompiledCondition match(CompiledAtom a) {
    CompiledCondition c;
    c.kind = CompiledCondition::Kind::match;
    c.atom = std::move(a);
    return c;
}
inline CompiledCondition negation(CompiledAtom a) {
    CompiledCondition c;
    c.kind = CompiledCondition::Kind::negation;
    c.atom = std::move(a);
    return c;
}
inline CompiledCondition builtin_test(const BuiltinRegistry& b, const std::string& name, std::vector<CompiledTerm> args) {
    CompiledCondition c;
    c.kind = CompiledCondition::Kind::test;
    c.test = CompiledTest{*b.find(name), std::move(args), SourceLocation{"test.rules", 1, 1}};
    return c;
}
inline CompiledConsequent assert_atom(CompiledAtom a) {
    CompiledConsequent c;
    c.kind = CompiledConsequent::Kind::assert_atom;
    c.atom = std::move(a);
    return c;
}
inline CompiledConsequent falsity() {
    CompiledConsequent c;
    c.kind = CompiledConsequent::Kind::falsity;
    return c;
}
inline CompiledGroundAtom ground(ValueTable& v, const std::string& predicate, std::vector<ValueId> args) {
    return CompiledGroundAtom{v.symbol(predicate), std::move(args), SourceLocation{"test.rules", 1, 1}};
}
inline CompiledRule rule(std::string name, std::uint32_t slots, std::vector<CompiledCondition> when,
                         std::vector<CompiledConsequent> then, std::uint32_t stratum = 0) {
    CompiledRule r;
    r.name = std::move(name);
    r.where = SourceLocation{"test.rules", 1, 1};
    for (std::uint32_t i = 0; i < slots; ++i) {
        std::string name = "?v";
        name += std::to_string(i);
        r.slot_names.push_back(name);
    }
    r.conditions = std::move(when);
    r.consequents = std::move(then);
    r.stratum = stratum;
    for (const auto& c : r.conditions)
        if (c.kind == CompiledCondition::Kind::negation || c.kind == CompiledCondition::Kind::aggregate)
            r.non_monotonic = true;
    return r;
}
inline CompiledConsequent exactly_one(Slot s, CompiledTerm set, CompiledAtom a) {
    CompiledConsequent c;
    c.kind = CompiledConsequent::Kind::exactly_one;
    c.slot = s;
    c.set = std::move(set);
    c.atom = std::move(a);
    return c;
}
inline CompiledCondition aggregate(CompiledAtom a, CompiledTerm value, BuiltinId fn, CompiledTerm start, Slot result) {
    CompiledCondition c;
    c.kind = CompiledCondition::Kind::aggregate;
    c.atom = std::move(a);
    c.value = std::move(value);
    c.function = fn;
    c.start = std::move(start);
    c.slot = result;
    return c;
}
}  // namespace qm::engine::test
