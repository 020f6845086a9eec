// atms/explanation.hpp
// Provides:   Explanation, a well-founded justification tree (BPS explain-node) flattened into
//             derivation order, and derive_explanation(), which computes one by forward chaining.
// Ownership:  a plain value returned to the caller.
// Invariants: every antecedent of steps[i] is a premise in `premises`, an assumption node whose
//             assumption is in `assumptions`, or the consequent of some steps[j] with j < i; so the
//             tree has no cycles, and replaying steps from the leaves derives `node`. The last step
//             derives `node` unless `node` is itself a leaf (a premise, or an assumption of the env).
//             Only justifications needed for `node` are listed.
// Knows nothing of rules: an informant is an opaque id.
#pragma once
#include "atms/fwd.hpp"
#include "atms/ids.hpp"
#include <optional>
#include <span>
#include <vector>

namespace qm::atms {
struct Explanation {
    NodeId node;                           // what is explained (the contradiction for a nogood)
    std::vector<JustId> steps;             // derivation order, leaves first
    std::vector<NodeId> premises;          // premise nodes used, increasing id
    std::vector<AssumptionId> assumptions; // assumptions used, increasing id (a subset of the env)
};

// Leaf facts for derive_explanation: which nodes hold without a justification.
struct DerivationBase {
    std::span<const NodeId> premises;
    // (node, assumption) for every assumption node whose assumption is in the environment.
    std::span<const std::pair<NodeId, AssumptionId>> assumptions;
};

// A step of kind at_most_one in a derivation: the two of its antecedents it was used with (in the
// clause's antecedent order), which hold as assumptions of the environment.
struct AtMostOneUse {
    std::size_t step;  // index into Explanation::steps
    NodeId first, second;
};

// Forward chains over `justs` (indexed by JustId) from the base, ignoring consistency, and returns
// the explanation of `goal`, or nullopt if goal is not derivable. O(total antecedents). A clause of
// kind at_most_one derives its consequent once two of its antecedents are in the base as
// assumptions (its constraint is over assumptions: a member node derived otherwise does not count);
// each such step used is reported in `used`, if given.
// Pre: every node id in justs and base is < node_count.
[[nodiscard]] std::optional<Explanation> derive_explanation(std::span<const Justification> justs,
                                                            std::size_t node_count,
                                                            const DerivationBase& base, NodeId goal,
                                                            std::vector<AtMostOneUse>* used = nullptr);
}  // namespace qm::atms
