// analysis/why_printer.hpp
// Provides:   the two forms of a "why" answer (Analysis::why, docs/OUTPUT.md "The text of --why"):
//             - print_why(): for people. The first line is the verdict with the decisive law and its
//               thesis citation; then the notes; then each reason (a minimal nogood or a case-analysis
//               branch) as a derivation tree in which a subtree met again is not repeated but referred
//               to by the number it was given where first shown (`[3]`), every law named by rule,
//               citation and file:line relative to the rules folder, and a closed-world step naming
//               the facts whose absence it used; then the responsible sets. By default trees are cut
//               at WhyPrintOptions::depth and the reasons at WhyPrintOptions::reasons, saying what was
//               left out; `full` prints everything.
//             - write_why_json(): for programs: every tree whole (nothing cut), each node with its
//               citation, the `not` conditions it relied on, and `ref`, the number of a subtree that
//               occurs more than once (the text's `[N]`; null for the others).
// Ownership:  writes to the stream given; keeps nothing.
#pragma once
#include "analysis/analysis.hpp"
#include <cstddef>
#include <ostream>

namespace qm::analysis {

struct WhyPrintOptions {
    bool full = false;          // every reason, every step
    std::size_t depth = 3;      // levels of a tree below its root shown when not full
    std::size_t reasons = 1;    // reasons whose derivation is shown when not full (the others: a line each)
};

void print_why(std::ostream& os, const WhyAnswer& w, const WhyPrintOptions& options = {});
void write_why_json(std::ostream& os, const WhyAnswer& w);

}  // namespace qm::analysis
