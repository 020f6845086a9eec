// cli/resource_limits.cpp: the limit options and their messages (cli/resource_limits.hpp).
#include "resource_limits.hpp"
#include <cctype>
#include <charconv>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <new>
#include <sys/resource.h>
#include <tuple>
#include <unistd.h>

#include "qm/address_sanitizer.hpp"

namespace qm::cli {
namespace {

constexpr std::uint64_t kib = 1024, mib = kib * 1024, gib = mib * 1024, tib = gib * 1024;

std::optional<std::uint64_t> applied_memory_limit;  // set by apply_memory_limit()

// A size: digits with an optional unit K, M, G or T (powers of 1024; a trailing B or iB allowed,
// any case), e.g. 4G, 512M, 1500000000.
std::optional<std::uint64_t> size_of(std::string_view s) {
    std::uint64_t n = 0;
    auto [p, ec] = std::from_chars(s.data(), s.data() + s.size(), n);
    if (ec != std::errc{} || p == s.data() || n == 0) return std::nullopt;
    std::string unit(p, s.data() + s.size());
    for (char& c : unit) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    if (unit.ends_with("IB")) unit.erase(unit.size() - 2);
    else if (unit.size() == 2 && unit[1] == 'B') unit.erase(1);
    std::uint64_t scale = 1;
    if (unit == "K") scale = kib;
    else if (unit == "M") scale = mib;
    else if (unit == "G") scale = gib;
    else if (unit == "T") scale = tib;
    else if (!unit.empty() && unit != "B") return std::nullopt;
    if (n > UINT64_MAX / scale) return std::nullopt;
    return n * scale;
}

// Ends the process when an exception cannot be thrown on (a std::bad_alloc in a noexcept function
// under the memory limit): the same message as main's, exit 2.
[[noreturn]] void on_terminate() {
    if (std::exception_ptr e = std::current_exception()) {
        try {
            std::rethrow_exception(e);
        } catch (const std::bad_alloc&) {
            if (applied_memory_limit) {
                const std::string m = "qm-atms: error: memory limit " + size_text(*applied_memory_limit) +
                                      " reached; raise it with --max-memory\n";
                [[maybe_unused]] auto w = ::write(2, m.data(), m.size());
                ::_exit(2);
            }
        } catch (...) {
        }
    }
    std::abort();
}

}  // namespace

std::uint64_t ResourceLimits::default_max_memory() {
    const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGE_SIZE);
    if (pages <= 0 || page <= 0) return 4 * gib;
    return static_cast<std::uint64_t>(pages) * static_cast<std::uint64_t>(page) / 2;
}

namespace {
constexpr const char* count_what = "a positive number";
constexpr const char* size_what = "a size like 4G, 512M or 2000000000 (bytes)";
}  // namespace

void declare_limit_options(CommandOptions& options, ResourceLimits& limits) {
    options.single("--max-facts", count_what, limits.given.facts);
    options.single("--max-environments", count_what, limits.given.environments);
    declare_memory_option(options, limits);
}

void declare_memory_option(CommandOptions& options, ResourceLimits& limits) {
    options.single("--max-memory", size_what, limits.given.memory);
}

std::optional<int> read_limit_options(const CommandOptions& options, ResourceLimits& limits, std::ostream& err) {
    for (auto [name, given, target] : {std::tuple{"--max-facts", &limits.given.facts, &limits.max_facts},
                                       std::tuple{"--max-environments", &limits.given.environments, &limits.max_environments}}) {
        if (!*given) continue;
        auto n = positive(**given);
        if (!n) return options.bad_value(err, name, **given);
        *target = *n;
    }
    if (limits.given.memory) {
        auto n = size_of(*limits.given.memory);
        if (!n) return options.bad_value(err, "--max-memory", *limits.given.memory);
        limits.max_memory = *n;
    }
    return std::nullopt;
}

std::string limits_usage() {
    return "  --max-facts N   stop with an error when the laws hold more than N facts (default 500000)\n"
           "  --max-environments N\n"
           "                  stop with an error when the ATMS holds more than N environments (default 1000000)\n" +
           std::string(memory_usage());
}

const char* memory_usage() noexcept {
    return "  --max-memory SIZE\n"
           "                  stop with an error when the process needs more memory, e.g. 4G or 512M\n"
           "                  (default: half the machine's)\n";
}

void apply_memory_limit(const ResourceLimits& limits) {
    std::set_terminate(on_terminate);
#ifndef QM_UNDER_ASAN
    rlimit r{};
    if (::getrlimit(RLIMIT_AS, &r) != 0) return;
    const rlim_t want = static_cast<rlim_t>(limits.max_memory);
    if (r.rlim_max != RLIM_INFINITY && want > r.rlim_max) return;  // a lower hard limit is already set
    r.rlim_cur = want;
    if (::setrlimit(RLIMIT_AS, &r) == 0) applied_memory_limit = limits.max_memory;
#else
    (void)limits;
#endif
}

std::string limit_message(const LimitReached& limit, const std::string& doing) {
    std::string where = "qm-atms: ";
    if (limit.where) where = to_string(*limit.where) + ": ";
    const char* option = limit.kind == LimitReached::Kind::facts          ? "--max-facts"
                         : limit.kind == LimitReached::Kind::environments ? "--max-environments"
                                                                          : "--max-states";
    return where + "error: " + limit_noun(limit.kind) + " limit " + std::to_string(limit.limit) + " reached while " +
           (limit.doing.empty() ? doing : limit.doing) + "; raise it with " + option + "\n";
}

std::optional<std::string> memory_limit_message(const std::string& doing) {
    if (!applied_memory_limit) return std::nullopt;
    return "qm-atms: error: memory limit " + size_text(*applied_memory_limit) + " reached while " + doing +
           "; raise it with --max-memory\n";
}

std::string size_text(std::uint64_t bytes) {
    for (auto [scale, unit] : {std::pair{tib, 'T'}, std::pair{gib, 'G'}, std::pair{mib, 'M'}, std::pair{kib, 'K'}}) {
        if (bytes < scale) continue;
        if (bytes % scale == 0) return std::to_string(bytes / scale) + unit;
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.1f%c", static_cast<double>(bytes) / static_cast<double>(scale), unit);
        return buf;
    }
    return std::to_string(bytes) + " bytes";
}

}  // namespace qm::cli
