// geometry/metric_scene_parser_def.hpp
// Provides:   the Spirit X3 grammar of metric scenes and of the CONFIG argument
//             (docs/METRIC_SCENE_FORMAT.md). Include only from metric_scene_parser.cpp: X3's
//             compile cost is paid in one translation unit.
// Ownership:  rules are constants; per-parse state (positions, diagnostics) is injected with
//             x3::with<state_tag>.
// Invariants: every position_tagged node produced by an annotated rule records its start
//             offset; the top-level rules turn the first expectation failure into one located
//             diagnostic (`expected ... but found ...`) and fail, so no exception escapes. Every
//             keyword position ends in unknown_word() (qm/x3_unknown_word.hpp), so a misspelt
//             keyword is named, with the nearest one, instead of the token after it.
#pragma once
#include "qm/sexpr_text.hpp"
#include "qm/x3_ascii.hpp"
#include "qm/x3_sexpr.hpp"
#include "qm/x3_unknown_word.hpp"
#include "geometry/metric_scene_ast.hpp"
#include "geometry/detail/metric_keywords.hpp"
#include "geometry/part_generators.hpp"
#include "geometry/metric_source.hpp"
#include "qm/diagnostics.hpp"
#include <boost/fusion/include/adapt_struct.hpp>
#include <boost/spirit/home/x3.hpp>
#include <cctype>
#include <string>
#include <string_view>
#include <type_traits>

BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::Point, x, y)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::PolygonItem, keyword, points)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::CircleItem, keyword, centre, radius)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::LineStep, keyword, x, y)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::ArcStep, keyword, x, y, cx, cy, sense)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::ProfileItem, keyword, start, steps)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::Param, name, value)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::GeneratorItem, generator, params)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::AtItem, keyword, x, y)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::TurnItem, keyword, degrees)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::Limits, keyword, lo, hi)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::DofItem, keyword, vector, limits)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::SymmetryItem, keyword, n)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::PartEntry, name, items)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::Setting, key, values)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::GridItem, keyword, n0, n1)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::WindowItem, keyword, part, lo, hi)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::PairEntry, a, b, items)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::LinkageEntry, first, rest)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::TorqueItem, keyword, sign)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::DirectionItem, keyword, x, y)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::WhenItem, keyword, lo, hi)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::ForceEntry, cause, part, items)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::SettingsSection, keyword, entries)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::PartsSection, keyword, entries)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::PairsSection, keyword, entries)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::LinkagesSection, keyword, entries)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::ForcesSection, keyword, entries)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::MechanismFile, keyword, name, sections)
BOOST_FUSION_ADAPT_STRUCT(qm::geometry::mast::ConfigEntry, part, value)

