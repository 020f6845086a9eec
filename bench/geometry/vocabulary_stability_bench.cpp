// bench/geometry/vocabulary_stability_bench.cpp: is a metric scene's place vocabulary the same,
// adjacency included, at every grid from a coarsest one to k times finer, and with the scene moved,
// turned by quarter turns and scaled 1e-3..1e3 (docs/ACCURACY.md)? Prints, per
// kinematic pair, each distinct vocabulary (geometry/vocabulary_signature.hpp) with the grids or
// drawings that gave it. Not a test: the exhaustive sweep takes minutes (scripts/vocabulary_sweep).
//
// usage: geometry_vocabulary_stability_bench SCENE.def [--pair K] [--grid N0 N1] [--factor F]
//                                            [--every S] [--transforms] [--threads T] [--show WHAT]
//   --grid: the coarsest grid (default: the pair's own); every grid (N0 + i S, N1 + i S N1 / N0)
//   up to F times (default 4) is built, S = 1 by default.
#include "geometry/kinematic_pairs.hpp"
#include "geometry/mechanism_transform.hpp"
#include "geometry/metric_scene_parser.hpp"
#include "geometry/place_text.hpp"
#include "geometry/vocabulary_signature.hpp"

#include <atomic>
#include <chrono>
#include <cmath>
#include <iostream>
#include <map>
#include <numbers>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace g = qm::geometry;

namespace {

struct Job {
    std::string what;  // the grid or drawing
    g::Mechanism m;
    std::size_t pair = 0;
    std::array<int, 2> grid{};
    std::string signature, counts;
    double seconds = 0;
    std::string text;  // the vocabulary as text, for --show
};

std::string show;  // --show WHAT: print the vocabulary of that grid or drawing

void run(Job& j) {
    const auto start = std::chrono::steady_clock::now();
    const auto sel = g::kinematic_pairs(j.m);
    const auto& pair = sel.modelled.at(j.pair);
    const auto oracle = g::pair_oracle(j.m, pair);
    auto request = g::place_request(j.m, pair);
    for (int k = 0; k < 2; ++k)
        if (j.grid[static_cast<std::size_t>(k)] > 0 && request.cspace.axes[static_cast<std::size_t>(k)].samples > 3)
            request.cspace.axes[static_cast<std::size_t>(k)].samples = j.grid[static_cast<std::size_t>(k)];
    const auto built = g::build_place_vocabulary(*oracle, request);
    j.signature = g::vocabulary_signature(built.vocabulary);
    j.counts = j.signature.substr(0, j.signature.find('\n'));
    if (j.what == show) {
        std::ostringstream os;
        g::write_place_text(os, built.vocabulary);
        j.text = os.str();
    }
    j.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void run_all(std::vector<Job>& jobs, int threads) {
    std::atomic<std::size_t> next{0};
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t)
        pool.emplace_back([&] {
            for (std::size_t i = next++; i < jobs.size(); i = next++) run(jobs[i]);
        });
    for (auto& t : pool) t.join();
}

void report(const std::vector<Job>& jobs) {
    std::map<std::string, std::vector<const Job*>> by;
    for (const auto& j : jobs) by[j.signature].push_back(&j);
    std::vector<std::pair<std::size_t, const std::string*>> order;
    for (const auto& [s, v] : by) order.push_back({v.size(), &s});
    std::sort(order.rbegin(), order.rend());
    double total = 0;
    for (const auto& j : jobs) total += j.seconds;
    std::cout << "  " << jobs.size() << " vocabularies, " << by.size() << " distinct (" << total << " s of computing)\n";
    for (const auto& [n, s] : order) {
        const auto& v = by[*s];
        std::cout << "  " << n << " x " << v.front()->counts << ":";
        int shown = 0;
        for (const auto* j : v)
            if (n < 40 || ++shown <= 12) std::cout << ' ' << j->what;
        if (n >= 40) std::cout << " ...";
        std::cout << '\n';
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: geometry_vocabulary_stability_bench SCENE.def [--pair K] [--grid N0 N1] [--factor F] [--every S] [--transforms] [--threads T]\n";
        return 2;
    }
    std::size_t only_pair = SIZE_MAX;
    std::array<int, 2> base{0, 0};
    double factor = 4;
    int every = 1, threads = 1;
    bool transforms = false;
    for (int i = 2; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--pair" && i + 1 < argc) only_pair = std::stoul(argv[++i]);
        else if (a == "--grid" && i + 2 < argc) base = {std::stoi(argv[i + 1]), std::stoi(argv[i + 2])}, i += 2;
        else if (a == "--factor" && i + 1 < argc) factor = std::stod(argv[++i]);
        else if (a == "--every" && i + 1 < argc) every = std::stoi(argv[++i]);
        else if (a == "--threads" && i + 1 < argc) threads = std::stoi(argv[++i]);
        else if (a == "--transforms") transforms = true;
        else if (a == "--show" && i + 1 < argc) show = argv[++i];
        else return std::cerr << "unknown option " << a << '\n', 2;
    }
    qm::Diagnostics d;
    const auto m = g::read_mechanism_file(argv[1], d);
    d.print(std::cerr);
    if (!m) return 2;
    const auto sel = g::kinematic_pairs(*m);
    for (std::size_t p = 0; p < sel.modelled.size(); ++p) {
        if (only_pair != SIZE_MAX && p != only_pair) continue;
        const auto& pair = sel.modelled[p];
        const auto request = g::place_request(*m, pair);
        std::array<int, 2> from = base;
        for (int k = 0; k < 2; ++k)
            if (from[static_cast<std::size_t>(k)] <= 0) from[static_cast<std::size_t>(k)] = request.cspace.axes[static_cast<std::size_t>(k)].samples;
        std::cout << "pair " << m->parts[pair.a].name << ' ' << m->parts[pair.b].name << '\n';
        std::vector<Job> jobs;
        if (transforms) {
            for (double scale : {1e-3, 1e-2, 0.1, 1.0, 10.0, 1e2, 1e3})
                for (int quarter = 0; quarter < 4; ++quarter)
                    for (const Eigen::Vector2d& shift : {Eigen::Vector2d(0, 0), Eigen::Vector2d(3.7, -1.3)}) {
                        std::ostringstream what;
                        what << "s" << scale << "/t" << 90 * quarter << (shift.norm() > 0 ? "/moved" : "");
                        jobs.push_back({what.str(), g::transformed(*m, scale, quarter * std::numbers::pi / 2, scale * shift), p, from, {}, {}, 0, {}});
                    }
        } else {
            for (int i = 0;; i += every) {
                const int n0 = from[0] + i, n1 = static_cast<int>(std::lround(from[1] + static_cast<double>(i) * from[1] / from[0]));
                if (n0 > factor * from[0] + 0.5) break;
                jobs.push_back({std::to_string(n0) + "x" + std::to_string(n1), *m, p, {n0, n1}, {}, {}, 0, {}});
            }
        }
        run_all(jobs, threads);
        report(jobs);
        for (const auto& j : jobs)
            if (!j.text.empty()) std::cout << "vocabulary at " << j.what << ":\n" << j.text;
    }
    return 0;
}
