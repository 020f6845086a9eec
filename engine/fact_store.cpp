// engine/fact_store.cpp: interning and indexing of facts.
#include "engine/fact_store.hpp"
#include "qm/assert.hpp"
#include <algorithm>

namespace qm::engine {

namespace {
// Spreads a key over the table's low bits (the tables are powers of two).
std::size_t mix(std::uint64_t k) noexcept {
    k ^= k >> 33;
    k *= 0xff51afd7ed558ccdULL;
    k ^= k >> 33;
    return static_cast<std::size_t>(k);
}
// A state's engine holds a few hundred facts in about a thousand lists: start near that size
// rather than rehash five times on the way there.
constexpr std::size_t initial_slots = 512;
// A new list's first block: glibc's smallest chunk holds six ids anyway, and most lists stay short.
constexpr std::size_t initial_list = 6;
}  // namespace

std::span<const FactId> FactStore::Lists::find(std::uint64_t key) const {
    if (slots_.empty()) return {};
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = mix(key) & mask; slots_[i] != 0; i = (i + 1) & mask)
        if (keys_[i] == key) return lists_[slots_[i] - 1];
    return {};
}

void FactStore::Lists::append(std::uint64_t key, FactId f) {
    if ((lists_.size() + 1) * 2 > slots_.size()) grow();  // at most half full
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = mix(key) & mask;
    for (; slots_[i] != 0; i = (i + 1) & mask)
        if (keys_[i] == key) return lists_[slots_[i] - 1].push_back(f);
    auto& list = lists_.emplace_back();
    list.reserve(initial_list);
    list.push_back(f);
    keys_[i] = key;
    slots_[i] = static_cast<std::uint32_t>(lists_.size());
}

void FactStore::Lists::grow() {
    const std::size_t size = std::max(initial_slots, slots_.size() * 2);
    std::vector<std::uint64_t> keys(size);
    std::vector<std::uint32_t> slots(size, 0);
    for (std::size_t j = 0; j < slots_.size(); ++j) {
        if (slots_[j] == 0) continue;
        std::size_t i = mix(keys_[j]) & (size - 1);
        while (slots[i] != 0) i = (i + 1) & (size - 1);
        keys[i] = keys_[j];
        slots[i] = slots_[j];
    }
    keys_ = std::move(keys);
    slots_ = std::move(slots);
    lists_.reserve(size / 2);  // enough until the next growth
}

std::uint64_t FactStore::list_key(ValueId predicate, std::uint32_t position, ValueId value) {
    // 24 bits of predicate, 8 of position, 32 of value: predicates and arities are small.
    return (static_cast<std::uint64_t>(predicate.value & 0xffffffu) << 40) ^
           (static_cast<std::uint64_t>(position & 0xffu) << 32) ^ value.value;
}

std::uint64_t FactStore::predicate_key(ValueId predicate) {
    // Position 255 is no argument's (arities are below 256): a predicate's own list.
    return list_key(predicate, 0xffu, ValueId{0});
}

std::uint32_t FactStore::hash(ValueId predicate, std::span<const ValueId> args) {
    std::uint64_t h = (0xcbf29ce484222325ULL ^ predicate.value) * 0x100000001b3ULL;
    for (ValueId a : args) h = (h ^ a.value) * 0x100000001b3ULL;
    return static_cast<std::uint32_t>(mix(h));
}

std::size_t FactStore::slot_of(ValueId predicate, std::span<const ValueId> args, std::uint32_t h) const {
    const std::size_t mask = by_key_.size() - 1;
    std::size_t i = h & mask;
    for (; by_key_[i] != 0; i = (i + 1) & mask) {
        const FactId f{by_key_[i] - 1};
        if (hash_[f] != h) continue;
        const Fact& fact = facts_[f];
        if (fact.predicate == predicate && std::equal(fact.args.begin(), fact.args.end(), args.begin(), args.end()))
            return i;
    }
    return i;
}

void FactStore::grow_keys() {
    const std::size_t size = std::max(initial_slots, by_key_.size() * 2);
    std::vector<std::uint32_t> slots(size, 0);
    for (std::uint32_t f = 0; f < facts_.size(); ++f) {
        std::size_t i = hash_[FactId{f}] & (size - 1);
        while (slots[i] != 0) i = (i + 1) & (size - 1);
        slots[i] = f + 1;
    }
    by_key_ = std::move(slots);
    facts_.reserve(size / 2);  // enough until the next growth
    active_.reserve(size / 2);
    hash_.reserve(size / 2);
}

void FactStore::index(Lists& lists, FactId f) {
    const Fact& fact = facts_[f];
    lists.append(predicate_key(fact.predicate), f);
    for (std::uint32_t i = 0; i < fact.args.size(); ++i) lists.append(list_key(fact.predicate, i, fact.args[i]), f);
}

std::pair<FactId, bool> FactStore::intern(ValueId predicate, std::span<const ValueId> args) {
    QM_REQUIRE(predicate.value < (1u << 24) && args.size() < 255, "predicate or arity too large to index");
    if ((facts_.size() + 1) * 2 > by_key_.size()) grow_keys();  // at most half full
    const std::uint32_t h = hash(predicate, args);
    const std::size_t slot = slot_of(predicate, args, h);
    if (by_key_[slot] != 0) return {FactId{by_key_[slot] - 1}, false};
    FactId id = facts_.push_back(Fact{predicate, std::vector<ValueId>(args.begin(), args.end())});
    active_.push_back(0);
    hash_.push_back(h);
    by_key_[slot] = id.value + 1;
    index(all_, id);
    return {id, true};
}

std::optional<FactId> FactStore::find(ValueId predicate, std::span<const ValueId> args) const {
    if (by_key_.empty()) return std::nullopt;
    const std::size_t slot = slot_of(predicate, args, hash(predicate, args));
    if (by_key_[slot] == 0) return std::nullopt;
    return FactId{by_key_[slot] - 1};
}

const Fact& FactStore::fact(FactId f) const {
    QM_REQUIRE(facts_.contains(f), "fact id out of range");
    return facts_[f];
}

std::span<const FactId> FactStore::with_predicate(ValueId predicate) const { return all_.find(predicate_key(predicate)); }

std::span<const FactId> FactStore::with_argument(ValueId predicate, std::uint32_t position, ValueId value) const {
    return all_.find(list_key(predicate, position, value));
}

bool FactStore::activate(FactId f) {
    QM_REQUIRE(facts_.contains(f), "fact id out of range");
    if (active_[f] != 0) return false;
    active_[f] = ++active_count_;
    index(active_lists_, f);
    return true;
}

bool FactStore::is_active(FactId f) const {
    QM_REQUIRE(facts_.contains(f), "fact id out of range");
    return active_[f] != 0;
}

std::uint32_t FactStore::activation_rank(FactId f) const {
    QM_REQUIRE(facts_.contains(f) && active_[f] != 0, "an active fact");
    return active_[f] - 1;
}

std::span<const FactId> FactStore::active_with_predicate(ValueId predicate) const {
    return active_lists_.find(predicate_key(predicate));
}

std::span<const FactId> FactStore::active_with_argument(ValueId predicate, std::uint32_t position,
                                                        ValueId value) const {
    return active_lists_.find(list_key(predicate, position, value));
}

}  // namespace qm::engine
