// analysis/why_responsible.cpp: responsible sets of --why answers (analysis/detail/why_responsible.hpp),
// read off the exclusions or found exactly by re-analysing subsets of the situation's items.
#include "analysis/detail/why_responsible.hpp"
#include "scene/direction_text.hpp"
#include <algorithm>
#include <bit>
#include "qm/assert.hpp"

namespace qm::analysis::detail {

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
               std::string* example) {
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

namespace {

// The minimal sets of the situation's items (those of `base`) with which alone the situation still
// rules the motion out: each candidate set, smallest first, is analysed as a situation of just
// those items (a what-if context over the same engine), skipping supersets of sets found. nullopt
// when the situation has more than st.options.why.exact_items items (2^N contexts at most), or a
// re-analysis cannot be decided.
std::optional<std::vector<std::vector<std::string>>> minimal_by_reanalysis(Analysis::State& st, std::size_t s,
                                                                           atms::EnvId base, ObjectId o,
                                                                           bool translational, const Direction& d) {
    std::vector<const SceneItem*> items;
    for (const SceneItem* item : st.facts->items(s))
        if (item->assumption && st.engine->atms().env(base).contains(*item->assumption)) items.push_back(item);
    const std::size_t n = items.size();
    QM_REQUIRE(st.options.why.exact_items < 32, "WhyLimits::exact_items is below 32");
    if (n > st.options.why.exact_items) return std::nullopt;
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

}  // namespace

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
                          "minimal sets (the situation has more than " + std::to_string(st.options.why.exact_items) +
                          " contacts, forces and given motions to re-analyse without)");
    }
}

}  // namespace qm::analysis::detail
