// envision/table_printer.hpp
// Provides:   write_table(), each chain's transition table in the layout of the thesis' Appendices
//             A-D: one row per place vector, one column per motion combination of one pair's two
//             parts (-- -0 -+ 0- 00 0+ +- +0 ++, the first part's motion first), each cell the next
//             states of the state with that place vector and those motions, as `PLACE m1 m2`.
//             The pair whose parts give the columns is the chain's pair with the most places (the
//             escapement in the clock, 9.1.5); rows and cells name only the places of pairs with more
//             than one place (Appendix A: "locations are numbered according to the current place of
//             the escapement"), joined by `/`. Where other objects' motions are not fixed by the
//             column's, each of the cell's states gets its own lines, headed by those motions in
//             brackets. A blank cell: no such state (its motion is constrained there); `.`: a state
//             with no transition (terminal). A transition over an instant is marked `i` (Table
//             5.1's subscript).
// Ownership:  writes to the stream given.
#pragma once
#include "envision/envisionment.hpp"
#include <ostream>

namespace qm::envision {
void write_table(std::ostream& os, const geometry::Mechanism& m, const Envisionment& e);
}
