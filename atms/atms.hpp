// atms/atms.hpp
// Provides:   Atms, an assumption-based truth maintenance system (de Kleer 1986, "An assumption-based
//             TMS"; the design of BPS atms.lisp, typed). Nodes carry an opaque DatumId; Horn clause
//             justifications carry an opaque InformantId. Queries: labels, consistency, minimal
//             nogoods, interpretations over choice sets, explanations. Queries built on these have
//             headers of their own: preferred_interpretations.hpp, case_refutation.hpp (refutation
//             by case analysis over choice sets), choice_set_groups.hpp (choice sets that share
//             nogoods).
// Ownership:  an Atms owns its nodes, assumptions, environments and justifications; all are referred
//             to by dense ids valid for the lifetime of the Atms. Nothing is ever removed. There is no
//             global state: any number of Atms objects can coexist. Not thread safe. References
//             returned by env(), label() and justification() stay valid only until the next call
//             that adds nodes, justifications, nogoods or environments (the stores may grow): copy
//             what must outlive such a call.
// Invariants: after every public call returns, each node's label is
//               sound      every label env E derives the node from E and the premises,
//               consistent no label env is nogood,
//               minimal    no label env is a superset of another,
//               complete   every consistent env deriving the node is a superset of a label env;
//             the contradiction node's label is always empty (its would-be envs become nogoods).
// Reentrancy: consumers never run during propagation; their events are queued and delivered, FIFO,
//             just before the public call that caused them returns. They may call any member
//             (including justify); events they cause are appended to the same queue. A consumer
//             removed by another's callback gets no further event.
// Errors:     every violated `Pre:` throws qm::InternalError (QM_REQUIRE), never UB.
// Knows nothing of rules, patterns or mechanics.
#pragma once
#include "atms/consumer.hpp"
#include "atms/environment.hpp"
#include "atms/environment_table.hpp"
#include "atms/explanation.hpp"
#include "atms/fwd.hpp"
#include "atms/ids.hpp"
#include "atms/justification.hpp"
#include "atms/label.hpp"
#include "atms/nogood_database.hpp"
#include <cstddef>
#include <deque>
#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <tuple>
#include <vector>

namespace qm::atms {
class Atms {
public:
    Atms();
    ~Atms();
    Atms(const Atms&) = delete;
    Atms& operator=(const Atms&) = delete;

    // ---- building -------------------------------------------------------------------------------
    NodeId add_node(DatumId d);        // a derived node; empty label until justified
    NodeId add_premise(DatumId d);     // holds in {}: label {{}}
    NodeId add_assumption(DatumId d);  // label {{a}} for a fresh assumption a
    // Records the Horn clause antecedents -> consequent and propagates labels. Justifying an
    // assumption node is allowed (de Kleer); justifying the contradiction node records nogoods.
    // Duplicate antecedents are ignored. An empty antecedent list makes the consequent true.
    // Pre: all ids valid; consequent is not a premise; no antecedent is the contradiction node.
    JustId justify(InformantId why, std::span<const NodeId> antecedents, NodeId consequent);
    JustId justify(InformantId why, std::initializer_list<NodeId> antecedents, NodeId consequent) {
        return justify(why, std::span<const NodeId>(antecedents.begin(), antecedents.size()), consequent);
    }
    // = justify(why, antecedents, contradiction()): the antecedents cannot hold together.
    JustId add_nogood(InformantId why, std::span<const NodeId> antecedents);
    JustId add_nogood(InformantId why, std::initializer_list<NodeId> antecedents) {
        return add_nogood(why, std::span<const NodeId>(antecedents.begin(), antecedents.size()));
    }
    // No two of `members` hold together: every environment holding two of them is nogood. This is
    // the at-most-one half of an `exactly one` choice set (the other half is the one pick per set
    // of interpretations) kept as ONE constraint, not as the S(S-1)/2 nogoods {a, b} that
    // add_nogood of every two member nodes would make: declaring it costs what the members' envs
    // hold, and consistency tests cost what the tested environment holds. Its pairs are still
    // nogoods to every query: minimal_nogoods() lists them, explain_nogood() explains one by a
    // clause a, b -> contradiction with informant `why` (an at_most_one clause of those two members,
    // recorded on first request; a constraint of two members is its own pair). The
    // constraint is over the assumptions, so it differs from those pairwise nogoods only where a
    // member's assumption node is itself justified (it then does not extend to the other
    // environments deriving that node). Duplicates collapse; fewer than two distinct members
    // constrain nothing. Returns its record, a Justification of kind at_most_one (justification.hpp)
    // whose antecedents are the members' nodes in the order given. Pre: ids valid.
    JustId add_at_most_one(InformantId why, std::span<const AssumptionId> members);

