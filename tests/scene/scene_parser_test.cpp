// tests/scene/scene_parser_test.cpp: scene/scene_parser.hpp - the bundled scenes (scenarios/alex/)
// parse and check, their content matches the thesis figures, both notations give the same Scene,
// and the --given / query-fact forms.
#include "scene/scene_parser.hpp"
#include "scene/scene_printer.hpp"
#include "../support/golden.hpp"
#include "../support/scene_reading.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <filesystem>

using namespace qm::scene;

namespace {
using qm::test::printed;
using qm::test::read_ok;

std::string scenes_dir() { return std::string(QM_SOURCE_DIR) + "/scenarios/alex"; }
Scene load_alex(const std::string& file) { return qm::test::load_ok("scenarios/alex/" + file); }

const Direction up{Sign::zero, Sign::plus};
const Direction down{Sign::zero, Sign::minus};
const Direction none2{Sign::zero, Sign::zero};

Direction reversed(Direction d) {
    for (auto& x : d) x = static_cast<Sign>(-static_cast<int>(x));
    return d;
}

// The qualitative dot product (section 2.3) is definitely negative: some term is -, none is +.
bool definitely_negative_dot(const Direction& a, const Direction& b) {
    bool neg = false, pos = false;
    for (std::size_t i = 0; i < a.size(); ++i) {
        const int p = static_cast<int>(a[i]) * static_cast<int>(b[i]);
        neg = neg || p < 0;
        pos = pos || p > 0;
    }
    return neg && !pos;
}

// Section 3.1.1: a corner's blocked space is the intersection of the half planes of its sides'
// reversed normals. Read as the thesis applies it to Figure 3.3 (the tip's blocked space is
// (+ +), (0 +), (- +)): d lies in the half plane of v unless v.d is definitely negative.
bool in_blocked_space(const Scene& s, SurfaceId corner, const Direction& d) {
    const CornerSides sides = *s.surfaces[corner].corner;
    for (SurfaceId side : {sides.first, sides.second})
        if (definitely_negative_dot(reversed(s.surfaces[side].normal), d)) return false;
    return true;
}

// Definition 25: `face` can touch `corner` when its normal lies in the corner's blocked space.
bool can_contact(const Scene& s, SurfaceId corner, SurfaceId face) {
    return in_blocked_space(s, corner, s.surfaces[face].normal);
}

std::vector<Direction> all_nonzero_2d() {
    std::vector<Direction> out;
    for (Sign x : {Sign::plus, Sign::zero, Sign::minus})
        for (Sign y : {Sign::plus, Sign::zero, Sign::minus})
            if (x != Sign::zero || y != Sign::zero) out.push_back({x, y});
    return out;
}
}  // namespace

TEST_CASE("scene/scene_parser: every bundled scene parses and checks") {
    std::size_t n = 0;
    for (const auto& e : std::filesystem::directory_iterator(scenes_dir())) {
        if (e.path().extension() != ".def") continue;
        INFO(e.path().string());
        Scene s = load_alex(e.path().filename().string());
        CHECK(!s.objects.empty());
        CHECK(!s.situations.empty());
        ++n;
    }
    CHECK(n >= 12);
}

TEST_CASE("scene/scene_parser: block.def is Figure 7.2") {
    Scene s = load_alex("block.def");
    CHECK(s.name == "block");
    CHECK(s.dimensions == 2);
    REQUIRE(s.objects.size() == 2);
    const ObjectId block = *s.find_object("block");
    const ObjectId table = *s.find_object("table");
    CHECK(s.objects[block].surfaces.size() == 12);
    CHECK(s.objects[table].surfaces.size() == 1);
    // Figure 7.2: (block-b-m (0 -) (0 +)), (tb (0 +) (0 0)).
    const Surface& bm = s.surfaces[*s.find_surface("block-b-m")];
    CHECK(bm.normal == down);
    CHECK(bm.origin == up);
    CHECK(s.owner(*s.find_surface("tb")) == table);
    CHECK(s.surfaces[*s.find_surface("tb")].origin == none2);
    // The table is fully constrained; ?x1 ?y1 match every translation.
    REQUIRE(s.objects[table].trans_constraints.size() == 1);
    for (Sign x : {Sign::minus, Sign::zero, Sign::plus})
        for (Sign y : {Sign::minus, Sign::zero, Sign::plus}) CHECK(matches(s.objects[table].trans_constraints[0], {x, y}));
    CHECK(s.objects[block].trans_constraints.empty());
    // Two forces (gravity on both), each its own implicit cause.
    REQUIRE(s.forces.size() == 2);
    CHECK(s.forces[0].cause != s.forces[1].cause);
    CHECK_FALSE(s.causes[s.forces[0].cause].is_explicit);
    // Situations: unsupported, then three contacts with the table.
    REQUIRE(s.situations.size() == 2);
    CHECK(s.situations[0].contacts.empty());
    REQUIRE(s.situations[1].contacts.size() == 3);
    CHECK(s.situations[1].contacts[0].first == *s.find_surface("tb"));
    CHECK(s.situations[1].contacts[0].second == *s.find_surface("block-b-l"));
    CHECK(s.situations[1].where.line > s.situations[0].where.line);
}

