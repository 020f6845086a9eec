// envision/text_printer.hpp
// Provides:   write_text(), the envisionment as `qm-atms envision` prints it by default (docs/
//             ENVISION.md): per kinematic chain its objects, its pairs with their place counts, the
//             numbers of states and transitions, the behavioural cycles, the transient ones (with
//             the object that rules them out), the terminal states and the possible rests (counted
//             with them), each state as `#ID NAME` (the first 12 of each list, then how many more);
//             then a summary line.
// Ownership:  writes to the stream given; keeps nothing.
#pragma once
#include "envision/envisionment.hpp"
#include <ostream>

namespace qm::envision {
void write_text(std::ostream& os, const geometry::Mechanism& m, const Envisionment& e);
}
