// cli/executable_prefault.cpp: the executable's segments mapped at once (cli/executable_prefault.hpp).
#include "executable_prefault.hpp"

#include <cstdint>
#include <link.h>
#include <sys/mman.h>
#include <unistd.h>

#ifndef MADV_POPULATE_READ
#define MADV_POPULATE_READ 22  // Linux 5.14, <linux/mman.h>; older kernels refuse it (EINVAL)
#endif
#ifndef MADV_POPULATE_WRITE
#define MADV_POPULATE_WRITE 23
#endif

namespace qm::cli {
namespace {

void populate(std::uintptr_t from, std::uintptr_t to, std::uintptr_t page, int advice) {
    from &= ~(page - 1);
    to = (to + page - 1) & ~(page - 1);
    if (to > from) (void)madvise(reinterpret_cast<void*>(from), to - from, advice);
}

// dl_iterate_phdr's first object is the executable itself.
int populate_executable(dl_phdr_info* info, std::size_t, void* data) {
    const auto page = *static_cast<const std::uintptr_t*>(data);
    std::uintptr_t relro_end = 0;  // read-only after start-up: a write populate would fail there
    for (std::size_t i = 0; i < info->dlpi_phnum; ++i) {
        const ElfW(Phdr)& ph = info->dlpi_phdr[i];
        if (ph.p_type == PT_GNU_RELRO) relro_end = info->dlpi_addr + ph.p_vaddr + ph.p_memsz;
    }
    for (std::size_t i = 0; i < info->dlpi_phnum; ++i) {
        const ElfW(Phdr)& ph = info->dlpi_phdr[i];
        if (ph.p_type != PT_LOAD) continue;
        const std::uintptr_t start = info->dlpi_addr + ph.p_vaddr, end = start + ph.p_memsz;
        if ((ph.p_flags & PF_W) == 0) {
            populate(start, end, page, MADV_POPULATE_READ);
            continue;
        }
        // The writable segment: its RELRO head read (now read-only), the rest written (copied from
        // the file, or zero for the bss), as the program is about to.
        const std::uintptr_t split = relro_end > start && relro_end < end ? (relro_end & ~(page - 1)) : start;
        if (split > start) populate(start, split, page, MADV_POPULATE_READ);
        populate(split, end, page, MADV_POPULATE_WRITE);
    }
    return 1;  // the executable only
}

}  // namespace

void prefault_executable() noexcept {
    std::uintptr_t page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
    dl_iterate_phdr(&populate_executable, &page);
}

}  // namespace qm::cli
