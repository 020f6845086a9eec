// atms/environment_table.cpp: interning, union memo and the per-assumption index.
#include "atms/environment_table.hpp"

#include "qm/assert.hpp"
#include "qm/limit_reached.hpp"
#include <utility>

namespace qm::atms {
EnvId EnvironmentTable::intern(const Environment& e, const NogoodDatabase& nogoods) {
    if (auto it = index_.find(e); it != index_.end()) return it->second;
    return add(e, nogoods.subsumes(e));
}

EnvId EnvironmentTable::intern_consistent(const Environment& e, const NogoodDatabase& nogoods) {
    QM_ASSERT(!nogoods.subsumes(e), "intern_consistent: the environment is nogood");
    (void)nogoods;
    if (auto it = index_.find(e); it != index_.end()) return it->second;
    return add(e, false);
}

EnvId EnvironmentTable::add(const Environment& e, bool nogood) {
    if (limit_ && envs_.size() >= *limit_) throw LimitReached(LimitReached::Kind::environments, *limit_);
    Entry entry;
    entry.env = e;
    entry.count = e.size();
    entry.nogood = nogood;
    const EnvId id = envs_.push_back(std::move(entry));
    index_.emplace(e, id);
    for (AssumptionId a : e.assumptions()) {
        if (by_assumption_.size() <= a.value) by_assumption_.resize(a.value + 1);
        by_assumption_[a.value].push_back(id);
    }
    return id;
}

EnvId EnvironmentTable::join(EnvId x, EnvId y, const NogoodDatabase& nogoods) {
    QM_REQUIRE(contains(x) && contains(y), "unknown environment id");
    if (x == y) return x;
    if (subset(x, y)) return y;
    if (subset(y, x)) return x;
    const std::uint64_t key = x < y ? (std::uint64_t{x.value} << 32) | y.value
                                    : (std::uint64_t{y.value} << 32) | x.value;
    if (auto it = joins_.find(key); it != joins_.end()) return it->second;
    const EnvId id = intern(atms::join(envs_[x].env, envs_[y].env), nogoods);
    joins_.emplace(key, id);
    return id;
}

bool EnvironmentTable::subset(EnvId x, EnvId y) const {
    if (x == y) return true;
    const Entry& a = envs_[x];
    const Entry& b = envs_[y];
    return a.count <= b.count && a.env.subset_of(b.env);
}

const std::vector<EnvId>& EnvironmentTable::containing(AssumptionId a) const {
    return a.value < by_assumption_.size() ? by_assumption_[a.value] : none_;
}
}  // namespace qm::atms
