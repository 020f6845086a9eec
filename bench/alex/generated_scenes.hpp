// bench/alex/generated_scenes.hpp
// Provides:   the Alex scenes of growing size that the benchmarks use (symbolic, no geometry):
//             stack(N), a stack of N blocks under gravity on a fixed table, each shaped like
//             Figure 7.2's block (three surfaces on top, three below, three contacts per level, a
//             force on every block); train(N), N pinned gears, each meshing the next on one tooth
//             (teeth alternate so that the train turns), with a driving torque on the first.
// Used by:    scene_gen (writes one scene for bench/startup/startup.py --args and
//             bench/engine/linear_fit.sh) and scene_read_bench.
#pragma once
#include <string>

namespace qm::bench {

inline std::string stack(int n) {
    std::string s = "(Defscenario 2 stack\n Individuals (table";
    for (int i = 0; i < n; ++i) s += " b" + std::to_string(i);
    s += ")\n Surfaces ((table (tb-l (0 +) (0 0)) (tb-m (0 +) (0 0)) (tb-r (0 +) (0 0)))\n";
    for (int i = 0; i < n; ++i) {
        const std::string b = "b" + std::to_string(i);
        s += "  (" + b + " (" + b + "-t-l (0 +) (+ -)) (" + b + "-t-m (0 +) (0 -)) (" + b + "-t-r (0 +) (- -)) (" + b +
             "-b-l (0 -) (+ +)) (" + b + "-b-m (0 -) (0 +)) (" + b + "-b-r (0 -) (- +)))\n";
    }
    s += " )\n Translational-Constraints ((table (?x ?y)))\n Rotational-Constraints ((table (?r)))\n Forces (";
    for (int i = 0; i < n; ++i) s += "(b" + std::to_string(i) + " (0 -) (0 0)) ";
    s += "))\n(Defstates (";
    std::string l = "tb-l", m = "tb-m", r = "tb-r";
    for (int i = 0; i < n; ++i) {
        const std::string b = "b" + std::to_string(i);
        s += "(Contact " + l + " " + b + "-b-l) (Contact " + m + " " + b + "-b-m) (Contact " + r + " " + b + "-b-r) ";
        l = b + "-t-l", m = b + "-t-m", r = b + "-t-r";
    }
    return s + "))\n";
}

// Gear i touches gear i+1 with its right tooth; meshing gears turn alternately, so the teeth face
// up and down in turn (a gear turning (+) pushes its neighbour's tooth up, one turning (-) down).
inline std::string train(int n) {
    std::string s = "(Defscenario 2 train\n Individuals (";
    for (int i = 0; i < n; ++i) s += " g" + std::to_string(i);
    s += ")\n Surfaces (";
    for (int i = 0; i < n; ++i) {
        const std::string g = "g" + std::to_string(i);
        s += "(" + g + " (" + g + "-l " + (i % 2 ? "(- -)" : "(- +)") + " (+ 0)) (" + g + "-r " + (i % 2 ? "(+ -)" : "(+ +)") +
             " (- 0)))\n";
    }
    s += " )\n Translational-Constraints (";
    for (int i = 0; i < n; ++i) s += "(g" + std::to_string(i) + " (?x ?y)) ";
    s += ")\n Forces ((g0 (0 +) (- 0))))\n(Defstates (";
    for (int i = 0; i + 1 < n; ++i)
        s += "(Contact g" + std::to_string(i) + "-r g" + std::to_string(i + 1) + "-l) ";
    return s + "))\n";
}

}  // namespace qm::bench
