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
        std::vector<bool> in_cycle(c.states.size(), false), ends(c.states.size(), false);
        for (const StateId s : c.graph.terminal) ends[s.value] = true;
        for (const StateId s : c.graph.possible_rests) ends[s.value] = true;
        auto state = [&](const char* indent, StateId s) {
            os << indent << node(k, s) << " [label=" << quoted("#" + std::to_string(s.value) + "\n" + state_name(e, c, s))
               << (ends[s.value] ? ", peripheries=2" : "") << "];\n";
        };
        auto cluster = [&](const std::string& name, const std::string& label, const char* style, const std::vector<StateId>& states) {
            os << "    subgraph " << quoted("cluster_" + std::to_string(c.chain.index + 1) + "_" + name) << " {\n      label=" << quoted(label)
               << "; style=" << style << "; color=gray;\n";
            for (const StateId s : states) {
                in_cycle[s.value] = true;
                state("      ", s);
            }
            os << "    }\n";
        };
        for (std::size_t i = 0; i < c.graph.cycles.size(); ++i)
            cluster("cycle_" + std::to_string(i + 1), "cycle " + std::to_string(i + 1), "rounded", c.graph.cycles[i]);
        for (std::size_t i = 0; i < c.graph.transient.size(); ++i)
            cluster("transient_" + std::to_string(i + 1), "transient cycle " + std::to_string(i + 1) + " (cannot repeat)", "dashed",
                    c.graph.transient[i].states);
        for (std::uint32_t i = 0; i < c.states.size(); ++i)
            if (!in_cycle[i] && c.is_shown(StateId{i})) state("    ", StateId{i});
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
