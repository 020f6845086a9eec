// atms/environment.hpp
// Provides:   Environment, a set of assumptions stored as a compact bitset over AssumptionId: only
//             the window of 64-bit words from the first to the last non-zero one is kept, with the
//             index of its first word, so a set of nearby assumptions is a word or two however many
//             assumptions the ATMS has. Free functions on raw word windows for the hot loops, and
//             SparseWords, a set given by its listed words only (weave's unions).
// Ownership:  a value type; canonical copies are interned by EnvironmentTable (environment_table.hpp).
// Invariants: words_ has no leading or trailing zero word, and first_ is 0 when words_ is empty,
//             so the defaulted == is set equality and the hash of equal sets is equal.
// Knows nothing of rules, facts or mechanics: an assumption is only an id.
#pragma once
#include "atms/ids.hpp"
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace qm::atms {
// A set given by some of its words only: words[i] is word index[i] of the set (index strictly
// increasing), every word not listed is zero (a listed word may be zero too). A set of a few
// assumptions far apart (a situation's assumption and an object's choices, say) is a few words here
// however wide its window: weave (label_update.cpp) forms its unions in this form, so their cost
// does not grow with the number of assumptions (docs/perf/alex.md, "Sparse unions in weave").
struct SparseWords {
    std::span<const std::uint64_t> words;
    std::span<const std::uint32_t> index;  // Pre: index.size() == words.size()
};

class Environment {
public:
    Environment() = default;  // the empty environment {}
    // Builds the set {as...}; duplicates are allowed and collapse.
    [[nodiscard]] static Environment of(std::span<const AssumptionId> as);
    // Builds a set from raw words (bit i <=> AssumptionId{i}); zero words at either end are dropped.
    [[nodiscard]] static Environment from_words(std::span<const std::uint64_t> words);
    // The same for a window: words[i] is word first_word + i, every word outside it zero.
    [[nodiscard]] static Environment from_words(std::span<const std::uint64_t> words, std::size_t first_word);
    // The set y (SparseWords above), as a window.
    [[nodiscard]] static Environment from_sparse(SparseWords y);
    // *this = from_words(words, first_word), reusing the storage it has (no allocation once it has
    // grown): for a loop that forms many environments one after another.
    void assign_words(std::span<const std::uint64_t> words, std::size_t first_word);

    [[nodiscard]] bool contains(AssumptionId a) const noexcept;
    [[nodiscard]] bool subset_of(const Environment& other) const noexcept;
    [[nodiscard]] bool empty() const noexcept { return words_.empty(); }
    [[nodiscard]] std::uint32_t size() const noexcept;  // number of assumptions
    [[nodiscard]] Environment with(AssumptionId a) const;
    [[nodiscard]] Environment without(AssumptionId a) const;
    void insert(AssumptionId a);  // in place: *this = with(a)
    void erase(AssumptionId a);   // in place: *this = without(a)
    friend Environment join(const Environment& x, const Environment& y);  // x ∪ y
    // The assumptions in increasing id order.
    [[nodiscard]] std::vector<AssumptionId> assumptions() const;
    // The lowest assumption. Pre: !empty().
    [[nodiscard]] AssumptionId first() const;
    // The stored window: words()[i] is word first_word() + i of the set; all other words are zero.
    // Both ends of a non-empty window are non-zero; the empty set has no words and first_word 0.
    [[nodiscard]] std::span<const std::uint64_t> words() const noexcept { return words_; }
    [[nodiscard]] std::size_t first_word() const noexcept { return first_; }
    [[nodiscard]] std::size_t end_word() const noexcept { return first_ + words_.size(); }
    [[nodiscard]] std::size_t hash() const noexcept;
    friend bool operator==(const Environment&, const Environment&) = default;

private:
    void normalise() noexcept;  // drops zero words at both ends (restores the invariants)
    std::uint32_t first_ = 0;
    std::vector<std::uint64_t> words_;  // bit i of words_[w] <=> AssumptionId{64 * (first_ + w) + i}
};

// True iff the set of window x (x[i] is word x_first + i) is a subset of the set of window y.
[[nodiscard]] bool window_subset(std::span<const std::uint64_t> x, std::size_t x_first,
                                 std::span<const std::uint64_t> y, std::size_t y_first) noexcept;
// The same for two windows that both start at word 0 (raw bitsets, any lengths).
[[nodiscard]] inline bool words_subset(std::span<const std::uint64_t> x, std::span<const std::uint64_t> y) noexcept {
    return window_subset(x, 0, y, 0);
}
// True iff the two windows share an assumption.
[[nodiscard]] bool window_intersects(std::span<const std::uint64_t> x, std::size_t x_first,
                                     std::span<const std::uint64_t> y, std::size_t y_first) noexcept;

// True iff the set of window x (x[i] is word x_first + i) is a subset of y.
[[nodiscard]] bool window_subset(std::span<const std::uint64_t> x, std::size_t x_first, SparseWords y) noexcept;
// True iff the set of window x and y share an assumption.
[[nodiscard]] bool window_intersects(std::span<const std::uint64_t> x, std::size_t x_first, SparseWords y) noexcept;

[[nodiscard]] Environment join(const Environment& x, const Environment& y);

struct EnvironmentHash {
    std::size_t operator()(const Environment& e) const noexcept { return e.hash(); }
};
}  // namespace qm::atms
