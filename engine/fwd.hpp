// engine/fwd.hpp
// Provides:   forward declarations of the rule engine's public types, so that headers can name them
//             without including each other (as atms/fwd.hpp does); the ids are complete here and
//             only here.
#pragma once
#include "qm/id.hpp"

namespace qm::engine {
using ValueId = qm::Id<struct ValueTag>;      // a symbol, integer, direction or set (value.hpp)
using FactId = qm::Id<struct FactTag>;        // a fact of the fact store (fact.hpp)
using RuleId = qm::Id<struct RuleTag>;        // a compiled rule (compiled_rule.hpp)
using BuiltinId = qm::Id<struct BuiltinTag>;  // a builtin test or function (builtin_registry.hpp)

struct Value;
class ValueTable;
struct Fact;
class FactStore;
struct Builtin;
class BuiltinRegistry;
struct RuleSpec;
struct ProgramSpec;
struct CompiledRule;
struct CompiledProgram;
struct LoadedProgram;
class SourceTexts;
struct RunOptions;
class Agenda;
class Matcher;
struct ContextRun;
class Engine;
struct RunReport;
struct WhyStep;
struct Derivation;
struct Why;
}  // namespace qm::engine
