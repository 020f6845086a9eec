// tests/scene/scene_parser_spellings_test.cpp: scene/scene_parser.hpp - the thesis' own spellings
// (docs/SCENE_FORMAT.md, "Spellings of the figures and the BNF"): each figure typed as printed
// (tests/scene/figures/) reads as the bundled scene it is, each spelling gives the same Scene as
// the cleaned-up one, and every bundled scene written out with seeded random choices among the
// spellings (a writer in this file, independent of scene/scene_printer) reads back equal.
#include "scene/scene_parser.hpp"
#include "scene/direction_text.hpp"
#include "scene/scene_printer.hpp"
#include "../support/scene_reading.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>
#include <random>
#include <sstream>

using namespace qm::scene;

namespace {
using qm::test::printed;
using qm::test::read_ok;
Scene load(const std::string& path) { return qm::test::load_ok(path); }
std::string source_dir() { return std::string(QM_SOURCE_DIR); }

// The first diagnostic as "line:col message", for inputs that must be rejected.
std::string first_error(const std::string& text) {
    qm::Diagnostics diags;
    auto s = read_scene("e.def", text, diags);
    CHECK_FALSE(s.has_value());
    REQUIRE(diags.has_errors());
    const auto d = diags.sorted()[0];
    return std::to_string(d.where.line) + ":" + std::to_string(d.where.column) + " " + d.message;
}

// Writes a checked Scene in the thesis' spellings, choosing among them with `rng`. Independent
// of scene/scene_printer (but for print_pattern), so that the reader is checked against a second
// description of the grammar.
class SpellingWriter {
public:
    SpellingWriter(const Scene& s, std::mt19937& rng) : s_(s), rng_(rng) {}

    // The s-expression notation: in `(Defscenario d name ...)` or after a figure's `Name d`.
    std::string sx() {
        std::vector<std::string> sections;
        sections.push_back("Individuals (" + join(object_names(), " ") + ")");
        if (coin()) sections.push_back("Descriptions (" + join(each_object([](const std::string& o) {
                                           return "(rigid-ob " + o + ")";
                                       }), " ") + ")");
        sections.push_back(surfaces_and_bare_constraints());
        if (has_corners()) sections.push_back("Corners (" + corner_groups_sx() + ")");
        if (!s_.linkages.empty()) sections.push_back("Linkages (" + join(linkages(), " ") + ")");
        if (!s_.forces.empty() || coin()) sections.push_back("Forces (" + join(forces("(", ")"), " ") + ")");
        for (bool t : {true, false})
            if (keyworded_[t ? 0 : 1]) sections.push_back(constraint_keyword(t) + " " + constraint_list(t));
        std::shuffle(sections.begin(), sections.end(), rng_);
        const bool figure = coin();
        std::string out = figure ? s_.name + " " + std::to_string(s_.dimensions) + "\n"
                                 : "(Defscenario " + std::to_string(s_.dimensions) + " " + s_.name + "\n";
        for (const auto& sec : sections) out += "  " + sec + "\n";
        if (!figure) out += ")\n";
        return out + sx_states();
    }

