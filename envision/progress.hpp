// envision/progress.hpp
// Provides:   Progress, what the envisioner reports while it works: the phase, the chain, and the
//             chain's states and transitions found so far, for a caller that draws a progress bar
//             or says how far a run got when a limit stops it; the envisioner never prints.
// Reports:    at the start and the end of every phase, and in between every 4096 states found, or
//             about every 16 states whose transitions are found, so that the caller may read a clock
//             at each report. The end's counts are exact, also when the state limit or an exception
//             (std::bad_alloc under a memory limit) stops the phase. Always from the thread that
//             called envision().
#pragma once
#include <cstddef>
#include <functional>

namespace qm::envision {
struct Progress {
    enum class Phase { places, states, transitions };
    Phase phase = Phase::places;  // the pairs' place vocabularies, then per chain its states, then its transitions
    std::size_t chain = 0;        // the chain's number, from 1; 0 while the place vocabularies are made
    std::size_t states = 0;       // the chain's states found so far
    std::size_t transitions = 0;  // the chain's transitions found so far
    std::size_t done = 0;         // transitions phase: the states whose transitions are all found, of `states`
};
using ProgressFn = std::function<void(const Progress&)>;
}  // namespace qm::envision
