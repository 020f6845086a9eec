// atms/detail/minimal_sets.cpp: the scratch bitset pool and the minimal-elements filter.
#include "atms/detail/minimal_sets.hpp"

#include "atms/environment.hpp"
#include "qm/assert.hpp"
#include <algorithm>
#include <bit>

namespace qm::atms::detail {
namespace {
constexpr std::uint32_t word_bits = 64;

std::uint32_t popcount(std::span<const std::uint64_t> row) noexcept {
    std::uint32_t n = 0;
    for (std::uint64_t w : row) n += static_cast<std::uint32_t>(std::popcount(w));
    return n;
}
}  // namespace

std::uint64_t* BitsetPool::push(std::span<const std::uint64_t> row) {
    QM_ASSERT(row.size() <= width_, "row wider than the pool");
    words_.resize(words_.size() + width_, 0);
    std::uint64_t* out = words_.data() + rows_ * width_;
    std::copy(row.begin(), row.end(), out);
    ++rows_;
    return out;
}

void BitsetPool::pop() noexcept {
    QM_ASSERT(rows_ > 0, "pop of an empty pool");
    --rows_;
    words_.resize(rows_ * width_);
}

void MinimalFilter::keep_minimal(const BitsetPool& in, BitsetPool& out) {
    QM_ASSERT(in.width() == out.width() && &in != &out, "keep_minimal: bad pools");
    out.clear();
    const std::size_t width = in.width();
    // Smaller sets first (a counting sort on the size): a kept row can then never be a proper
    // superset of a later one, so kept rows are final and each row is tested once. A duplicate of
    // a kept row is caught by the subset test itself.
    counts_.resize(in.size());
    sigs_.resize(in.size());
    std::uint32_t largest = 0;
    for (std::uint32_t i = 0; i < in.size(); ++i) {
        counts_[i] = popcount(in[i]);
        std::uint64_t sig = 0;  // the OR of the row's words: a subset's is a subset of it
        for (std::uint64_t w : in[i]) sig |= w;
        sigs_[i] = sig;
        largest = std::max(largest, counts_[i]);
    }
    starts_.assign(largest + 2, 0);
    for (std::uint32_t c : counts_) ++starts_[c + 1];
    for (std::size_t c = 1; c < starts_.size(); ++c) starts_[c] += starts_[c - 1];
    order_.resize(in.size());
    for (std::uint32_t i = 0; i < in.size(); ++i) order_[starts_[counts_[i]]++] = i;
    if (by_lowest_.size() < width * word_bits) by_lowest_.resize(width * word_bits);
    for (std::uint32_t bit : touched_) by_lowest_[bit].clear();  // not all: width may be large
    touched_.clear();
    kept_sigs_.clear();
    for (std::uint32_t i : order_) {
        const auto row = in[i];
        if (counts_[i] == 0) {  // {} is below everything: it is the only minimal set
            out.push(row);
            return;
        }
        // A kept row K with K ⊆ row has its lowest bit in row: look only in those buckets.
        bool subsumed = false;
        for (std::size_t w = 0; w < width && !subsumed; ++w) {
            for (std::uint64_t bits = row[w]; bits != 0 && !subsumed; bits &= bits - 1) {
                const auto bit = w * word_bits + static_cast<std::size_t>(std::countr_zero(bits));
                for (std::uint32_t k : by_lowest_[bit])
                    if ((kept_sigs_[k] & ~sigs_[i]) == 0 && words_subset(out[k], row)) {
                        subsumed = true;
                        break;
                    }
            }
        }
        if (subsumed) continue;
        std::size_t w = 0;
        while (row[w] == 0) ++w;
        const auto lowest = w * word_bits + static_cast<std::size_t>(std::countr_zero(row[w]));
        if (by_lowest_[lowest].empty()) touched_.push_back(static_cast<std::uint32_t>(lowest));
        by_lowest_[lowest].push_back(static_cast<std::uint32_t>(out.size()));
        kept_sigs_.push_back(sigs_[i]);
        out.push(row);
    }
}
}  // namespace qm::atms::detail
