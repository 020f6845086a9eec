// tests/scene/scene_printer_test.cpp: scene/scene_printer.hpp - exact output for small scenes (one
// with corners and linkages), and parse(print(s)) == s in both notations for seeded random scenes
// with faces, corners, linkages, constraints, forces, contacts and motions (the scene generator
// below builds Scenes directly, independently of the parser).
#include "scene/scene_parser.hpp"
#include "scene/scene_printer.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <sstream>

using namespace qm::scene;

namespace {

Scene random_scene(std::mt19937& rng) {
    auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
    auto sign = [&] { return static_cast<Sign>(pick(3) - 1); };
    auto dir = [&](std::size_t n, bool nonzero) {
        Direction d;
        do {
            d.clear();
            for (std::size_t i = 0; i < n; ++i) d.push_back(sign());
        } while (nonzero && std::all_of(d.begin(), d.end(), [](Sign s) { return s == Sign::zero; }));
        return d;
    };
    Scene s;
    s.name = "random-" + std::to_string(pick(1000));
    s.dimensions = 2 + pick(2);
    const int n_obj = 1 + pick(4);
    for (int i = 0; i < n_obj; ++i) s.objects.push_back({"o" + std::to_string(i), "rigid-ob", {}, {}, {}, {}, {}, {}, {}});
    const int n_surf = pick(8);
    for (int i = 0; i < n_surf; ++i) {
        // Surfaces are grouped by owner in increasing id order, as the reader assigns them.
        const ObjectId o{static_cast<std::uint32_t>(std::min(n_obj - 1, i * n_obj / std::max(1, n_surf)))};
        const SurfaceId id = s.surfaces.push_back(
            {"s-" + std::to_string(i), o, dir(s.translation_arity(), true), dir(s.translation_arity(), false), std::nullopt, {}});
        s.objects[o].surfaces.push_back(id);
    }
    // Corners (section 3.1.1) take the ids after every face, grouped by owner, as the reader
    // assigns them; each joins two different faces of its own object (Definition 18).
    std::vector<std::vector<SurfaceId>> faces(static_cast<std::size_t>(n_obj));
    for (std::uint32_t i = 0; i < s.surfaces.size(); ++i) faces[s.surfaces[SurfaceId{i}].object.value].push_back(SurfaceId{i});
    int n_corner = 0;
    for (int o = 0; o < n_obj; ++o) {
        const auto& own = faces[static_cast<std::size_t>(o)];
        if (own.size() < 2) continue;
        for (int k = pick(3); k > 0; --k) {
            const int i = pick(static_cast<int>(own.size()));
            const int j = (i + 1 + pick(static_cast<int>(own.size()) - 1)) % static_cast<int>(own.size());
            const ObjectId owner{static_cast<std::uint32_t>(o)};
            const SurfaceId id = s.surfaces.push_back({"k-" + std::to_string(n_corner++), owner, {},
                                                       dir(s.translation_arity(), false),
                                                       CornerSides{own[static_cast<std::size_t>(i)], own[static_cast<std::size_t>(j)]},
                                                       {}});
            s.objects[owner].surfaces.push_back(id);
        }
    }
    const int n_all = static_cast<int>(s.surfaces.size());
    // Linkages (Definition 21): distinct pairs of different objects, in either order.
    for (int k = n_obj > 1 ? pick(3) : 0; k > 0; --k) {
        const ObjectId a{static_cast<std::uint32_t>(pick(n_obj))}, b{static_cast<std::uint32_t>(pick(n_obj))};
        const bool listed = std::any_of(s.linkages.begin(), s.linkages.end(), [&](const Linkage& l) {
            return (l.first == a && l.second == b) || (l.first == b && l.second == a);
        });
        if (a != b && !listed) s.linkages.push_back({a, b, {}});
    }
    auto pattern = [&](std::size_t n) {
        DirectionPattern p;
        for (std::size_t i = 0; i < n; ++i)
            p.push_back(pick(2) ? PatternSlot{std::nullopt, "v" + std::to_string(i)} : PatternSlot{sign(), ""});
        return p;
    };
    for (auto& o : s.objects) {
        for (int k = pick(3); k > 0; --k) o.trans_constraints.push_back(pattern(s.translation_arity()));
        for (int k = pick(2); k > 0; --k) o.rot_constraints.push_back(pattern(s.rotation_arity()));
    }
    std::size_t entry = 0;
    auto force = [&] {
        ++entry;
        CauseId c;
        if (pick(3) == 0) {
            const std::string name = "cause-" + std::to_string(pick(2));
            auto found = s.find_cause(name);
            c = found ? *found : s.causes.push_back({name, true});
        } else {
            c = s.causes.push_back({"force#" + std::to_string(entry), false});
        }
        return Force{ObjectId{static_cast<std::uint32_t>(pick(n_obj))}, dir(s.translation_arity(), false),
                     dir(s.translation_arity(), false), c, {}};
    };
    for (int k = pick(3); k > 0; --k) s.forces.push_back(force());
    for (int k = pick(4); k > 0; --k) {
        Situation sit;
        if (n_all >= 2)
            for (int c = pick(4); c > 0; --c) {  // faces and corners alike
                SurfaceId a{static_cast<std::uint32_t>(pick(n_all))}, b{static_cast<std::uint32_t>(pick(n_all))};
                if (s.owner(a) != s.owner(b)) sit.contacts.push_back({a, b, {}});
            }
        for (int f = pick(2); f > 0; --f) sit.forces.push_back(force());
        for (int m = pick(2); m > 0; --m)
            sit.motions.push_back({ObjectId{static_cast<std::uint32_t>(pick(n_obj))}, dir(s.translation_arity(), false),
                                   dir(s.rotation_arity(), false), {}});
        s.situations.push_back(std::move(sit));
    }
    return s;
}

std::optional<Scene> reread(const std::string& text) {
    qm::Diagnostics d;
    auto s = read_scene("printed.def", text, d);
    std::ostringstream os;
    d.print(os);
    INFO(text << "\n" << os.str());
    CHECK(s.has_value());
    return s;
}

}  // namespace

