// tests/alex/scene_printer_test.cpp: alex/scene_printer.hpp - exact output for a small scene, and
// parse(print(s)) == s in both notations for seeded random scenes (the scene generator below
// builds Scenes directly, independently of the parser).
#include "alex/scene_parser.hpp"
#include "alex/scene_printer.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <random>
#include <sstream>

using namespace qm::alex;

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
    for (int i = 0; i < n_obj; ++i) s.objects.push_back({"o" + std::to_string(i), "rigid-ob", {}, {}, {}, {}});
    const int n_surf = pick(8);
    for (int i = 0; i < n_surf; ++i) {
        // Surfaces are grouped by owner in increasing id order, as the reader assigns them.
        const ObjectId o{static_cast<std::uint32_t>(std::min(n_obj - 1, i * n_obj / std::max(1, n_surf)))};
        const SurfaceId id = s.surfaces.push_back(
            {"s-" + std::to_string(i), o, dir(s.translation_arity(), true), dir(s.translation_arity(), false), std::nullopt, {}});
        s.objects[o].surfaces.push_back(id);
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
        if (n_surf >= 2)
            for (int c = pick(4); c > 0; --c) {
                SurfaceId a{static_cast<std::uint32_t>(pick(n_surf))}, b{static_cast<std::uint32_t>(pick(n_surf))};
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

TEST_CASE("alex/scene_printer: exact output for a small scene") {
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
    CHECK(print_direction({Sign::plus, Sign::zero, Sign::minus}) == "(+ 0 -)");
    CHECK(print_pattern({{std::nullopt, "r"}}) == "(?r)");
}

TEST_CASE("alex/scene_printer: parse(print(s)) == s for 300 seeded random scenes, both notations") {
    std::mt19937 rng(20260123);
    for (int i = 0; i < 300; ++i) {
        const Scene s = random_scene(rng);
        auto a = reread(print_scene(s));
        auto b = reread(print_scene_keywords(s));
        REQUIRE(a.has_value());
        REQUIRE(b.has_value());
        CHECK(*a == s);
        CHECK(*b == s);
    }
}
