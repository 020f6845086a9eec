// cli/heap_setup.cpp: the heap reserved in one break segment and advised into huge pages
// (cli/heap_setup.hpp).
#include "heap_setup.hpp"

#include "qm/address_sanitizer.hpp"

#include <cstdint>
#include <cstdlib>

// Off under AddressSanitizer, whose allocator is its own.
#if defined(__GLIBC__) && !defined(QM_UNDER_ASAN)
#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace qm::cli {
void prepare_heap() noexcept {
#if defined(__GLIBC__) && !defined(QM_UNDER_ASAN)
    // The segment reserved at once: more than the 200-block stack's peak (about 60 MB), so the scenes
    // of docs/perf/alex.md live in it; growth beyond it is served as before, in 4 KiB pages. Kept
    // well below a sensible --max-memory; a limit under heap_reserve_limit_floor gives it back first
    // (release_heap_reserve), so that the limit still means what it says (tests/cli/limits_test.cpp).
    constexpr int reserve = static_cast<int>(heap_reserve_bytes);
    // glibc's largest allowed mmap threshold on 64-bit (HEAP_MAX_SIZE / 2): blocks below it come from
    // the heap.
    constexpr int mmap_threshold = 32 << 20;
    constexpr int default_top_pad = 128 << 10;  // glibc's M_TOP_PAD default (DEFAULT_TOP_PAD)
    constexpr std::uintptr_t huge_page = std::uintptr_t{2} << 20;  // x86-64's transparent huge page
    if (mallopt(M_MMAP_THRESHOLD, mmap_threshold) == 0) return;
    // No trimming (not even of the reserve, free at first): a trimmed and regrown break would be a
    // new mapping without the advice.
    mallopt(M_TRIM_THRESHOLD, 4 * reserve);
    // The reserve's body starts at a huge-page boundary. The break starts wherever the kernel put
    // it, and the part of the segment below the first 2 MiB boundary can only have 4 KiB pages: a
    // scene's first megabyte or so, all of a small one, was faulted in page by page, at about 10 us
    // a fault on this machine's virtual machine against about 50 us for a whole 2 MiB huge page
    // (docs/perf/startup.md, "Fourth pass": 209 heap faults of block.def). So the top the C library
    // holds (what the static initialisers and main left) is trimmed and the break moved up to just
    // below the next boundary; glibc's malloc takes a break moved by someone else as a gap it never
    // touches (its "foreign sbrk" case), so the gap costs address space only. Every byte malloc
    // writes while growing the segment (the probe's header and that of the top after it) must fall
    // below the boundary: a page touched above it before the advice would be a 4 KiB page, and its
    // 2 MiB range would stay in 4 KiB pages. Hence a probe only just larger than all the free
    // memory malloc holds (so that no free block can serve it and the break must grow), placed so
    // that it ends a page below the boundary.
    malloc_trim(0);
    const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
#if __GLIBC_PREREQ(2, 33)
    const std::size_t free_bytes = mallinfo2().fordblks;
#else
    const auto free_bytes = static_cast<std::size_t>(mallinfo().fordblks);  // mallinfo2 is glibc 2.33's
#endif
    const std::size_t probe_size = (free_bytes + page + 15) & ~std::size_t{15};
    const auto brk_end = reinterpret_cast<std::uintptr_t>(sbrk(0));
    const std::uintptr_t below = (probe_size + 2 * page - 1) & ~(page - 1);  // the probe, headers, slack
    const std::uintptr_t start = ((brk_end + below + huge_page - 1) & ~(huge_page - 1)) - below;
    if (start != brk_end && sbrk(static_cast<intptr_t>(start - brk_end)) == reinterpret_cast<void*>(-1)) return;
    mallopt(M_TOP_PAD, reserve);
    // Larger than any free block and the top: malloc extends the break by block + pad.
    void* probe = std::malloc(probe_size);
    mallopt(M_TOP_PAD, default_top_pad);
    if (probe == nullptr) return;
    const auto from = reinterpret_cast<std::uintptr_t>(probe) & ~(page - 1);
    const auto to = reinterpret_cast<std::uintptr_t>(sbrk(0));
    std::free(probe);  // back to the heap's top, kept (M_TRIM_THRESHOLD)
    // Only a probe inside the break segment (not an mmap fallback) tells where the segment is.
    if (to > from) madvise(reinterpret_cast<void*>(from), to - from, MADV_HUGEPAGE);
#endif
}

void release_heap_reserve() noexcept {
#if defined(__GLIBC__) && !defined(QM_UNDER_ASAN)
    malloc_trim(0);  // unlike the automatic trim, not bound by M_TRIM_THRESHOLD
#endif
}
}  // namespace qm::cli
