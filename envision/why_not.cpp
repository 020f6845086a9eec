// envision/why_not.cpp: why there is no such transition, or no such state.
#include "envision/why_not.hpp"
#include "bridge/clock_vocabulary.hpp"
#include "engine/why.hpp"
#include "engine/why_printer.hpp"
#include "envision/state_dynamics.hpp"
#include "envision/state_query.hpp"
#include "envision/state_space.hpp"
#include "envision/successors.hpp"

#include <algorithm>

namespace qm::envision {
namespace g = qm::geometry;

namespace {

std::string name_of(const Envisionment& e, std::size_t chain, const State& s) {
    const auto& c = e.chains[chain];
    std::string out;
    for (std::size_t k = 0; k < c.chain.pairs.size(); ++k) out += (k ? " " : "") + e.pairs[c.chain.pairs[k]].name + "-" + std::to_string(s.places[k].value);
    for (const auto m : s.motions) out += std::string(" ") + sign_word(m);
    return out;
}

// One step of a derivation of `false`, as a line: the rule (or premise) and what it used.
std::string step_text(engine::Engine& e, atms::JustId j) {
    const auto& just = e.atms().justification(j);
    const engine::Firing& f = e.firing(just.informant);
    auto node = [&](atms::NodeId n) -> std::string {
        if (n == e.atms().contradiction()) return "false";
        if (const auto a = e.atms().assumption_of(n)) return e.print(*a);
        const auto fact = e.fact_of(n);
        return fact ? e.print(*fact) : "?";
    };
    std::string out = node(just.consequent) + " <= ";
    if (f.kind == engine::Firing::Kind::rule && f.rule)
        out += "rule " + e.program().rules[*f.rule].name + " at " + f.where->file.str() + ":" + std::to_string(f.where->line);
    else
        out += f.kind == engine::Firing::Kind::premise ? "premise" : "assumption";
    for (std::size_t i = 0; i < just.antecedents.size(); ++i) out += (i ? ", " : ": ") + node(just.antecedents[i]);
    return out;
}

// Why a combination of places and motions is not a state: the minimal nogoods within it.
bool explain_not_a_state(std::ostream& os, const g::Mechanism& m, const Envisionment& e, std::size_t chain, const State& s,
                         const EnvisionOptions& options, Diagnostics& diagnostics) {
    const auto laws = Laws::load(options.rules, diagnostics);
    if (!laws) return false;
    const auto& c = e.chains[chain];
    auto space = state_space_engine(*laws, m, e.pairs, c.chain, diagnostics);
    if (!space) return false;
    std::vector<atms::AssumptionId> chosen;
    for (std::size_t k = 0; k < s.places.size(); ++k) chosen.push_back(space->place[k].at(s.places[k].value));
    for (std::size_t o = 0; o < s.motions.size(); ++o) chosen.push_back(space->motion[o].at(s.motions[o]));
    engine::Engine& engine = *space->engine;
    const atms::EnvId env = engine.atms().environment(chosen);
    os << "'" << name_of(e, chain, s) << "' is not a state: its places and motions are inconsistent\n";
    std::size_t shown = 0;
    for (const auto nogood : engine.atms().minimal_nogoods()) {
        if (!engine.atms().env(nogood).subset_of(engine.atms().env(env))) continue;
        os << "  nogood {";
        const auto as = engine.atms().env(nogood).assumptions();
        for (std::size_t i = 0; i < as.size(); ++i) os << (i ? ", " : "") << engine.print(as[i]);
        os << "}:\n";
        const auto x = engine.atms().explain_nogood(nogood);
        for (const auto j : x.steps) os << "    " << step_text(engine, j) << '\n';
        ++shown;
    }
    if (shown == 0) os << "  (no nogood of the laws lies within it: it is a state; the envisionment was made with other laws or forces)\n";
    return true;
}

}  // namespace

bool write_why_not(std::ostream& os, const g::Mechanism& m, const Envisionment& e, const EnvisionOptions& options,
                   const std::string& question, Diagnostics& diagnostics) {
    const auto arrow = question.find("->");
    if (arrow == std::string::npos) {
        diagnostics.error({"--why-not", 1, 1}, "expected 'STATE -> STATE'", question);
        return false;
    }
    const auto from = parse_state(e, question.substr(0, arrow), "--why-not", diagnostics, question, 1);
    const auto to = parse_state(e, question.substr(arrow + 2), "--why-not", diagnostics, question, static_cast<std::uint32_t>(arrow + 3));
    if (!from || !to) return false;
    if (from->chain != to->chain) {
        diagnostics.error({"--why-not", 1, static_cast<std::uint32_t>(arrow + 3)}, "the two states are in different chains: no transition joins chains", question);
        return false;
    }
    if (!from->id) return explain_not_a_state(os, m, e, from->chain, from->state, options, diagnostics);
    if (!to->id) return explain_not_a_state(os, m, e, to->chain, to->state, options, diagnostics);
    const auto& c = e.chains[from->chain];
    const std::string a = "#" + std::to_string(from->id->value) + " " + state_name(e, c, *from->id);
    const std::string b = "#" + std::to_string(to->id->value) + " " + state_name(e, c, *to->id);
    for (const auto& t : c.transitions)
        if (t.from == *from->id && t.to == *to->id) {
            os << "there is a transition " << a << " -> " << b << " (" << to_string(t.duration) << ")\n";
            return true;
        }
    const auto laws = Laws::load(options.rules, diagnostics);
    if (!laws) return false;
    const State* const only[] = {&c.states[*from->id]};
    PlaceVectorEngine engine(*laws, m, e.pairs, c.chain, only, options.without);
    const auto env = engine.run(0, diagnostics);
    if (!env) return false;
    const auto dynamics = read_dynamics(engine.engine(), *env, m, e.pairs, c.chain, diagnostics);
    if (!dynamics) return false;
    std::vector<std::string> objects;
    for (const auto p : c.chain.objects) objects.push_back(e.parts[p.value]);
    os << "no transition " << a << " -> " << b << "\n";
    if (dynamics->steps.empty()) os << "  the first state takes no step: nothing changes in it (a terminal state)\n";
    const auto reasons = why_no_transition(*from->id, *to->id, c.states, c.chain, e.pairs, objects, c.tables, *dynamics);
    for (std::size_t i = 0; i < reasons.size(); ++i) {
        os << "  step " << reasons[i].first << ":\n";
        for (const auto& r : reasons[i].second) os << "    " << r << '\n';
        for (const auto& [s, t] : dynamics->preempts)
            if (t == i) os << "    (it happens only if step " << dynamics->steps[s].name << " cannot: Law 4)\n";
    }
    // How the laws derived what the first state can do: its net forces and steps.
    os << "  the laws in the first state:\n";
    engine::Engine& x = engine.engine();
    for (const char* predicate : {bridge::clock::net_force, bridge::clock::step})
        for (const auto f : x.facts_of(x.values().symbol(predicate))) {
            if (!x.atms().holds_in(x.node(f), *env)) continue;
            std::string text = engine::print_why(engine::why(x, f));
            // indent
            std::string indented = "    ";
            for (char ch : text) {
                indented += ch;
                if (ch == '\n') indented += "    ";
            }
            while (!indented.empty() && (indented.back() == ' ')) indented.pop_back();
            os << indented;
        }
    return true;
}

}  // namespace qm::envision
