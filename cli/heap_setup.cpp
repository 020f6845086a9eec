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
    if (mallopt(M_MMAP_THRESHOLD, mmap_threshold) == 0) return;
    // No trimming (not even of the reserve, free at first): a trimmed and regrown break would be a
    // new mapping without the advice.
    mallopt(M_TRIM_THRESHOLD, 4 * reserve);
    mallopt(M_TOP_PAD, reserve);
    // A block larger than the initial heap's free top makes malloc extend the break by block + pad.
    void* probe = std::malloc(1 << 20);
    mallopt(M_TOP_PAD, default_top_pad);
    if (probe == nullptr) return;
    const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
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
