// analysis/why_query.cpp: Analysis::why, "why was this motion ruled out?" read off the ATMS: the minimal
// nogoods that exclude a motion (or the constraint that removes a freedom), each with its
// derivation down to the scene's premises and assumptions, naming the law at every step.
#include "analysis/analysis.hpp"
#include "analysis/detail/analysis_state.hpp"
#include "engine/preferences.hpp"
#include "engine/why.hpp"
#include "scene/direction_text.hpp"
#include "scene/vocabulary.hpp"
#include "qm/assert.hpp"
#include <algorithm>
#include <bit>
#include <filesystem>
#include <functional>
#include <map>
#include <set>
#include <tuple>

namespace qm::analysis {
namespace v = scene::vocabulary;
using engine::ValueId;

namespace {

// Fact text in the thesis' notation where it has one (section 2, Defs 7, 19, 23, 24), else in the
// rule language's.
std::string fact_text(const Analysis::State& st, engine::FactId f) {
    const engine::Engine& e = *st.engine;
    const engine::Fact& fact = e.facts().fact(f);
    const std::string pred = e.values().print(fact.predicate);
    static const std::map<std::string, std::string> thesis{
        {std::string(v::trans_motion), "Translational-Motion"},     {std::string(v::rot_motion), "Rotational-Motion"},
        {std::string(v::trans_freedom), "Translational-Freedom"},   {std::string(v::rot_freedom), "Rotational-Freedom"},
        {std::string(v::trans_constraint), "TransConstraint"},      {std::string(v::rot_constraint), "RotConstraint"}};
    if (auto it = thesis.find(pred); it != thesis.end() && fact.args.size() == 2)
        return it->second + " (" + e.values().print(fact.args[0]) + " " + e.values().print(fact.args[1]) + ")";
    if (auto a = e.assumption(f))
        if (const SceneItem* item = st.facts->item(*a)) return item->text;
    return e.print(f);
}

std::string node_text(const Analysis::State& st, atms::NodeId n) {
    const engine::Engine& e = *st.engine;
    if (n == e.atms().contradiction()) return "false";
    if (auto f = e.fact_of(n)) return fact_text(st, *f);
    if (auto a = e.atms().assumption_of(n)) return e.print(*a);
    return "?";
}

std::string located(const SourceLocation& w) { return w.file + ":" + std::to_string(w.line); }

// Turns an ATMS explanation (justifications in derivation order) into a tree rooted at `root`;
// a node met twice is shown once and referred to afterwards.
class TreeBuilder {
public:
    TreeBuilder(const Analysis::State& st, const atms::Explanation& x) : st_(st) {
        for (atms::JustId j : x.steps) by_consequent_.try_emplace(st.engine->atms().justification(j).consequent, j);
    }
    Derivation build(atms::NodeId n) {
        const engine::Engine& e = *st_.engine;
        const auto& atms = e.atms();
        Derivation d;
        d.fact = node_text(st_, n);
        // A scene item is a leaf, however it is held (its own assumption, or its situation's).
        if (auto f = e.fact_of(n))
            if (const SceneItem* item = st_.facts->item(*f)) {
                d.fact = item->text;
                d.source = located(item->where);
                items_used_.insert(item->text);
                return d;
            }
        auto it = by_consequent_.find(n);
        if (it == by_consequent_.end()) {  // a leaf: a premise or an assumption
            leaf(n, d);
            return d;
        }
        if (!shown_.insert(n).second) {
            d.shown_above = true;
            return d;
        }
        const atms::Justification& just = atms.justification(it->second);
        const engine::Firing& firing = e.firing(just.informant);
        if (firing.kind == engine::Firing::Kind::rule) {
            const engine::CompiledRule& rule = e.program().rules[*firing.rule];
            d.law = rule.name;
            d.source = law_location(firing.where);
            if (auto c = st_.program.citations.find(firing.where.file); c != st_.program.citations.end()) d.citation = c->second;
            for (std::size_t i = 0; i < firing.binding.size(); ++i)
                if (firing.binding[i]) d.bindings.push_back(rule.slot_names[i] + " = " + e.values().print(*firing.binding[i]));
            d.absent = engine::absent_conditions(*st_.engine, firing);
        } else if (firing.kind == engine::Firing::Kind::closed_world) {
            d.law = "closed world";
            d.source = "the situation";
        } else {
            d.source = located(firing.where);
        }
        for (atms::NodeId a : just.antecedents) {
            // The assumption node behind a scene item reads as the item itself: skip the step
            // "item <- assume item".
            d.from.push_back(build(a));
        }
        // The closed world is one assumption for every `not` of the situation: say which facts'
        // absence this step used.
        if (!d.absent.empty())
            for (Derivation& f : d.from)
                if (f.fact == closed_world_text) {
                    f.fact = "the situation holds no ";
                    for (std::size_t i = 0; i < d.absent.size(); ++i) f.fact += (i ? ", no " : "") + d.absent[i];
                    f.fact += " (closed world: what it does not say is false)";
                }
        collapse_assumption_step(d);
        return d;
    }

