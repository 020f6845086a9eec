// atms/environment_table.cpp: interning, union memo and the per-assumption index.
#include "atms/environment_table.hpp"

#include "qm/assert.hpp"
#include "qm/limit_reached.hpp"
#include <bit>
#include <utility>

namespace qm::atms {
EnvId EnvironmentTable::intern(const Environment& e, const NogoodDatabase& nogoods) {
    const std::size_t h = e.hash();
    if (auto id = find(e, h)) return *id;
    return add(e, h, nogoods.subsumes(e));
}

EnvId EnvironmentTable::intern_consistent(const Environment& e, const NogoodDatabase& nogoods) {
    QM_ASSERT(!nogoods.subsumes(e), "intern_consistent: the environment is nogood");
    (void)nogoods;
    const std::size_t h = e.hash();
    if (auto id = find(e, h)) return *id;
    return add(e, h, false);
}

std::optional<EnvId> EnvironmentTable::find(const Environment& e, std::size_t hash) const noexcept {
    if (slots_.empty()) return std::nullopt;
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = hash & mask; slots_[i] != 0; i = (i + 1) & mask) {
        const EnvId id{slots_[i] - 1};
        const Entry& entry = envs_[id];
        if (entry.hash == hash && entry.env == e) return id;
    }
    return std::nullopt;
}

void EnvironmentTable::grow() {
    slots_.assign(slots_.empty() ? 64 : slots_.size() * 2, 0);
    const std::size_t mask = slots_.size() - 1;
    for (std::uint32_t v = 0; v < envs_.size(); ++v) {
        std::size_t i = envs_[EnvId{v}].hash & mask;
        while (slots_[i] != 0) i = (i + 1) & mask;
        slots_[i] = v + 1;
    }
}

EnvId EnvironmentTable::add(const Environment& e, std::size_t hash, bool nogood) {
    if (limit_ && envs_.size() >= *limit_) throw LimitReached(LimitReached::Kind::environments, *limit_);
    Entry entry;
    entry.env = e;
    entry.hash = hash;
    for (std::uint64_t w : e.words()) entry.sig |= w;
    entry.count = e.size();
    entry.nogood = nogood;
    const EnvId id = envs_.push_back(std::move(entry));
    // At most half full, so probes stay short.
    if (2 * envs_.size() > slots_.size()) {
        grow();  // places the new id too
    } else {
        const std::size_t mask = slots_.size() - 1;
        std::size_t i = hash & mask;
        while (slots_[i] != 0) i = (i + 1) & mask;
        slots_[i] = id.value + 1;
    }
    for (std::size_t w = 0; w < e.words().size(); ++w)
        for (std::uint64_t bits = e.words()[w]; bits != 0; bits &= bits - 1) {
            const auto a = static_cast<std::size_t>(std::size_t{e.index()[w]} * 64 + static_cast<std::size_t>(std::countr_zero(bits)));
            if (by_assumption_.size() <= a) by_assumption_.resize(a + 1);
            by_assumption_[a].push_back(id);
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
    return a.count <= b.count && (a.sig & ~b.sig) == 0 && a.env.subset_of(b.env);
}

const std::vector<EnvId>& EnvironmentTable::containing(AssumptionId a) const {
    return a.value < by_assumption_.size() ? by_assumption_[a.value] : none_;
}
}  // namespace qm::atms
