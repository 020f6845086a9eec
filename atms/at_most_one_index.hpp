// atms/at_most_one_index.hpp
// Provides:   AtMostOneIndex, the at-most-one constraints of an ATMS: each is a set of assumptions
//             no two of which hold together, i.e. the S(S-1)/2 pairwise nogoods of an `exactly one`
//             choice set of S members kept as one constraint (its at-least-one half is the
//             interpretations' business: interpretations.hpp). The queries answer, without forming
//             a pair, whether an environment holds two members of some constraint:
//               violated_by(w, first)      does the window w (word first on) hold two members of one?
//               other_member(a, w, first)  does w hold a member other than a of one of a's?
//             Both cost what the constraints' members list (members are stored sparsely,
//             environment.hpp), not the width of the query window; other_member also takes a set
//             given by its listed words.
// Ownership:  owns copies of the member sets; constraints are numbered densely from 0 in the order
//             added and never removed.
// Invariants: a constraint has at least two distinct members (smaller ones constrain nothing and
//             are not stored: add() returns nullopt); an assumption may be in several constraints.
// Knows nothing of nodes, labels or rules: an assumption is only an id.
#pragma once
#include "atms/environment.hpp"
#include "atms/ids.hpp"
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace qm::atms {
class AtMostOneIndex {
public:
    // Adds the constraint "at most one of members" (duplicates collapse) and returns its number,
    // or nullopt if it has fewer than two distinct members.
    std::optional<std::uint32_t> add(std::span<const AssumptionId> members);

    [[nodiscard]] bool empty() const noexcept { return members_.empty(); }
    [[nodiscard]] std::size_t size() const noexcept { return members_.size(); }
    // The members of constraint c as a set. Pre: c < size().
    [[nodiscard]] const Environment& members(std::uint32_t c) const;
    // The constraints that have a as a member, in the order added.
    [[nodiscard]] std::span<const std::uint32_t> of(AssumptionId a) const noexcept {
        return a.value < of_.size() ? std::span<const std::uint32_t>(of_[a.value]) : std::span<const std::uint32_t>();
    }

    // words[i] is word first + i of a set; words outside the window are zero.
    [[nodiscard]] bool violated_by(std::span<const std::uint64_t> words, std::size_t first = 0) const noexcept;
    // Some constraint of a has a member other than a in the window (a itself may or may not be in it).
    [[nodiscard]] bool other_member(AssumptionId a, std::span<const std::uint64_t> words, std::size_t first = 0) const noexcept;
    // The same for a set given by its listed words (environment.hpp).
    [[nodiscard]] bool other_member(AssumptionId a, SparseWords set) const noexcept;

private:
    // Both other_member forms: the constraints of a, each tested by the set's own form
    // (at_most_one_index.cpp: a raw window or listed words).
    template <class Set>
    [[nodiscard]] bool other_member_in(AssumptionId a, const Set& set) const noexcept;
    std::vector<Environment> members_;
    std::vector<std::vector<std::uint32_t>> of_;  // assumption -> constraints holding it
};
}  // namespace qm::atms
