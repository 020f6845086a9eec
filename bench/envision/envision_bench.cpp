// bench/envision/envision_bench.cpp
// Prints numbers, passes or fails nothing (STYLE.md section 8):
//   1. every bundled metric mechanism (and, given as arguments, any other): the envisionment's
//      stages in process, median of REPETITIONS runs with a warm place cache (places read from the
//      cache, states, transitions), and one run with a cold cache (a fresh folder: every
//      vocabulary computed); states, transitions, cycles, terminal states;
//   2. gear trains of N = 1..50 pairs on shafts (one place each, 8.1.6's gap), warm: time per N, to
//      see that it grows at most linearly;
//   3. a clock-like chain: the bundled escapement's pair with its wheel on the shaft of the first of
//      six gear pairs (the QRG clock's train chain, 9.1.3), warm;
//   4. the fixed cost of one state's engine: an engine over the laws a state's engine gets, made and
//      run with no facts.
// Usage: envision_bench [REPETITIONS [MECH.def ...]]   (default 5)
#include "envision/envisionment.hpp"
#include "geometry/metric_scene_parser.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace qm;
namespace fs = std::filesystem;
namespace ev = qm::envision;

namespace {

struct Times {
    double places = 0, states = 0, transitions = 0, total = 0;
    std::size_t n_states = 0, n_transitions = 0, n_cycles = 0, n_terminal = 0;
};

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0 : v[v.size() / 2];
}

Times once(const geometry::Mechanism& m, const fs::path& cache_dir) {
    const geometry::PlaceCache cache(cache_dir);
    ev::EnvisionOptions o;
    o.rules = fs::path(QM_SOURCE_DIR) / "rules/clock";
    o.cache = &cache;
    Diagnostics d;
    const auto t0 = std::chrono::steady_clock::now();
    const auto e = ev::envision(m, o, d);
    const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!e) {
        d.print(std::cerr);
        std::exit(1);
    }
    Times t;
    t.total = total;
    t.places = e->seconds_places;
    for (const auto& c : e->chains) {
        t.states += c.seconds_states;
        t.transitions += c.seconds_transitions;
        t.n_states += c.states.size();
        t.n_transitions += c.transitions.size();
        t.n_cycles += c.graph.cycles.size();
        t.n_terminal += c.graph.terminal.size();
    }
    return t;
}

Times warm(const geometry::Mechanism& m, const fs::path& cache_dir, int reps) {
    (void)once(m, cache_dir);  // fill the cache
    std::vector<double> p, s, tr, tot;
    Times last;
    for (int i = 0; i < reps; ++i) {
        last = once(m, cache_dir);
        p.push_back(last.places);
        s.push_back(last.states);
        tr.push_back(last.transitions);
        tot.push_back(last.total);
    }
    last.places = median(p);
    last.states = median(s);
    last.transitions = median(tr);
    last.total = median(tot);
    return last;
}

geometry::Mechanism read(const std::string& name, const std::string& text) {
    Diagnostics d;
    auto m = geometry::read_mechanism(name, text, d);
    if (!m) {
        d.print(std::cerr);
        std::exit(1);
    }
    return std::move(*m);
}

geometry::Mechanism read_file(const std::string& path) {
    Diagnostics d;
    auto m = geometry::read_mechanism_file(path, d);
    if (!m) {
        d.print(std::cerr);
        std::exit(1);
    }
    return std::move(*m);
}

