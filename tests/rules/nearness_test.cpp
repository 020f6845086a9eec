// tests/rules/nearness_test.cpp: rules/nearness.rules (Def 38 up to the threshold of 8.3.4) against
// an independent oracle, the former C++ ranking: Def 38's rank 0..5 of a definite x relative to a
// definite v, and for an ambiguous v the minimum over the explicit list of its resolutions (section
// 2.3), capped at the threshold 3. Every net force and torque v over + 0 - ? and every definite
// motion x of 1, 2 and 3 signs (2-D rotations, 2-D translations, 3-D translations and rotations):
// the laws must give exactly one rank per pair, and that rank.
#include "law_harness.hpp"
#include <algorithm>

using qm::test::Laws;

namespace {

std::string oracle_neg(std::string v) {
    for (char& c : v) c = c == '+' ? '-' : c == '-' ? '+' : c;
    return v;
}
char oracle_dot(const std::string& a, const std::string& b) {
    auto sum = [](char x, char y) { return x == '0' ? y : y == '0' ? x : (x == '?' || y == '?') ? '?' : x == y ? x : '?'; };
    auto product = [](char x, char y) { return (x == '0' || y == '0') ? '0' : (x == '?' || y == '?') ? '?' : x == y ? '+' : '-'; };
    char s = '0';
    for (std::size_t i = 0; i < a.size(); ++i) s = sum(s, product(a[i], b[i]));
    return s;
}
// Def 38 for a definite v: v; Open-Half-Plane(v, x); zero; Rotate-90(v, +/-) and any other x with
// no definite dot product; Open-Half-Plane(-v, x); -v.
int oracle_nearness(const std::string& v, const std::string& x) {
    if (x == v) return 0;
    if (x == oracle_neg(v)) return 5;
    if (x.find_first_not_of('0') == std::string::npos) return 2;
    if (oracle_dot(v, x) == '+') return 1;
    if (oracle_dot(oracle_neg(v), x) == '+') return 4;
    return 3;
}
int oracle_nearness_resolved(const std::string& v, const std::string& x) {
    std::vector<std::string> resolutions{""};
    for (char c : v) {
        std::vector<std::string> next;
        for (const auto& p : resolutions)
            for (char s : {'+', '0', '-'})
                if (c == '?' || c == s) next.push_back(p + s);
        resolutions = std::move(next);
    }
    int best = 5;
    for (const auto& r : resolutions) best = std::min(best, oracle_nearness(r, x));
    return best;
}

std::vector<std::string> sign_strings(std::size_t n, const std::string& signs) {
    std::vector<std::string> out{""};
    for (std::size_t i = 0; i < n; ++i) {
        std::vector<std::string> next;
        for (const auto& p : out)
            for (char c : signs) next.push_back(p + c);
        out = std::move(next);
    }
    return out;
}
std::string text(const std::string& signs) {
    std::string out = "(";
    for (std::size_t i = 0; i < signs.size(); ++i) out += (i ? " " : "") + std::string(1, signs[i]);
    return out + ")";
}

}  // namespace

TEST_CASE("rules/nearness: one rank per motion, Def 38's nearest over the resolutions up to 8.3.4's threshold") {
    std::size_t pairs = 0;
    std::vector<std::size_t> per_rank(4, 0);
    for (std::size_t n = 1; n <= 3; ++n) {
        const auto forces = sign_strings(n, "+0-?");
        const auto motions = sign_strings(n, "+0-");
        std::string facts;
        for (std::size_t i = 0; i < forces.size(); ++i) {
            facts += "fact (resolved-net-force o" + std::to_string(i) + " " + text(forces[i]) + ")\n";
            facts += "fact (resolved-net-torque o" + std::to_string(i) + " " + text(forces[i]) + ")\n";
        }
        for (const auto& x : motions) facts += "fact (translation " + text(x) + ")\nfact (rotation " + text(x) + ")\n";
        Laws l({"nearness.rules"}, facts);
        for (std::size_t i = 0; i < forces.size(); ++i)
            for (const auto& x : motions)
                for (const char* predicate : {"trans-nearness", "rot-nearness"}) {
                    std::vector<int> ranks;
                    for (int k = 0; k <= 5; ++k)
                        if (l.holds(std::string("(") + predicate + " o" + std::to_string(i) + " " + text(x) + " " +
                                    std::to_string(k) + ")"))
                            ranks.push_back(k);
                    const int expected = std::min(oracle_nearness_resolved(forces[i], x), 3);
                    if (ranks != std::vector<int>{expected}) {
                        CAPTURE(predicate);
                        CAPTURE(forces[i]);
                        CAPTURE(x);
                        CHECK(ranks == std::vector<int>{expected});
                    }
                    ++per_rank[static_cast<std::size_t>(expected)];
                    ++pairs;
                }
        // Nothing else is ranked: one fact per pair of each predicate.
        CHECK(l.all("trans-nearness").size() == forces.size() * motions.size());
        CHECK(l.all("rot-nearness").size() == forces.size() * motions.size());
    }
    CHECK(pairs == 2 * (4 * 3 + 16 * 9 + 64 * 27));
    // Every class is met (the oracle is not trivially one rank).
    for (std::size_t k = 0; k < 4; ++k) CHECK(per_rank[k] > 0);
}
