// envision/progress.hpp
// Provides:   Progress, what the envisioner reports while it works (a phase, work done of a total),
//             for a caller that draws a progress bar; the envisioner never prints.
#pragma once
#include <cstddef>
#include <functional>
#include <string>

namespace qm::envision {
struct Progress {
    std::string phase;      // e.g. "chain 1: states", "chain 1: transitions"
    std::size_t done = 0;
    std::size_t total = 0;  // 0 when unknown
};
using ProgressFn = std::function<void(const Progress&)>;
}  // namespace qm::envision