// gear-0 drives gear-1; pinion-k on gear-k's shaft drives gear-(k+1) (module 1/6, play 0.02).
std::string train_text(int n, bool with_escapement) {
    std::ostringstream parts, pairs, links;
    std::string previous = "g0";
    if (with_escapement) {
        parts << "(scape-wheel (scape-wheel (teeth 15) (root-radius 0.85) (tip-radius 1.0) (lean 0.8) (root-land 0.2)) (turn 8) (rotation))\n"
              << "(pallets (anchor (span 0.45) (reach 0.5) (width 0.1) (top 0.1)) (at 0 1.4) (rotation))\n";
        pairs << "(scape-wheel pallets (window pallets -20 20) (grid 64 64))\n";
        links << "(scape-wheel g0)\n";
    }
    parts << "(g0 (spur-gear (teeth 12) (pitch-radius 1) (play 0.02)) (rotation))\n";
    for (int k = 1; k <= n; ++k) {
        const double x = 2.5 * k;
        parts << "(g" << k << " (spur-gear (teeth 18) (pitch-radius 1.5) (play 0.02)) (at " << x << " 0) (turn 10) (rotation))\n";
        pairs << "(" << previous << " g" << k << ")\n";
        if (k < n) {
            parts << "(p" << k << " (spur-gear (teeth 12) (pitch-radius 1) (play 0.02)) (at " << x << " 0) (rotation))\n";
            links << "(g" << k << " p" << k << ")\n";
            previous = "p" + std::to_string(k);
        }
    }
    std::ostringstream os;
    os << "(Defmechanism train\n Settings ((chordal-tolerance 1e-7) (grid 48 48) (gap-epsilon 0.03))\n Parts (" << parts.str() << ")\n";
    if (!links.str().empty()) os << " Linkages (" << links.str() << ")\n";
    os << " Pairs (" << pairs.str() << ")\n Forces ((spring g" << n << " (torque -))";
    if (with_escapement) os << " (gravity pallets (direction 0 -1) (at 0 1.0))";
    os << "))\n";
    return os.str();
}

void row(const std::string& name, const Times& w, const Times* cold) {
    std::printf("%-40s %6zu %6zu %4zu %4zu | warm %8.4f = places %7.4f + states %7.4f + transitions %7.4f", name.c_str(), w.n_states,
                w.n_transitions, w.n_cycles, w.n_terminal, w.total, w.places, w.states, w.transitions);
    if (cold) std::printf(" | cold %7.3f (places %7.3f)", cold->total, cold->places);
    std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
    const int reps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
    std::vector<std::string> files{"scenarios/metric/escapement.def", "scenarios/metric/ratchet.def", "scenarios/metric/scotch_yoke.def",
                                   "scenarios/metric/cam.def", "scenarios/metric/gear_train.def"};
    std::vector<std::string> given(argv + std::min(argc, 2), argv + argc);
    const fs::path root = fs::path(QM_BINARY_DIR) / "envision-bench-cache";
    std::printf("1. mechanisms (seconds; medians of %d warm runs; cold: one run with an empty cache)\n", reps);
    std::printf("%-40s %6s %6s %4s %4s\n", "mechanism", "states", "trans", "cyc", "term");
    int k = 0;
    auto measure = [&](const std::string& path) {
        const auto m = read_file(path);
        const fs::path cold_dir = root / ("cold-" + std::to_string(k++));
        fs::remove_all(cold_dir);
        const Times cold = once(m, cold_dir);
        row(fs::path(path).filename().string(), warm(m, root / "warm", reps), &cold);
    };
    for (const auto& f : files) measure((fs::path(QM_SOURCE_DIR) / f).string());
    for (const auto& f : given) measure(f);

    std::printf("\n2. gear trains of N pairs, warm (seconds)\n");
    for (int n : {1, 2, 5, 10, 20, 30, 40, 50}) row("train " + std::to_string(n), warm(read("train", train_text(n, false)), root / "warm", reps), nullptr);

    std::printf("\n3. the escapement on the first of six gear pairs (the clock's train chain), warm\n");
    row("escapement + 6 gear pairs", warm(read("clock-like", train_text(6, true)), root / "warm", reps), nullptr);

    std::printf("\n4. one state's engine over the laws, made and run with no facts\n");
    Diagnostics d;
    const auto laws = ev::Laws::load(fs::path(QM_SOURCE_DIR) / "rules/clock", d);
    if (!laws) return 1;
    std::vector<double> t;
    for (int r = 0; r < reps; ++r) {
        const auto t0 = std::chrono::steady_clock::now();
        for (int i = 0; i < 200; ++i) {
            auto e = laws->state_engine();
            Diagnostics dd;
            (void)e->run_in_context(e->atms().empty_environment(), dd);
        }
        t.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / 200);
    }
    std::printf("%.1f microseconds per engine\n", median(t) * 1e6);
    return 0;
}
