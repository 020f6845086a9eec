// bench/alex/alex_bench.cpp
// Prints numbers, passes or fails nothing (STYLE.md section 8):
//   1. every bundled thesis scene analysed end to end as a process (start, loading the rule files,
//      analysis, output), median wall time of several runs and peak memory;
//   2. generated scenes of growing size: a stack of N blocks under gravity on a table (three
//      contacts per level, as Figure 7.2's block), and a train of N pinned gears with a driving
//      torque on the first; median wall time and peak memory for N = 10..200.
// Usage: alex_bench [REPETITIONS]   (default 7)
#include "generated_scenes.hpp"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <fcntl.h>
#include <spawn.h>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

extern char** environ;

namespace {

struct Sample {
    double ms = 0;
    long peak_kib = 0;
    int status = -1;
};

// Runs qm-atms on a scene, output to /dev/null; wall time and the child's peak RSS.
Sample run(const std::string& scene) {
    const std::string exe = std::string(QM_BINARY_DIR) + "/cli/qm-atms";
    std::vector<std::string> args{exe, scene};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    const auto t0 = std::chrono::steady_clock::now();
    pid_t pid = 0;
    Sample s;
    if (posix_spawn(&pid, exe.c_str(), &actions, nullptr, argv.data(), environ) != 0) return s;
    int status = 0;
    rusage usage{};
    wait4(pid, &status, 0, &usage);
    s.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    s.peak_kib = usage.ru_maxrss;
    s.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    posix_spawn_file_actions_destroy(&actions);
    return s;
}

Sample median(const std::string& scene, int reps) {
    std::vector<Sample> xs;
    for (int i = 0; i < reps; ++i) xs.push_back(run(scene));
    std::sort(xs.begin(), xs.end(), [](const Sample& a, const Sample& b) { return a.ms < b.ms; });
    Sample m = xs[xs.size() / 2];
    for (const Sample& x : xs) m.peak_kib = std::max(m.peak_kib, x.peak_kib);
    return m;
}

std::string write(const std::string& name, const std::string& text) {
    const std::string path = std::string(QM_BINARY_DIR) + "/bench_" + name + ".def";
    std::ofstream(path) << text;
    return path;
}

}  // namespace

int main(int argc, char** argv) {
    const int reps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
    std::printf("# qm-atms end to end, median of %d runs (wall ms), peak RSS of the process (MiB)\n", reps);
    std::printf("%-28s %10s %10s %6s\n", "thesis scene", "ms", "MiB", "exit");
    for (const char* name : {"block.def", "arch.def", "gears.def", "recoil_escapement.def", "block_stack.def",
                             "wedge_ramp.def", "wedge_ramp_catch.def", "corner_contacts.def", "force_feedback.def",
                             "block_boulder.def", "lever.def", "block_3d.def", "linked_gears.def"}) {
        const Sample s = median(std::string(QM_SOURCE_DIR) + "/scenarios/alex/" + name, reps);
        std::printf("%-28s %10.2f %10.1f %6d\n", name, s.ms, static_cast<double>(s.peak_kib) / 1024.0, s.status);
    }
    std::printf("\n%-10s %6s %12s %10s %12s %10s\n", "generated", "N", "stack ms", "stack MiB", "train ms", "train MiB");
    for (int n : {10, 25, 50, 100, 150, 200}) {
        const Sample a = median(write("stack_" + std::to_string(n), qm::bench::stack(n)), reps);
        const Sample b = median(write("train_" + std::to_string(n), qm::bench::train(n)), reps);
        std::printf("%-10s %6d %12.1f %10.1f %12.1f %10.1f%s\n", "", n, a.ms, static_cast<double>(a.peak_kib) / 1024.0, b.ms,
                    static_cast<double>(b.peak_kib) / 1024.0, a.status || b.status ? "  (non-zero exit!)" : "");
    }
    return 0;
}
