// envision/state_report.cpp: "what happens next", "what could have just happened" (11.2.1).
#include "envision/state_report.hpp"
#include "bridge/clock_vocabulary.hpp"
#include "envision/fact_reader.hpp"
#include "envision/state_dynamics.hpp"

namespace qm::envision {

namespace {

std::string transition_text(const Envisionment& e, const ChainEnvisionment& c, const Transition& t, StateId other) {
    std::string causes;
    for (const auto& w : cause_words(t.causes)) causes += (causes.empty() ? "" : ", ") + w;
    return "#" + std::to_string(other.value) + " " + state_name(e, c, other) + "  (" + to_string(t.duration) + "; " + causes + ")";
}

}  // namespace

bool write_next(std::ostream& os, const geometry::Mechanism& m, const Envisionment& e, const StateRef& s, const EnvisionOptions& options,
                Diagnostics& diagnostics) {
    const ChainEnvisionment& c = e.chains[s.chain];
    const auto laws = Laws::load(options.rules, diagnostics);
    if (!laws) return false;
    const State* const only[] = {&c.states[s.state]};
    PlaceVectorEngine engine(*laws, m, e.pairs, c.chain, only, options.without);
    const auto env = engine.run(0, diagnostics);
    if (!env) return false;
    const auto dynamics = read_dynamics(engine.engine(), *env, m, e.pairs, c.chain, diagnostics);
    if (!dynamics) return false;
    os << "state #" << s.state.value << ' ' << state_name(e, c, s.state) << " (chain " << c.chain.index + 1 << ")\n";
    const FactReader read(engine.engine(), *env);
    os << "  forces:";
    bool any = false;
    read.each(bridge::clock::force_on, 3, [&](std::span<const engine::ValueId> a) {
        os << (any ? ";" : "") << ' ' << read.symbol(a[0]) << " (" << sign_word(read.sign(a[1])) << ") " << read.symbol(a[2]);
        any = true;
    });
    os << (any ? "\n" : " none\n") << "  net force:";
    for (std::size_t o = 0; o < c.chain.objects.size(); ++o)
        os << (o ? "," : "") << ' ' << m.parts[c.chain.objects[o]].name << " (" << sign_word(dynamics->net_force[o]) << ')';
    os << '\n';
    for (const auto& step : dynamics->steps) {
        os << "  step " << step.name << " (" << to_string(step.duration) << ", " << cause_words(step.cause).front() << "):";
        for (std::size_t k = 0; k < step.places.size(); ++k) {
            os << ' ' << e.pairs[c.chain.pairs[k]].name << " ->";
            for (const auto& o : step.places[k]) os << ' ' << o.place.value << ' ' << to_string(o.how) << (&o == &step.places[k].back() ? "" : ",");
            os << ';';
        }
        for (std::size_t o = 0; o < step.motions.size(); ++o) {
            os << ' ' << m.parts[c.chain.objects[o]].name;
            for (const auto x : step.motions[o]) os << ' ' << sign_word(x);
            os << (o + 1 < step.motions.size() ? ";" : "");
        }
        os << '\n';
    }
    for (const auto& [first, then] : dynamics->preempts)
        os << "  step " << dynamics->steps[then].name << " happens only if step " << dynamics->steps[first].name << " cannot (Law 4)\n";
    if (dynamics->steps.empty()) os << "  no step: nothing changes (a terminal state)\n";
    if (dynamics->may_rest)
        os << "  a possible rest: its contacts may hold every part its forces would start, depending on magnitudes (rules/clock/rest.rules)\n";
    std::size_t n = 0;
    for (const auto& t : c.transitions) n += t.from == s.state;
    os << "  next (" << n << "):\n";
    for (const auto& t : c.transitions)
        if (t.from == s.state) os << "    " << transition_text(e, c, t, t.to) << '\n';
    return true;
}

void write_previous(std::ostream& os, const Envisionment& e, const StateRef& s) {
    const ChainEnvisionment& c = e.chains[s.chain];
    std::size_t n = 0;
    for (const auto& t : c.transitions) n += t.to == s.state;
    os << "state #" << s.state.value << ' ' << state_name(e, c, s.state) << " (chain " << c.chain.index + 1 << ")\n  previous (" << n << "):\n";
    for (const auto& t : c.transitions)
        if (t.to == s.state) os << "    " << transition_text(e, c, t, t.from) << '\n';
}

}  // namespace qm::envision

namespace qm::envision {

void write_behaviour(std::ostream& os, const Envisionment& e, const Behaviour& b, const BehaviourAnswer& answer) {
    const ChainEnvisionment& c = e.chains[b.chain];
    os << "behaviour (chain " << c.chain.index + 1 << "):";
    for (std::size_t i = 0; i < b.steps.size(); ++i) os << (i ? " ;" : "") << ' ' << b.steps[i].text;
    for (const auto& d : b.avoid) os << "  avoiding: " << d.text;
    os << '\n';
    if (!answer.path.empty()) {
        os << "path (" << answer.path.size() << (answer.path.size() == 1 ? " state" : " states") << "):\n";
        for (std::size_t i = 0; i < answer.path.size(); ++i) {
            os << "  #" << answer.path[i].value << ' ' << state_name(e, c, answer.path[i]);
            std::string marks;
            for (std::size_t d = 0; d < answer.matched_at.size(); ++d)
                if (answer.matched_at[d] == i) marks += (marks.empty() ? "" : ", ") + std::to_string(d + 1) + ": " + b.steps[d].text;
            if (!marks.empty()) os << "   <- " << marks;
            os << '\n';
        }
        return;
    }
    if (answer.matched == 0) {
        os << "no path: no state matches description 1 ('" << b.steps.front().text << "')" << (b.avoid.empty() ? "" : " that is not avoided") << '\n';
        return;
    }
    os << "no path: descriptions 1.." << answer.matched << " are matched (the last at #" << answer.farthest->value << ' '
       << state_name(e, c, *answer.farthest) << "), but no path goes on to a state matching description " << answer.matched + 1 << " ('"
       << b.steps[answer.matched].text << "')\n";
}

}  // namespace qm::envision
