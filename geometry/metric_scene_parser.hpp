// geometry/metric_scene_parser.hpp
// Provides:   the reader of metric scenes (docs/METRIC_SCENE_FORMAT.md): parse_mechanism_ast
//             (text -> raw AST, X3), read_mechanism (parse + check -> Mechanism, building every
//             part's profiles from its drawing or generator), read_mechanism_file, and
//             parse_configuration, the CONFIG argument of `qm-atms --emit-def`
//             (`pallets=3.5, scape-wheel=-2`: degrees for rotations, lengths for translations).
// Ownership:  results are values owned by the caller.
// Errors:     bad input never throws: every problem goes into `diags` as a located error
//             (`file:line:col: error: ...` with the source line for the caret) and the result is
//             empty. A syntax error stops the parse (one per input); the checker reports every
//             error it finds.
// Knows nothing of FCL, the ATMS or the engine. The grammar lives in metric_scene_parser_def.hpp,
// instantiated once, in metric_scene_parser.cpp.
#pragma once
#include "geometry/mechanism.hpp"
#include "geometry/metric_scene_ast.hpp"
#include "geometry/metric_source.hpp"
#include "qm/diagnostics.hpp"
#include <optional>
#include <string>
#include <string_view>

namespace qm::geometry {

struct ParsedMechanism {
    mast::MechanismFile file;
    MetricPositions positions;
};

[[nodiscard]] std::optional<ParsedMechanism> parse_mechanism_ast(const MetricSource& src, Diagnostics& diags);
[[nodiscard]] std::optional<Mechanism> read_mechanism(std::string file, std::string text, Diagnostics& diags);
// An unreadable file is an error in diags.
[[nodiscard]] std::optional<Mechanism> read_mechanism_file(const std::string& path, Diagnostics& diags);

// `origin` names the argument in diagnostics (column = position in `text`).
[[nodiscard]] std::optional<Configuration> parse_configuration(const Mechanism& m, std::string_view text, Diagnostics& diags,
                                                               std::string origin = "CONFIG");

}  // namespace qm::geometry
