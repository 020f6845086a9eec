// cli/progress_bar.cpp: the envisioner's progress line (cli/progress_bar.hpp).
#include "progress_bar.hpp"
#include <cstdio>

namespace qm::cli {

namespace {

using Phase = envision::Progress::Phase;

std::string per_second(std::size_t count, double seconds) {
    return std::to_string(seconds > 0 ? static_cast<unsigned long long>(static_cast<double>(count) / seconds + 0.5) : 0ULL);
}

}  // namespace

std::string progress_line(const envision::Progress& p, double seconds) {
    if (p.phase == Phase::places) return "place vocabularies";
    const std::string chain = "chain " + std::to_string(p.chain) + ": ";
    if (p.phase == Phase::states) return chain + std::to_string(p.states) + " states (" + per_second(p.states, seconds) + " states/s)";
    constexpr std::size_t width = 10;
    const std::size_t filled = p.states == 0 ? 0 : width * p.done / p.states;
    return chain + std::to_string(p.transitions) + " transitions (" + per_second(p.transitions, seconds) + " transitions/s) [" +
           std::string(filled, '#') + std::string(width - filled, ' ') + "] " + std::to_string(p.done) + "/" +
           std::to_string(p.states) + " states";
}

std::string run_so_far_text(const envision::Progress& p, bool envisioned, std::size_t states, std::size_t transitions,
                            double seconds, const std::string& scene) {
    const std::string what = envisioned                 ? "answering from the envisionment"
                             : p.phase == Phase::places ? "making the place vocabularies"
                             : p.phase == Phase::states ? "finding the states of chain " + std::to_string(p.chain)
                                                        : "finding the transitions of chain " + std::to_string(p.chain);
    char after[32];
    std::snprintf(after, sizeof after, "%.1f", seconds);
    return what + " of " + scene + " (after " + after + " s: " + std::to_string(states) + " states and " + std::to_string(transitions) +
           " transitions found)";
}

ProgressBar::ProgressBar(bool draw) : start_(Clock::now()), phase_start_(start_), draw_(draw) {}

void ProgressBar::operator()(const envision::Progress& p) {
    const auto now = Clock::now();
    const bool new_phase = p.phase != last_.phase || p.chain != last_.chain;
    if (p.chain != last_.chain) {
        earlier_states_ += last_.states;
        earlier_transitions_ += last_.transitions;
    }
    if (new_phase) phase_start_ = now;
    last_ = p;
    if (!draw_ || now - start_ < std::chrono::seconds(1)) return;
    if (width_ != 0 && !new_phase && now - drawn_at_ < std::chrono::milliseconds(100)) return;
    const std::string line = progress_line(p, std::chrono::duration<double>(now - phase_start_).count());
    const int pad = width_ > line.size() ? static_cast<int>(width_ - line.size()) : 0;
    std::fprintf(stderr, "\r%s%*s", line.c_str(), pad, "");
    std::fflush(stderr);
    width_ = line.size();
    drawn_at_ = now;
}

void ProgressBar::envisioned() {
    clear();
    envisioned_ = true;
}

void ProgressBar::clear() {
    if (width_ == 0) return;
    std::fprintf(stderr, "\r%*s\r", static_cast<int>(width_), "");
    std::fflush(stderr);
    width_ = 0;
}

std::string ProgressBar::run_so_far(const std::string& scene) const {
    return run_so_far_text(last_, envisioned_, earlier_states_ + last_.states, earlier_transitions_ + last_.transitions,
                           std::chrono::duration<double>(Clock::now() - start_).count(), scene);
}

}  // namespace qm::cli
