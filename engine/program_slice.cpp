// engine/program_slice.cpp
#include "engine/program_slice.hpp"
#include <vector>

namespace qm::engine {

namespace {

// Predicates a rule needs facts of before it can fire.
std::vector<std::string> needed(const RuleSpec& r) {
    std::vector<std::string> out;
    for (const auto& c : r.conditions) {
        if (c.kind == ConditionSpec::Kind::atom) out.push_back(c.atom.predicate);
        if (c.kind == ConditionSpec::Kind::exists)
            for (const auto& a : c.atoms) out.push_back(a.predicate);
    }
    return out;
}

// Every predicate a rule reads (positive, negated, quantified, aggregated).
std::vector<std::string> read(const RuleSpec& r) {
    std::vector<std::string> out;
    for (const auto& c : r.conditions) {
        if (c.kind == ConditionSpec::Kind::atom || c.kind == ConditionSpec::Kind::negation || c.kind == ConditionSpec::Kind::aggregate)
            out.push_back(c.atom.predicate);
        if (c.kind == ConditionSpec::Kind::for_all || c.kind == ConditionSpec::Kind::exists)
            for (const auto& a : c.atoms) out.push_back(a.predicate);
    }
    return out;
}

bool concludes_false(const RuleSpec& r) {
    for (const auto& c : r.consequents)
        if (c.kind == ConsequentSpec::Kind::falsity) return true;
    return false;
}

}  // namespace

ProgramSpec slice_program(const ProgramSpec& program, const std::set<std::string>& inputs, const std::set<std::string>& outputs) {
    // Forward: which rules can fire.
    std::set<std::string> producible = inputs;
    for (const auto& f : program.facts) producible.insert(f.predicate);
    for (const auto& a : program.assumptions) producible.insert(a.predicate);
    std::vector<bool> can_fire(program.rules.size(), false);
    for (bool grew = true; grew;) {
        grew = false;
        for (std::size_t i = 0; i < program.rules.size(); ++i) {
            if (can_fire[i]) continue;
            bool ok = true;
            for (const auto& p : needed(program.rules[i])) ok = ok && producible.count(p) > 0;
            if (!ok) continue;
            can_fire[i] = grew = true;
            for (const auto& c : program.rules[i].consequents)
                if (c.kind != ConsequentSpec::Kind::falsity) producible.insert(c.atom.predicate);
        }
    }
    // Backward: which of those matter for the outputs (or may make environments nogood). A `prefer`
    // matters where a kept rule still concludes or assumes its chosen predicate: the preference
    // query then reads its ranks, so they are wanted too.
    std::set<std::string> wanted = outputs;
    std::set<std::string> concluded;
    std::vector<bool> keep(program.rules.size(), false);
    std::vector<bool> keep_preference(program.preferences.size(), false);
    for (bool grew = true; grew;) {
        grew = false;
        for (std::size_t i = 0; i < program.rules.size(); ++i) {
            if (keep[i] || !can_fire[i]) continue;
            bool matters = concludes_false(program.rules[i]);
            for (const auto& c : program.rules[i].consequents)
                matters = matters || (c.kind != ConsequentSpec::Kind::falsity && wanted.count(c.atom.predicate) > 0);
            if (!matters) continue;
            keep[i] = grew = true;
            for (const auto& p : read(program.rules[i])) wanted.insert(p);
            for (const auto& c : program.rules[i].consequents)
                if (c.kind != ConsequentSpec::Kind::falsity) concluded.insert(c.atom.predicate);
        }
        for (std::size_t j = 0; j < program.preferences.size(); ++j) {
            const PreferenceSpec& p = program.preferences[j];
            if (keep_preference[j] || !concluded.count(p.choice.predicate)) continue;
            keep_preference[j] = grew = true;
            wanted.insert(p.rank.predicate);
        }
    }
    ProgramSpec out;
    for (std::size_t i = 0; i < program.rules.size(); ++i)
        if (keep[i]) out.rules.push_back(program.rules[i]);
    for (std::size_t j = 0; j < program.preferences.size(); ++j)
        if (keep_preference[j]) out.preferences.push_back(program.preferences[j]);
    for (const auto& f : program.facts)
        if (wanted.count(f.predicate)) out.facts.push_back(f);
    for (const auto& a : program.assumptions)
        if (wanted.count(a.predicate)) out.assumptions.push_back(a);
    return out;
}

}  // namespace qm::engine
