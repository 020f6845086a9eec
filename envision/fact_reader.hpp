// envision/fact_reader.hpp
// Provides:   FactReader, the driver's reading of conclusions back from an engine: the facts of a
//             predicate that hold in an environment (or unconditionally), with their arguments
//             decoded as symbols, integers, signs and pair directions.
// Ownership:  refers to an engine it does not own, for the duration of a reading.
// Errors:     a conclusion of the wrong shape (the laws and the driver disagree on a predicate's
//             arguments) is an InternalError naming the fact.
#pragma once
#include "engine/engine.hpp"
#include "geometry/qualitative_sign.hpp"
#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>

namespace qm::envision {

class FactReader {
public:
    // env: read the facts that hold there; nullopt: the facts that hold in every environment.
    FactReader(engine::Engine& e, std::optional<atms::EnvId> env) : e_(e), env_(env) {}
    // Calls f(args) for each fact of `predicate` with `arity` arguments that holds.
    void each(const char* predicate, std::size_t arity, const std::function<void(std::span<const engine::ValueId>)>& f) const;
    [[nodiscard]] const std::string& symbol(engine::ValueId v) const;
    [[nodiscard]] std::int64_t integer(engine::ValueId v) const;
    // A one-component direction: -1, 0, +1, or ambiguous_sign for (?).
    [[nodiscard]] std::int8_t sign(engine::ValueId v) const;
    // A two-component definite direction.
    [[nodiscard]] geometry::QualDirection direction(engine::ValueId v) const;

private:
    [[noreturn]] void bad(engine::ValueId v, const char* expected) const;
    engine::Engine& e_;
    std::optional<atms::EnvId> env_;
};

}  // namespace qm::envision
