// tests/engine/builtins_qualitative_test.cpp: the qualitative builtins against real arithmetic:
// every cell of the sign tables is checked against sampled real numbers with those signs (a
// definite table entry must be the sign of every sample; ? must be justified by samples of both
// signs), Open-Half-Plane is sound for real dot products, Rotate-90 agrees with the real rotation
// matrix, nearness follows Def 38's classes.
#include "engine/builtin_registry.hpp"
#include <algorithm>
#include <doctest/doctest.h>
#include <random>
#include <set>

using namespace qm::engine;

namespace {
ValueTable values;
ValueId dir(const std::string& s) { return values.direction(s); }
BuiltinResult apply(const char* name, std::vector<ValueId> args) {
    return default_builtins().apply(*default_builtins().find(name), values, args);
}
std::string text(const BuiltinResult& r) { return r.value ? values.print(*r.value) : "error: " + r.error; }

char sign_of(double x) { return x > 0 ? '+' : x < 0 ? '-' : '0'; }
double sample(char s, std::mt19937& rng) {
    std::uniform_real_distribution<double> d(0.1, 10.0);
    return s == '+' ? d(rng) : s == '-' ? -d(rng) : 0.0;
}
}  // namespace

TEST_CASE("engine/builtins_qualitative: sign sum and product tables agree with sampled reals") {
    std::mt19937 rng(3);
    for (char a : {'+', '0', '-'})
        for (char b : {'+', '0', '-'}) {
            char sum = values.value(*apply("sign-sum", {dir({a}), dir({b})}).value).text[0];
            char product = values.value(*apply("sign-product", {dir({a}), dir({b})}).value).text[0];
            std::set<char> sums, products;
            for (int i = 0; i < 200; ++i) {
                double x = sample(a, rng), y = sample(b, rng);
                sums.insert(sign_of(x + y));
                products.insert(sign_of(x * y));
            }
            CAPTURE(a);
            CAPTURE(b);
            if (sum == '?') CHECK(sums.size() > 1);
            else CHECK(sums == std::set<char>{sum});
            CHECK(products == std::set<char>{product});
        }
    CHECK(text(apply("sign-sum", {dir("?"), dir("0")})) == "(?)");
    CHECK(text(apply("sign-product", {dir("?"), dir("0")})) == "(0)");
    CHECK(text(apply("sign-product", {dir("?"), dir("-")})) == "(?)");
}

TEST_CASE("engine/builtins_qualitative: open-half-plane is sound for real dot products; ambiguous is false") {
    std::mt19937 rng(5);
    auto all = apply("translations", {values.integer(3)});
    REQUIRE(all.value.has_value());
    const auto& dirs = values.value(*all.value).elements;
    CHECK(dirs.size() == 27);
    for (ValueId a : dirs)
        for (ValueId b : dirs) {
            bool open = apply("open-half-plane", {a, b}).holds;
            bool closed = apply("half-plane", {a, b}).holds;
            const auto& sa = values.value(a).text;
            const auto& sb = values.value(b).text;
            for (int i = 0; i < 20; ++i) {
                double dot = 0;
                for (int k = 0; k < 3; ++k) dot += sample(sa[k], rng) * sample(sb[k], rng);
                if (open) CHECK(dot > 0);
                if (closed) CHECK(dot >= 0);
            }
        }
    CHECK(!apply("open-half-plane", {dir("+-"), dir("++")}).holds);  // dot product ambiguous
    CHECK(apply("open-half-plane", {dir("+-"), dir("+0")}).holds);
}

