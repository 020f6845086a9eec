// atms/nogood_database.cpp: minimal nogoods indexed by lowest assumption and by every assumption.
#include "atms/nogood_database.hpp"

#include "qm/assert.hpp"

namespace qm::atms {
namespace {
void ensure(std::vector<std::vector<std::uint32_t>>& index, AssumptionId a) {
    if (index.size() <= a.value) index.resize(a.value + 1);
}
}  // namespace

bool NogoodDatabase::subsumes(const Environment& e) const noexcept {
    if (empty_nogood_) return true;
    // A nogood N is a subset of e only if N's highest assumption is in e: visit just those buckets.
    for (AssumptionId a : e.assumptions()) {
        if (a.value >= by_first_.size()) break;
        for (std::uint32_t i : by_first_[a.value]) {
            const Entry& n = entries_[i];
            if (n.live && n.env.subset_of(e)) return true;
        }
    }
    return false;
}

bool NogoodDatabase::subsumes_with(std::span<const std::uint64_t> words, AssumptionId a) const noexcept {
    if (empty_nogood_) return true;
    if (a.value >= containing_.size()) return false;
    for (std::uint32_t i : containing_[a.value]) {
        const Entry& n = entries_[i];
        if (n.live && words_subset(n.env.words(), words)) return true;
    }
    return false;
}

void NogoodDatabase::add(EnvId id, const Environment& e) {
    QM_REQUIRE(!subsumes(e), "nogood already subsumed by a known nogood");
    if (e.empty()) {
        // {} is nogood: every environment is inconsistent; it is the only minimal nogood.
        for (Entry& n : entries_) n.live = false;
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
}

std::vector<EnvId> NogoodDatabase::minimal() const {
    std::vector<EnvId> out;
    out.reserve(live_);
    for (const Entry& n : entries_)
        if (n.live) out.push_back(n.id);
    return out;
}
}  // namespace qm::atms
