// engine/preferences.cpp
#include "engine/preferences.hpp"
#include "qm/assert.hpp"
#include <algorithm>
#include <limits>

namespace qm::engine {
namespace {

// The preference choosing among facts like f, if any (the checker allows one per predicate).
const CompiledPreference* preference_of(const Engine& e, const Fact& f) {
    for (const CompiledPreference& p : e.program().preferences)
        if (p.choice == f.predicate && p.key.size() == f.args.size()) return &p;
    return nullptr;
}

const Fact* fact_of(const Engine& e, atms::AssumptionId a) {
    auto f = e.fact_of(e.atms().node_of(a));
    return f ? &e.facts().fact(*f) : nullptr;
}

// Does rank fact r rank the member with these arguments?
bool ranks(const CompiledPreference& p, const Fact& r, const std::vector<ValueId>& member) {
    if (r.args.size() != p.key.size() + 1) return false;
    for (std::size_t i = 0; i < p.key.size(); ++i)
        if (r.args[p.key[i]] != member[i]) return false;
    return true;
}

// The facts of p's rank predicate that may rank the member: by its first argument's index.
std::span<const FactId> candidates(const Engine& e, const CompiledPreference& p, const std::vector<ValueId>& member) {
    if (p.key.empty()) return e.facts_of(p.rank);
    return e.facts().with_argument(p.rank, p.key[0], member[0]);
}

}  // namespace

const CompiledPreference* choosing_preference(const Engine& e, std::span<const atms::AssumptionId> set) {
    const Fact* first = set.empty() ? nullptr : fact_of(e, set.front());
    return first ? preference_of(e, *first) : nullptr;
}

std::vector<std::vector<std::int64_t>> choice_set_rank_table(Engine& e, std::span<const atms::AssumptionId> set,
                                                             std::span<const atms::AssumptionId> references) {
    QM_REQUIRE(references.size() < 16, "a rank table over at most 15 reference assumptions");
    const std::size_t masks = std::size_t{1} << references.size();
    std::vector<std::vector<std::int64_t>> table(masks);
    std::vector<atms::AssumptionId> members;
    for (std::size_t mask = 0; mask < masks; ++mask) {
        members.clear();
        for (std::size_t j = 0; j < references.size(); ++j)
            if (mask >> j & 1U) members.push_back(references[j]);
        auto ranks = choice_set_ranks(e, set, e.atms().environment(members));
        table[mask] = ranks ? std::move(*ranks) : std::vector<std::int64_t>(set.size(), 0);
    }
    return table;
}

std::vector<FactId> rank_facts(const Engine& e, atms::AssumptionId a) {
    std::vector<FactId> out;
    const Fact* member = fact_of(e, a);
    const CompiledPreference* p = member ? preference_of(e, *member) : nullptr;
    if (!p) return out;
    for (FactId r : candidates(e, *p, member->args))
        if (ranks(*p, e.facts().fact(r), member->args)) out.push_back(r);
    return out;
}

std::optional<std::vector<std::int64_t>> choice_set_ranks(const Engine& e, std::span<const atms::AssumptionId> set,
                                                          atms::EnvId env) {
    if (set.empty()) return std::nullopt;
    const Fact* first = fact_of(e, set.front());
    const CompiledPreference* p = first ? preference_of(e, *first) : nullptr;
    if (!p) return std::nullopt;
    std::vector<std::optional<std::int64_t>> rank(set.size());
    bool any = false;
    for (std::size_t i = 0; i < set.size(); ++i) {
        const Fact* member = fact_of(e, set[i]);
        if (!member || member->predicate != p->choice || member->args.size() != p->key.size()) continue;
        for (FactId f : candidates(e, *p, member->args)) {
            const Fact& r = e.facts().fact(f);
            if (!ranks(*p, r, member->args)) continue;
            const Value& k = e.values().value(r.args[p->rank_at]);
            if (k.kind != ValueKind::integer || !e.atms().holds_in(e.node(f), env)) continue;
            const std::int64_t value = p->up_to ? std::min(k.integer, *p->up_to) : k.integer;
            rank[i] = rank[i] ? std::min(*rank[i], value) : value;
            any = true;
        }
    }
    if (!any) return std::nullopt;
    std::int64_t farthest = 0;
    for (const auto& r : rank)
        if (r) farthest = std::max(farthest, *r);
    std::vector<std::int64_t> out;
    out.reserve(set.size());
    const std::int64_t unranked = farthest == std::numeric_limits<std::int64_t>::max() ? farthest : farthest + 1;
    for (const auto& r : rank) out.push_back(r ? *r : unranked);
    return out;
}

}  // namespace qm::engine