TEST_CASE("engine/builtins_qualitative: rotate-90 agrees with the real quarter-turn matrices") {
    std::mt19937 rng(9);
    for (char x : {'+', '0', '-'})
        for (char y : {'+', '0', '-'})
            for (char r : {'+', '-'}) {
                double vx = sample(x, rng), vy = sample(y, rng);
                // Counter-clockwise for (+): (x, y) -> (-y, x); clockwise for (-): (x, y) -> (y, -x).
                double rx = r == '+' ? -vy : vy, ry = r == '+' ? vx : -vx;
                CHECK(text(apply("rotate-90", {dir({x, y}), dir({r})})) == values.print(dir({sign_of(rx), sign_of(ry)})));
            }
    CHECK(!apply("rotate-90", {dir("+00"), dir("+")}).error.empty());  // a 3-D vector needs (rx ry rz)
    CHECK(text(apply("rotate-90", {dir("+-"), dir("0")})) == "(0 0)");   // no rotation, no perpendicular
}

TEST_CASE("engine/builtins_qualitative: 3-D rotate-90 is the sign of the real cross product w x v") {
    std::mt19937 rng(13);
    auto all = apply("translations", {values.integer(3)});
    const auto dirs = values.value(*all.value).elements;
    for (ValueId v : dirs)
        for (ValueId r : dirs) {
            const std::string sv = values.value(v).text, sr = values.value(r).text;
            const std::string got = values.value(*apply("rotate-90", {v, r}).value).text;
            // Sample reals with these signs: every definite component must be the sign of every
            // sample of w x v; a `?` must be justified by samples of both signs.
            std::vector<std::set<char>> seen(3);
            for (int i = 0; i < 300; ++i) {
                double x = sample(sv[0], rng), y = sample(sv[1], rng), z = sample(sv[2], rng);
                double a = sample(sr[0], rng), b = sample(sr[1], rng), c = sample(sr[2], rng);
                const double cross[3] = {b * z - c * y, c * x - a * z, a * y - b * x};
                for (int k = 0; k < 3; ++k) seen[k].insert(sign_of(cross[k]));
            }
            CAPTURE(sv);
            CAPTURE(sr);
            for (int k = 0; k < 3; ++k) {
                if (got[k] == '?') CHECK(seen[k].size() > 1);
                else CHECK(seen[k] == std::set<char>{got[k]});
            }
        }
    // About z, the 3-D turn agrees with the 2-D one on the x-y plane.
    CHECK(text(apply("rotate-90", {dir("+00"), dir("00+")})) == "(0 + 0)");
    CHECK(text(apply("rotate-90", {dir("0+0"), dir("+00")})) == "(0 0 +)");  // y to z about x (Table 2.1)
}

TEST_CASE("engine/builtins_qualitative: a set of directions is the intersection of their half planes") {
    const ValueId corner = values.set({dir("+-"), dir("--")});  // two potential contact normals
    CHECK(apply("open-half-plane", {corner, dir("0-")}).holds);    // in both open half planes
    CHECK(!apply("open-half-plane", {corner, dir("+-")}).holds);   // only in the first
    CHECK(!apply("half-plane", {corner, dir("+-")}).holds);        // (- -).(+ -) is ambiguous
    CHECK(apply("half-plane", {values.set({dir("+0"), dir("0-")}), dir("0-")}).holds);  // dots 0 and +
    CHECK(!apply("open-half-plane", {values.set({dir("+0"), dir("0-")}), dir("0-")}).holds);
    CHECK(apply("outside-open-half-plane", {corner, dir("0+")}).holds);
    CHECK(!apply("outside-open-half-plane", {corner, dir("+-")}).holds);
    CHECK(text(apply("neg", {corner})) == values.print(values.set({dir("-+"), dir("++")})));
    CHECK(text(apply("rotate-90", {corner, dir("+")})) == values.print(values.set({dir("++"), dir("+-")})));
    CHECK(!apply("open-half-plane", {values.set({}), dir("0-")}).error.empty());
    CHECK(text(apply("qsum-of", {corner})) == "(? -)");
    CHECK(text(apply("qsum-of", {dir("+0")})) == "(+ 0)");
    // For single vectors outside- is exactly the negation.
    auto all = apply("translations", {values.integer(2)});
    for (ValueId a : values.value(*all.value).elements)
        for (ValueId b : values.value(*all.value).elements)
            CHECK(apply("outside-open-half-plane", {a, b}).holds == !apply("open-half-plane", {a, b}).holds);
}

