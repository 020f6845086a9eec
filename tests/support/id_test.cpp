#include "qm/id.hpp"
#include <doctest/doctest.h>
#include <type_traits>

namespace {
using AId = qm::Id<struct ATag>;
using BId = qm::Id<struct BTag>;
}  // namespace

static_assert(!std::is_convertible_v<AId, BId>, "ids of different tables must not mix");
static_assert(sizeof(AId) == sizeof(std::uint32_t));

TEST_CASE("support/id: IdVector hands out dense ids from 0") {
    qm::IdVector<AId, int> v;
    auto a = v.push_back(7);
    auto b = v.push_back(9);
    CHECK(a.value == 0);
    CHECK(b.value == 1);
    CHECK(v[b] == 9);
    CHECK(v.contains(b));
    CHECK_FALSE(v.contains(AId{2}));
}

TEST_CASE("support/id: out-of-range access is an InternalError in test builds") {
    qm::IdVector<AId, int> v;
    CHECK_THROWS_AS((void)v[AId{0}], qm::InternalError);
}

TEST_CASE("support/assert: QM_REQUIRE throws with the condition text") {
    CHECK_THROWS_WITH_AS(QM_REQUIRE(1 == 2, "numbers"), doctest::Contains("1 == 2"), qm::InternalError);
}