    // The keyword notation, with Figure 7.2's `Situations {...}` and the closing CONTACT list.
    std::string keywords() {
        std::vector<std::string> sections;
        const std::string names = join(object_names(), ", ");
        sections.push_back("Individuals : " + (coin() ? "(" + names + ")" : names));
        if (coin()) sections.push_back("Descriptions : " + join(each_object([&](const std::string& o) {
                                           return "rigid-ob" + std::string(coin() ? " " : "") + "(" + o + ")";
                                       }), ", "));
        for (bool t : {true, false}) {
            std::vector<std::string> entries;
            for (const auto& o : s_.objects) {
                const auto& list = t ? o.trans_constraints : o.rot_constraints;
                if (list.empty()) continue;
                std::string e = o.name;
                for (const auto& p : list) e += " " + print_pattern(p);
                entries.push_back(e);
            }
            if (!entries.empty()) sections.push_back(constraint_keyword(t) + " : " + join(entries, ", "));
        }
        for (bool corners : {false, true}) {
            std::vector<std::string> groups;
            for (const auto& g : surface_groups(corners)) {
                std::string text = s_.objects[s_.owner(g[0])].name + " ";
                for (std::size_t i = 0; i < g.size(); ++i)
                    text += (i == 0 ? "" : corners || coin() ? ", " : "\n    ") + entry(g[i]);  // Figure 7.12: no comma
                groups.push_back(text);
            }
            if (!groups.empty())
                sections.push_back(std::string(corners ? "Corners : " : "Surfaces : ") +
                                   join(groups, coin() ? ",\n  " : "\n  "));
        }
        if (!s_.linkages.empty()) sections.push_back("Linkages : " + join(linkages(), ", "));
        if (!s_.forces.empty()) sections.push_back("Forces : " + join(forces("", ""), ", "));
        std::shuffle(sections.begin(), sections.end(), rng_);
        std::string out = s_.name + " " + std::to_string(s_.dimensions) + "\n";
        for (const auto& sec : sections) out += sec + "\n";
        return out + keyword_states();
    }

private:
    bool coin() { return rng_() % 2 == 0; }
    int pick(int n) { return static_cast<int>(rng_() % static_cast<unsigned>(n)); }

    static std::string join(const std::vector<std::string>& items, const std::string& sep) {
        std::string out;
        for (std::size_t i = 0; i < items.size(); ++i) out += (i ? sep : "") + items[i];
        return out;
    }
    template <class F>
    std::vector<std::string> each_object(F f) {
        std::vector<std::string> out;
        for (const auto& o : s_.objects) out.push_back(f(o.name));
        return out;
    }
    std::vector<std::string> object_names() {
        return each_object([](const std::string& o) { return o; });
    }
    static std::string constraint_keyword(bool t) { return t ? "Translational-Constraints" : "Rotational-Constraints"; }

    bool has_corners() const {
        for (std::uint32_t i = 0; i < s_.surfaces.size(); ++i)
            if (s_.surfaces[SurfaceId{i}].is_corner()) return true;
        return false;
    }
    // Each object's faces (or corners) in SurfaceId order, the groups ordered by first member:
    // read back in this order they get the same ids.
    std::vector<std::vector<SurfaceId>> surface_groups(bool corners) const {
        std::vector<std::vector<SurfaceId>> out;
        for (const auto& o : s_.objects) {
            std::vector<SurfaceId> g;
            for (SurfaceId id : o.surfaces)
                if (s_.surfaces[id].is_corner() == corners) g.push_back(id);
            if (!g.empty()) out.push_back(g);
        }
        std::sort(out.begin(), out.end(), [](const auto& a, const auto& b) { return a[0] < b[0]; });
        return out;
    }
    std::string entry_body(SurfaceId id) const {
        const Surface& f = s_.surfaces[id];
        if (f.corner)
            return f.name + " " + s_.surfaces[f.corner->first].name + " " + s_.surfaces[f.corner->second].name + " " +
                   thesis_text(f.origin);
        return f.name + " " + thesis_text(f.normal) + " " + thesis_text(f.origin);
    }
    std::string entry(SurfaceId id) const { return "(" + entry_body(id) + ")"; }

