// bridge/clock_vocabulary.hpp
// Provides:   the predicate and constant names through which the envisioner talks to its laws
//             (rules/clock/*.rules): what the bridge asserts and what the driver reads back. The
//             names are the rule files' own; the meaning of each is stated in bridge/place_facts.hpp
//             (premises and assumptions) and in the rule file that concludes it (conclusions).
// Knows nothing of any law: which fact follows from which is only in rules/clock/.
#pragma once
#include <initializer_list>

namespace qm::bridge::clock {
// ---- premises (bridge/place_facts.hpp) ----
inline constexpr const char* pair = "pair";                      // (pair P A B)
inline constexpr const char* pair_places = "pair-places";        // (pair-places P SET)
inline constexpr const char* axis = "axis";                      // (axis P I periodic|bounded)
inline constexpr const char* clock_object = "clock-object";      // (clock-object O)
inline constexpr const char* possible_motions = "possible-motions";  // (possible-motions O SET)
inline constexpr const char* fixed_part = "fixed-part";          // (fixed-part O)
inline constexpr const char* linkage = "linkage";                // (linkage A B)
inline constexpr const char* cause = "cause";                    // (cause C)
inline constexpr const char* place_kind = "place-kind";          // (place-kind P PLACE KIND)
inline constexpr const char* join_kind = "join-kind";            // (join-kind P PLACE KIND)
inline constexpr const char* place_normal = "place-normal";      // (place-normal P PLACE N)
inline constexpr const char* place_normals = "place-normals";    // (place-normals P PLACE SET)
inline constexpr const char* join_concave = "join-concave";      // (join-concave P PLACE)
inline constexpr const char* join_convex = "join-convex";        // (join-convex P PLACE)
inline constexpr const char* gap_place = "gap-place";            // (gap-place P PLACE)
inline constexpr const char* adjacent = "adjacent";              // (adjacent P PLACE NEXT V DURATION)
inline constexpr const char* force_sign_at = "force-sign-at";    // (force-sign-at P PLACE O S C)
inline constexpr const char* constant_force = "constant-force";  // (constant-force O S C)
inline constexpr const char* places_apart = "places-apart";      // (places-apart P PLACE Q PLACE2)
inline constexpr const char* current_place = "current-place";    // (current-place P PLACE)
inline constexpr const char* current_motion = "current-motion";  // (current-motion O M)
// ---- assumptions ----
inline constexpr const char* external_force = "external-force";  // (external-force O C)
// ---- conclusions the driver reads ----
inline constexpr const char* at = "at";                          // (at P PLACE): choice set, states.rules
inline constexpr const char* motion = "motion";                  // (motion O M): choice set, states.rules
inline constexpr const char* blocked_motion = "blocked-motion";  // (blocked-motion P PLACE V)
inline constexpr const char* arrival = "arrival";                // (arrival P PLACE HOW V AFTER)
inline constexpr const char* collision = "collision";            // (collision P PLACE V AFTER): that arrival is a collision
inline constexpr const char* place_change = "place-change";      // (place-change HOW): reaching a place so changes it
inline constexpr const char* step_allows = "step-allows";        // (step-allows O H): an assumption, nearness.rules
// One object's situation in a hypothesised step, each an assumption (settling.rules).
inline constexpr const char* step_forbids = "step-forbids";          // (step-forbids O H)
inline constexpr const char* motion_now = "motion-now";              // (motion-now O C)
inline constexpr const char* collision_fixes = "collision-fixes";    // (collision-fixes O F)
inline constexpr const char* no_collision = "no-collision";          // (no-collision O)
inline constexpr const char* next_motion = "next-motion";            // (next-motion O M)
inline constexpr const char* step_reachable = "step-reachable";      // (step-reachable O)
inline constexpr const char* step_unreachable = "step-unreachable";  // (step-unreachable O)
inline constexpr const char* step = "step";                      // (step S DURATION CAUSE)
inline constexpr const char* place_option = "place-option";      // (place-option S P NEXT HOW)
inline constexpr const char* motion_option = "motion-option";    // (motion-option S O M)
inline constexpr const char* preempts = "preempts";              // (preempts S T)
inline constexpr const char* may_rest = "may-rest";              // (may-rest): the state may also stay as it is
inline constexpr const char* force_on = "force-on";              // (force-on O S C)
inline constexpr const char* net_force = "net-force";            // (net-force O S)

// What a chain's state-space engine is given and read for (envision/state_space.hpp), and what one
// state's engine is (envision/state_dynamics.hpp): the envisioner gives each engine only the laws
// that can matter for these (engine/program_slice.hpp).
inline const std::initializer_list<const char*> state_space_inputs{
    pair, pair_places, axis, clock_object, possible_motions, fixed_part, linkage, place_kind, join_kind, place_normal,
    place_normals, join_concave, join_convex, gap_place, adjacent, force_sign_at, places_apart};
inline const std::initializer_list<const char*> state_space_outputs{at, motion, arrival, collision, place_change};
inline const std::initializer_list<const char*> state_inputs{
    pair, axis, place_kind, join_kind, clock_object, fixed_part, linkage, cause, place_normal, place_normals, join_concave, join_convex, gap_place,
    adjacent, force_sign_at, constant_force, current_place, current_motion, external_force};
inline const std::initializer_list<const char*> state_outputs{step, place_option, motion_option, preempts, may_rest, force_on, net_force};
}  // namespace qm::bridge::clock
