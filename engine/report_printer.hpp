// engine/report_printer.hpp
// Provides:   print_report(), the text form of a RunReport (engine/run_report.hpp) for `qm-atms run`:
//             each fact with its label, the minimal nogoods (a choice set too large to list its
//             pairwise ones as one line "any two of the N assumptions {...} of the choice set at
//             FILE:LINE:COL (K nogoods, not listed)"), and the interpretations.
// Knows nothing of the ATMS.
#pragma once
#include "engine/run_report.hpp"
#include <string>

namespace qm::engine {
[[nodiscard]] std::string print_report(const RunReport& report);
}
