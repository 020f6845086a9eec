// atms/nogood_database.cpp: minimal stated nogoods filed under one of their assumptions (filed_,
// the buckets a query looks in; pairs separately, answered by the partner bitsets), indexed by every
// assumption (containing_, to retire supersets), and the at-most-one constraints.
#include "atms/nogood_database.hpp"

#include "qm/assert.hpp"
#include <algorithm>
#include <bit>

namespace qm::atms {
namespace {
constexpr std::uint32_t word_bits = 64;

void ensure(std::vector<std::vector<std::uint32_t>>& index, AssumptionId a) {
    if (index.size() <= a.value) index.resize(a.value + 1);
}

// Bit i set iff the set has an assumption congruent to i modulo 64: the OR of its words. N is a
// subset of e only if signature(N) is a subset of signature(e), a test of one word.
std::uint64_t signature(std::span<const std::uint64_t> words) noexcept {
    std::uint64_t sig = 0;
    for (std::uint64_t w : words) sig |= w;
    return sig;
}
}  // namespace

bool NogoodDatabase::subsumes_sparse(SparseWords set) const noexcept {
    if (empty_nogood_) return true;
    // A stated nogood N of size 1 or >= 3 is filed under one of its assumptions: N is a subset of e
    // only if that one is in e, so only the buckets of e's assumptions are visited, and in them the
    // signature rejects most without touching N. A pair {a, b} is found from either member through
    // the partners of a.
    const std::uint64_t sig = signature(set.words);
    for (std::size_t j = 0; j < set.words.size(); ++j) {
        for (std::uint64_t bits = set.words[j]; bits != 0; bits &= bits - 1) {
            const std::size_t a = set.index[j] * word_bits + static_cast<std::size_t>(std::countr_zero(bits));
            if (a < partners_.size()) {
                const Environment& p = partners_[a];
                if (!p.empty() && sparse_intersects(p.sparse(), set)) return true;
            }
            if (a < filed_.size()) {
                for (const Filed& f : filed_[a]) {
                    if ((f.sig & ~sig) != 0) continue;
                    if (sparse_subset(entries_[f.entry].env.sparse(), set)) return true;
                }
            }
            // A constraint with two members in e is found from either, folded into this one pass.
            const AssumptionId id{static_cast<std::uint32_t>(a)};
            if (!at_most_one_.of(id).empty() && at_most_one_.other_member(id, set)) return true;
        }
    }
    return false;
}

bool NogoodDatabase::excludes(const Environment& base, AssumptionId a) const noexcept {
    if (empty_nogood_) return true;
    if (sparse_intersects(partners(a).sparse(), base.sparse())) return true;
    if (a.value < not_pairs_.size()) {
        const std::uint64_t own_word = a.value / word_bits;
        const std::uint64_t own_bit = std::uint64_t{1} << (a.value % word_bits);
        const auto bw = base.words();
        const auto bi = base.index();
        for (std::uint32_t i : not_pairs_[a.value]) {
            const Entry& n = entries_[i];
            if (!n.live) continue;
            // n minus a within base (a merge of the listed words, so nothing is allocated)?
            bool inside = true;
            std::size_t k = 0;
            for (std::size_t w = 0; w < n.env.words().size() && inside; ++w) {
                const std::uint64_t at = n.env.index()[w];
                const std::uint64_t need = n.env.words()[w] & (at == own_word ? ~own_bit : ~std::uint64_t{0});
                if (need == 0) continue;
                while (k < bi.size() && bi[k] < at) ++k;
                inside = k < bi.size() && bi[k] == at && (need & ~bw[k]) == 0;
            }
            if (inside) return true;
        }
    }
    return at_most_one_.other_member(a, base.sparse());
}

bool NogoodDatabase::larger_with(std::span<const std::uint64_t> words, AssumptionId a, std::uint64_t sig) const noexcept {
    if (a.value >= not_pairs_.size()) return false;
    for (std::uint32_t i : not_pairs_[a.value]) {
        const Entry& n = entries_[i];
        if (n.live && (n.sig & ~sig) == 0 && sparse_subset(n.env.sparse(), words)) return true;
    }
    return false;
}

void NogoodDatabase::set_partner(AssumptionId a, AssumptionId b, bool on) {
    if (partners_.size() <= a.value) partners_.resize(a.value + 1);
    if (on) partners_[a.value].insert(b);
    else partners_[a.value].erase(b);
}

void NogoodDatabase::retire(std::uint32_t entry) {
    Entry& n = entries_[entry];
    if (!n.live) return;
    n.live = false;
    --live_;
    if (n.size == 2) {
        const auto pair = n.env.assumptions();
        set_partner(pair[0], pair[1], false);
        set_partner(pair[1], pair[0], false);
    } else {
        std::vector<Filed>& bucket = filed_[n.filed_under.value];
        auto it = std::find_if(bucket.begin(), bucket.end(), [&](const Filed& f) { return f.entry == entry; });
        QM_ASSERT(it != bucket.end(), "a live nogood is filed");
        *it = bucket.back();
        bucket.pop_back();
    }
}

void NogoodDatabase::add(EnvId id, const Environment& e) {
    QM_REQUIRE(!subsumes(e), "nogood already subsumed by a known nogood");
    if (e.empty()) {
        // {} is nogood: every environment is inconsistent; it is the only minimal nogood.
        for (Entry& n : entries_) n.live = false;
        partners_.clear();
        filed_.clear();
        entries_.push_back(Entry{id, e, 0, 0, AssumptionId{}, true});
        live_ = 1;
        empty_nogood_ = true;
        return;
    }
    const auto as = e.assumptions();
    const auto size = static_cast<std::uint32_t>(as.size());
    // Every superset of e contains each of e's assumptions: scan the smallest of their buckets,
    // testing only the larger nogoods there (an equal one would have subsumed e).
    AssumptionId rarest = as.front();
    for (AssumptionId a : as) {
        if (a.value >= containing_.size() || containing_[a.value].empty()) {
            rarest = a;
            break;
        }
        if (containing_[a.value].size() < containing_[rarest.value].size()) rarest = a;
    }
    const std::uint64_t sig = signature(e.words());
    if (rarest.value < containing_.size())
        for (std::uint32_t i : containing_[rarest.value]) {
            const Entry& n = entries_[i];
            if (n.live && n.size > size && (sig & ~n.sig) == 0 && e.subset_of(n.env)) retire(i);
        }
    const auto index = static_cast<std::uint32_t>(entries_.size());
    entries_.push_back(Entry{id, e, sig, size, as.front(), true});
    ++live_;
    for (AssumptionId a : as) {
        ensure(containing_, a);
        containing_[a.value].push_back(index);
    }
    if (as.size() == 2) {
        ensure(pairs_by_first_, as.back());
        pairs_by_first_[as.back().value].push_back(index);
        set_partner(as[0], as[1], true);
        set_partner(as[1], as[0], true);
    } else {
        // Filed under its assumption with the fewest nogoods filed so far, so that no bucket grows
        // with every nogood of a busy assumption (the highest, say).
        AssumptionId under = as.front();
        for (AssumptionId a : as) {
            const std::size_t here = a.value < filed_.size() ? filed_[a.value].size() : 0;
            const std::size_t best = under.value < filed_.size() ? filed_[under.value].size() : 0;
            if (here < best) under = a;
        }
        if (filed_.size() <= under.value) filed_.resize(under.value + 1);
        filed_[under.value].push_back(Filed{sig, index});
        entries_.back().filed_under = under;
        for (AssumptionId a : as) {
            ensure(not_pairs_, a);
            not_pairs_[a.value].push_back(index);
        }
    }
}

std::optional<std::uint32_t> NogoodDatabase::add_at_most_one(std::span<const AssumptionId> members) {
    const std::optional<std::uint32_t> c = at_most_one_.add(members);
    if (!c || empty_nogood_) return c;
    // A stated nogood holding two members is a superset of their pair: no longer minimal. Each is
    // reached through the buckets of the members it holds.
    const Environment& set = at_most_one_.members(*c);
    for (AssumptionId a : set.assumptions()) {
        if (a.value >= containing_.size()) continue;
        for (std::uint32_t i : containing_[a.value]) {
            const Entry& n = entries_[i];
            if (!n.live) continue;
            std::uint32_t shared = 0;
            for (AssumptionId b : n.env.assumptions()) shared += set.contains(b) ? 1 : 0;
            if (shared >= 2) retire(i);
        }
    }
    return c;
}

std::vector<EnvId> NogoodDatabase::minimal() const {
    std::vector<EnvId> out;
    out.reserve(live_);
    for (const Entry& n : entries_)
        if (n.live) out.push_back(n.id);
    return out;
}

std::vector<EnvId> NogoodDatabase::within(const Environment& e) const {
    std::vector<std::uint32_t> found;
    if (empty_nogood_) {
        for (std::uint32_t i = 0; i < entries_.size(); ++i)
            if (entries_[i].live) found.push_back(i);
    }
    if (!empty_nogood_)
        for (AssumptionId a : e.assumptions()) {
            if (a.value < filed_.size())
                for (const Filed& f : filed_[a.value])
                    if (entries_[f.entry].env.subset_of(e)) found.push_back(f.entry);
            if (a.value < pairs_by_first_.size())
                for (std::uint32_t i : pairs_by_first_[a.value])
                    if (entries_[i].live && entries_[i].env.subset_of(e)) found.push_back(i);
        }
    std::sort(found.begin(), found.end());
    std::vector<EnvId> out;
    out.reserve(found.size());
    for (std::uint32_t i : found) out.push_back(entries_[i].id);
    return out;
}
}  // namespace qm::atms
