// envision/state_query.cpp
#include "envision/state_query.hpp"

#include <cctype>

namespace qm::envision {

namespace {

struct Word {
    std::string text;
    std::uint32_t column;
};

std::vector<Word> words_of(const std::string& s) {
    std::vector<Word> out;
    for (std::size_t i = 0; i < s.size();) {
        while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
        const std::size_t start = i;
        while (i < s.size() && !std::isspace(static_cast<unsigned char>(s[i]))) ++i;
        if (i > start) out.push_back({s.substr(start, i - start), static_cast<std::uint32_t>(start + 1)});
    }
    return out;
}

std::optional<std::uint64_t> number(std::string_view s) {
    if (!s.empty() && s.front() == '#') s.remove_prefix(1);
    if (s.empty() || s.size() > 9) return std::nullopt;
    std::uint64_t n = 0;
    for (char c : s) {
        if (c < '0' || c > '9') return std::nullopt;
        n = n * 10 + static_cast<std::uint64_t>(c - '0');
    }
    return n;
}

}  // namespace

std::optional<StateRef> find_state(const Envisionment& e, const std::string& text, const std::string& option, Diagnostics& diagnostics) {
    const auto named = parse_state(e, text, option, diagnostics);
    if (!named) return std::nullopt;
    if (!named->id) {
        diagnostics.error({option, 1, 1}, "'" + text + "' is not a state of the envisionment: its motions are not consistent with its places", text);
        return std::nullopt;
    }
    return StateRef{named->chain, *named->id};
}

std::optional<NamedState> parse_state(const Envisionment& e, const std::string& text, const std::string& option, Diagnostics& diagnostics,
                                      const std::string& whole, std::uint32_t offset) {
    auto error = [&](std::uint32_t column, const std::string& message) {
        diagnostics.error({option, 1, column + offset - 1}, message, whole.empty() ? text : whole);
        return std::nullopt;
    };
    const auto words = words_of(text);
    if (words.empty()) return error(1, "expected a state: its id (as `#12`) or its name (as `PAIR-PLACE ... m1 m2 ...`)");
    if (words.size() == 1 && words[0].text.find('/') == std::string::npos) {
        // An id, with its chain when there are several.
        std::string w = words[0].text;
        std::size_t chain = 0;
        if (const auto colon = w.find(':'); colon != std::string::npos) {
            const auto c = number(w.substr(0, colon));
            if (!c || *c == 0 || *c > e.chains.size())
                return error(words[0].column, "unknown chain '" + w.substr(0, colon) + "' (there " +
                                                  (e.chains.size() == 1 ? "is 1 chain" : "are " + std::to_string(e.chains.size()) + " chains") + ")");
            chain = static_cast<std::size_t>(*c - 1);
            w = w.substr(colon + 1);
        } else if (e.chains.size() > 1) {
            return error(words[0].column, "there are " + std::to_string(e.chains.size()) + " chains: name the state as CHAIN:ID (e.g. 1:" + w + ") or by its name");
        }
        const auto id = number(w);
        if (!id) return error(words[0].column, "expected a state id (a number, as `#12`) or a state name, not '" + words[0].text + "'");
        if (*id >= e.chains[chain].states.size())
            return error(words[0].column, "no state " + std::to_string(*id) + ": chain " + std::to_string(chain + 1) + " has " +
                                              std::to_string(e.chains[chain].states.size()) + " states (ids from 0)");
        const StateId sid{static_cast<std::uint32_t>(*id)};
        return NamedState{chain, e.chains[chain].states[sid], sid};
    }
    // A name: PAIR-PLACE for each pair of one chain, then a motion for each of its objects.
    std::optional<std::size_t> chain;
    State wanted;
    std::vector<bool> named;
    std::size_t w = 0;
    for (; w < words.size() && words[w].text.find('/') != std::string::npos; ++w) {
        const std::string& t = words[w].text;
        const auto dash = t.rfind('-');
        const auto place = dash == std::string::npos ? std::nullopt : number(t.substr(dash + 1));
        if (!place) return error(words[w].column, "expected PAIR-PLACE (as `scape-wheel/pallets-36`), not '" + t + "'");
        const std::string pair = t.substr(0, dash);
        std::optional<std::pair<std::size_t, std::size_t>> found;  // chain, position in chain
        for (std::size_t c = 0; c < e.chains.size() && !found; ++c)
            for (std::size_t k = 0; k < e.chains[c].chain.pairs.size(); ++k)
                if (e.pairs[e.chains[c].chain.pairs[k]].name == pair) found = {c, k};
        if (!found) return error(words[w].column, "unknown pair '" + pair + "'");
        if (chain && *chain != found->first) return error(words[w].column, "pair '" + pair + "' is in another chain than the pairs before it");
        chain = found->first;
        const auto& c = e.chains[*chain];
        if (wanted.places.empty()) wanted.places.assign(c.chain.pairs.size(), geometry::PlaceId{0});
        if (named.size() <= found->second) named.resize(c.chain.pairs.size(), false);
        if (named[found->second]) return error(words[w].column, "pair '" + pair + "' is named twice");
        named[found->second] = true;
        const auto count = e.pairs[c.chain.pairs[found->second]].vocabulary.places.size();
        if (*place >= count)
            return error(words[w].column, "pair '" + pair + "' has no place " + std::to_string(*place) + " (places 0.." + std::to_string(count - 1) + ")");
        wanted.places[found->second] = geometry::PlaceId{static_cast<std::uint32_t>(*place)};
    }
    if (!chain) return error(words[0].column, "expected a state name starting with PAIR-PLACE (as `scape-wheel/pallets-36 - -`), not '" + words[0].text + "'");
    const auto& c = e.chains[*chain];
    if (w != c.chain.pairs.size())
        return error(words[0].column, "a state of chain " + std::to_string(*chain + 1) + " names the place of each of its " +
                                          std::to_string(c.chain.pairs.size()) + " pairs, in the chain's order");
    for (; w < words.size(); ++w) {
        const std::string& t = words[w].text;
        if (t != "+" && t != "0" && t != "-") return error(words[w].column, "expected a motion +, 0 or -, not '" + t + "'");
        wanted.motions.push_back(static_cast<std::int8_t>(t == "+" ? 1 : t == "-" ? -1 : 0));
    }
    if (wanted.motions.size() != c.chain.objects.size())
        return error(words.back().column, "expected " + std::to_string(c.chain.objects.size()) + " motions (one per part of the chain) after the places, found " +
                                              std::to_string(wanted.motions.size()));
    return NamedState{*chain, wanted, c.states.find(wanted)};
}

}  // namespace qm::envision
