// cli/geometry_usage.hpp
// Provides:   the usage lines of the commands that need the geometry stack (FCL, geometry/,
//             bridge/, envision/): --emit-def and --places (cli/metric_command.hpp), draw
//             (cli/draw_command.hpp), explore (cli/explore_command.hpp) and envision
//             (cli/envision_command.hpp), for `--help` and each command's usage error.
// Errors:     none.
#pragma once

namespace qm::cli {
[[nodiscard]] const char* metric_usage() noexcept;
[[nodiscard]] const char* draw_usage() noexcept;
[[nodiscard]] const char* explore_usage() noexcept;
[[nodiscard]] const char* envision_usage() noexcept;
}  // namespace qm::cli
