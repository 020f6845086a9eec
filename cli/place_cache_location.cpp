// cli/place_cache_location.cpp
#include "place_cache_location.hpp"
#include <cstdlib>

namespace qm::cli {

std::filesystem::path default_place_cache() {
    if (const char* p = std::getenv("QM_PLACE_CACHE"); p && *p) return p;
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::filesystem::path(x) / "qm-atms" / "places";
    if (const char* h = std::getenv("HOME"); h && *h) return std::filesystem::path(h) / ".cache" / "qm-atms" / "places";
    return {};
}

}  // namespace qm::cli
