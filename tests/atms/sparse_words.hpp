// tests/atms/sparse_words.hpp
// Test helper (not a test): an Environment written as SparseWords (atms/environment.hpp), the form
// weave's unions take, so that the nogood database's and the at-most-one index's sparse questions
// can be asked of the same sets as their window questions. Shared by those two tests.
#pragma once
#include "atms/environment.hpp"
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

}  // namespace qm::atms::test
