// bench/alex/scene_gen.cpp: writes one generated scene (generated_scenes.hpp) to standard output,
// for scripts that measure the analysis at many sizes (bench/engine/linear_fit.sh).
// Usage: scene_gen stack|train N     (N >= 1; exit 2 on a bad argument)
#include "generated_scenes.hpp"
#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
    const std::string kind = argc == 3 ? argv[1] : "";
    char* end = nullptr;
    const long n = argc == 3 ? std::strtol(argv[2], &end, 10) : 0;
    if ((kind != "stack" && kind != "train") || end == argv[2] || *end != '\0' || n < 1 || n > 100000) {
        std::fprintf(stderr, "usage: scene_gen stack|train N   (1 <= N <= 100000)\n");
        return 2;
    }
    const std::string text = kind == "stack" ? qm::bench::stack(static_cast<int>(n)) : qm::bench::train(static_cast<int>(n));
    std::fwrite(text.data(), 1, text.size(), stdout);
    return 0;
}