TEST_CASE("engine/builtins_qualitative: vector sums, negation, direction sets, nearness, zero tests") {
    CHECK(text(apply("qsum", {dir("+-0"), dir("++-")})) == "(+ ? -)");
    CHECK(text(apply("cancel-ambiguous", {dir("+?-0")})) == "(+ 0 - 0)");
    // Law 5 as a fold: qsum is associative, so a same-cause sum cancels in any order.
    for (auto order : {std::vector<std::string>{"+0", "+0", "-+"}, {"-+", "+0", "+0"}, {"+0", "-+", "+0"}}) {
        ValueId acc = dir("00");
        for (const auto& d : order) acc = *apply("qsum", {acc, dir(d)}).value;
        CHECK(text(apply("cancel-ambiguous", {acc})) == "(0 +)");
    }
    CHECK(text(apply("set-add", {values.set({dir("+")}), dir("-")})) == values.print(values.set({dir("+"), dir("-")})));
    CHECK(text(apply("neg", {dir("+0-?")})) == "(- 0 + ?)");
    CHECK(text(apply("dot-sign", {dir("+-"), dir("+-")})) == "(+)");
    CHECK(values.value(*apply("rotations", {values.integer(2)}).value).elements.size() == 3);
    CHECK(values.value(*apply("rotations", {values.integer(3)}).value).elements.size() == 27);
    CHECK(text(apply("zero-rotation", {values.integer(2)})) == "(0)");
    CHECK(text(apply("zero-translation", {values.integer(3)})) == "(0 0 0)");
    CHECK(!apply("translations", {values.integer(9)}).error.empty());
    CHECK(apply("zero?", {dir("00")}).holds);
    CHECK(apply("nonzero?", {dir("0-")}).holds);
    // An ambiguous component is not known to be 0: (?) is nonzero, as docs/RULES.md says.
    CHECK(apply("nonzero?", {dir("?")}).holds);
    CHECK(apply("nonzero?", {dir("?0")}).holds);
    CHECK(!apply("zero?", {dir("?")}).holds);
    // resolve-as: each `?` of v takes x's sign there; definite components stay.
    CHECK(text(apply("resolve-as", {dir("?0"), dir("-+")})) == "(- 0)");
    CHECK(text(apply("resolve-as", {dir("+?-"), dir("0-+")})) == "(+ - -)");
    CHECK(text(apply("resolve-as", {dir("+0"), dir("--")})) == "(+ 0)");
    CHECK(!apply("resolve-as", {dir("?0"), dir("+")}).error.empty());
    CHECK(!apply("qsum", {dir("+"), dir("++")}).error.empty());
    CHECK(!apply("neg", {values.symbol("up")}).error.empty());
}

