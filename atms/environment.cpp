// atms/environment.cpp: the bitset operations of Environment, on windows of words.
#include "atms/environment.hpp"

#include "qm/assert.hpp"
#include <algorithm>
#include <bit>

namespace qm::atms {
namespace {
constexpr std::uint32_t word_bits = 64;

std::uint64_t bit_of(AssumptionId a) noexcept { return std::uint64_t{1} << (a.value % word_bits); }
}  // namespace

Environment Environment::of(std::span<const AssumptionId> as) {
    Environment e;
    if (as.empty()) return e;
    const auto [lo, hi] = std::minmax_element(as.begin(), as.end());
    e.first_ = lo->value / word_bits;
    e.words_.assign(hi->value / word_bits - e.first_ + 1, 0);
    for (AssumptionId a : as) e.words_[a.value / word_bits - e.first_] |= bit_of(a);
    return e;
}

Environment Environment::from_words(std::span<const std::uint64_t> words) { return from_words(words, 0); }

Environment Environment::from_words(std::span<const std::uint64_t> words, std::size_t first_word) {
    Environment e;
    e.assign_words(words, first_word);
    return e;
}

void Environment::assign_words(std::span<const std::uint64_t> words, std::size_t first_word) {
    std::size_t lo = 0, hi = words.size();
    while (lo < hi && words[lo] == 0) ++lo;
    while (hi > lo && words[hi - 1] == 0) --hi;
    if (lo == hi) {
        words_.clear();
        first_ = 0;
        return;
    }
    QM_REQUIRE(first_word + hi <= std::size_t{UINT32_MAX} / word_bits, "assumption id out of range");
    first_ = static_cast<std::uint32_t>(first_word + lo);
    words_.assign(words.begin() + static_cast<std::ptrdiff_t>(lo), words.begin() + static_cast<std::ptrdiff_t>(hi));
}

void Environment::normalise() noexcept {
    while (!words_.empty() && words_.back() == 0) words_.pop_back();
    std::size_t lead = 0;
    while (lead < words_.size() && words_[lead] == 0) ++lead;
    if (lead > 0) {
        words_.erase(words_.begin(), words_.begin() + static_cast<std::ptrdiff_t>(lead));
        first_ += static_cast<std::uint32_t>(lead);
    }
    if (words_.empty()) first_ = 0;
}

bool Environment::contains(AssumptionId a) const noexcept {
    const std::size_t w = a.value / word_bits;
    return w >= first_ && w < end_word() && (words_[w - first_] & bit_of(a)) != 0;
}

bool window_subset(std::span<const std::uint64_t> x, std::size_t x_first, std::span<const std::uint64_t> y,
                   std::size_t y_first) noexcept {
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (x[i] == 0) continue;
        const std::size_t w = x_first + i;  // absolute word index
        if (w < y_first || w - y_first >= y.size() || (x[i] & ~y[w - y_first]) != 0) return false;
    }
    return true;
}

bool window_intersects(std::span<const std::uint64_t> x, std::size_t x_first, std::span<const std::uint64_t> y,
                       std::size_t y_first) noexcept {
    const std::size_t lo = std::max(x_first, y_first);
    const std::size_t hi = std::min(x_first + x.size(), y_first + y.size());
    for (std::size_t w = lo; w < hi; ++w)
        if ((x[w - x_first] & y[w - y_first]) != 0) return true;
    return false;
}

bool window_subset(std::span<const std::uint64_t> x, std::size_t x_first, SparseWords y) noexcept {
    // Both walks go up: x's words in order, y's index by a cursor (a merge, no search).
    std::size_t j = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (x[i] == 0) continue;
        const std::size_t w = x_first + i;
        while (j < y.index.size() && y.index[j] < w) ++j;
        if (j == y.index.size() || y.index[j] != w || (x[i] & ~y.words[j]) != 0) return false;
    }
    return true;
}

bool window_intersects(std::span<const std::uint64_t> x, std::size_t x_first, SparseWords y) noexcept {
    for (std::size_t j = 0; j < y.index.size(); ++j) {
        const std::size_t w = y.index[j];
        if (w < x_first) continue;
        if (w - x_first >= x.size()) break;
        if ((x[w - x_first] & y.words[j]) != 0) return true;
    }
    return false;
}

