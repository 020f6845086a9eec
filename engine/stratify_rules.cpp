// engine/stratify_rules.cpp: the classic stratification by relaxation (Apt, Blair and Walker 1988):
// s(head) >= s(positive body), s(head) >= s(negative body) + 1; no solution below #predicates
// strata means a cycle through a negative edge, which is then found and named.
#include "engine/stratify_rules.hpp"
#include <algorithm>
#include <deque>
#include <optional>
#include <string>
#include <unordered_map>

namespace qm::engine {
namespace {

struct NegativeUse {
    std::uint32_t predicate;
    SourceLocation where;
    bool aggregate;
};

struct Uses {
    std::vector<std::uint32_t> positive, heads;
    std::vector<NegativeUse> negative;
};

// One step of a dependency path: `to` is concluded by rule `rule` from a body that uses `from`.
struct Step {
    std::uint32_t from, to;
    std::size_t rule;
};

// The shortest chain of rules by which `to` depends on `from` (empty if to == from); nullopt if none.
std::optional<std::vector<Step>> dependency_path(const std::vector<Uses>& uses, std::uint32_t from, std::uint32_t to) {
    std::unordered_map<std::uint32_t, Step> reached_by;  // predicate -> the step that first reached it
    std::deque<std::uint32_t> queue{from};
    reached_by.emplace(from, Step{from, from, 0});
    while (!queue.empty() && !reached_by.count(to)) {
        const std::uint32_t p = queue.front();
        queue.pop_front();
        for (std::size_t r = 0; r < uses.size(); ++r) {
            const Uses& u = uses[r];
            bool uses_p = std::find(u.positive.begin(), u.positive.end(), p) != u.positive.end() ||
                          std::any_of(u.negative.begin(), u.negative.end(), [&](const NegativeUse& n) { return n.predicate == p; });
            if (!uses_p) continue;
            for (auto h : u.heads)
                if (reached_by.emplace(h, Step{p, h, r}).second) queue.push_back(h);
        }
    }
    if (!reached_by.count(to)) return std::nullopt;
    std::vector<Step> path;
    for (std::uint32_t p = to; p != from;) {
        path.push_back(reached_by.at(p));
        p = path.back().from;
    }
    std::reverse(path.begin(), path.end());
    return path;
}

}  // namespace

std::uint32_t stratify_rules(CompiledProgram& program, const ValueTable& values, Diagnostics& diagnostics) {
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
                    u.negative.push_back({c.atom.predicate.value, c.where.file.empty() ? c.atom.where : c.where,
                                          c.kind == CompiledCondition::Kind::aggregate});
                    break;
                case CompiledCondition::Kind::test: break;
            }
        }
        for (const auto& c : r.consequents)
            if (c.kind != CompiledConsequent::Kind::falsity) u.heads.push_back(c.atom.predicate.value);
        for (auto p : u.positive) stratum.emplace(p, 0);
        for (const auto& n : u.negative) stratum.emplace(n.predicate, 0);
        for (auto p : u.heads) stratum.emplace(p, 0);
        uses.push_back(std::move(u));
    }
    const std::uint32_t limit = static_cast<std::uint32_t>(stratum.size()) + 1;
    auto rule_stratum = [&](const Uses& u) {
        std::uint32_t s = 0;
        for (auto p : u.positive) s = std::max(s, stratum[p]);
        for (const auto& n : u.negative) s = std::max(s, stratum[n.predicate] + 1);
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
        CompiledRule& r = program.rules[RuleId{static_cast<std::uint32_t>(i)}];
        r.stratum = std::min(rule_stratum(uses[i]), limit);
        count = std::max(count, r.stratum + 1);
    }
    if (!cyclic) return count;

    // Name the cycle of every rule whose `not` or aggregate depends on one of its own conclusions.
    auto name = [&](std::uint32_t p) { return values.print(ValueId{p}); };
    bool reported = false;
    for (std::size_t i = 0; i < uses.size(); ++i) {
        const CompiledRule& r = program.rules[RuleId{static_cast<std::uint32_t>(i)}];
        for (const NegativeUse& n : uses[i].negative) {
            std::optional<std::vector<Step>> path;
            std::uint32_t head = 0;
            for (auto h : uses[i].heads)
                if ((path = dependency_path(uses, h, n.predicate))) {
                    head = h;
                    break;
                }
            if (!path) continue;
            const char* how = n.aggregate ? "an aggregate" : "`not`";
            std::string cycle = name(head);
            for (const Step& s : *path)
                cycle += " -> " + name(s.to) + " (rule '" + program.rules[RuleId{static_cast<std::uint32_t>(s.rule)}].name + "')";
            cycle += " -> " + name(head) + " (rule '" + r.name + "', " + how + ")";
            diagnostics.error(n.where, "rule '" + r.name + "': " + (n.aggregate ? "aggregation" : "negation") +
                                           " through recursion: '" + name(n.predicate) + "', used under " + how +
                                           " here, depends on this rule's own conclusion '" + name(head) +
                                           "' through the cycle " + cycle);
            reported = true;
            break;
        }
    }
    if (!reported && !program.rules.empty())
        diagnostics.error(program.rules[RuleId{0}].where, "the program cannot be stratified");
    return count;
}

}  // namespace qm::engine
