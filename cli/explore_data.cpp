// cli/explore_data.cpp
#include "explore_data.hpp"
#include "state_drawing.hpp"

#include "envision/json_printer.hpp"
#include "geometry/contact_detection.hpp"
#include "geometry/cspace_svg.hpp"
#include "geometry/mechanism_drawing.hpp"
#include "geometry/part_svg.hpp"
#include "geometry/place_json.hpp"
#include "geometry/place_sample.hpp"
#include "qm/assert.hpp"
#include "qm/json.hpp"

#include <algorithm>
#include <numbers>
#include <sstream>
#include <string_view>

namespace qm::cli {

namespace {

namespace g = qm::geometry;
namespace ev = qm::envision;

// The data sits inside an HTML <script> element: its strings are written with "</" as "<\/".
void json_string(std::ostream& os, std::string_view s) { write_json_string(os, s, Json::in_script); }

const char* unit_of(const g::Part& p) { return p.rotates() ? "degrees" : p.translates() ? "length" : "fixed"; }

double scene_value(const g::Part& p, double q) { return p.rotates() ? q * 180.0 / std::numbers::pi : p.translates() ? q : 0.0; }

// The pair's parts at configuration q: its values in the scene's units, the parts' transforms,
// the contact marks.
class PairDrawing {
public:
    PairDrawing(const g::Mechanism& m, const ExplorePair& e)
        : m_(m), e_(e), parts_{{&m.parts[e.pair.a], 0.0}, {&m.parts[e.pair.b], 0.0}},
          options_{560, 460, "", true, m.settings.normal_zero_tolerance}, frame_(g::parts_frame(parts_, options_)) {}

    void write_svg(std::ostream& os) const { g::write_parts_svg(os, parts_, {}, options_); }

