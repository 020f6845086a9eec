// analysis/detail/analysis_state.hpp (internal to analysis/)
// Provides:   Analysis::State, shared by analysis.cpp (building and solving) and the why_*.cpp
//             files (explanations): the engine that holds the laws' labels, the scene's facts, each
//             situation's context run and results, and each object's Law 1 choice sets.
// Ownership:  owned by Analysis through a unique_ptr; the SceneFacts refer into scene and engine,
//             which therefore never move while the State lives. The Laws are shared (shared_ptr to
//             const) by every State made from one load: a what-if State copies neither the program
//             nor its match plans.
#pragma once
#include "analysis/analysis.hpp"
#include "analysis/branches.hpp"
#include "analysis/motion_selection.hpp"
#include "analysis/scene_facts.hpp"
#include "engine/engine.hpp"
#include "engine/rule_compiler.hpp"
#include "engine/shared_program.hpp"
#include "scene/what_if.hpp"
#include <map>
#include <memory>
#include <optional>
#include <vector>

namespace qm::analysis {

// The laws as loaded, made once per analysis and only read after: the compiled program with its
// match plans (every engine of every State runs over it, none copies it) and the value table it was
// compiled with (each engine starts from its own copy, to which the scene's facts add values).
struct Laws {
    std::shared_ptr<const engine::SharedProgram> program;
    engine::ValueTable values;
    std::map<std::string, std::string> citations;  // engine::LoadedProgram::citations
};
[[nodiscard]] std::shared_ptr<const Laws> share_laws(engine::LoadedProgram loaded);

struct Analysis::State {
    Scene scene;
    AnalysisOptions options;
    std::shared_ptr<const Laws> laws;         // pristine, shared by every State made from them (with_given)
    std::unique_ptr<engine::Engine> engine;
    std::unique_ptr<SceneFacts> facts;
    IdVector<ObjectId, ObjectChoices> choices;
    BranchSets branches;                      // the laws' choice sets other than Law 1's
    // By situation (0-based), by chain of its result: the branching sets enumerated with that chain.
    std::vector<std::vector<std::vector<std::uint32_t>>> chain_branches;
    std::vector<engine::ContextRun> runs;     // by situation, 0-based
    std::vector<SituationResult> results;     // by situation, 0-based

    // Runs the laws in situation s (1-based) less `without`, plus the `added` assumptions (items of
    // other situations a what-if adds); nullopt if they report errors.
    [[nodiscard]] std::optional<engine::ContextRun> run(std::size_t s, std::span<const QueryFact> without,
                                                        Diagnostics& diagnostics,
                                                        std::span<const atms::AssumptionId> added = {});
    // Reads freedom, motions and stability of situation s in its context environment env; if
    // branches_of is given, the branching sets enumerated with each chain of the result.
    [[nodiscard]] SituationResult read(std::size_t s, atms::EnvId env,
                                       std::vector<std::vector<std::uint32_t>>* branches_of = nullptr);
    // Fills r.kinematic: the kinematically consistent combinations of situation s less `without`
    // (the forces taken away; analysis/kinematic_set.cpp). Pre: choices are read.
    // A stable verdict that relies on the forces gets a note saying so.
    void add_kinematic(SituationResult& r, std::size_t s, std::span<const QueryFact> without,
                       std::span<const atms::AssumptionId> added = {});
    void kinematic_set(SituationResult& r, std::size_t s, std::span<const QueryFact> without,
                       std::span<const atms::AssumptionId> added);
    // run, then read.
    [[nodiscard]] std::optional<SituationResult> solve(std::size_t s, std::span<const QueryFact> without,
                                                       Diagnostics& diagnostics);
    [[nodiscard]] bool holds(std::string_view predicate, std::span<const engine::ValueId> args, atms::EnvId env);
    [[nodiscard]] MotionRanks ranks(ObjectId o, atms::EnvId env) const;
    // branches from the engine's choice sets (after a run, which may declare new ones).
    void refresh_branches();
    // The nodes of the facts ranking o's motions (whatever environment they hold in).
    [[nodiscard]] std::vector<atms::NodeId> rank_nodes(ObjectId o) const;
    // The objects in contact in env (through the situation's contact items) and the linkages.
    [[nodiscard]] std::vector<std::pair<ObjectId, ObjectId>> pairs(std::size_t s, atms::EnvId env) const;
    // A new State for situation s alone, with `without` taken away and `given` motions added.
    [[nodiscard]] std::unique_ptr<State> restricted(std::size_t s, std::span<const QueryFact> without,
                                                    std::span<const Motion> given, Diagnostics& diagnostics,
                                                    std::optional<Granularity> granularity = std::nullopt,
                                                    const scene::Additions* added = nullptr) const;
};

// Builds a State: loads nothing (program is given), asserts the scene, runs every situation.
// nullptr (with diagnostics) if the laws cannot be evaluated for this scene.
[[nodiscard]] std::unique_ptr<Analysis::State> build_state(const Scene& scene, const AnalysisOptions& options,
                                                           std::shared_ptr<const Laws> laws,
                                                           Diagnostics& diagnostics);
}  // namespace qm::analysis
