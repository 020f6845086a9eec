// atms/label_update.hpp
// Provides:   weave(), the core of de Kleer's label update (1986, section 4; BPS atms.lisp `weave`):
//             given the new envs of one antecedent, combine them with the labels of the other
//             antecedents of a justification into the minimal consistent unions.
// Ownership:  pure function over the caller's table. Intermediate unions are scratch bitsets
//             (detail/minimal_sets.hpp); only the returned minimal consistent unions are interned.
// Knows nothing of nodes or justifications beyond the labels it is handed.
#pragma once
#include "atms/detail/minimal_sets.hpp"
#include "atms/environment_table.hpp"
#include "atms/label.hpp"
#include "atms/nogood_database.hpp"
#include <span>
#include <vector>

namespace qm::atms {
// Returns the minimal (under inclusion) consistent envs of the form e ∪ l1 ∪ ... ∪ lk with e in
// `envs` and li in *labels[i]. Empty if any label is empty.
// Pre: envs are valid ids in table; labels are minimal labels over table.
[[nodiscard]] std::vector<EnvId> weave(EnvironmentTable& table, const NogoodDatabase& nogoods,
                                       std::vector<EnvId> envs, std::span<const Label* const> labels);
// The same, forming the unions in `scratch` (reused across calls by Atms, so nothing is allocated
// per call once it has grown).
[[nodiscard]] std::vector<EnvId> weave(EnvironmentTable& table, const NogoodDatabase& nogoods,
                                       std::span<const EnvId> envs, std::span<const Label* const> labels,
                                       detail::WeaveScratch& scratch);
}  // namespace qm::atms
