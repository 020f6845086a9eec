// atms/detail/minimal_sets.hpp (internal to atms/; nothing outside the module includes it)
// Provides:   BitsetPool, a flat array of equal-width bitsets (scratch space for sets that are
//             formed and mostly thrown away, such as the unions inside weave), MinimalFilter,
//             which keeps the minimal elements under set inclusion of a pool, duplicates removed,
//             and WeaveScratch, the pools of one weave kept between calls.
// Ownership:  values; a row pointer or span is valid until the next push/clear of its pool.
// Invariants: every row of a pool has exactly width() words (zero padded).
// Knows nothing of environments' ids, labels or nodes: a row is only a set of bit positions.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace qm::atms::detail {
class BitsetPool {
public:
    explicit BitsetPool(std::size_t width) : width_(width) {}
    [[nodiscard]] std::size_t width() const noexcept { return width_; }
    [[nodiscard]] std::size_t size() const noexcept { return rows_; }
    [[nodiscard]] std::span<const std::uint64_t> operator[](std::size_t i) const noexcept {
        return {words_.data() + i * width_, width_};
    }
    // Row i for in-place updates. Pre: i < size().
    [[nodiscard]] std::uint64_t* row(std::size_t i) noexcept { return words_.data() + i * width_; }
    // Appends a copy of `row` (zero padded) and returns the new row for in-place updates.
    // Pre: row.size() <= width(); row does not point into this pool.
    std::uint64_t* push(std::span<const std::uint64_t> row);
    void pop() noexcept;  // Pre: size() > 0
    void clear() noexcept {
        words_.clear();
        rows_ = 0;
    }
    // Empties the pool and sets a new row width, keeping the allocated storage.
    void reset(std::size_t width) noexcept {
        clear();
        width_ = width;
    }

private:
    std::size_t width_;
    std::size_t rows_ = 0;
    std::vector<std::uint64_t> words_;
};

class MinimalFilter {
public:
    // Replaces `out` by the minimal rows of `in` (no row a subset of another, no duplicates), in
    // increasing order of size. O(n) sorting plus, per row, a subset test against the kept rows
    // whose lowest bit the row contains. Pre: in.width() == out.width(); &in != &out.
    void keep_minimal(const BitsetPool& in, BitsetPool& out);

private:
    std::vector<std::uint32_t> order_;
    std::vector<std::uint32_t> counts_;
    std::vector<std::uint64_t> sigs_;       // per row of in: the OR of its words
    std::vector<std::uint64_t> kept_sigs_;  // per row of out
    std::vector<std::uint32_t> starts_;  // counting sort offsets by size
    std::vector<std::vector<std::uint32_t>> by_lowest_;  // lowest bit -> kept row indices in out
    std::vector<std::uint32_t> touched_;                  // the non-empty buckets of by_lowest_
};

// The scratch space of one weave, kept by its owner between calls so that adding a justification
// allocates nothing once the pools have grown (label_update.hpp).
struct WeaveScratch {
    BitsetPool current{0}, unions{0}, minimal{0}, placed{0};
    std::vector<std::uint64_t> index;  // the words the rows stand for (SparseWords::index)
    MinimalFilter filter;
};
}  // namespace qm::atms::detail
