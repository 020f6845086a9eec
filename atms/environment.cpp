// atms/environment.cpp: the set operations of Environment, on its listed non-zero words; the free
// functions on raw bitsets and on SparseWords.
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
    // Sorted ids, then one pass: the words into the block's front, their indices after them.
    std::vector<std::uint32_t> ids;
    ids.reserve(as.size());
    for (AssumptionId a : as) ids.push_back(a.value);
    std::sort(ids.begin(), ids.end());
    std::size_t k = 0;
    for (std::size_t i = 0; i < ids.size(); ++i) k += (i == 0 || ids[i] / word_bits != ids[i - 1] / word_bits) ? 1 : 0;
    e.data_.assign(2 * k, 0);
    std::size_t at = 0;
    for (std::size_t i = 0; i < ids.size(); ++i) {
        if (i > 0 && ids[i] / word_bits != ids[i - 1] / word_bits) ++at;
        e.data_[k + at] = ids[i] / word_bits;
        e.data_[at] |= std::uint64_t{1} << (ids[i] % word_bits);
    }
    return e;
}

void Environment::assign_listed(std::span<const std::uint64_t> words, std::span<const std::uint64_t> index) {
    // Checked before anything changes, so that a refused id leaves the environment as it was.
    std::size_t k = 0;
    for (std::size_t j = 0; j < words.size(); ++j) {
        if (words[j] == 0) continue;
        QM_REQUIRE(index[j] <= std::size_t{UINT32_MAX} / word_bits, "assumption id out of range");
        ++k;
    }
    data_.resize(2 * k);
    std::size_t at = 0;
    for (std::size_t j = 0; j < words.size(); ++j) {
        if (words[j] == 0) continue;
        data_[at] = words[j];
        data_[k + at] = index[j];
        ++at;
    }
}

void Environment::assign_words(std::span<const std::uint64_t> words, std::size_t first_word) {
    std::size_t k = 0;
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (words[i] == 0) continue;
        QM_REQUIRE(first_word + i <= std::size_t{UINT32_MAX} / word_bits, "assumption id out of range");
        ++k;
    }
    data_.resize(2 * k);
    std::size_t at = 0;
    for (std::size_t i = 0; i < words.size(); ++i) {
        if (words[i] == 0) continue;
        data_[at] = words[i];
        data_[k + at] = first_word + i;
        ++at;
    }
}

Environment Environment::from_sparse(SparseWords y) {
    Environment e;
    e.assign_listed(y.words, y.index);
    return e;
}

bool Environment::contains(AssumptionId a) const noexcept {
    if (empty()) return false;
    const std::uint64_t w = a.value / word_bits;
    const auto ix = index();
    // Where w is if every word from the first one on is listed (an interpretation over nearby
    // assumptions, say): tried first, a binary search otherwise (callers test membership per
    // assumption of an interpretation, analysis/).
    std::size_t at = static_cast<std::size_t>(w - ix.front());
    if (w < ix.front() || at >= ix.size() || ix[at] != w) {
        const auto it = std::lower_bound(ix.begin(), ix.end(), w);
        if (it == ix.end() || *it != w) return false;
        at = static_cast<std::size_t>(it - ix.begin());
    }
    return (data_[at] & bit_of(a)) != 0;
}

bool words_subset(std::span<const std::uint64_t> x, std::span<const std::uint64_t> y) noexcept {
    for (std::size_t i = 0; i < x.size(); ++i)
        if (x[i] != 0 && (i >= y.size() || (x[i] & ~y[i]) != 0)) return false;
    return true;
}

bool sparse_subset(SparseWords x, SparseWords y) noexcept {
    // A merge of the two increasing index lists.
    std::size_t j = 0;
    for (std::size_t i = 0; i < x.words.size(); ++i) {
        if (x.words[i] == 0) continue;
        const std::uint64_t w = x.index[i];
        while (j < y.index.size() && y.index[j] < w) ++j;
        if (j == y.index.size() || y.index[j] != w || (x.words[i] & ~y.words[j]) != 0) return false;
    }
    return true;
}

bool sparse_intersects(SparseWords x, SparseWords y) noexcept {
    std::size_t i = 0, j = 0;
    while (i < x.index.size() && j < y.index.size()) {
        if (x.index[i] < y.index[j]) ++i;
        else if (y.index[j] < x.index[i]) ++j;
        else if ((x.words[i++] & y.words[j++]) != 0) return true;
    }
    return false;
}

