// tests/analysis/oracle_scenes.hpp: the scenes of the two test oracles (kinematics_oracle_test.cpp,
// force_oracle_test.cpp): bundled ones read (tests/support/scene_reading.hpp) and analysed, and
// seeded random ones written as scene text. Deterministic: std::mt19937 with fixed seeds, reduced with `%` (not the
// implementation-defined distributions).
#pragma once
#include "analysis/analysis.hpp"
#include "../support/scene_reading.hpp"

#include <doctest/doctest.h>

#include <algorithm>
#include <cstdlib>
#include <functional>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace oracle {
using namespace qm::scene;
using qm::analysis::Analysis;

inline std::string text(const Direction& d) {
    std::string s = "(";
    for (std::size_t i = 0; i < d.size(); ++i) s += (i ? " " : "") + std::string(1, sign_char(d[i]));
    return s + ")";
}
inline Direction opposite(Direction d) {
    for (Sign& s : d) s = static_cast<Sign>(-static_cast<int>(s));
    return d;
}

using qm::test::printed;
inline Scene read_ok(const std::string& src) { return qm::test::read_ok(src, "oracle.def"); }
// A bundled scene of scenarios/alex/.
inline Scene read_file_ok(const std::string& name) { return qm::test::load_ok("scenarios/alex/" + name); }
inline Analysis analyse_ok(const Scene& scene) {
    qm::analysis::AnalysisOptions options;
    options.rules_directory = std::string(QM_SOURCE_DIR) + "/rules";
    qm::Diagnostics diags;
    auto a = qm::analysis::analyse(scene, options, diags);
    INFO(printed(diags));
    REQUIRE(a.has_value());
    return std::move(*a);
}
inline ObjectId id(const Scene& s, const char* name) {
    const auto o = s.find_object(name);
    REQUIRE(o.has_value());
    return *o;
}

// ---------------------------------------------------------------------------------------------
// Random scenes.

class Random {
public:
    explicit Random(std::uint32_t seed) : rng_(seed) {}
    std::size_t below(std::size_t n) { return static_cast<std::size_t>(rng_() % n); }
    bool chance(unsigned percent) { return below(100) < percent; }
    Sign sign() { return static_cast<Sign>(static_cast<int>(below(3)) - 1); }
    Direction direction(std::size_t n) {
        Direction d;
        for (std::size_t i = 0; i < n; ++i) d.push_back(sign());
        return d;
    }
    Direction non_zero(std::size_t n) {
        for (;;) {
            Direction d = direction(n);
            if (std::any_of(d.begin(), d.end(), [](Sign s) { return s != Sign::zero; })) return d;
        }
    }

private:
    std::mt19937 rng_;
};

// A constraint pattern as scene text: each place a fixed sign or a variable. With `repeat`, now and
// then a variable name repeats inside one pattern; the guide says each `?x` matches any sign in its
// own place, so the repeat must not link the places.
inline std::string pattern(Random& rnd, std::size_t n, unsigned variable_percent, int& vars, bool repeat = false) {
    std::string s = "(";
    for (std::size_t i = 0; i < n; ++i) {
        if (i) s += ' ';
        if (rnd.chance(variable_percent)) s += "?v" + std::to_string(repeat && rnd.chance(15) && vars > 0 ? vars : ++vars);
        else s += sign_char(rnd.sign());
    }
    return s + ")";
}
inline std::string all_variables(std::size_t n, int& vars) {
    std::string s = "(";
    for (std::size_t i = 0; i < n; ++i) s += (i ? " ?v" : "?v") + std::to_string(++vars);
    return s + ")";
}

// One random scene ("group") of a few objects. Several are written side by side in one scene text
// (render), group g's names starting with `g<g>`; no contact joins two groups, so each group's chains
// are its own (loading the rule files costs more than analysing a small group).
struct Group {
    struct Obj {
        std::vector<std::pair<Direction, Direction>> surfaces;  // (normal, origin)
        std::vector<std::string> trans, rot;                    // constraint patterns, as text
    };
    struct Touch {
        std::size_t a, sa, b, sb;  // object, surface index of each side
    };
    struct F {
        std::size_t object;
        Direction dir, origin;
        int cause;  // -1: its own; else a shared name of the group
    };
    struct Given {
        std::size_t object;
        Direction translation, rotation;
    };
    // A surface as placed, for choosing contacts.
    struct Placed {
        std::size_t object, index;
        Direction normal;
    };
    std::vector<Obj> objects;
    std::vector<F> scene_forces;
    std::vector<std::vector<Touch>> contacts;  // per situation
    std::vector<std::vector<F>> forces;        // per situation
    std::vector<std::vector<Given>> motions;   // per situation
    std::vector<std::pair<std::size_t, std::size_t>> linkages;
    std::vector<Placed> placed;

