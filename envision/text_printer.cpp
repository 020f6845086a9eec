// envision/text_printer.cpp
#include "envision/text_printer.hpp"

namespace qm::envision {

namespace {

// A summary, not a listing: the first states of each list (the JSON has them all).
constexpr std::size_t shown_per_list = 12;

std::string plural(std::size_t n, const char* one, const char* many) { return std::to_string(n) + " " + (n == 1 ? one : many); }

}  // namespace

void write_text(std::ostream& os, const geometry::Mechanism& m, const Envisionment& e) {
    std::size_t states = 0, transitions = 0, cycles = 0, terminal = 0;
    os << "mechanism " << e.mechanism << ": " << plural(e.pairs.size(), "kinematic pair", "kinematic pairs") << ", "
       << plural(e.chains.size(), "kinematic chain", "kinematic chains") << '\n';
    for (const auto& c : e.chains) {
        os << "chain " << c.chain.index + 1 << ":\n  objects:";
        for (const auto p : c.chain.objects) os << ' ' << m.parts[p].name;
        os << "\n  pairs:";
        for (std::size_t k = 0; k < c.chain.pairs.size(); ++k) {
            const auto& pair = e.pairs[c.chain.pairs[k]];
            os << (k ? ", " : " ") << pair.name << " (" << plural(pair.vocabulary.places.size(), "place", "places")
               << (pair.from_cache ? ", from cache" : "") << ')';
        }
        os << "\n  states: " << c.shown_count() << ", transitions: " << c.transitions.size() << ", cycles: " << c.graph.cycles.size()
           << ", terminal states: " << c.graph.terminal.size() << '\n';
        for (std::size_t i = 0; i < c.graph.cycles.size(); ++i) {
            const auto& cycle = c.graph.cycles[i];
            os << "  cycle " << i + 1 << " (" << plural(cycle.size(), "state", "states") << "):\n";
            for (std::size_t k = 0; k < cycle.size() && k < shown_per_list; ++k) os << "    #" << cycle[k].value << ' ' << state_name(e, c, cycle[k]) << '\n';
            if (cycle.size() > shown_per_list) os << "    ... and " << cycle.size() - shown_per_list << " more (--json lists them all)\n";
        }
        if (!c.graph.terminal.empty()) os << "  terminal states:\n";
        for (std::size_t k = 0; k < c.graph.terminal.size() && k < shown_per_list; ++k)
            os << "    #" << c.graph.terminal[k].value << ' ' << state_name(e, c, c.graph.terminal[k]) << '\n';
        if (c.graph.terminal.size() > shown_per_list) os << "    ... and " << c.graph.terminal.size() - shown_per_list << " more (--json lists them all)\n";
        states += c.shown_count();
        transitions += c.transitions.size();
        cycles += c.graph.cycles.size();
        terminal += c.graph.terminal.size();
    }
    os << "summary: " << plural(e.chains.size(), "chain", "chains") << ", " << plural(states, "state", "states") << ", "
       << plural(transitions, "transition", "transitions") << ", " << plural(cycles, "cycle", "cycles") << ", "
       << plural(terminal, "terminal state", "terminal states") << '\n';
}

}  // namespace qm::envision
