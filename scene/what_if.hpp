// scene/what_if.hpp
// Provides:   the one home of what `--given` and `--without` (and the interactive `given` and
//             `whatif`) mean and how they are checked:
//             - can_take_away(): a query that names a contact or a force, the items a what-if takes away;
//             - names_contact(), names_force(): whether a query names that contact (in either order)
//               or that force (`Force OBJ`: every force on OBJ, scene-level ones included;
//               `Force OBJ CAUSE`: the force(s) of that cause on OBJ);
//             - has_item(), item_text(): whether situation s has the item, and the item in the
//               scene's notation, for messages and notes;
//             - read_givens(), read_withouts(), read_whatif(): the texts parsed and checked against
//               the scene, every error located at the option (or command) that gave it;
//             - replace_given_motions(): a given motion replaces a Motion the scene gives the same
//               object in any situation (one motion at a time, Law 1), said in a note at that Motion;
//             - replaced_by(), what_if_scene(): a situation alone with given motions and without the
//               items of a what-if (for analysing it afresh);
//             - what_if_note(): what a what-if result says it took away;
//             - Additions, read_withs(), read_with(), add_to_scene(), with_note(): what `--with` and
//               the interactive `with` add (a contact, a force), checked the same way: an item the
//               situation already has is an error, a contact of two faces whose normals are not
//               opposite a warning (section 3.1.1).
// Errors:     bad texts go into the Diagnostics (bad input), as `--given:1:1: error: ...`.
// Knows the scene model only (no engine, no law).
#pragma once
#include "scene/scene.hpp"
#include "qm/diagnostics.hpp"
#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace qm::scene {

[[nodiscard]] bool can_take_away(const QueryFact& q) noexcept;
[[nodiscard]] bool names_contact(const QueryFact& q, SurfaceId first, SurfaceId second) noexcept;
[[nodiscard]] bool names_force(const QueryFact& q, ObjectId object, CauseId cause) noexcept;
// Whether situation s (from 1) has the contact or force q.
[[nodiscard]] bool has_item(const Scene& scene, std::size_t s, const QueryFact& q);
// "Contact (a b)", "force of cause 'wind' on 'block'" or "force on 'block'".
[[nodiscard]] std::string item_text(const Scene& scene, const QueryFact& q);

// Every `--given` text read as a motion; at most one per object.
[[nodiscard]] std::vector<Motion> read_givens(const Scene& scene, std::span<const std::string> texts, Diagnostics& diags);
// Every `--without` text read as a contact or force that the scene has: in situation `only` when
// given (1-based; not checked when past the last situation, which the caller reports), else in
// some situation.
[[nodiscard]] std::vector<QueryFact> read_withouts(const Scene& scene, std::span<const std::string> texts,
                                                   std::optional<std::size_t> only, Diagnostics& diags);
// The interactive `whatif [without] FACT[; FACT]...`: contacts or forces of situation s.
[[nodiscard]] std::vector<QueryFact> read_whatif(const Scene& scene, std::size_t s, const std::string& text, Diagnostics& diags);

// Removes, from every situation, the Motions of objects that a given motion replaces, with a note
// at each (`texts` aligned with `given`, as the user wrote them).
void replace_given_motions(Scene& scene, std::span<const Motion> given, std::span<const std::string> texts, Diagnostics& diags);

// Whether one of `given` is a motion of m's object (and so replaces m).
[[nodiscard]] bool replaced_by(const Motion& m, std::span<const Motion> given) noexcept;
// The scene with situation s (from 1) alone, the motions of `given` replacing those of the same
// objects, and without the contacts and forces `without` names (scene-level forces included).
[[nodiscard]] Scene what_if_scene(const Scene& scene, std::size_t s, std::span<const QueryFact> without,
                                  std::span<const Motion> given);

// "what-if: analysed without Contact (a b), every force on 'block' (--without)", or empty when
// situation s has none of the items.
[[nodiscard]] std::string what_if_note(const Scene& scene, std::size_t s, std::span<const QueryFact> without);

// What a what-if adds to a situation: contacts and forces.
struct Additions {
    std::vector<Contact> contacts;
    std::vector<AddedForce> forces;
    [[nodiscard]] bool empty() const noexcept { return contacts.empty() && forces.empty(); }
};

// Every `--with` text read as `Contact A B` or `Force OBJ DIR ORIGIN [CAUSE]`, each added to every
// situation (to situation `only` when given) that does not have it already: one that every such
// situation has is an error, located at the option.
[[nodiscard]] Additions read_withs(const Scene& scene, std::span<const std::string> texts, std::optional<std::size_t> only,
                                   Diagnostics& diags);
// The interactive `with FACT[; FACT]...`: contacts or forces that situation s does not have.
[[nodiscard]] Additions read_with(const Scene& scene, std::size_t s, const std::string& text, Diagnostics& diags);
// Adds `added` to situation s (from 1; every situation when s is 0) where it is not already, new
// causes included. Returns, per situation (0-based), the thesis notation of what was added there.
std::vector<std::vector<std::string>> add_to_scene(Scene& scene, const Additions& added, std::size_t s = 0);
// "Contact (a b)", "Force (block (0 -) (0 0) wind)": an added item in the scene's notation.
[[nodiscard]] std::string added_text(const Scene& scene, const Contact& c);
[[nodiscard]] std::string added_text(const Scene& scene, const AddedForce& f);
// "what-if: analysed with Contact (a b), Force (...) (--with)", or empty when nothing was added.
[[nodiscard]] std::string with_note(std::span<const std::string> added, const char* origin = "--with");

}  // namespace qm::scene
