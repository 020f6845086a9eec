// envision/behaviour_query.cpp: reachability, described behaviours (5.4, 9.1.5, 11.2.2).
#include "envision/behaviour_query.hpp"

#include <algorithm>
#include <cctype>
#include <deque>
#include <map>

namespace qm::envision {
namespace g = qm::geometry;

namespace {

struct Word {
    std::string text;
    std::uint32_t column;
};

std::vector<std::vector<Word>> descriptions_of(const std::string& s) {
    std::vector<std::vector<Word>> out(1);
    for (std::size_t i = 0; i < s.size();) {
        if (s[i] == ';') {
            out.emplace_back();
            ++i;
            continue;
        }
        if (std::isspace(static_cast<unsigned char>(s[i]))) {
            ++i;
            continue;
        }
        const std::size_t start = i;
        while (i < s.size() && s[i] != ';' && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
        out.back().push_back({s.substr(start, i - start), static_cast<std::uint32_t>(start + 1)});
    }
    return out;
}

std::optional<std::uint64_t> number(std::string_view s) {
    if (s.empty() || s.size() > 9) return std::nullopt;
    std::uint64_t n = 0;
    for (char c : s) {
        if (c < '0' || c > '9') return std::nullopt;
        n = n * 10 + static_cast<std::uint64_t>(c - '0');
    }
    return n;
}

bool in_contact(const g::Place& p) { return !p.normals.empty(); }

class Parser {
public:
    Parser(const Envisionment& e, Diagnostics& d) : e_(e), d_(d) {}

    std::optional<StateDescription> description(const std::vector<Word>& words, const std::string& text, const std::string& option) {
        auto error = [&](std::uint32_t column, const std::string& message) {
            d_.error({option, 1, column}, message, text);
            return std::nullopt;
        };
        if (words.empty()) return error(1, "expected a state description: terms such as PAIR-PLACE, PAIR:contact, PART=+ or #ID");
        StateDescription out;
        for (const auto& w : words) {
            out.text += (out.text.empty() ? "" : " ") + w.text;
            DescriptionTerm t;
            const std::string& x = w.text;
            if (x == "terminal" || x == "rest" || x == "cycle" || x == "transient") {
                t.kind = x == "terminal" ? DescriptionTerm::Kind::terminal
                         : x == "rest"   ? DescriptionTerm::Kind::rest
                         : x == "cycle"  ? DescriptionTerm::Kind::cycle
                                         : DescriptionTerm::Kind::transient;
                out.terms.push_back(t);
                continue;
            }
            if (x.front() == '#') {
                const auto id = number(x.substr(1));
                if (!id) return error(w.column, "expected a state id after '#', not '" + x + "'");
                t.kind = DescriptionTerm::Kind::state;
                t.value = static_cast<std::uint32_t>(*id);
                out.terms.push_back(t);
                continue;
            }
            if (const auto eq = x.find('='); eq != std::string::npos) {
                const std::string part = x.substr(0, eq), m = x.substr(eq + 1);
                if (m != "+" && m != "0" && m != "-") return error(w.column + static_cast<std::uint32_t>(eq) + 1, "expected a motion +, 0 or -, not '" + m + "'");
                auto where = object(part);
                if (!where) return error(w.column, "unknown part '" + part + "' (in no chain)");
                if (!same_chain(where->first)) return error(w.column, "'" + part + "' is in another chain than the terms before it");
                t.kind = DescriptionTerm::Kind::motion;
                t.index = where->second;
                t.motion = static_cast<std::int8_t>(m == "+" ? 1 : m == "-" ? -1 : 0);
                out.terms.push_back(t);
                continue;
            }
            if (const auto colon = x.find(':'); colon != std::string::npos) {
                const std::string pair = x.substr(0, colon), kind = x.substr(colon + 1);
                auto where = pair_of(pair);
                if (!where) return error(w.column, "unknown pair '" + pair + "'");
                if (!same_chain(where->first)) return error(w.column, "pair '" + pair + "' is in another chain than the terms before it");
                t.index = where->second;
                if (kind == "contact") t.kind = DescriptionTerm::Kind::contact;
                else if (kind == "free") t.kind = DescriptionTerm::Kind::free;
                else {
                    t.kind = DescriptionTerm::Kind::place_kind;
                    bool known = false;
                    for (const auto k : {g::PlaceKind::cseg, g::PlaceKind::join, g::PlaceKind::fsd, g::PlaceKind::external_division,
                                         g::PlaceKind::face, g::PlaceKind::stop})
                        if (kind == g::to_string(k)) {
                            t.place_kind = k;
                            known = true;
                        }
                    if (!known)
                        return error(w.column + static_cast<std::uint32_t>(colon) + 1,
                                     "unknown kind of place '" + kind + "' (contact, free, cseg, join, fsd, external-division, face, stop)");
                }
                out.terms.push_back(t);
                continue;
            }
            const auto dash = x.rfind('-');
            const auto place = dash == std::string::npos ? std::nullopt : number(x.substr(dash + 1));
            if (!place || x.find('/') == std::string::npos)
                return error(w.column, "expected PAIR-PLACE, PAIR:KIND, PART=MOTION, #ID, terminal, rest, cycle or transient, not '" + x + "'");
            auto where = pair_of(x.substr(0, dash));
            if (!where) return error(w.column, "unknown pair '" + x.substr(0, dash) + "'");
            if (!same_chain(where->first)) return error(w.column, "pair '" + x.substr(0, dash) + "' is in another chain than the terms before it");
            const auto count = e_.pairs[e_.chains[where->first].chain.pairs[where->second]].vocabulary.places.size();
            if (*place >= count)
                return error(w.column, "pair '" + x.substr(0, dash) + "' has no place " + std::to_string(*place) + " (places 0.." + std::to_string(count - 1) + ")");
            t.kind = DescriptionTerm::Kind::place;
            t.index = where->second;
            t.value = static_cast<std::uint32_t>(*place);
            out.terms.push_back(t);
        }
        return out;
    }

    std::optional<std::size_t> chain() const { return chain_; }
    bool same_chain(std::size_t c) {
        if (chain_ && *chain_ != c) return false;
        chain_ = c;
        return true;
    }

private:
    std::optional<std::pair<std::size_t, std::size_t>> pair_of(const std::string& name) const {
        for (std::size_t c = 0; c < e_.chains.size(); ++c)
            for (std::size_t k = 0; k < e_.chains[c].chain.pairs.size(); ++k)
                if (e_.pairs[e_.chains[c].chain.pairs[k]].name == name) return std::pair{c, k};
        return std::nullopt;
    }
    std::optional<std::pair<std::size_t, std::size_t>> object(const std::string& name) const {
        for (std::size_t c = 0; c < e_.chains.size(); ++c)
            for (std::size_t o = 0; o < e_.chains[c].chain.objects.size(); ++o)
                if (e_.parts[e_.chains[c].chain.objects[o].value] == name) return std::pair{c, o};
        return std::nullopt;
    }

    const Envisionment& e_;
    Diagnostics& d_;
    std::optional<std::size_t> chain_;
};

}  // namespace

std::vector<bool> reachable_from(const ChainEnvisionment& c, StateId from) {
    std::vector<std::vector<StateId>> next(c.states.size());
    for (const auto& t : c.transitions) next[t.from.value].push_back(t.to);
    std::vector<bool> seen(c.states.size(), false);
    std::deque<StateId> queue{from};
    seen[from.value] = true;
    while (!queue.empty()) {
        const StateId s = queue.front();
        queue.pop_front();
        for (const StateId t : next[s.value])
            if (!seen[t.value]) {
                seen[t.value] = true;
                queue.push_back(t);
            }
    }
    return seen;
}

bool matches(const Envisionment& e, const ChainEnvisionment& c, StateId s, const StateDescription& d) {
    const State& state = c.states[s];
    const auto in = [s](const std::vector<StateId>& sorted) { return std::binary_search(sorted.begin(), sorted.end(), s); };
    for (const auto& t : d.terms) {
        bool ok = true;
        switch (t.kind) {
            case DescriptionTerm::Kind::state: ok = s.value == t.value; break;
            case DescriptionTerm::Kind::terminal: ok = in(c.graph.terminal); break;
            case DescriptionTerm::Kind::rest: ok = in(c.graph.terminal) || in(c.graph.possible_rests); break;
            case DescriptionTerm::Kind::cycle: ok = std::any_of(c.graph.cycles.begin(), c.graph.cycles.end(), in); break;
            case DescriptionTerm::Kind::transient:
                ok = std::any_of(c.graph.transient.begin(), c.graph.transient.end(), [&](const TransientCycle& x) { return in(x.states); });
                break;
            case DescriptionTerm::Kind::motion: ok = state.motions[t.index] == t.motion; break;
            case DescriptionTerm::Kind::place: ok = state.places[t.index].value == t.value; break;
            default: {
                const g::Place& p = e.pairs[c.chain.pairs[t.index]].vocabulary.at(state.places[t.index]);
                if (t.kind == DescriptionTerm::Kind::contact) ok = in_contact(p);
                else if (t.kind == DescriptionTerm::Kind::free) ok = !in_contact(p);
                else ok = p.kind == t.place_kind;
            }
        }
        if (!ok) return false;
    }
    return true;
}

std::optional<Behaviour> parse_behaviour(const Envisionment& e, const std::string& steps, const std::string& steps_option,
                                         const std::vector<std::string>& avoid, Diagnostics& diagnostics) {
    Parser p(e, diagnostics);
    Behaviour b;
    bool ok = true;
    for (const auto& words : descriptions_of(steps)) {
        auto d = p.description(words, steps, steps_option);
        if (!d) {
            ok = false;
            continue;
        }
        b.steps.push_back(std::move(*d));
    }
    for (const auto& a : avoid)
        for (const auto& words : descriptions_of(a)) {
            auto d = p.description(words, a, "--avoid");
            if (!d) {
                ok = false;
                continue;
            }
            b.avoid.push_back(std::move(*d));
        }
    if (!ok) return std::nullopt;
    if (!p.chain()) {
        if (e.chains.size() > 1) {
            diagnostics.error({steps_option, 1, 1}, "there are " + std::to_string(e.chains.size()) + " chains: name a pair or a part of the one meant", steps);
            return std::nullopt;
        }
        b.chain = 0;
    } else {
        b.chain = *p.chain();
    }
    for (const auto& d : b.steps)
        for (const auto& t : d.terms)
            if (t.kind == DescriptionTerm::Kind::state && t.value >= e.chains[b.chain].states.size()) {
                diagnostics.error({steps_option, 1, 1}, "no state " + std::to_string(t.value) + " in chain " + std::to_string(b.chain + 1), steps);
                return std::nullopt;
            }
    return b;
}

BehaviourAnswer find_behaviour(const Envisionment& e, const Behaviour& b) {
    const ChainEnvisionment& c = e.chains[b.chain];
    const std::size_t n = c.states.size(), k = b.steps.size();
    std::vector<std::vector<StateId>> next(n);
    for (const auto& t : c.transitions) next[t.from.value].push_back(t.to);
    auto avoided = [&](StateId s) {
        for (const auto& d : b.avoid)
            if (matches(e, c, s, d)) return true;
        return false;
    };
    // Greedy: a state matches as many of the next descriptions as it can (matching a description
    // as early as possible never costs a later one).
    auto advance = [&](StateId s, std::size_t done) {
        while (done < k && matches(e, c, s, b.steps[done])) ++done;
        return done;
    };
    // Breadth-first over (state, descriptions matched).
    std::map<std::pair<std::uint32_t, std::size_t>, std::pair<std::uint32_t, std::size_t>> parent;
    std::deque<std::pair<std::uint32_t, std::size_t>> queue;
    BehaviourAnswer answer;
    for (std::uint32_t s = 0; s < n; ++s) {
        if (avoided(StateId{s}) || !matches(e, c, StateId{s}, b.steps.front())) continue;
        const auto node = std::pair{s, advance(StateId{s}, 0)};
        if (parent.emplace(node, node).second) queue.push_back(node);
    }
    std::optional<std::pair<std::uint32_t, std::size_t>> goal;
    while (!queue.empty() && !goal) {
        const auto node = queue.front();
        queue.pop_front();
        if (node.second > answer.matched) {
            answer.matched = node.second;
            answer.farthest = StateId{node.first};
        }
        if (node.second == k) {
            goal = node;
            break;
        }
        for (const StateId t : next[node.first]) {
            if (avoided(t)) continue;
            const auto to = std::pair{t.value, advance(t, node.second)};
            if (parent.emplace(to, node).second) queue.push_back(to);
        }
    }
    if (!goal) return answer;
    std::vector<std::pair<std::uint32_t, std::size_t>> nodes;
    for (auto node = *goal;; node = parent.at(node)) {
        nodes.push_back(node);
        if (parent.at(node) == node) break;
    }
    std::reverse(nodes.begin(), nodes.end());
    std::size_t done = 0;
    for (std::size_t i = 0; i < nodes.size(); ++i) {
        answer.path.push_back(StateId{nodes[i].first});
        for (; done < nodes[i].second; ++done) answer.matched_at.push_back(i);
    }
    answer.matched = k;
    return answer;
}

}  // namespace qm::envision
