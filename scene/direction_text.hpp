// scene/direction_text.hpp
// Provides:   conversions of qualitative directions (scene::Direction) to and from the two spellings
//             in use: the thesis' `(+ 0 -)` (output, --why) and the rule engine's sign string "+0-",
//             and the canonical order of directions (lexicographic over + 0 -, Definition 1).
// Ownership:  pure functions on values.
#pragma once
#include "scene/scene.hpp"
#include <string>
#include <string_view>
#include <vector>

namespace qm::scene {
[[nodiscard]] std::string thesis_text(const Direction& d);   // "(+ 0 -)"
[[nodiscard]] std::string sign_string(const Direction& d);   // "+0-"
// Pre: s holds only + 0 -.
[[nodiscard]] Direction from_sign_string(std::string_view s);
// Every direction with n components, in canonical order: (+ +) (+ 0) (+ -) (0 +) ... (- -).
[[nodiscard]] std::vector<Direction> all_directions(std::size_t n);
// Canonical order: + before 0 before -, component by component.
[[nodiscard]] bool canonical_less(const Direction& a, const Direction& b);
[[nodiscard]] bool is_zero(const Direction& d);
}  // namespace qm::scene
