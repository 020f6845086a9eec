// atms/environment.hpp
// Provides:   Environment, a set of assumptions stored as a bitset over AssumptionId.
// Ownership:  a value type; canonical copies are interned by EnvironmentTable (environment_table.hpp).
// Invariants: words_ has no trailing zero word, so the defaulted == is set equality and the hash
//             of equal sets is equal.
// Knows nothing of rules, facts or mechanics: an assumption is only an id.
#pragma once
#include "atms/ids.hpp"
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace qm::atms {
class Environment {
public:
    Environment() = default;  // the empty environment {}
    // Builds the set {as...}; duplicates are allowed and collapse.
    [[nodiscard]] static Environment of(std::span<const AssumptionId> as);
    // Builds a set from raw words (bit i <=> AssumptionId{i}); trailing zero words are dropped.
    [[nodiscard]] static Environment from_words(std::span<const std::uint64_t> words);
    // The same for a window of words starting at word `first_word` (all words before it zero).
    [[nodiscard]] static Environment from_words(std::span<const std::uint64_t> words, std::size_t first_word);
    // Index of the first non-zero word (words().size() for the empty set).
    [[nodiscard]] std::size_t first_word() const noexcept;

    [[nodiscard]] bool contains(AssumptionId a) const noexcept;
    [[nodiscard]] bool subset_of(const Environment& other) const noexcept;
    [[nodiscard]] bool empty() const noexcept { return words_.empty(); }
    [[nodiscard]] std::uint32_t size() const noexcept;  // number of assumptions
    [[nodiscard]] Environment with(AssumptionId a) const;
    friend Environment join(const Environment& x, const Environment& y);  // x ∪ y
    // The assumptions in increasing id order.
    [[nodiscard]] std::vector<AssumptionId> assumptions() const;
    // The lowest assumption. Pre: !empty().
    [[nodiscard]] AssumptionId first() const;
    [[nodiscard]] std::span<const std::uint64_t> words() const noexcept { return words_; }
    [[nodiscard]] std::size_t hash() const noexcept;
    friend bool operator==(const Environment&, const Environment&) = default;

private:
    void trim() noexcept;
    std::vector<std::uint64_t> words_;  // bit i set <=> AssumptionId{i} is in the set
};

// True iff the set given by `words` is a subset of `of` (both raw bitsets, any lengths).
[[nodiscard]] bool words_subset(std::span<const std::uint64_t> words,
                                std::span<const std::uint64_t> of) noexcept;
// The same when `of` is a window: of[i] is word of_first + i, every word outside the window zero.
[[nodiscard]] bool words_subset(std::span<const std::uint64_t> words, std::span<const std::uint64_t> of,
                                std::size_t of_first) noexcept;

[[nodiscard]] Environment join(const Environment& x, const Environment& y);

struct EnvironmentHash {
    std::size_t operator()(const Environment& e) const noexcept { return e.hash(); }
};
}  // namespace qm::atms
