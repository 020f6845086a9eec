// atms/environment_table.hpp
// Provides:   EnvironmentTable, which interns environments (the BPS env table): equal assumption
//             sets always get the same EnvId, so comparing environments is comparing ids. Per env it
//             caches the size, the nogood flag and the nodes whose labels have held it; it indexes
//             environments by assumption and memoises unions. The interning index is an
//             open-addressing table of ids (the environment itself is stored once, in its entry).
// Ownership:  owns every Environment it hands out; ids and references stay valid for its lifetime
//             (references into the table may be invalidated by interning; ids never are).
// Invariants: the nogood flag of an env is true iff some nogood of the NogoodDatabase passed to
//             intern()/join() is a subset of it, provided the owner calls mark_nogood on every
//             superset when a nogood is added (Atms does).
// Limit:      an optional bound on the number of environments (set_limit): interning one more
//             throws qm::LimitReached (qm/limit_reached.hpp) before anything changes here; the
//             caller (an Atms mid-update) must then be discarded. Without it a runaway program
//             fills the machine's memory with environments.
// Knows nothing of justifications or rules.
#pragma once
#include "qm/assert.hpp"
#include "atms/environment.hpp"
#include "atms/ids.hpp"
#include "atms/nogood_database.hpp"
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

namespace qm::atms {
class EnvironmentTable {
public:
    EnvironmentTable() = default;
    EnvironmentTable(const EnvironmentTable&) = delete;
    EnvironmentTable& operator=(const EnvironmentTable&) = delete;

    // The id of e, creating it (with its nogood flag from `nogoods`) if new.
    EnvId intern(const Environment& e, const NogoodDatabase& nogoods);
    // The same for an env the caller has just found consistent (weave's results), sparing the
    // nogood test. Pre: !nogoods.subsumes(e) (checked by QM_ASSERT).
    EnvId intern_consistent(const Environment& e, const NogoodDatabase& nogoods);
    // The union of x and y, memoised. Pre: x, y valid.
    EnvId join(EnvId x, EnvId y, const NogoodDatabase& nogoods);

    [[nodiscard]] std::size_t size() const noexcept { return envs_.size(); }
    // At most `n` environments from now on (none: no limit).
    void set_limit(std::optional<std::size_t> n) { limit_ = n; }
    [[nodiscard]] bool contains(EnvId e) const noexcept { return envs_.contains(e); }
    // Pre (checked, also in release builds: an unknown id is an InternalError): e valid.
    [[nodiscard]] const Environment& operator[](EnvId e) const { return entry(e).env; }
    [[nodiscard]] std::uint32_t count(EnvId e) const { return entry(e).count; }  // |e|
    [[nodiscard]] bool is_nogood(EnvId e) const { return entry(e).nogood; }
    void mark_nogood(EnvId e) { envs_[checked(e)].nogood = true; }
    // x is a subset of y (size and signature checks first).
    [[nodiscard]] bool subset(EnvId x, EnvId y) const;
    // The OR of e's words: bit i set iff e has an assumption congruent to i modulo 64. x is a
    // subset of y only if signature(x) is a subset of signature(y).
    [[nodiscard]] std::uint64_t signature(EnvId e) const { return entry(e).sig; }
    // Nodes whose label has held e (the BPS env-nodes field); may list nodes that dropped e since.
    [[nodiscard]] const std::vector<NodeId>& nodes(EnvId e) const { return entry(e).nodes; }
    void add_node(EnvId e, NodeId n) { envs_[checked(e)].nodes.push_back(n); }
    // Every interned env containing a, in creation order.
    [[nodiscard]] const std::vector<EnvId>& containing(AssumptionId a) const;

private:
    EnvId add(const Environment& e, std::size_t hash, bool nogood);  // Pre: e not interned yet
    [[nodiscard]] std::optional<EnvId> find(const Environment& e, std::size_t hash) const noexcept;
    void grow();  // doubles slots_, re-placing every id by its stored hash
    struct Entry {
        Environment env;
        std::size_t hash = 0;
        std::uint64_t sig = 0;
        std::uint32_t count = 0;
        bool nogood = false;
        std::vector<NodeId> nodes;
    };
    [[nodiscard]] EnvId checked(EnvId e) const {
        QM_REQUIRE(envs_.contains(e), "unknown environment id");
        return e;
    }
    [[nodiscard]] const Entry& entry(EnvId e) const { return envs_[checked(e)]; }
    IdVector<EnvId, Entry> envs_;
    std::vector<std::uint32_t> slots_;  // power-of-two size, linear probing; EnvId + 1, 0 = free
    std::unordered_map<std::uint64_t, EnvId> joins_;  // key: (min id << 32) | max id
    std::vector<std::vector<EnvId>> by_assumption_;   // indexed by AssumptionId::value
    std::vector<EnvId> none_;
    std::optional<std::size_t> limit_;
};
}  // namespace qm::atms