TEST_CASE("scene/scene_parser: surface normals of the bundled scenes point out of their objects") {
    // A geometric sanity check independent of the files' comments: in every bundled scene each
    // contact joins two surfaces with opposite normals (surfaces touching face each other); a
    // corner touches only a surface that can contact it (Def 25), and two corners touch only if
    // a side of each can contact the other (Def 26).
    std::size_t corner_contacts = 0;
    for (const auto& e : std::filesystem::directory_iterator(scenes_dir())) {
        if (e.path().extension() != ".def") continue;
        INFO(e.path().string());
        Scene s = load_alex(e.path().filename().string());
        for (const auto& sit : s.situations)
            for (const auto& c : sit.contacts) {
                const Surface& a = s.surfaces[c.first];
                const Surface& b = s.surfaces[c.second];
                INFO(a.name << " / " << b.name);
                if (!a.is_corner() && !b.is_corner()) {
                    CHECK(a.normal == reversed(b.normal));
                    continue;
                }
                ++corner_contacts;
                if (a.is_corner() != b.is_corner()) {
                    CHECK((a.is_corner() ? can_contact(s, c.first, c.second) : can_contact(s, c.second, c.first)));
                    continue;
                }
                auto some_side_touches = [&](SurfaceId corner, SurfaceId other) {
                    const CornerSides k = *s.surfaces[other].corner;
                    return can_contact(s, corner, k.first) || can_contact(s, corner, k.second);
                };
                CHECK(some_side_touches(c.first, c.second));
                CHECK(some_side_touches(c.second, c.first));
            }
    }
    CHECK(corner_contacts >= 2);
}

TEST_CASE("scene/scene_parser: corner_contacts.def is Figure 3.3, with a Corners section") {
    Scene s = load_alex("corner_contacts.def");
    const ObjectId upper = *s.find_object("upper");
    const ObjectId lower = *s.find_object("lower");
    const SurfaceId tip = *s.find_surface("tip");
    const SurfaceId left = *s.find_surface("left-corner");
    const SurfaceId a = *s.find_surface("a"), b = *s.find_surface("b"), c = *s.find_surface("c");
    // A corner is a surface of its object with two sides and an origin, and no normal (Def 18).
    REQUIRE(s.surfaces[tip].is_corner());
    CHECK(s.surfaces[tip].normal.empty());
    CHECK(s.surfaces[tip].origin == up);
    CHECK(s.owner(tip) == upper);
    CHECK(*s.surfaces[tip].corner == CornerSides{c, *s.find_surface("d")});
    CHECK(*s.surfaces[left].corner == CornerSides{a, b});
    CHECK(s.owner(left) == lower);
    CHECK(std::find(s.objects[upper].surfaces.begin(), s.objects[upper].surfaces.end(), tip) !=
          s.objects[upper].surfaces.end());
    // Faces take the SurfaceIds before every corner, whatever the section order.
    for (SurfaceId id : {tip, left})
        for (std::uint32_t i = 0; i < s.surfaces.size(); ++i)
            if (!s.surfaces[SurfaceId{i}].is_corner()) CHECK(SurfaceId{i} < id);
    // Section 3.1.1, as the thesis states it for Figure 3.3: the tip's blocked space is exactly
    // (+ +), (0 +), (- +); A (- +) may touch it and B (- -) may not. And the lower block's corner
    // may touch C.
    std::vector<Direction> blocked;
    for (const Direction& d : all_nonzero_2d())
        if (in_blocked_space(s, tip, d)) blocked.push_back(d);
    CHECK(blocked == std::vector<Direction>{{Sign::plus, Sign::plus}, {Sign::zero, Sign::plus}, {Sign::minus, Sign::plus}});
    CHECK(s.surfaces[a].normal == Direction{Sign::minus, Sign::plus});
    CHECK(s.surfaces[b].normal == Direction{Sign::minus, Sign::minus});
    CHECK(can_contact(s, tip, a));
    CHECK_FALSE(can_contact(s, tip, b));
    CHECK(can_contact(s, left, c));
    // The situations: tip on A, then corner against corner.
    REQUIRE(s.situations.size() == 2);
    CHECK(s.situations[0].contacts[0].first == tip);
    CHECK(s.situations[0].contacts[0].second == a);
    CHECK(s.situations[1].contacts[0].second == left);
    // A corner is named in query facts like any surface.
    qm::Diagnostics d;
    auto q = parse_query_fact(s, "Contact tip left-corner", d);
    REQUIRE(q.has_value());
    CHECK(q->first == tip);
}

