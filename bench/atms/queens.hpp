// bench/atms/queens.hpp: N-queens on the ATMS (one choice set per row, assumption = column,
// pairwise nogoods for attacking squares) and the plain bitmask backtracking counter that is its
// floor; shared by atms_bench (the recorded tables) and atms_gbench (Google Benchmark runs).
#pragma once
#include "atms/atms.hpp"
#include <cstdint>
#include <cstdlib>
#include <vector>

namespace qm::atms::bench {

struct Queens {
    Atms atms;
    std::vector<std::vector<AssumptionId>> rows;
    explicit Queens(int n) : rows(static_cast<std::size_t>(n)) {
        std::vector<NodeId> node(static_cast<std::size_t>(n * n));
        for (int r = 0; r < n; ++r)
            for (int c = 0; c < n; ++c) {
                const NodeId q = atms.add_assumption(DatumId{static_cast<std::uint32_t>(r * n + c)});
                node[static_cast<std::size_t>(r * n + c)] = q;
                rows[static_cast<std::size_t>(r)].push_back(*atms.assumption_of(q));
            }
        for (int r1 = 0; r1 < n; ++r1)
            for (int c1 = 0; c1 < n; ++c1)
                for (int r2 = r1 + 1; r2 < n; ++r2)
                    for (int c2 = 0; c2 < n; ++c2)
                        if (c1 == c2 || std::abs(r1 - r2) == std::abs(c1 - c2))
                            atms.add_nogood(InformantId{0}, {node[static_cast<std::size_t>(r1 * n + c1)],
                                                             node[static_cast<std::size_t>(r2 * n + c2)]});
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
