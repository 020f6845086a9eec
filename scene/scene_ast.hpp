// scene/scene_ast.hpp
// Provides:   the raw AST of an Alex scene file as the parser (scene/scene_parser.hpp) produces it,
//             before any check: names are as spelled, signs are raw tokens ("+", "--", "?x"), and
//             sections come in source order. Both notations of docs/SCENE_FORMAT.md (s-expression,
//             Figures 6.1/7.2/7.8, and `Keyword : items`, Figures 7.12/7.16) produce this same AST;
//             so do the figures' own spellings (bare constraint lists after Surfaces, brace-
//             delimited situations, a closing CONTACT list), which are resolved by the checker.
//             Also SourceText (a file's text with line lookup) and PositionTable (qm/position_table.hpp), which maps each
//             node's position tag to its byte offset so that the checker can point at the source.
// Ownership:  plain values. Every node derives from x3::position_tagged; id_first is read through
//             the PositionTable filled by the same parse (the byte offset itself below 1 GiB). A sign
//             token's text is read from the SourceText it was parsed from.
// Knows nothing of the checked model (scene/scene.hpp) or of mechanics.
#pragma once
#include "qm/diagnostics.hpp"
#include "qm/source_text.hpp"
#include "qm/position_table.hpp"
#include <boost/optional.hpp>
#include <boost/spirit/home/x3/support/ast/position_tagged.hpp>
#include <boost/spirit/home/x3/support/ast/variant.hpp>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace qm::scene {

// The text of one input with line/column lookup (shared by every reader of the project).
using SourceText = qm::SourceText;

namespace ast {
namespace x3 = boost::spirit::x3;

struct Name : x3::position_tagged { std::string text; };
// "+", "0", "-", "?x" or a bad token: where it starts (its position tag) and its length; its text
// is the source's (text_of). Signs are most of a scene's tokens, so a std::string each would
// weigh on the peak memory of reading a large scene.
struct SignToken : x3::position_tagged { std::uint32_t length = 0; };
struct Direction : x3::position_tagged { std::vector<SignToken> parts; };

struct Description : x3::position_tagged { Name kind; Name object; };          // (rigid-ob block)
struct SurfaceEntry : x3::position_tagged { Name name; Direction normal; Direction origin; };
struct ObjectSurfaces : x3::position_tagged { Name object; std::vector<SurfaceEntry> surfaces; };
// (tip c-left c-right (+ +)): a corner, the two surfaces meeting there, its origin direction.
struct CornerEntry : x3::position_tagged { Name name; Name first; Name second; Direction origin; };
struct ObjectCorners : x3::position_tagged { Name object; std::vector<CornerEntry> corners; };
struct LinkageEntry : x3::position_tagged { Name first; Name second; };  // (gear-a gear-b)
struct ConstraintEntry : x3::position_tagged { Name object; std::vector<Direction> directions; };
struct ForceEntry : x3::position_tagged { Name object; Direction direction; Direction origin; boost::optional<Name> cause; };
struct ContactEntry : x3::position_tagged { Name first; Name second; };
struct MotionEntry : x3::position_tagged { Name object; Direction translation; Direction rotation; };

// Forces and motions are boxed: a large situation is mostly contacts, and the variant is as
// large as its largest alternative (168 bytes inline, 96 boxed).
struct Descriptor : x3::variant<ContactEntry, x3::forward_ast<ForceEntry>, x3::forward_ast<MotionEntry>> {
    using base_type::base_type;
    using base_type::operator=;
};
struct Situation : x3::position_tagged { std::vector<Descriptor> descriptors; };

struct Individuals : x3::position_tagged { std::vector<Name> names; };
struct Descriptions : x3::position_tagged { std::vector<Description> entries; };
struct Surfaces : x3::position_tagged { std::vector<ObjectSurfaces> entries; };
struct TransConstraints : x3::position_tagged { std::vector<ConstraintEntry> entries; };
struct RotConstraints : x3::position_tagged { std::vector<ConstraintEntry> entries; };
struct Forces : x3::position_tagged { std::vector<ForceEntry> entries; };
struct Corners : x3::position_tagged { std::vector<ObjectCorners> entries; };
struct Linkages : x3::position_tagged { std::vector<LinkageEntry> entries; };
// A constraint list written without its keyword after Surfaces, as Figure 6.1's BNF has it
// (`Surfaces (...) ((table (?x ?y))) ((table (?r)))`); the checker decides which kind it is.
struct BareConstraints : x3::position_tagged { std::vector<ConstraintEntry> entries; };
// `Situations {} {Contact(a b), ...}` (Figure 7.2) as a section of the keyword notation.
struct SituationList : x3::position_tagged { std::vector<Situation> situations; };
// Situation and SituationList are sections only in the keyword notation
// (`Situation : Contact (a b), ...`); BareConstraints only in the s-expression notation.
struct Section : x3::variant<Individuals, Descriptions, Surfaces, TransConstraints, RotConstraints, Forces, Corners,
                             Linkages, Situation, BareConstraints, SituationList> {
    using base_type::base_type;
    using base_type::operator=;
};

struct Dimensions : x3::position_tagged { std::string text; };  // an integer token

struct Scenario : x3::position_tagged {
    Dimensions dimensions;
    Name name;
    std::vector<Section> sections;
    std::vector<Situation> situations;    // (Defstates ...) or `Situations {...}` after the sections
    // The keyword notation's closing `CONTACT (a b), (c d)` (Figures 7.12, 7.16): one situation,
    // tagged at CONTACT, holding only contacts. Allowed only in a scene with no other situation.
    boost::optional<Situation> contact_list;
};

// A query fact as written: `Rotational-Motion (follower (-))`, `Contact a b`, `Force obj`.
struct QueryFact : x3::position_tagged {
    Name predicate;
    Name first;
    boost::optional<Name> second;       // Contact only
    boost::optional<Direction> direction;  // the motion/freedom predicates only
};

}  // namespace ast

// Maps a node's position tag (id_first) to the byte offset where the node starts.
using PositionTable = qm::x3_parse::PositionTable;

}  // namespace qm::scene
