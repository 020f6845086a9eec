// engine/fact_store.cpp: interning and indexing of facts.
#include "engine/fact_store.hpp"
#include "qm/assert.hpp"

namespace qm::engine {

std::size_t FactStore::KeyHash::operator()(const std::vector<std::uint32_t>& k) const noexcept {
    std::size_t h = 0xcbf29ce484222325ULL;
    for (std::uint32_t x : k) h = (h ^ x) * 0x100000001b3ULL;
    return h;
}

std::vector<std::uint32_t> FactStore::key(ValueId predicate, std::span<const ValueId> args) {
    std::vector<std::uint32_t> k;
    k.reserve(args.size() + 1);
    k.push_back(predicate.value);
    for (ValueId a : args) k.push_back(a.value);
    return k;
}

std::uint64_t FactStore::arg_key(ValueId predicate, std::uint32_t position, ValueId value) {
    // 24 bits of predicate, 8 of position, 32 of value: predicates and arities are small.
    return (static_cast<std::uint64_t>(predicate.value & 0xffffffu) << 40) ^
           (static_cast<std::uint64_t>(position & 0xffu) << 32) ^ value.value;
}

std::pair<FactId, bool> FactStore::intern(ValueId predicate, std::span<const ValueId> args) {
    QM_REQUIRE(predicate.value < (1u << 24) && args.size() < 256, "predicate or arity too large to index");
    auto k = key(predicate, args);
    if (auto it = by_key_.find(k); it != by_key_.end()) return {it->second, false};
    FactId id = facts_.push_back(Fact{predicate, std::vector<ValueId>(args.begin(), args.end())});
    active_.push_back(0);
    by_key_.emplace(std::move(k), id);
    all_by_predicate_[predicate.value].push_back(id);
    for (std::uint32_t i = 0; i < args.size(); ++i) all_by_argument_[arg_key(predicate, i, args[i])].push_back(id);
    return {id, true};
}

std::optional<FactId> FactStore::find(ValueId predicate, std::span<const ValueId> args) const {
    auto it = by_key_.find(key(predicate, args));
    if (it == by_key_.end()) return std::nullopt;
    return it->second;
}

const Fact& FactStore::fact(FactId f) const {
    QM_REQUIRE(facts_.contains(f), "fact id out of range");
    return facts_[f];
}

std::span<const FactId> FactStore::with_predicate(ValueId predicate) const {
    auto it = all_by_predicate_.find(predicate.value);
    if (it == all_by_predicate_.end()) return {};
    return it->second;
}

std::span<const FactId> FactStore::with_argument(ValueId predicate, std::uint32_t position, ValueId value) const {
    auto it = all_by_argument_.find(arg_key(predicate, position, value));
    if (it == all_by_argument_.end()) return {};
    return it->second;
}

bool FactStore::activate(FactId f) {
    QM_REQUIRE(facts_.contains(f), "fact id out of range");
    if (active_[f] != 0) return false;
    active_[f] = 1;
    const Fact& fact = facts_[f];
    active_by_predicate_[fact.predicate.value].push_back(f);
    for (std::uint32_t i = 0; i < fact.args.size(); ++i)
        active_by_argument_[arg_key(fact.predicate, i, fact.args[i])].push_back(f);
    return true;
}

bool FactStore::is_active(FactId f) const {
    QM_REQUIRE(facts_.contains(f), "fact id out of range");
    return active_[f] != 0;
}

std::span<const FactId> FactStore::active_with_predicate(ValueId predicate) const {
    auto it = active_by_predicate_.find(predicate.value);
    if (it == active_by_predicate_.end()) return {};
    return it->second;
}

std::span<const FactId> FactStore::active_with_argument(ValueId predicate, std::uint32_t position,
                                                        ValueId value) const {
    auto it = active_by_argument_.find(arg_key(predicate, position, value));
    if (it == active_by_argument_.end()) return {};
    return it->second;
}

}  // namespace qm::engine
