// scene/scene_parser_def.hpp
// Provides:   the Spirit X3 grammar of Alex scenes (docs/SCENE_FORMAT.md; thesis Figure 6.1 and
//             the notations of Figures 7.2, 7.8, 7.12, 7.16 with their own spellings: `Name dims`
//             headers, `(defState ...)`, `Situations {...}`, closing CONTACT lists, keyword-less
//             constraint lists and `obj (entry*)` surface lists; the Corners and Linkages sections
//             of section 3.1.1 and Definition 21), of `--given` motions and of query facts. Include
//             only from scene_parser.cpp: X3's compile cost is paid in one TU.
// Ownership:  rules are constants; per-parse state (positions, diagnostics) is injected with
//             x3::with<state_tag>.
// Invariants: every rule whose attribute is position_tagged records its start offset on success
//             (annotate); the top-level rules turn the first expectation failure into one located
//             diagnostic (report_errors) and fail, so no exception escapes a parse.
#pragma once
#include "scene/scene_ast.hpp"
#include "qm/sexpr_text.hpp"
#include "qm/x3_ascii.hpp"
#include "qm/x3_sexpr.hpp"
#include "qm/diagnostics.hpp"
#include <boost/fusion/include/adapt_struct.hpp>
#include <boost/spirit/home/x3.hpp>
#include <algorithm>
#include <cstdint>
#include <string>
#include <type_traits>

BOOST_FUSION_ADAPT_STRUCT(qm::scene::ast::Description, kind, object)
BOOST_FUSION_ADAPT_STRUCT(qm::scene::ast::SurfaceEntry, name, normal, origin)
BOOST_FUSION_ADAPT_STRUCT(qm::scene::ast::ObjectSurfaces, object, surfaces)
BOOST_FUSION_ADAPT_STRUCT(qm::scene::ast::CornerEntry, name, first, second, origin)
BOOST_FUSION_ADAPT_STRUCT(qm::scene::ast::ObjectCorners, object, corners)
BOOST_FUSION_ADAPT_STRUCT(qm::scene::ast::LinkageEntry, first, second)
BOOST_FUSION_ADAPT_STRUCT(qm::scene::ast::ConstraintEntry, object, directions)
BOOST_FUSION_ADAPT_STRUCT(qm::scene::ast::ForceEntry, object, direction, origin, cause)
BOOST_FUSION_ADAPT_STRUCT(qm::scene::ast::ContactEntry, first, second)
BOOST_FUSION_ADAPT_STRUCT(qm::scene::ast::MotionEntry, object, translation, rotation)
BOOST_FUSION_ADAPT_STRUCT(qm::scene::ast::Scenario, dimensions, name, sections, situations)
BOOST_FUSION_ADAPT_STRUCT(qm::scene::ast::QueryFact, predicate, first, second, direction)

namespace qm::scene::parser {
namespace x3 = boost::spirit::x3;

// A scene with a `Name dims` header (Figures 7.2, 7.8, 7.12, 7.16) names the scene before its
// dimension count (`Gears 2`); its body is in the keyword notation or, in Figures 7.2 and 7.8,
// the s-expression notation's sections.
struct SceneBody {
    std::vector<ast::Section> sections;
    std::vector<ast::Situation> situations;
    boost::optional<ast::Situation> contact_list;
};
struct HeaderScenario {
    ast::Name name;
    ast::Dimensions dimensions;
    SceneBody body;
};
}  // namespace qm::scene::parser
BOOST_FUSION_ADAPT_STRUCT(qm::scene::parser::SceneBody, sections, situations, contact_list)
BOOST_FUSION_ADAPT_STRUCT(qm::scene::parser::HeaderScenario, name, dimensions, body)

