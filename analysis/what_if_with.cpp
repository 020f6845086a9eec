// analysis/what_if_with.cpp: Analysis::what_if_with, a situation with contacts or forces added.
// The monotonic laws ran once over every assumption of the scene, so an added
// item that is an assumption already (a contact or force of another situation) needs only a new
// context over the same engine: its labels are reused and only the rules with `not` or an
// aggregate run again, as for a smaller situation. A new item would be a new assumption, and a
// closed world may not grow once a `not` has been decided in it (docs/RULES.md "Semantics"): then
// the situation is analysed afresh. The note says which.
#include "analysis/detail/analysis_state.hpp"
#include "qm/assert.hpp"

namespace qm::analysis {

std::optional<SituationResult> Analysis::what_if_with(std::size_t situation, const scene::Additions& added,
                                                      Diagnostics& diagnostics) {
    QM_REQUIRE(situation >= 1 && situation <= state_->results.size(), "situation index out of range");
    State& st = *state_;
    std::vector<std::string> texts;
    std::vector<atms::AssumptionId> known;  // the added items' assumptions, where the scene has them
    std::string fresh;                      // the first added item the scene does not have
    for (const Contact& c : added.contacts) {
        texts.push_back(scene::added_text(st.scene, c));
        auto a = st.facts->granularity() == Granularity::item ? st.facts->assumption_of(c) : std::nullopt;
        if (a) known.push_back(*a);
        else if (fresh.empty()) fresh = texts.back();
    }
    for (const scene::AddedForce& f : added.forces) {
        texts.push_back(scene::added_text(st.scene, f));
        auto a = st.facts->granularity() == Granularity::item && !f.new_cause ? st.facts->assumption_of(f.force) : std::nullopt;
        if (a) known.push_back(*a);
        else if (fresh.empty()) fresh = texts.back();
    }
    if (fresh.empty()) {
        auto run = st.run(situation, st.options.without, diagnostics, known);
        if (!run) return std::nullopt;
        st.refresh_branches();
        SituationResult r = st.read(situation, run->environment);
        st.add_kinematic(r, situation, st.options.without, known);
        r.notes.insert(r.notes.begin(), scene::with_note(texts, "with"));
        r.notes.push_back("what-if: what was added holds in other situations of the scene, so the monotonic laws' labels "
                          "were reused; the rules with `not` or an aggregate (freedom, force distribution, net force, "
                          "nearness) were run again for the larger situation");
        return r;
    }
    auto state = st.restricted(situation, st.options.without, {}, diagnostics, std::nullopt, &added);
    if (!state) return std::nullopt;
    SituationResult r = state->results.front();
    r.index = situation;
    r.notes.insert(r.notes.begin(), scene::with_note(texts, "with"));
    r.notes.push_back("what-if: " + fresh +
                      (st.facts->granularity() == Granularity::situation
                           ? " is added to a scene analysed one assumption per situation"
                           : " is new to the scene, and a closed world may not grow once a `not` has been decided in it") +
                      ", so the larger situation was analysed afresh");
    return r;
}

}  // namespace qm::analysis
