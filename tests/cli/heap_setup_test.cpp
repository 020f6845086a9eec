// tests/cli/heap_setup_test.cpp: prepare_heap() (cli/heap_setup.hpp) in this test's own process. The
// reserve is advised into huge pages (VmFlags "hg") from just below a 2 MiB boundary, and nothing at
// or above that boundary was touched before the advice: a page touched there first would be a 4 KiB
// page, and its whole 2 MiB range would stay in 4 KiB pages (about 10 us a fault on a virtual
// machine, docs/perf/startup.md, "Fourth pass"). Read with open/read into a static buffer, so that
// reading /proc/self/smaps allocates nothing on the heap it looks at.
#include "heap_setup.hpp"
#include "qm/address_sanitizer.hpp"
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <doctest/doctest.h>
#include <string_view>
#include <fcntl.h>
#include <malloc.h>
#include <unistd.h>

namespace {

char smaps[1 << 20];

// The whole of /proc/self/smaps, or an empty text.
[[maybe_unused]] const char* read_smaps() {  // unused under AddressSanitizer (the test is empty there)
    const int fd = ::open("/proc/self/smaps", O_RDONLY);
    if (fd < 0) return "";
    std::size_t n = 0;
    for (ssize_t r; n + 1 < sizeof smaps && (r = ::read(fd, smaps + n, sizeof smaps - 1 - n)) > 0;) n += static_cast<std::size_t>(r);
    ::close(fd);
    smaps[n] = '\0';
    return smaps;
}

}  // namespace

TEST_CASE("cli/heap_setup: the reserve is advised into huge pages from just below a 2 MiB boundary, untouched above it") {
#if defined(__GLIBC__) && !defined(QM_UNDER_ASAN)
    constexpr std::uintptr_t huge_page = std::uintptr_t{2} << 20;
    const std::size_t free_before = mallinfo2().fordblks;
    qm::cli::prepare_heap();
    const std::uintptr_t page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
    // The advised mapping: a [heap] entry whose VmFlags hold "hg". An entry opens with its address
    // range ("start-end perms ..."); its fields ("Rss:", "VmFlags:", ...) follow, one a line.
    std::uintptr_t start = 0, end = 0, rss_kb = 0;
    bool found = false;
    std::uintptr_t s = 0, e = 0, rss = 0;
    bool heap = false;
    for (const char* line = read_smaps(); *line && !found;) {
        const char* eol = std::strchr(line, '\n');
        if (!eol) eol = line + std::strlen(line);
        const std::string_view text(line, static_cast<std::size_t>(eol - line));
        int used = 0;
        std::uintptr_t from = 0, to = 0;  // a field's line may match the first number ("FilePmdMapped")
        if (std::sscanf(line, "%lx-%lx %n", &from, &to, &used) == 2 && used > 0) {
            s = from, e = to;
            heap = text.ends_with("[heap]");
            rss = 0;
        } else if (text.starts_with("Rss:")) {
            std::sscanf(line + 4, "%lu", &rss);
        } else if (text.starts_with("VmFlags:") && heap && (text.find(" hg") != std::string_view::npos)) {
            start = s, end = e, rss_kb = rss, found = true;
        }
        line = *eol ? eol + 1 : eol;
    }
    REQUIRE(found);
    CHECK(end - start >= qm::cli::heap_reserve_bytes);
    const std::uintptr_t boundary = (start + huge_page - 1) & ~(huge_page - 1);
    // Only the probe (just larger than the free memory malloc held) and a page of slack lie below.
    CHECK(boundary - start <= free_before + 3 * page);
    // Resident: only pages below the boundary.
    CHECK(rss_kb * 1024 <= boundary - start);
#else
    MESSAGE("prepare_heap() does nothing under AddressSanitizer");
#endif
}
