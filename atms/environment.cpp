// atms/environment.cpp: the bitset operations of Environment.
#include "atms/environment.hpp"

#include <algorithm>
#include <bit>

namespace qm::atms {
namespace {
constexpr std::uint32_t word_bits = 64;
}

Environment Environment::of(std::span<const AssumptionId> as) {
    Environment e;
    for (AssumptionId a : as) {
        const std::size_t w = a.value / word_bits;
        if (e.words_.size() <= w) e.words_.resize(w + 1, 0);
        e.words_[w] |= std::uint64_t{1} << (a.value % word_bits);
    }
    return e;
}

Environment Environment::from_words(std::span<const std::uint64_t> words) {
    Environment e;
    e.words_.assign(words.begin(), words.end());
    e.trim();
    return e;
}

Environment Environment::from_words(std::span<const std::uint64_t> words, std::size_t first_word) {
    Environment e;
    e.words_.assign(first_word, 0);
    e.words_.insert(e.words_.end(), words.begin(), words.end());
    e.trim();
    return e;
}

std::size_t Environment::first_word() const noexcept {
    std::size_t w = 0;
    while (w < words_.size() && words_[w] == 0) ++w;
    return w;
}

void Environment::trim() noexcept {
    while (!words_.empty() && words_.back() == 0) words_.pop_back();
}

bool Environment::contains(AssumptionId a) const noexcept {
    const std::size_t w = a.value / word_bits;
    return w < words_.size() && ((words_[w] >> (a.value % word_bits)) & 1U) != 0;
}

bool words_subset(std::span<const std::uint64_t> words, std::span<const std::uint64_t> of) noexcept {
    const std::size_t common = std::min(words.size(), of.size());
    for (std::size_t i = 0; i < common; ++i)
        if ((words[i] & ~of[i]) != 0) return false;
    for (std::size_t i = common; i < words.size(); ++i)
        if (words[i] != 0) return false;
    return true;
}

bool words_subset(std::span<const std::uint64_t> words, std::span<const std::uint64_t> of,
                  std::size_t of_first) noexcept {
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (words[i] == 0) continue;
        if (i < of_first || i - of_first >= of.size() || (words[i] & ~of[i - of_first]) != 0) return false;
    }
    return true;
}

bool Environment::subset_of(const Environment& other) const noexcept {
    // No trailing zero words: a longer bitset has a bit the shorter one lacks.
    if (words_.size() > other.words_.size()) return false;
    return words_subset(words_, other.words_);
}

std::uint32_t Environment::size() const noexcept {
    std::uint32_t n = 0;
    for (std::uint64_t w : words_) n += static_cast<std::uint32_t>(std::popcount(w));
    return n;
}

Environment Environment::with(AssumptionId a) const {
    Environment e = *this;
    const std::size_t w = a.value / word_bits;
    if (e.words_.size() <= w) e.words_.resize(w + 1, 0);
    e.words_[w] |= std::uint64_t{1} << (a.value % word_bits);
    return e;
}

Environment join(const Environment& x, const Environment& y) {
    const Environment& longer = x.words_.size() >= y.words_.size() ? x : y;
    const Environment& shorter = x.words_.size() >= y.words_.size() ? y : x;
    Environment e = longer;
    for (std::size_t i = 0; i < shorter.words_.size(); ++i) e.words_[i] |= shorter.words_[i];
    return e;  // the longer one's last word is non-zero, so no trim is needed
}

std::vector<AssumptionId> Environment::assumptions() const {
    std::vector<AssumptionId> out;
    for (std::size_t i = 0; i < words_.size(); ++i) {
        std::uint64_t w = words_[i];
        while (w != 0) {
            const int bit = std::countr_zero(w);
            out.push_back(AssumptionId{static_cast<std::uint32_t>(i * word_bits + static_cast<std::size_t>(bit))});
            w &= w - 1;
        }
    }
    return out;
}

AssumptionId Environment::first() const {
    QM_REQUIRE(!words_.empty(), "first() of the empty environment");
    for (std::size_t i = 0;; ++i)
        if (words_[i] != 0)
            return AssumptionId{static_cast<std::uint32_t>(i * word_bits +
                                                           static_cast<std::size_t>(std::countr_zero(words_[i])))};
}

std::size_t Environment::hash() const noexcept {
    // Mixes only the non-zero words (with their positions): with thousands of assumptions most
    // words of an environment are zero, and skipping them is cheaper than multiplying them in.
    std::uint64_t h = 0x9e3779b97f4a7c15ULL;
    for (std::size_t i = 0; i < words_.size(); ++i) {
        if (words_[i] == 0) continue;
        h ^= words_[i] + 0x9e3779b97f4a7c15ULL + i + (h << 6) + (h >> 2);
        h *= 0xff51afd7ed558ccdULL;
    }
    return static_cast<std::size_t>(h ^ (h >> 33));
}
}  // namespace qm::atms