    // 1 to max_surfaces surfaces of object o, each normal often (facing_percent) the reverse of
    // another object's, so that many contacts are between facing surfaces (where Table 3.1's and
    // Table 3.2's choices of SN coincide).
    void add_surfaces(Random& rnd, std::size_t o, std::size_t tn, std::size_t max_surfaces, unsigned facing_percent) {
        const std::size_t n = 1 + rnd.below(max_surfaces);
        for (std::size_t i = 0; i < n; ++i) {
            Direction normal = rnd.non_zero(tn);
            std::vector<const Placed*> others;
            for (const auto& p : placed)
                if (p.object != o) others.push_back(&p);
            if (!others.empty() && rnd.chance(facing_percent)) normal = opposite(others[rnd.below(others.size())]->normal);
            const Direction origin = rnd.chance(20) ? Direction(tn, Sign::zero) : rnd.direction(tn);
            objects[o].surfaces.push_back({normal, origin});
            placed.push_back({o, i, normal});
        }
    }
    // Up to `count` contacts of situation k between surfaces of different objects that `allowed`
    // lets touch, facing ones preferred (facing_percent).
    void add_contacts(Random& rnd, std::size_t k, std::size_t count, unsigned facing_percent,
                      const std::function<bool(std::size_t, std::size_t)>& allowed) {
        std::set<std::pair<std::size_t, std::size_t>> used;
        for (std::size_t c = 0; c < count; ++c) {
            std::vector<std::pair<std::size_t, std::size_t>> candidates, facing;
            for (std::size_t a = 0; a < placed.size(); ++a)
                for (std::size_t b = a + 1; b < placed.size(); ++b) {
                    if (placed[a].object == placed[b].object || used.count({a, b})) continue;
                    if (!allowed(placed[a].object, placed[b].object)) continue;
                    candidates.push_back({a, b});
                    if (placed[a].normal == opposite(placed[b].normal)) facing.push_back({a, b});
                }
            if (candidates.empty()) break;
            const auto& pool = !facing.empty() && rnd.chance(facing_percent) ? facing : candidates;
            auto [a, b] = pool[rnd.below(pool.size())];
            used.insert({a, b});
            if (rnd.chance(50)) std::swap(a, b);
            contacts[k].push_back({placed[a].object, placed[a].index, placed[b].object, placed[b].index});
        }
    }
};

inline std::string object_name(std::size_t g, std::size_t o) { return "g" + std::to_string(g) + "o" + std::to_string(o); }
inline std::string surface_name(std::size_t g, std::size_t o, std::size_t s) { return object_name(g, o) + "-s" + std::to_string(s); }
inline std::string force_text(std::size_t g, const Group::F& f) {
    std::string s = object_name(g, f.object) + " " + text(f.dir) + " " + text(f.origin);
    if (f.cause >= 0) s += " g" + std::to_string(g) + "c" + std::to_string(f.cause);
    return s;
}

// groups[i] written as group numbers[i], with `situations` situations.
inline std::string render(int dims, const std::vector<Group>& groups, std::size_t situations, const std::vector<std::size_t>& numbers) {
    std::ostringstream os;
    os << "(Defscenario " << dims << " random\n  Individuals (";
    for (std::size_t g = 0; g < groups.size(); ++g)
        for (std::size_t o = 0; o < groups[g].objects.size(); ++o) os << ' ' << object_name(numbers[g], o);
    os << ")\n  Surfaces (";
    std::string trans, rot, forces, links;
    for (std::size_t g = 0; g < groups.size(); ++g) {
        for (std::size_t o = 0; o < groups[g].objects.size(); ++o) {
            const Group::Obj& obj = groups[g].objects[o];
            os << "\n    (" << object_name(numbers[g], o);
            for (std::size_t s = 0; s < obj.surfaces.size(); ++s)
                os << " (" << surface_name(numbers[g], o, s) << ' ' << text(obj.surfaces[s].first) << ' '
                   << text(obj.surfaces[s].second) << ')';
            os << ')';
            auto entry = [&](std::string& section, const std::vector<std::string>& ps) {
                if (ps.empty()) return;
                section += "\n    (" + object_name(numbers[g], o);
                for (const auto& p : ps) section += " " + p;
                section += ")";
            };
            entry(trans, obj.trans);
            entry(rot, obj.rot);
        }
        for (const Group::F& f : groups[g].scene_forces) forces += "\n    (" + force_text(numbers[g], f) + ")";
        for (const auto& [a, b] : groups[g].linkages) links += " (" + object_name(numbers[g], a) + " " + object_name(numbers[g], b) + ")";
    }
    os << ")\n";
    if (!trans.empty()) os << "  Translational-Constraints (" << trans << ")\n";
    if (!rot.empty()) os << "  Rotational-Constraints (" << rot << ")\n";
    if (!forces.empty()) os << "  Forces (" << forces << ")\n";
    if (!links.empty()) os << "  Linkages (" << links << ")\n";
    os << ")\n(Defstates\n";
    for (std::size_t k = 0; k < situations; ++k) {
        os << "  (";
        for (std::size_t g = 0; g < groups.size(); ++g) {
            for (const Group::Touch& t : groups[g].contacts[k])
                os << "(Contact " << surface_name(numbers[g], t.a, t.sa) << ' ' << surface_name(numbers[g], t.b, t.sb) << ')';
            for (const Group::F& f : groups[g].forces[k]) os << "(Force " << force_text(numbers[g], f) << ')';
            for (const Group::Given& m : groups[g].motions[k])
                os << "(Motion " << object_name(numbers[g], m.object) << ' ' << text(m.translation) << ' ' << text(m.rotation) << ')';
        }
        os << ")\n";
    }
    os << ")\n";
    return os.str();
}

// packs_release packs of random scenes in a Release build, packs_debug in the others (a Debug or
// sanitized build analyses far more slowly); the environment variable `env` overrides both (soak
// runs).
inline std::size_t packs_for(std::size_t packs_release, std::size_t packs_debug, const char* env) {
#if defined(NDEBUG) && !defined(QM_SANITIZED_BUILD)
    std::size_t packs = packs_release;
    (void)packs_debug;
#else
    std::size_t packs = packs_debug;
    (void)packs_release;
#endif
    if (const char* given = std::getenv(env))
        if (const std::size_t n = std::strtoul(given, nullptr, 10); n > 0) packs = n;
    return packs;
}

}  // namespace oracle