    // The scene items the trees built so far rest on.
    [[nodiscard]] std::vector<std::string> items_used() const { return {items_used_.begin(), items_used_.end()}; }

private:
    void leaf(atms::NodeId n, Derivation& d) {
        const engine::Engine& e = *st_.engine;
        const auto& atms = e.atms();
        if (auto a = atms.assumption_of(n)) {
            if (const SceneItem* item = st_.facts->item(*a)) {
                d.fact = item->text;
                d.source = located(item->where);
            } else if (!e.fact_of(n)) {
                d.fact = closed_world_text;
            } else {
                d.fact = "assumed: " + d.fact;  // a choice (Law 1) or an assumption the laws made
            }
            return;
        }
        const auto& justs = atms.justifications(n);
        if (!justs.empty()) d.source = located(e.firing(atms.justification(justs.front()).informant).where);
    }
    // A fact justified only by its own assumption node is a leaf: drop the indirection.
    static void collapse_assumption_step(Derivation& d) {
        if (d.law.empty() && d.from.size() == 1 && d.from.front().fact == d.fact) {
            Derivation inner = std::move(d.from.front());
            d = std::move(inner);
        }
    }

    // A law's file:line relative to the rules folder, when it is in it (else as loaded).
    [[nodiscard]] std::string law_location(const SourceLocation& w) const {
        const std::filesystem::path rel = std::filesystem::path(w.file).lexically_relative(st_.options.rules_directory);
        const bool inside = !rel.empty() && *rel.begin() != "..";
        return (inside ? rel.generic_string() : w.file) + ":" + std::to_string(w.line);
    }
    static constexpr const char* closed_world_text = "the closed world of the situation (what it does not say is false)";

