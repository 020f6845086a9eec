// tests/scene/scene_test.cpp: scene/scene.hpp - pattern matching, lookups, ownership, equality.
#include "scene/scene.hpp"

#include <doctest/doctest.h>

using namespace qm::scene;

namespace {
const Sign signs[] = {Sign::minus, Sign::zero, Sign::plus};
}

TEST_CASE("scene/scene: a pattern's variables match any sign, its signs only themselves") {
    // Brute force over all 2-D directions against all patterns of fixed signs and variables.
    for (int mask = 0; mask < 4; ++mask)
        for (Sign px : signs)
            for (Sign py : signs) {
                DirectionPattern p{{(mask & 1) ? std::nullopt : std::optional(px), "x"},
                                   {(mask & 2) ? std::nullopt : std::optional(py), "y"}};
                for (Sign x : signs)
                    for (Sign y : signs) {
                        const bool expect = ((mask & 1) || x == px) && ((mask & 2) || y == py);
                        CHECK(matches(p, {x, y}) == expect);
                    }
            }
    // (rack (?x +)): every translation with positive y (spec README).
    DirectionPattern rack{{std::nullopt, "x"}, {Sign::plus, ""}};
    CHECK(matches(rack, {Sign::minus, Sign::plus}));
    CHECK_FALSE(matches(rack, {Sign::plus, Sign::zero}));
}

TEST_CASE("scene/scene: lookups and ownership") {
    Scene s;
    const ObjectId a = s.objects.push_back({"a", "rigid-ob", {}, {}, {}, {}, {}, {}, {}});
    const ObjectId b = s.objects.push_back({"b", "rigid-ob", {}, {}, {}, {}, {}, {}, {}});
    const SurfaceId p = s.surfaces.push_back({"p", a, {Sign::zero, Sign::plus}, {Sign::zero, Sign::minus}, std::nullopt, {}});
    const SurfaceId q = s.surfaces.push_back({"q", b, {Sign::zero, Sign::minus}, {Sign::zero, Sign::plus}, std::nullopt, {}});
    s.objects[a].surfaces.push_back(p);
    s.objects[b].surfaces.push_back(q);
    CHECK(s.find_object("b") == b);
    CHECK_FALSE(s.find_object("c").has_value());
    CHECK(s.find_surface("q") == q);
    CHECK(s.owner(p) == a);
    CHECK(s.owner(q) == b);
    CHECK_THROWS_AS(static_cast<void>(s.owner(SurfaceId{7})), qm::InternalError);  // Pre: a surface of this scene
    CHECK(s.rotation_arity() == 1);
    s.dimensions = 3;
    CHECK(s.rotation_arity() == 3);
    CHECK(s.translation_arity() == 3);
}

TEST_CASE("scene/scene: equality compares content, never source locations") {
    Scene x;
    x.name = "s";
    x.objects.push_back({"a", "rigid-ob", {}, {}, {}, {"f.def", 3, 4}, {}, {}, {}});
    Scene y = x;
    y.objects[ObjectId{0}].where = {"g.def", 9, 9};
    y.where = {"g.def", 1, 1};
    CHECK(x == y);
    y.objects[ObjectId{0}].trans_constraints.push_back({{std::nullopt, "x"}, {std::nullopt, "y"}});
    CHECK_FALSE(x == y);
    Scene z = x;
    z.situations.push_back({});
    CHECK_FALSE(x == z);
    // Linkages (Def 21) and corner sides (Def 18) are content; a linkage's location is not.
    Scene l = x;
    l.objects.push_back({"b", "rigid-ob", {}, {}, {}, {}, {}, {}, {}});
    Scene l2 = l;
    l.linkages.push_back({ObjectId{0}, ObjectId{1}, {"f.def", 1, 1}});
    CHECK_FALSE(l == l2);
    l2.linkages.push_back({ObjectId{0}, ObjectId{1}, {"g.def", 7, 7}});
    CHECK(l == l2);
    l2.linkages[0] = {ObjectId{1}, ObjectId{0}, {}};
    CHECK_FALSE(l == l2);  // the order as written is kept
    Scene k = x;
    const Direction up{Sign::zero, Sign::plus};
    for (const char* n : {"p", "q"}) k.surfaces.push_back({n, ObjectId{0}, up, up, std::nullopt, {}});
    Scene k2 = k;
    k.surfaces.push_back({"c", ObjectId{0}, {}, up, CornerSides{SurfaceId{0}, SurfaceId{1}}, {}});
    k2.surfaces.push_back({"c", ObjectId{0}, {}, up, CornerSides{SurfaceId{1}, SurfaceId{0}}, {}});
    CHECK(k.surfaces[SurfaceId{2}].is_corner());
    CHECK_FALSE(k.surfaces[SurfaceId{0}].is_corner());
    CHECK_FALSE(k == k2);
    CHECK(sign_char(Sign::minus) == '-');
    CHECK(sign_char(Sign::zero) == '0');
    CHECK(sign_char(Sign::plus) == '+');
}

TEST_CASE("scene/scene: find_* by hash agree with a scan, also for entries added after a lookup") {
    // The index learns entries as they are added (a scan per lookup would make reading quadratic).
    Scene s;
    auto scan = [&](const std::string& name) -> std::optional<ObjectId> {
        for (std::uint32_t i = 0; i < s.objects.size(); ++i)
            if (s.objects[ObjectId{i}].name == name) return ObjectId{i};
        return std::nullopt;
    };
    for (int round = 0; round < 50; ++round) {
        Object o;
        o.name = "o" + std::to_string(round % 37);  // repeats from round 37 on: the first stays
        s.objects.push_back(o);
        for (int q = 0; q < 40; ++q) {
            const std::string name = "o" + std::to_string(q);
            CHECK(s.find_object(name) == scan(name));
        }
    }
    const Scene copy = s;
    CHECK(copy.find_object("o36") == scan("o36"));
    CHECK(!copy.find_object("o37"));
}
