// engine/agenda.hpp
// Provides:   Agenda, the queue of rule instances found by the matcher and not yet executed, with the
//             set of every instance ever queued so that a rule never fires twice on the same binding
//             (for a non-monotonic rule: the same binding in the same context). Urgent instances
//             (those of rules concluding `false`) run before all others, FIFO within each class:
//             a contradiction found early empties labels before facts derived in the doomed
//             environments can wake further rules (otherwise e.g. arithmetic propagation over
//             conflicting values need not terminate).
// Ownership:  owns its queued instances.
// Invariants: an instance key is pushed at most once over the agenda's lifetime.
// Knows nothing of the ATMS.
#pragma once
#include "engine/binding.hpp"
#include "engine/compiled_rule.hpp"
#include "engine/fact.hpp"
#include <cstdint>
#include <deque>
#include <optional>
#include <unordered_set>
#include <vector>

namespace qm::engine {
struct RuleInstance {
    RuleId rule;
    Binding binding;
    std::vector<FactId> antecedents;
    std::optional<std::uint32_t> context;
};

class Agenda {
public:
    // Queues the instance unless one with the same rule, binding and context was ever queued.
    // Returns whether it was queued.
    bool push(RuleInstance instance, bool urgent = false);
    [[nodiscard]] bool empty() const noexcept { return queue_.empty() && urgent_.empty(); }
    // Pre: !empty().
    RuleInstance pop();
    [[nodiscard]] std::size_t instances_ever() const noexcept { return seen_.size(); }

private:
    struct KeyHash {
        std::size_t operator()(const std::vector<std::uint32_t>& k) const noexcept;
    };
    std::deque<RuleInstance> queue_;
    std::deque<RuleInstance> urgent_;
    std::unordered_set<std::vector<std::uint32_t>, KeyHash> seen_;
};
}  // namespace qm::engine
