// envision/json_printer.hpp
// Provides:   write_json(), the envisionment as JSON, schema qm-envisionment/1 (docs/ENVISION.md):
//   {"schema": "qm-envisionment/1", "mechanism": NAME,
//    "chains": [{"index": I, "objects": [NAME...], "pairs": [{"parts": [A, B], "places": N}...],
//                "states": [{"id": ID, "places": [{"parts": [A, B], "place": P}...],
//                            "motions": {OBJ: "(+)"|"(0)"|"(-)"},
//                            "net_force": {OBJ: "(+)"|"(0)"|"(-)"|"(?)"}}...],
//                "transitions": [{"from": ID, "to": ID, "duration": "instant"|"interval",
//                                 "causes": ["kinematic"|"dynamic"|"collision"...]}...],
//                "cycles": [[ID...]...],
//                "transient_cycles": [{"states": [ID...], "object": NAME, "motion": "(+)"|"(-)",
//                                      "kept_by": "A/B"?}...],
//                "terminal": [ID...], "possible_rests": [ID...]}]}
//             `cycles` can repeat; a transient cycle cannot (its object moves one way throughout
//             along a bounded coordinate, or, with `kept_by`, along one that the places of that pair
//             in the cycle keep from coming round); `terminal` lists where behaviour may end: the states with
//             no transition and the possible rests (states that may also rest, beside their
//             transitions), which `possible_rests` lists alone.
//             I is the chain's number as the text output prints it (from 1); P is the place's id in
//             `qm-atms --places MECH.def --json` for that pair; IDs number a chain's states from 0
//             in a fixed order (envision/state_space.hpp), stable across runs.
// Ownership:  writes one line (and a newline) to the stream given.
#pragma once
#include "envision/envisionment.hpp"
#include <ostream>

namespace qm::envision {
void write_json(std::ostream& os, const geometry::Mechanism& m, const Envisionment& e);
}
