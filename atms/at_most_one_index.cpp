// atms/at_most_one_index.cpp: the at-most-one constraints, tested by intersecting a constraint's
// member window with the environment's window, never pair by pair.
#include "atms/at_most_one_index.hpp"

#include "qm/assert.hpp"
#include <algorithm>
#include <bit>

namespace qm::atms {
namespace {
constexpr std::uint32_t word_bits = 64;
}

std::optional<std::uint32_t> AtMostOneIndex::add(std::span<const AssumptionId> members) {
    Environment set = Environment::of(members);
    if (set.size() < 2) return std::nullopt;
    const auto c = static_cast<std::uint32_t>(members_.size());
    for (AssumptionId a : set.assumptions()) {
        if (of_.size() <= a.value) of_.resize(a.value + 1);
        of_[a.value].push_back(c);
    }
    members_.push_back(std::move(set));
    return c;
}

const Environment& AtMostOneIndex::members(std::uint32_t c) const {
    QM_REQUIRE(c < members_.size(), "unknown at-most-one constraint");
    return members_[c];
}

bool AtMostOneIndex::other_member(AssumptionId a, std::span<const std::uint64_t> words, std::size_t first) const noexcept {
    if (a.value >= of_.size()) return false;
    const std::size_t own_word = a.value / word_bits;
    const std::uint64_t own_bit = std::uint64_t{1} << (a.value % word_bits);
    for (std::uint32_t c : of_[a.value]) {
        const Environment& m = members_[c];
        // Only the words both windows cover can hold a shared member.
        const std::size_t lo = std::max(m.first_word(), first);
        const std::size_t hi = std::min(m.end_word(), first + words.size());
        for (std::size_t w = lo; w < hi; ++w) {
            std::uint64_t shared = m.words()[w - m.first_word()] & words[w - first];
            if (w == own_word) shared &= ~own_bit;
            if (shared != 0) return true;
        }
    }
    return false;
}

bool AtMostOneIndex::other_member(AssumptionId a, SparseWords set) const noexcept {
    if (a.value >= of_.size()) return false;
    const std::size_t own_word = a.value / word_bits;
    const std::uint64_t own_bit = std::uint64_t{1} << (a.value % word_bits);
    for (std::uint32_t c : of_[a.value]) {
        const Environment& m = members_[c];
        // Only the listed words inside the member window can hold a shared member.
        for (std::size_t j = 0; j < set.index.size(); ++j) {
            const std::size_t w = set.index[j];
            if (w < m.first_word()) continue;
            if (w >= m.end_word()) break;
            std::uint64_t shared = m.words()[w - m.first_word()] & set.words[j];
            if (w == own_word) shared &= ~own_bit;
            if (shared != 0) return true;
        }
    }
    return false;
}

bool AtMostOneIndex::violated_by(std::span<const std::uint64_t> words, std::size_t first) const noexcept {
    if (members_.empty()) return false;
    // A constraint with two members in the set is found from either; one with a single member in
    // it is tested once, from that member.
    for (std::size_t w = 0; w < words.size(); ++w) {
        for (std::uint64_t bits = words[w]; bits != 0; bits &= bits - 1) {
            const std::size_t a = (first + w) * word_bits + static_cast<std::size_t>(std::countr_zero(bits));
            if (a >= of_.size()) return false;
            if (other_member(AssumptionId{static_cast<std::uint32_t>(a)}, words, first)) return true;
        }
    }
    return false;
}
}  // namespace qm::atms
