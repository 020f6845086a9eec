// support/qm/address_sanitizer.hpp
// Provides:   QM_UNDER_ASAN, defined (as 1) when the including file is compiled with
//             AddressSanitizer, by GCC (__SANITIZE_ADDRESS__) or clang (__has_feature), whatever
//             the build system says: the fuzz build and a hand-made sanitizer build set no
//             QM_SANITIZED_BUILD.
// Why:        AddressSanitizer reserves terabytes of address space for its shadow memory, so an
//             address-space limit (RLIMIT_AS, --max-memory) cannot be applied or tested under it.
//             Code that only wants a smaller workload in the project's sanitizer build asks
//             QM_SANITIZED_BUILD (cmake/QmDefaults.cmake) instead.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define QM_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define QM_UNDER_ASAN 1
#endif
#endif
