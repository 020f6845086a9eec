// cli/progress_bar.hpp
// Provides:   ProgressBar, the envisioner's progress (envision/progress.hpp) on stderr: one line,
//             redrawn in place at most ten times a second, only when stderr is a terminal and once
//             the run has taken a second. Drawn or not, it keeps how far the run got, for the
//             message of a limit that stops it (run_so_far()), while envisioning or after, while the
//             answer is made. Its texts are pure functions of the counts and seconds,
//             progress_line() and run_so_far_text():
//               chain 1: 12288 states (6144 states/s)
//               chain 1: 950 transitions (1900 transitions/s) [####      ] 600/1378 states
//               finding the transitions of chain 2 of clock.def (after 3.1 s: 2068 states and 4499 transitions found)
// Ownership:  one ProgressBar per run, fed from one thread; it writes to stderr through stdio.
// Knows nothing of the laws: only counts, phases and time.
#pragma once
#include "envision/progress.hpp"
#include <chrono>
#include <cstddef>
#include <string>

namespace qm::cli {

// The line for report p, `seconds` into its phase: what the phase has found and how many a second;
// the transitions phase also as a bar of the states done.
[[nodiscard]] std::string progress_line(const envision::Progress& p, double seconds);

// How far a run on `scene` got, `seconds` after it started: the phase and chain of its last report
// p (or, once `envisioned`, the answer being made), and the states and transitions found so far
// over all chains.
[[nodiscard]] std::string run_so_far_text(const envision::Progress& p, bool envisioned, std::size_t states,
                                          std::size_t transitions, double seconds, const std::string& scene);

class ProgressBar {
public:
    explicit ProgressBar(bool draw);  // draw: stderr is a terminal
    ProgressBar(const ProgressBar&) = delete;
    ProgressBar& operator=(const ProgressBar&) = delete;
    ~ProgressBar() { clear(); }

    void operator()(const envision::Progress& p);
    void clear();       // erases the line, if one is drawn
    void envisioned();  // envision() has returned: clears the line; the answer is being made
    [[nodiscard]] std::string run_so_far(const std::string& scene) const;

private:
    using Clock = std::chrono::steady_clock;
    Clock::time_point start_, phase_start_, drawn_at_;
    envision::Progress last_;
    std::size_t earlier_states_ = 0, earlier_transitions_ = 0;  // the chains before last_'s
    std::size_t width_ = 0;                                     // of the line on the terminal; 0: none
    bool draw_ = false, envisioned_ = false;
};

}  // namespace qm::cli
