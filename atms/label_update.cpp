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
// ORs env into a row over `index` (SparseWords): each non-zero word of env at its listed position.
// Pre: every non-zero word of env is listed.
void place(std::uint64_t* row, const Environment& env, std::span<const std::uint64_t> index) {
    const auto words = env.words();
    auto at = index.begin();
    for (std::size_t w = 0; w < words.size(); ++w) {
        at = std::lower_bound(at, index.end(), env.index()[w]);
        row[at - index.begin()] |= words[w];
    }
}
}  // namespace

std::vector<EnvId> weave(EnvironmentTable& table, const NogoodDatabase& nogoods, std::vector<EnvId> envs,
                         std::span<const Label* const> labels) {
    detail::WeaveScratch scratch;
    return weave(table, nogoods, envs, labels, scratch);
}

std::vector<EnvId> weave(EnvironmentTable& table, const NogoodDatabase& nogoods, std::span<const EnvId> envs,
                         std::span<const Label* const> labels, detail::WeaveScratch& scratch) {
    // All unions are formed over the words that some involved env has non-zero (SparseWords,
    // environment.hpp), not over the window from the lowest to the highest involved assumption: an
    // env that holds a situation's assumption (among the first created) and an object's choices
    // (created as the rules reach the object) spans a window that grows with the scene, and every
    // union, subset test and nogood test paid for it (docs/perf/alex.md, "Sparse unions in weave").
    std::vector<std::uint64_t>& index = scratch.index;
    index.clear();
    auto collect = [&](EnvId e) {
        const auto words = table[e].index();
        index.insert(index.end(), words.begin(), words.end());
    };
    for (EnvId e : envs) collect(e);
    for (const Label* label : labels) {
        if (label->empty()) return {};
        for (EnvId l : *label) collect(l);
    }
    std::sort(index.begin(), index.end());
    index.erase(std::unique(index.begin(), index.end()), index.end());
    const std::size_t width = index.size();
    BitsetPool& current = scratch.current;
    current.reset(width);
    for (EnvId e : envs)
        if (!table.is_nogood(e)) place(current.push({}), table[e], index);
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
            place(current.row(0), table[label->front()], index);
            tested = false;
            continue;
        }
        // Each env of the label as its row over index, once, rather than placed again per union.
        BitsetPool& placed = scratch.placed;
        placed.reset(width);
        for (EnvId l : *label) place(placed.push({}), table[l], index);
        unions.clear();
        for (std::size_t i = 0; i < current.size(); ++i) {
            const auto c = current[i];
            for (std::size_t k = 0; k < placed.size(); ++k) {
                std::uint64_t* u = unions.push(c);
                const auto p = placed[k];
                for (std::size_t w = 0; w < width; ++w) u[w] |= p[w];
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
            if (!nogoods.subsumes_sparse({minimal[i], index})) current.push(minimal[i]);
        tested = true;
        if (current.size() == 0) break;
    }
    if (!tested && nogoods.subsumes_sparse({current[0], index})) current.clear();
    std::vector<EnvId> out;
    out.reserve(current.size());
    for (std::size_t i = 0; i < current.size(); ++i)
        out.push_back(table.intern_consistent(Environment::from_sparse({current[i], index}), nogoods));
    return out;
}
}  // namespace qm::atms
