// cli/rules_location.hpp
// Provides:   default_rules_directory(), where `qm-atms` finds the laws when --rules is not given:
//             found relative to the executable, never the working directory. In order:
//             $QM_ATMS_RULES; <exe>/../share/qm-atms/rules (an installed tree); the source tree's
//             rules/ that the executable was built from.
// Ownership:  returns a path value.
#pragma once
#include <filesystem>
#include <optional>

namespace qm::cli {
[[nodiscard]] std::optional<std::filesystem::path> default_rules_directory();
}
