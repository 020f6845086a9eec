// atms/interpretations.cpp: backtracking over choice sets with nogood pruning (de Kleer 1986,
// section 6). The partial choice is one mutable bitset; only complete interpretations are built
// as Environment values, so a search over millions of partial choices allocates nothing per step.
#include "atms/interpretations.hpp"

#include "qm/assert.hpp"

#include <algorithm>

namespace qm::atms {
namespace {
constexpr std::uint32_t word_bits = 64;

struct Search {
    const NogoodDatabase& nogoods;
    const std::vector<std::vector<AssumptionId>>& choices;  // pre-filtered per set
    const std::function<bool(const Environment&)>& visit;
    std::vector<std::uint64_t> words;
    std::size_t visited = 0;

    // Returns false once visit asked to stop.
    bool run(std::size_t depth) {
        if (depth == choices.size()) {
            ++visited;
            return visit(Environment::from_words(words));
        }
        for (AssumptionId a : choices[depth]) {
            std::uint64_t& w = words[a.value / word_bits];
            const std::uint64_t bit = std::uint64_t{1} << (a.value % word_bits);
            if ((w & bit) != 0) {  // already chosen (in base): nothing new can be inconsistent
                if (!run(depth + 1)) return false;
                continue;
            }
            w |= bit;
            // The partial choice was consistent, so a new nogood must contain a.
            const bool ok = !nogoods.subsumes_with(words, a);
            if (ok && !run(depth + 1)) {
                w &= ~bit;
                return false;
            }
            w &= ~bit;
        }
        return true;
    }
};
}  // namespace

std::size_t enumerate_interpretations(const NogoodDatabase& nogoods, std::size_t assumption_count,
                                      std::span<const std::vector<AssumptionId>> choice_sets,
                                      const Environment& base,
                                      const std::function<bool(const Environment&)>& visit) {
    if (nogoods.subsumes(base)) return 0;
    // The partial choice is a plain bitset from word 0 over every assumption.
    std::vector<std::uint64_t> words(std::max(base.end_word(), (assumption_count + word_bits - 1) / word_bits), 0);
    std::copy(base.words().begin(), base.words().end(), words.begin() + static_cast<std::ptrdiff_t>(base.first_word()));
    // Drop choices inconsistent with base alone once, instead of at every node of the search.
    std::vector<std::vector<AssumptionId>> choices;
    choices.reserve(choice_sets.size());
    for (const auto& set : choice_sets) {
        auto& kept = choices.emplace_back();
        // A set the base already picks from keeps only that pick: any other member would make two.
        std::vector<AssumptionId> in_base;
        for (AssumptionId a : set)
            if (base.contains(a) && std::find(in_base.begin(), in_base.end(), a) == in_base.end()) in_base.push_back(a);
        if (in_base.size() > 1) return 0;  // the base itself picks twice from one set
        if (in_base.size() == 1) {
            kept = in_base;
            continue;
        }
        for (AssumptionId a : set) {
            QM_REQUIRE(a.value < assumption_count, "unknown assumption in a choice set");
            std::uint64_t& w = words[a.value / word_bits];
            const std::uint64_t bit = std::uint64_t{1} << (a.value % word_bits);
            w |= bit;
            if (!nogoods.subsumes_with(words, a)) kept.push_back(a);
            w &= ~bit;
        }
        if (kept.empty()) return 0;
    }
    Search search{nogoods, choices, visit, std::move(words)};
    search.run(0);
    return search.visited;
}
}  // namespace qm::atms
