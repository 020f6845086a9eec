// cli/state_drawing.cpp
#include "state_drawing.hpp"

#include "bridge/pair_places.hpp"
#include "rules_location.hpp"

#include "envision/state_query.hpp"
#include "geometry/mechanism_drawing.hpp"
#include "geometry/place_sample.hpp"

#include <algorithm>
#include <cctype>
#include <sstream>

namespace qm::cli {

namespace {

namespace g = qm::geometry;
namespace ev = qm::envision;

// "after an instant (kinematic, collision)": how the history got to a state.
std::string transition_text(const ev::ChainEnvisionment& c, ev::StateId from, ev::StateId to) {
    for (const auto& t : c.transitions) {
        if (t.from != from || t.to != to) continue;
        std::string causes;
        for (const auto& w : ev::cause_words(t.causes)) causes += (causes.empty() ? "" : ", ") + w;
        return std::string(t.duration == ev::Duration::instant ? "after an instant" : "after an interval") + " (" + causes + ")";
    }
    return "";
}

std::string xml_text(const std::string& s) {
    std::string out;
    for (const char ch : s) out += ch == '<' ? "&lt;" : ch == '>' ? "&gt;" : ch == '&' ? "&amp;" : std::string(1, ch);
    return out;
}

bool has_transition(const ev::ChainEnvisionment& c, ev::StateId from, ev::StateId to) {
    return std::any_of(c.transitions.begin(), c.transitions.end(), [&](const ev::Transition& t) { return t.from == from && t.to == to; });
}

}  // namespace

std::optional<ev::Envisionment> envision_for_drawing(const g::Mechanism& m, bool use_cache, const std::optional<std::filesystem::path>& cache_dir,
                                                     Diagnostics& diags) {
    const auto rules = default_rules_directory();
    if (!rules) {
        diags.error({"qm-atms", 1, 1}, "cannot find the laws (rules/clock): set QM_ATMS_RULES");
        return std::nullopt;
    }
    const std::optional<g::PlaceCache> cache = bridge::open_place_cache(use_cache, cache_dir);
    ev::EnvisionOptions options;
    options.rules = *rules / "clock";
    options.cache = cache ? &*cache : nullptr;
    return ev::envision(m, options, diags);
}

std::vector<g::PartId> chain_drawn_parts(const ev::Envisionment& e, const ev::ChainEnvisionment& c) {
    std::vector<g::PartId> drawn(c.chain.objects.begin(), c.chain.objects.end());
    for (const std::size_t k : c.chain.pairs)
        for (const g::PartId p : {e.pairs[k].spec.a, e.pairs[k].spec.b})
            if (std::find(drawn.begin(), drawn.end(), p) == drawn.end()) drawn.push_back(p);
    return drawn;
}

g::Configuration state_configuration(const g::Mechanism& m, const ev::Envisionment& e, const ev::ChainEnvisionment& c, ev::StateId s) {
    g::Configuration q{std::vector<double>(m.parts.size(), 0.0)};
    std::vector<bool> placed(m.parts.size(), false);
    const ev::State& state = c.states[s];
    for (std::size_t k = 0; k < c.chain.pairs.size(); ++k) {
        const auto& pair = e.pairs[c.chain.pairs[k]];
        const g::Place& place = pair.vocabulary.places[state.places[k].value];
        const Eigen::Vector2d sample = g::sample_configuration(pair.request.cspace, place);
        for (int i = 0; i < 2; ++i) {
            const g::PartId p = i == 0 ? pair.spec.a : pair.spec.b;
            if (placed[p.value] || m.parts[p].fixed()) continue;  // a fixed part's axis is a dummy
            q.q[p.value] = sample[i];
            placed[p.value] = true;
        }
    }
    return q;
}

std::optional<History> parse_history(const ev::Envisionment& e, const std::string& text, Diagnostics& diags) {
    // States named in full hold spaces, so `;` separates them when there is one; else spaces do.
    const char separator = text.find(';') != std::string::npos ? ';' : ' ';
    std::vector<std::pair<std::string, std::uint32_t>> words;
    for (std::size_t i = 0; i <= text.size();) {
        const std::size_t end = std::min(text.find(separator, i), text.size());
        std::size_t a = i, b = end;
        while (a < b && std::isspace(static_cast<unsigned char>(text[a]))) ++a;
        while (b > a && std::isspace(static_cast<unsigned char>(text[b - 1]))) --b;
        if (b > a) words.emplace_back(text.substr(a, b - a), static_cast<std::uint32_t>(a + 1));
        i = end + 1;
    }
    if (words.empty()) {
        diags.error({"--history", 1, 1}, "expected the states of a history: ids ('#12 #15 #3') or names separated by ';'", text);
        return std::nullopt;
    }
    History h;
    for (std::size_t k = 0; k < words.size(); ++k) {
        const auto s = ev::find_state(e, words[k].first, "--history", diags);
        if (!s) return std::nullopt;
        if (k == 0) h.chain = s->chain;
        const SourceLocation at{"--history", 1, words[k].second};
        if (s->chain != h.chain) {
            diags.error(at, "'" + words[k].first + "' is a state of chain " + std::to_string(s->chain + 1) + ", the history's first of chain " +
                                std::to_string(h.chain + 1) + ": a history stays in one chain", text);
            return std::nullopt;
        }
        if (k > 0 && !has_transition(e.chains[h.chain], h.states.back(), s->state)) {
            diags.error(at, "no transition from #" + std::to_string(h.states.back().value) + " to #" + std::to_string(s->state.value) +
                                " (envision --why-not '" + std::to_string(h.states.back().value) + " -> " + std::to_string(s->state.value) +
                                "' says why)", text);
            return std::nullopt;
        }
        h.states.push_back(s->state);
    }
    return h;
}

void write_history_svg(std::ostream& os, const g::Mechanism& m, const ev::Envisionment& e, const History& h, int panel_width, int panel_height,
                       std::size_t columns) {
    const auto& c = e.chains[h.chain];
    const auto drawn = chain_drawn_parts(e, c);
    columns = std::max<std::size_t>(1, std::min(columns, h.states.size()));
    const std::size_t rows = (h.states.size() + columns - 1) / columns;
    const int header = 28, footer = 22, label_height = 36;
    const int width = static_cast<int>(columns) * panel_width, height = header + static_cast<int>(rows) * panel_height + footer;
    os << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height << "\" viewBox=\"0 0 " << width << ' '
       << height << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n<text x=\"12\" y=\"19\" font-family=\"sans-serif\" "
       << "font-size=\"14\">" << xml_text(m.name + ": a history of chain " + std::to_string(c.chain.index + 1) + ", " +
                                                          std::to_string(h.states.size()) + " states")
       << "</text>\n";
    for (std::size_t k = 0; k < h.states.size(); ++k) {
        const ev::StateId s = h.states[k];
        const g::Configuration q = state_configuration(m, e, c, s);
        auto parts = g::drawn_parts(m, q, drawn);
        for (std::size_t i = 0; i < drawn.size(); ++i) {
            const auto it = std::find(c.chain.objects.begin(), c.chain.objects.end(), drawn[i]);
            if (it != c.chain.objects.end()) parts[i].motion = c.states[s].motions[static_cast<std::size_t>(it - c.chain.objects.begin())];
        }
        const auto contacts = g::mechanism_contacts(m, q, drawn);
        // Two lines above each drawing, the same for every drawing so that the drawings line up: the
        // state, and how the history got there.
        const int x = static_cast<int>(k % columns) * panel_width, y = header + static_cast<int>(k / columns) * panel_height;
        os << "<text class=\"state-name\" x=\"" << x + 10 << "\" y=\"" << y + 16 << "\" font-family=\"sans-serif\" font-size=\"12\">"
           << xml_text(std::to_string(k + 1) + ". #" + std::to_string(s.value) + " " + ev::state_name(e, c, s)) << "</text>\n";
        if (k > 0)
            os << "<text x=\"" << x + 10 << "\" y=\"" << y + 31 << "\" font-family=\"sans-serif\" font-size=\"11\" fill=\"#555555\">"
               << xml_text(transition_text(c, h.states[k - 1], s)) << "</text>\n";
        std::ostringstream panel;
        g::write_parts_svg(panel, parts, contacts.marks, {panel_width, panel_height - label_height, "", false, m.settings.normal_zero_tolerance});
        // Each drawing is a nested <svg> placed in the strip (its own viewBox keeps its coordinates).
        std::string text = panel.str();
        text.insert(4, " class=\"history-state\" data-state=\"" + std::to_string(s.value) + "\" x=\"" + std::to_string(x) + "\" y=\"" +
                           std::to_string(y + label_height) + "\"");
        os << text;
        os << "<rect x=\"" << x + 0.5 << "\" y=\"" << y + 0.5 << "\" width=\"" << panel_width - 1 << "\" height=\"" << panel_height - 1
           << "\" fill=\"none\" stroke=\"#cccccc\"/>\n";
    }
    os << "<text x=\"12\" y=\"" << height - 7 << "\" font-family=\"sans-serif\" font-size=\"11\" fill=\"#555555\">Orange arrows: the parts' "
       << "motions (+ counter-clockwise, or along the axis); black dots: contacts, with the surfaces' outward normals. Each pair at its "
       << "place's sample configuration.</text>\n</svg>\n";
}

}  // namespace qm::cli
