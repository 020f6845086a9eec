// atms/nogood_database.cpp: minimal nogoods indexed by highest assumption (by_first_: the first
// bucket a query looks in) and by every assumption.
#include "atms/nogood_database.hpp"

#include "qm/assert.hpp"
#include <algorithm>
#include <bit>

namespace qm::atms {
namespace {
void ensure(std::vector<std::vector<std::uint32_t>>& index, AssumptionId a) {
    if (index.size() <= a.value) index.resize(a.value + 1);
}
}  // namespace

bool NogoodDatabase::subsumes_words(std::span<const std::uint64_t> words, std::size_t first_word) const noexcept {
    if (empty_nogood_) return true;
    // A nogood N is a subset of e only if N's highest assumption is in e: visit just those buckets.
    for (std::size_t w = 0; w < words.size(); ++w) {
        for (std::uint64_t bits = words[w]; bits != 0; bits &= bits - 1) {
            const std::size_t a = (first_word + w) * 64 + static_cast<std::size_t>(std::countr_zero(bits));
            if (a >= by_first_.size()) return false;
            for (std::uint32_t i : by_first_[a]) {
                const Entry& n = entries_[i];
                if (n.live && window_subset(n.env.words(), n.env.first_word(), words, first_word)) return true;
            }
        }
    }
    return false;
}

bool NogoodDatabase::subsumes_with(std::span<const std::uint64_t> words, AssumptionId a) const noexcept {
    if (empty_nogood_) return true;
    if (a.value < partners_.size()) {
        const Environment& p = partners_[a.value];
        if (window_intersects(p.words(), p.first_word(), words, 0)) return true;
    }
    if (a.value >= not_pairs_.size()) return false;
    for (std::uint32_t i : not_pairs_[a.value]) {
        const Entry& n = entries_[i];
        if (n.live && window_subset(n.env.words(), n.env.first_word(), words, 0)) return true;
    }
    return false;
}

void NogoodDatabase::set_partner(AssumptionId a, AssumptionId b, bool on) {
    if (partners_.size() <= a.value) partners_.resize(a.value + 1);
    if (on) partners_[a.value].insert(b);
    else partners_[a.value].erase(b);
}

void NogoodDatabase::add(EnvId id, const Environment& e) {
    QM_REQUIRE(!subsumes(e), "nogood already subsumed by a known nogood");
    if (e.empty()) {
        // {} is nogood: every environment is inconsistent; it is the only minimal nogood.
        for (Entry& n : entries_) n.live = false;
        partners_.clear();
        entries_.push_back(Entry{id, e, true});
        live_ = 1;
        empty_nogood_ = true;
        return;
    }
    const auto as = e.assumptions();
    // Every superset of e contains each of e's assumptions: scan the smallest of their buckets.
    AssumptionId rarest = as.front();
    for (AssumptionId a : as) {
        if (a.value >= containing_.size() || containing_[a.value].empty()) {
            rarest = a;
            break;
        }
        if (containing_[a.value].size() < containing_[rarest.value].size()) rarest = a;
    }
    if (rarest.value < containing_.size()) {
        for (std::uint32_t i : containing_[rarest.value]) {
            Entry& n = entries_[i];
            if (n.live && e.subset_of(n.env)) {
                n.live = false;
                --live_;
                if (n.env.size() == 2) {
                    const auto pair = n.env.assumptions();
                    set_partner(pair[0], pair[1], false);
                    set_partner(pair[1], pair[0], false);
                }
            }
        }
    }
    const auto index = static_cast<std::uint32_t>(entries_.size());
    entries_.push_back(Entry{id, e, true});
    ++live_;
    ensure(by_first_, as.back());
    by_first_[as.back().value].push_back(index);
    for (AssumptionId a : as) {
        ensure(containing_, a);
        containing_[a.value].push_back(index);
    }
    if (as.size() == 2) {
        set_partner(as[0], as[1], true);
        set_partner(as[1], as[0], true);
    } else {
        for (AssumptionId a : as) {
            ensure(not_pairs_, a);
            not_pairs_[a.value].push_back(index);
        }
    }
}

std::vector<EnvId> NogoodDatabase::minimal() const {
    std::vector<EnvId> out;
    out.reserve(live_);
    for (const Entry& n : entries_)
        if (n.live) out.push_back(n.id);
    return out;
}
}  // namespace qm::atms