TEST_CASE("scene/scene_printer: exact output for a small scene") {
    qm::Diagnostics d;
    auto s = read_scene("t.def",
                        "t 2 Individuals : a, b Translational-Constraints : b (?x ?y) "
                        "Surfaces : a (p (0 +) (+ -)) b (q (0 -) (0 0)) Forces : a (0 -) (0 0) g "
                        "Situation : Contact (p q), Motion (a (0 0) (-))",
                        d);
    REQUIRE(s.has_value());
    CHECK(print_scene(*s) ==
          "(Defscenario 2 t\n"
          "  Individuals (a b)\n"
          "  Descriptions ((rigid-ob a)(rigid-ob b))\n"
          "  Surfaces (\n"
          "    (a\n"
          "      (p (0 +) (+ -)))\n"
          "    (b\n"
          "      (q (0 -) (0 0))))\n"
          "  Translational-Constraints ((b (?x ?y)))\n"
          "  Forces (\n"
          "    (a (0 -) (0 0) g)))\n"
          "(Defstates\n"
          "  ((Contact p q)\n"
          "   (Motion a (0 0) (-))))\n");
    CHECK(print_scene_keywords(*s) ==
          "t 2\n"
          "Individuals : (a, b)\n"
          "Descriptions : rigid-ob(a), rigid-ob(b)\n"
          "Translational-Constraints : b (?x ?y)\n"
          "Surfaces : a (p (0 +) (+ -))\n"
          "  b (q (0 -) (0 0))\n"
          "Forces : a (0 -) (0 0) g\n"
          "Situation : Contact (p q), Motion (a (0 0) (-))\n");
    CHECK(print_pattern({{std::nullopt, "r"}}) == "(?r)");
}

TEST_CASE("scene/scene_printer: exact output for corners and linkages") {
    qm::Diagnostics d;
    auto s = read_scene("t.def",
                        "(Defscenario 2 t Individuals (a b c) Linkages ((b c) (a c))"
                        " Corners ((b (m q r (0 +))) (a (k p p2 (- 0)) (k2 p2 p (+ 0))))"
                        " Surfaces ((a (p (0 +) (+ -)) (p2 (+ 0) (0 0))) (b (q (0 -) (0 0)) (r (- 0) (0 0)))))"
                        "(Defstates ((Contact k m)))",
                        d);
    REQUIRE(s.has_value());
    CHECK(print_scene(*s) ==
          "(Defscenario 2 t\n"
          "  Individuals (a b c)\n"
          "  Descriptions ((rigid-ob a)(rigid-ob b)(rigid-ob c))\n"
          "  Surfaces (\n"
          "    (a\n"
          "      (p (0 +) (+ -))\n"
          "      (p2 (+ 0) (0 0)))\n"
          "    (b\n"
          "      (q (0 -) (0 0))\n"
          "      (r (- 0) (0 0))))\n"
          "  Corners (\n"
          "    (b\n"
          "      (m q r (0 +)))\n"
          "    (a\n"
          "      (k p p2 (- 0))\n"
          "      (k2 p2 p (+ 0))))\n"
          "  Linkages ((b c)(a c))\n"
          "  Forces ())\n"
          "(Defstates\n"
          "  ((Contact k m)))\n");
    CHECK(print_scene_keywords(*s) ==
          "t 2\n"
          "Individuals : (a, b, c)\n"
          "Descriptions : rigid-ob(a), rigid-ob(b), rigid-ob(c)\n"
          "Surfaces : a (p (0 +) (+ -)), (p2 (+ 0) (0 0))\n"
          "  b (q (0 -) (0 0)), (r (- 0) (0 0))\n"
          "Corners : b (m q r (0 +))\n"
          "  a (k p p2 (- 0)), (k2 p2 p (+ 0))\n"
          "Linkages : (b c), (a c)\n"
          "Situation : Contact (k m)\n");
}

TEST_CASE("scene/scene_printer: parse(print(s)) == s for 300 seeded random scenes, both notations") {
    std::mt19937 rng(20260123);
    int with_corners = 0, with_linkages = 0, corner_contacts = 0;
    for (int i = 0; i < 300; ++i) {
        const Scene s = random_scene(rng);
        with_corners += std::any_of(s.surfaces.begin(), s.surfaces.end(), [](const Surface& f) { return f.is_corner(); });
        with_linkages += !s.linkages.empty();
        for (const auto& sit : s.situations)
            for (const auto& c : sit.contacts) corner_contacts += s.surfaces[c.first].is_corner() || s.surfaces[c.second].is_corner();
        auto a = reread(print_scene(s));
        auto b = reread(print_scene_keywords(s));
        REQUIRE(a.has_value());
        REQUIRE(b.has_value());
        CHECK(*a == s);
        CHECK(*b == s);
    }
    // The generator exercises the new sections (counts fixed by the seed).
    CHECK(with_corners > 50);
    CHECK(with_linkages > 50);
    CHECK(corner_contacts > 30);
}
