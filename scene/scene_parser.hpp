// scene/scene_parser.hpp
// Provides:   the reader for Alex scenes (thesis Figure 6.1; grammar in docs/SCENE_FORMAT.md):
//             parse_scene_ast (text -> raw AST, either notation), read_scene (parse + check ->
//             Scene), and the two command-line forms: parse_given (`--given 'obj trans rot'`) and
//             parse_query_fact (`--why` / `--without`: `Rotational-Motion (follower (-))`,
//             `Translational-Freedom (block (0 +))`, `Contact a b`, `Force obj`).
// Ownership:  results are values owned by the caller; the SourceText must outlive nothing.
// Errors:     bad input never throws: every problem goes into `diags` as a located error
//             (`file:line:col: error: expected ... but found ...`, with the source line for the
//             caret) and the result is empty. A syntax error stops the parse (one per input);
//             semantic checks report every error they find.
// Knows nothing of the ATMS, the rule engine or geometry. The grammar itself lives in
// scene_parser_def.hpp and is instantiated once, in scene_parser.cpp.
#pragma once
#include "scene/scene.hpp"
#include "scene/scene_ast.hpp"
#include "qm/diagnostics.hpp"
#include <optional>
#include <string>
#include <string_view>

namespace qm::scene {

struct ParsedScene {
    ast::Scenario scenario;
    PositionTable positions;  // locates the nodes of `scenario` in the SourceText parsed
};

// Parses either notation (a file whose first token is '(' is s-expression notation; after a
// `Name dims` header, sections whose keyword is followed by '(' are too, as in Figures 7.2 and
// 7.8), with the figures' and the BNF's own spellings (docs/SCENE_FORMAT.md).
[[nodiscard]] std::optional<ParsedScene> parse_scene_ast(const SourceText& src, Diagnostics& diags);

// Parses and checks a scene. `file` names the input in diagnostics.
[[nodiscard]] std::optional<Scene> read_scene(std::string file, std::string text, Diagnostics& diags);

// Reads the file at `path` (an unreadable file is an error in diags) and calls read_scene.
[[nodiscard]] std::optional<Scene> read_scene_file(const std::string& path, Diagnostics& diags);

// `obj trans rot`, e.g. `pallet (0 0) (+)`: a motion given as current, checked against `scene`.
// `origin` names the input in diagnostics (column = position in `text`).
[[nodiscard]] std::optional<Motion> parse_given(const Scene& scene, std::string_view text, Diagnostics& diags,
                                                std::string origin = "--given");

// One fact: `<Predicate> [(] <args> [)]` with Predicate one of Translational-Motion,
// Rotational-Motion, Translational-Freedom, Rotational-Freedom (args: object direction),
// Contact (args: two surfaces), Force (args: an object). Case-insensitive, checked against `scene`.
[[nodiscard]] std::optional<QueryFact> parse_query_fact(const Scene& scene, std::string_view text,
                                                        Diagnostics& diags, std::string origin = "--why");

}  // namespace qm::scene
