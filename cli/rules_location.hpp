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
// default_rule_cache(), where the compiled laws are kept between runs (engine/program_cache.hpp):
// $QM_RULE_CACHE (`off`: no cache); $XDG_CACHE_HOME/qm-atms/rules; ~/.cache/qm-atms/rules; else
// none (empty). A folder that cannot be created or written only means no cache.
[[nodiscard]] std::filesystem::path default_rule_cache();
}
