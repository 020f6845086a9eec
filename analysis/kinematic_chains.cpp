// analysis/kinematic_chains.cpp: Definition 22 with Boost.Graph's connected components.
#include "analysis/kinematic_chains.hpp"
#include "qm/assert.hpp"
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>
#include <map>

namespace qm::analysis {

std::vector<std::vector<ObjectId>> kinematic_chains(std::size_t object_count,
                                                    std::span<const std::pair<ObjectId, ObjectId>> pairs) {
    using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
    Graph g(object_count);
    for (const auto& [a, b] : pairs) {
        QM_REQUIRE(a.value < object_count && b.value < object_count, "object id out of range");
        boost::add_edge(a.value, b.value, g);
    }
    std::vector<int> component(object_count);
    boost::connected_components(g, component.data());
    // Renumber components by their first (smallest) object, so the order is deterministic.
    std::map<int, std::size_t> index;
    std::vector<std::vector<ObjectId>> chains;
    for (std::uint32_t v = 0; v < object_count; ++v) {
        auto [it, fresh] = index.try_emplace(component[v], chains.size());
        if (fresh) chains.emplace_back();
        chains[it->second].push_back(ObjectId{v});
    }
    return chains;
}

}  // namespace qm::analysis
