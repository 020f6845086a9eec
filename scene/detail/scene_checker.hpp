// scene/detail/scene_checker.hpp (internal to scene/scene_checker*.cpp)
// Provides:   CheckContext (located errors; sign tokens and directions -> checked values) and
//             SceneChecker (raw AST -> Scene), whose members are split by concern over
//             scene_checker.cpp (sections, objects, entry points), scene_checker_directions.cpp
//             (CheckContext), scene_checker_surfaces.cpp (surfaces and corners),
//             scene_checker_constraints.cpp (constraints, forces, linkages) and
//             scene_checker_situations.cpp (situations, --given, query facts).
// Ownership:  a SceneChecker lives for one check; it points into the AST and PositionTable it
//             checks, which must outlive it, and builds the Scene it hands back by value.
// Knows nothing of X3 (only its AST), the ATMS, the engine or geometry. Only scene_checker*.cpp
// include this header.
#pragma once
#include "scene/scene.hpp"
#include "scene/scene_ast.hpp"
#include "scene/scene_checker.hpp"
#include "qm/diagnostics.hpp"
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace qm::scene::detail {

[[nodiscard]] std::string lower(const std::string& s);
[[nodiscard]] std::string plural(std::size_t n, const char* word);       // "1 sign", "2 signs"
[[nodiscard]] std::string line_column(const SourceLocation& l);          // "line 3, column 7"

// Reports located errors and converts the leaves (signs, directions) of the AST.
class CheckContext {
public:
    CheckContext(const PositionTable& pos, const SourceText& src, Diagnostics& diags)
        : pos_(pos), src_(src), diags_(diags) {}

    [[nodiscard]] SourceLocation where(const ast::x3::position_tagged& node) const;
    [[nodiscard]] std::size_t offset(const ast::x3::position_tagged& node) const { return pos_.offset_of(node); }
    [[nodiscard]] std::string at(const ast::x3::position_tagged& node) const { return line_column(where(node)); }
    void error(const ast::x3::position_tagged& node, std::string message, std::vector<std::string> notes = {});
    [[nodiscard]] std::size_t errors() const noexcept { return errors_; }
    void warning(const ast::x3::position_tagged& node, std::string message);

    // A sign token's text, from the source it was parsed from (the AST keeps only its length).
    [[nodiscard]] std::string text_of(const ast::SignToken& t) const;
    // One sign token; variables (`?x`) only when allowed (constraint entries).
    std::optional<PatternSlot> slot(const ast::SignToken& t, bool allow_variable);
    // A direction of `arity` signs; `role` names it in messages ("a surface normal").
    std::optional<DirectionPattern> pattern(const ast::Direction& d, std::size_t arity, const std::string& role,
                                            bool allow_variables);
    std::optional<Direction> direction(const ast::Direction& d, std::size_t arity, const std::string& role);

    void set_dimensions(int d) { dims_ = d; }

private:
    const PositionTable& pos_;
    const SourceText& src_;
    Diagnostics& diags_;
    std::size_t errors_ = 0;
    int dims_ = 2;
};

class SceneChecker {
public:
    SceneChecker(const PositionTable& pos, const SourceText& src, Diagnostics& diags) : cx_(pos, src, diags) {}

    // scene_checker.cpp
    std::optional<Scene> run(const ast::Scenario& s);
    // Starts from an already checked scene (for --given and query facts).
    void adopt(const Scene& scene);
    std::optional<ObjectId> object(const ast::Name& n, const char* section);

    // scene_checker_situations.cpp
    std::optional<Motion> motion(const ast::MotionEntry& e);
    std::optional<SurfaceId> surface_ref(const ast::Name& n);
    // scene_checker_constraints.cpp: one force entry; a cause the scene lacks is added to scene_.
    std::optional<Force> check_force(const ast::ForceEntry& e);

    CheckContext cx_;
    Scene scene_;

private:
    // scene_checker.cpp
    // The object or surface named so (lower case) among those added so far, by hash: a scan of
    // the scene's tables (Scene::find_*) for every name would make a check quadratic in its size.
    [[nodiscard]] std::optional<ObjectId> find_object(const std::string& name) const;
    [[nodiscard]] std::optional<SurfaceId> find_surface(const std::string& name) const;
    void dimensions(const ast::Dimensions& d);
    template <class T>
    void once(const T& section, const T*& slot, std::vector<const T*>& all, const char* keyword,
              const std::string& reading = {});
    void collect_sections(const ast::Scenario& s);
    // Registers a bare constraint list as the kind bare_kind decided (none: nothing to register).
    void bare(const ast::BareConstraints& b, std::optional<bool> translational, const ast::TransConstraints*& t1,
              const ast::RotConstraints*& r1);
    // The closing CONTACT list of the keyword notation: the only situation, when there is no other.
    void contact_list(const ast::Scenario& s);
    void reserve_tables();
    void individuals(const ast::Individuals& ind);
    void descriptions(const ast::Descriptions& d);

    // scene_checker_surfaces.cpp
    template <class Group>
    std::optional<ObjectId> group_owner(const Group& g, std::map<ObjectId, const Group*>& groups,
                                        const char* section, const char* what);
    void surfaces(const ast::Surfaces& s);
    void duplicate_surface(const ast::Name& first, std::optional<ObjectId> first_owner, const ast::Name& second,
                           std::optional<ObjectId> second_owner);
    void index_corner_names();
    SurfaceId add_surface(Surface s, const ast::Name& n);
    void surface(const ast::SurfaceEntry& e, std::optional<ObjectId> owner);
    void corners(const ast::Corners& c);
    std::optional<SurfaceId> corner(const ast::CornerEntry& e, std::optional<ObjectId> owner);
    void corner_sides(const ast::CornerEntry& e, ObjectId owner, std::optional<SurfaceId> k);

    // scene_checker_constraints.cpp
    // Figure 6.1's constraint lists without keywords: whether sections[i] is translational
    // (true) or rotational (false), by its place after Surfaces, else by the arity of its
    // directions; empty after reporting why it cannot be told, or for a lone empty list (no
    // constraint either way).
    std::optional<bool> bare_kind(const std::vector<ast::Section>& sections, std::size_t i);
    void constraints(const std::vector<ast::ConstraintEntry>& entries, bool translational);
    void linkages(const ast::Linkages& l);

    // scene_checker_situations.cpp
    void situation(const ast::Situation& s);
    struct DescriptorVisitor;

    std::size_t force_entries_ = 0;
    const ast::Individuals* individuals_ = nullptr;
    std::vector<const ast::Descriptions*> descriptions_;
    std::vector<const ast::Surfaces*> surfaces_;
    std::vector<const ast::TransConstraints*> trans_;
    std::vector<const ast::RotConstraints*> rot_;
    std::vector<const ast::Forces*> forces_;
    std::vector<const ast::Corners*> corners_;
    std::vector<const ast::Linkages*> linkages_;
    std::vector<const ast::Name*> surface_names_;  // the declaring name of each SurfaceId
    std::unordered_map<std::string, ObjectId> object_ids_;    // scene_.objects by name
    std::unordered_map<std::string, SurfaceId> surface_ids_;  // scene_.surfaces by name
    std::map<std::string, std::pair<const ast::Name*, std::optional<ObjectId>>> first_corner_;
    std::vector<const ast::Situation*> situations_;
    // Keyworded copies of the bare constraint lists (std::deque: the pointers above stay valid).
    std::deque<ast::TransConstraints> bare_trans_;
    std::deque<ast::RotConstraints> bare_rot_;
};

}  // namespace qm::scene::detail
