// atms/atms_nogoods.cpp: what is inconsistent. A stated nogood (BPS new-nogood) and an at-most-one
// constraint (a choice set's exclusions, kept whole) both retire the interned environments they
// make inconsistent from the labels; the queries list and explain the constraints' pairs as the
// pairwise nogoods they stand for.
#include "atms/atms.hpp"

#include "qm/assert.hpp"
#include <algorithm>
#include <numeric>
#include <bit>
#include <utility>

namespace qm::atms {

void Atms::retire_env(EnvId e) {
    envs_.mark_nogood(e);
    for (NodeId n : envs_.nodes(e)) {
        Label& l = labels_[n];
        auto it = std::lower_bound(l.begin(), l.end(), e);
        if (it != l.end() && *it == e) l.erase(it);
    }
}

void Atms::new_nogood(EnvId env) {
    if (envs_.is_nogood(env)) return;  // already subsumed by a known nogood
    const Environment& nogood = envs_[env];  // stays put: nothing below interns an environment
    nogoods_.add(env, nogood);
    events_.push_back(Event{Event::Kind::nogood, env.value});
    // Mark every interned superset nogood and drop it from the labels holding it (BPS new-nogood).
    auto retire = [&](EnvId e) {
        if (envs_.is_nogood(e) && e != env) return;
        retire_env(e);
    };
    if (nogood.empty()) {
        for (std::uint32_t i = 0; i < envs_.size(); ++i) retire(EnvId{i});
        return;
    }
    // Scan the supersets through the rarest of the nogood's assumptions.
    AssumptionId rarest = nogood.first();
    for (std::size_t w = 0; w < nogood.words().size(); ++w)
        for (std::uint64_t bits = nogood.words()[w]; bits != 0; bits &= bits - 1) {
            const AssumptionId a{static_cast<std::uint32_t>(std::size_t{nogood.index()[w]} * 64 + static_cast<std::size_t>(std::countr_zero(bits)))};
            if (envs_.containing(a).size() < envs_.containing(rarest).size()) rarest = a;
        }
    // containing() may not grow during the scan (retire interns nothing), so indexing is safe.
    const auto& candidates = envs_.containing(rarest);
    for (std::size_t i = 0; i < candidates.size(); ++i)
        if (envs_.subset(env, candidates[i])) retire(candidates[i]);
}

JustId Atms::add_at_most_one(InformantId why, std::span<const AssumptionId> members) {
    std::vector<NodeId> nodes;
    nodes.reserve(members.size());
    for (AssumptionId a : members) {
        QM_REQUIRE(assumption_nodes_.contains(a), "unknown assumption id");
        nodes.push_back(assumption_nodes_[a]);
    }
    // Duplicates collapse, keeping the first occurrence's place. Found by sorting the members' places
    // (stable: the first occurrence leads its equals), so that a constraint costs what it holds, not
    // the number of nodes (a table indexed by node made a scene's choice sets quadratic in its size).
    std::vector<std::size_t> order(nodes.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) { return nodes[x].value < nodes[y].value; });
    std::vector<char> keep(nodes.size(), 1);
    for (std::size_t i = 1; i < order.size(); ++i)
        if (nodes[order[i]] == nodes[order[i - 1]]) keep[order[i]] = 0;
    std::size_t kept = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i)
        if (keep[i] != 0) nodes[kept++] = nodes[i];
    nodes.resize(kept);
    const JustId j{static_cast<std::uint32_t>(justs_.size())};
    justs_.push_back(Justification{why, std::move(nodes), contradiction_, Justification::Kind::at_most_one});
    at_most_one_.push_back(j);
    if (!nogoods_.add_at_most_one(members)) return j;
    // An interned environment holding two members is now inconsistent: each is reached through
    // the index of the members it holds; one that was consistent and now is not holds two.
    for (AssumptionId a : members) {
        const auto& candidates = envs_.containing(a);  // retire_env interns nothing
        for (std::size_t i = 0; i < candidates.size(); ++i) {
            const EnvId e = candidates[i];
            if (!envs_.is_nogood(e) && nogoods_.subsumes(envs_[e])) retire_env(e);
        }
    }
    run_events();  // a label emptied here cancels its pending announcement
    return j;
}

