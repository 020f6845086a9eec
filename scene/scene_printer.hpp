// scene/scene_printer.hpp
// Provides:   print_scene (a checked Scene in the s-expression notation of Figure 6.1) and
//             print_scene_keywords (the `Keyword : items` notation of Figures 7.12/7.16), both as
//             documented in docs/SCENE_FORMAT.md, plus print_pattern. Corners and
//             Linkages sections are written only when the scene has corners or linkages.
// Invariants: for every checked Scene s, reading print_scene(s) or print_scene_keywords(s) back
//             gives a Scene equal to s (tests/scene/scene_printer_test.cpp). Implicit causes
//             ("force#N") are not printed; explicit ones are, after the force's origin.
// Ownership:  returns strings; never prints to a stream of its own.
#pragma once
#include "scene/scene.hpp"
#include <string>

namespace qm::scene {

[[nodiscard]] std::string print_pattern(const DirectionPattern& p);   // "(?x 0)"
[[nodiscard]] std::string print_scene(const Scene& scene);
[[nodiscard]] std::string print_scene_keywords(const Scene& scene);

}  // namespace qm::scene
