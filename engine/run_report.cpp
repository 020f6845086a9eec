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

EnvText env_text(const Engine& engine, atms::EnvId env) {
    auto as = engine.atms().env(env).assumptions();
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
    r.nogoods = sorted_envs(engine, engine.atms().minimal_nogoods());
    for (auto env : engine.interpretations()) r.interpretations.push_back(env_text(engine, env));
    return r;
}

}  // namespace qm::engine
