// engine/agenda.cpp
#include "engine/agenda.hpp"
#include "qm/assert.hpp"
#include <algorithm>
#include <cstring>
#include <limits>

namespace qm::engine {

namespace {
constexpr std::uint32_t unbound = std::numeric_limits<std::uint32_t>::max();
// A state's engine queues a few hundred instances: start near that size rather than grow five times.
constexpr std::size_t initial_agenda_slots = 256;

std::uint32_t key_hash(std::span<const std::uint32_t> key) noexcept {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (std::uint32_t x : key) h = (h ^ x) * 0x100000001b3ULL;
    h ^= h >> 33;
    h *= 0xff51afd7ed558ccdULL;
    h ^= h >> 33;
    return static_cast<std::uint32_t>(h);
}
}  // namespace

bool Agenda::insert(RuleId rule, const Binding& binding, std::optional<std::uint32_t> context) {
    // The candidate key is appended to the pool first and dropped again if it is a repeat.
    const std::size_t offset = words_.size();
    words_.push_back(rule.value);
    words_.push_back(context ? *context : unbound);
    for (const auto& v : binding) words_.push_back(v ? v->value : unbound);
    const std::span<const std::uint32_t> key(words_.data() + offset, words_.size() - offset);
    const std::uint32_t h = key_hash(key);
    if (!slots_.empty()) {
        const std::size_t mask = slots_.size() - 1;
        for (std::size_t i = h & mask; slots_[i] != 0; i = (i + 1) & mask) {
            const Key& k = keys_[slots_[i] - 1];
            if (k.hash == h && k.size == key.size() &&
                std::memcmp(words_.data() + k.offset, key.data(), key.size() * sizeof(std::uint32_t)) == 0) {
                words_.resize(offset);
                return false;
            }
        }
    }
    if ((keys_.size() + 1) * 2 > slots_.size()) grow();  // at most half full
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = h & mask;
    while (slots_[i] != 0) i = (i + 1) & mask;
    keys_.push_back(Key{static_cast<std::uint32_t>(offset), static_cast<std::uint32_t>(key.size()), h});
    slots_[i] = static_cast<std::uint32_t>(keys_.size());
    return true;
}

void Agenda::grow() {
    const std::size_t size = std::max(initial_agenda_slots, slots_.size() * 2);
    std::vector<std::uint32_t> slots(size, 0);
    for (std::size_t k = 0; k < keys_.size(); ++k) {
        std::size_t i = keys_[k].hash & (size - 1);
        while (slots[i] != 0) i = (i + 1) & (size - 1);
        slots[i] = static_cast<std::uint32_t>(k + 1);
    }
    slots_ = std::move(slots);
    keys_.reserve(size / 2);  // enough until the next growth
    if (words_.capacity() < size * 4) words_.reserve(size * 4);
}

bool Agenda::push(RuleInstance instance, bool urgent) {
    if (!insert(instance.rule, instance.binding, instance.context)) return false;
    (urgent ? urgent_ : queue_).push_back(std::move(instance));
    return true;
}

bool Agenda::push(RuleId rule, const Binding& binding, std::span<const FactId> antecedents, std::optional<std::uint32_t> context,
                  bool urgent) {
    if (!insert(rule, binding, context)) return false;
    (urgent ? urgent_ : queue_).push_back(RuleInstance{rule, binding, std::vector<FactId>(antecedents.begin(), antecedents.end()), context});
    return true;
}

RuleInstance Agenda::pop() {
    QM_REQUIRE(!empty(), "pop from an empty agenda");
    auto& from = urgent_.empty() ? queue_ : urgent_;
    RuleInstance r = std::move(from.front());
    from.pop_front();
    return r;
}

}  // namespace qm::engine