    const Analysis::State& st_;
    std::map<atms::NodeId, atms::JustId> by_consequent_;
    std::set<atms::NodeId> shown_;
    std::set<std::string> items_used_;
};

// The items of an environment. With one assumption per situation an environment names only the
// situation: then the items the derivation used stand for it (a sufficient set, maybe not minimal).
std::vector<std::string> item_texts(const Analysis::State& st, const atms::Environment& env,
                                    const TreeBuilder* used = nullptr) {
    if (used && st.facts->granularity() == Granularity::situation) return used->items_used();
    std::vector<std::string> out;
    for (atms::AssumptionId a : env.assumptions())
        if (const SceneItem* item = st.facts->item(a)) out.push_back(item->text);
    return out;
}

Exclusion explain_nogood(const Analysis::State& st, atms::EnvId nogood) {
    const atms::Explanation x = st.engine->atms().explain_nogood(nogood);
    TreeBuilder b(st, x);
    Derivation d = b.build(st.engine->atms().contradiction());
    return {item_texts(st, st.engine->atms().env(nogood), &b), std::move(d)};
}

void coarse_note(const Analysis::State& st, WhyAnswer& w) {
    if (st.facts->granularity() == Granularity::situation) {
        w.responsible_minimal = false;
        w.notes.push_back("this large scene is analysed one assumption per situation: each reason's contacts and "
                          "forces are those its derivation uses, a sufficient set that may not be minimal");
    }
}

// The distinct responsible sets of the exclusions, none a superset of another, smallest first.
std::vector<std::vector<std::string>> minimal_sets(const std::vector<Exclusion>& exclusions) {
    std::vector<std::vector<std::string>> sets;
    for (const Exclusion& x : exclusions) {
        std::vector<std::string> s = x.responsible;
        std::sort(s.begin(), s.end());
        sets.push_back(std::move(s));
    }
    std::sort(sets.begin(), sets.end(), [](const auto& a, const auto& b) { return a.size() != b.size() ? a.size() < b.size() : a < b; });
    sets.erase(std::unique(sets.begin(), sets.end()), sets.end());
    std::vector<std::vector<std::string>> out;
    for (const auto& s : sets)
        if (std::none_of(out.begin(), out.end(), [&](const auto& m) { return std::includes(s.begin(), s.end(), m.begin(), m.end()); }))
            out.push_back(s);
    return out;
}

// Whether `d` is the object's motion in some predicted combination of r; the first such combination
// as text in `example`.
bool predicted(const Analysis::State& st, const SituationResult& r, ObjectId o, bool translational, const Direction& d,
               std::string* example = nullptr) {
    for (const ChainMotions& chain : r.chains)
        for (std::size_t k = 0; k < chain.objects.size(); ++k)
            if (chain.objects[k] == o)
                for (const auto& combination : chain.combinations) {
                    if ((translational ? combination[k].translation : combination[k].rotation) != d) continue;
                    if (example)
                        for (std::size_t j = 0; j < chain.objects.size(); ++j)
                            *example += " " + st.scene.objects[chain.objects[j]].name + " " +
                                        thesis_text(combination[j].translation) + " " + thesis_text(combination[j].rotation);
                    return true;
                }
    return false;
}

// Above this many items in a situation the minimal responsible sets are not searched for by
// re-analysis (2^N contexts at most): the answer gives a sufficient set and says so.
constexpr std::size_t exact_item_limit = 8;

// The minimal sets of the situation's items (those of `base`) with which alone the situation still
// rules the motion out: each candidate set, smallest first, is analysed as a situation of just
// those items (a what-if context over the same engine), skipping supersets of sets found. nullopt
// when the situation has more than exact_item_limit items, or a re-analysis cannot be decided.
std::optional<std::vector<std::vector<std::string>>> minimal_by_reanalysis(Analysis::State& st, std::size_t s,
                                                                           atms::EnvId base, ObjectId o,
                                                                           bool translational, const Direction& d) {
    std::vector<const SceneItem*> items;
    for (const SceneItem* item : st.facts->items(s))
        if (item->assumption && st.engine->atms().env(base).contains(*item->assumption)) items.push_back(item);
    const std::size_t n = items.size();
    if (n > exact_item_limit) return std::nullopt;
    std::vector<std::uint32_t> masks;
    for (std::uint32_t m = 0; m + 1 < (1U << n); ++m) masks.push_back(m);  // the full set is known to rule it out
    std::stable_sort(masks.begin(), masks.end(), [](std::uint32_t a, std::uint32_t b) { return std::popcount(a) < std::popcount(b); });
    std::vector<std::uint32_t> found;
    for (std::uint32_t m : masks) {
        if (std::any_of(found.begin(), found.end(), [&](std::uint32_t f) { return (m & f) == f; })) continue;
        std::vector<atms::AssumptionId> members;
        for (std::size_t i = 0; i < n; ++i)
            if (m & (1U << i)) members.push_back(*items[i]->assumption);
        Diagnostics quiet;
        const engine::ContextRun run = st.engine->run_in_context(st.engine->atms().environment(members), quiet);
        if (quiet.has_errors()) return std::nullopt;
        const SituationResult r = st.read(s, run.environment);
        if (!r.complete) return std::nullopt;
        if (!predicted(st, r, o, translational, d)) found.push_back(m);
    }
    if (found.empty()) found.push_back((1U << n) - 1);
    std::vector<std::vector<std::string>> out;
    for (std::uint32_t m : found) {
        std::vector<std::string> set;
        for (std::size_t i = 0; i < n; ++i)
            if (m & (1U << i)) set.push_back(items[i]->text);
        std::sort(set.begin(), set.end());
        out.push_back(std::move(set));
    }
    return out;
}

// w's responsible sets: the exact minimal ones by re-analysis where the situation is small enough,
// else `together` (the items `reasons` rest on), which suffices but is not reduced.
void set_responsible(Analysis::State& st, WhyAnswer& w, const std::set<std::string>& together, std::size_t s,
                     atms::EnvId base, ObjectId o, bool translational, const Direction& d, const std::string& reasons) {
    if (st.facts->granularity() == Granularity::situation) {
        w.responsible_sets.push_back({together.begin(), together.end()});
    } else if (auto exact = minimal_by_reanalysis(st, s, base, o, translational, d)) {
        w.responsible_sets = std::move(*exact);
    } else {
        w.responsible_sets.push_back({together.begin(), together.end()});
        w.responsible_minimal = false;
        w.notes.push_back("responsible: the items " + reasons + " rest on, which together suffice; not reduced to "
                          "minimal sets (the situation has more than " + std::to_string(exact_item_limit) +
                          " contacts, forces and given motions to re-analyse without)");
    }
}

// A refutation of a motion by case analysis over the other choice sets of its kinematic chain
// (Law 1): a search that picks, at each step, the choice set with the fewest choices left open by
// the nogoods (so a forced motion is settled first), and backjumps: when the refutation below one
// choice does not use that choice, it refutes the whole step, and the other choices' nogoods are
// dropped. So the nogoods kept are those of the argument: the ones with the queried motion and the
// ones forcing the other motions they name; a nogood that excludes a motion the argument never
// needs (a pinned object's translations, say) is left out.
class Refuter {
public:
    Refuter(const atms::Atms& atms, std::vector<std::vector<atms::AssumptionId>> sets, std::vector<atms::EnvId> nogoods,
            atms::AssumptionId queried)
        : atms_(atms), sets_(std::move(sets)), nogoods_(std::move(nogoods)), queried_(queried) {
        for (std::size_t i = 0; i < nogoods_.size(); ++i)
            for (atms::AssumptionId a : atms_.env(nogoods_[i]).assumptions()) by_assumption_[a.value].push_back(i);
    }

