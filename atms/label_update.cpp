// atms/label_update.cpp: weave, de Kleer 1986 section 4 (BPS atms.lisp `weave`).
//
// Why the unions are raw bitsets and not interned environments: a weave over labels of sizes
// m1..mk forms up to m1*...*mk unions, and nearly all of them are either inconsistent or subsumed
// before the weave ends. Interning each one (as BPS's union-env does) made the environment table
// grow ~40x larger than all labels together on the random theories of bench/atms, and every new
// nogood scans that table (Atms::new_nogood). So the intermediate unions live in one flat scratch
// array of fixed-width bitsets, and only the final minimal, consistent unions are interned.
#include "atms/label_update.hpp"

#include "atms/detail/minimal_sets.hpp"
#include <algorithm>
#include <cstdint>
#include <utility>

namespace qm::atms {
using detail::BitsetPool;
using detail::MinimalFilter;

namespace {
// Appends env to the pool as a row of the window starting at word `first` (Pre: env lies inside).
void push(BitsetPool& pool, const Environment& env, std::size_t first) {
    std::uint64_t* row = pool.push({});
    if (!env.empty()) std::copy(env.words().begin(), env.words().end(), row + (env.first_word() - first));
}
}  // namespace

std::vector<EnvId> weave(EnvironmentTable& table, const NogoodDatabase& nogoods, std::vector<EnvId> envs,
                         std::span<const Label* const> labels) {
    detail::WeaveScratch scratch;
    return weave(table, nogoods, envs, labels, scratch);
}

std::vector<EnvId> weave(EnvironmentTable& table, const NogoodDatabase& nogoods, std::span<const EnvId> envs,
                         std::span<const Label* const> labels, detail::WeaveScratch& scratch) {
    // All unions are formed in the window of words [first, last) that holds every involved
    // assumption, so with thousands of assumptions an env of nearby ones stays a few words wide.
    std::size_t first = SIZE_MAX, last = 0;
    auto widen = [&](EnvId e) {
        const Environment& env = table[e];
        if (env.empty()) return;
        first = std::min(first, env.first_word());
        last = std::max(last, env.end_word());
    };
    for (EnvId e : envs) widen(e);
    for (const Label* label : labels) {
        if (label->empty()) return {};
        for (EnvId l : *label) widen(l);
    }
    if (first > last) first = last = 0;  // only empty environments
    const std::size_t width = last - first;
    BitsetPool& current = scratch.current;
    current.reset(width);
    for (EnvId e : envs)
        if (!table.is_nogood(e)) push(current, table[e], first);
    BitsetPool& unions = scratch.unions;
    BitsetPool& minimal = scratch.minimal;
    unions.reset(width);
    minimal.reset(width);
    MinimalFilter& filter = scratch.filter;
    bool tested = true;  // every row of current is known consistent
    for (const Label* label : labels) {
        if (current.size() == 1 && label->size() == 1) {
            // One union of one env with one env (e.g. a nogood between two assumptions): formed in
            // place; its consistency is tested once, after the last label.
            const Environment& le = table[label->front()];
            std::uint64_t* row = current.row(0);
            for (std::size_t w = 0; w < le.words().size(); ++w) row[le.first_word() - first + w] |= le.words()[w];
            tested = false;
            continue;
        }
        unions.clear();
        for (std::size_t i = 0; i < current.size(); ++i) {
            const auto c = current[i];
            for (EnvId l : *label) {
                std::uint64_t* u = unions.push(c);
                const Environment& le = table[l];
                if (le.empty()) continue;
                std::uint64_t* at = u + (le.first_word() - first);
                for (std::size_t w = 0; w < le.words().size(); ++w) at[w] |= le.words()[w];
            }
        }
        // Drop the inconsistent unions (they can never support the consequent) only after
        // minimising: a superset of an inconsistent set is inconsistent, so the minimal consistent
        // unions are exactly the consistent minimal ones, and most unions never reach the nogood
        // test. Measured on bench/atms's deep random theories, testing every union first spent
        // 85% of the time in the nogood database.
        filter.keep_minimal(unions, minimal);
        current.clear();
        for (std::size_t i = 0; i < minimal.size(); ++i)
            if (!nogoods.subsumes_words(minimal[i], first)) current.push(minimal[i]);
        tested = true;
        if (current.size() == 0) break;
    }
    if (!tested && nogoods.subsumes_words(current[0], first)) current.clear();
    std::vector<EnvId> out;
    out.reserve(current.size());
    for (std::size_t i = 0; i < current.size(); ++i)
        out.push_back(table.intern_consistent(Environment::from_words(current[i], first), nogoods));
    return out;
}
}  // namespace qm::atms
