// support/qm/keyword_slot.hpp
// Provides:   KeywordSlot, the keywords that may stand at one position of a scene language, and
//             unknown_word_message(), what a reader says of a word that is none of them:
//               unknown word 'polygn': expected a part item (polygon, ...); did you mean 'polygon'?
//             with the nearest keyword (qm/spelling.hpp nearest_keyword; keywords compare without
//             case), or, for a keyword of another position, `expected a part item (...) but found
//             'torque'`: misplaced, not unknown.
// Ownership:  a slot is a value; `elsewhere` points at a list that outlives it.
// Knows nothing of any one language or parser: the slots are the grammar's (e.g.
// geometry/detail/metric_keywords.hpp), the parser is qm/x3_unknown_word.hpp.
#pragma once
#include "qm/spelling.hpp"
#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

namespace qm {

struct KeywordSlot {
    std::string what;                 // what the position takes, e.g. "a step (line x y) or (arc x y cx cy ccw|cw)"
    std::vector<std::string> words;   // its keywords, spelt as the language's documentation writes them
    const std::vector<std::string>* elsewhere = nullptr;  // every keyword of the language, lower case
};

[[nodiscard]] inline std::string ascii_lower(std::string_view s) {
    std::string out(s);
    for (char& c : out) c = c >= 'A' && c <= 'Z' ? static_cast<char>(c - 'A' + 'a') : c;
    return out;
}

// Pre: `written` is none of slot.words (in any case).
[[nodiscard]] inline std::string unknown_word_message(const KeywordSlot& slot, std::string_view written) {
    const std::string word = ascii_lower(written);
    if (slot.elsewhere && std::find(slot.elsewhere->begin(), slot.elsewhere->end(), word) != slot.elsewhere->end())
        return "expected " + slot.what + " but found '" + std::string(written) + "'";
    std::vector<std::string> folded;
    for (const std::string& w : slot.words) folded.push_back(ascii_lower(w));
    std::string message = "unknown word '" + std::string(written) + "': expected " + slot.what;
    if (auto near = nearest_keyword(word, folded)) {
        const auto k = static_cast<std::size_t>(std::find(folded.begin(), folded.end(), *near) - folded.begin());
        message += "; did you mean '" + slot.words[k] + "'?";
    }
    return message;
}

}  // namespace qm