    // Figure 6.1: `obj (entry*)` with bare or parenthesised entries, or the figures' `(obj entry*)`.
    std::string surfaces_and_bare_constraints() {
        std::string out = "Surfaces (";
        for (const auto& g : surface_groups(false)) {
            const std::string obj = s_.objects[s_.owner(g[0])].name;
            const int style = pick(3);  // 0: (obj (e) ...), 1: obj ((e) ...), 2: obj (e-or-bare ...)
            out += style == 0 ? "(" + obj : obj + " (";
            for (SurfaceId id : g) out += " " + (style == 2 && coin() ? entry_body(id) : entry(id));
            out += ") ";
        }
        out += ")";
        return out + bare_constraints();
    }
    std::string corner_groups_sx() const {
        std::string out;
        for (const auto& g : surface_groups(true)) {
            out += "(" + s_.objects[s_.owner(g[0])].name;
            for (SurfaceId id : g) out += " " + entry(id);
            out += ")";
        }
        return out;
    }
    bool any_constraints(bool t) const {
        for (const auto& o : s_.objects)
            if (!(t ? o.trans_constraints : o.rot_constraints).empty()) return true;
        return false;
    }
    std::string constraint_list(bool t) const {
        std::string out = "(";
        for (const auto& o : s_.objects) {
            const auto& list = t ? o.trans_constraints : o.rot_constraints;
            if (list.empty()) continue;
            out += "(" + o.name;
            for (const auto& p : list) out += " " + print_pattern(p);
            out += ")";
        }
        return out + ")";
    }
    // Which constraint kinds go without keywords after Surfaces (Figure 6.1), and which with.
    // A lone list is read by its arity, which tells the kinds apart only in 2-D.
    std::string bare_constraints() {
        const bool t = any_constraints(true), r = any_constraints(false), lone_ok = s_.dimensions == 2;
        keyworded_[0] = t;
        keyworded_[1] = r;
        switch (pick(4)) {
            case 0: return "";  // both keyworded (or absent)
            case 1:             // two lists, translational then rotational; `()` for a missing kind
                keyworded_[0] = keyworded_[1] = false;
                return " " + constraint_list(true) + " " + constraint_list(false);
            case 2:  // the translational list alone
                if (!t || !lone_ok) return "";
                keyworded_[0] = false;
                return " " + constraint_list(true);
            default:  // the rotational list alone, or an empty lone list when there is none of either
                if (!t && !r) return coin() ? " ()" : "";
                if (!r || !lone_ok) return "";
                keyworded_[1] = false;
                return " " + constraint_list(false);
        }
    }
    std::vector<std::string> linkages() const {
        std::vector<std::string> out;
        for (const auto& l : s_.linkages)
            out.push_back("(" + s_.objects[l.first].name + " " + s_.objects[l.second].name + ")");
        return out;
    }
    std::string force_body(const Force& f) const {
        std::string out =
            s_.objects[f.object].name + " " + thesis_text(f.direction) + " " + thesis_text(f.origin);
        if (s_.causes[f.cause].is_explicit) out += " " + s_.causes[f.cause].name;
        return out;
    }
    std::vector<std::string> forces(const std::string& open, const std::string& close) const {
        std::vector<std::string> out;
        for (const auto& f : s_.forces) out.push_back(open + force_body(f) + close);
        return out;
    }
    std::string motion_body(const Motion& m) const {
        return s_.objects[m.object].name + " " + thesis_text(m.translation) + " " + thesis_text(m.rotation);
    }
    // A situation's descriptors in the keyword form: `Contact(a b)` (Figure 7.2) or `Contact (a b)`.
    std::vector<std::string> keyword_descriptors(const Situation& sit) {
        std::vector<std::string> out;
        auto kw = [&](const char* word, const std::string& body) {
            return std::string(word) + (coin() ? "" : " ") + "(" + body + ")";
        };
        for (const auto& c : sit.contacts)
            out.push_back(kw("Contact", s_.surfaces[c.first].name + " " + s_.surfaces[c.second].name));
        for (const auto& f : sit.forces) out.push_back(kw("Force", force_body(f)));
        for (const auto& m : sit.motions) out.push_back(kw("Motion", motion_body(m)));
        return out;
    }
    std::string braces(const Situation& sit) { return "{" + join(keyword_descriptors(sit), ", ") + "}"; }
    std::string paren_situation(const Situation& sit) const {
        std::vector<std::string> out;
        for (const auto& c : sit.contacts)
            out.push_back("(Contact " + s_.surfaces[c.first].name + " " + s_.surfaces[c.second].name + ")");
        for (const auto& f : sit.forces) out.push_back("(Force " + force_body(f) + ")");
        for (const auto& m : sit.motions) out.push_back("(Motion " + motion_body(m) + ")");
        return "(" + join(out, " ") + ")";
    }
    std::string sx_states() {
        const auto& sits = s_.situations;
        if (!sits.empty() && coin()) {  // Figure 7.2
            std::string out = coin() ? "Situations" : "Situations :";
            for (const auto& sit : sits) out += "\n  " + braces(sit);
            return out + "\n";
        }
        if (sits.empty() && coin()) return "";
        static const char* const keywords[] = {"Defstates", "defState", "DEFSTATE", "defstates"};  // Figure 7.8
        std::string out = std::string("(") + keywords[pick(4)];
        for (const auto& sit : sits) out += "\n  " + (coin() ? braces(sit) : paren_situation(sit));
        return out + ")\n";
    }
    std::string keyword_states() {
        const auto& sits = s_.situations;
        // Figures 7.12 and 7.16: a closing CONTACT list is the one situation, of contacts only.
        if (sits.size() == 1 && !sits[0].contacts.empty() && sits[0].forces.empty() && sits[0].motions.empty() &&
            coin()) {
            std::vector<std::string> pairs;
            for (const auto& c : sits[0].contacts)
                pairs.push_back("(" + s_.surfaces[c.first].name + " " + s_.surfaces[c.second].name + ")");
            return std::string(coin() ? "CONTACT " : "Contact ") + join(pairs, ", ") + "\n";
        }
        std::string out;
        for (std::size_t i = 0; i < sits.size();) {
            if (coin()) {  // a run of situations in braces
                out += coin() ? "Situations" : "Situations :";
                for (std::size_t n = 1 + static_cast<std::size_t>(pick(3)); n > 0 && i < sits.size(); --n)
                    out += " " + braces(sits[i++]);
                out += "\n";
            } else {
                out += "Situation : " + join(keyword_descriptors(sits[i++]), ", ") + "\n";
            }
        }
        return out;
    }

