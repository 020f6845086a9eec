// atms/atms.cpp: the Atms facade. Label propagation follows de Kleer 1986 section 4 and BPS
// atms.lisp (justify-node, propagate, update, weave, new-nogood), with the recursion of
// `propagate` replaced by a FIFO work list so long derivation chains cannot overflow the stack.
#include "atms/atms.hpp"

#include "atms/interpretations.hpp"
#include "atms/label_update.hpp"
#include "qm/assert.hpp"
#include <algorithm>
#include <unordered_set>
#include <utility>

namespace qm::atms {

Atms::Atms() : scratch_(std::make_unique<detail::WeaveScratch>()) {
    empty_env_ = envs_.intern(Environment{}, nogoods_);
    contradiction_ = new_node(DatumId{});
}

Atms::~Atms() = default;

NodeId Atms::new_node(DatumId d) {
    const NodeId n = nodes_.push_back(NodeData{d, std::nullopt, false, {}, {}});
    labels_.push_back(Label{});
    return n;
}

void Atms::require_node(NodeId n) const { QM_REQUIRE(nodes_.contains(n), "unknown node id"); }
void Atms::require_env(EnvId e) const { QM_REQUIRE(envs_.contains(e), "unknown environment id"); }

NodeId Atms::add_node(DatumId d) { return new_node(d); }

NodeId Atms::add_premise(DatumId d) {
    const NodeId n = new_node(d);
    nodes_[n].premise = true;
    premises_.push_back(n);
    // {} is consistent unless {} itself was declared nogood, in which case nothing holds.
    if (!envs_.is_nogood(empty_env_)) {
        labels_[n].push_back(empty_env_);
        envs_.add_node(empty_env_, n);
        events_.push_back(Event{Event::Kind::label_nonempty, n.value});
    }
    run_events();
    return n;
}

NodeId Atms::add_assumption(DatumId d) {
    const NodeId n = new_node(d);
    const AssumptionId a = assumption_nodes_.push_back(n);
    nodes_[n].assumption = a;
    const AssumptionId as[] = {a};
    const EnvId e = envs_.intern(Environment::of(as), nogoods_);
    if (!envs_.is_nogood(e)) {
        labels_[n].push_back(e);
        envs_.add_node(e, n);
        events_.push_back(Event{Event::Kind::label_nonempty, n.value});
    }
    run_events();
    return n;
}

JustId Atms::justify(InformantId why, std::span<const NodeId> antecedents, NodeId consequent) {
    require_node(consequent);
    QM_REQUIRE(!nodes_[consequent].premise, "a premise cannot be the consequent of a justification");
    std::vector<NodeId> ants;
    ants.reserve(antecedents.size());
    for (NodeId a : antecedents) {
        require_node(a);
        QM_REQUIRE(a != contradiction_, "the contradiction node cannot be an antecedent");
        if (std::find(ants.begin(), ants.end(), a) == ants.end()) ants.push_back(a);
    }
    const JustId j{static_cast<std::uint32_t>(justs_.size())};
    for (NodeId a : ants) nodes_[a].consequences.push_back(j);
    justs_.push_back(Justification{why, std::move(ants), consequent});
    nodes_[consequent].justifications.push_back(j);
    // BPS justify-node: propagate with the empty environment as the "changed" label.
    work_.push_back(Pending{j, std::nullopt, {empty_env_}});
    propagate_all();
    run_events();
    return j;
}

JustId Atms::add_nogood(InformantId why, std::span<const NodeId> antecedents) {
    return justify(why, antecedents, contradiction_);
}

void Atms::propagate_all() {
    while (!work_.empty()) {
        Pending p = std::move(work_.front());
        work_.pop_front();
        propagate(p);
    }
}

void Atms::propagate(const Pending& p) {
    const Justification& just = justs_[p.just.value];
    std::vector<EnvId> envs;
    if (p.changed) {
        // Envs removed from the antecedent's label since this item was queued were either
        // subsumed (their subset is queued too) or became nogood: both are skipped.
        const Label& current = labels_[*p.changed];
        for (EnvId e : p.envs)
            if (std::binary_search(current.begin(), current.end(), e)) envs.push_back(e);
    } else {
        envs = p.envs;
    }
    std::vector<const Label*> others;
    others.reserve(just.antecedents.size());
    for (NodeId a : just.antecedents)
        if (!p.changed || a != *p.changed) others.push_back(&labels_[a]);
    envs = weave(envs_, nogoods_, envs, others, *scratch_);
    if (envs.empty()) return;
    update(std::move(envs), just.consequent, p.just);
}

void Atms::update(std::vector<EnvId> envs, NodeId consequent, JustId /*just*/) {
    if (consequent == contradiction_) {
        for (EnvId e : envs) new_nogood(e);
        return;
    }
    Label& label = labels_[consequent];
    const bool was_empty = label.empty();
    std::vector<EnvId> added;
    for (EnvId e : envs) {
        if (envs_.is_nogood(e)) continue;  // may have become nogood while envs were formed
        if (label_add_minimal(label, e, envs_)) {
            envs_.add_node(e, consequent);
            added.push_back(e);
        }
    }
    // label_add_minimal may have removed an env added earlier in this loop.
    std::erase_if(added, [&](EnvId e) { return !std::binary_search(label.begin(), label.end(), e); });
    if (added.empty()) return;
    if (was_empty) events_.push_back(Event{Event::Kind::label_nonempty, consequent.value});
    for (JustId j : nodes_[consequent].consequences) work_.push_back(Pending{j, consequent, added});
}

void Atms::run_events() {
    if (running_events_) return;  // the outer drain loop will deliver them
    running_events_ = true;
    struct Reset {
        bool& flag;
        ~Reset() { flag = false; }
    } reset{running_events_};
    // A consumer that a callback removed (and perhaps destroyed) gets no further event.
    auto still_registered = [&](Consumer* c) { return std::find(consumers_.begin(), consumers_.end(), c) != consumers_.end(); };
    while (!events_.empty()) {
        const Event ev = events_.front();
        events_.pop_front();
        const std::vector<Consumer*> consumers = consumers_;  // callbacks may (un)register
        if (ev.kind == Event::Kind::label_nonempty) {
            const NodeId n{ev.id};
            if (labels_[n].empty()) continue;  // emptied by a nogood before delivery
            for (Consumer* c : consumers)
                if (still_registered(c)) c->label_became_nonempty(n);
        } else {
            for (Consumer* c : consumers)
                if (still_registered(c)) c->environment_became_nogood(EnvId{ev.id});
        }
    }
}

// ---- queries ----------------------------------------------------------------------------------

DatumId Atms::datum(NodeId n) const {
    require_node(n);
    return nodes_[n].datum;
}
bool Atms::is_premise(NodeId n) const {
    require_node(n);
    return nodes_[n].premise;
}
std::optional<AssumptionId> Atms::assumption_of(NodeId n) const {
    require_node(n);
    return nodes_[n].assumption;
}
NodeId Atms::node_of(AssumptionId a) const {
    QM_REQUIRE(assumption_nodes_.contains(a), "unknown assumption id");
    return assumption_nodes_[a];
}
const std::vector<JustId>& Atms::justifications(NodeId n) const {
    require_node(n);
    return nodes_[n].justifications;
}
const Justification& Atms::justification(JustId j) const {
    QM_REQUIRE(j.value < justs_.size(), "unknown justification id");
    return justs_[j.value];
}
const std::vector<EnvId>& Atms::label(NodeId n) const {
    require_node(n);
    return labels_[n];
}
bool Atms::holds_in(NodeId n, EnvId env) const {
    require_node(n);
    require_env(env);
    return !envs_.is_nogood(env) && label_subsumes(labels_[n], env, envs_);
}
bool Atms::is_true(NodeId n) const { return holds_in(n, empty_env_); }
bool Atms::is_in(NodeId n) const { return !label(n).empty(); }
bool Atms::is_consistent(EnvId env) const {
    require_env(env);
    return !envs_.is_nogood(env);
}
EnvId Atms::environment(std::span<const AssumptionId> as) {
    for (AssumptionId a : as) QM_REQUIRE(assumption_nodes_.contains(a), "unknown assumption id");
    return envs_.intern(Environment::of(as), nogoods_);
}
const Environment& Atms::env(EnvId e) const {
    require_env(e);
    return envs_[e];
}

// ---- interpretations --------------------------------------------------------------------------

std::size_t Atms::for_each_interpretation(std::span<const std::vector<AssumptionId>> choice_sets, EnvId base,
                                          const std::function<bool(const Environment&)>& visit) const {
    require_env(base);
    // The preconditions on the sets (known ids, disjoint) are checked there. A copy of the base: a
    // visitor may intern environments (interpretations() does), which moves the table's.
    const Environment base_env = envs_[base];
    return enumerate_interpretations(nogoods_, assumption_nodes_.size(), choice_sets, base_env, visit);
}

std::vector<EnvId> Atms::interpretations(std::span<const std::vector<AssumptionId>> choice_sets, EnvId base) {
    // Each interpretation is interned as it is found, so that the environment limit
    // (limit_environments) bounds the enumeration: collecting them first let 40 binary choice
    // sets fill the memory before the limit was consulted.
    std::vector<EnvId> out;
    // A choice repeated within a set gives the same env twice: keep the first (checked only then).
    const bool repeats = std::any_of(choice_sets.begin(), choice_sets.end(), [](const std::vector<AssumptionId>& set) {
        std::vector<AssumptionId> sorted = set;
        std::sort(sorted.begin(), sorted.end());
        return std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end();
    });
    std::unordered_set<EnvId> seen;
    for_each_interpretation(choice_sets, base, [&](const Environment& e) {
        const EnvId id = envs_.intern_consistent(e, nogoods_);  // found consistent
        if (!repeats || seen.insert(id).second) out.push_back(id);
        return true;
    });
    return out;
}

std::vector<EnvId> Atms::interpretations(std::span<const std::vector<AssumptionId>> choice_sets) {
    return interpretations(choice_sets, empty_env_);
}

// ---- explanations -----------------------------------------------------------------------------

DerivationBase Atms::derivation_base(const Environment& e,
                                     std::vector<std::pair<NodeId, AssumptionId>>& scratch) const {
    scratch.clear();
    for (AssumptionId a : e.assumptions())
        if (assumption_nodes_.contains(a)) scratch.emplace_back(assumption_nodes_[a], a);
    return DerivationBase{premises_, scratch};
}

Explanation Atms::explain(NodeId n, EnvId env) const {
    QM_REQUIRE(holds_in(n, env), "explain: the node does not hold in the environment");
    std::vector<std::pair<NodeId, AssumptionId>> scratch;
    auto out = derive_explanation(justs_, nodes_.size(), derivation_base(envs_[env], scratch), n);
    QM_ASSERT(out.has_value(), "label unsound: node in label but not derivable");
    QM_REQUIRE(out.has_value(), "internal: node holds but has no derivation");
    return *out;
}

// ---- consumers --------------------------------------------------------------------------------

void Atms::add_consumer(Consumer& c) {
    QM_REQUIRE(std::find(consumers_.begin(), consumers_.end(), &c) == consumers_.end(),
               "consumer already registered");
    consumers_.push_back(&c);
}

void Atms::remove_consumer(Consumer& c) {
    auto it = std::find(consumers_.begin(), consumers_.end(), &c);
    QM_REQUIRE(it != consumers_.end(), "consumer not registered");
    consumers_.erase(it);
}
}  // namespace qm::atms