namespace qm::geometry::mparser {
namespace x3 = boost::spirit::x3;
namespace ast = qm::geometry::mast;

// The X3 plumbing shared with the other readers (qm/x3_parse.hpp, qm/x3_sexpr.hpp): `annotate`
// records where a node starts; an entry rule's first expectation failure becomes the located
// diagnostic `expected ... but found TOKEN` and the parse fails, so no exception escapes.
using x3_parse::annotate;
using x3_parse::state_tag;
using report_errors = x3_parse::first_failure;
// The characters that are tokens of their own in "but found ..." (qm/sexpr_text.hpp token_at).
inline constexpr std::string_view punctuation = "()=,";

// --- lexical pieces --------------------------------------------------------------------------
// ASCII classes (qm/x3_ascii.hpp): x3::space/alpha/alnum/no_case abort on bytes >= 0x80 in a
// debug build; these compare bytes, so a non-ASCII byte is a located syntax error.
using x3_ascii::name_char;

// A case-insensitive keyword, not followed by a name character. Pre: s is lower case.
using x3_ascii::kw;

template <class Node>
inline auto store_text(std::string Node::*member) {
    return [member](auto& ctx) {
        const auto& r = x3::_attr(ctx);
        (x3::_val(ctx).*member).assign(r.begin(), r.end());
    };
}

// A keyword as a Name node (its text as written), for the first member of every item.
struct keyword_class;
inline auto kwname(const char* s) { return x3::rule<keyword_class, ast::Name>{s} = x3::raw[kw(s)][store_text(&ast::Name::text)]; }

// The keyword positions (geometry/detail/metric_keywords.hpp): each ends in unknown_word().
using x3_parse::unknown_word;
namespace kws = qm::geometry::detail;

// A generator's name (geometry/part_generators.hpp), in any case.
inline auto known_generator = [](auto& ctx) {
    x3::_pass(ctx) = find_generator(ascii_lower(x3::_attr(ctx).text)) != nullptr;
    x3::_val(ctx) = x3::_attr(ctx);
};

// Note: `a >> b > c` is written `(a >> b) > c` (the C++ precedence) so that clang does not warn.

// --- rule ids --------------------------------------------------------------------------------
#define QM_METRIC_RULE_ID(id) struct id : annotate {}
QM_METRIC_RULE_ID(name_class);
QM_METRIC_RULE_ID(number_class);
QM_METRIC_RULE_ID(sign_class);
QM_METRIC_RULE_ID(point_class);
QM_METRIC_RULE_ID(polygon_item_class);
QM_METRIC_RULE_ID(circle_item_class);
QM_METRIC_RULE_ID(line_step_class);
QM_METRIC_RULE_ID(arc_step_class);
QM_METRIC_RULE_ID(step_class);
QM_METRIC_RULE_ID(profile_item_class);
QM_METRIC_RULE_ID(param_class);
QM_METRIC_RULE_ID(generator_item_class);
QM_METRIC_RULE_ID(at_item_class);
QM_METRIC_RULE_ID(turn_item_class);
QM_METRIC_RULE_ID(limits_class);
QM_METRIC_RULE_ID(dof_item_class);
QM_METRIC_RULE_ID(symmetry_item_class);
QM_METRIC_RULE_ID(part_item_class);
QM_METRIC_RULE_ID(part_entry_class);
QM_METRIC_RULE_ID(setting_class);
QM_METRIC_RULE_ID(grid_item_class);
QM_METRIC_RULE_ID(window_item_class);
QM_METRIC_RULE_ID(pair_item_class);
QM_METRIC_RULE_ID(pair_entry_class);
QM_METRIC_RULE_ID(linkage_entry_class);
QM_METRIC_RULE_ID(torque_item_class);
QM_METRIC_RULE_ID(direction_item_class);
QM_METRIC_RULE_ID(when_item_class);
QM_METRIC_RULE_ID(force_item_class);
QM_METRIC_RULE_ID(force_entry_class);
QM_METRIC_RULE_ID(settings_section_class);
QM_METRIC_RULE_ID(parts_section_class);
QM_METRIC_RULE_ID(pairs_section_class);
QM_METRIC_RULE_ID(linkages_section_class);
QM_METRIC_RULE_ID(forces_section_class);
QM_METRIC_RULE_ID(section_class);
QM_METRIC_RULE_ID(config_entry_class);
#undef QM_METRIC_RULE_ID
struct mechanism_file_class : annotate, report_errors {};
struct config_class : annotate, report_errors {};

// --- rules -----------------------------------------------------------------------------------
const x3::rule<name_class, ast::Name> name = "a name";
const x3::rule<number_class, ast::Number> number = "a number";
const x3::rule<sign_class, ast::SignToken> sign = "a sign (+ or -)";
const x3::rule<point_class, ast::Point> point = "a point like (0 1.5)";
const x3::rule<polygon_item_class, ast::PolygonItem> polygon_item = "(polygon ...)";
const x3::rule<circle_item_class, ast::CircleItem> circle_item = "(circle ...)";
const x3::rule<line_step_class, ast::LineStep> line_step = "(line x y)";
const x3::rule<arc_step_class, ast::ArcStep> arc_step = "(arc x y cx cy ccw|cw)";
const x3::rule<step_class, ast::Step> step = "a step (line x y) or (arc x y cx cy ccw|cw)";
const x3::rule<profile_item_class, ast::ProfileItem> profile_item = "(profile ...)";
const x3::rule<param_class, ast::Param> param = "a parameter like (teeth 12)";
const x3::rule<generator_item_class, ast::GeneratorItem> generator_item = "a generated shape like (spur-gear (teeth 12))";
const x3::rule<at_item_class, ast::AtItem> at_item = "(at x y)";
const x3::rule<turn_item_class, ast::TurnItem> turn_item = "(turn degrees)";
const x3::rule<limits_class, ast::Limits> limits = "(limits lo hi)";
const x3::rule<dof_item_class, ast::DofItem> dof_item = "(fixed), (rotation [pivot]) or (translation (dx dy) (limits lo hi))";
const x3::rule<symmetry_item_class, ast::SymmetryItem> symmetry_item = "(symmetry n)";
const x3::rule<part_item_class, ast::PartItem> part_item = "a part item";
const x3::rule<part_entry_class, ast::PartEntry> part_entry = "a part like (wheel (spur-gear) (rotation))";
const x3::rule<setting_class, ast::Setting> setting = "a setting like (grid 64 64)";
const x3::rule<grid_item_class, ast::GridItem> grid_item = "(grid n0 n1)";
const x3::rule<window_item_class, ast::WindowItem> window_item = "(window part lo hi)";
const x3::rule<pair_item_class, ast::PairItem> pair_item = "a pair setting";
const x3::rule<pair_entry_class, ast::PairEntry> pair_entry = "a pair like (wheel pinion)";
const x3::rule<linkage_entry_class, ast::LinkageEntry> linkage_entry = "a linkage like (gear-2 pinion-2)";
const x3::rule<torque_item_class, ast::TorqueItem> torque_item = "(torque +|-)";
const x3::rule<direction_item_class, ast::DirectionItem> direction_item = "(direction dx dy)";
const x3::rule<when_item_class, ast::WhenItem> when_item = "(when lo hi)";
const x3::rule<force_item_class, ast::ForceItem> force_item = "a force item";
const x3::rule<force_entry_class, ast::ForceEntry> force_entry = "a force like (spring wheel (torque +))";
const x3::rule<settings_section_class, ast::SettingsSection> settings_section = "Settings";
const x3::rule<parts_section_class, ast::PartsSection> parts_section = "Parts";
const x3::rule<pairs_section_class, ast::PairsSection> pairs_section = "Pairs";
const x3::rule<linkages_section_class, ast::LinkagesSection> linkages_section = "Linkages";
const x3::rule<forces_section_class, ast::ForcesSection> forces_section = "Forces";
const x3::rule<section_class, ast::Section> section = "a section";
const x3::rule<mechanism_file_class, ast::MechanismFile> mechanism_file = "a metric scene";
const x3::rule<config_entry_class, ast::ConfigEntry> config_entry = "an entry like part=12.5";
const x3::rule<config_class, std::vector<ast::ConfigEntry>> config = "a configuration like 'wheel=10, pallets=-3'";

// Rules with semantic actions are un-annotated inner rules wrapped by the annotated rule.
const x3::rule<struct name_inner_class, ast::Name> name_inner = "name";
const x3::rule<struct number_inner_class, ast::Number> number_inner = "number";
const x3::rule<struct sign_inner_class, ast::SignToken> sign_inner = "sign";

// Rules that only name what was expected, for readable messages.
const x3::rule<struct close_class> close = "')'";
const x3::rule<struct part_end_class> part_end =
    "')' or a part item: (polygon ...), (circle ...), (profile ...), a generator like (spur-gear ...), (at x y), (turn deg), "
    "(fixed), (rotation [pivot]), (translation (dx dy) (limits lo hi)), (symmetry n)";
const x3::rule<struct pair_end_class> pair_end = "')' or a pair setting: (grid n0 n1) or (window part lo hi)";
const x3::rule<struct force_end_class> force_end = "')' or a force item: (torque +|-), (direction dx dy), (at x y), (when lo hi)";
const x3::rule<struct profile_end_class> profile_end = "')' or a step: (line x y) or (arc x y cx cy ccw|cw)";
const x3::rule<struct section_end_class> section_end = "a section keyword (Settings, Parts, Pairs, Linkages, Forces) or ')'";
const x3::rule<struct defmechanism_class, ast::Name> defmechanism = "'Defmechanism'";
const x3::rule<struct eoi_class> end_of_input = "end of input";
const x3::rule<struct sense_class, ast::Name> sense = "ccw or cw";
const x3::rule<struct generator_name_class, ast::Name> generator_name = "a generator";

const auto name_def = name_inner;
const auto name_inner_def = x3::raw[x3::lexeme[x3_ascii::letter >> *name_char]][store_text(&ast::Name::text)];
const auto number_def = number_inner;
const auto number_inner_def = x3::double_[([](auto& ctx) { x3::_val(ctx).value = x3::_attr(ctx); })];
const auto sign_def = sign_inner;
const auto sign_inner_def = x3::raw[x3::lexeme[+(x3::char_ - x3_ascii::blank - x3::char_("();"))]][store_text(&ast::SignToken::text)];
const auto point_def = (x3::lit('(') >> number) > number > close;

const auto sense_def = kwname("ccw") | kwname("cw") | unknown_word(kws::sense_keywords(), false);
const auto polygon_item_def = (x3::lit('(') >> kwname("polygon")) > +point > close;
const auto circle_item_def = (x3::lit('(') >> kwname("circle")) > point > number > close;
const auto line_step_def = (x3::lit('(') >> kwname("line")) > number > number > close;
const auto arc_step_def = (x3::lit('(') >> kwname("arc")) > number > number > number > number > sense > close;
const auto step_def = line_step | arc_step | unknown_word(kws::step_keywords(), true);
const auto profile_item_def = (x3::lit('(') >> kwname("profile")) > point > +step > profile_end;
const auto param_def = (x3::lit('(') >> name) > number > close;
// A known generator's item is read with expectations. Any other name heads a generator item if the
// item reads as one: the checker names the unknown generator, and checks the rest of the scene;
// a word heading anything else is an unknown word, reported by part_item.
const auto generator_name_def = name[known_generator];
const auto generator_item_def = ((x3::lit('(') >> generator_name) > *param > close) | ((x3::lit('(') >> name >> *param) >> ')');
const auto at_item_def = (x3::lit('(') >> kwname("at")) > number > number > close;
const auto turn_item_def = (x3::lit('(') >> kwname("turn")) > number > close;
const auto limits_def = ((x3::lit('(') >> kwname("limits")) > number > number > close) | unknown_word(kws::limits_keywords(), true);
const auto dof_item_def =
    ((x3::lit('(') >> kwname("fixed")) > x3::attr(boost::optional<ast::Point>()) > x3::attr(boost::optional<ast::Limits>()) > close) |
    ((x3::lit('(') >> kwname("rotation")) > -point > x3::attr(boost::optional<ast::Limits>()) > close) |
    ((x3::lit('(') >> kwname("translation")) > point > limits > close);
const auto symmetry_item_def = (x3::lit('(') >> kwname("symmetry")) > number > close;
const auto part_item_def = polygon_item | circle_item | profile_item | at_item | turn_item | dof_item | symmetry_item | generator_item |
                           unknown_word(kws::part_item_keywords(), true);
const auto part_entry_def = (x3::lit('(') >> name) > *part_item > part_end;

const auto setting_def = (x3::lit('(') >> name) > *number > close;

const auto grid_item_def = (x3::lit('(') >> kwname("grid")) > number > number > close;
const auto window_item_def = (x3::lit('(') >> kwname("window")) > name > number > number > close;
const auto pair_item_def = grid_item | window_item | unknown_word(kws::pair_item_keywords(), true);
const auto pair_entry_def = (x3::lit('(') >> name) > name > *pair_item > pair_end;

const auto linkage_entry_def = (x3::lit('(') >> name) > +name > close;

const auto torque_item_def = (x3::lit('(') >> kwname("torque")) > sign > close;
const auto direction_item_def = (x3::lit('(') >> kwname("direction")) > number > number > close;
const auto when_item_def = (x3::lit('(') >> kwname("when")) > number > number > close;
const auto force_item_def = torque_item | direction_item | at_item | when_item | unknown_word(kws::force_item_keywords(), true);
const auto force_entry_def = (x3::lit('(') >> name) > name > *force_item > force_end;

const auto settings_section_def = kwname("settings") > '(' > *setting > close;
const auto parts_section_def = kwname("parts") > '(' > *part_entry > close;
const auto pairs_section_def = kwname("pairs") > '(' > *pair_entry > close;
const auto linkages_section_def = kwname("linkages") > '(' > *linkage_entry > close;
const auto forces_section_def = kwname("forces") > '(' > *force_entry > close;
const auto section_def =
    settings_section | parts_section | pairs_section | linkages_section | forces_section | unknown_word(kws::section_keywords(), false);

const auto close_def = x3::lit(')');
const auto part_end_def = x3::lit(')');
const auto pair_end_def = x3::lit(')');
const auto force_end_def = x3::lit(')');
const auto profile_end_def = x3::lit(')');
const auto section_end_def = x3::lit(')');
const auto defmechanism_def = x3::raw[kw("defmechanism")][store_text(&ast::Name::text)] | unknown_word(kws::defmechanism_keywords(), false);
const auto end_of_input_def = x3::eoi;

const auto mechanism_file_def = x3::lit('(') > defmechanism > name > *section > section_end > end_of_input;
const auto config_entry_def = name > '=' > number;
const auto config_def = -(config_entry % -x3::lit(',')) > end_of_input;

BOOST_SPIRIT_DEFINE(name, name_inner, number, number_inner, sign, sign_inner, point, sense, polygon_item, circle_item, line_step, arc_step,
                    step, profile_item, param, generator_name, generator_item, at_item, turn_item, limits, dof_item, symmetry_item, part_item,
                    part_entry, setting)
BOOST_SPIRIT_DEFINE(grid_item, window_item, pair_item, pair_entry, linkage_entry, torque_item, direction_item, when_item,
                    force_item, force_entry, settings_section, parts_section, pairs_section, linkages_section, forces_section,
                    section, close, part_end, pair_end, force_end, profile_end, section_end, defmechanism, end_of_input,
                    mechanism_file, config_entry, config)

}  // namespace qm::geometry::mparser