    const Scene& s_;
    std::mt19937& rng_;
    bool keyworded_[2] = {false, false};  // translational, rotational constraints need a keyword
};

std::vector<std::string> bundled_scenes() {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(source_dir() + "/scenarios/alex"))
        if (e.path().extension() == ".def") out.push_back("scenarios/alex/" + e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
}
}  // namespace

TEST_CASE("scene/scene_parser: the figures typed as printed read as the bundled scenes") {
    CHECK(load("tests/scene/figures/fig7_2.def") == load("scenarios/alex/block.def"));
    CHECK(load("tests/scene/figures/fig6_1_bnf.def") == load("scenarios/alex/block.def"));
    CHECK(load("tests/scene/figures/fig7_8.def") == load("scenarios/alex/arch.def"));
    CHECK(load("tests/scene/figures/fig7_12.def") == load("scenarios/alex/gears.def"));
    // Figure 7.16 has one situation, the first of recoil_escapement.def (the second adds
    // Figure 7.18's given motion).
    Scene recoil = load("scenarios/alex/recoil_escapement.def");
    REQUIRE(recoil.situations.size() == 2);
    recoil.situations.pop_back();
    const Scene fig = load("tests/scene/figures/fig7_16.def");
    CHECK(fig == recoil);
    REQUIRE(fig.situations.size() == 1);
    CHECK(fig.situations[0].contacts.size() == 2);
    CHECK(fig.situations[0].where.line == 14);  // located at CONTACT
}

TEST_CASE("scene/scene_parser: Defstate and defState (Figure 7.8) are Defstates") {
    const std::string scene = "(Defscenario 2 s Individuals (a b) Surfaces ((a (p (0 +) (0 -))) (b (q (0 -) (0 +)))))\n";
    const Scene canonical = read_ok(scene + "(Defstates ((Contact p q)) ())");
    CHECK(canonical.situations.size() == 2);
    for (const char* kw : {"Defstate", "defState", "DEFSTATE", "defstates"})
        CHECK(read_ok(scene + "(" + kw + " ((Contact p q)) ())") == canonical);
    CHECK(first_error(scene + "(Defstat ((Contact p q)))") ==
          "2:1 expected end of input but found '('");
}

