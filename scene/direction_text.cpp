// scene/direction_text.cpp
#include "scene/direction_text.hpp"
#include "qm/assert.hpp"
#include <algorithm>

namespace qm::scene {
namespace {
int rank(Sign s) { return s == Sign::plus ? 0 : s == Sign::zero ? 1 : 2; }
}  // namespace

std::string thesis_text(const Direction& d) {
    std::string out = "(";
    for (std::size_t i = 0; i < d.size(); ++i) {
        if (i) out += ' ';
        out += sign_char(d[i]);
    }
    return out + ")";
}

std::string sign_string(const Direction& d) {
    std::string out;
    for (Sign s : d) out += sign_char(s);
    return out;
}

Direction from_sign_string(std::string_view s) {
    Direction d;
    for (char c : s) {
        QM_REQUIRE(c == '+' || c == '0' || c == '-', "a definite sign");
        d.push_back(c == '+' ? Sign::plus : c == '-' ? Sign::minus : Sign::zero);
    }
    return d;
}

std::vector<Direction> all_directions(std::size_t n) {
    std::vector<Direction> out{Direction{}};
    for (std::size_t i = 0; i < n; ++i) {
        std::vector<Direction> next;
        for (const auto& p : out)
            for (Sign s : {Sign::plus, Sign::zero, Sign::minus}) {
                Direction d = p;
                d.push_back(s);
                next.push_back(std::move(d));
            }
        out = std::move(next);
    }
    return out;
}

bool canonical_less(const Direction& a, const Direction& b) {
    return std::lexicographical_compare(a.begin(), a.end(), b.begin(), b.end(),
                                        [](Sign x, Sign y) { return rank(x) < rank(y); });
}

bool is_zero(const Direction& d) {
    return std::all_of(d.begin(), d.end(), [](Sign s) { return s == Sign::zero; });
}
}  // namespace qm::scene
