// engine/builtin_registry.hpp
// Provides:   BuiltinRegistry, the runtime implementations of the rule language's builtins: tests
//             (`(open-half-plane ?a ?b)` in a condition) and functions (`(neg ?sn)` in a term; a
//             function that returns a set value is a set generator, as in `[for all ?d in (translations 2) ...]`).
//             default_builtins() holds every builtin the engine offers (builtins_*.hpp register them).
// Ownership:  the registry owns its entries; BuiltinIds stay valid for its lifetime.
// Invariants: names are unique across tests and functions. Builtins are pure: the same arguments
//             always give the same result, so a rule firing can be replayed from its binding.
// Errors:     a builtin applied to values outside its domain (e.g. `neg` of a symbol) reports an error
//             text; the engine turns it into a located diagnostic. It never throws for bad values.
// Knows nothing of the ATMS or of mechanics.
#pragma once
#include "engine/fwd.hpp"
#include "engine/value_table.hpp"
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>

namespace qm::engine {

// The answer of a builtin: a value (functions), a truth (tests), or an error text.
struct BuiltinResult {
    std::optional<ValueId> value;  // functions: the result
    bool holds = false;            // tests: the truth
    std::string error;             // non-empty: the arguments were outside the builtin's domain
    [[nodiscard]] static BuiltinResult of(ValueId v) { return {v, true, {}}; }
    [[nodiscard]] static BuiltinResult truth(bool b) { return {std::nullopt, b, {}}; }
    [[nodiscard]] static BuiltinResult fail(std::string why) { return {std::nullopt, false, std::move(why)}; }
};

using BuiltinFn = std::function<BuiltinResult(ValueTable&, std::span<const ValueId>)>;

enum class BuiltinKind : std::uint8_t { test, function };

struct Builtin {
    std::string name;
    BuiltinKind kind = BuiltinKind::test;
    std::uint32_t min_arity = 0;
    std::uint32_t max_arity = 0;
    BuiltinFn fn;
};

class BuiltinRegistry {
public:
    // Pre: name not yet registered; min_arity <= max_arity.
    BuiltinId add(std::string name, BuiltinKind kind, std::uint32_t min_arity, std::uint32_t max_arity,
                  BuiltinFn fn);
    [[nodiscard]] std::optional<BuiltinId> find(std::string_view name) const;
    [[nodiscard]] const Builtin& get(BuiltinId id) const;  // Pre: id valid
    // Applies builtin id to args. Pre: args.size() within the builtin's arity.
    [[nodiscard]] BuiltinResult apply(BuiltinId id, ValueTable& values, std::span<const ValueId> args) const;
    [[nodiscard]] std::size_t size() const noexcept { return builtins_.size(); }

private:
    IdVector<BuiltinId, Builtin> builtins_;
    std::unordered_map<std::string, BuiltinId> by_name_;
};

// Every builtin of the engine: comparison, integer arithmetic and the qualitative vector maths.
[[nodiscard]] const BuiltinRegistry& default_builtins();
}  // namespace qm::engine
