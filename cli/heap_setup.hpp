// cli/heap_setup.hpp
// Provides:   prepare_heap(), which the qm-atms executables call first thing in main: it asks the C
//             library's allocator to keep the process' heap in one contiguous break segment, reserves
//             that segment at once, and marks it for transparent huge pages (madvise MADV_HUGEPAGE).
// Why:        a large scene touches tens of MB of fresh heap (the ATMS' environments and labels, the
//             engine's facts): on this machine's kernel (THP "madvise" mode, a virtual machine) every
//             first touch of a 4 KiB page was a page fault, 16.5 k of them for the stack of 200 blocks,
//             about a third of its CPU time (docs/perf/alex.md, "Huge pages for the heap"). With the
//             heap in 2 MiB pages the same run takes about 4 k faults. The reserve's body starts at
//             a 2 MiB boundary (the break is moved up to it first), so that a small scene's heap,
//             which lived below the first boundary in 4 KiB pages, is one huge page too: block.def
//             209 -> 0 heap faults of 4 KiB (docs/perf/startup.md, "Fourth pass"). It is the effect of glibc's
//             tunable glibc.malloc.hugetlb=1, obtained without asking users to set an environment
//             variable.
// What it changes: glibc's M_MMAP_THRESHOLD (large blocks stay in the heap instead of separate
//             mappings, which were unmapped at free and faulted again at the next growth) and
//             M_TRIM_THRESHOLD (the heap's top is not given back mid-run); M_TOP_PAD only while
//             reserving. Address space is reserved, not memory: untouched pages cost nothing, and
//             under --max-memory (RLIMIT_AS, set later) the reserved part is what later allocations use.
// Failure:    every step is advisory: if the break cannot grow or madvise is refused, the heap stays
//             as the C library made it and only speed differs. Not done under AddressSanitizer
//             (its allocator replaces glibc's). Outputs never depend on it.
//             The reserve is mapped address space, which RLIMIT_AS counts but does not take back:
//             a --max-memory near it would let the heap grow inside the reserve past the limit, so
//             apply_memory_limit() gives the reserve back first (release_heap_reserve) when the limit
//             is below heap_reserve_limit_floor.
#pragma once
#include <cstdint>

namespace qm::cli {
inline constexpr std::uint64_t heap_reserve_bytes = std::uint64_t{128} << 20;
inline constexpr std::uint64_t heap_reserve_limit_floor = 8 * heap_reserve_bytes;
void prepare_heap() noexcept;
// Returns the heap's free top, the untouched reserve included, to the operating system; later growth
// is in ordinary pages and counts against RLIMIT_AS as it happens.
void release_heap_reserve() noexcept;
}  // namespace qm::cli
