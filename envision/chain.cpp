// envision/chain.cpp: the kinematic chains of Def 22 (scene/kinematic_chains.hpp), their pairs in
// the order 8.2.3 traverses them.
#include "envision/chain.hpp"
#include "qm/assert.hpp"

#include "scene/kinematic_chains.hpp"

#include <algorithm>
#include <deque>

namespace qm::envision {
namespace g = qm::geometry;

std::size_t Chain::object_index(g::PartId p) const {
    const auto it = std::find(objects.begin(), objects.end(), p);
    QM_REQUIRE(it != objects.end(), "part not in the chain");
    return static_cast<std::size_t>(it - objects.begin());
}

std::vector<Chain> kinematic_chains(const g::Mechanism& m, std::span<const bridge::PairPlaces> pairs) {
    std::vector<std::pair<g::PartId, g::PartId>> links;
    for (const auto& p : pairs) links.emplace_back(p.spec.a, p.spec.b);
    for (const auto& l : m.linkages)
        for (std::size_t i = 1; i < l.parts.size(); ++i) links.emplace_back(l.parts[0], l.parts[i]);
    std::vector<std::size_t> component(m.parts.size());
    const auto components = scene::kinematic_chains(m.parts.size(), links);
    for (std::size_t c = 0; c < components.size(); ++c)
        for (const g::PartId p : components[c]) component[p.value] = c;

    std::vector<Chain> chains;
    std::vector<int> chain_of_component(m.parts.size(), -1);
    std::vector<bool> placed(pairs.size(), false);
    for (std::size_t first = 0; first < pairs.size(); ++first) {
        if (placed[first]) continue;
        const std::size_t c = component[pairs[first].spec.a.value];
        QM_ASSERT(chain_of_component[c] < 0, "a component's first pair is met once");
        chain_of_component[c] = static_cast<int>(chains.size());
        Chain chain;
        chain.index = chains.size();
        auto add_object = [&](g::PartId p) {
            auto add = [&](g::PartId x) {
                if (std::find(chain.objects.begin(), chain.objects.end(), x) == chain.objects.end()) chain.objects.push_back(x);
            };
            add(p);
            if (const auto s = m.shaft_of(p))
                for (const g::PartId mate : m.linkages[*s].parts) add(mate);
        };
        // The chain's pairs, breadth-first over pairs that share a part or a shaft (8.2.3).
        std::deque<std::size_t> queue{first};
        placed[first] = true;
        while (!queue.empty()) {
            const std::size_t k = queue.front();
            queue.pop_front();
            chain.pairs.push_back(k);
            add_object(pairs[k].spec.a);
            add_object(pairs[k].spec.b);
            for (std::size_t j = 0; j < pairs.size(); ++j) {
                if (placed[j] || component[pairs[j].spec.a.value] != c) continue;
                const auto& x = pairs[k].spec;
                const auto& y = pairs[j].spec;
                if (m.same_shaft(x.a, y.a) || m.same_shaft(x.a, y.b) || m.same_shaft(x.b, y.a) || m.same_shaft(x.b, y.b)) {
                    placed[j] = true;
                    queue.push_back(j);
                }
            }
        }
        QM_ASSERT(std::none_of(pairs.begin(), pairs.end(), [&](const bridge::PairPlaces& p) {
                      return component[p.spec.a.value] == c && !placed[static_cast<std::size_t>(&p - pairs.data())];
                  }),
                  "the pairs of a chain are reached along shared parts and shafts");
        chains.push_back(std::move(chain));
    }
    return chains;
}

}  // namespace qm::envision
