// atms/at_most_one_index.cpp: the at-most-one constraints, tested by intersecting a constraint's
// listed member words with the environment's words, never pair by pair.
#include "atms/at_most_one_index.hpp"

#include "qm/assert.hpp"
#include <algorithm>

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

// Each constraint of a is tested for a member of the set other than a: m, a constraint's members,
// may list thousands of words (one choice over 100,000 states: 1,563), the set a few, so this costs
// what the set lists times a binary search in m's word indices, never a walk through all of m (that
// walk made one large choice set quadratic).
bool AtMostOneIndex::other_member(AssumptionId a, SparseWords set) const noexcept {
    if (a.value >= of_.size()) return false;
    const std::size_t own_word = a.value / word_bits;
    const std::uint64_t own_bit = std::uint64_t{1} << (a.value % word_bits);
    for (std::uint32_t c : of_[a.value]) {
        const auto mi = members_[c].index();
        const auto mw = members_[c].words();
        auto from = mi.begin();
        for (std::size_t j = 0; j < set.index.size() && from != mi.end(); ++j) {
            from = std::lower_bound(from, mi.end(), set.index[j]);
            if (from == mi.end() || *from != set.index[j]) continue;
            std::uint64_t shared = mw[static_cast<std::size_t>(from - mi.begin())] & set.words[j];
            if (*from == own_word) shared &= ~own_bit;
            if (shared != 0) return true;
        }
    }
    return false;
}
}  // namespace qm::atms
