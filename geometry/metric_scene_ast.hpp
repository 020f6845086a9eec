// geometry/metric_scene_ast.hpp
// Provides:   the raw AST of a metric scene file (docs/METRIC_SCENE_FORMAT.md) and of the CONFIG
//             argument, as the X3 grammar (metric_scene_parser_def.hpp) produces them before any
//             check: names as spelled, numbers as read, items in source order. Every item starts
//             with its keyword as written, so that the checker can point at it. Also
//             MetricPositions, which maps a node's position tag to its byte offset.
// Ownership:  plain values. Every node derives from x3::position_tagged.
// Knows nothing of the checked model (mechanism.hpp).
#pragma once
#include "qm/position_table.hpp"
#include <boost/optional.hpp>
#include <boost/spirit/home/x3/support/ast/position_tagged.hpp>
#include <boost/spirit/home/x3/support/ast/variant.hpp>
#include <cstddef>
#include <string>
#include <vector>

namespace qm::geometry {
namespace mast {
namespace x3 = boost::spirit::x3;

struct Name : x3::position_tagged { std::string text; };
struct Number : x3::position_tagged { double value = 0.0; };
struct Point : x3::position_tagged { Number x, y; };

// Shapes drawn by hand.
struct PolygonItem : x3::position_tagged { Name keyword; std::vector<Point> points; };
struct CircleItem : x3::position_tagged { Name keyword; Point centre; Number radius; };
struct LineStep : x3::position_tagged { Name keyword; Number x, y; };
struct ArcStep : x3::position_tagged { Name keyword; Number x, y, cx, cy; Name sense; };
struct Step : x3::variant<LineStep, ArcStep> {
    using base_type::base_type;
    using base_type::operator=;
};
struct ProfileItem : x3::position_tagged { Name keyword; Point start; std::vector<Step> steps; };
// A generated shape: (spur-gear (teeth 12) (play 0.02)).
struct Param : x3::position_tagged { Name name; Number value; };
struct GeneratorItem : x3::position_tagged { Name generator; std::vector<Param> params; };
// Placement and degree of freedom.
struct AtItem : x3::position_tagged { Name keyword; Number x, y; };
struct TurnItem : x3::position_tagged { Name keyword; Number degrees; };
struct Limits : x3::position_tagged { Name keyword; Number lo, hi; };
// (fixed), (rotation [pivot]), (translation axis (limits lo hi)).
struct DofItem : x3::position_tagged { Name keyword; boost::optional<Point> vector; boost::optional<Limits> limits; };
struct SymmetryItem : x3::position_tagged { Name keyword; Number n; };
struct PartItem : x3::variant<PolygonItem, CircleItem, ProfileItem, AtItem, TurnItem, DofItem, SymmetryItem, GeneratorItem> {
    using base_type::base_type;
    using base_type::operator=;
};
struct PartEntry : x3::position_tagged { Name name; std::vector<PartItem> items; };

struct Setting : x3::position_tagged { Name key; std::vector<Number> values; };

struct GridItem : x3::position_tagged { Name keyword; Number n0, n1; };
struct WindowItem : x3::position_tagged { Name keyword; Name part; Number lo, hi; };
struct PairItem : x3::variant<GridItem, WindowItem> {
    using base_type::base_type;
    using base_type::operator=;
};
struct PairEntry : x3::position_tagged { Name a, b; std::vector<PairItem> items; };

struct LinkageEntry : x3::position_tagged { Name first; std::vector<Name> rest; };

struct SignToken : x3::position_tagged { std::string text; };
struct TorqueItem : x3::position_tagged { Name keyword; SignToken sign; };
struct DirectionItem : x3::position_tagged { Name keyword; Number x, y; };
struct WhenItem : x3::position_tagged { Name keyword; Number lo, hi; };
struct ForceItem : x3::variant<TorqueItem, DirectionItem, AtItem, WhenItem> {
    using base_type::base_type;
    using base_type::operator=;
};
struct ForceEntry : x3::position_tagged { Name cause; Name part; std::vector<ForceItem> items; };

struct SettingsSection : x3::position_tagged { Name keyword; std::vector<Setting> entries; };
struct PartsSection : x3::position_tagged { Name keyword; std::vector<PartEntry> entries; };
struct PairsSection : x3::position_tagged { Name keyword; std::vector<PairEntry> entries; };
struct LinkagesSection : x3::position_tagged { Name keyword; std::vector<LinkageEntry> entries; };
struct ForcesSection : x3::position_tagged { Name keyword; std::vector<ForceEntry> entries; };
struct Section : x3::variant<SettingsSection, PartsSection, PairsSection, LinkagesSection, ForcesSection> {
    using base_type::base_type;
    using base_type::operator=;
};

struct MechanismFile : x3::position_tagged { Name keyword; Name name; std::vector<Section> sections; };

// One CONFIG entry: `pallets=3.5` (a CONFIG is a list of them; parts not named stay as drawn).
struct ConfigEntry : x3::position_tagged { Name part; Number value; };

}  // namespace mast

// Maps a node's position tag (id_first) to the byte offset where the node starts.
using MetricPositions = qm::x3_parse::PositionTable;

}  // namespace qm::geometry
