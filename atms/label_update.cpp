// atms/label_update.cpp: weave, de Kleer 1986 section 4 (BPS atms.lisp `weave`).
#include "atms/label_update.hpp"

#include <utility>

namespace qm::atms {
std::vector<EnvId> weave(EnvironmentTable& table, const NogoodDatabase& nogoods, std::vector<EnvId> envs,
                         std::span<const Label* const> labels) {
    std::vector<EnvId> next;
    for (const Label* label : labels) {
        next.clear();
        for (EnvId e : envs) {
            for (EnvId l : *label) {
                const EnvId u = table.join(e, l, nogoods);
                // An inconsistent union can never support the consequent: drop it now, so later
                // unions stay small (the "remove nogoods" step of the update).
                if (table.is_nogood(u)) continue;
                label_add_minimal(next, u, table);
            }
        }
        std::swap(envs, next);
        if (envs.empty()) break;
    }
    return envs;
}
}  // namespace qm::atms
