// tests/atms/sparse_words.hpp
// Test helper (not a test): an Environment written as SparseWords (atms/environment.hpp), the form
// weave's unions take, zero words listed or not, for the nogood database's and the at-most-one
// index's sparse questions; and an Environment without one assumption. Shared by those two tests.
#pragma once
#include "atms/environment.hpp"
#include <algorithm>
#include <cstdint>
#include <vector>

namespace qm::atms::test {

// e as SparseWords: its non-zero words only, or (all_words) every word of its window, zero words
// listed too. The vectors must outlive the view.
inline SparseWords sparse(const Environment& e, bool all_words, std::vector<std::uint64_t>& words,
                          std::vector<std::uint64_t>& index) {
    words.clear();
    index.clear();
    const auto window = e.window();
    for (std::size_t w = 0; w < window.size(); ++w) {
        if (window[w] == 0 && !all_words) continue;
        words.push_back(window[w]);
        index.push_back(e.first_word() + w);
    }
    return {words, index};
}

// e without a.
inline Environment without(const Environment& e, AssumptionId a) {
    std::vector<AssumptionId> rest = e.assumptions();
    rest.erase(std::remove(rest.begin(), rest.end(), a), rest.end());
    return Environment::of(rest);
}

}  // namespace qm::atms::test