// The pairs of constraint j that are minimal nogoods: both members consistent on their own.
std::vector<std::pair<AssumptionId, AssumptionId>> Atms::live_pairs(JustId j) const {
    const Justification& record = justs_[j.value];
    std::vector<AssumptionId> ok;
    for (NodeId n : record.antecedents) {
        const AssumptionId a = *nodes_[n].assumption;
        const AssumptionId one[] = {a};
        if (!nogoods_.subsumes(Environment::of(one))) ok.push_back(a);
    }
    std::vector<std::pair<AssumptionId, AssumptionId>> out;
    if (record.antecedents.size() < 2) return out;
    out.reserve(ok.size() * (ok.size() - (ok.empty() ? 0 : 1)) / 2);
    for (std::size_t x = 0; x < ok.size(); ++x)
        for (std::size_t y = x + 1; y < ok.size(); ++y) out.emplace_back(ok[x], ok[y]);
    return out;
}

EnvId Atms::pair_env(AssumptionId a, AssumptionId b) {
    const AssumptionId two[] = {a, b};
    return envs_.intern(Environment::of(two), nogoods_);
}

std::vector<EnvId> Atms::stated_nogoods() const {
    auto out = nogoods_.minimal();
    std::sort(out.begin(), out.end());
    return out;
}

std::vector<EnvId> Atms::at_most_one_nogoods(JustId j) {
    QM_REQUIRE(j.value < justs_.size() && justs_[j.value].kind == Justification::Kind::at_most_one,
               "not an at-most-one constraint");
    std::vector<EnvId> out;
    for (auto [a, b] : live_pairs(j)) out.push_back(pair_env(a, b));
    return out;
}

std::vector<EnvId> Atms::minimal_nogoods() {
    std::vector<EnvId> out = nogoods_.minimal();
    const std::size_t stated = out.size();
    for (JustId j : at_most_one_)
        for (auto [a, b] : live_pairs(j)) out.push_back(pair_env(a, b));
    std::sort(out.begin(), out.end());
    // Two constraints may share a pair.
    if (out.size() > stated) out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

std::vector<EnvId> Atms::minimal_nogoods_within(const Environment& e) {
    std::vector<EnvId> out = nogoods_.within(e);
    const AtMostOneIndex& index = nogoods_.at_most_one();
    if (!index.empty() && !nogoods_.empty_env_is_nogood()) {
        // The pairs within e: its members of each constraint, each consistent alone.
        std::vector<AssumptionId> as = e.assumptions();
        std::erase_if(as, [&](AssumptionId a) {
            const AssumptionId one[] = {a};
            return nogoods_.subsumes(Environment::of(one));
        });
        for (std::size_t x = 0; x < as.size(); ++x)
            for (std::size_t y = x + 1; y < as.size(); ++y) {
                const auto cx = index.of(as[x]), cy = index.of(as[y]);
                const bool shared = std::any_of(cx.begin(), cx.end(), [&](std::uint32_t c) {
                    return std::find(cy.begin(), cy.end(), c) != cy.end();
                });
                if (shared) out.push_back(pair_env(as[x], as[y]));
            }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

Explanation Atms::explain_nogood(EnvId env) {
    QM_REQUIRE(!is_consistent(env), "explain_nogood: the environment is consistent");
    std::vector<std::pair<NodeId, AssumptionId>> scratch;
    std::vector<AtMostOneUse> used;
    auto out = derive_explanation(justs_, nodes_.size(), derivation_base(envs_[env], scratch), contradiction_, &used);
    QM_REQUIRE(out.has_value(), "internal: nogood has no derivation of the contradiction");
    // A constraint's step becomes its pair's own clause, as the pairwise nogood would be. The pair
    // is itself an at-most-one clause (of two members), so that later derivations count its members
    // only as assumptions, as the constraint does; a record of two members is its own pair.
    for (const AtMostOneUse& u : used) {
        const JustId record = out->steps[u.step];
        if (justs_[record.value].antecedents.size() == 2) continue;
        const auto key = std::tuple(record.value, u.first.value, u.second.value);
        auto it = pair_justs_.find(key);
        if (it == pair_justs_.end()) {
            const JustId j{static_cast<std::uint32_t>(justs_.size())};
            justs_.push_back(Justification{justs_[record.value].informant, {u.first, u.second}, contradiction_,
                                           Justification::Kind::at_most_one});
            it = pair_justs_.emplace(key, j).first;
        }
        out->steps[u.step] = it->second;
    }
    return *out;
}
}  // namespace qm::atms
