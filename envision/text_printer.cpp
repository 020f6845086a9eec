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
        os << "\n  states: " << c.shown_count() << ", transitions: " << c.transitions.size() << ", cycles: " << c.graph.cycles.size();
        if (!c.graph.transient.empty()) os << ", transient cycles: " << c.graph.transient.size();
        os << ", terminal states: " << c.graph.ends();
        if (!c.graph.possible_rests.empty()) os << " (" << plural(c.graph.possible_rests.size(), "possible rest", "possible rests") << ")";
        os << '\n';
        auto list = [&](const std::vector<StateId>& ids, const char* note) {
            for (std::size_t k = 0; k < ids.size() && k < shown_per_list; ++k) os << "    #" << ids[k].value << ' ' << state_name(e, c, ids[k]) << note << '\n';
            if (ids.size() > shown_per_list) os << "    ... and " << ids.size() - shown_per_list << " more (--json lists them all)\n";
        };
        for (std::size_t i = 0; i < c.graph.cycles.size(); ++i) {
            os << "  cycle " << i + 1 << " (" << plural(c.graph.cycles[i].size(), "state", "states") << "):\n";
            list(c.graph.cycles[i], "");
        }
        for (std::size_t i = 0; i < c.graph.transient.size(); ++i) {
            const auto& t = c.graph.transient[i];
            os << "  transient cycle " << i + 1 << " (" << plural(t.states.size(), "state", "states") << "; cannot repeat: "
               << m.parts[c.chain.objects[t.object]].name << " moves " << sign_word(t.motion) << " throughout, "
               << (t.pair ? "and the places of " + e.pairs[c.chain.pairs[*t.pair]].name + " in it keep it from coming round"
                          : std::string("along a bounded coordinate"))
               << "):\n";
            list(t.states, "");
        }
        if (c.graph.ends() != 0) os << "  terminal states:\n";
        list(c.graph.terminal, "");
        list(c.graph.possible_rests, "  (may rest; may also move on)");
        states += c.shown_count();
        transitions += c.transitions.size();
        cycles += c.graph.cycles.size();
        terminal += c.graph.ends();
    }
    os << "summary: " << plural(e.chains.size(), "chain", "chains") << ", " << plural(states, "state", "states") << ", "
       << plural(transitions, "transition", "transitions") << ", " << plural(cycles, "cycle", "cycles") << ", "
       << plural(terminal, "terminal state", "terminal states") << '\n';
}

}  // namespace qm::envision