    void write_at(std::ostream& os, Eigen::Vector2d q) const {
        for (int k = 0; k < 2; ++k)
            if (parts_[static_cast<std::size_t>(k)].part->fixed()) q[k] = 0.0;  // a fixed part's dummy axis
        const g::ContactRequest request{m_.settings.contact_tolerance, m_.settings.normal_zero_tolerance};
        const auto contacts = g::detect_contacts(*e_.places.oracle, q, request);
        const bool overlap = contacts.status == g::ContactStatus::overlapping;
        const auto marks = overlap ? std::vector<g::ContactMark>{} : g::contact_marks(m_, e_.pair, contacts, 0, 1);
        std::ostringstream svg;
        g::write_contact_marks(svg, frame_, parts_, marks, options_);
        const auto precision = os.precision(10);
        os << "{\"config\":[" << scene_value(*parts_[0].part, q[0]) << ',' << scene_value(*parts_[1].part, q[1]) << "],\"q\":[" << q[0] << ','
           << q[1] << "],\"transforms\":[";
        json_string(os, g::part_transform(*parts_[0].part, q[0]));
        os << ',';
        json_string(os, g::part_transform(*parts_[1].part, q[1]));
        os << "],\"contacts\":" << marks.size() << ",\"overlap\":" << (overlap ? "true" : "false") << ",\"contacts_svg\":";
        json_string(os, svg.str());
        os << '}';
        os.precision(precision);
    }

private:
    const g::Mechanism& m_;
    const ExplorePair& e_;
    std::vector<g::DrawnPart> parts_;
    g::DrawingOptions options_;
    g::DrawingFrame frame_;
};

void write_pair(std::ostream& os, const g::Mechanism& m, const ExplorePair& e) {
    const g::Part& a = m.parts[e.pair.a];
    const g::Part& b = m.parts[e.pair.b];
    os << "{\"parts\":[";
    json_string(os, a.name);
    os << ',';
    json_string(os, b.name);
    os << "],\"units\":[\"" << unit_of(a) << "\",\"" << unit_of(b) << "\"],\n\"vocabulary\":";
    const auto svg = bridge::cspace_svg_options(m, e.pair, 720, 540);
    g::write_place_json(os, e.places.request.cspace, e.places.vocabulary, {svg.axes[0].unit, svg.axes[1].unit});
    std::ostringstream cspace;
    g::write_cspace_svg(cspace, *e.places.oracle, *e.places.space, e.places.vocabulary, bridge::cspace_svg_options(m, e.pair, 720, 540));
    os << ",\"cspace_svg\":";
    json_string(os, cspace.str());
    const PairDrawing drawing(m, e);
    std::ostringstream parts;
    drawing.write_svg(parts);
    os << ",\n\"drawing_svg\":";
    json_string(os, parts.str());
    os << ",\n\"as_drawn\":";
    drawing.write_at(os, Eigen::Vector2d::Zero());
    os << ",\n\"samples\":[";
    for (const auto& p : e.places.vocabulary.places) {
        os << (p.id.value ? ",\n" : "\n");
        drawing.write_at(os, g::sample_configuration(e.places.request.cspace, p));
    }
    os << "]}";
}

// The pair of the page (its index in `pairs`) with the parts of an envisioned pair.
std::size_t page_pair(const g::Mechanism& m, const std::vector<ExplorePair>& pairs, const bridge::PairPlaces& p) {
    for (std::size_t k = 0; k < pairs.size(); ++k)
        if (pairs[k].pair.a == p.spec.a && pairs[k].pair.b == p.spec.b) return k;
    throw InternalError("the envisioned pair " + m.parts[p.spec.a].name + "/" + m.parts[p.spec.b].name + " is not a pair of the page");
}

// A chain drawn as one picture: its parts as drawn, their motions' arrows, and every pair's contact
// marks at every place (in this picture's frame). The page puts a state's parts where the first pair
// that holds each puts it, as state_configuration() does.
void write_chain(std::ostream& os, const g::Mechanism& m, const std::vector<ExplorePair>& pairs, const ev::Envisionment& e,
                 const ev::ChainEnvisionment& c) {
    const auto drawn_ids = chain_drawn_parts(e, c);
    std::vector<g::DrawnPart> drawn;
    for (const auto p : drawn_ids) drawn.push_back({&m.parts[p], 0.0});
    const g::DrawingOptions options{560, 460, "", true, m.settings.normal_zero_tolerance};
    const g::DrawingFrame frame = g::parts_frame(drawn, options);
    std::ostringstream svg;
    g::write_parts_svg(svg, drawn, {}, options);
    os << "{\"index\":" << c.chain.index + 1 << ",\"parts\":[";
    for (std::size_t k = 0; k < drawn.size(); ++k) {
        os << (k ? "," : "");
        json_string(os, drawn[k].part->name);
    }
    os << "],\"drawing_svg\":";
    json_string(os, svg.str());
    os << ",\"world_transform\":";
    json_string(os, frame.world_transform());
    os << ",\"arrows\":{";
    for (std::size_t k = 0; k < drawn.size(); ++k) {
        os << (k ? "," : "");
        json_string(os, drawn[k].part->name);
        os << ":{\"+\":";
        json_string(os, g::motion_arrow(*drawn[k].part, 0.0, 1, frame.scale));
        os << ",\"-\":";
        json_string(os, g::motion_arrow(*drawn[k].part, 0.0, -1, frame.scale));
        os << '}';
    }
    os << "},\n\"pairs\":[";
    const g::ContactRequest request{m.settings.contact_tolerance, m.settings.normal_zero_tolerance};
    for (std::size_t k = 0; k < c.chain.pairs.size(); ++k) {
        const std::size_t index = page_pair(m, pairs, e.pairs[c.chain.pairs[k]]);
        const ExplorePair& pair = pairs[index];
        const auto at = [&](g::PartId p) { return static_cast<std::size_t>(std::find(drawn_ids.begin(), drawn_ids.end(), p) - drawn_ids.begin()); };
        os << (k ? ",\n" : "\n") << "{\"pair\":" << index << ",\"contacts_svg\":[";
        for (const auto& place : pair.places.vocabulary.places) {
            Eigen::Vector2d q = g::sample_configuration(pair.places.request.cspace, place);
            for (int i = 0; i < 2; ++i)
                if (m.parts[i == 0 ? pair.pair.a : pair.pair.b].fixed()) q[i] = 0.0;
            const auto contacts = g::detect_contacts(*pair.places.oracle, q, request);
            std::ostringstream marks;
            if (contacts.status != g::ContactStatus::overlapping)
                g::write_contact_marks(marks, frame, drawn, g::contact_marks(m, pair.pair, contacts, at(pair.pair.a), at(pair.pair.b)), options);
            os << (place.id.value ? "," : "");
            json_string(os, marks.str());
        }
        os << "]}";
    }
    os << "]}";
}

}  // namespace

void write_explore_data(std::ostream& os, const g::Mechanism& m, const std::vector<ExplorePair>& pairs, const std::vector<g::SkippedPair>& skipped,
                        const ev::Envisionment* e, const std::vector<ExplorePath>& paths) {
    os << "{\"schema\":\"qm-explore/1\",\"mechanism\":";
    json_string(os, m.name);
    os << ",\"pairs\":[";
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        os << (k ? ",\n" : "\n");
        write_pair(os, m, pairs[k]);
    }
    os << "],\n\"skipped\":[";
    for (std::size_t k = 0; k < skipped.size(); ++k) {
        os << (k ? "," : "") << "{\"parts\":[";
        json_string(os, m.parts[skipped[k].a].name);
        os << ',';
        json_string(os, m.parts[skipped[k].b].name);
        os << "],\"reason\":";
        json_string(os, skipped[k].reason);
        os << '}';
    }
    os << "],\n\"envisionment\":";
    if (!e) {
        os << "null,\"chains\":[],\"paths\":[]}";
        return;
    }
    // The envisioner's own JSON, so that the page and `envision --json` agree; "</" can only occur
    // inside its strings, where "<\/" reads the same.
    std::ostringstream json;
    ev::write_json(json, m, *e);
    std::string text = json.str();
    while (!text.empty() && text.back() == '\n') text.pop_back();
    for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3)) text.insert(at + 1, "\\");
    os << text << ",\n\"chains\":[";
    for (std::size_t k = 0; k < e->chains.size(); ++k) {
        os << (k ? ",\n" : "\n");
        write_chain(os, m, pairs, *e, e->chains[k]);
    }
    os << "],\n\"paths\":[";
    for (std::size_t k = 0; k < paths.size(); ++k) {
        os << (k ? "," : "") << "{\"description\":";
        json_string(os, paths[k].description);
        os << ",\"chain\":" << e->chains[paths[k].chain].chain.index + 1 << ",\"states\":[";
        for (std::size_t i = 0; i < paths[k].states.size(); ++i) os << (i ? "," : "") << paths[k].states[i].value;
        os << "]}";
    }
    os << "]}";
}

}  // namespace qm::cli
