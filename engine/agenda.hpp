// engine/agenda.hpp
// Provides:   Agenda, the queue of rule instances found by the matcher and not yet executed, with the
//             set of every instance ever queued so that a rule never fires twice on the same binding
//             (for a non-monotonic rule: the same binding in the same context). Urgent instances
//             (those of rules concluding `false`) run before all others, FIFO within each class:
//             a contradiction found early empties labels before facts derived in the doomed
//             environments can wake further rules (otherwise e.g. arithmetic propagation over
//             conflicting values need not terminate).
// Ownership:  owns its queued instances and the keys of every instance ever queued.
// Invariants: an instance key is pushed at most once over the agenda's lifetime.
// Knows nothing of the ATMS.
#pragma once
#include "engine/binding.hpp"
#include "engine/compiled_rule.hpp"
#include "engine/fact.hpp"
#include <cstdint>
#include <deque>
#include <optional>
#include <span>
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
    // The same, but the instance is made (its binding and antecedents copied) only if it is new:
    // the matcher finds the same binding again and again, and most of its matches are repeats.
    bool push(RuleId rule, const Binding& binding, std::span<const FactId> antecedents, std::optional<std::uint32_t> context,
              bool urgent = false);
    [[nodiscard]] bool empty() const noexcept { return queue_.empty() && urgent_.empty(); }
    // Pre: !empty().
    RuleInstance pop();
    [[nodiscard]] std::size_t instances_ever() const noexcept { return keys_.size(); }

private:
    // The set of keys ever queued: each key (rule, context, one word per slot) is kept in one pool
    // of words, found through an open-addressed table of key indexes (the pattern of
    // fact_store.cpp): a lookup, hit or miss, allocates nothing.
    struct Key {
        std::uint32_t offset = 0;  // into words_
        std::uint32_t size = 0;
        std::uint32_t hash = 0;
    };
    // Adds the key (rule, context, binding) unless it is there; returns whether it was added.
    bool insert(RuleId rule, const Binding& binding, std::optional<std::uint32_t> context);
    void grow();
    std::deque<RuleInstance> queue_;
    std::deque<RuleInstance> urgent_;
    std::vector<std::uint32_t> words_;  // every key's words, one key after another
    std::vector<Key> keys_;
    std::vector<std::uint32_t> slots_;  // 0: empty, else 1 + an index into keys_; a power of two, at most half full
};
}  // namespace qm::engine
