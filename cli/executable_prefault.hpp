// cli/executable_prefault.hpp
// Provides:   prefault_executable(), which the qm-atms executables call once a command that does
//             real work starts (not for --help): it maps the running executable's segments into the
//             page tables in one system call each (madvise MADV_POPULATE_READ for code and constants,
//             MADV_POPULATE_WRITE for the writable data past RELRO) instead of a page fault at each
//             first touch.
// Why:        on this machine's virtual machine a page fault costs 10-14 us (a file-backed one maps
//             16 pages around it), while populating the whole 4.2 MB of the light executable's code
//             and constants takes about 0.15-0.2 ms: block.def took 54 faults in them and 20 in its
//             data and bss, about 0.8 ms of a run of about 8 (docs/perf/startup.md, "Fourth pass").
//             The populate reads as a first touch would: on a cold page cache it reads the whole
//             code from disk at once, not only the pages this run needs (on a warm cache, the usual
//             case for a command run again, nothing is read).
// Failure:    advisory: a kernel without MADV_POPULATE_* (before Linux 5.14) or any error leaves the
//             pages to be faulted in as before. Outputs never depend on it.
#pragma once

namespace qm::cli {
void prefault_executable() noexcept;
}  // namespace qm::cli