    // ---- nodes ----------------------------------------------------------------------------------
    [[nodiscard]] NodeId contradiction() const noexcept { return contradiction_; }
    [[nodiscard]] std::size_t node_count() const noexcept { return nodes_.size(); }
    [[nodiscard]] std::size_t assumption_count() const noexcept { return assumption_nodes_.size(); }
    [[nodiscard]] std::size_t justification_count() const noexcept { return justs_.size(); }
    [[nodiscard]] std::size_t environment_count() const noexcept { return envs_.size(); }
    // At most `n` environments (none: no limit, the default): interning one more throws
    // qm::LimitReached (qm/limit_reached.hpp), after which this Atms must only be destroyed.
    void limit_environments(std::optional<std::size_t> n) { envs_.set_limit(n); }
    // Pre (all node queries): the id was issued by this Atms.
    [[nodiscard]] DatumId datum(NodeId n) const;
    [[nodiscard]] bool is_premise(NodeId n) const;
    [[nodiscard]] std::optional<AssumptionId> assumption_of(NodeId n) const;
    // Pre: a was issued by this Atms.
    [[nodiscard]] NodeId node_of(AssumptionId a) const;
    [[nodiscard]] const std::vector<JustId>& justifications(NodeId n) const;  // those concluding n
    [[nodiscard]] const Justification& justification(JustId j) const;        // Pre: j valid

    // ---- labels and consistency -----------------------------------------------------------------
    // The label: minimal consistent environments in which n holds, sorted by EnvId.
    [[nodiscard]] const std::vector<EnvId>& label(NodeId n) const;
    // Some label env is a subset of env, and env is consistent. Pre: n, env valid.
    [[nodiscard]] bool holds_in(NodeId n, EnvId env) const;
    [[nodiscard]] bool is_true(NodeId n) const;   // holds in {}
    [[nodiscard]] bool is_in(NodeId n) const;     // holds in some consistent env (label non-empty)
    [[nodiscard]] bool is_consistent(EnvId env) const;  // no nogood is a subset. Pre: env valid
    // The interned environment of a set of assumptions (duplicates collapse). Pre: ids valid.
    EnvId environment(std::span<const AssumptionId> as);
    EnvId environment(std::initializer_list<AssumptionId> as) {
        return environment(std::span<const AssumptionId>(as.begin(), as.size()));
    }
    [[nodiscard]] EnvId empty_environment() const noexcept { return empty_env_; }
    [[nodiscard]] const Environment& env(EnvId e) const;  // Pre: e valid
    // Every minimal nogood, sorted by EnvId: the stated ones and the pairs {a, b} of two members of
    // an at-most-one constraint that are each consistent. Interns the pairs not interned yet, so it
    // costs O(S^2) for a constraint of S members: minimal_nogoods_within(e) asks about one
    // environment, stated_nogoods() and at_most_one_nogoods(j) about the parts.
    std::vector<EnvId> minimal_nogoods();
    // The minimal nogoods that are subsets of e, sorted by EnvId (interns the pairs among them).
    // Costs what e holds, not what the database holds.
    std::vector<EnvId> minimal_nogoods_within(const Environment& e);
    // The minimal nogoods that are not pairs of an at-most-one constraint, sorted by EnvId.
    [[nodiscard]] std::vector<EnvId> stated_nogoods() const;
    // The minimal nogoods that constraint j (add_at_most_one's record) makes, interned, in member
    // order (a before b as given; pairs listed by the first, then the second). Pre: j is one.
    std::vector<EnvId> at_most_one_nogoods(JustId j);

