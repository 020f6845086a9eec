// envision/dot_printer.cpp
#include "envision/dot_printer.hpp"

namespace qm::envision {

namespace {
std::string quoted(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        out += c;
    }
    return out + "\"";
}
std::string node(std::size_t chain, StateId s) { return "c" + std::to_string(chain + 1) + "s" + std::to_string(s.value); }
}  // namespace

void write_dot(std::ostream& os, const Envisionment& e) {
    os << "digraph " << quoted(e.mechanism) << " {\n  rankdir=LR;\n  node [shape=box, fontsize=10];\n";
    for (std::size_t k = 0; k < e.chains.size(); ++k) {
        const auto& c = e.chains[k];
        os << "  subgraph " << quoted("cluster_chain_" + std::to_string(c.chain.index + 1)) << " {\n    label="
           << quoted("chain " + std::to_string(c.chain.index + 1)) << ";\n";
        std::vector<bool> in_cycle(c.states.size(), false);
        for (std::size_t i = 0; i < c.graph.cycles.size(); ++i) {
            os << "    subgraph " << quoted("cluster_" + std::to_string(c.chain.index + 1) + "_cycle_" + std::to_string(i + 1))
               << " {\n      label=" << quoted("cycle " + std::to_string(i + 1)) << "; style=rounded; color=gray;\n";
            for (const StateId s : c.graph.cycles[i]) {
                in_cycle[s.value] = true;
                os << "      " << node(k, s) << " [label=" << quoted("#" + std::to_string(s.value) + "\n" + state_name(e, c, s)) << "];\n";
            }
            os << "    }\n";
        }
        std::vector<bool> terminal(c.states.size(), false);
        for (const StateId s : c.graph.terminal) terminal[s.value] = true;
        for (std::uint32_t i = 0; i < c.states.size(); ++i) {
            if (in_cycle[i] || !c.is_shown(StateId{i})) continue;
            os << "    " << node(k, StateId{i}) << " [label=" << quoted("#" + std::to_string(i) + "\n" + state_name(e, c, StateId{i}))
               << (terminal[i] ? ", peripheries=2" : "") << "];\n";
        }
        os << "  }\n";
        for (const auto& t : c.transitions) {
            const char* colour = (t.causes & Cause::collision) ? "red" : (t.causes & Cause::dynamic) ? "blue" : "black";
            os << "  " << node(k, t.from) << " -> " << node(k, t.to) << " [color=" << colour
               << (t.duration == Duration::instant ? ", style=dashed" : "") << "];\n";
        }
    }
    os << "}\n";
}

}  // namespace qm::envision
