// atms/at_most_one_index.cpp: the at-most-one constraints, tested by intersecting a constraint's
// listed member words with the environment's words, never pair by pair.
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

namespace {
// The two forms of the query set for other_member_in. meets(m, own_word, own_bit): does the set hold
// a member of m other than the one at (own_word, own_bit)? m, a constraint's members, may list
// thousands of words (one choice over 100,000 states: 1,563), the query set a few, so each costs
// what the query set lists times a binary search in m's word indices, never a walk through all of m
// (that walk made one large choice set quadratic).
struct WindowSet {
    std::span<const std::uint64_t> words;
    std::size_t first;
    [[nodiscard]] bool meets(const Environment& m, std::size_t own_word, std::uint64_t own_bit) const noexcept {
        const auto mi = m.index();
        const auto mw = m.words();
        for (auto it = std::lower_bound(mi.begin(), mi.end(), first); it != mi.end() && *it - first < words.size(); ++it) {
            const auto j = static_cast<std::size_t>(it - mi.begin());
            std::uint64_t shared = mw[j] & words[*it - first];
            if (*it == own_word) shared &= ~own_bit;
            if (shared != 0) return true;
        }
        return false;
    }
};
struct ListedSet {
    SparseWords set;
    [[nodiscard]] bool meets(const Environment& m, std::size_t own_word, std::uint64_t own_bit) const noexcept {
        const auto mi = m.index();
        const auto mw = m.words();
        auto from = mi.begin();
        for (std::size_t j = 0; j < set.index.size() && from != mi.end(); ++j) {
            from = std::lower_bound(from, mi.end(), set.index[j]);
            if (from == mi.end() || *from != set.index[j]) continue;
            std::uint64_t shared = mw[static_cast<std::size_t>(from - mi.begin())] & set.words[j];
            if (*from == own_word) shared &= ~own_bit;
            if (shared != 0) return true;
        }
        return false;
    }
};
}  // namespace

template <class Set>
bool AtMostOneIndex::other_member_in(AssumptionId a, const Set& set) const noexcept {
    if (a.value >= of_.size()) return false;
    const std::size_t own_word = a.value / word_bits;
    const std::uint64_t own_bit = std::uint64_t{1} << (a.value % word_bits);
    for (std::uint32_t c : of_[a.value])
        if (set.meets(members_[c], own_word, own_bit)) return true;
    return false;
}

bool AtMostOneIndex::other_member(AssumptionId a, std::span<const std::uint64_t> words, std::size_t first) const noexcept {
    return other_member_in(a, WindowSet{words, first});
}

bool AtMostOneIndex::other_member(AssumptionId a, SparseWords set) const noexcept {
    return other_member_in(a, ListedSet{set});
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
