// envision/dot_printer.hpp
// Provides:   write_dot(), the envisionment as a Graphviz digraph (--dot), drawn as
//             the thesis' Figures 9.21-9.24 group it: each behavioural cycle a cluster (a transient
//             one dashed), terminal states and possible rests doubled, transitions over an instant
//             dashed, collisions red, changes of motion by force blue, changes of place black.
// Ownership:  writes to the stream given.
#pragma once
#include "envision/envisionment.hpp"
#include <ostream>

namespace qm::envision {
void write_dot(std::ostream& os, const Envisionment& e);
}
