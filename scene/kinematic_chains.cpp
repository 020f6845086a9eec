// scene/kinematic_chains.cpp: Definition 22 with Boost.Graph's connected components.
#include "scene/kinematic_chains.hpp"
#include "qm/assert.hpp"
#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/connected_components.hpp>
#include <map>

namespace qm::scene {

std::vector<std::vector<std::uint32_t>> kinematic_chains(std::size_t count, std::span<const std::pair<std::uint32_t, std::uint32_t>> links) {
    using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
    Graph g(count);
    for (const auto& [a, b] : links) {
        QM_REQUIRE(a < count && b < count, "object id out of range");
        boost::add_edge(a, b, g);
    }
    std::vector<int> component(count);
    boost::connected_components(g, component.data());
    // Renumber components by their first (smallest) object, so the order is deterministic.
    std::map<int, std::size_t> index;
    std::vector<std::vector<std::uint32_t>> chains;
    for (std::uint32_t v = 0; v < count; ++v) {
        auto [it, fresh] = index.try_emplace(component[v], chains.size());
        if (fresh) chains.emplace_back();
        chains[it->second].push_back(v);
    }
    return chains;
}

}  // namespace qm::scene
