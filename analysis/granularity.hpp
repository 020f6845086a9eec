// analysis/granularity.hpp
// Provides:   Granularity, how finely an analysis splits each situation into ATMS assumptions.
//             `item`: every contact, force and given motion is its own assumption, so labels name
//             the items a conclusion rests on (minimal responsible sets) and a what-if reuses the
//             labels of the monotonic laws. `situation`: one assumption per situation, whose items
//             hold wherever it does; labels stay small however many alternative supports a
//             conclusion has (a tall stack of blocks has a linear number per constraint, each as
//             large as the stack), at the price of recomputing for what-ifs and explanations.
#pragma once
#include <cstdint>

namespace qm::analysis {
enum class Granularity : std::uint8_t { item, situation };
}
