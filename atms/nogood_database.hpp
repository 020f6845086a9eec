// atms/nogood_database.hpp
// Provides:   NogoodDatabase, the set of minimal nogoods (environments known to be inconsistent) with
//             indexes that make the two consistency questions fast:
//               subsumes(e)          is some nogood a subset of e?  (checks only nogoods whose
//                                    highest assumption is in e; subsumes_words(w, first) is the
//                                    same question for a raw bitset window starting at word first)
//               subsumes_with(w, a)  is some live nogood containing a a subset of w?  When w minus
//                                    a is consistent (the backtracking step of interpretations),
//                                    this equals subsumes(w). Two-assumption nogoods {a, b}, the
//                                    usual exclusions, are answered by one bitset of the partners
//                                    b of a, ANDed with w; only larger ones are tested one by one.
// Ownership:  owns copies of its nogood environments; EnvIds refer to the owner's EnvironmentTable.
// Invariants: live nogoods are pairwise incomparable (a new nogood retires its supersets).
// Knows nothing of labels, nodes or rules.
#pragma once
#include "atms/environment.hpp"
#include "atms/ids.hpp"
#include <cstdint>
#include <span>
#include <vector>

namespace qm::atms {
class NogoodDatabase {
public:
    [[nodiscard]] bool subsumes(const Environment& e) const noexcept {
        return subsumes_words(e.words(), e.first_word());
    }
    // words[i] is word first_word + i of the set; words outside the window are zero.
    [[nodiscard]] bool subsumes_words(std::span<const std::uint64_t> words, std::size_t first_word = 0) const noexcept;
    // words is a raw bitset from word 0 (the mutable partial choice of interpretations).
    [[nodiscard]] bool subsumes_with(std::span<const std::uint64_t> words, AssumptionId a) const noexcept;
    // Adds env as a minimal nogood, retiring the live nogoods that are supersets of it.
    // Pre: !subsumes(e) (an already subsumed nogood adds nothing and is the caller's bug).
    void add(EnvId id, const Environment& e);
    // Live nogoods, in order of addition.
    [[nodiscard]] std::vector<EnvId> minimal() const;
    [[nodiscard]] std::size_t size() const noexcept { return live_; }
    [[nodiscard]] bool empty_env_is_nogood() const noexcept { return empty_nogood_; }

private:
    void set_partner(AssumptionId a, AssumptionId b, bool on);
    struct Entry {
        EnvId id;
        Environment env;
        bool live = true;
    };
    std::vector<Entry> entries_;
    std::vector<std::vector<std::uint32_t>> by_first_;    // highest assumption -> entry indices (the newest is the rarest in a query)
    std::vector<std::vector<std::uint32_t>> containing_;  // assumption -> entry indices
    std::vector<std::vector<std::uint32_t>> not_pairs_;   // assumption -> live-or-dead entries of size != 2
    std::vector<Environment> partners_;                   // a -> the b with {a, b} a live nogood
    std::size_t live_ = 0;
    bool empty_nogood_ = false;
};
}  // namespace qm::atms