TEST_CASE("scene/scene_parser: linked_gears.def links gears A and B (Def 21)") {
    Scene s = load_alex("linked_gears.def");
    REQUIRE(s.linkages.size() == 1);
    CHECK(s.linkages[0].first == *s.find_object("gear-a"));
    CHECK(s.linkages[0].second == *s.find_object("gear-b"));
    CHECK(s.linkages[0].where.line > 1);
    for (const auto& o : s.objects) {
        INFO(o.name);
        REQUIRE(o.trans_constraints.size() == 1);  // pinned: every translation constrained
        for (const Direction& d : all_nonzero_2d()) CHECK(matches(o.trans_constraints[0], d));
        CHECK(o.rot_constraints.empty());           // free to rotate
    }
    REQUIRE(s.situations.size() == 3);
    CHECK(s.situations[1].motions.size() == 1);
    CHECK(s.situations[2].forces.size() == 1);
}

TEST_CASE("scene/scene_parser: Corners and Linkages in either notation and any section order") {
    const Scene file = load_alex("corner_contacts.def");
    // corner_contacts.def by hand in the keyword notation, Corners before Surfaces.
    const Scene kw = read_ok(R"(Corner-Contacts 2
        Individuals : upper, lower, table
        Descriptions : rigid-ob(upper), rigid-ob(lower), rigid-ob(table)
        Corners : upper (tip c d (0 +))
                  lower (Left-Corner A B (+ 0))
        Surfaces : upper (c (+ -) (- +)), (d (- -) (+ +)), (upper-top (0 +) (0 -)),
                   lower (a (- +) (+ -)), (b (- -) (+ +)), (lower-b-l (0 -) (+ +)), (lower-b-r (0 -) (- +))
                   table (tb (0 +) (0 0))
        Translational-Constraints : table (?x ?y)
        Rotational-Constraints : table (?r)
        Forces : upper (0 -) (0 0), lower (0 -) (0 0)
        Situation : Contact (tip a), Contact (lower-b-l tb), Contact (lower-b-r tb)
        Situation : Contact (tip left-corner), Contact (lower-b-l tb), Contact (lower-b-r tb))");
    CHECK(kw == file);
    const Scene gears = load_alex("linked_gears.def");
    std::string text = print_scene_keywords(gears);
    // The keyword form of the section, with the pair reversed: a linkage is read as written.
    const Scene linked = read_ok("l 2 Individuals : a, b, c Linkages : (b a), (B c)");
    REQUIRE(linked.linkages.size() == 2);
    CHECK(linked.linkages[0].first == ObjectId{1});
    CHECK(linked.linkages[0].second == ObjectId{0});
    CHECK(linked.linkages[1].second == ObjectId{2});
    CHECK(read_ok("(Defscenario 2 l Linkages ((b a) (b c)) Individuals (a b c))") == linked);
    CHECK(text.find("Linkages : (gear-a gear-b)\n") != std::string::npos);
    // Both sections may be empty.
    const Scene empty = read_ok("(Defscenario 2 e Individuals (a) Corners () Linkages ())");
    CHECK(empty.linkages.empty());
    CHECK(empty.surfaces.size() == 0);
}

