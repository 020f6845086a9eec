// scene/vocabulary.hpp
// Provides:   the predicate names through which the Alex driver and the laws in rules/ talk: what the
//             driver asserts about a scene, and what it reads back. The laws themselves (which facts
//             follow from which) live only in rules/*.rules; docs/ANALYSIS.md documents each name.
// Invariants: every name is a kebab-case predicate of the rule language, as the thesis names it.
// Knows no law of mechanics.
#pragma once
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
inline constexpr std::string_view trans_nearness = "trans-nearness";      // (trans-nearness O T K), Def 38
inline constexpr std::string_view rot_nearness = "rot-nearness";
inline constexpr std::string_view touch = "touch";                        // (touch P Q NORMALS), Def 19: a contact the laws use
}  // namespace qm::scene::vocabulary