TEST_CASE("scene/scene_parser: constraint lists without keywords after Surfaces (Figure 6.1)") {
    const std::string head = "(Defscenario 2 s Individuals (a t) Surfaces ((a (p (0 -) (0 +))) (t (q (0 +) (0 0))))";
    const Scene both = read_ok(head + " Translational-Constraints ((t (?x ?y)) (a (+ ?y) (- ?z))) "
                                      "Rotational-Constraints ((t (?r))))");
    // Two lists: translational, then rotational, whatever their arity says.
    CHECK(read_ok(head + " ((t (?x ?y)) (a (+ ?y) (- ?z))) ((t (?r))))") == both);
    // One list: its arity tells (2 signs: translational, 1 sign: rotational), with or without a
    // keyworded section of the other kind.
    CHECK(read_ok(head + " ((t (?x ?y)) (a (+ ?y) (- ?z))) Rotational-Constraints ((t (?r))))") == both);
    CHECK(read_ok(head + " ((t (?r))) Translational-Constraints ((t (?x ?y)) (a (+ ?y) (- ?z))))") == both);
    CHECK(read_ok(head + " Rotational-Constraints ((t (?r))) Translational-Constraints ((t (?x ?y)) "
                         "(a (+ ?y) (- ?z))))") == both);
    // `()` stands for a kind with no constraint; a lone `()` is no constraint of either kind.
    const Scene rot_only = read_ok(head + " Rotational-Constraints ((t (?r))))");
    CHECK(read_ok(head + " () ((t (?r))))") == rot_only);
    CHECK(read_ok(head + " ((t (?r))))") == rot_only);
    const Scene none = read_ok(head + ")");
    CHECK(read_ok(head + " ())") == none);
    CHECK(read_ok(head + " () ())") == none);
    // After a figure's header too.
    CHECK(read_ok("s 2 Individuals (a t) Surfaces ((a (p (0 -) (0 +))) (t (q (0 +) (0 0)))) "
                  "((t (?x ?y)) (a (+ ?y) (- ?z))) ((t (?r)))") == both);
    // 3-D: two lists are told apart by their place; a lone one cannot be.
    const std::string head3 = "(Defscenario 3 s Individuals (t) Surfaces ((t (q (0 0 +) (0 0 0))))";
    CHECK(read_ok(head3 + " ((t (?x ?y ?z))) ((t (?a ?b ?c))))") ==
          read_ok(head3 + " Translational-Constraints ((t (?x ?y ?z))) Rotational-Constraints ((t (?a ?b ?c))))"));
    CHECK(read_ok(head3 + " () ((t (?a 0 ?c))))") == read_ok(head3 + " Rotational-Constraints ((t (?a 0 ?c))))"));
    CHECK(read_ok(head3 + " ())") == read_ok(head3 + ")"));
    CHECK(first_error(head3 + " ((t (?x ?y ?z))))") ==
          "1:69 in a 3-D scene translations and rotations both have 3 signs, so a single constraint list without "
          "its keyword after Surfaces could be either; write Translational-Constraints or Rotational-Constraints "
          "before it");
    // Two lists with the wrong arities are read by place and then fail the arity check.
    CHECK(first_error(head + " ((t (?r))) ((t (?x ?y))))") ==
          "1:91 a translational constraint needs 2 signs in a 2-D scene but has 1");
}

TEST_CASE("scene/scene_parser: Figure 6.1's surface lists: `obj (entry*)`, entries bare or parenthesised") {
    const Scene canonical = read_ok("(Defscenario 2 s Individuals (a b) Surfaces ((a (p (0 +) (0 -)) (r (+ 0) (- 0))) "
                                    "(b (q (0 -) (0 +)))) Corners ((a (k p r (- -)))))");
    for (const char* surfaces : {"(a ((p (0 +) (0 -)) (r (+ 0) (- 0))) b ((q (0 -) (0 +))))",
                                 "(a (p (0 +) (0 -) r (+ 0) (- 0)) b (q (0 -) (0 +)))",
                                 "(a (p (0 +) (0 -) (r (+ 0) (- 0))) (b (q (0 -) (0 +))))",
                                 "(a (P (0 +) (0 -)\n r (+ 0) (- 0))\n b ((Q (0 -) (0 +))))"}) {
        INFO(surfaces);
        CHECK(read_ok(std::string("(Defscenario 2 s Individuals (a b) Surfaces ") + surfaces +
                      " Corners ((a (k p r (- -)))))") == canonical);
    }
    CHECK(read_ok("(Defscenario 2 s Individuals (a) Surfaces (a ()))") ==
          read_ok("(Defscenario 2 s Individuals (a) Surfaces ((a)))"));
    // A bare entry needs both its directions, like a parenthesised one.
    CHECK(first_error("(Defscenario 2 s Individuals (a) Surfaces (a (p (0 +) r (0 -) (0 +))))") ==
          "1:55 expected a direction like (0 +) but found 'r'");
}

