// atms/choice_set_groups.cpp: union-find over members and choice sets, joined by the label
// environments of the members' nodes and by stated nogoods.
#include "atms/choice_set_groups.hpp"

#include "qm/assert.hpp"
#include <algorithm>
#include <numeric>

namespace qm::atms {
namespace {

struct UnionFind {
    explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
    std::size_t find(std::size_t x) {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void join(std::size_t a, std::size_t b) { parent[find(a)] = find(b); }
    std::vector<std::size_t> parent;
};

// The sets of the assumptions of e outside base, distinct, ascending; nullopt if one of them is in
// no set.
std::optional<std::vector<std::uint32_t>> sets_beyond(const ChoiceSetIndex& index, const Environment& e,
                                                      const Environment& base) {
    std::vector<std::uint32_t> out;
    for (AssumptionId a : e.assumptions()) {
        if (base.contains(a)) continue;
        auto s = index.of(a);
        if (!s) return std::nullopt;
        out.push_back(*s);
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace

ChoiceSetIndex index_choice_sets(std::vector<std::vector<AssumptionId>> sets) {
    ChoiceSetIndex out;
    out.sets = std::move(sets);
    for (std::uint32_t index = 0; index < out.sets.size(); ++index)
        for (AssumptionId a : out.sets[index]) {
            if (out.set_of.size() <= a.value) out.set_of.resize(a.value + 1);
            QM_REQUIRE(!out.set_of[a.value], "no assumption is in two choice sets");
            out.set_of[a.value] = index;
        }
    return out;
}

std::vector<ChoiceSetGroup> group_by_shared_nogoods(const Atms& atms, const ChoiceSetIndex& index, EnvId base,
                                                    std::span<const std::vector<NodeId>> members) {
    const std::size_t n = members.size(), sets = index.sets.size();
    // Elements 0..n-1 are members, n.. are sets.
    UnionFind uf(n + sets);
    std::vector<bool> reached(sets, false);
    const Environment& world = atms.env(base);
    if (!index.empty()) {
        for (std::size_t c = 0; c < n; ++c)
            for (NodeId node : members[c])
                for (EnvId l : atms.label(node))
                    if (auto part = sets_beyond(index, atms.env(l), world))
                        for (std::uint32_t s : *part) {
                            uf.join(c, n + s);
                            reached[s] = true;
                        }
        // Sets that a nogood couples: their choices are not independent. (The pairs of a choice
        // set's own at-most-one constraint lie within one set: they couple nothing.)
        if (std::any_of(reached.begin(), reached.end(), [](bool r) { return r; }))
            for (EnvId ng : atms.stated_nogoods())
                if (auto part = sets_beyond(index, atms.env(ng), world); part && part->size() > 1)
                    for (std::size_t i = 1; i < part->size(); ++i) uf.join(n + (*part)[0], n + (*part)[i]);
    }
    std::vector<ChoiceSetGroup> out;
    std::vector<std::optional<std::size_t>> group_of(n + sets);
    for (std::size_t c = 0; c < n; ++c) {
        auto& g = group_of[uf.find(c)];
        if (!g) {
            g = out.size();
            out.emplace_back();
        }
        out[*g].members.push_back(c);
    }
    for (std::size_t s = 0; s < sets; ++s)
        if (auto g = group_of[uf.find(n + s)]) out[*g].sets.push_back(static_cast<std::uint32_t>(s));
    return out;
}

}  // namespace qm::atms
