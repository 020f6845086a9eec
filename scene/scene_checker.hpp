// scene/scene_checker.hpp
// Provides:   the semantic checks that turn a raw AST (scene/scene_ast.hpp) into a checked Scene
//             (scene/scene.hpp): section multiplicity, declared and unique names, surface ownership,
//             sign tokens and direction arity (2-D/3-D, Table 2.1), variables only in constraints,
//             contacts between surfaces of two different objects, forces' causes, corners (two
//             different faces of their own object, Def 18) and linkages (two different declared
//             objects, each pair once; Def 21). Also the checks
//             of a `--given` motion and of a query fact against an already checked Scene.
// Ownership:  pure functions; the result is a value owned by the caller.
// Errors:     every problem found is reported into `diags` (located via the PositionTable filled
//             by the same parse, with the source line for the caret); the result is empty when
//             any error was found. Never throws on bad input.
// Knows nothing of X3 (only its AST), the ATMS, the engine or geometry.
#pragma once
#include "scene/scene.hpp"
#include "scene/scene_ast.hpp"
#include "qm/diagnostics.hpp"
#include <optional>

namespace qm::scene {

[[nodiscard]] std::optional<Scene> check_scene(const ast::Scenario& scenario, const PositionTable& positions,
                                               const SourceText& src, Diagnostics& diags);

[[nodiscard]] std::optional<Motion> check_given(const ast::MotionEntry& given, const Scene& scene,
                                                const PositionTable& positions, const SourceText& src,
                                                Diagnostics& diags);

[[nodiscard]] std::optional<QueryFact> check_query(const ast::QueryFact& fact, const Scene& scene,
                                                   const PositionTable& positions, const SourceText& src,
                                                   Diagnostics& diags);

}  // namespace qm::scene
