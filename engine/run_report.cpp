// engine/run_report.cpp
#include "engine/run_report.hpp"
#include <algorithm>

namespace qm::engine {
namespace {

bool fact_less(const Engine& e, FactId a, FactId b) {
    const Fact& x = e.facts().fact(a);
    const Fact& y = e.facts().fact(b);
    const ValueTable& v = e.values();
    if (x.predicate != y.predicate) return v.print(x.predicate) < v.print(y.predicate);
    auto less = [&](ValueId p, ValueId q) { return v.less(p, q); };
    return std::lexicographical_compare(x.args.begin(), x.args.end(), y.args.begin(), y.args.end(), less);
}

// Environments in report order: by size, then lexicographically by their texts.
std::vector<EnvText> sorted_envs(const Engine& e, const std::vector<atms::EnvId>& envs) {
    std::vector<EnvText> out;
    for (auto env : envs) out.push_back(env_text(e, env));
    std::sort(out.begin(), out.end(), [](const EnvText& a, const EnvText& b) {
        if (a.size() != b.size()) return a.size() < b.size();
        return a < b;
    });
    return out;
}

}  // namespace

std::vector<FactId> facts_in_order(const Engine& engine) {
    std::vector<FactId> out;
    for (std::uint32_t i = 0; i < engine.facts().size(); ++i) out.push_back(FactId{i});
    std::sort(out.begin(), out.end(), [&](FactId a, FactId b) { return fact_less(engine, a, b); });
    return out;
}

EnvText env_text(const Engine& engine, atms::EnvId env) { return env_text(engine, engine.atms().env(env)); }

EnvText env_text(const Engine& engine, const atms::Environment& env) {
    auto as = env.assumptions();
    std::vector<std::pair<std::optional<FactId>, atms::AssumptionId>> keyed;
    for (auto a : as) keyed.emplace_back(engine.fact_of(engine.atms().node_of(a)), a);
    // Facts in fact order; closed-world markers last, by id.
    std::sort(keyed.begin(), keyed.end(), [&](const auto& x, const auto& y) {
        if (x.first && y.first) return fact_less(engine, *x.first, *y.first);
        if (x.first || y.first) return x.first.has_value();
        return x.second < y.second;
    });
    EnvText out;
    for (const auto& k : keyed) out.push_back(engine.print(k.second));
    return out;
}

RunReport make_report(Engine& engine) {
    RunReport r;
    for (FactId f : facts_in_order(engine)) r.facts.push_back({engine.print(f), sorted_envs(engine, engine.label(f))});
    // Every minimal nogood, but the pairs of a large choice set only as a count.
    atms::Atms& atms = engine.atms();
    std::vector<atms::EnvId> nogoods = atms.stated_nogoods();
    for (std::size_t i = 0; i < engine.choice_sets().size(); ++i) {
        const std::vector<atms::AssumptionId>& set = engine.choice_sets()[i];
        if (set.size() <= listed_choice_set_limit) {
            for (atms::EnvId ng : atms.at_most_one_nogoods(engine.choice_set_constraint(i))) nogoods.push_back(ng);
            continue;
        }
        std::size_t alone = 0;  // members consistent on their own
        for (atms::AssumptionId a : set) alone += atms.is_consistent(atms.environment({a})) ? 1 : 0;
        const SourceLocation& at = engine.choice_set_where(i);
        r.unlisted.push_back({env_text(engine, atms::Environment::of(set)),
                              to_string(at),
                              alone * (alone - (alone == 0 ? 0 : 1)) / 2});
    }
    r.nogoods = sorted_envs(engine, nogoods);
    for (auto env : engine.interpretations()) r.interpretations.push_back(env_text(engine, env));
    return r;
}

}  // namespace qm::engine