bool Environment::subset_of(const Environment& other) const noexcept {
    if (count() > other.count()) return false;  // a word other lacks
    return sparse_subset(sparse(), other.sparse());
}

std::uint32_t Environment::size() const noexcept {
    std::uint32_t n = 0;
    for (std::uint64_t w : words()) n += static_cast<std::uint32_t>(std::popcount(w));
    return n;
}

Environment Environment::with(AssumptionId a) const {
    Environment e = *this;
    e.insert(a);
    return e;
}

void Environment::insert(AssumptionId a) {
    // In place: OR into its word, or a new word (and its index) at its place in the block.
    const std::uint64_t w = a.value / word_bits;
    const std::size_t k = count();
    const auto ix = index();
    const auto at = static_cast<std::size_t>(std::lower_bound(ix.begin(), ix.end(), w) - ix.begin());
    if (at < k && ix[at] == w) {
        data_[at] |= bit_of(a);
        return;
    }
    data_.insert(data_.begin() + static_cast<std::ptrdiff_t>(k + at), w);
    data_.insert(data_.begin() + static_cast<std::ptrdiff_t>(at), bit_of(a));
}

void Environment::erase(AssumptionId a) {
    if (!contains(a)) return;
    std::vector<std::uint64_t> words(this->words().begin(), this->words().end());
    const auto ix = index();
    words[static_cast<std::size_t>(std::lower_bound(ix.begin(), ix.end(), std::uint64_t{a.value / word_bits}) - ix.begin())] &= ~bit_of(a);
    const std::vector<std::uint64_t> listed(ix.begin(), ix.end());
    assign_listed(words, listed);  // drops the word if it is now zero
}

Environment join(const Environment& x, const Environment& y) {
    if (x.empty()) return y;
    if (y.empty()) return x;
    // Merged into the front of one block, indices at its back half, then moved down to follow.
    const std::size_t kx = x.count(), ky = y.count(), cap = kx + ky;
    const auto xw = x.words(), xi = x.index(), yw = y.words(), yi = y.index();
    Environment e;
    e.data_.resize(2 * cap);
    std::uint64_t* out = e.data_.data();
    std::size_t i = 0, j = 0, m = 0;
    while (i < kx || j < ky) {
        if (j == ky || (i < kx && xi[i] < yi[j])) {
            out[cap + m] = xi[i];
            out[m++] = xw[i++];
        } else if (i == kx || yi[j] < xi[i]) {
            out[cap + m] = yi[j];
            out[m++] = yw[j++];
        } else {
            out[cap + m] = xi[i];
            out[m++] = xw[i++] | yw[j++];
        }
    }
    if (m != cap) std::copy(out + cap, out + cap + m, out + m);  // close the gap (std::copy needs distinct ranges)
    e.data_.resize(2 * m);
    return e;  // non-zero words of x or y stay non-zero
}

std::vector<AssumptionId> Environment::assumptions() const {
    std::vector<AssumptionId> out;
    const auto ws = words();
    const auto ix = index();
    for (std::size_t i = 0; i < ws.size(); ++i) {
        for (std::uint64_t w = ws[i]; w != 0; w &= w - 1) {
            const auto bit = static_cast<std::uint32_t>(std::countr_zero(w));
            out.push_back(AssumptionId{static_cast<std::uint32_t>(ix[i] * word_bits + bit)});
        }
    }
    return out;
}

AssumptionId Environment::first() const {
    QM_REQUIRE(!empty(), "first() of the empty environment");
    return AssumptionId{static_cast<std::uint32_t>(index().front() * word_bits +
                                                   static_cast<std::uint64_t>(std::countr_zero(words().front())))};
}

std::vector<std::uint64_t> Environment::window() const {
    std::vector<std::uint64_t> out(end_word() - first_word(), 0);
    for (std::size_t i = 0; i < count(); ++i) out[index()[i] - first_word()] = words()[i];
    return out;
}

std::size_t Environment::hash() const noexcept {
    std::uint64_t h = 0x9e3779b97f4a7c15ULL;
    for (std::uint64_t x : data_) {
        h ^= x + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
        h *= 0xff51afd7ed558ccdULL;
    }
    return static_cast<std::size_t>(h ^ (h >> 33));
}
}  // namespace qm::atms