TEST_CASE("scene/scene_parser: gears.def (keyword notation) is Figure 7.12") {
    Scene s = load_alex("gears.def");
    CHECK(s.name == "gears");
    REQUIRE(s.objects.size() == 2);
    CHECK(s.objects[ObjectId{0}].name == "driver");
    CHECK(s.objects[ObjectId{1}].name == "follower");
    const Surface& l1 = s.surfaces[*s.find_surface("l-1")];
    CHECK(l1.normal == Direction{Sign::minus, Sign::minus});
    CHECK(l1.origin == up);
    CHECK(s.owner(*s.find_surface("l-1")) == ObjectId{1});  // "Follower" in the figure: names ignore case
    CHECK(s.owner(*s.find_surface("d-3")) == ObjectId{0});
    REQUIRE(s.situations.size() == 1);
    REQUIRE(s.situations[0].contacts.size() == 1);
    CHECK(s.situations[0].contacts[0].second == *s.find_surface("d-1"));
}

TEST_CASE("scene/scene_parser: recoil_escapement.def gives the pallet (+) in its second situation") {
    Scene s = load_alex("recoil_escapement.def");
    REQUIRE(s.situations.size() == 2);
    CHECK(s.situations[0].motions.empty());
    REQUIRE(s.situations[1].motions.size() == 1);
    const Motion& m = s.situations[1].motions[0];
    CHECK(m.object == *s.find_object("pallet"));
    CHECK(m.translation == none2);
    CHECK(m.rotation == Direction{Sign::plus});
    CHECK(s.objects[*s.find_object("scape-wheel")].surfaces.size() == 5);
}

TEST_CASE("scene/scene_parser: explicit causes are shared by name; lever.def names its cause") {
    Scene lever = load_alex("lever.def");
    REQUIRE(lever.forces.size() == 1);
    CHECK(lever.causes[lever.forces[0].cause].name == "hand");
    CHECK(lever.causes[lever.forces[0].cause].is_explicit);
    CHECK(lever.forces[0].origin == Direction{Sign::minus, Sign::minus});
    Scene s = read_ok("(Defscenario 2 c Individuals (a b) Forces ((a (0 -) (0 0) g) (b (0 -) (0 0) G) (a (+ 0) (0 0))))"
                      "(Defstates ((Force b (- 0) (0 0) g)))");
    REQUIRE(s.forces.size() == 3);
    CHECK(s.forces[0].cause == s.forces[1].cause);  // g and G: names ignore case
    CHECK(s.forces[2].cause != s.forces[0].cause);
    CHECK(s.causes[s.forces[2].cause].name == "force#3");
    REQUIRE(s.situations[0].forces.size() == 1);
    CHECK(s.situations[0].forces[0].cause == s.forces[0].cause);
}

TEST_CASE("scene/scene_parser: block_3d.def has 3-D translations and rotation triples") {
    Scene s = load_alex("block_3d.def");
    CHECK(s.dimensions == 3);
    CHECK(s.rotation_arity() == 3);
    const ObjectId table = *s.find_object("table");
    REQUIRE(s.objects[table].rot_constraints.size() == 1);
    CHECK(s.objects[table].rot_constraints[0].size() == 3);
    REQUIRE(s.situations.size() == 3);
    REQUIRE(s.situations[2].motions.size() == 1);
    CHECK(s.situations[2].motions[0].rotation == Direction{Sign::zero, Sign::zero, Sign::plus});
}

TEST_CASE("scene/scene_parser: both notations give the same Scene") {
    // Figure 7.12 written by hand in the s-expression notation must equal gears.def.
    const Scene kw = load_alex("gears.def");
    const Scene sx = read_ok(R"((defscenario 2 GEARS
        individuals (driver follower)
        descriptions ((rigid-ob driver) (rigid-ob follower))
        surfaces ((Follower (l-1 (- -) (0 +)) (l-2 (0 -) (0 +)) (l-3 (+ -) (0 +)))
                  (Driver (d-1 (+ +) (0 -)) (d-2 (0 +) (0 -)) (d-3 (- +) (0 -))))
        translational-constraints ((driver (?x1 ?y1)) (follower (?x3 ?y3)))
        forces ())
      (defstates ((contact l-1 d-1))))");
    CHECK(sx == kw);
    // Printed in either notation, a scene reads back equal: scene_printer_test.cpp (random scenes)
    // and scene_parser_spellings_test.cpp (every bundled scene, in the thesis' spellings).
}

