// tests/support/spelling_test.cpp: support/qm/spelling.hpp - edit_distance() against a plain
// recursive definition of the optimal string alignment distance on seeded random short words, and
// nearest_spelling()'s documented tolerance on the slips the messages are for.
#include "qm/spelling.hpp"
#include <doctest/doctest.h>
#include <random>
#include <string>
#include <vector>

namespace {

// Optimal string alignment, straight from its recursive definition (exponential: short words only).
std::size_t osa(const std::string& a, const std::string& b, std::size_t i, std::size_t j) {
    if (i == 0) return j;
    if (j == 0) return i;
    std::size_t best = std::min({osa(a, b, i - 1, j) + 1, osa(a, b, i, j - 1) + 1,
                                 osa(a, b, i - 1, j - 1) + (a[i - 1] == b[j - 1] ? 0 : 1)});
    if (i > 1 && j > 1 && a[i - 1] == b[j - 2] && a[i - 2] == b[j - 1]) best = std::min(best, osa(a, b, i - 2, j - 2) + 1);
    return best;
}

}  // namespace

TEST_CASE("support/spelling: edit_distance is the optimal string alignment distance") {
    std::mt19937 rng(17);
    std::uniform_int_distribution<int> length(0, 6), letter(0, 2);
    for (int k = 0; k < 2000; ++k) {
        std::string a, b;
        for (int n = length(rng); n > 0; --n) a += static_cast<char>('a' + letter(rng));
        for (int n = length(rng); n > 0; --n) b += static_cast<char>('a' + letter(rng));
        CAPTURE(a);
        CAPTURE(b);
        CHECK(qm::edit_distance(a, b) == osa(a, b, a.size(), b.size()));
        CHECK(qm::edit_distance(a, b) == qm::edit_distance(b, a));
    }
    CHECK(qm::edit_distance("surfce", "surface") == 1);
    CHECK(qm::edit_distance("motoins", "motions") == 1);  // a swap of neighbours is one edit
}

TEST_CASE("support/spelling: nearest_spelling proposes only a slip of the hand") {
    const std::vector<std::string> predicates = {"surface", "surface-normal", "open-half-plane", "touch", "<"};
    CHECK(qm::nearest_spelling("surfce", predicates) == "surface");
    CHECK(qm::nearest_spelling("open-half-plain", predicates) == "open-half-plane");
    CHECK(qm::nearest_spelling("surface", predicates) == std::nullopt);  // an exact match is not proposed
    CHECK(qm::nearest_spelling("contact", predicates) == std::nullopt);  // too far
    CHECK(qm::nearest_spelling("n", predicates) == std::nullopt);        // nothing in common with '<'
    CHECK(qm::nearest_spelling("tuch", predicates) == "touch");
    CHECK(qm::did_you_mean("surfce", predicates) == "; did you mean 'surface'?");
    CHECK(qm::did_you_mean("xyz", predicates).empty());
}

TEST_CASE("support/spelling: nearest_keyword also takes a keyword's verb for its noun") {
    const std::vector<std::string> items = {"polygon", "circle", "rotation", "translation", "turn", "at"};
    CHECK(qm::nearest_keyword("polygn", items) == "polygon");          // a slip of the hand, as nearest_spelling
    CHECK(qm::nearest_keyword("rotate", items) == "rotation");         // three edits, but the verb of the noun
    CHECK(qm::nearest_keyword("translate", items) == "translation");
    CHECK(qm::nearest_spelling("rotate", items) == std::nullopt);      // beyond a slip's tolerance
    CHECK(qm::nearest_keyword("circles", items) == "circle");
    CHECK(qm::nearest_keyword("rota", items) == std::nullopt);         // too short a stem to guess from
    CHECK(qm::nearest_keyword("sprocket", items) == std::nullopt);
    const std::vector<std::string> two = {"translation-x", "translation-y"};
    CHECK(qm::nearest_keyword("translate", two) == std::nullopt);      // two candidates of the stem: no guess
}
