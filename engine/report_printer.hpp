// engine/report_printer.hpp
// Provides:   print_report(), the text form of a RunReport (engine/run_report.hpp) for `qm-atms run`:
//             each fact with its label, the minimal nogoods, and the interpretations.
// Knows nothing of the ATMS.
#pragma once
#include "engine/run_report.hpp"
#include <string>

namespace qm::engine {
[[nodiscard]] std::string print_report(const RunReport& report);
}
