// atms/environment.hpp
// Provides:   Environment, a set of assumptions stored sparsely over AssumptionId: only its non-zero
//             64-bit words, each with its word index, so a set costs (in memory, hashing, subset
//             tests) what it holds, however far apart its assumptions are and however many the ATMS
//             has (docs/perf/engine.md, "Sparse environments"). SparseWords, a set given by its
//             listed words (an Environment's own form, and weave's unions); free functions on
//             sparse sets and raw bitsets for the hot loops.
// Ownership:  a value type; canonical copies are interned by EnvironmentTable (environment_table.hpp).
// Invariants: words() holds no zero word; index()[i] is the word index of words()[i], strictly
//             increasing; so the defaulted == is set equality and the hash of equal sets is equal.
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
    std::span<const std::uint64_t> index;  // Pre: index.size() == words.size()
};

class Environment {
public:
    Environment() = default;  // the empty environment {}
    // Builds the set {as...}; duplicates are allowed and collapse.
    [[nodiscard]] static Environment of(std::span<const AssumptionId> as);
    // The set y (SparseWords above).
    [[nodiscard]] static Environment from_sparse(SparseWords y);
    // *this = the set of the window words (words[i] is word first_word + i, every word outside it
    // zero), reusing the storage it has (no allocation once it has grown): for a loop that forms
    // many environments one after another.
    void assign_words(std::span<const std::uint64_t> words, std::size_t first_word);

    [[nodiscard]] bool contains(AssumptionId a) const noexcept;
    [[nodiscard]] bool subset_of(const Environment& other) const noexcept;
    [[nodiscard]] bool empty() const noexcept { return data_.empty(); }
    [[nodiscard]] std::uint32_t size() const noexcept;  // number of assumptions
    [[nodiscard]] Environment with(AssumptionId a) const;
    void insert(AssumptionId a);  // in place: *this = with(a)
    void erase(AssumptionId a);   // in place: *this without a
    friend Environment join(const Environment& x, const Environment& y);  // x ∪ y
    // The assumptions in increasing id order.
    [[nodiscard]] std::vector<AssumptionId> assumptions() const;
    // The lowest assumption. Pre: !empty().
    [[nodiscard]] AssumptionId first() const;
    // The non-zero words in increasing order, and their word indices: words()[i] is word index()[i]
    // of the set (bit b of it <=> AssumptionId{64 * index()[i] + b}); every other word is zero.
    [[nodiscard]] std::span<const std::uint64_t> words() const noexcept { return {data_.data(), count()}; }
    [[nodiscard]] std::span<const std::uint64_t> index() const noexcept { return {data_.data() + count(), count()}; }
    [[nodiscard]] SparseWords sparse() const noexcept { return {words(), index()}; }
    // The window from the lowest to the highest non-zero word: [first_word(), end_word()); 0 and 0
    // for the empty set. window() is that window written out densely (for tests and raw bitsets).
    [[nodiscard]] std::size_t first_word() const noexcept { return empty() ? 0 : data_[count()]; }
    [[nodiscard]] std::size_t end_word() const noexcept { return empty() ? 0 : data_.back() + 1; }
    [[nodiscard]] std::vector<std::uint64_t> window() const;
    [[nodiscard]] std::size_t hash() const noexcept;
    friend bool operator==(const Environment&, const Environment&) = default;

private:
    [[nodiscard]] std::size_t count() const noexcept { return data_.size() / 2; }  // listed words
    // Builds from listed words (some may be zero: they are dropped). Pre: index increasing.
    void assign_listed(std::span<const std::uint64_t> words, std::span<const std::uint64_t> index);
    // The non-zero words in increasing word index, then their word indices, in one block (one
    // allocation per environment): data_[i] is word data_[count() + i] of the set.
    std::vector<std::uint64_t> data_;
};

// True iff the raw bitset x (bit i <=> AssumptionId{i}) is a subset of the raw bitset y (any lengths).
[[nodiscard]] bool words_subset(std::span<const std::uint64_t> x, std::span<const std::uint64_t> y) noexcept;

// Subset and intersection with x given by its listed words: they cost what x lists (and, for y
// sparse, what y lists), never the width of a window; y is a window (y[i] is word y_first + i) or
// listed words.
[[nodiscard]] bool sparse_subset(SparseWords x, SparseWords y) noexcept;
// (inline: the backtracking search of interpretations calls it per nogood per pick)
[[nodiscard]] inline bool sparse_subset(SparseWords x, std::span<const std::uint64_t> y, std::size_t y_first = 0) noexcept {
    for (std::size_t i = 0; i < x.words.size(); ++i) {
        if (x.words[i] == 0) continue;
        const std::size_t w = x.index[i];
        if (w < y_first || w - y_first >= y.size() || (x.words[i] & ~y[w - y_first]) != 0) return false;
    }
    return true;
}
[[nodiscard]] bool sparse_intersects(SparseWords x, SparseWords y) noexcept;

[[nodiscard]] Environment join(const Environment& x, const Environment& y);

struct EnvironmentHash {
    std::size_t operator()(const Environment& e) const noexcept { return e.hash(); }
};
}  // namespace qm::atms
