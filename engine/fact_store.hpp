// engine/fact_store.hpp
// Provides:   FactStore, the interned facts with the indexes the matcher uses: facts by predicate
//             and by (predicate, argument position, value), each for all facts (the closed world of
//             `not` and aggregates) and for the active ones (matching).
// Ownership:  owns every Fact; FactIds stay valid for the store's lifetime; nothing is removed.
// Invariants: equal (predicate, args) always map to the same FactId. A fact is "active" once the
//             engine has seen it hold in some consistent environment; only active facts are indexed
//             for matching, in activation order (so matching order is deterministic). Every list of an
//             argument index is the subsequence of its predicate's list (all or active) holding that
//             value at that position, in the same order.
// Cost:       a state's engine interns and indexes thousands of facts and is then dropped
//             (docs/perf/envision.md), so the tables are open-addressed arrays: a lookup allocates
//             nothing, and a new fact allocates only its arguments and the growth of its lists.
// Knows nothing of the ATMS or of rules.
#pragma once
#include "engine/fact.hpp"
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace qm::engine {
class FactStore {
public:
    // Returns the fact's id and whether it was new.
    std::pair<FactId, bool> intern(ValueId predicate, std::span<const ValueId> args);
    [[nodiscard]] std::optional<FactId> find(ValueId predicate, std::span<const ValueId> args) const;
    // Pre: f issued by this store.
    [[nodiscard]] const Fact& fact(FactId f) const;
    [[nodiscard]] std::size_t size() const noexcept { return facts_.size(); }
    // All facts of a predicate (active or not), in creation order.
    [[nodiscard]] std::span<const FactId> with_predicate(ValueId predicate) const;
    // The facts of with_predicate(predicate) whose argument at position is value, in that order.
    [[nodiscard]] std::span<const FactId> with_argument(ValueId predicate, std::uint32_t position, ValueId value) const;

    // Marks f active and indexes it. Returns false if it already was. Pre: f valid.
    bool activate(FactId f);
    [[nodiscard]] bool is_active(FactId f) const;
    // The number of facts activated before f: every active list is in this order. Pre: f active.
    [[nodiscard]] std::uint32_t activation_rank(FactId f) const;
    [[nodiscard]] std::span<const FactId> active_with_predicate(ValueId predicate) const;
    [[nodiscard]] std::span<const FactId> active_with_argument(ValueId predicate, std::uint32_t position,
                                                               ValueId value) const;

private:
    // Lists of facts by a 64-bit key (a predicate, or a predicate, position and value: list_key),
    // open-addressed with linear probing; a key's list never moves to another key.
    class Lists {
    public:
        [[nodiscard]] std::span<const FactId> find(std::uint64_t key) const;
        void append(std::uint64_t key, FactId f);

    private:
        void grow();
        std::vector<std::uint64_t> keys_;    // per slot
        std::vector<std::uint32_t> slots_;   // per slot: index into lists_ plus one; 0 = empty
        std::vector<std::vector<FactId>> lists_;
    };
    static std::uint64_t list_key(ValueId predicate, std::uint32_t position, ValueId value);
    static std::uint64_t predicate_key(ValueId predicate);
    static std::uint32_t hash(ValueId predicate, std::span<const ValueId> args);
    // The slot of (predicate, args) in by_key_: its fact's slot, or the empty slot where it goes.
    [[nodiscard]] std::size_t slot_of(ValueId predicate, std::span<const ValueId> args, std::uint32_t h) const;
    void grow_keys();
    void index(Lists& lists, FactId f);

    IdVector<FactId, Fact> facts_;
    IdVector<FactId, std::uint32_t> active_;  // 0 = inactive, else the activation rank plus one
    std::uint32_t active_count_ = 0;
    IdVector<FactId, std::uint32_t> hash_;   // hash(predicate, args) of each fact
    std::vector<std::uint32_t> by_key_;      // open-addressed: FactId plus one; 0 = empty
    Lists all_, active_lists_;
};
}  // namespace qm::engine