TEST_CASE("scene/scene_parser: keyword notation details") {
    // Individuals with or without parentheses; a comma between surface groups is optional;
    // keywords and names are case-insensitive; an empty Situation is allowed.
    const Scene a = read_ok("S 2\nINDIVIDUALS : x, y\nsurfaces : X (p (0 +) (0 -)), Y (q (0 -) (0 +))\n"
                            "Situation :\nSituation : contact (p q), MOTION (x (0 +) (0)), force (y (0 -) (0 0) w)");
    const Scene b = read_ok("s 2 Individuals : (x, y) Surfaces : x (p (0 +) (0 -)) y (q (0 -) (0 +))"
                            " Situation : Situation : Contact (p q), Force (y (0 -) (0 0) w), Motion (x (0 +) (0))");
    CHECK(a == b);
    REQUIRE(a.situations.size() == 2);
    CHECK(a.situations[0].contacts.empty());
    CHECK(a.situations[1].motions.size() == 1);
    CHECK(a.situations[1].forces.size() == 1);
}

TEST_CASE("scene/scene_parser: --given motions") {
    const Scene s = load_alex("recoil_escapement.def");
    qm::Diagnostics diags;
    auto m = parse_given(s, "pallet (0 0) (+)", diags);
    REQUIRE(m.has_value());
    CHECK(m->object == *s.find_object("pallet"));
    CHECK(m->rotation == Direction{Sign::plus});
    CHECK(*m == s.situations[1].motions[0]);

    qm::Diagnostics bad;
    CHECK_FALSE(parse_given(s, "palet (0 0) (+)", bad).has_value());
    CHECK(printed(bad) == "--given:1:1: error: object 'palet' in a motion is not declared in Individuals; did you mean 'pallet'?\n"
                      "  palet (0 0) (+)\n  ^\n");

    qm::Diagnostics arity;
    CHECK_FALSE(parse_given(s, "pallet (0 0) (+ +)", arity).has_value());
    REQUIRE(arity.size() == 1);
    CHECK(arity.items()[0].where.column == 14);
    CHECK(arity.items()[0].message == "a rotational motion needs 1 sign in a 2-D scene but has 2");

    qm::Diagnostics syntax;
    CHECK_FALSE(parse_given(s, "pallet (0 0)", syntax).has_value());
    REQUIRE(syntax.size() == 1);
    CHECK(syntax.items()[0].message == "expected a direction like (0 +) but found end of input");
}

TEST_CASE("scene/scene_parser: query facts") {
    const Scene s = load_alex("gears.def");
    using K = QueryFact::Kind;
    auto ok = [&](const std::string& text) {
        qm::Diagnostics d;
        auto q = parse_query_fact(s, text, d);
        INFO(text << "\n" << printed(d));
        REQUIRE(q.has_value());
        return *q;
    };
    QueryFact q = ok("Rotational-Motion (follower (-))");
    CHECK(q.kind == K::rotational_motion);
    CHECK(q.object == s.find_object("follower"));
    CHECK(q.direction == Direction{Sign::minus});
    q = ok("translational-freedom (Driver (0 +))");
    CHECK(q.kind == K::translational_freedom);
    CHECK(q.direction == up);
    q = ok("Contact l-1 d-1");
    CHECK(q.kind == K::contact);
    CHECK(q.first == s.find_surface("l-1"));
    CHECK(q.second == s.find_surface("d-1"));
    CHECK(ok("Contact (l-1 d-1)") == q);
    q = ok("Force driver");
    CHECK(q.kind == K::force);
    CHECK(q.object == s.find_object("driver"));
    CHECK(ok("Rotational-Freedom driver (+)").kind == K::rotational_freedom);
    CHECK(ok("Translational-Motion (driver (0 0))").kind == K::translational_motion);

    auto err = [&](const std::string& text) {
        qm::Diagnostics d;
        CHECK_FALSE(parse_query_fact(s, text, d, "--why").has_value());
        REQUIRE(d.size() >= 1);
        const auto first = d.sorted()[0];
        return std::to_string(first.where.column) + ": " + first.message;
    };
    CHECK(err("Rotational-Motion (follower (+ +))") ==
          "29: a rotation needs 1 sign in a 2-D scene but has 2");
    CHECK(err("Rotational-Motion (folower (+))") == "20: object 'folower' in the fact is not declared in Individuals; did you mean 'follower'?");
    CHECK(err("Spinning (driver (+))") ==
          "1: unknown predicate 'Spinning': expected Translational-Motion, Rotational-Motion, Translational-Freedom, "
          "Rotational-Freedom, Contact or Force");
    CHECK(err("Contact l-1 d-9") == "13: unknown surface 'd-9'; did you mean 'd-1'?");
    CHECK(err("Contact l-1") == "9: Contact needs two surfaces");
    CHECK(err("Rotational-Motion (driver)") == "20: rotational-motion needs a direction after the object, like (driver (0 +))");
    CHECK(err("Rotational-Motion (driver (--))") ==
          "28: bad sign '--': a sign is '+', '0' or '-' (the thesis' OCR prints '-' as '--'; write '-')");
    CHECK(err("Rotational-Motion (driver (+)") == "19: unbalanced parentheses: this '(' is never closed (1 unclosed in all)");
    CHECK(err("") == "1: empty input: expected a fact like 'Rotational-Motion (follower (-))'");
    CHECK(err("Force driver x y") == "16: expected end of input but found 'y'");
}

