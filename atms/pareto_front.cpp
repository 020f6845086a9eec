// atms/pareto_front.cpp
#include "atms/pareto_front.hpp"
#include "qm/assert.hpp"

namespace qm::atms {

namespace {
// Does x dominate y: no worse anywhere, better somewhere?
template <class Rank>
bool dominates(const std::vector<Rank>& x, const std::vector<Rank>& y) {
    bool better = false;
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (x[i] > y[i]) return false;
        better = better || x[i] < y[i];
    }
    return better;
}

template <class Rank>
std::vector<std::size_t> front(std::span<const std::vector<Rank>> ranks) {
    for (const auto& r : ranks) QM_REQUIRE(r.size() == ranks.front().size(), "rank vectors of different lengths");
    std::vector<std::size_t> out;
    for (std::size_t i = 0; i < ranks.size(); ++i) {
        bool dominated = false;
        for (std::size_t j = 0; j < ranks.size() && !dominated; ++j) dominated = j != i && dominates(ranks[j], ranks[i]);
        if (!dominated) out.push_back(i);
    }
    return out;
}
}  // namespace

std::vector<std::size_t> pareto_front(std::span<const std::vector<int>> ranks) { return front(ranks); }
std::vector<std::size_t> pareto_front(std::span<const std::vector<std::int64_t>> ranks) { return front(ranks); }

}  // namespace qm::atms
