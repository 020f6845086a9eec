// cli/geometry_usage.hpp
// Provides:   the usage lines of the commands that need the geometry stack (FCL, geometry/,
//             bridge/, envision/): --emit-def and --places (cli/metric_command.hpp), draw
//             (cli/draw_command.hpp), explore (cli/explore_command.hpp) and envision
//             (cli/envision_command.hpp). They live apart from those commands so that the light
//             qm-atms, which links none of the geometry stack (cli/geometry_dispatch.hpp,
//             docs/perf/startup.md), prints the whole `--help` itself instead of starting
//             qm-atms-geometry for it.
// Errors:     none.
#pragma once

namespace qm::cli {
[[nodiscard]] const char* metric_usage() noexcept;
[[nodiscard]] const char* draw_usage() noexcept;
[[nodiscard]] const char* explore_usage() noexcept;
[[nodiscard]] const char* envision_usage() noexcept;
}  // namespace qm::cli
