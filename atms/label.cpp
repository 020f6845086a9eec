// atms/label.cpp: minimal-label maintenance (de Kleer 1986, section 4).
#include "atms/label.hpp"

#include <algorithm>

namespace qm::atms {
bool label_subsumes(const Label& label, EnvId env, const EnvironmentTable& table) {
    return std::any_of(label.begin(), label.end(), [&](EnvId l) { return table.subset(l, env); });
}

bool label_add_minimal(Label& label, EnvId env, const EnvironmentTable& table) {
    if (label_subsumes(label, env, table)) return false;
    std::erase_if(label, [&](EnvId l) { return table.subset(env, l); });
    label.insert(std::lower_bound(label.begin(), label.end(), env), env);
    return true;
}

bool label_is_minimal(const Label& label, const EnvironmentTable& table) {
    if (!std::is_sorted(label.begin(), label.end())) return false;
    for (std::size_t i = 0; i < label.size(); ++i)
        for (std::size_t j = 0; j < label.size(); ++j)
            if (i != j && table.subset(label[i], label[j])) return false;  // also catches duplicates
    return true;
}
}  // namespace qm::atms
