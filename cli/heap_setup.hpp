// cli/heap_setup.hpp
// Provides:   prepare_heap(), which the qm-atms executables call first thing in main: it asks the C
//             library's allocator to keep the process' heap in one contiguous break segment, reserves
//             that segment at once, and marks it for transparent huge pages (madvise MADV_HUGEPAGE).
// Why:        a large scene touches tens of MB of fresh heap (the ATMS' environments and labels, the
//             engine's facts): on this machine's kernel (THP "madvise" mode, a virtual machine) every
//             first touch of a 4 KiB page was a page fault, 16.5 k of them for the stack of 200 blocks,
//             about a third of its CPU time (docs/perf/alex.md, "Huge pages for the heap"). With the
//             heap in 2 MiB pages the same run takes about 4 k faults. It is the effect of glibc's
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
#pragma once

namespace qm::cli {
void prepare_heap() noexcept;
}  // namespace qm::cli
