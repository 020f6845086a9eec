// tests/scene/what_if_test.cpp: scene/what_if.hpp - what --given and --without name, their checks,
// and the scene a what-if analyses. Each property is checked on a scene written here, against a
// brute-force count over its items.
#include "scene/scene_parser.hpp"
#include "scene/what_if.hpp"
#include "../support/scene_reading.hpp"

#include <doctest/doctest.h>
#include <sstream>
#include <string>
#include <vector>

using namespace qm::scene;

namespace {
// Two situations; a scene-level force on a (gravity) and one of cause wind in situation 2.
const char* text = R"((Defscenario 2 two
  Individuals (a b)
  Descriptions ((rigid-ob a) (rigid-ob b))
  Surfaces ((a (a-bottom (0 -) (0 +)) (a-side (+ 0) (- 0))) (b (b-top (0 +) (0 -))))
  Forces ((a (0 -) (0 0))))
(Defstates
  ((Contact b-top a-bottom) (Motion b (0 0) (0)))
  ((Contact a-bottom b-top) (Force a (+ 0) (0 0) wind) (Motion a (0 -) (0)))))";

Scene two() { return qm::test::read_ok(text, "two.def"); }

QueryFact query(const Scene& s, const std::string& q) {
    qm::Diagnostics d;
    auto f = parse_query_fact(s, q, d, "test");
    REQUIRE(f);
    return *f;
}

using qm::test::printed;
}  // namespace

TEST_CASE("scene/what_if: a contact is named in either order, a force by object and optional cause") {
    const Scene s = two();
    const QueryFact contact = query(s, "Contact a-bottom b-top"), reversed = query(s, "Contact b-top a-bottom");
    const QueryFact on_a = query(s, "Force a"), wind_on_a = query(s, "Force a wind"), on_b = query(s, "Force b");
    const SurfaceId bottom = *s.find_surface("a-bottom"), top = *s.find_surface("b-top"), side = *s.find_surface("a-side");
    CHECK(names_contact(contact, bottom, top));
    CHECK(names_contact(contact, top, bottom));
    CHECK(names_contact(reversed, bottom, top));
    CHECK_FALSE(names_contact(contact, side, top));
    CHECK_FALSE(names_contact(on_a, bottom, top));
    const ObjectId a = *s.find_object("a");
    const CauseId wind = *s.find_cause("wind"), gravity = s.forces.front().cause;
    CHECK(names_force(on_a, a, gravity));
    CHECK(names_force(on_a, a, wind));
    CHECK(names_force(wind_on_a, a, wind));
    CHECK_FALSE(names_force(wind_on_a, a, gravity));
    CHECK_FALSE(names_force(on_b, a, gravity));
    CHECK_FALSE(names_force(contact, a, gravity));
    CHECK(can_take_away(contact));
    CHECK(can_take_away(on_b));
    CHECK_FALSE(can_take_away(query(s, "Translational-Motion (a (0 -))")));
}

TEST_CASE("scene/what_if: has_item agrees with a count over each situation's items, scene-level forces included") {
    const Scene s = two();
    for (const std::string q : {"Contact a-bottom b-top", "Contact a-side b-top", "Force a", "Force a wind", "Force b"})
        for (std::size_t k = 1; k <= s.situations.size(); ++k) {
            const QueryFact f = query(s, q);
            std::size_t count = 0;
            const Situation& sit = s.situations[k - 1];
            for (const Contact& c : sit.contacts) count += names_contact(f, c.first, c.second);
            for (const Force& x : sit.forces) count += names_force(f, x.object, x.cause);
            for (const Force& x : s.forces) count += names_force(f, x.object, x.cause);
            CAPTURE(q);
            CAPTURE(k);
            CHECK(has_item(s, k, f) == (count > 0));
        }
    CHECK(item_text(s, query(s, "Contact b-top a-bottom")) == "Contact (b-top a-bottom)");
    CHECK(item_text(s, query(s, "Force a wind")) == "force of cause 'wind' on 'a'");
    CHECK(item_text(s, query(s, "Force a")) == "force on 'a'");
}

TEST_CASE("scene/what_if: the what-if scene keeps one situation, less what is taken away, with the given motions") {
    const Scene s = two();
    const std::vector<QueryFact> without{query(s, "Force a")};
    qm::Diagnostics d;
    const std::vector<Motion> given{*parse_given(s, "a (0 0) (+)", d, "test")};
    const Scene w = what_if_scene(s, 2, without, given);
    REQUIRE(w.situations.size() == 1);
    CHECK(w.forces.empty());                       // the scene-level force on a
    CHECK(w.situations[0].forces.empty());         // and the wind
    CHECK(w.situations[0].contacts == s.situations[1].contacts);
    REQUIRE(w.situations[0].motions.size() == 1);  // a's Motion replaced by the given one
    CHECK(w.situations[0].motions[0] == given[0]);
    CHECK(what_if_note(s, 2, without) == "what-if: analysed without every force on 'a' (--without)");
    CHECK(what_if_note(s, 1, std::vector<QueryFact>{query(s, "Force a wind")}).empty());
}

TEST_CASE("scene/what_if: --given and --without are checked, every error located at its option") {
    Scene s = two();
    qm::Diagnostics d;
    const std::vector<std::string> givens{"a (0 0) (+)", "a (0 0) (-)"};
    CHECK(read_givens(s, givens, d).size() == 1);
    CHECK(printed(d) == "--given:1:1: error: expected one --given per object, but 'a' is given twice ('a (0 0) (+)' and 'a (0 0) (-)')\n");
    d = {};
    const std::vector<std::string> withouts{"Force a wind", "Contact a-side b-top", "Rotational-Motion (a (+))"};
    CHECK(read_withouts(s, withouts, std::nullopt, d).size() == 1);
    CHECK(printed(d) ==
          "--without:1:1: error: expected a contact or force of the scene to take away, but no situation has a Contact (a-side b-top)\n"
          "--without:1:1: error: expected 'Contact A B' or 'Force OBJ [CAUSE]' to take away, but found 'Rotational-Motion (a (+))'\n");
    d = {};
    CHECK(read_withouts(s, std::vector<std::string>{"Force a wind"}, 1, d).empty());
    CHECK(printed(d) == "--without:1:1: error: expected a contact or force of the scene to take away, but situation 1 has no force of cause 'wind' on 'a'\n");
    d = {};
    CHECK(read_whatif(s, 2, "without Force a wind; Contact b-top a-bottom", d).size() == 2);
    CHECK_FALSE(d.has_errors());
    CHECK(read_whatif(s, 1, "Force a wind", d).empty());
    CHECK(printed(d) == "whatif:1:1: error: expected a contact or force of situation 1 to take away, but it has no force of cause 'wind' on 'a'\n");
    d = {};
    const std::vector<Motion> given = read_givens(s, std::vector<std::string>{"a (0 0) (+)"}, d);
    replace_given_motions(s, given, std::vector<std::string>{"a (0 0) (+)"}, d);
    CHECK(s.situations[0].motions.size() == 1);  // b's Motion stays
    CHECK(s.situations[1].motions.empty());      // a's is replaced
    CHECK(printed(d) == "two.def:8:57: note: --given 'a (0 0) (+)' replaces this Motion (a (0 -) (0)) in situation 2\n");
}
