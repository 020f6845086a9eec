// bench/atms/queens.hpp: N-queens on the ATMS (one choice set per row, assumption = column) and the
// plain bitmask backtracking counter that is its floor; shared by atms_bench (the recorded tables)
// and atms_gbench (Google Benchmark runs). Two encodings of "no two queens attack":
//   pairwise     a nogood for every attacking pair of squares in different rows (504 at N = 8),
//                each added with add_nogood, as a rule program's `false` rules make them;
//   at_most_one  one at-most-one constraint per column and per diagonal (Atms::add_at_most_one, 38
//                at N = 8), the exclusions a bitboard keeps, stated as such.
// Both state the same exclusions (tests/atms/at_most_one_test.cpp checks a constraint against an
// oracle that reads it as its pairs).
#pragma once
#include "atms/atms.hpp"
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace qm::atms::bench {

enum class Encoding { pairwise, at_most_one };

struct Queens {
    Atms atms;
    std::vector<std::vector<AssumptionId>> rows;
    Queens(int n, Encoding encoding) : rows(static_cast<std::size_t>(n)) {
        const auto at = [n](int r, int c) { return static_cast<std::size_t>(r * n + c); };
        std::vector<NodeId> node(static_cast<std::size_t>(n * n));
        for (int r = 0; r < n; ++r)
            for (int c = 0; c < n; ++c) {
                const NodeId q = atms.add_assumption(DatumId{static_cast<std::uint32_t>(r * n + c)});
                node[at(r, c)] = q;
                rows[static_cast<std::size_t>(r)].push_back(*atms.assumption_of(q));
            }
        if (encoding == Encoding::pairwise) {
            for (int r1 = 0; r1 < n; ++r1)
                for (int c1 = 0; c1 < n; ++c1)
                    for (int r2 = r1 + 1; r2 < n; ++r2)
                        for (int c2 = 0; c2 < n; ++c2)
                            if (c1 == c2 || std::abs(r1 - r2) == std::abs(c1 - c2))
                                atms.add_nogood(InformantId{0}, {node[at(r1, c1)], node[at(r2, c2)]});
            return;
        }
        const auto square = [&](int r, int c) { return rows[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)]; };
        std::vector<AssumptionId> line;
        for (int c = 0; c < n; ++c) {  // columns
            line.clear();
            for (int r = 0; r < n; ++r) line.push_back(square(r, c));
            atms.add_at_most_one(InformantId{0}, line);
        }
        for (int d = -(n - 2); d <= n - 2; ++d) {  // diagonals of two or more squares, both ways
            line.clear();
            for (int r = 0; r < n; ++r)
                if (r + d >= 0 && r + d < n) line.push_back(square(r, r + d));
            atms.add_at_most_one(InformantId{0}, line);
            line.clear();
            for (int r = 0; r < n; ++r)
                if (n - 1 - r + d >= 0 && n - 1 - r + d < n) line.push_back(square(r, n - 1 - r + d));
            atms.add_at_most_one(InformantId{0}, line);
        }
    }
};

// The floor: bitmask backtracking.
inline std::size_t queens_plain(int n, int row, std::uint32_t cols, std::uint32_t d1, std::uint32_t d2) {
    if (row == n) return 1;
    std::size_t count = 0;
    std::uint32_t free = ~(cols | d1 | d2) & ((1U << n) - 1);
    while (free != 0) {
        const std::uint32_t bit = free & (~free + 1);
        free ^= bit;
        count += queens_plain(n, row + 1, cols | bit, (d1 | bit) << 1, (d2 | bit) >> 1);
    }
    return count;
}

}  // namespace qm::atms::bench
