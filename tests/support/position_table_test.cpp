// tests/support/position_table_test.cpp: a node's tag gives back the offset it was added with,
// below 1 GiB directly and beyond it through the table; an untagged node reads as offset 0.
#include "qm/position_table.hpp"

#include <doctest/doctest.h>
#include <random>

using qm::x3_parse::PositionTable;

namespace {
boost::spirit::x3::position_tagged tagged(int id) {
    boost::spirit::x3::position_tagged n;
    n.id_first = id;
    return n;
}
}  // namespace

TEST_CASE("support/position_table: offsets come back exactly, near and far, in any order") {
    PositionTable t;
    std::mt19937_64 rng(19);
    std::uniform_int_distribution<std::size_t> near(0, PositionTable::direct_limit - 1);
    std::uniform_int_distribution<std::size_t> far(PositionTable::direct_limit, std::size_t{1} << 40);
    std::vector<std::pair<int, std::size_t>> added;
    for (int i = 0; i < 2000; ++i) {
        const std::size_t off = (i % 3 == 0) ? far(rng) : near(rng);
        added.emplace_back(t.add(off), off);
    }
    added.emplace_back(t.add(0), 0);
    added.emplace_back(t.add(PositionTable::direct_limit - 1), PositionTable::direct_limit - 1);
    added.emplace_back(t.add(PositionTable::direct_limit), PositionTable::direct_limit);
    for (const auto& [id, off] : added) {
        CHECK(id >= 0);
        CHECK(t.offset_of(tagged(id)) == off);
    }
}

TEST_CASE("support/position_table: an untagged node or an unknown far tag reads as offset 0") {
    PositionTable t;
    CHECK(t.offset_of(tagged(-1)) == 0);
    CHECK(t.offset_of(boost::spirit::x3::position_tagged{}) == 0);
    CHECK(t.offset_of(tagged(static_cast<int>(PositionTable::direct_limit) + 5)) == 0);
    CHECK(t.add(123) == 123);  // below the limit a tag costs no memory: it is the offset
}
