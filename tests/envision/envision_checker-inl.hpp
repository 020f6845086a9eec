// tests/envision/envision_checker-inl.hpp: the checker's transitions (see envision_checker.hpp).
#pragma once

namespace qm::envision::checker {

namespace detail {

struct PlaceOption {
    std::uint32_t place;
    int how;  // 0 stay, 1 move, 2 wrap
};
struct Step {
    bool instant = false;
    std::uint8_t cause = 0;
    std::vector<std::vector<PlaceOption>> places;
    std::vector<std::vector<std::int8_t>> motions;
};

inline std::int8_t sign_sum(std::int8_t a, std::int8_t b) {
    if (a == 0) return b;
    if (b == 0) return a;
    if (a == ambiguous || b == ambiguous || a != b) return ambiguous;
    return a;
}

inline std::vector<g::QualDirection> resolutions(std::array<std::int8_t, 2> d) {
    std::vector<g::QualDirection> out;
    for (std::int8_t x = -1; x <= 1; ++x)
        for (std::int8_t y = -1; y <= 1; ++y)
            if ((d[0] == ambiguous || d[0] == x) && (d[1] == ambiguous || d[1] == y)) out.push_back(g::QualDirection{{x, y}});
    return out;
}

// Def 38 for one-component motions, up to 8.3.4's zero threshold.
inline int rank(std::int8_t h, std::int8_t m) { return m == h ? 0 : m == 0 ? 2 : 3; }

}  // namespace detail

inline std::set<Edge> Checker::successors(const Key& s, const std::set<Key>& all) const {
    using detail::PlaceOption;
    using detail::Step;
    const std::size_t n = s.motions.size();
    const auto net = net_force(s);
    std::vector<std::vector<std::pair<std::int8_t, int>>> table(n);
    bool motion_due = false, motion_instant = false, motion_interval = false;
    for (std::size_t o = 0; o < n; ++o) {
        table[o] = table_5_1(s.motions[o], net[o]);
        bool persists = false;
        for (const auto& [next, how] : table[o]) {
            persists = persists || how == 0;
            motion_instant = motion_instant || how == 1;
            motion_interval = motion_interval || how == 2;
        }
        motion_due = motion_due || !persists;
    }
    // Next places (8.1.3, 8.3.2).
    std::vector<std::vector<PlaceOption>> instant(pairs_.size()), later(pairs_.size());
    bool place_instant = false, place_due = false, place_later = false;
    for (std::size_t k = 0; k < pairs_.size(); ++k) {
        const auto v = pair_motion(k, s.motions);
        for (const auto& a : pairs_[k]->vocabulary.adjacency) {
            if (a.from.value != s.places[k] || a.motion != v || a.constrained) continue;
            if (a.instantaneous) {
                instant[k].push_back({a.to.value, 1});
            } else if (a.to != a.from) {
                later[k].push_back({a.to.value, 1});
            } else {
                bool bounded = false;
                for (int i = 0; i < 2; ++i) bounded = bounded || (!request_[k].cspace.axes[static_cast<std::size_t>(i)].periodic && v.s[static_cast<std::size_t>(i)] != 0);
                if (!bounded) later[k].push_back({a.to.value, 2});  // no wrapping along a bounded axis
            }
        }
        place_instant = place_instant || !instant[k].empty();
        place_due = place_due || (!instant[k].empty() && later[k].empty());
        place_later = place_later || !later[k].empty();
    }
    // Laws 3-4: the steps, each with the steps that come before it (a step happens only if none of
    // those can: the held changes of docs/LAWS.md).
    std::vector<Step> steps;
    auto stay = [&](std::size_t k) { return PlaceOption{s.places[k], 0}; };
    auto persist = [&](std::size_t o) { return std::vector<std::int8_t>{s.motions[o]}; };
    const bool due = place_due || motion_due;
    int ik = -1, id = -1, intk = -1, intd = -1;
    if (place_instant) {
        Step st{true, 1, {}, {}};
        for (std::size_t k = 0; k < pairs_.size(); ++k) {
            auto opts = instant[k];
            if (instant[k].empty() || !later[k].empty()) opts.push_back(stay(k));
            st.places.push_back(opts);
        }
        for (std::size_t o = 0; o < n; ++o) st.motions.push_back(persist(o));
        ik = static_cast<int>(steps.size());
        steps.push_back(st);
    }
    if (motion_instant) {
        Step st{true, 2, {}, {}};
        for (std::size_t k = 0; k < pairs_.size(); ++k) st.places.push_back({stay(k)});
        for (std::size_t o = 0; o < n; ++o) {
            std::vector<std::int8_t> opts;
            for (const auto& [next, how] : table[o])
                if (how == 0 || how == 1) opts.push_back(next);
            st.motions.push_back(opts);
        }
        id = static_cast<int>(steps.size());
        steps.push_back(st);
    }
    if (place_later) {
        Step st{false, 1, {}, {}};
        for (std::size_t k = 0; k < pairs_.size(); ++k) {
            auto opts = later[k];
            opts.push_back(stay(k));
            st.places.push_back(opts);
        }
        for (std::size_t o = 0; o < n; ++o) st.motions.push_back(persist(o));
        intk = static_cast<int>(steps.size());
        steps.push_back(st);
    }
    if (motion_interval) {
        Step st{false, 2, {}, {}};
        for (std::size_t k = 0; k < pairs_.size(); ++k) st.places.push_back({stay(k)});
        for (std::size_t o = 0; o < n; ++o) {
            std::vector<std::int8_t> opts;
            bool persists = false;
            for (const auto& [next, how] : table[o]) {
                if (how == 0 || how == 2) opts.push_back(next);
                persists = persists || how == 0;
            }
            if (!persists) opts.push_back(s.motions[o]);  // a change due in an instant that could not happen
            st.motions.push_back(opts);
        }
        intd = static_cast<int>(steps.size());
        steps.push_back(st);
    }
    std::vector<std::vector<int>> before(steps.size());  // the steps that preempt each
    if (ik >= 0 && id >= 0) before[static_cast<std::size_t>(id)].push_back(ik);
    if (due)
        for (const int later_step : {intk, intd})
            for (const int first : {ik, id})
                if (later_step >= 0 && first >= 0) before[static_cast<std::size_t>(later_step)].push_back(first);

    // Arrivals: persistence, collisions (5.3.3), the ends of bounded axes.
    auto arrival = [&](std::size_t k, PlaceOption q, g::QualDirection v) {
        std::vector<g::QualDirection> out;
        const g::Place& p = pairs_[k]->vocabulary.places[q.place];
        if (q.how == 0 || q.how == 2) return std::vector<g::QualDirection>{v};
        if (!blocked(k, q.place, v)) return std::vector<g::QualDirection>{v};
        std::vector<std::array<std::int8_t, 2>> pushes;
        std::array<std::int8_t, 2> sum{0, 0};
        for (const auto nn : p.normals) {
            pushes.push_back({detail::sign_sum(v.s[0], nn.s[0]), detail::sign_sum(v.s[1], nn.s[1])});
            sum = {detail::sign_sum(sum[0], nn.s[0]), detail::sign_sum(sum[1], nn.s[1])};
        }
        if (!p.normals.empty()) pushes.push_back({detail::sign_sum(v.s[0], sum[0]), detail::sign_sum(v.s[1], sum[1])});
        for (const auto& push : pushes)
            for (const auto x : detail::resolutions(push)) {
                const bool leaves = std::all_of(p.normals.begin(), p.normals.end(), [&](auto nn) { return g::qdot(nn, x) == g::QualSign::pos; });
                if (!blocked(k, q.place, x) && !leaves && std::find(out.begin(), out.end(), x) == out.end()) out.push_back(x);
            }
        return out;
    };

    std::vector<std::map<std::pair<Key, bool>, std::uint8_t>> found_by(steps.size());
    for (std::size_t step_index = 0; step_index < steps.size(); ++step_index) {
        const Step& st = steps[step_index];
        auto& found = found_by[step_index];
        std::vector<PlaceOption> q(pairs_.size());
        // Each combination of next places, then each collision branch, then the chain made consistent.
        std::function<void(std::size_t)> places = [&](std::size_t k) {
            if (k < pairs_.size()) {
                for (const auto o : st.places[k]) {
                    if (o.how == 0 && std::any_of(st.places[k].begin(), st.places[k].end(), [](auto x) { return x.how == 2; })) continue;
                    q[k] = o;
                    places(k + 1);
                }
                return;
            }
            std::vector<std::pair<std::size_t, std::vector<g::QualDirection>>> changed;
            for (std::size_t p = 0; p < pairs_.size(); ++p) {
                std::vector<g::QualDirection> afters;
                bool same = true;
                for (const auto ma : st.motions[ends_[p].first])
                    for (const auto mb : st.motions[ends_[p].second]) {
                        const g::QualDirection v{{ma, mb}};
                        for (const auto x : arrival(p, q[p], v)) {
                            same = same && x == v;
                            if (std::find(afters.begin(), afters.end(), x) == afters.end()) afters.push_back(x);
                        }
                    }
                if (afters.empty()) return;
                if (!same) changed.push_back({p, afters});
            }
            std::vector<g::QualDirection> branch(changed.size());
            std::function<void(std::size_t)> branches = [&](std::size_t i) {
                if (i < changed.size()) {
                    for (const auto x : changed[i].second) {
                        branch[i] = x;
                        branches(i + 1);
                    }
                    return;
                }
                // The motions the branch's collisions give each part (several where two collisions
                // meet it).
                std::vector<std::set<std::int8_t>> fixed(n);
                for (std::size_t c = 0; c < changed.size(); ++c) {
                    const auto [a, b] = ends_[changed[c].first];
                    fixed[a].insert(branch[c].s[0]);
                    fixed[b].insert(branch[c].s[1]);
                }
                bool wraps = false;
                std::uint8_t causes = static_cast<std::uint8_t>(st.cause | (changed.empty() ? 0 : 4));
                std::vector<std::uint32_t> target;
                for (std::size_t k2 = 0; k2 < q.size(); ++k2) {
                    wraps = wraps || q[k2].how == 2;
                    if (q[k2].place != s.places[k2] || q[k2].how == 2) causes |= 1;
                    target.push_back(q[k2].place);
                }
                // 3.3: a part no state at these places lets start as the step says (the colliding
                // parts as the collision fixes them, the other parts that must change changing or
                // staying) cannot move: it stays as it is, and the others go on.
                auto allows = [&](std::size_t o, std::int8_t m) { return std::find(st.motions[o].begin(), st.motions[o].end(), m) != st.motions[o].end(); };
                auto must_change = [&](std::size_t o) { return !allows(o, s.motions[o]); };
                // 8.3.4: where no state at these places lets every colliding part move as its
                // collisions give it (the others that must change changing or staying), each keeps
                // its outcome or stops, the nearest preferred.
                bool collision_reach = false;
                for (const Key& t : all) {
                    if (t.places != target || collision_reach) continue;
                    bool ok = true;
                    for (std::size_t p = 0; p < n && ok; ++p) {
                        if (!fixed[p].empty()) ok = fixed[p] == std::set<std::int8_t>{t.motions[p]};
                        else if (must_change(p)) ok = allows(p, t.motions[p]) || t.motions[p] == s.motions[p];
                    }
                    collision_reach = ok;
                }
                auto collided_ok = [&](std::size_t o, std::int8_t m) {
                    if (fixed[o] == std::set<std::int8_t>{m}) return true;
                    return !collision_reach && m == 0;
                };
                std::vector<bool> reach(n, false);
                for (const Key& t : all) {
                    if (t.places != target) continue;
                    for (std::size_t o = 0; o < n; ++o) {
                        if (!allows(o, t.motions[o])) continue;
                        bool others = true;
                        for (std::size_t p = 0; p < n; ++p) {
                            if (p == o) continue;
                            if (!fixed[p].empty()) others = others && collided_ok(p, t.motions[p]);
                            else if (must_change(p)) others = others && (allows(p, t.motions[p]) || t.motions[p] == s.motions[p]);
                        }
                        reach[o] = reach[o] || others;
                    }
                }
                std::vector<const Key*> cands;
                std::vector<std::vector<int>> ranks;
                for (const Key& t : all) {
                    if (t.places != target) continue;
                    bool ok = true;
                    std::vector<int> r;
                    for (std::size_t o = 0; o < n && ok; ++o) {
                        const auto& opts = st.motions[o];
                        const bool in = std::find(opts.begin(), opts.end(), t.motions[o]) != opts.end();
                        const bool must = std::find(opts.begin(), opts.end(), s.motions[o]) == opts.end();
                        if (!fixed[o].empty()) {
                            ok = collided_ok(o, t.motions[o]);
                            if (ok && !collision_reach) {  // its outcome or rest: the preference chooses
                                int best = 3;
                                for (const auto y : opts) best = std::min(best, detail::rank(y, t.motions[o]));
                                r.push_back(best);
                            }
                        } else if (must && !reach[o]) ok = t.motions[o] == s.motions[o];
                        else if (must) ok = in;
                        else {
                            int best = 3;
                            for (const auto y : opts) best = std::min(best, detail::rank(y, t.motions[o]));
                            r.push_back(best);
                        }
                    }
                    if (ok) {
                        cands.push_back(&t);
                        ranks.push_back(r);
                    }
                }
                for (std::size_t i2 = 0; i2 < cands.size(); ++i2) {
                    bool dominated = false;
                    for (std::size_t j = 0; j < cands.size() && !dominated; ++j) {
                        bool le = true, lt = false;
                        for (std::size_t c = 0; c < ranks[j].size(); ++c) {
                            le = le && ranks[j][c] <= ranks[i2][c];
                            lt = lt || ranks[j][c] < ranks[i2][c];
                        }
                        dominated = le && lt;
                    }
                    if (dominated || (*cands[i2] == s && !wraps)) continue;
                    found[{*cands[i2], st.instant}] |= causes;
                }
            };
            branches(0);
        };
        places(0);
    }
    // Steps are listed so that those that preempt come first.
    std::vector<bool> kept(steps.size(), false);
    std::map<std::pair<Key, bool>, std::uint8_t> merged;
    for (std::size_t i = 0; i < steps.size(); ++i) {
        bool preempted = false;
        for (const int first : before[i]) preempted = preempted || kept[static_cast<std::size_t>(first)];
        kept[i] = !preempted && !found_by[i].empty();
        if (kept[i])
            for (const auto& [key, causes] : found_by[i]) merged[key] |= causes;
    }
    std::set<Edge> out;
    for (const auto& [key, causes] : merged) out.insert({key.first, key.second, causes});
    return out;
}

}  // namespace qm::envision::checker