Environment Environment::from_sparse(SparseWords y) {
    Environment e;
    std::size_t lo = 0, hi = y.words.size();
    while (lo < hi && y.words[lo] == 0) ++lo;
    while (hi > lo && y.words[hi - 1] == 0) --hi;
    if (lo == hi) return e;
    QM_REQUIRE(std::size_t{y.index[hi - 1]} + 1 <= std::size_t{UINT32_MAX} / word_bits, "assumption id out of range");
    e.first_ = y.index[lo];
    e.words_.assign(std::size_t{y.index[hi - 1]} - e.first_ + 1, 0);
    for (std::size_t j = lo; j < hi; ++j) e.words_[y.index[j] - e.first_] = y.words[j];
    return e;  // both ends are non-zero words of y
}

bool Environment::subset_of(const Environment& other) const noexcept {
    // Both windows are tight, so a window reaching outside the other's has a bit the other lacks.
    if (empty()) return true;
    if (first_ < other.first_ || end_word() > other.end_word()) return false;
    return window_subset(words_, first_, other.words_, other.first_);
}

std::uint32_t Environment::size() const noexcept {
    std::uint32_t n = 0;
    for (std::uint64_t w : words_) n += static_cast<std::uint32_t>(std::popcount(w));
    return n;
}

Environment Environment::with(AssumptionId a) const {
    const AssumptionId one[] = {a};
    return join(*this, Environment::of(one));
}

Environment Environment::without(AssumptionId a) const {
    Environment e = *this;
    e.erase(a);
    return e;
}

void Environment::insert(AssumptionId a) {
    const auto w = static_cast<std::uint32_t>(a.value / word_bits);
    if (words_.empty()) {
        first_ = w;
        words_.assign(1, bit_of(a));
        return;
    }
    if (w < first_) {
        words_.insert(words_.begin(), first_ - w, 0);
        first_ = w;
    } else if (w >= end_word()) {
        words_.resize(w - first_ + 1, 0);
    }
    words_[w - first_] |= bit_of(a);
}

void Environment::erase(AssumptionId a) {
    if (!contains(a)) return;
    words_[a.value / word_bits - first_] &= ~bit_of(a);
    normalise();
}

Environment join(const Environment& x, const Environment& y) {
    if (x.empty()) return y;
    if (y.empty()) return x;
    Environment e;
    e.first_ = std::min(x.first_, y.first_);
    e.words_.assign(std::max(x.end_word(), y.end_word()) - e.first_, 0);
    for (std::size_t i = 0; i < x.words_.size(); ++i) e.words_[x.first_ - e.first_ + i] |= x.words_[i];
    for (std::size_t i = 0; i < y.words_.size(); ++i) e.words_[y.first_ - e.first_ + i] |= y.words_[i];
    return e;  // both ends come from a non-zero end word of x or y: no normalising needed
}

std::vector<AssumptionId> Environment::assumptions() const {
    std::vector<AssumptionId> out;
    for (std::size_t i = 0; i < words_.size(); ++i) {
        for (std::uint64_t w = words_[i]; w != 0; w &= w - 1) {
            const auto bit = static_cast<std::size_t>(std::countr_zero(w));
            out.push_back(AssumptionId{static_cast<std::uint32_t>((first_ + i) * word_bits + bit)});
        }
    }
    return out;
}

AssumptionId Environment::first() const {
    QM_REQUIRE(!words_.empty(), "first() of the empty environment");
    return AssumptionId{static_cast<std::uint32_t>(first_ * word_bits +
                                                   static_cast<std::size_t>(std::countr_zero(words_.front())))};
}

std::size_t Environment::hash() const noexcept {
    std::uint64_t h = 0x9e3779b97f4a7c15ULL ^ first_;
    for (std::uint64_t w : words_) {
        h ^= w + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
        h *= 0xff51afd7ed558ccdULL;
    }
    return static_cast<std::size_t>(h ^ (h >> 33));
}
}  // namespace qm::atms
