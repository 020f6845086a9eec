// engine/agenda.cpp
#include "engine/agenda.hpp"
#include "qm/assert.hpp"
#include <limits>

namespace qm::engine {

std::size_t Agenda::KeyHash::operator()(const std::vector<std::uint32_t>& k) const noexcept {
    std::size_t h = 0xcbf29ce484222325ULL;
    for (std::uint32_t x : k) h = (h ^ x) * 0x100000001b3ULL;
    return h;
}

bool Agenda::push(RuleInstance instance, bool urgent) {
    constexpr std::uint32_t unbound = std::numeric_limits<std::uint32_t>::max();
    std::vector<std::uint32_t> key;
    key.reserve(instance.binding.size() + 2);
    key.push_back(instance.rule.value);
    key.push_back(instance.context ? *instance.context : unbound);
    for (const auto& v : instance.binding) key.push_back(v ? v->value : unbound);
    if (!seen_.insert(std::move(key)).second) return false;
    (urgent ? urgent_ : queue_).push_back(std::move(instance));
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
