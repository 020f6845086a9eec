// scene/vocabulary.hpp
// Provides:   the predicate names through which the Alex driver and the laws in rules/ talk: what the
//             driver asserts about a scene, and what it reads back. The laws themselves (which facts
//             follow from which) live only in rules/*.rules; docs/ANALYSIS.md documents each name.
// Invariants: every name is a kebab-case predicate of the rule language, as the thesis names it.
// Knows no law of mechanics.
#pragma once
#include <array>
#include <string_view>

namespace qm::scene::vocabulary {
// Asserted by the driver (premises).
inline constexpr std::string_view dimensions = "dimensions";              // (dimensions N)
inline constexpr std::string_view rigid_body = "rigid-body";              // (rigid-body O), Figure 6.1
inline constexpr std::string_view surface = "surface";                    // (surface O S), Def 15
inline constexpr std::string_view surface_normal = "surface-normal";      // (surface-normal S D), Def 16
inline constexpr std::string_view origin_dir = "origin-dir";              // (origin-dir S D), Def 17
inline constexpr std::string_view corner = "corner";                      // (corner O C S1 S2), Def 18
inline constexpr std::string_view frame_trans_constraint = "frame-trans-constraint";  // (... O D), 6.1
inline constexpr std::string_view frame_rot_constraint = "frame-rot-constraint";      // (... O R), 6.1
inline constexpr std::string_view linkage = "linkage";                    // (linkage A B), Def 21
// Asserted by the driver (assumptions: what a situation says, and what a what-if can take away).
inline constexpr std::string_view contact = "contact";                    // (contact P Q), Def 19
inline constexpr std::string_view external_force = "external-force";      // (external-force O D ORIGIN CAUSE), Def 8
inline constexpr std::string_view given_motion = "given-motion";          // (given-motion O T R), 6.2
// Read back.
inline constexpr std::string_view trans_motion = "trans-motion";          // choice assumptions, Law 1
inline constexpr std::string_view rot_motion = "rot-motion";
inline constexpr std::string_view trans_freedom = "trans-freedom";        // Def 24
inline constexpr std::string_view rot_freedom = "rot-freedom";
inline constexpr std::string_view trans_constraint = "trans-constraint";  // Def 23 (for why)
inline constexpr std::string_view rot_constraint = "rot-constraint";
inline constexpr std::string_view touch = "touch";                        // (touch P Q NORMALS), Def 19: a contact the laws use

// The driver's declaration to the laws: rules/scene_facts.rules states these as `input` and
// `output` items (docs/RULES.md "Declarations"); tests/analysis/scene_vocabulary_test.cpp keeps the
// two equal, so the rule checker knows every fact the driver asserts.
inline constexpr std::array asserted = {dimensions,   rigid_body, surface, surface_normal, origin_dir, corner,
                                        frame_trans_constraint, frame_rot_constraint, linkage, contact,
                                        external_force, given_motion};
// Which motions a force produces is not read back by name: the laws declare it as a `prefer`
// (rules/nearness.rules), which the driver applies through engine/preferences.hpp.
inline constexpr std::array read_back = {trans_motion, rot_motion, trans_freedom, rot_freedom, trans_constraint,
                                         rot_constraint, touch};
}  // namespace qm::scene::vocabulary
