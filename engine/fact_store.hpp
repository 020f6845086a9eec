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
// Knows nothing of the ATMS or of rules.
#pragma once
#include "engine/fact.hpp"
#include <cstdint>
#include <optional>
#include <span>
#include <unordered_map>
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
    [[nodiscard]] std::span<const FactId> active_with_predicate(ValueId predicate) const;
    [[nodiscard]] std::span<const FactId> active_with_argument(ValueId predicate, std::uint32_t position,
                                                               ValueId value) const;

private:
    struct KeyHash {
        std::size_t operator()(const std::vector<std::uint32_t>& k) const noexcept;
    };
    static std::vector<std::uint32_t> key(ValueId predicate, std::span<const ValueId> args);
    static std::uint64_t arg_key(ValueId predicate, std::uint32_t position, ValueId value);

    IdVector<FactId, Fact> facts_;
    IdVector<FactId, std::uint8_t> active_;  // 1 = active (not bool: IdVector returns references)
    std::unordered_map<std::vector<std::uint32_t>, FactId, KeyHash> by_key_;
    std::unordered_map<std::uint32_t, std::vector<FactId>> all_by_predicate_;
    std::unordered_map<std::uint64_t, std::vector<FactId>> all_by_argument_;
    std::unordered_map<std::uint32_t, std::vector<FactId>> active_by_predicate_;
    std::unordered_map<std::uint64_t, std::vector<FactId>> active_by_argument_;
};
}  // namespace qm::engine
