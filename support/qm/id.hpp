// support/qm/id.hpp
// Provides:   Id<Tag>, a strong typedef over a dense uint32 index (STYLE.md section 5), and
//             IdVector<K, V>, a vector indexed by such ids (bounds checked by QM_ASSERT).
// Invariants: ids start at 0 and are handed out by the table that owns them; there are no
//             sentinel values (use std::optional<Id<Tag>>).
#pragma once
#include "qm/assert.hpp"
#include <compare>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace qm {

template <class Tag>
struct Id {
    std::uint32_t value{};
    friend constexpr auto operator<=>(Id, Id) = default;
    friend constexpr bool operator==(Id, Id) = default;
};

template <class K, class V>
class IdVector {
public:
    [[nodiscard]] std::size_t size() const noexcept { return items_.size(); }
    [[nodiscard]] bool empty() const noexcept { return items_.empty(); }
    [[nodiscard]] bool contains(K k) const noexcept { return k.value < items_.size(); }
    V& operator[](K k) {
        QM_ASSERT(contains(k), "id out of range");
        return items_[k.value];
    }
    const V& operator[](K k) const {
        QM_ASSERT(contains(k), "id out of range");
        return items_[k.value];
    }
    // Appends v and returns its id.
    K push_back(V v) {
        items_.push_back(std::move(v));
        return K{static_cast<std::uint32_t>(items_.size() - 1)};
    }
    void reserve(std::size_t n) { items_.reserve(n); }
    auto begin() noexcept { return items_.begin(); }
    auto end() noexcept { return items_.end(); }
    auto begin() const noexcept { return items_.begin(); }
    auto end() const noexcept { return items_.end(); }

private:
    std::vector<V> items_;
};

}  // namespace qm

template <class Tag>
struct std::hash<qm::Id<Tag>> {
    std::size_t operator()(qm::Id<Tag> id) const noexcept { return std::hash<std::uint32_t>{}(id.value); }
};
