// atms/interpretations.cpp: backtracking over choice sets with nogood pruning (de Kleer 1986,
// section 6), done the way a bitboard N-queens search is. The candidates of all sets are numbered
// in search order, so a set's candidates are one range of bits; picking a candidate excludes, in
// one bitset, every candidate of a later set that it forms a two-assumption nogood with or shares
// an at-most-one constraint with (its exclusion window, computed once). A set's remaining
// candidates are then the clear bits of its range, visited in order; only nogoods of three or more
// assumptions are tested at each pick. The exclusions are undone from a trail, and the partial
// choice is one mutable bitset: only complete interpretations are built as Environment values, so
// the search allocates nothing per step.
#include "atms/interpretations.hpp"

#include "qm/assert.hpp"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <unordered_map>

namespace qm::atms {
namespace {
constexpr std::uint32_t word_bits = 64;

// The candidates ("locals") of every set, in search order: set d holds [start[d], start[d + 1]).
struct Plan {
    std::vector<AssumptionId> assumption;  // local -> assumption
    std::vector<std::uint32_t> start;      // set -> first local; one more entry, the end
    std::vector<std::uint8_t> in_base;     // local -> the base holds it already
    std::vector<std::uint8_t> larger;      // local -> some nogood of size 1 or >= 3 contains it
    // local -> its exclusion window: words excl_words[excl_at[k] .. excl_at[k + 1]) are words
    // excl_first[k] ... of the bitset over locals (only locals of later sets are set).
    std::vector<std::uint32_t> excl_first, excl_at;
    std::vector<std::uint64_t> excl_words;
};

// (assumption, local) for every candidate, sorted: a candidate of an assumption repeated within
// its set appears once per occurrence, side by side.
using LocalIndex = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

// Fills the exclusion windows of plan (assumption, start, in_base, larger already set).
void exclusions(const NogoodDatabase& nogoods, Plan& plan) {
    const auto locals = static_cast<std::uint32_t>(plan.assumption.size());
    LocalIndex by_assumption;
    by_assumption.reserve(locals);
    for (std::uint32_t k = 0; k < locals; ++k) by_assumption.emplace_back(plan.assumption[k].value, k);
    std::sort(by_assumption.begin(), by_assumption.end());
    // constraint -> its members' locals, increasing.
    const AtMostOneIndex& index = nogoods.at_most_one();
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> members;
    if (!index.empty())
        for (std::uint32_t k = 0; k < locals; ++k)
            for (std::uint32_t c : index.of(plan.assumption[k])) members[c].push_back(k);
    plan.excl_first.assign(locals, 0);
    plan.excl_at.assign(locals + 1, 0);
    std::vector<std::uint32_t> hit;
    std::uint32_t set = 0;
    for (std::uint32_t k = 0; k < locals; ++k) {
        while (plan.start[set + 1] <= k) ++set;
        const std::uint32_t later = plan.start[set + 1];
        hit.clear();
        const Environment& partners = nogoods.partners(plan.assumption[k]);
        for (std::size_t w = 0; w < partners.words().size(); ++w)
            for (std::uint64_t bits = partners.words()[w]; bits != 0; bits &= bits - 1) {
                const auto b = static_cast<std::uint32_t>(std::size_t{partners.index()[w]} * word_bits +
                                                          static_cast<std::size_t>(std::countr_zero(bits)));
                for (auto it = std::lower_bound(by_assumption.begin(), by_assumption.end(), std::pair(b, 0U));
                     it != by_assumption.end() && it->first == b; ++it)
                    if (it->second >= later) hit.push_back(it->second);
            }
        for (std::uint32_t c : index.of(plan.assumption[k])) {
            const std::vector<std::uint32_t>& m = members[c];
            for (auto it = std::lower_bound(m.begin(), m.end(), later); it != m.end(); ++it) hit.push_back(*it);
        }
        if (!hit.empty()) {
            const auto [lo, hi] = std::minmax_element(hit.begin(), hit.end());
            plan.excl_first[k] = *lo / word_bits;
            const std::size_t at = plan.excl_words.size();
            plan.excl_words.resize(at + *hi / word_bits - *lo / word_bits + 1, 0);
            for (std::uint32_t j : hit)
                plan.excl_words[at + j / word_bits - plan.excl_first[k]] |= std::uint64_t{1} << (j % word_bits);
        }
        plan.excl_at[k + 1] = static_cast<std::uint32_t>(plan.excl_words.size());
    }
}

// Pre of enumerate_interpretations: known assumptions, none in two sets (checked first, whatever
// the base, in O(K log K) for K members in all).
void require_disjoint(std::span<const std::vector<AssumptionId>> choice_sets, std::size_t assumption_count) {
    LocalIndex owner;  // (assumption, set)
    for (std::uint32_t s = 0; s < choice_sets.size(); ++s)
        for (AssumptionId a : choice_sets[s]) {
            QM_REQUIRE(a.value < assumption_count, "unknown assumption in a choice set");
            owner.emplace_back(a.value, s);
        }
    std::sort(owner.begin(), owner.end());
    for (std::size_t i = 1; i < owner.size(); ++i)
        QM_REQUIRE(owner[i].first != owner[i - 1].first || owner[i].second == owner[i - 1].second,
                   "an assumption occurs in two choice sets");
}

struct Search {
    const NogoodDatabase& nogoods;
    const Plan& plan;
    const std::function<bool(const Environment&)>& visit;
    std::vector<std::uint64_t> words;     // base + the picks so far, from word 0
    std::vector<std::uint64_t> excluded;  // over locals: candidates a pick so far rules out
    std::vector<std::pair<std::uint32_t, std::uint64_t>> trail;  // (word, old value) to undo
    std::size_t base_first = 0, base_end = 0;  // the base's window of words
    std::vector<AssumptionId> picked;          // the picks so far that the base does not hold
    std::vector<std::uint64_t> sigs;           // per depth: the OR of words' words (base + picks)
    Environment current;                       // the interpretation handed to visit, reused
    std::size_t visited = 0;

