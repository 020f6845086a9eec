// engine/why_printer.hpp
// Provides:   print_why(), the text form of a Why (engine/why.hpp): one line per justification step,
//             "  (fact) <= rule NAME at FILE:LINE {?x = v, ...}: antecedent, ...".
// Knows nothing of the ATMS.
#pragma once
#include "engine/why.hpp"
#include <string>

namespace qm::engine {
[[nodiscard]] std::string print_why(const Why& why);
}
