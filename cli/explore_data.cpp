// cli/explore_data.cpp
#include "explore_data.hpp"

#include "geometry/contact_detection.hpp"
#include "geometry/cspace_svg.hpp"
#include "geometry/mechanism_drawing.hpp"
#include "geometry/part_svg.hpp"
#include "geometry/place_json.hpp"
#include "geometry/place_sample.hpp"
#include "qm/json.hpp"

#include <numbers>
#include <sstream>
#include <string_view>

namespace qm::cli {

namespace {

namespace g = qm::geometry;

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
        os << "{\"config\":[" << scene_value(*parts_[0].part, q[0]) << ',' << scene_value(*parts_[1].part, q[1]) << "],\"transforms\":[";
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
    g::write_place_json(os, e.places.request.cspace, e.places.vocabulary);
    std::ostringstream cspace;
    g::write_cspace_svg(cspace, *e.places.oracle, *e.places.space, e.places.vocabulary, cspace_svg_options(m, e.pair, 720, 540));
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

}  // namespace

void write_explore_data(std::ostream& os, const g::Mechanism& m, const std::vector<ExplorePair>& pairs, const std::vector<g::SkippedPair>& skipped) {
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
    os << "],\n\"envisionment\":null}";
}

}  // namespace qm::cli