TEST_CASE("engine/builtins_qualitative: qsum-compared is the sign of a real sum whose magnitudes compare as w") {
    // Every sign pair and comparison against sampled reals x, y with those signs and sign(|x| - |y|) = w:
    // a definite answer must be the sign of every such x + y; ? must be justified by samples of both signs.
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> magnitude(0.1, 10.0);
    for (char a : {'+', '0', '-'})
        for (char b : {'+', '0', '-'})
            for (char w : {'+', '0', '-', '?'}) {
                const std::string got = values.value(*apply("qsum-compared", {dir({a}), dir({b}), dir({w})}).value).text;
                std::set<char> sums;
                for (int i = 0; i < 400; ++i) {
                    double m = magnitude(rng), n = magnitude(rng);
                    if (a == '0') m = 0;
                    if (b == '0') n = 0;
                    // Only samples whose magnitudes compare as w (any comparison for ?).
                    const char cmp = sign_of(m - n);
                    if (w != '?' && cmp != w) continue;
                    sums.insert(sign_of((a == '-' ? -m : m) + (b == '-' ? -n : n)));
                }
                CAPTURE(a);
                CAPTURE(b);
                CAPTURE(w);
                if (sums.empty()) continue;  // e.g. a zero and a non-zero magnitude cannot be equal
                if (got == "?") CHECK(sums.size() > 1);
                else CHECK(sums == std::set<char>{got[0]});
            }
    // Component by component; where the terms do not oppose the comparison does not matter.
    CHECK(text(apply("qsum-compared", {dir("+-0+"), dir("-++0"), dir("+")})) == "(+ - + +)");
    CHECK(text(apply("qsum-compared", {dir("+-0+"), dir("-++0"), dir("-")})) == "(- + + +)");
    CHECK(text(apply("qsum-compared", {dir("+-0+"), dir("-++0"), dir("0")})) == "(0 0 + +)");
    CHECK(text(apply("qsum-compared", {dir("+-0+"), dir("-++0"), dir("?")})) == text(apply("qsum", {dir("+-0+"), dir("-++0")})));
    CHECK(text(apply("qsum-compared", {dir("?0"), dir("-0"), dir("+")})) == "(? 0)");
    CHECK(!apply("qsum-compared", {dir("+0"), dir("-0"), dir("++")}).error.empty());
    CHECK(!apply("qsum-compared", {dir("+0"), dir("-"), dir("+")}).error.empty());
}

TEST_CASE("engine/builtins_qualitative: components of a direction") {
    CHECK(text(apply("components", {dir("+0-")})) == "3");
    CHECK(text(apply("components", {dir("-")})) == "1");
    CHECK(text(apply("component", {dir("+0-"), values.integer(1)})) == "(+)");
    CHECK(text(apply("component", {dir("+0-"), values.integer(3)})) == "(-)");
    CHECK(text(apply("component", {dir("?0"), values.integer(1)})) == "(?)");
    CHECK(text(apply("with-component", {dir("+0-"), values.integer(2), dir("?")})) == "(+ ? -)");
    CHECK(text(apply("with-component", {dir("?"), values.integer(1), dir("0")})) == "(0)");
    // Out of range, wrong kinds: errors, never a crash.
    CHECK(!apply("component", {dir("+0"), values.integer(0)}).error.empty());
    CHECK(!apply("component", {dir("+0"), values.integer(3)}).error.empty());
    CHECK(!apply("component", {dir("+0"), values.symbol("x")}).error.empty());
    CHECK(!apply("with-component", {dir("+0"), values.integer(1), dir("+-")}).error.empty());
    CHECK(!apply("with-component", {dir("+0"), values.integer(-1), dir("+")}).error.empty());
    CHECK(!apply("components", {values.integer(2)}).error.empty());
}

TEST_CASE("engine/builtins_qualitative: resolutions are exactly the definite directions a sum with `?` may stand for") {
    // The resolutions of qsum(a, b) are exactly the sign vectors of sums of numbers with a's and b's
    // signs (section 2.3).
    std::mt19937 rng(11);
    const std::string signs = "+0-";
    for (char a0 : signs)
        for (char a1 : signs)
            for (char b0 : signs)
                for (char b1 : signs) {
                    const ValueId sum = *apply("qsum", {dir({a0, a1}), dir({b0, b1})}).value;
                    const Value& set = values.value(*apply("resolutions", {sum}).value);
                    std::set<std::string> listed, sampled;
                    for (ValueId x : set.elements) listed.insert(values.value(x).text);
                    // Small whole magnitudes, so that opposite terms can balance exactly (a `?` may be 0).
                    std::uniform_int_distribution<int> magnitude(1, 3);
                    auto term = [&](char s) { return s == '+' ? magnitude(rng) : s == '-' ? -magnitude(rng) : 0; };
                    for (int i = 0; i < 400; ++i) {
                        const int y0 = term(a0) + term(b0), y1 = term(a1) + term(b1);
                        sampled.insert(std::string{sign_of(y0), sign_of(y1)});
                    }
                    CHECK(listed == sampled);
                }
    CHECK(text(apply("resolutions", {dir("+0")})) == "{(+ 0)}");
    CHECK(values.value(*apply("resolutions", {dir("????????")}).value).elements.size() == 6561);
    CHECK(!apply("resolutions", {dir("?????????")}).error.empty());
    CHECK(!apply("resolutions", {values.symbol("x")}).error.empty());
}

