// engine/value_table.hpp
// Provides:   ValueTable, which interns Values (equal values get the same ValueId), gives them a
//             total order and prints them in the rule language's own notation.
// Ownership:  owns every Value; ids stay valid for the table's lifetime; nothing is removed.
// Invariants: print() is injective on values, so the printed text is the interning key.
// Knows nothing of the ATMS or of rules.
#pragma once
#include "engine/value.hpp"
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

namespace qm::engine {
class ValueTable {
public:
    ValueId symbol(std::string_view name);
    ValueId integer(std::int64_t v);
    // Pre: signs holds only + 0 - ? and is not empty.
    ValueId direction(std::string_view signs);
    // Elements may be in any order and repeat; the stored set is sorted and distinct.
    ValueId set(std::vector<ValueId> elements);

    // Pre (all queries): id issued by this table.
    [[nodiscard]] const Value& value(ValueId id) const;
    [[nodiscard]] const std::string& print(ValueId id) const { return printed_[id]; }
    // Total order: integers (numerically) < symbols < directions < sets, then by content.
    [[nodiscard]] bool less(ValueId a, ValueId b) const;
    [[nodiscard]] std::size_t size() const noexcept { return values_.size(); }

    // A memo of pure function applications on this table's values (builtins are pure,
    // builtin_registry.hpp), so that a rule evaluating `(translations ?n)` for every binding
    // builds the set once. The key is an opaque caller id (the registry and builtin) plus the args.
    struct Application {
        std::optional<ValueId> value;
        bool holds = false;
        std::string error;
    };
    // Applications with more than max_remembered_args arguments are not remembered.
    static constexpr std::size_t max_remembered_args = 3;
    [[nodiscard]] const Application* remembered(std::uintptr_t function, std::span<const ValueId> args) const;
    void remember(std::uintptr_t function, std::span<const ValueId> args, Application result);

private:
    using ApplicationKey = std::array<std::uint64_t, 1 + max_remembered_args / 2 + 1>;
    struct KeyHash {
        std::size_t operator()(const ApplicationKey& k) const noexcept;
    };
    static ApplicationKey application_key(std::uintptr_t function, std::span<const ValueId> args);
    std::unordered_map<ApplicationKey, Application, KeyHash> applications_;
    ValueId intern(Value v);
    [[nodiscard]] std::string render(const Value& v) const;

    IdVector<ValueId, Value> values_;
    IdVector<ValueId, std::string> printed_;
    std::unordered_map<std::string, ValueId> by_text_;
};
}  // namespace qm::engine
