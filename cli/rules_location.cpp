// cli/rules_location.cpp
#include "rules_location.hpp"
#include <cstdlib>
#include <system_error>

namespace qm::cli {

std::optional<std::filesystem::path> default_rules_directory() {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (const char* env = std::getenv("QM_ATMS_RULES"); env && *env) return fs::path(env);
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const fs::path installed = exe.parent_path().parent_path() / "share" / "qm-atms" / "rules";
        if (fs::is_directory(installed, ec)) return installed;
    }
#ifdef QM_RULES_SOURCE_DIR
    if (fs::is_directory(QM_RULES_SOURCE_DIR, ec)) return fs::path(QM_RULES_SOURCE_DIR);
#endif
    return std::nullopt;
}

}  // namespace qm::cli