    struct Proof {
        std::vector<atms::EnvId> nogoods;   // in the order the search met them
        atms::Environment involved;         // the assumptions those nogoods use
    };

    // nullopt: some choice from every set is consistent with `start`, or the search gave up (gave_up()).
    std::optional<Proof> refute(const atms::Environment& start) {
        for (std::size_t i = 0; i < nogoods_.size(); ++i)
            if (atms_.env(nogoods_[i]).subset_of(start)) return leaf(i);
        std::vector<char> assigned(sets_.size(), 0);
        return node(start, assigned);
    }
    [[nodiscard]] bool gave_up() const noexcept { return gave_up_; }
    static constexpr std::size_t node_budget = 200000;

private:
    Proof leaf(std::size_t i) {
        used_.insert(i);
        return {{nogoods_[i]}, atms_.env(nogoods_[i])};
    }
    // The nogood that closes `env` (which has c, and had no nogood without it): among those with
    // c, one already used, else one with the queried motion, else the smallest.
    std::optional<std::size_t> closing(const atms::Environment& env, atms::AssumptionId c) const {
        auto it = by_assumption_.find(c.value);
        if (it == by_assumption_.end()) return std::nullopt;
        std::optional<std::size_t> best;
        auto rank = [&](std::size_t i) {
            const atms::Environment& x = atms_.env(nogoods_[i]);
            return std::tuple(used_.count(i) ? 0 : 1, x.contains(queried_) ? 0 : 1, x.size(), i);
        };
        for (std::size_t i : it->second)
            if (atms_.env(nogoods_[i]).subset_of(env) && (!best || rank(i) < rank(*best))) best = i;
        return best;
    }
    std::optional<Proof> node(const atms::Environment& env, std::vector<char>& assigned) {
        if (++nodes_ > node_budget) gave_up_ = true;
        if (gave_up_) return std::nullopt;
        std::optional<std::size_t> pick;
        std::vector<std::optional<std::size_t>> closed, pick_closed;
        std::size_t best_open = 0, best_closed = 0;
        for (std::size_t k = 0; k < sets_.size(); ++k) {
            if (assigned[k]) continue;
            closed.clear();
            std::size_t open = 0;
            for (atms::AssumptionId c : sets_[k]) {
                closed.push_back(closing(env.with(c), c));
                if (!closed.back()) ++open;
            }
            const std::size_t shut = sets_[k].size() - open;
            if (!pick || open < best_open || (open == best_open && shut < best_closed)) {
                pick = k;
                best_open = open;
                best_closed = shut;
                pick_closed = closed;
            }
        }
        if (!pick) return std::nullopt;  // every set chosen, no nogood met: consistent
        const std::vector<atms::AssumptionId>& set = sets_[*pick];
        assigned[*pick] = 1;
        std::vector<std::size_t> order;  // open choices first: one of them may refute the whole step
        for (std::size_t i = 0; i < set.size(); ++i)
            if (!pick_closed[i]) order.push_back(i);
        for (std::size_t i = 0; i < set.size(); ++i)
            if (pick_closed[i]) order.push_back(i);
        Proof all;
        for (std::size_t i : order) {
            std::optional<Proof> p = pick_closed[i] ? leaf(*pick_closed[i]) : node(env.with(set[i]), assigned);
            if (!p) {
                assigned[*pick] = 0;
                return std::nullopt;
            }
            if (!p->involved.contains(set[i])) {  // this step's choice plays no part: backjump
                assigned[*pick] = 0;
                return p;
            }
            for (atms::EnvId ng : p->nogoods)
                if (std::find(all.nogoods.begin(), all.nogoods.end(), ng) == all.nogoods.end()) all.nogoods.push_back(ng);
            all.involved = join(all.involved, p->involved);
        }
        for (atms::AssumptionId c : set) all.involved.erase(c);
        assigned[*pick] = 0;
        return all;
    }

