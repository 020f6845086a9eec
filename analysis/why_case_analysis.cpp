// analysis/why_case_analysis.cpp: --why's answer by case analysis over the other motions of a kinematic
// chain (analysis/detail/why_case_analysis.hpp). The search is the ATMS's (atms/case_refutation.hpp):
// it picks the most constrained choice set first and backjumps, so the nogoods kept are those of
// the argument: the ones with the queried motion and the ones forcing the other motions they name;
// a nogood that excludes a motion the argument never needs (a pinned object's translations, say)
// is left out.
#include "analysis/detail/why_case_analysis.hpp"
#include "analysis/detail/why_derivation.hpp"
#include "analysis/detail/why_responsible.hpp"
#include "atms/case_refutation.hpp"
#include "scene/direction_text.hpp"
#include <algorithm>
#include <set>

namespace qm::analysis::detail {
namespace {

// The one motion (a Law 1 choice) a nogood rules out by the scene's description alone: a nogood
// of that choice and no scene item (the closed world of the situation aside); else nullopt.
std::optional<atms::AssumptionId> sole_choice(const Analysis::State& st, const atms::Environment& nogood) {
    std::optional<atms::AssumptionId> choice;
    for (atms::AssumptionId b : nogood.assumptions()) {
        if (st.facts->item(b)) return std::nullopt;
        const bool is_choice = std::any_of(st.choices.begin(), st.choices.end(), [&](const ObjectChoices& c) {
            return std::find(c.trans.begin(), c.trans.end(), b) != c.trans.end() ||
                   std::find(c.rot.begin(), c.rot.end(), b) != c.rot.end();
        });
        if (!is_choice) {
            if (st.engine->fact_of(st.engine->atms().node_of(b))) return std::nullopt;  // an assumption the laws made
            continue;  // a closed world
        }
        if (choice) return std::nullopt;
        choice = b;
    }
    return choice;
}

// "the scene's description alone rules out every translation of driver but (0 0)": the motions of
// other objects a case analysis relies on being impossible whatever the situation says (e.g. a
// pinned object's translations), said once instead of one reason each.
std::string description_alone_note(const Analysis::State& st, const std::vector<atms::AssumptionId>& fixed) {
    std::vector<std::string> parts;
    for (const ObjectChoices& c : st.choices)
        for (bool trans : {true, false}) {
            const auto& set = trans ? c.trans : c.rot;
            const auto& dirs = trans ? c.trans_dirs : c.rot_dirs;
            std::vector<std::string> out, left;
            for (std::size_t i = 0; i < set.size(); ++i)
                (std::find(fixed.begin(), fixed.end(), set[i]) != fixed.end() ? out : left).push_back(thesis_text(dirs[i]));
            if (out.empty()) continue;
            const std::string kind = trans ? "translation" : "rotation", name = st.scene.objects[c.object].name;
            if (left.size() == 1) {
                parts.push_back("every " + kind + " of " + name + " but " + left.front());
            } else {
                std::string list;
                for (std::size_t i = 0; i < out.size(); ++i) list += (i ? ", " : "") + out[i];
                parts.push_back(name + "'s " + kind + (out.size() > 1 ? "s " : " ") + list);
            }
        }
    std::string text = "the case analysis also uses motions that the scene's description alone rules out "
                       "(not listed as reasons):";
    for (std::size_t i = 0; i < parts.size(); ++i) text += (i ? "; " : " ") + parts[i];
    return text;
}

}  // namespace

void explain_by_cases(Analysis::State& st, WhyAnswer& w, const WhyMotion& m) {
    const auto& atms = st.engine->atms();
    const atms::AssumptionId a = m.choice;
    const char* in_every_branch = m.branched ? ", in every branch of the laws (docs/ANALYSIS.md, Branches)" : "";
    atms::RefutationOptions options;
    options.node_budget = st.options.why.case_analysis_steps;
    options.prefer = a;
    atms::RefutationResult refutation = atms::refute_by_cases(atms, m.sets, m.relevant, m.with_choice, options);
    if (!refutation.proof) {  // the search gave up: the exclusion stands (the ATMS found no consistent choice)
        w.notes.push_back("inconsistent with every choice of the other motions of its kinematic chain, but the "
                          "case analysis is too large to show (it stopped after " +
                          std::to_string(st.options.why.case_analysis_steps) + " steps); --without can take parts away");
        w.responsible_minimal = false;
        coarse_note(st, w);
        return;
    }
    const atms::Refutation& proof = *refutation.proof;
    std::vector<atms::EnvId> nogoods = proof.nogoods;
    order_by_relevance(st, nogoods, a);
    std::set<std::string> together;
    std::vector<atms::AssumptionId> fixed;  // other objects' motions the description alone rules out
    for (atms::EnvId ng : nogoods) {
        if (auto c = sole_choice(st, st.engine->atms().env(ng)); c && *c != a) {
            fixed.push_back(*c);
            continue;
        }
        w.exclusions.push_back(explain_nogood(st, ng));
        together.insert(w.exclusions.back().responsible.begin(), w.exclusions.back().responsible.end());
    }
    if (proof.involved.contains(a))
        w.notes.push_back(std::string("excluded by case analysis over the other motions of its kinematic chain") +
                          in_every_branch + ": the first reasons rule it out together with motions of other "
                          "objects, the others rule out the alternatives to those motions");
    else
        w.notes.push_back(std::string("no combination of the motions of its kinematic chain is consistent in this "
                                      "situation") + in_every_branch + ", whatever this object does: these "
                          "nogoods exclude them all");
    if (!fixed.empty()) w.notes.push_back(description_alone_note(st, fixed));
    set_responsible(st, w, together, m.situation, m.env, m.object, m.translational, m.direction, "the reasons");
    coarse_note(st, w);
}

}  // namespace qm::analysis::detail