    // The interpretation found, formed from the window its assumptions span (not from every word).
    const Environment& found() {
        std::size_t lo = base_first, hi = base_end;
        if (lo == hi) lo = SIZE_MAX, hi = 0;
        for (AssumptionId a : picked) {
            lo = std::min<std::size_t>(lo, a.value / word_bits);
            hi = std::max<std::size_t>(hi, a.value / word_bits + 1);
        }
        if (lo >= hi) lo = hi = 0;
        current.assign_words(std::span<const std::uint64_t>(words).subspan(lo, hi - lo), lo);
        return current;
    }

    // Returns false once visit asked to stop.
    bool run(std::size_t depth) {
        if (depth + 1 == plan.start.size()) {
            ++visited;
            return visit(found());
        }
        const std::uint32_t lo = plan.start[depth], hi = plan.start[depth + 1];
        for (std::uint32_t w = lo / word_bits; w * word_bits < hi; ++w) {
            std::uint64_t range = ~std::uint64_t{0};
            if (w == lo / word_bits) range &= ~std::uint64_t{0} << (lo % word_bits);
            if ((w + 1) * word_bits > hi) range &= ~std::uint64_t{0} >> ((w + 1) * word_bits - hi);
            // Deeper levels restore `excluded` before returning, so reading it per word is safe.
            for (std::uint64_t bits = range & ~excluded[w]; bits != 0; bits &= bits - 1)
                if (!pick(depth, w * word_bits + static_cast<std::uint32_t>(std::countr_zero(bits)))) return false;
        }
        return true;
    }

    bool pick(std::size_t depth, std::uint32_t k) {
        const AssumptionId a = plan.assumption[k];
        std::uint64_t& w = words[a.value / word_bits];
        const std::uint64_t bit = std::uint64_t{1} << (a.value % word_bits);
        const bool fresh = plan.in_base[k] == 0;  // a base member: already chosen, nothing new
        sigs[depth + 1] = sigs[depth] | bit;
        if (fresh) {
            w |= bit;
            // The partial choice was consistent and pairs are excluded ahead: only a larger
            // nogood containing a can be violated now.
            if (plan.larger[k] != 0 && nogoods.larger_with(words, a, sigs[depth + 1])) {
                w &= ~bit;
                return true;
            }
            picked.push_back(a);
        }
        const std::size_t mark = trail.size();
        const std::uint32_t first = plan.excl_first[k];
        for (std::uint32_t i = plan.excl_at[k]; i < plan.excl_at[k + 1]; ++i) {
            std::uint64_t& e = excluded[first + i - plan.excl_at[k]];
            const std::uint64_t more = plan.excl_words[i] & ~e;
            if (more == 0) continue;
            trail.emplace_back(static_cast<std::uint32_t>(&e - excluded.data()), e);
            e |= more;
        }
        const bool go_on = run(depth + 1);
        while (trail.size() > mark) {
            excluded[trail.back().first] = trail.back().second;
            trail.pop_back();
        }
        if (fresh) {
            w &= ~bit;
            picked.pop_back();
        }
        return go_on;
    }
};
}  // namespace

std::size_t enumerate_interpretations(const NogoodDatabase& nogoods, std::size_t assumption_count,
                                      std::span<const std::vector<AssumptionId>> choice_sets,
                                      const Environment& base,
                                      const std::function<bool(const Environment&)>& visit) {
    require_disjoint(choice_sets, assumption_count);
    if (nogoods.subsumes(base)) return 0;
    // The partial choice is a plain bitset from word 0 over every assumption.
    std::vector<std::uint64_t> words(std::max(base.end_word(), (assumption_count + word_bits - 1) / word_bits), 0);
    for (std::size_t i = 0; i < base.words().size(); ++i) words[base.index()[i]] = base.words()[i];
    // Drop choices inconsistent with base alone once, instead of at every node of the search.
    Plan plan;
    plan.start.push_back(0);
    for (const auto& set : choice_sets) {
        // A set the base already picks from keeps only that pick: any other member would make two.
        std::vector<AssumptionId> in_base;
        for (AssumptionId a : set)
            if (base.contains(a) && std::find(in_base.begin(), in_base.end(), a) == in_base.end()) in_base.push_back(a);
        if (in_base.size() > 1) return 0;  // the base itself picks twice from one set
        if (in_base.size() == 1) {
            plan.assumption.push_back(in_base.front());
            plan.in_base.push_back(1);
        } else {
            for (AssumptionId a : set) {
                if (!nogoods.excludes(base, a)) {
                    plan.assumption.push_back(a);
                    plan.in_base.push_back(0);
                }
            }
        }
        if (plan.assumption.size() == plan.start.back()) return 0;  // nothing left to pick
        plan.start.push_back(static_cast<std::uint32_t>(plan.assumption.size()));
    }
    for (AssumptionId a : plan.assumption) plan.larger.push_back(nogoods.has_larger(a) ? 1 : 0);
    exclusions(nogoods, plan);
    Search search{nogoods, plan, visit, std::move(words), {}, {}, base.first_word(), base.end_word(), {}, {}, {}, 0};
    search.excluded.assign((plan.assumption.size() + word_bits - 1) / word_bits + 1, 0);
    search.picked.reserve(choice_sets.size());
    search.sigs.assign(choice_sets.size() + 1, 0);
    for (std::uint64_t w : base.words()) search.sigs[0] |= w;
    search.run(0);
    return search.visited;
}
}  // namespace qm::atms
