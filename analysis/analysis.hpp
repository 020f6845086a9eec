// analysis/analysis.hpp
// Provides:   analyse(), the Alex driver's library API (thesis chapters 6-7): it loads the laws from a
//             rule folder, turns a checked Scene into facts (scene items are premises; each
//             situation's contacts, forces and given motions are ATMS assumptions), runs the engine,
//             and reads back, per situation, the free directions of every object, every consistent
//             combination of motions (interpretations of the uniqueness-of-motion choice sets, solved
//             per kinematic chain, Def 22) and the stability verdict. The same Analysis answers "why"
//             and "what if" queries from the labels it already holds (docs/ANALYSIS.md says what is
//             reused and what is recomputed); the searches behind "why" are bounded by WhyLimits.
// Ownership:  an Analysis owns its engine(s) and a copy of the Scene; results are plain values.
// Invariants: situation indices count from 1 in file order; every direction list is in canonical
//             order (lexicographic over + 0 -, as Definition 1 enumerates them) and includes the
//             zero direction among the free ones; chains partition the scene's objects.
// Errors:     rule files that do not load (syntax, semantics) and queries naming unknown things go
//             into the Diagnostics (bad input, exit 2 at the CLI); API misuse throws qm::InternalError.
// Knows no law of mechanics: every law comes from the rule files.
#pragma once
#include "analysis/fwd.hpp"
#include "analysis/granularity.hpp"
#include "engine/law_check.hpp"
#include "engine/run_options.hpp"
#include "scene/scene.hpp"
#include "scene/what_if.hpp"
#include "qm/diagnostics.hpp"
#include "qm/id.hpp"
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace qm::analysis {

// Bounds on the searches behind --why (analysis/why_*.cpp); an answer that reaches one says so.
struct WhyLimits {
    // Minimal responsible sets are found by re-analysing the subsets of a situation's contacts,
    // forces and given motions (2^N contexts) up to this many of them (below 32); above, a sufficient
    // set is given.
    std::size_t exact_items = 8;
    // Case splits of a refutation by case analysis (atms/case_refutation.hpp) before giving up.
    std::size_t case_analysis_steps = 200000;
    // For a consistent motion no force drives: nearness reasons gathered at most, and consistent
    // combinations with it visited at most to find them.
    std::size_t rank_reasons = 8;
    std::size_t rank_combinations = 32;
};

struct AnalysisOptions {
    std::filesystem::path rules_directory;  // every *.rules file directly in it, loaded in name order
    std::vector<Motion> given;              // `--given`: current motions added to every situation
    std::vector<QueryFact> without;         // `--without`: contacts/forces taken away everywhere
    std::size_t combination_limit = 100000; // per chain: stop enumerating after this many (--limit)
    // Empty: `item` when every situation has at most auto_item_limit items, else `situation`.
    std::optional<Granularity> granularity;
    static constexpr std::size_t auto_item_limit = 64;
    // `--kinematic`: enumerate the kinematically consistent combinations up to combination_limit (to
    // list them); otherwise they are only counted, up to kinematic_count_cap, and not at all in a
    // scene analysed one assumption per situation (docs/ANALYSIS.md "Kinematic and selected").
    bool kinematic = false;
    static constexpr std::size_t kinematic_count_cap = 1000;
    // Bounds on the engine's facts and environments (engine/run_options.hpp); reaching one throws
    // qm::LimitReached out of analyse() or a query (the Analysis must then be dropped).
    engine::EngineLimits limits;
    WhyLimits why;  // Analysis::why's searches
};

// Free directions of one object (zero included), canonical order.
struct Freedom {
    std::vector<Direction> translation;
    std::vector<Direction> rotation;
    friend bool operator==(const Freedom&, const Freedom&) = default;
};

struct ObjectMotion {
    Direction translation;
    Direction rotation;
    friend bool operator==(const ObjectMotion&, const ObjectMotion&) = default;
};

// One kinematic chain (Def 22) solved on its own.
struct ChainMotions {
    std::vector<ObjectId> objects;                        // ascending ids
    std::vector<std::vector<ObjectMotion>> combinations;  // each aligned with `objects`; canonical order
    friend bool operator==(const ChainMotions&, const ChainMotions&) = default;
};

using SceneMotion = IdVector<ObjectId, ObjectMotion>;  // one motion per object of the scene

struct SituationResult {
    std::size_t index = 0;                 // 1-based, file order
    IdVector<ObjectId, Freedom> freedom;
    std::vector<ChainMotions> chains;      // partition of all objects
    bool stable = false;                   // every consistent combination is all-zero (and one exists)
    bool complete = true;                  // false: some chain's enumeration stopped at the limit
    std::vector<std::string> notes;        // e.g. which part of a what-if answer was recomputed
    // The kinematically consistent combinations (Figure 7.14's consistent combinations: blocking,
    // pushing, linkages and given motions alone, with the forces taken away), per kinematic chain;
    // `chains` holds those the forces select among them.
    std::vector<ChainMotions> kinematic;
    bool kinematic_complete = true;        // false: some chain's enumeration stopped (cap or --limit)
    bool kinematic_computed = true;        // false: not computed (see AnalysisOptions::kinematic)

    // Combinations of the whole scene: the product over chains (saturating at UINT64_MAX).
    [[nodiscard]] std::uint64_t combination_count() const;
    [[nodiscard]] std::uint64_t kinematic_count() const;  // the same over `kinematic`
    // Calls f for every combination of the whole scene in canonical order, without storing the
    // product; stops early when f returns false.
    void for_each_combination(const std::function<bool(const SceneMotion&)>& f) const;
};

// As SituationResult::for_each_combination, over any list of chains (e.g. its `kinematic`).
void for_each_combination(const std::vector<ChainMotions>& chains, const std::function<bool(const SceneMotion&)>& f);

// A derivation tree: how a fact follows from scene premises and assumptions, one law at a time.
struct Derivation {
    std::string fact;                      // the thesis' notation where one exists, else the rule language's
    std::string law;                       // the rule's name; empty for a leaf
    std::string citation;                  // the thesis part the law's file cites (`cite`), e.g. "section 3.2, Table 3.2"
    std::string source;                    // "motion_transfer.rules:12" (relative to the rules folder), or the scene's file:line for a leaf
    std::vector<std::string> bindings;     // "?o = block", in the rule's slot order
    std::vector<std::string> absent;       // the law's `not` conditions: facts the situation does not hold, which it relied on
    std::vector<Derivation> from;          // antecedents
    bool shown_above = false;              // derived earlier in the same tree: not repeated
    friend bool operator==(const Derivation&, const Derivation&) = default;
};

// One minimal nogood that rules a queried motion out (or one branch of a case analysis).
struct Exclusion {
    std::vector<std::string> responsible;  // the contacts, forces and given motions in it ("Contact (l-1 d-1)")
    Derivation derivation;                 // of `false`
    friend bool operator==(const Exclusion&, const Exclusion&) = default;
};

struct WhyAnswer {
    enum class Status : std::uint8_t { holds, ruled_out } status = Status::holds;
    std::string query;                     // normalised, in the output notation
    std::size_t situation = 0;
    std::vector<Derivation> support;       // holds: a consistent combination / the absence of constraints, explained
    std::vector<Exclusion> exclusions;     // ruled_out: each minimal nogood (or case-analysis branch)
    // Sets of contacts, forces and given motions, each of which suffices to rule the fact out
    // (docs/ANALYSIS.md, "Why"); every minimal such set when responsible_minimal, else one
    // sufficient set that may not be minimal (a large scene).
    std::vector<std::vector<std::string>> responsible_sets;
    bool responsible_minimal = true;
    std::vector<std::string> notes;        // e.g. "excluded by case analysis over gear's motions"
};

class Analysis {
public:
    Analysis(Analysis&&) noexcept;
    Analysis& operator=(Analysis&&) noexcept;
    ~Analysis();

    [[nodiscard]] const Scene& scene() const noexcept;
    [[nodiscard]] const std::vector<SituationResult>& situations() const noexcept;

    // Pre (QM_REQUIRE): 1 <= situation <= situations().size(). Bad queries (kinds that cannot be
    // asked, unknown names) go into diagnostics and return nullopt.
    [[nodiscard]] std::optional<WhyAnswer> why(const QueryFact& query, std::size_t situation, Diagnostics& diagnostics);
    // The situation with some contacts/forces taken away (docs/ANALYSIS.md: reuse vs recompute).
    [[nodiscard]] std::optional<SituationResult> what_if(std::size_t situation, std::span<const QueryFact> without,
                                                         Diagnostics& diagnostics);
    // The contacts of a situation from which the laws derive no `touch` (rules/contact.rules), so
    // that they constrain and push nothing: e.g. a corner against a surface it cannot touch
    // (Definition 25). One located warning each, in the situation's order.
    // Pre (QM_REQUIRE): 1 <= situation <= situations().size().
    [[nodiscard]] std::vector<Diagnostic> inert_contacts(std::size_t situation);
    // The situation with contacts or forces added (`with`; docs/ANALYSIS.md "What-if: reuse and
    // recomputation"): from the labels already computed when every added item is an assumption of
    // the scene already (a contact or force of another situation), else analysed afresh; a note
    // says which. Pre (QM_REQUIRE): 1 <= situation <= situations().size().
    [[nodiscard]] std::optional<SituationResult> what_if_with(std::size_t situation, const scene::Additions& added,
                                                              Diagnostics& diagnostics);
    // The situation with extra current motions given (Figure 7.18).
    [[nodiscard]] std::optional<SituationResult> with_given(std::size_t situation, std::span<const Motion> given,
                                                            Diagnostics& diagnostics);

    struct State;  // opaque (analysis/detail/analysis_state.hpp)

private:
    explicit Analysis(std::unique_ptr<State> state);
    friend std::optional<Analysis> analyse(const Scene&, const AnalysisOptions&, Diagnostics&);
    std::unique_ptr<State> state_;
};

// Loads the rules and analyses every situation. nullopt when the rules do not load (diagnostics say why).
// Warnings about the rules (engine/law_check.hpp, engine/predicate_check.hpp) go into diagnostics
// beside an analysis that succeeds.
[[nodiscard]] std::optional<Analysis> analyse(const Scene& scene, const AnalysisOptions& options, Diagnostics& diagnostics);

// How the laws are checked for a scene of this many dimensions (none: no arity check), `what` naming
// the scene in the warning: citations required, direction literals of its arities.
[[nodiscard]] engine::LawCheckOptions law_check_options(std::optional<std::size_t> dimensions, const std::string& what);

}  // namespace qm::analysis
