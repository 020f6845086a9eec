// bench/scene/scene_read_bench.cpp: reads (parses and checks, scene/scene_parser.hpp) one generated
// Alex scene of about MEGABYTES MB and prints its size, its objects, the seconds the read took and
// the process' peak resident memory. One size per process, so that the peak is that size's.
// Usage: scene_read_bench MEGABYTES [train|stack] [--write FILE]
//   train: gears meshing in a row (bench/alex/generated_scenes.hpp), 2 surfaces and one contact per
//   object; stack: blocks of 6 surfaces, 3 contacts per level. --write also writes the scene to FILE
//   (for timing `qm-atms FILE` as a whole).
#include "generated_scenes.hpp"
#include "scene/scene_parser.hpp"
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <sys/resource.h>

namespace {

std::string scene_of(const std::string& kind, int n) { return kind == "stack" ? qm::bench::stack(n) : qm::bench::train(n); }

}  // namespace

int main(int argc, char** argv) {
    const double mb = argc >= 2 ? std::atof(argv[1]) : 0;
    const std::string kind = argc >= 3 && argv[2][0] != '-' ? argv[2] : "train";
    std::string write_to;
    // The name the scene is read as: every located entry of the checked scene keeps a copy of it,
    // so a realistic path (longer than a short string's 15 characters) is the default.
    std::string name = "scenarios/generated/" + kind + "-scene.def";
    for (int i = 2; i + 1 < argc; ++i) {
        if (std::string(argv[i]) == "--write") write_to = argv[i + 1];
        if (std::string(argv[i]) == "--name") name = argv[i + 1];
    }
    if (mb <= 0 || (kind != "train" && kind != "stack")) {
        std::fprintf(stderr, "usage: scene_read_bench MEGABYTES [train|stack] [--write FILE] [--name NAME]\n");
        return 2;
    }
    // Objects for the size asked, from the bytes per object of a sample.
    const double per_object = static_cast<double>(scene_of(kind, 1000).size()) / 1000.0;
    const int n = std::max(2, static_cast<int>(mb * 1e6 / per_object));
    std::string text = scene_of(kind, n);
    if (!write_to.empty()) std::ofstream(write_to, std::ios::binary) << text;
    const std::size_t bytes = text.size();
    const auto t0 = std::chrono::steady_clock::now();
    qm::Diagnostics d;
    auto scene = qm::scene::read_scene(name, std::move(text), d);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    std::printf("%s %.1f MB (%zu bytes): %d objects, %zu surfaces, read in %.3f s, peak RSS %.0f MB%s\n", kind.c_str(),
                static_cast<double>(bytes) / 1e6, bytes, n, scene ? static_cast<std::size_t>(scene->surfaces.size()) : 0,
                seconds, static_cast<double>(u.ru_maxrss) / 1024.0, scene ? "" : " (NOT READ)");
    return scene ? 0 : 1;
}
