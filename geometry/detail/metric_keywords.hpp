// geometry/detail/metric_keywords.hpp
// Provides:   the keyword positions of the metric-scene grammar (metric_scene_parser_def.hpp), each
//             with its keywords and what it takes, for the message of a word that is none of them
//             (qm/keyword_slot.hpp): the parser's at every position, the checker's for a generator
//             item naming no generator (metric_part_checker.cpp).
// Ownership:  static slots, built on first use.
// Invariants: each slot lists the keywords of its rules in the grammar, as docs/METRIC_SCENE_FORMAT.md
//             spells them; every_keyword() is their union, lower case.
#pragma once
#include "qm/keyword_slot.hpp"
#include <string>
#include <vector>

namespace qm::geometry::detail {

[[nodiscard]] const std::vector<std::string>& every_keyword();
[[nodiscard]] const KeywordSlot& defmechanism_keywords();
[[nodiscard]] const KeywordSlot& section_keywords();
[[nodiscard]] const KeywordSlot& part_item_keywords();  // the items and the generators (geometry/part_generators.hpp)
[[nodiscard]] const KeywordSlot& step_keywords();
[[nodiscard]] const KeywordSlot& limits_keywords();
[[nodiscard]] const KeywordSlot& sense_keywords();
[[nodiscard]] const KeywordSlot& pair_item_keywords();
[[nodiscard]] const KeywordSlot& force_item_keywords();

}  // namespace qm::geometry::detail
