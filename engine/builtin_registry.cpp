// engine/builtin_registry.cpp
#include "engine/builtin_registry.hpp"
#include "engine/builtins_comparison.hpp"
#include "engine/builtins_integer.hpp"
#include "engine/builtins_qualitative.hpp"
#include "qm/assert.hpp"

namespace qm::engine {

BuiltinId BuiltinRegistry::add(std::string name, BuiltinKind kind, std::uint32_t min_arity,
                               std::uint32_t max_arity, BuiltinFn fn) {
    QM_REQUIRE(!by_name_.contains(name), "builtin registered twice: " + name);
    QM_REQUIRE(min_arity <= max_arity, "builtin arity range is empty: " + name);
    BuiltinId id = builtins_.push_back(Builtin{name, kind, min_arity, max_arity, std::move(fn)});
    by_name_.emplace(std::move(name), id);
    return id;
}

std::optional<BuiltinId> BuiltinRegistry::find(std::string_view name) const {
    auto it = by_name_.find(std::string(name));
    if (it == by_name_.end()) return std::nullopt;
    return it->second;
}

const Builtin& BuiltinRegistry::get(BuiltinId id) const {
    QM_REQUIRE(builtins_.contains(id), "builtin id out of range");
    return builtins_[id];
}

BuiltinResult BuiltinRegistry::apply(BuiltinId id, ValueTable& values, std::span<const ValueId> args) const {
    const Builtin& b = get(id);
    QM_REQUIRE(args.size() >= b.min_arity && args.size() <= b.max_arity, "wrong arity for builtin " + b.name);
    // Builtins are pure: remember each application (keyed by this registry's entry).
    const auto key = reinterpret_cast<std::uintptr_t>(&b);
    if (const ValueTable::Application* known = values.remembered(key, args))
        return BuiltinResult{known->value, known->holds, known->error};
    BuiltinResult r = b.fn(values, args);
    if (r.value && values.print(*r.value).size() > max_value_text)
        r = BuiltinResult::fail("'" + b.name + "' would make a value of " + std::to_string(values.print(*r.value).size()) +
                                " characters, more than the " + std::to_string(max_value_text) + " a value may have");
    values.remember(key, args, {r.value, r.holds, r.error});
    return r;
}

const BuiltinRegistry& default_builtins() {
    static const BuiltinRegistry registry = [] {
        BuiltinRegistry r;
        register_comparison_builtins(r);
        register_integer_builtins(r);
        register_qualitative_builtins(r);
        return r;
    }();
    return registry;
}

}  // namespace qm::engine