    const atms::Atms& atms_;
    std::vector<std::vector<atms::AssumptionId>> sets_;
    std::vector<atms::EnvId> nogoods_;
    atms::AssumptionId queried_;
    std::map<std::uint32_t, std::vector<std::size_t>> by_assumption_;
    std::set<std::size_t> used_;
    std::size_t nodes_ = 0;
    bool gave_up_ = false;
};

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

// The derivations of the nearness rank (Definition 38) of object o's motion d within `within`, if
// the laws rank it (the object has a net force; `prefer` in rules/nearness.rules): one, or where
// comparisons of causes branch (docs/LAWS.md, "Opposing causes") one per branch that `within` admits.
std::vector<Exclusion> rank_reasons(Analysis::State& st, ObjectId o, bool translational, const Direction& d,
                                    const atms::Environment& within) {
    const engine::Engine& e = *st.engine;
    const auto& atms = e.atms();
    const auto& set = translational ? st.choices[o].trans : st.choices[o].rot;
    const auto& dirs = translational ? st.choices[o].trans_dirs : st.choices[o].rot_dirs;
    const auto at = std::find(dirs.begin(), dirs.end(), d);
    std::vector<Exclusion> out;
    if (at == dirs.end()) return out;
    for (engine::FactId f : engine::rank_facts(e, set[static_cast<std::size_t>(at - dirs.begin())])) {
        const atms::NodeId n = e.node(f);
        for (atms::EnvId label_env : atms.label(n)) {
            if (!atms.env(label_env).subset_of(within)) continue;
            TreeBuilder b(st, atms.explain(n, label_env));
            Derivation tree = b.build(n);
            out.push_back(Exclusion{item_texts(st, atms.env(label_env), &b), std::move(tree)});
        }
    }
    return out;
}

// Most relevant first: nogoods with the queried motion, then those naming scene items, smaller
// ones first; otherwise in the order found.
void order_by_relevance(const Analysis::State& st, std::vector<atms::EnvId>& nogoods, atms::AssumptionId a) {
    const auto& atms = st.engine->atms();
    auto key = [&](atms::EnvId ng) {
        const atms::Environment& x = atms.env(ng);
        std::size_t items = 0;
        for (atms::AssumptionId b : x.assumptions())
            if (st.facts->item(b)) ++items;
        return std::tuple(x.contains(a) ? 0 : 1, items > 0 ? 0 : 1, x.size());
    };
    std::stable_sort(nogoods.begin(), nogoods.end(), [&](atms::EnvId x, atms::EnvId y) { return key(x) < key(y); });
}

}  // namespace

std::optional<WhyAnswer> Analysis::why(const QueryFact& query, std::size_t situation, Diagnostics& diagnostics) {
    QM_REQUIRE(situation >= 1 && situation <= state_->results.size(), "situation index out of range");
    if (state_->facts->granularity() == Granularity::situation &&
        state_->facts->items(situation).size() <= AnalysisOptions::auto_item_limit) {
        // The labels name only the situation: explain from an analysis of this situation with
        // one assumption per item, which names the responsible contacts and forces. (Above the
        // limit that analysis is too costly, and the coarse labels answer: see the note below.)
        auto fine = state_->restricted(situation, {}, {}, diagnostics, Granularity::item);
        if (!fine) return std::nullopt;
        Analysis one(std::move(fine));
        auto w = one.why(query, 1, diagnostics);
        if (w) {
            w->situation = situation;
            w->notes.push_back("explained from a per-item analysis of this situation (the scene is analysed one "
                               "assumption per situation)");
        }
        return w;
    }
    State& st = *state_;
    engine::Engine& e = *st.engine;
    auto& atms = e.atms();
    const std::string where = "--why";
    if (query.kind == QueryFact::Kind::contact || query.kind == QueryFact::Kind::force) {
        diagnostics.error({where, 1, 1}, "expected a motion or a freedom to explain (Translational-Motion, "
                                         "Rotational-Motion, Translational-Freedom, Rotational-Freedom), not a contact or force");
        return std::nullopt;
    }
    const ObjectId o = *query.object;
    const bool translational =
        query.kind == QueryFact::Kind::translational_motion || query.kind == QueryFact::Kind::translational_freedom;
    const bool motion =
        query.kind == QueryFact::Kind::translational_motion || query.kind == QueryFact::Kind::rotational_motion;
    const engine::ContextRun& run = st.runs[situation - 1];
    const atms::EnvId env = run.environment;
    const SituationResult& result = st.results[situation - 1];

    WhyAnswer w;
    w.situation = situation;
    w.query = std::string(translational ? "Translational-" : "Rotational-") + (motion ? "Motion" : "Freedom") + " (" +
              st.scene.objects[o].name + " " + thesis_text(query.direction) + ")";
    const std::vector<ValueId> args{st.facts->symbol(o), st.facts->direction(query.direction)};
    // A contact the laws cannot use changes every answer about the objects it joins: say so first.
    for (const Diagnostic& inert : inert_contacts(situation)) w.notes.push_back(located(inert.where) + ": " + inert.message);

    if (!motion) {
        // Def 24: free unless a law constrains it; the constraint's derivation is the answer.
        auto freedom = st.facts->find(translational ? v::trans_freedom : v::rot_freedom, args);
        if (freedom && atms.holds_in(e.node(*freedom), env)) {
            w.status = WhyAnswer::Status::holds;
            w.notes.push_back("no law constrains it in this situation (Definition 24)");
            return w;
        }
        auto constraint = st.facts->find(translational ? v::trans_constraint : v::rot_constraint, args);
        if (!constraint || !atms.holds_in(e.node(*constraint), env)) {
            diagnostics.error({where, 1, 1}, "the laws neither free nor constrain " + w.query +
                                                 ": expected the rules to define freedom (rules/freedom.rules)");
            return std::nullopt;
        }
        w.status = WhyAnswer::Status::ruled_out;
        const atms::NodeId n = e.node(*constraint);
        for (atms::EnvId label_env : atms.label(n)) {
            if (!atms.env(label_env).subset_of(atms.env(env))) continue;
            TreeBuilder b(st, atms.explain(n, label_env));
            Derivation d = b.build(n);
            w.exclusions.push_back({item_texts(st, atms.env(label_env), &b), std::move(d)});
        }
        w.responsible_sets = minimal_sets(w.exclusions);
        coarse_note(st, w);
        return w;
    }

    // A motion: does a selected combination have it?
    std::string example;
    if (predicted(st, result, o, translational, query.direction, &example)) {
        w.status = WhyAnswer::Status::holds;
        w.notes.push_back("consistent, and a predicted motion, e.g. with" + example);
        return w;
    }
    w.status = WhyAnswer::Status::ruled_out;
    const ObjectChoices& mine = st.choices[o];
    const auto& set = translational ? mine.trans : mine.rot;
    const auto& set_dirs = translational ? mine.trans_dirs : mine.rot_dirs;
    auto pos = std::find(set_dirs.begin(), set_dirs.end(), query.direction);
    if (pos == set_dirs.end()) {
        diagnostics.error({where, 1, 1}, "the laws give no such motion: " + w.query);
        return std::nullopt;
    }
    const atms::AssumptionId a = set[static_cast<std::size_t>(pos - set_dirs.begin())];
    const atms::Environment& base = atms.env(env);
    const atms::Environment with_a = base.with(a);

    // The chain's other choices: the assumptions a nogood may mention besides the situation's. The
    // branches enumerated with the chain (docs/ANALYSIS.md "Branches") are choices too.
    std::vector<std::vector<atms::AssumptionId>> sets;
    atms::Environment chain_choices;
    bool branched = false;
    for (std::size_t c = 0; c < result.chains.size(); ++c) {
        const ChainMotions& chain = result.chains[c];
        if (std::find(chain.objects.begin(), chain.objects.end(), o) == chain.objects.end()) continue;
        for (ObjectId x : chain.objects) {
            for (const auto* s : {&st.choices[x].trans, &st.choices[x].rot}) {
                for (atms::AssumptionId c2 : *s) chain_choices = chain_choices.with(c2);
                if (std::find(s->begin(), s->end(), a) == s->end()) sets.push_back(*s);
            }
        }
        if (situation - 1 < st.chain_branches.size() && c < st.chain_branches[situation - 1].size())
            for (std::uint32_t b : st.chain_branches[situation - 1][c]) {
                for (atms::AssumptionId c2 : st.branches.sets[b]) chain_choices = chain_choices.with(c2);
                sets.push_back(st.branches.sets[b]);
                branched = true;
            }
    }
    const atms::Environment scope = join(base, chain_choices);
    std::vector<atms::EnvId> relevant;
    for (atms::EnvId ng : atms.minimal_nogoods())
        if (atms.env(ng).subset_of(scope)) relevant.push_back(ng);

    // 1. Nogoods made of this motion and the situation alone: each one's items suffice (with
    //    the motion they are inconsistent), and together they are every minimal such set.
    std::vector<atms::EnvId> direct;
    for (atms::EnvId ng : relevant)
        if (atms.env(ng).contains(a) && atms.env(ng).subset_of(with_a)) direct.push_back(ng);
    if (!direct.empty()) {
        order_by_relevance(st, direct, a);
        for (atms::EnvId ng : direct) w.exclusions.push_back(explain_nogood(st, ng));
        w.responsible_sets = minimal_sets(w.exclusions);
        coarse_note(st, w);
        return w;
    }

    // Is the motion consistent with some choice of the chain's other motions?
    const atms::EnvId with_a_id = atms.environment(with_a.assumptions());
    const bool consistent =
        atms.for_each_interpretation(sets, with_a_id, [](const atms::Environment&) { return false; }) > 0;

    // 2. Inconsistent: a case analysis over the other motions of its chain (Refuter).
    if (!consistent) {
        const char* in_every_branch = branched ? ", in every branch of the laws (docs/ANALYSIS.md, Branches)" : "";
        Refuter refuter(atms, sets, relevant, a);
        std::optional<Refuter::Proof> proof = refuter.refute(with_a);
        if (!proof) {  // the search gave up: the exclusion stands (the ATMS found no consistent choice)
            w.notes.push_back("inconsistent with every choice of the other motions of its kinematic chain, but the "
                              "case analysis is too large to show (it stopped after " +
                              std::to_string(Refuter::node_budget) + " steps); --without can take parts away");
            w.responsible_minimal = false;
            coarse_note(st, w);
            return w;
        }
        std::vector<atms::EnvId> nogoods = proof->nogoods;
        order_by_relevance(st, nogoods, a);
        std::set<std::string> together;
        std::vector<atms::AssumptionId> fixed;  // other objects' motions the description alone rules out
        for (atms::EnvId ng : nogoods) {
            if (auto c = sole_choice(st, atms.env(ng)); c && *c != a) {
                fixed.push_back(*c);
                continue;
            }
            w.exclusions.push_back(explain_nogood(st, ng));
            together.insert(w.exclusions.back().responsible.begin(), w.exclusions.back().responsible.end());
        }
        if (proof->involved.contains(a))
            w.notes.push_back(std::string("excluded by case analysis over the other motions of its kinematic chain") +
                              in_every_branch + ": the first reasons rule it out together with motions of other "
                              "objects, the others rule out the alternatives to those motions");
        else
            w.notes.push_back(std::string("no combination of the motions of its kinematic chain is consistent in this "
                                          "situation") + in_every_branch + ", whatever this object does: these "
                              "nogoods exclude them all");
        if (!fixed.empty()) w.notes.push_back(description_alone_note(st, fixed));
        set_responsible(st, w, together, situation, env, o, translational, query.direction, "the reasons");
        coarse_note(st, w);
        return w;
    }

    if (!result.complete) {
        // Consistent, and not among the combinations listed before the limit: it may be a later one.
        diagnostics.error({where, 1, 1}, "cannot tell whether " + w.query + " is predicted: it is consistent, but the "
                                         "enumeration of its kinematic chain stopped at --limit " +
                                             std::to_string(st.options.combination_limit) + "; expected a larger --limit");
        return std::nullopt;
    }

    // 3. Consistent, but not what the forces produce (section 6.2, Definition 38).
    std::set<std::string> together;
    auto add = [&](Exclusion x) {
        together.insert(x.responsible.begin(), x.responsible.end());
        w.exclusions.push_back(std::move(x));
    };
    std::string predicted_example;
    for (const ChainMotions& chain : result.chains)
        if (std::find(chain.objects.begin(), chain.objects.end(), o) != chain.objects.end() && !chain.combinations.empty())
            for (std::size_t j = 0; j < chain.objects.size(); ++j)
                predicted_example += " " + st.scene.objects[chain.objects[j]].name + " " +
                                     thesis_text(chain.combinations.front()[j].translation) + " " +
                                     thesis_text(chain.combinations.front()[j].rotation);
    if (auto mine = rank_reasons(st, o, translational, query.direction, scope); !mine.empty()) {
        for (Exclusion& x : mine) add(std::move(x));
        w.notes.push_back("consistent, but not produced by the forces: other consistent combinations are nearer to "
                          "every net force (section 6.2, Definition 38), e.g. the predicted" + predicted_example);
    } else {
        // Not ranked itself (no force drives it): every consistent combination with it needs motions
        // of the driven objects that are farther from their net forces than a predicted one's. The
        // reasons are the ranks of those motions no predicted combination has (from the first few
        // such combinations).
        std::set<std::tuple<std::uint32_t, bool, std::size_t>> seen;
        std::size_t visited = 0;
        std::vector<ObjectId> chain_objects;
        for (const ChainMotions& chain : result.chains)
            if (std::find(chain.objects.begin(), chain.objects.end(), o) != chain.objects.end()) chain_objects = chain.objects;
        atms.for_each_interpretation(sets, with_a_id, [&](const atms::Environment& full) {
            for (ObjectId x : chain_objects)
                for (bool trans : {true, false}) {
                    const auto& xs = trans ? st.choices[x].trans : st.choices[x].rot;
                    const auto& xd = trans ? st.choices[x].trans_dirs : st.choices[x].rot_dirs;
                    for (std::size_t i = 0; i < xs.size(); ++i)
                        if (full.contains(xs[i]) && !predicted(st, result, x, trans, xd[i]) &&
                            seen.insert({x.value, trans, i}).second && w.exclusions.size() < 8)
                            for (Exclusion& r : rank_reasons(st, x, trans, xd[i], full)) add(std::move(r));
                }
            return ++visited < 32 && w.exclusions.size() < 8;
        });
        w.notes.push_back("consistent, but not produced by the forces: " + st.scene.objects[o].name +
                          " has no nearness rank of its own (no force drives it), and every consistent combination "
                          "with this motion needs motions of the driven objects that are farther from their net forces "
                          "(section 6.2, Definition 38) than those of a predicted combination, e.g." + predicted_example +
                          "; the reasons are the ranks of those motions");
    }
    set_responsible(st, w, together, situation, env, o, translational, query.direction, "the nearness ranks");
    coarse_note(st, w);
    return w;
}

}  // namespace qm::analysis
