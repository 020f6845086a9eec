// engine/value_table.hpp
// Provides:   ValueTable, which interns Values (equal values get the same ValueId), gives them a
//             total order and prints them in the rule language's own notation.
// Ownership:  owns every Value; ids stay valid for the table's lifetime; nothing is removed. After
//             share(), the values so far are a read-only base shared by the table and its copies
//             (each copy then owns only the values added to it since): copying a program's table
//             for every engine made over it (an engine per state, envision/) costs nothing per value.
// Invariants: print() is injective on values, so the printed text is the interning key.
// Knows nothing of the ATMS or of rules.
#pragma once
#include "engine/value.hpp"
#include <array>
#include <memory>
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
    [[nodiscard]] const std::string& print(ValueId id) const {
        return id.value < base_size_ ? base_->printed[id.value] : printed_[id.value - base_size_];
    }
    // Total order: integers (numerically) < symbols < directions < sets, then by content.
    [[nodiscard]] bool less(ValueId a, ValueId b) const;
    [[nodiscard]] std::size_t size() const noexcept { return base_size_ + values_.size(); }

    // Moves every value (and remembered application) into the base shared with copies made from
    // now on. Ids, printing, order and lookups are unchanged. The base is never written again, so
    // copies may be used in different threads.
    void share();

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
    ValueId intern(Value v);
    [[nodiscard]] std::string render(const Value& v) const;

    // The shared values (ids below base_size_) and those of this table alone (ids from base_size_ on).
    struct Values {
        std::vector<Value> values;
        std::vector<std::string> printed;
        std::unordered_map<std::string, ValueId> by_text;
        std::unordered_map<ApplicationKey, Application, KeyHash> applications;
    };
    std::shared_ptr<const Values> base_;
    std::uint32_t base_size_ = 0;
    std::vector<Value> values_;
    std::vector<std::string> printed_;
    std::unordered_map<std::string, ValueId> by_text_;
    std::unordered_map<ApplicationKey, Application, KeyHash> applications_;
};
}  // namespace qm::engine
