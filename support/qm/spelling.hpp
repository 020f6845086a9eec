// support/qm/spelling.hpp
// Provides:   edit_distance() (optimal string alignment: insertions, deletions, substitutions and
//             swaps of two neighbours each cost 1) and nearest_spelling(), the "did you mean" of
//             every message that names something unknown: a misspelt predicate in a rule file, a
//             command or a name typed in the interactive mode; and nearest_keyword(), the same for a
//             keyword of a scene or an option of a command, which also takes a verb for its noun
//             (`rotate` for `rotation`).
// Invariants: nearest_spelling() proposes only a candidate close enough to be a slip of the hand:
//             at most 1 edit for words of up to 4 characters, 2 up to 10, 3 beyond, and fewer edits
//             than either word has characters (a one-letter word is never "near" another); the
//             nearest wins, ties go to the candidate given first; an exact match is never proposed.
// Knows nothing of what the words mean.
#pragma once
#include <algorithm>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace qm {

[[nodiscard]] inline std::size_t edit_distance(std::string_view a, std::string_view b) {
    // Three rows of the dynamic programme: the one before the previous is needed for swaps.
    std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = a[i - 1] == b[j - 1] ? 0 : 1;
            row[j] = std::min({previous[j] + 1, row[j - 1] + 1, previous[j - 1] + cost});
            if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) row[j] = std::min(row[j], before[j - 2] + 1);
        }
        std::swap(before, previous);
        std::swap(previous, row);
    }
    return previous[b.size()];
}

// The edits a word of this length may be away from a proposal.
[[nodiscard]] constexpr std::size_t spelling_tolerance(std::size_t length) noexcept {
    return length <= 4 ? 1 : length <= 10 ? 2 : 3;
}

// The candidate nearest to word within spelling_tolerance, if any. Range: strings or string_views.
template <class Range>
[[nodiscard]] std::optional<std::string> nearest_spelling(std::string_view word, const Range& candidates) {
    std::optional<std::string> best;
    std::size_t best_distance = spelling_tolerance(word.size()) + 1;
    for (const auto& c : candidates) {
        const std::string_view candidate(c);
        if (candidate == word) continue;
        const std::size_t longer = std::max(candidate.size(), word.size());
        const std::size_t shorter = std::min(candidate.size(), word.size());
        if (longer - shorter >= best_distance) continue;  // cannot be nearer
        const std::size_t d = edit_distance(word, candidate);
        if (d >= word.size() || d >= candidate.size()) continue;  // nothing in common: `n` is no slip for `<`
        if (d < best_distance) {
            best_distance = d;
            best = std::string(candidate);
        }
    }
    return best;
}

// nearest_spelling(), else the one candidate that begins with all of word but its last letter
// (at least four letters kept): a keyword written as the verb of its noun, `translate` for
// `translation`, is more edits away than a slip of the hand but no less plainly meant.
template <class Range>
[[nodiscard]] std::optional<std::string> nearest_keyword(std::string_view word, const Range& candidates) {
    if (auto near = nearest_spelling(word, candidates)) return near;
    if (word.size() < 5) return std::nullopt;
    const std::string_view stem = word.substr(0, word.size() - 1);
    std::optional<std::string> only;
    for (const auto& c : candidates) {
        const std::string_view candidate(c);
        if (!candidate.starts_with(stem) || candidate == word) continue;
        if (only) return std::nullopt;  // two nouns of that stem: no guess
        only = std::string(candidate);
    }
    return only;
}

// "; did you mean 'X'?" when a near candidate exists, else "": appended to a message.
template <class Range>
[[nodiscard]] std::string did_you_mean(std::string_view word, const Range& candidates) {
    auto near = nearest_spelling(word, candidates);
    return near ? "; did you mean '" + *near + "'?" : std::string();
}

}  // namespace qm