TEST_CASE("engine/builtins_qualitative: resolve-as is the resolution of v that agrees with x where v is ambiguous") {
    // Every v over + 0 - ? and definite x of 1 to 4 signs: the one element of (resolutions v) equal
    // to x at every `?` of v.
    std::size_t pairs = 0;
    for (std::size_t n = 1; n <= 4; ++n) {
        std::vector<std::string> all{""};
        for (std::size_t i = 0; i < n; ++i) {
            std::vector<std::string> next;
            for (const auto& p : all)
                for (char c : {'+', '0', '-', '?'}) next.push_back(p + c);
            all = std::move(next);
        }
        for (const auto& v : all)
            for (const auto& x : all) {
                if (x.find('?') != std::string::npos) continue;
                std::vector<std::string> agreeing;
                for (ValueId r : values.value(*apply("resolutions", {dir(v)}).value).elements) {
                    const std::string& t = values.value(r).text;
                    bool agrees = true;
                    for (std::size_t i = 0; i < n; ++i) agrees = agrees && (v[i] != '?' || t[i] == x[i]);
                    if (agrees) agreeing.push_back(t);
                }
                REQUIRE(agreeing.size() == 1);
                const auto r = apply("resolve-as", {dir(v), dir(x)});
                REQUIRE(r.value.has_value());
                CHECK(values.value(*r.value).text == agreeing.front());
                ++pairs;
            }
    }
    CHECK(pairs == 4 * 3 + 16 * 9 + 64 * 27 + 256 * 81);
}

TEST_CASE("engine/builtins_qualitative: translations of any dimension 1..8 (Defs 1, 3); rotations in 2-D and 3-D only") {
    auto count = [](const char* name, std::int64_t n) {
        auto r = apply(name, {values.integer(n)});
        REQUIRE(r.value.has_value());
        return values.value(*r.value).elements.size();
    };
    CHECK(count("translations", 1) == 3);
    CHECK(text(apply("translations", {values.integer(1)})) == "{(+) (-) (0)}");
    CHECK(count("translations", 2) == 9);
    CHECK(count("translations", 4) == 81);
    CHECK(count("translations", 8) == 6561);
    CHECK(text(apply("zero-translation", {values.integer(1)})) == "(0)");
    CHECK(text(apply("zero-translation", {values.integer(4)})) == "(0 0 0 0)");
    // Every 4-D direction once, each of four signs from + 0 -.
    auto four = apply("translations", {values.integer(4)});
    std::set<std::string> seen;
    for (ValueId d : values.value(*four.value).elements) {
        CHECK(values.value(d).text.size() == 4);
        seen.insert(values.value(d).text);
    }
    CHECK(seen.size() == 81);
    for (std::int64_t bad : {0, -1, 9, 64})
        for (const char* name : {"translations", "zero-translation"})
            CHECK(apply(name, {values.integer(bad)}).error ==
                  std::string("'") + name + "' expects a dimension from 1 to 8, not " + std::to_string(bad));
    for (std::int64_t bad : {1, 4})
        for (const char* name : {"rotations", "zero-rotation"})
            CHECK(apply(name, {values.integer(bad)}).error ==
                  std::string("'") + name + "' expects the dimension 2 or 3 (rotations are defined only in the plane "
                                            "and in space), not " + std::to_string(bad));
    CHECK(!apply("translations", {values.symbol("two")}).error.empty());
}