TEST_CASE("scene/scene_parser: situations in braces (Figure 7.2) in both notations") {
    const std::string sx = "(Defscenario 2 s Individuals (a b) Surfaces ((a (p (0 +) (0 -))) (b (q (0 -) (0 +)))))\n";
    const Scene canonical = read_ok(sx + "(Defstates () ((Contact p q) (Force b (0 -) (0 0) g) (Motion a (0 0) (+))))");
    CHECK(read_ok(sx + "Situations {} {Contact(p q), Force(b (0 -) (0 0) g), Motion(a (0 0) (+))}") == canonical);
    CHECK(read_ok(sx + "Situations : {}\n{Contact (p q), Force (b (0 -) (0 0) g), MOTION(a (0 0) (+))}") == canonical);
    CHECK(read_ok(sx + "(Defstates {} {Contact(p q), Force(b (0 -) (0 0) g), Motion(a (0 0) (+))})") == canonical);
    CHECK(read_ok(sx + "(Defstates () {Contact(p q), Force(b (0 -) (0 0) g), Motion(a (0 0) (+))})") == canonical);
    const std::string kw = "S 2\nIndividuals : a, b\nSurfaces : a (p (0 +) (0 -)), b (q (0 -) (0 +))\n";
    CHECK(read_ok(kw + "Situations {} {Contact(p q), Force(b (0 -) (0 0) g), Motion(a (0 0) (+))}") == canonical);
    CHECK(read_ok(kw + "Situations {}\nSituation : Contact (p q), Force (b (0 -) (0 0) g), Motion (a (0 0) (+))") ==
          canonical);
    // A keyword-notation Forces list does not take `Situations` as its last force's cause.
    const Scene forced = read_ok(kw + "Forces : a (0 -) (0 0) w\nSituation :\nSituation : Contact (p q)");
    CHECK(read_ok(kw + "Forces : a (0 -) (0 0) w\nSituations {} {Contact(p q)}") == forced);
    CHECK(read_ok(kw + "Forces : a (0 -) (0 0) w Situations : {} {Contact(p q)}") == forced);
    CHECK(first_error(kw + "Situations {Contact(p q) Contact(q p)}") == "4:26 expected ',' or '}' but found 'Contact'");
    CHECK(first_error(kw + "Situations {Contact(p q),}") ==
          "4:26 expected a situation descriptor (Contact, Force or Motion) but found '}'");
    CHECK(first_error(kw + "Situations") ==
          "4:11 expected a situation in braces like {} or {Contact(a b), Contact(c d)} but found end of input");
    CHECK(first_error(sx + "Situations") ==
          "2:11 expected a situation in braces like {} or {Contact(a b), Contact(c d)} but found end of input");
}