namespace qm::scene::parser {

// The X3 plumbing shared with the other readers (qm/x3_parse.hpp, qm/x3_sexpr.hpp): `annotate`
// records where a node starts; an entry rule's first expectation failure becomes the located
// diagnostic `expected ... but found TOKEN` and the parse fails, so no exception escapes.
using x3_parse::annotate;
using x3_parse::state_tag;
using report_errors = x3_parse::first_failure;
// The characters that are tokens of their own in "but found ..." (qm/sexpr_text.hpp token_at).
inline constexpr std::string_view punctuation = "(),:";

// --- lexical pieces --------------------------------------------------------------------------
// ASCII classes and case-insensitive keywords (qm/x3_ascii.hpp: x3's own classes abort on bytes
// >= 0x80 in a debug build). The skipper (qm/x3_sexpr.hpp) also skips `;` comments.
using x3_ascii::blank;
using x3_ascii::digit;
using x3_ascii::kw;
using x3_ascii::letter;
using x3_ascii::name_char;

// Note: `a >> b > c` is written `(a >> b) > c` (the C++ precedence) so that clang does not warn.

// Semantic action storing the matched text (x3::raw) into a member of the rule's attribute.
template <class Node>
inline auto store_text(std::string Node::*member) {
    return [member](auto& ctx) {
        const auto& r = x3::_attr(ctx);
        (x3::_val(ctx).*member).assign(r.begin(), r.end());
    };
}
// Semantic action storing the length of the matched text (x3::raw) into a member: the text itself
// stays in the source (a sign token, scene/scene_ast.hpp).
template <class Node>
inline auto store_length(std::uint32_t Node::*member) {
    return [member](auto& ctx) {
        const auto& r = x3::_attr(ctx);
        x3::_val(ctx).*member = static_cast<std::uint32_t>(std::min<std::size_t>(r.size(), UINT32_MAX));
    };
}
// Semantic action moving the parsed attribute into a member of the rule's attribute.
template <class Node, class M>
inline auto store(M Node::*member) {
    return [member](auto& ctx) { x3::_val(ctx).*member = std::move(x3::_attr(ctx)); };
}

// --- rule ids --------------------------------------------------------------------------------
#define QM_SCENE_RULE_ID(id) struct id : annotate {}
QM_SCENE_RULE_ID(name_class);
QM_SCENE_RULE_ID(sign_class);
QM_SCENE_RULE_ID(direction_class);
QM_SCENE_RULE_ID(dimensions_class);
QM_SCENE_RULE_ID(description_sx_class);
QM_SCENE_RULE_ID(description_kw_class);
QM_SCENE_RULE_ID(surface_entry_class);
QM_SCENE_RULE_ID(object_surfaces_sx_class);
QM_SCENE_RULE_ID(object_surfaces_paren_class);
QM_SCENE_RULE_ID(object_surfaces_bnf_class);
QM_SCENE_RULE_ID(bare_surface_entry_class);
QM_SCENE_RULE_ID(object_surfaces_kw_class);
QM_SCENE_RULE_ID(corner_entry_class);
QM_SCENE_RULE_ID(object_corners_sx_class);
QM_SCENE_RULE_ID(object_corners_kw_class);
QM_SCENE_RULE_ID(linkage_entry_class);
QM_SCENE_RULE_ID(constraint_sx_class);
QM_SCENE_RULE_ID(constraint_kw_class);
QM_SCENE_RULE_ID(force_body_class);
QM_SCENE_RULE_ID(force_body_kw_class);
QM_SCENE_RULE_ID(force_entry_sx_class);
QM_SCENE_RULE_ID(contact_sx_class);
QM_SCENE_RULE_ID(force_sx_class);
QM_SCENE_RULE_ID(motion_sx_class);
QM_SCENE_RULE_ID(contact_kw_class);
QM_SCENE_RULE_ID(force_kw_class);
QM_SCENE_RULE_ID(motion_kw_class);
QM_SCENE_RULE_ID(descriptor_sx_class);
QM_SCENE_RULE_ID(descriptor_body_sx_class);
QM_SCENE_RULE_ID(descriptor_kw_class);
QM_SCENE_RULE_ID(situation_sx_class);
QM_SCENE_RULE_ID(situation_kw_class);
QM_SCENE_RULE_ID(situation_braces_class);
QM_SCENE_RULE_ID(contact_pair_class);
QM_SCENE_RULE_ID(contact_list_class);
QM_SCENE_RULE_ID(situations_kw_class);
QM_SCENE_RULE_ID(bare_constraints_class);
QM_SCENE_RULE_ID(individuals_sx_class);
QM_SCENE_RULE_ID(individuals_kw_class);
QM_SCENE_RULE_ID(descriptions_sx_class);
QM_SCENE_RULE_ID(descriptions_kw_class);
QM_SCENE_RULE_ID(surfaces_sx_class);
QM_SCENE_RULE_ID(surfaces_kw_class);
QM_SCENE_RULE_ID(trans_sx_class);
QM_SCENE_RULE_ID(trans_kw_class);
QM_SCENE_RULE_ID(rot_sx_class);
QM_SCENE_RULE_ID(rot_kw_class);
QM_SCENE_RULE_ID(forces_sx_class);
QM_SCENE_RULE_ID(forces_kw_class);
QM_SCENE_RULE_ID(corners_sx_class);
QM_SCENE_RULE_ID(corners_kw_class);
QM_SCENE_RULE_ID(linkages_sx_class);
QM_SCENE_RULE_ID(linkages_kw_class);
QM_SCENE_RULE_ID(section_sx_class);
QM_SCENE_RULE_ID(section_kw_class);
QM_SCENE_RULE_ID(defstates_class);
QM_SCENE_RULE_ID(scenario_sx_class);
QM_SCENE_RULE_ID(header_scenario_class);
QM_SCENE_RULE_ID(scenario_kw_class);
#undef QM_SCENE_RULE_ID
struct scene_file_class : annotate, report_errors {};
struct given_class : annotate, report_errors {};
struct query_class : annotate, report_errors {};
struct force_text_class : annotate, report_errors {};

// --- rules -----------------------------------------------------------------------------------
const x3::rule<name_class, ast::Name> name = "a name";
const x3::rule<sign_class, ast::SignToken> sign = "a sign";
const x3::rule<direction_class, ast::Direction> direction = "a direction like (0 +)";
const x3::rule<dimensions_class, ast::Dimensions> dimensions = "the number of dimensions (2 or 3)";
const x3::rule<description_sx_class, ast::Description> description_sx = "an object description like (rigid-ob block)";
const x3::rule<description_kw_class, ast::Description> description_kw = "an object description like rigid-ob(block)";
const x3::rule<surface_entry_class, ast::SurfaceEntry> surface_entry = "a surface entry like (top (0 +) (0 -))";
const x3::rule<object_surfaces_sx_class, ast::ObjectSurfaces> object_surfaces_sx = "an object's surfaces";
const x3::rule<object_surfaces_paren_class, ast::ObjectSurfaces> object_surfaces_paren = "an object's surfaces";
const x3::rule<object_surfaces_bnf_class, ast::ObjectSurfaces> object_surfaces_bnf = "an object's surfaces";
const x3::rule<bare_surface_entry_class, ast::SurfaceEntry> bare_surface_entry =
    "a surface entry like top (0 +) (0 -)";
const x3::rule<object_surfaces_kw_class, ast::ObjectSurfaces> object_surfaces_kw = "an object's surfaces";
const x3::rule<corner_entry_class, ast::CornerEntry> corner_entry =
    "a corner entry like (tip side-1 side-2 (0 +))";
const x3::rule<object_corners_sx_class, ast::ObjectCorners> object_corners_sx = "an object's corners";
const x3::rule<object_corners_kw_class, ast::ObjectCorners> object_corners_kw = "an object's corners";
const x3::rule<linkage_entry_class, ast::LinkageEntry> linkage_entry = "a linkage like (gear-a gear-b)";
const x3::rule<constraint_sx_class, ast::ConstraintEntry> constraint_sx = "a constraint entry like (table (?x ?y))";
const x3::rule<constraint_kw_class, ast::ConstraintEntry> constraint_kw = "a constraint entry like table (?x ?y)";
const x3::rule<force_body_class, ast::ForceEntry> force_body = "a force";
const x3::rule<force_body_kw_class, ast::ForceEntry> force_body_kw = "a force";
const x3::rule<force_entry_sx_class, ast::ForceEntry> force_entry_sx = "a force entry like (block (0 -) (0 0))";
const x3::rule<contact_sx_class, ast::ContactEntry> contact_sx = "a contact";
const x3::rule<force_sx_class, ast::ForceEntry> force_sx = "a force";
const x3::rule<motion_sx_class, ast::MotionEntry> motion_sx = "a motion";
const x3::rule<contact_kw_class, ast::ContactEntry> contact_kw = "a contact";
const x3::rule<force_kw_class, ast::ForceEntry> force_kw = "a force";
const x3::rule<motion_kw_class, ast::MotionEntry> motion_kw = "a motion";
const x3::rule<descriptor_sx_class, ast::Descriptor> descriptor_sx = "a situation descriptor";
const x3::rule<descriptor_body_sx_class, ast::Descriptor> descriptor_body_sx =
    "Contact, Force or Motion";
const x3::rule<descriptor_kw_class, ast::Descriptor> descriptor_kw =
    "a situation descriptor (Contact, Force or Motion)";
const x3::rule<situation_sx_class, ast::Situation> situation_sx = "a situation";
const x3::rule<situation_kw_class, ast::Situation> situation_kw = "a situation";
const x3::rule<situation_braces_class, ast::Situation> situation_braces = "a situation like {Contact(a b)}";
const x3::rule<contact_pair_class, ast::ContactEntry> contact_pair = "a contact like (l-1 d-1)";
const x3::rule<contact_list_class, ast::Situation> contact_list = "a CONTACT list";
const x3::rule<situations_kw_class, ast::SituationList> situations_kw = "Situations";
const x3::rule<bare_constraints_class, ast::BareConstraints> bare_constraints = "a constraint list";
const x3::rule<individuals_sx_class, ast::Individuals> individuals_sx = "Individuals";
const x3::rule<individuals_kw_class, ast::Individuals> individuals_kw = "Individuals";
const x3::rule<descriptions_sx_class, ast::Descriptions> descriptions_sx = "Descriptions";
const x3::rule<descriptions_kw_class, ast::Descriptions> descriptions_kw = "Descriptions";
const x3::rule<surfaces_sx_class, ast::Surfaces> surfaces_sx = "Surfaces";
const x3::rule<surfaces_kw_class, ast::Surfaces> surfaces_kw = "Surfaces";
const x3::rule<trans_sx_class, ast::TransConstraints> trans_sx = "Translational-Constraints";
const x3::rule<trans_kw_class, ast::TransConstraints> trans_kw = "Translational-Constraints";
const x3::rule<rot_sx_class, ast::RotConstraints> rot_sx = "Rotational-Constraints";
const x3::rule<rot_kw_class, ast::RotConstraints> rot_kw = "Rotational-Constraints";
const x3::rule<forces_sx_class, ast::Forces> forces_sx = "Forces";
const x3::rule<forces_kw_class, ast::Forces> forces_kw = "Forces";
const x3::rule<corners_sx_class, ast::Corners> corners_sx = "Corners";
const x3::rule<corners_kw_class, ast::Corners> corners_kw = "Corners";
const x3::rule<linkages_sx_class, ast::Linkages> linkages_sx = "Linkages";
const x3::rule<linkages_kw_class, ast::Linkages> linkages_kw = "Linkages";
const x3::rule<section_sx_class, ast::Section> section_sx = "a section";
const x3::rule<section_kw_class, ast::Section> section_kw = "a section";
const x3::rule<defstates_class, std::vector<ast::Situation>> defstates = "(Defstates ...)";
const x3::rule<scenario_sx_class, ast::Scenario> scenario_sx = "(Defscenario ...)";
const x3::rule<header_scenario_class, HeaderScenario> header_scenario = "a scene";
const x3::rule<scenario_kw_class, ast::Scenario> scenario_kw = "a scene";
const x3::rule<scene_file_class, ast::Scenario> scene_file = "a scene";
const x3::rule<given_class, ast::MotionEntry> given = "a motion like 'pallet (0 0) (+)'";
const x3::rule<query_class, ast::QueryFact> query = "a fact";
const x3::rule<force_text_class, ast::ForceEntry> force_text = "a force like 'Force block (0 -) (0 0)'";


// Rules with semantic actions get their attribute as `unused` in on_success, so each is an
// un-annotated inner rule wrapped by the annotated rule of the same name.
const x3::rule<struct name_inner_class, ast::Name> name_inner = "name";
const x3::rule<struct sign_inner_class, ast::SignToken> sign_inner = "sign";
const x3::rule<struct direction_inner_class, ast::Direction> direction_inner = "direction";
const x3::rule<struct dimensions_inner_class, ast::Dimensions> dimensions_inner = "dimensions";
const x3::rule<struct situation_sx_inner_class, ast::Situation> situation_sx_inner = "situation sx";
const x3::rule<struct situation_kw_inner_class, ast::Situation> situation_kw_inner = "situation kw";
const x3::rule<struct situation_braces_inner_class, ast::Situation> situation_braces_inner = "situation braces";
const x3::rule<struct contact_list_inner_class, ast::Situation> contact_list_inner = "contact list";
const x3::rule<struct situations_kw_inner_class, ast::SituationList> situations_kw_inner = "situations kw";
const x3::rule<struct bare_constraints_inner_class, ast::BareConstraints> bare_constraints_inner = "bare constraints";
const x3::rule<struct individuals_sx_inner_class, ast::Individuals> individuals_sx_inner = "individuals sx";
const x3::rule<struct individuals_kw_inner_class, ast::Individuals> individuals_kw_inner = "individuals kw";
const x3::rule<struct descriptions_sx_inner_class, ast::Descriptions> descriptions_sx_inner = "descriptions sx";
const x3::rule<struct descriptions_kw_inner_class, ast::Descriptions> descriptions_kw_inner = "descriptions kw";
const x3::rule<struct surfaces_sx_inner_class, ast::Surfaces> surfaces_sx_inner = "surfaces sx";
const x3::rule<struct surfaces_kw_inner_class, ast::Surfaces> surfaces_kw_inner = "surfaces kw";
const x3::rule<struct trans_sx_inner_class, ast::TransConstraints> trans_sx_inner = "trans sx";
const x3::rule<struct trans_kw_inner_class, ast::TransConstraints> trans_kw_inner = "trans kw";
const x3::rule<struct rot_sx_inner_class, ast::RotConstraints> rot_sx_inner = "rot sx";
const x3::rule<struct rot_kw_inner_class, ast::RotConstraints> rot_kw_inner = "rot kw";
const x3::rule<struct forces_sx_inner_class, ast::Forces> forces_sx_inner = "forces sx";
const x3::rule<struct forces_kw_inner_class, ast::Forces> forces_kw_inner = "forces kw";
const x3::rule<struct corners_sx_inner_class, ast::Corners> corners_sx_inner = "corners sx";
const x3::rule<struct corners_kw_inner_class, ast::Corners> corners_kw_inner = "corners kw";
const x3::rule<struct linkages_sx_inner_class, ast::Linkages> linkages_sx_inner = "linkages sx";
const x3::rule<struct linkages_kw_inner_class, ast::Linkages> linkages_kw_inner = "linkages kw";

// Rules that exist only to give expectation failures readable names: an expectation on a bare
// list (`a % ','`, `+a`) would report X3's mangled type name.
const x3::rule<struct name_list_class, std::vector<ast::Name>> name_list = "names separated by ','";
const x3::rule<struct name_items_class, std::vector<ast::Name>> name_items = "a name";
const x3::rule<struct description_list_class, std::vector<ast::Description>> description_list_kw =
    "an object description like rigid-ob(block)";
const x3::rule<struct surface_groups_class, std::vector<ast::ObjectSurfaces>> surface_groups_kw =
    "an object's surfaces like block (top (0 +) (0 -))";
const x3::rule<struct surface_list_class, std::vector<ast::SurfaceEntry>> surface_list_kw =
    "a surface entry like (top (0 +) (0 -))";
const x3::rule<struct corner_groups_class, std::vector<ast::ObjectCorners>> corner_groups_kw =
    "an object's corners like block (tip side-1 side-2 (0 +))";
const x3::rule<struct corner_list_class, std::vector<ast::CornerEntry>> corner_list_kw =
    "a corner entry like (tip side-1 side-2 (0 +))";
const x3::rule<struct constraint_list_class, std::vector<ast::ConstraintEntry>> constraint_list_kw =
    "a constraint entry like table (?x ?y)";
const x3::rule<struct direction_list_class, std::vector<ast::Direction>> direction_list = "a direction like (0 +)";
const x3::rule<struct force_list_class, std::vector<ast::ForceEntry>> force_list_kw =
    "a force like block (0 -) (0 0)";
const x3::rule<struct brace_items_class, std::vector<ast::Descriptor>> brace_items =
    "a situation descriptor (Contact, Force or Motion) or '}'";
const x3::rule<struct brace_close_class> brace_close = "',' or '}'";
// A comma-separated list of keyword-notation descriptors: after a ',' a descriptor must follow, so
// an unknown one (`Contact (a b), Frobnicate (x)`) is reported where it is, not at the ','.
const x3::rule<struct descriptor_list_kw_class, std::vector<ast::Descriptor>> descriptor_list_kw =
    "a situation descriptor (Contact, Force or Motion)";
const x3::rule<struct brace_situations_class, std::vector<ast::Situation>> brace_situations =
    "a situation in braces like {} or {Contact(a b), Contact(c d)}";
const x3::rule<struct situations_braces_class, std::vector<ast::Situation>> situations_braces = "Situations";
const x3::rule<struct contact_pairs_class, std::vector<ast::ContactEntry>> contact_pairs = "a contact like (l-1 d-1)";
const x3::rule<struct contact_list_end_class> contact_list_end =
    "end of input (a CONTACT list ends the scene; more situations are written 'Situation : ...')";
const x3::rule<struct sx_states_class, std::vector<ast::Situation>> sx_states = "(Defstates ...)";
const x3::rule<struct figure_tail_class, std::vector<ast::Situation>> figure_tail =
    "a section keyword (Individuals, Descriptions, Surfaces, Corners, Translational-Constraints, "
    "Rotational-Constraints, Forces, Linkages), '(Defstates', 'Situations' or end of input";
const x3::rule<struct figure_body_class, SceneBody> figure_body = "a section";
const x3::rule<struct keyword_body_class, SceneBody> keyword_body = "a section";
const x3::rule<struct scene_body_class, SceneBody> scene_body = "a section";
const x3::rule<struct linkage_list_class, std::vector<ast::LinkageEntry>> linkage_list_kw =
    "a linkage like (gear-a gear-b)";
const x3::rule<struct defscenario_kw_class> defscenario_kw = "'Defscenario'";
const x3::rule<struct sx_end_class> sx_section_end =
    "a section keyword (Individuals, Descriptions, Surfaces, Corners, Translational-Constraints, "
    "Rotational-Constraints, Forces, Linkages) or ')'";
const x3::rule<struct kw_end_class> kw_section_end =
    "a section keyword (Individuals, Descriptions, Surfaces, Corners, Translational-Constraints, "
    "Rotational-Constraints, Forces, Linkages, Situation) followed by ':'";
const x3::rule<struct eoi_class> end_of_input = "end of input";
const x3::rule<struct colon_class> colon = "':'";

// A name starts with a letter; a word followed by ':' is a section keyword, never a name.
const auto name_def = name_inner;
const auto name_inner_def = (x3::raw[x3::lexeme[letter >> *name_char]] >> !x3::lit(':'))[store_text(&ast::Name::text)];
// Any token up to a blank, parenthesis, comma, colon or comment: the checker judges it, so that
// `--` or `++` get a helpful message instead of a bare syntax error.
const auto sign_def = sign_inner;
const auto sign_inner_def = x3::raw[x3::lexeme[+(x3::char_ - blank - x3::char_("(),:;"))]][store_length(&ast::SignToken::length)];
const auto direction_def = direction_inner;
const auto direction_inner_def = ((x3::lit('(') >> *sign) > ')')[store(&ast::Direction::parts)];
const auto dimensions_def = dimensions_inner;
const auto dimensions_inner_def = x3::raw[x3::lexeme[+digit >> !name_char]][store_text(&ast::Dimensions::text)];

const auto description_sx_def = (x3::lit('(') >> name) > name > ')';
const auto description_kw_def = (name >> '(') > name > ')';
const auto surface_entry_def = (x3::lit('(') >> name) > direction > direction > ')';
// Figure 6.1: `<name> "(" <surface entry>* ")"` with `<surface entry> ::= <name> <dir> <dir>`;
// the figures (7.2, 7.8) put each object's group and each entry in parentheses instead. A group
// starting with '(' is the figures' form, one starting with a name the BNF's; inside the BNF's
// group an entry is parenthesised when it starts with '(' and bare when it starts with a name.
const auto object_surfaces_sx_def = object_surfaces_paren | object_surfaces_bnf;
const auto object_surfaces_paren_def = (x3::lit('(') >> name) > *surface_entry > ')';
const auto object_surfaces_bnf_def = (name >> '(') > *(surface_entry | bare_surface_entry) > ')';
const auto bare_surface_entry_def = name > direction > direction;
// Words that end a keyword-notation group list rather than start a group: the situation words
// (so that a closing `CONTACT (a b)` is a CONTACT list and `Force`/`Motion` a misplaced
// keyword), and `Situations` (Figure 7.2) unless a group's '(' follows it. A word followed by
// ':' is never a name anyway.
const auto list_stop = kw("contact") | kw("force") | kw("motion") | (kw("situations") >> !x3::lit('('));
const auto object_surfaces_kw_def = (!list_stop >> name) > surface_list_kw;
// The comma between two entries of one object may be left out (Figure 7.12 breaks a line
// there without one): an entry starts with '(', the next object's group with its name.
const auto surface_list_kw_def = surface_entry % -x3::lit(',');
// Corners (section 3.1.1, Definition 18): grouped by object like Surfaces. Inside either list
// a '(' can only open a corner entry, so the entry commits at its '('.
const auto corner_entry_def = x3::lit('(') > name > name > name > direction > ')';
const auto object_corners_sx_def = (x3::lit('(') >> name) > *corner_entry > ')';
const auto object_corners_kw_def = (!list_stop >> name) > corner_list_kw;
const auto corner_list_kw_def = corner_entry % ',';
// Linkages (Definition 21): a pair of objects.
const auto linkage_entry_def = x3::lit('(') > name > name > ')';
const auto constraint_sx_def = (x3::lit('(') >> name) > *direction > ')';
const auto constraint_kw_def = name > direction_list;
const auto direction_list_def = +direction;
const auto force_body_def = name > direction > direction > -name;
const auto force_entry_sx_def = (x3::lit('(') >> force_body) > ')';
// In the keyword notation's Forces list the optional cause is not taken from a closing
// `CONTACT (` or from `Situations {`, which follow the list.
const auto force_body_kw_def =
    name > direction > direction > -(!((kw("contact") >> '(') | (kw("situations") >> -x3::lit(':') >> '{')) >> name);

const auto contact_sx_def = kw("contact") > name > name;
const auto force_sx_def = kw("force") > force_body;
const auto motion_sx_def = kw("motion") > name > direction > direction;
const auto descriptor_body_sx_def = contact_sx | force_sx | motion_sx;
const auto descriptor_sx_def = x3::lit('(') > descriptor_body_sx > ')';
const auto situation_sx_def = situation_sx_inner | situation_braces;
const auto situation_sx_inner_def = ((x3::lit('(') >> *descriptor_sx) > ')')[store(&ast::Situation::descriptors)];
const auto contact_kw_def = kw("contact") > '(' > name > name > ')';
const auto force_kw_def = kw("force") > '(' > force_body > ')';
const auto motion_kw_def = kw("motion") > '(' > name > direction > direction > ')';
const auto descriptor_kw_def = contact_kw | force_kw | motion_kw;
// Figure 7.2: `{}` is a situation without descriptors, `{Contact(tb block-b-l), ...}` one with.
const auto situation_braces_def = situation_braces_inner;
const auto situation_braces_inner_def = (x3::lit('{') > brace_items)[store(&ast::Situation::descriptors)];
const auto descriptor_list_kw_def = descriptor_kw > *(x3::lit(',') > descriptor_kw);
// A word directly followed by '(' after `Situation :` can only start a descriptor.
const auto descriptor_start = x3::lexeme[letter >> *name_char] >> '(';
const auto brace_items_def =
    (x3::lit('}') >> x3::attr(std::vector<ast::Descriptor>{})) | (descriptor_list_kw > brace_close);
const auto brace_close_def = x3::lit('}');
const auto brace_situations_def = +situation_braces;
const auto situations_braces_def = (kw("situations") >> -colon) > brace_situations;
const auto situations_kw_def = situations_kw_inner;
const auto situations_kw_inner_def = situations_braces[store(&ast::SituationList::situations)];
// Figures 7.12 and 7.16 end with `CONTACT (l-1 d-1)`, `CONTACT (a b), (c d)`: one situation.
const auto contact_pair_def = x3::lit('(') > name > name > ')';
const auto contact_pairs_def = contact_pair % ',';
const auto contact_list_def = contact_list_inner;
const auto contact_list_inner_def = (kw("contact") > contact_pairs > contact_list_end)[([](auto& ctx) {
    for (auto& c : x3::_attr(ctx)) x3::_val(ctx).descriptors.emplace_back(std::move(c));
})];
const auto contact_list_end_def = x3::eoi;
const auto situation_kw_def = situation_kw_inner;
const auto situation_kw_inner_def =
    (kw("situation") > colon > -(&descriptor_start > descriptor_list_kw))[([](auto& ctx) {
        auto& items = x3::_attr(ctx);
        if (items) x3::_val(ctx).descriptors = std::move(*items);
    })];

const auto individuals_sx_def = individuals_sx_inner;
const auto individuals_sx_inner_def = (kw("individuals") > '(' > *name > ')')[store(&ast::Individuals::names)];
const auto individuals_kw_def = individuals_kw_inner;
const auto individuals_kw_inner_def =
    (kw("individuals") > colon > name_list)[store(&ast::Individuals::names)];
const auto name_list_def = (x3::lit('(') > name_items > ')') | name_items;
const auto name_items_def = name % ',';
const auto description_list_kw_def = description_kw % ',';
const auto surface_groups_kw_def = object_surfaces_kw % -x3::lit(',');
const auto corner_groups_kw_def = object_corners_kw % -x3::lit(',');
const auto constraint_list_kw_def = constraint_kw % ',';
const auto force_list_kw_def = force_body_kw % ',';
const auto linkage_list_kw_def = linkage_entry % ',';
const auto descriptions_sx_def = descriptions_sx_inner;
const auto descriptions_sx_inner_def = (kw("descriptions") > '(' > *description_sx > ')')[store(&ast::Descriptions::entries)];
const auto descriptions_kw_def = descriptions_kw_inner;
const auto descriptions_kw_inner_def = (kw("descriptions") > colon > description_list_kw)[store(&ast::Descriptions::entries)];
const auto surfaces_sx_def = surfaces_sx_inner;
const auto surfaces_sx_inner_def = (kw("surfaces") > '(' > *object_surfaces_sx > ')')[store(&ast::Surfaces::entries)];
const auto surfaces_kw_def = surfaces_kw_inner;
const auto surfaces_kw_inner_def = (kw("surfaces") > colon > surface_groups_kw)[store(&ast::Surfaces::entries)];
const auto trans_sx_def = trans_sx_inner;
const auto trans_sx_inner_def = (kw("translational-constraints") > '(' > *constraint_sx > ')')[store(&ast::TransConstraints::entries)];
const auto trans_kw_def = trans_kw_inner;
const auto trans_kw_inner_def = (kw("translational-constraints") > colon > constraint_list_kw)[store(&ast::TransConstraints::entries)];
const auto rot_sx_def = rot_sx_inner;
const auto rot_sx_inner_def = (kw("rotational-constraints") > '(' > *constraint_sx > ')')[store(&ast::RotConstraints::entries)];
const auto rot_kw_def = rot_kw_inner;
const auto rot_kw_inner_def = (kw("rotational-constraints") > colon > constraint_list_kw)[store(&ast::RotConstraints::entries)];
const auto forces_sx_def = forces_sx_inner;
const auto forces_sx_inner_def = (kw("forces") > '(' > *force_entry_sx > ')')[store(&ast::Forces::entries)];
const auto forces_kw_def = forces_kw_inner;
const auto forces_kw_inner_def = (kw("forces") > colon > force_list_kw)[store(&ast::Forces::entries)];
const auto corners_sx_def = corners_sx_inner;
const auto corners_sx_inner_def = (kw("corners") > '(' > *object_corners_sx > ')')[store(&ast::Corners::entries)];
const auto corners_kw_def = corners_kw_inner;
const auto corners_kw_inner_def = (kw("corners") > colon > corner_groups_kw)[store(&ast::Corners::entries)];
const auto linkages_sx_def = linkages_sx_inner;
const auto linkages_sx_inner_def = (kw("linkages") > '(' > *linkage_entry > ')')[store(&ast::Linkages::entries)];
const auto linkages_kw_def = linkages_kw_inner;
const auto linkages_kw_inner_def = (kw("linkages") > colon > linkage_list_kw)[store(&ast::Linkages::entries)];
// Figure 6.1 gives the constraint sections without keywords: a list of constraint entries
// (`((table (?x ?y)))`, or `()`) after Surfaces. `(` followed by `(` or `)` can be nothing else.
const auto bare_constraints_def = bare_constraints_inner;
const auto bare_constraints_inner_def =
    (((x3::lit('(') >> &(x3::lit('(') | x3::lit(')'))) > *constraint_sx) > ')')[store(&ast::BareConstraints::entries)];

const auto section_sx_def = individuals_sx | descriptions_sx | surfaces_sx | corners_sx | trans_sx | rot_sx |
                            forces_sx | linkages_sx | bare_constraints;
const auto section_kw_def = individuals_kw | descriptions_kw | surfaces_kw | corners_kw | trans_kw | rot_kw | forces_kw |
                            linkages_kw | situation_kw | situations_kw;
// A section keyword directly followed by '(' starts the s-expression notation's sections.
const auto sx_section_start = (kw("individuals") | kw("descriptions") | kw("surfaces") | kw("corners") |
                               kw("translational-constraints") | kw("rotational-constraints") | kw("forces") |
                               kw("linkages")) >> '(';

const auto defscenario_kw_def = kw("defscenario");
const auto sx_section_end_def = x3::lit(')');
const auto kw_section_end_def = x3::eoi;
const auto end_of_input_def = x3::eoi;
const auto colon_def = x3::lit(':');

// Figure 7.8 writes `(defState (...))`: Defstate is the same keyword as Defstates.
const auto defstates_def = (x3::lit('(') >> (kw("defstates") | kw("defstate"))) > *situation_sx > ')';
// The situations after the scenario: `(Defstates ...)`, `Situations {...} ...` (Figure 7.2), or none.
const auto sx_states_def = defstates | situations_braces | x3::attr(std::vector<ast::Situation>{});
const auto scenario_sx_def = x3::lit('(') > defscenario_kw > dimensions > name > *section_sx > sx_section_end >
                             sx_states > end_of_input;
// After a `Name dims` header: the s-expression notation's sections when the first section
// keyword is followed by '(' (Figures 7.2, 7.8), else the keyword notation.
const auto figure_body_def = (&sx_section_start >> *section_sx) > figure_tail >
                             x3::attr(boost::optional<ast::Situation>{});
const auto figure_tail_def = ((defstates | situations_braces) > end_of_input) |
                             (x3::eoi >> x3::attr(std::vector<ast::Situation>{}));
const auto keyword_body_def = *section_kw > x3::attr(std::vector<ast::Situation>{}) > -contact_list > kw_section_end;
const auto scene_body_def = figure_body | keyword_body;
const auto header_scenario_def = name > dimensions > scene_body;
const auto scenario_kw_def = header_scenario[([](auto& ctx) {
    HeaderScenario& k = x3::_attr(ctx);
    ast::Scenario& s = x3::_val(ctx);
    s.name = std::move(k.name);
    s.dimensions = std::move(k.dimensions);
    s.sections = std::move(k.body.sections);
    s.situations = std::move(k.body.situations);
    s.contact_list = std::move(k.body.contact_list);
})];
const auto scene_file_def = (&x3::lit('(') >> scenario_sx) | scenario_kw;

const auto given_def = name > direction > direction > end_of_input;
// The parentheses around the arguments are optional; balance is checked before parsing.
const auto query_def = name > -x3::lit('(') > name > -name > -direction > -x3::lit(')') > end_of_input;
// `--with 'Force obj dir origin [cause]'`: a force entry after the keyword, parentheses optional.
const auto force_text_def = kw("force") > -x3::lit('(') > force_body > -x3::lit(')') > end_of_input;

BOOST_SPIRIT_DEFINE(name_inner, sign_inner, direction_inner, dimensions_inner, situation_sx_inner, situation_kw_inner,
                    situation_braces_inner, contact_list_inner, situations_kw_inner, bare_constraints_inner,
                    individuals_sx_inner, individuals_kw_inner, descriptions_sx_inner, descriptions_kw_inner, surfaces_sx_inner, surfaces_kw_inner, trans_sx_inner, trans_kw_inner, rot_sx_inner, rot_kw_inner, forces_sx_inner, forces_kw_inner, corners_sx_inner, corners_kw_inner, linkages_sx_inner, linkages_kw_inner)
BOOST_SPIRIT_DEFINE(name, sign, direction, dimensions, description_sx, description_kw, surface_entry,
                    object_surfaces_sx, object_surfaces_paren, object_surfaces_bnf, bare_surface_entry,
                    object_surfaces_kw, constraint_sx, constraint_kw, force_body, force_body_kw,
                    force_entry_sx, contact_sx, force_sx, motion_sx, contact_kw, force_kw, motion_kw,
                    descriptor_sx, descriptor_body_sx, descriptor_kw, situation_sx, situation_kw, corner_entry,
                    object_corners_sx, object_corners_kw, linkage_entry, situation_braces, contact_pair,
                    contact_list, situations_kw, bare_constraints)
BOOST_SPIRIT_DEFINE(individuals_sx, individuals_kw, descriptions_sx, descriptions_kw, surfaces_sx, surfaces_kw,
                    trans_sx, trans_kw, rot_sx, rot_kw, forces_sx, forces_kw, corners_sx, corners_kw, linkages_sx,
                    linkages_kw, section_sx, section_kw,
                    name_list, name_items, description_list_kw, surface_groups_kw, surface_list_kw, corner_groups_kw,
                    corner_list_kw, constraint_list_kw, direction_list, force_list_kw, linkage_list_kw, defscenario_kw, sx_section_end, kw_section_end, end_of_input, colon, defstates,
                    scenario_sx, header_scenario, scenario_kw, scene_file, given, query, force_text, brace_items, brace_close,
                    descriptor_list_kw,
                    brace_situations, situations_braces, contact_pairs, contact_list_end, sx_states, figure_tail,
                    figure_body, keyword_body, scene_body)

}  // namespace qm::scene::parser