    // ---- interpretations (interpretations.hpp has the algorithm) --------------------------------
    // All consistent environments base + exactly one assumption from each choice set, found by
    // backtracking with nogood pruning (never the full product), in lexicographic order of the
    // choices (first set varies slowest). No choice sets: {base} if base is consistent. An empty
    // set: none. A base that holds a member of a set keeps that member as the set's pick, and a
    // base holding two members of one set has no interpretation (exactly one per set).
    // Pre: ids valid; no assumption occurs in two sets.
    std::vector<EnvId> interpretations(std::span<const std::vector<AssumptionId>> choice_sets);
    std::vector<EnvId> interpretations(std::span<const std::vector<AssumptionId>> choice_sets, EnvId base);
    // Streaming form: calls visit(env) for each interpretation without interning it (env is valid
    // during the call only: copy it to keep it); visit returns false to stop. Returns the number
    // visited. Same preconditions.
    std::size_t for_each_interpretation(std::span<const std::vector<AssumptionId>> choice_sets, EnvId base,
                                        const std::function<bool(const Environment&)>& visit) const;

    // ---- explanations ---------------------------------------------------------------------------
    // A well-founded justification tree deriving n from premises and assumptions of env.
    // Pre: holds_in(n, env).
    [[nodiscard]] Explanation explain(NodeId n, EnvId env) const;
    // The justifications deriving the contradiction from the assumptions of env. Where an
    // at-most-one constraint does, the step is the clause of the pair of its members that env holds
    // (antecedents the two member nodes in the constraint's order; recorded on first use, in no
    // node's lists: see add_at_most_one). Pre: !is_consistent(env).
    [[nodiscard]] Explanation explain_nogood(EnvId env);

    // ---- consumers ------------------------------------------------------------------------------
    // Pre: c is not already registered. c must outlive this Atms or be removed first.
    void add_consumer(Consumer& c);
    void remove_consumer(Consumer& c);  // Pre: c is registered

private:
    struct NodeData {
        DatumId datum;
        std::optional<AssumptionId> assumption;
        bool premise = false;
        std::vector<JustId> justifications;  // concluding this node
        std::vector<JustId> consequences;    // having this node as an antecedent
    };
    struct Pending {  // a propagation work item (the BPS `propagate` call, made iterative)
        JustId just;
        std::optional<NodeId> changed;  // the antecedent whose label grew, if any
        std::vector<EnvId> envs;        // its new label envs
    };
    struct Event {
        enum class Kind { label_nonempty, nogood } kind;
        std::uint32_t id;
    };

    NodeId new_node(DatumId d);
    void require_node(NodeId n) const;
    void require_env(EnvId e) const;
    void propagate_all();
    void propagate(const Pending& p);
    void update(std::vector<EnvId> envs, NodeId consequent, JustId just);
    void new_nogood(EnvId env);
    void retire_env(EnvId e);  // marks e nogood and drops it from the labels holding it
    [[nodiscard]] std::vector<std::pair<AssumptionId, AssumptionId>> live_pairs(JustId j) const;
    EnvId pair_env(AssumptionId a, AssumptionId b);
    void run_events();
    [[nodiscard]] DerivationBase derivation_base(const Environment& e,
                                                 std::vector<std::pair<NodeId, AssumptionId>>& scratch) const;

    EnvironmentTable envs_;
    NogoodDatabase nogoods_;
    IdVector<NodeId, NodeData> nodes_;
    IdVector<NodeId, Label> labels_;
    std::vector<Justification> justs_;  // indexed by JustId
    IdVector<AssumptionId, NodeId> assumption_nodes_;
    std::vector<NodeId> premises_;
    NodeId contradiction_{};
    EnvId empty_env_{};
    std::deque<Pending> work_;
    std::deque<Event> events_;
    std::vector<Consumer*> consumers_;
    bool running_events_ = false;
    std::unique_ptr<detail::WeaveScratch> scratch_;  // reused by every weave (label_update.hpp)
    std::vector<JustId> at_most_one_;  // the records of add_at_most_one, in order
    // (record, first node, second node) -> the pair's justification, once explained
    std::map<std::tuple<std::uint32_t, std::uint32_t, std::uint32_t>, JustId> pair_justs_;
};
}  // namespace qm::atms