TEST_CASE("scene/scene_parser: never throws, whatever the input; syntax errors name what was expected") {
    // Every prefix of real scenes, in both notations, is bad input or a valid scene: never an
    // exception. Each "expected X" names X in words: an expectation on a bare X3 list would
    // print a mangled C++ type name (N5boost6spirit...).
    std::vector<std::string> texts;
    for (const char* file : {"block.def", "gears.def", "corner_contacts.def", "linked_gears.def"}) {
        texts.push_back(qm::test::slurp(scenes_dir() + "/" + file));
        const Scene s = load_alex(file);
        texts.push_back(print_scene_keywords(s));
    }
    // The thesis' own spellings (tests/scene/figures/): figure headers, bare constraint lists,
    // BNF surface groups, braces, defState, closing CONTACT lists.
    for (const char* file : {"fig7_2.def", "fig7_8.def", "fig7_12.def", "fig7_16.def", "fig6_1_bnf.def"}) {
        texts.push_back(qm::test::slurp(std::string(QM_SOURCE_DIR) + "/tests/scene/figures/" + file));
        REQUIRE(!texts.back().empty());
    }
    std::size_t syntax_errors = 0;
    for (const std::string& text : texts)
        for (std::size_t n = 0; n <= text.size(); n += 3) {
            qm::Diagnostics d;
            std::optional<Scene> s;
            CHECK_NOTHROW(s = read_scene("p.def", text.substr(0, n), d));
            CHECK(s.has_value() != d.has_errors());
            for (const auto& item : d.items()) {
                const auto at = item.message.find(" but found ");
                if (item.message.rfind("expected ", 0) != 0 || at == std::string::npos) continue;
                ++syntax_errors;
                const std::string what = item.message.substr(9, at - 9);
                INFO(item.message);
                CHECK(what.find("boost") == std::string::npos);
                CHECK(what.find("spirit") == std::string::npos);
            }
        }
    CHECK(syntax_errors > 150);
}

TEST_CASE("scene/scene_parser: bytes outside ASCII are bad input (in a comment, text), never an abort") {
    // Spirit's character classes assert that a char is in 0..UCHAR_MAX; a byte >= 0x80 in a
    // signed char is not, so the reader classifies bytes itself (this test aborts otherwise in
    // a build with assertions, as the test builds are).
    for (int b = 0x80; b <= 0xff; ++b) {
        const std::string byte(1, static_cast<char>(b));
        INFO(b);
        for (const std::string& text :
             {"(Defscenario 2 s Individuals (a" + byte + "))", byte + "(Defscenario 2 s)", "S" + byte + " 2",
              "S 2 Individuals : a" + byte, "S 2 Individuals" + byte + " : a", "S 2 Situations {" + byte + "}",
              "(Defscenario 2 s Individuals (a) Surfaces ((a (p (0 +" + byte + ") (0 -)))))",
              "(Defscenario 2 s Individuals (a)) (Defstates" + byte + ")"}) {
            qm::Diagnostics d;
            std::optional<Scene> s;
            CHECK_NOTHROW(s = read_scene("b.def", text, d));
            CHECK_FALSE(s.has_value());
            CHECK(d.has_errors());
        }
        qm::Diagnostics d;
        CHECK(read_scene("c.def", "S 2 ; caf" + byte + "\nIndividuals : a ; " + byte + byte, d).has_value());
        CHECK(d.size() == 0);
    }
}
