// envision/json_printer.cpp: schema qm-envisionment/1.
#include "envision/json_printer.hpp"
#include "qm/json.hpp"

#include <algorithm>

namespace qm::envision {

namespace {

using qm::json_string;

std::string parts_json(const geometry::Mechanism& m, const bridge::PairPlaces& p) {
    return "[" + json_string(m.parts[p.spec.a].name) + "," + json_string(m.parts[p.spec.b].name) + "]";
}

std::string signs_json(const geometry::Mechanism& m, const Chain& chain, const std::vector<std::int8_t>& signs) {
    std::string out = "{";
    for (std::size_t o = 0; o < chain.objects.size(); ++o) {
        out += (o ? "," : "") + json_string(m.parts[chain.objects[o]].name) + ":\"(";
        out += (o < signs.size() ? sign_word(signs[o]) : "?");
        out += ")\"";
    }
    return out + "}";
}

std::string ids_json(const std::vector<StateId>& ids) {
    std::string out = "[";
    for (std::size_t i = 0; i < ids.size(); ++i) out += (i ? "," : "") + std::to_string(ids[i].value);
    return out + "]";
}

void chain_json(std::ostream& os, const geometry::Mechanism& m, const Envisionment& e, const ChainEnvisionment& c) {
    os << "{\"index\":" << c.chain.index + 1 << ",\"objects\":[";
    for (std::size_t o = 0; o < c.chain.objects.size(); ++o) os << (o ? "," : "") << json_string(m.parts[c.chain.objects[o]].name);
    os << "],\"pairs\":[";
    for (std::size_t k = 0; k < c.chain.pairs.size(); ++k) {
        const auto& p = e.pairs[c.chain.pairs[k]];
        os << (k ? "," : "") << "{\"parts\":" << parts_json(m, p) << ",\"places\":" << p.vocabulary.places.size() << '}';
    }
    os << "],\"states\":[";
    bool first = true;
    for (std::uint32_t i = 0; i < c.states.size(); ++i) {
        if (!c.is_shown(StateId{i})) continue;
        const State& s = c.states[StateId{i}];
        os << (first ? "" : ",") << "{\"id\":" << i << ",\"places\":[";
        first = false;
        for (std::size_t k = 0; k < c.chain.pairs.size(); ++k)
            os << (k ? "," : "") << "{\"parts\":" << parts_json(m, e.pairs[c.chain.pairs[k]]) << ",\"place\":" << s.places[k].value << '}';
        os << "],\"motions\":" << signs_json(m, c.chain, s.motions) << ",\"net_force\":" << signs_json(m, c.chain, s.net_force) << '}';
    }
    os << "],\"transitions\":[";
    for (std::size_t i = 0; i < c.transitions.size(); ++i) {
        const Transition& t = c.transitions[i];
        os << (i ? "," : "") << "{\"from\":" << t.from.value << ",\"to\":" << t.to.value << ",\"duration\":\"" << to_string(t.duration)
           << "\",\"causes\":[";
        const auto causes = cause_words(t.causes);
        for (std::size_t k = 0; k < causes.size(); ++k) os << (k ? "," : "") << '"' << causes[k] << '"';
        os << "]}";
    }
    os << "],\"cycles\":[";
    for (std::size_t i = 0; i < c.graph.cycles.size(); ++i) os << (i ? "," : "") << ids_json(c.graph.cycles[i]);
    os << "],\"transient_cycles\":[";
    for (std::size_t i = 0; i < c.graph.transient.size(); ++i) {
        const auto& t = c.graph.transient[i];
        os << (i ? "," : "") << "{\"states\":" << ids_json(t.states) << ",\"object\":" << json_string(m.parts[c.chain.objects[t.object]].name)
           << ",\"motion\":\"(" << sign_word(t.motion) << ")\"";
        if (t.pair) os << ",\"kept_by\":" << json_string(e.pairs[c.chain.pairs[*t.pair]].name);
        os << '}';
    }
    std::vector<StateId> ends = c.graph.terminal;
    ends.insert(ends.end(), c.graph.possible_rests.begin(), c.graph.possible_rests.end());
    std::sort(ends.begin(), ends.end());
    os << "],\"terminal\":" << ids_json(ends) << ",\"possible_rests\":" << ids_json(c.graph.possible_rests) << '}';
}

}  // namespace

void write_json(std::ostream& os, const geometry::Mechanism& m, const Envisionment& e) {
    os << "{\"schema\":\"qm-envisionment/1\",\"mechanism\":" << json_string(e.mechanism) << ",\"chains\":[";
    for (std::size_t i = 0; i < e.chains.size(); ++i) {
        if (i) os << ',';
        chain_json(os, m, e, e.chains[i]);
    }
    os << "]}\n";
}

}  // namespace qm::envision
