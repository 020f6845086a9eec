// atms/explanation.cpp: explanations by forward chaining (BPS explain-node). Chaining with one
// counter per justification derives each node through the first justification whose antecedents
// are all derived, so the recorded reasons are well founded by construction.
#include "atms/explanation.hpp"

#include "atms/justification.hpp"
#include "qm/assert.hpp"
#include <algorithm>
#include <cstdint>

namespace qm::atms {
namespace {
enum class How : std::uint8_t { underived, premise, assumption, justified };
}

std::optional<Explanation> derive_explanation(std::span<const Justification> justs, std::size_t node_count,
                                              const DerivationBase& base, NodeId goal, std::vector<AtMostOneUse>* used) {
    QM_REQUIRE(goal.value < node_count, "unknown node id");
    for (const Justification& j : justs) {
        QM_REQUIRE(j.consequent.value < node_count, "a justification's consequent is an unknown node id");
        for (NodeId a : j.antecedents) QM_REQUIRE(a.value < node_count, "a justification's antecedent is an unknown node id");
    }
    for (NodeId p : base.premises) QM_REQUIRE(p.value < node_count, "a premise is an unknown node id");
    for (const auto& entry : base.assumptions) QM_REQUIRE(entry.first.value < node_count, "an assumption's node is an unknown node id");
    std::vector<How> how(node_count, How::underived);
    std::vector<std::uint32_t> reason(node_count, 0);       // JustId value when How::justified
    std::vector<AssumptionId> assumption_of(node_count);    // when How::assumption
    std::vector<std::vector<std::uint32_t>> users(node_count);
    std::vector<std::size_t> missing(justs.size());
    std::vector<NodeId> queue;

    auto derive = [&](NodeId n, How h, std::uint32_t j) {
        if (how[n.value] != How::underived) return;
        how[n.value] = h;
        reason[n.value] = j;
        queue.push_back(n);
    };
    // An at_most_one clause needs two members; the first one met is kept in `first_member`.
    std::vector<std::optional<NodeId>> first_member(justs.size());
    std::vector<std::pair<NodeId, NodeId>> pair_of(justs.size());
    auto at_most_one = [&](std::uint32_t j) { return justs[j].kind == Justification::Kind::at_most_one; };
    for (std::uint32_t j = 0; j < justs.size(); ++j) {
        missing[j] = at_most_one(j) ? 2 : justs[j].antecedents.size();
        for (NodeId a : justs[j].antecedents) users[a.value].push_back(j);
    }
    for (NodeId p : base.premises) derive(p, How::premise, 0);
    for (auto [n, a] : base.assumptions) {
        assumption_of[n.value] = a;
        derive(n, How::assumption, 0);
    }
    for (std::uint32_t j = 0; j < justs.size(); ++j)
        if (missing[j] == 0) derive(justs[j].consequent, How::justified, j);
    for (std::size_t head = 0; head < queue.size() && how[goal.value] == How::underived; ++head) {
        const NodeId n = queue[head];
        for (std::uint32_t j : users[n.value]) {
            if (at_most_one(j)) {
                if (how[n.value] != How::assumption || missing[j] == 0) continue;
                if (--missing[j] == 1) {
                    first_member[j] = n;
                    continue;
                }
                // In the clause's antecedent order, as a pairwise nogood of the set would list them.
                const auto& ants = justs[j].antecedents;
                const bool in_order = std::find(ants.begin(), ants.end(), *first_member[j]) < std::find(ants.begin(), ants.end(), n);
                pair_of[j] = in_order ? std::pair(*first_member[j], n) : std::pair(n, *first_member[j]);
                derive(justs[j].consequent, How::justified, j);
            } else if (--missing[j] == 0) {
                derive(justs[j].consequent, How::justified, j);
            }
        }
    }
    if (how[goal.value] == How::underived) return std::nullopt;

    // Post-order walk from the goal: antecedents before the step that uses them.
    Explanation out;
    out.node = goal;
    std::vector<bool> done(node_count, false);
    std::vector<std::pair<NodeId, bool>> stack{{goal, false}};
    while (!stack.empty()) {
        auto [n, expanded] = stack.back();
        stack.pop_back();
        if (done[n.value]) continue;
        if (how[n.value] == How::premise) {
            done[n.value] = true;
            out.premises.push_back(n);
        } else if (how[n.value] == How::assumption) {
            done[n.value] = true;
            out.assumptions.push_back(assumption_of[n.value]);
        } else if (expanded) {
            done[n.value] = true;
            const std::uint32_t j = reason[n.value];
            if (at_most_one(j) && used) used->push_back(AtMostOneUse{out.steps.size(), pair_of[j].first, pair_of[j].second});
            out.steps.push_back(JustId{j});
        } else {
            stack.emplace_back(n, true);
            const std::uint32_t j = reason[n.value];
            if (at_most_one(j)) {
                for (NodeId a : {pair_of[j].first, pair_of[j].second})
                    if (!done[a.value]) stack.emplace_back(a, false);
                continue;
            }
            for (NodeId a : justs[j].antecedents)
                if (!done[a.value]) stack.emplace_back(a, false);
        }
    }
    std::sort(out.premises.begin(), out.premises.end());
    std::sort(out.assumptions.begin(), out.assumptions.end());
    return out;
}
}  // namespace qm::atms
