// atms/nogood_database.hpp
// Provides:   NogoodDatabase, what is known to be inconsistent: the minimal nogoods stated one by one
//             (environments) and the at-most-one constraints (at_most_one_index.hpp), each standing
//             for the nogoods {a, b} of every two of its members without storing them. Indexes make
//             the consistency questions cost what could match, not a scan:
//               subsumes(e)          is e inconsistent (some nogood a subset of e, or two members of
//                                    one constraint in e)?  A nogood of size 1 or >= 3 is filed
//                                    under one of its assumptions (the one with the fewest filed,
//                                    when it is added), so only the buckets of e's assumptions are
//                                    visited, and a one-word signature (members modulo 64) rejects
//                                    most there; two-assumption nogoods {a, b}, the usual
//                                    exclusions, by one bitset of the partners b of each a of e;
//                                    constraints by their listed members. subsumes_sparse(set) is
//                                    the same question for a set given by its listed words.
//               excludes(base, a)    is base + a inconsistent, base being consistent without a?
//               within(e)            the live stated nogoods that are subsets of e.
// Ownership:  owns copies of its nogood environments; EnvIds refer to the owner's EnvironmentTable.
// Invariants: live stated nogoods are pairwise incomparable (a new nogood retires its supersets), and
//             none holds two members of a constraint (a new constraint retires them).
// Knows nothing of labels, nodes or rules.
#pragma once
#include "atms/at_most_one_index.hpp"
#include "atms/environment.hpp"
#include "atms/ids.hpp"
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace qm::atms {
class NogoodDatabase {
public:
    [[nodiscard]] bool subsumes(const Environment& e) const noexcept { return subsumes_sparse(e.sparse()); }
    // The same for a set given by its listed words (environment.hpp): costs what the listed words
    // hold, not the width of the window from its lowest to its highest assumption.
    [[nodiscard]] bool subsumes_sparse(SparseWords set) const noexcept;
    // Pre: base is consistent and does not hold a.
    [[nodiscard]] bool excludes(const Environment& base, AssumptionId a) const noexcept;
    // Adds env as a minimal nogood, retiring the live nogoods that are supersets of it.
    // Pre: !subsumes(e) (an already subsumed nogood adds nothing and is the caller's bug).
    void add(EnvId id, const Environment& e);
    // Adds the constraint "at most one of members", retiring the live stated nogoods holding two of
    // them. Returns its number in at_most_one(), or nullopt if it has fewer than two members.
    std::optional<std::uint32_t> add_at_most_one(std::span<const AssumptionId> members);

    // Live stated nogoods, in order of addition (the constraints' pairs are not among them).
    [[nodiscard]] std::vector<EnvId> minimal() const;
    // Live stated nogoods that are subsets of e, in order of addition.
    [[nodiscard]] std::vector<EnvId> within(const Environment& e) const;
    [[nodiscard]] std::size_t size() const noexcept { return live_; }  // live stated nogoods
    [[nodiscard]] bool empty_env_is_nogood() const noexcept { return empty_nogood_; }
    [[nodiscard]] const AtMostOneIndex& at_most_one() const noexcept { return at_most_one_; }
    // The b with {a, b} a live stated nogood, as a set (empty if none).
    [[nodiscard]] const Environment& partners(AssumptionId a) const noexcept {
        return a.value < partners_.size() ? partners_[a.value] : no_partners_;
    }
    // Some stated nogood of size 1 or >= 3 (live or retired) contains a: only then can
    // larger_with(w, a) be true.
    [[nodiscard]] bool has_larger(AssumptionId a) const noexcept {
        return a.value < not_pairs_.size() && !not_pairs_[a.value].empty();
    }
    // Some live stated nogood of size 1 or >= 3 containing a is a subset of the raw bitset words.
    // sig, if given, is the OR of words' words (a superset of it will do): a nogood whose own
    // signature is not inside it is passed over without a subset test.
    [[nodiscard]] bool larger_with(std::span<const std::uint64_t> words, AssumptionId a,
                                   std::uint64_t sig = ~std::uint64_t{0}) const noexcept;

private:
    void set_partner(AssumptionId a, AssumptionId b, bool on);
    void retire(std::uint32_t entry);
    struct Entry {
        EnvId id;
        Environment env;
        std::uint64_t sig = 0;     // the OR of env's words
        std::uint32_t size = 0;    // |env|
        AssumptionId filed_under;  // size != 2: its bucket in filed_
        bool live = true;
    };
    struct Filed {
        std::uint64_t sig;  // the entry's, kept here so a rejection touches no entry
        std::uint32_t entry;
    };
    std::vector<Entry> entries_;
    std::vector<std::vector<Filed>> filed_;                   // assumption -> live entries of size != 2 filed under it
    std::vector<std::vector<std::uint32_t>> pairs_by_first_;  // highest assumption -> entries of size 2
    std::vector<std::vector<std::uint32_t>> containing_;  // assumption -> entry indices
    std::vector<std::vector<std::uint32_t>> not_pairs_;   // assumption -> live-or-dead entries of size != 2
    std::vector<Environment> partners_;                   // a -> the b with {a, b} a live nogood
    Environment no_partners_;
    AtMostOneIndex at_most_one_;
    std::size_t live_ = 0;
    bool empty_nogood_ = false;
};
}  // namespace qm::atms