TEST_CASE("scene/scene_parser: a closing CONTACT list (Figures 7.12, 7.16) is the one situation") {
    const std::string kw = "S 2\nIndividuals : a, b\nSurfaces : a (p (0 +) (0 -)), (r (+ 0) (- 0)) b (q (0 -) (0 +))\n";
    const Scene two = read_ok(kw + "Situation : Contact (p q), Contact (q r)");
    CHECK(read_ok(kw + "CONTACT (p q), (q r)") == two);
    CHECK(read_ok(kw + "contact (p q),\n  (q r)\n; a comment") == two);
    CHECK(read_ok(kw + "CONTACT (p q)") == read_ok(kw + "Situation : Contact (p q)"));
    // After a keyword-notation Forces list, with or without an explicit cause.
    for (const char* forces : {"Forces : a (0 -) (0 0)\n", "Forces : a (0 -) (0 0) hand\n"}) {
        INFO(forces);
        CHECK(read_ok(kw + forces + "CONTACT (p q), (q r)") ==
              read_ok(kw + forces + "Situation : Contact (p q), Contact (q r)"));
    }
    // A cause named like the keyword is still a cause when no '(' follows it.
    const Scene cause = read_ok(kw + "Forces : a (0 -) (0 0) contact");
    REQUIRE(cause.forces.size() == 1);
    CHECK(cause.causes[cause.forces[0].cause].name == "contact");
    // Beside other situations the list is ambiguous; and it ends the scene.
    CHECK(first_error(kw + "Situation : Contact (p q)\nCONTACT (q r)") ==
          "5:1 a closing CONTACT list is read as the scene's only situation (Figures 7.12, 7.16), but this scene "
          "has other situations; write it as 'Situation : Contact (a b), Contact (c d)'");
    CHECK(first_error(kw + "CONTACT (p q)\nSituation : Contact (q r)") ==
          "5:1 expected end of input (a CONTACT list ends the scene; more situations are written 'Situation : ...') "
          "but found 'Situation'");
    CHECK(first_error(kw + "CONTACT (p x)") == "4:12 unknown surface 'x'");
    // Other descriptors are not figure spellings: rejected.
    CHECK(first_error(kw + "FORCE (a (0 -) (0 0))") ==
          "4:1 expected a section keyword (Individuals, Descriptions, Surfaces, Corners, Translational-Constraints, "
          "Rotational-Constraints, Forces, Linkages, Situation) followed by ':' but found 'FORCE'");
}

TEST_CASE("scene/scene_parser: OCR garbage is still rejected with the same messages") {
    // The reading guide's OCR faults are not spellings: `--` for `-`, `1` for `l` in names.
    CHECK(first_error("(Defscenario 2 a Individuals (l t)\n Surfaces ((l (lt-b-l (0 --) (+ +))) (t (tb (0 +) (0 0)))))") ==
          "2:26 bad sign '--': a sign is '+', '0' or '-' (the thesis' OCR prints '-' as '--'; write '-')");
    CHECK(first_error("(Defscenario 2 a Individuals (l t)\n Surfaces ((l (lt-b-l (0 -) (+ +))) (t (tb (0 +) (0 0)))))\n"
                      "(Defstates ((Contact tb 1t-b-1)))") ==
          "3:25 expected a name but found '1t-b-1'");
    CHECK(first_error("A 2 Individuals (l t)\n Surfaces ((l (1t-b-1 (0 -) (+ +))) (t (tb (0 +) (0 0))))") ==
          "2:15 expected ')' but found '('");
    CHECK(first_error("Gears 2\nIndividuals : (driver, follower)\nSurfaces : follower (1-1 (- -) (0 +))") ==
          "3:21 expected a surface entry like (top (0 +) (0 -)) but found '('");
    CHECK(first_error("Geere2\nIndividuals : (driver, follower)") ==
          "2:1 expected the number of dimensions (2 or 3) but found 'Individuals'");
}

TEST_CASE("scene/scene_parser: every bundled scene in random thesis spellings reads back equal") {
    // Seeded: the same spellings on every run. Each scene is written 60 times in each notation.
    std::mt19937 rng(20261124);
    std::size_t written = 0;
    for (const auto& file : bundled_scenes()) {
        const Scene s = load(file);
        for (int i = 0; i < 60; ++i) {
            SpellingWriter w(s, rng);
            for (const std::string& text : {w.sx(), w.keywords()}) {
                qm::Diagnostics diags;
                auto back = read_scene("spelled.def", text, diags);
                INFO(file << "\n" << text << "\n" << printed(diags));
                REQUIRE(back.has_value());
                CHECK(*back == s);
                ++written;
            }
        }
    }
    CHECK(written >= 1500);
}
