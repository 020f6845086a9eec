// engine/stratify_rules.cpp: the classic stratification by relaxation (Apt, Blair and Walker 1988):
// s(head) >= s(positive body), s(head) >= s(negative body) + 1; no solution below #predicates
// strata means a cycle through a negative edge.
#include "engine/stratify_rules.hpp"
#include <algorithm>
#include <unordered_map>

namespace qm::engine {
namespace {

struct Uses {
    std::vector<std::uint32_t> positive, negative, heads;
    SourceLocation negative_where;
};

}  // namespace

std::uint32_t stratify_rules(CompiledProgram& program, const ValueTable& values, Diagnostics& diagnostics) {
    (void)values;
    std::unordered_map<std::uint32_t, std::uint32_t> stratum;  // predicate ValueId -> stratum
    std::vector<Uses> uses;
    for (const auto& r : program.rules) {
        Uses u;
        for (const auto& c : r.conditions) {
            switch (c.kind) {
                case CompiledCondition::Kind::match: u.positive.push_back(c.atom.predicate.value); break;
                case CompiledCondition::Kind::for_all:
                case CompiledCondition::Kind::exists:
                    for (const auto& a : c.atoms) u.positive.push_back(a.predicate.value);
                    break;
                case CompiledCondition::Kind::negation:
                case CompiledCondition::Kind::aggregate:
                    if (u.negative.empty()) u.negative_where = c.where.file.empty() ? c.atom.where : c.where;
                    u.negative.push_back(c.atom.predicate.value);
                    break;
                case CompiledCondition::Kind::test: break;
            }
        }
        for (const auto& c : r.consequents)
            if (c.kind != CompiledConsequent::Kind::falsity) u.heads.push_back(c.atom.predicate.value);
        for (auto p : u.positive) stratum.emplace(p, 0);
        for (auto p : u.negative) stratum.emplace(p, 0);
        for (auto p : u.heads) stratum.emplace(p, 0);
        uses.push_back(std::move(u));
    }
    const std::uint32_t limit = static_cast<std::uint32_t>(stratum.size()) + 1;
    auto rule_stratum = [&](const Uses& u) {
        std::uint32_t s = 0;
        for (auto p : u.positive) s = std::max(s, stratum[p]);
        for (auto p : u.negative) s = std::max(s, stratum[p] + 1);
        return s;
    };
    bool cyclic = false;
    for (bool changed = true; changed && !cyclic;) {
        changed = false;
        for (const auto& u : uses) {
            std::uint32_t s = rule_stratum(u);
            for (auto h : u.heads) {
                if (stratum[h] < s) {
                    stratum[h] = s;
                    changed = true;
                    if (s > limit) cyclic = true;
                }
            }
        }
    }
    std::uint32_t count = 1;
    for (std::size_t i = 0; i < program.rules.size(); ++i) {
        RuleId id{static_cast<std::uint32_t>(i)};
        CompiledRule& r = program.rules[id];
        r.stratum = std::min(rule_stratum(uses[i]), limit);
        count = std::max(count, r.stratum + 1);
        if (cyclic && !uses[i].negative.empty() && r.stratum >= limit)
            diagnostics.error(uses[i].negative_where,
                              "rule '" + r.name + "': negation or aggregation through recursion: a predicate it uses "
                              "under `not` or an aggregate depends on its own conclusions");
    }
    if (cyclic) {
        bool reported = std::any_of(program.rules.begin(), program.rules.end(), [&](const CompiledRule& r) { return r.stratum >= limit; });
        if (!reported && !program.rules.empty())
            diagnostics.error(program.rules[RuleId{0}].where, "the program cannot be stratified");
    }
    return count;
}

}  // namespace qm::engine
