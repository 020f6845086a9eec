// atms/label.hpp
// Provides:   Label (a node's label: a sorted vector of EnvId, minimal under set inclusion) and the
//             two operations on it that the label update needs (de Kleer 1986, section 4).
// Ownership:  a value; environments are referred to by id into one EnvironmentTable.
// Invariants: sorted by EnvId, no duplicates, no env a proper subset of another (minimal).
// Knows nothing of nodes or justifications.
#pragma once
#include "atms/environment_table.hpp"
#include "atms/ids.hpp"
#include <vector>

namespace qm::atms {
using Label = std::vector<EnvId>;

// Some env of `label` is a subset of env (so env adds nothing to the label).
[[nodiscard]] bool label_subsumes(const Label& label, EnvId env, const EnvironmentTable& table);
// Adds env unless subsumed, removing the envs it subsumes (proper supersets). Returns true if added.
bool label_add_minimal(Label& label, EnvId env, const EnvironmentTable& table);
// True iff the label is sorted, duplicate-free and minimal (for assertions and tests).
[[nodiscard]] bool label_is_minimal(const Label& label, const EnvironmentTable& table);
}  // namespace qm::atms
