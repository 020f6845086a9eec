# Project-wide compile settings applied per target with qm_defaults(<target>), so that
# third-party code (doctest, benchmark) is never compiled with our -Werror.
set(QM_WARNINGS -Wall -Wextra -Wpedantic)
if(QM_WERROR)
  list(APPEND QM_WARNINGS -Werror)
endif()
# GCC 12 reports impossible memcpy overlaps inside std::string's operator+ when it inlines at -O2/-O3
# (GCC bug 105329/105651, fixed in 13): a false positive in libstdc++, not in our code.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  list(APPEND QM_WARNINGS -Wno-restrict)
endif()

# The processor the build assumes (README, "The processor"). On x86-64 the default is x86-64-v2
# (every x86-64 processor since about 2009: POPCNT, SSE4.2), so std::popcount, which the ATMS's
# bitsets use everywhere, is one instruction instead of a call to libgcc's __popcountdi2. Applied
# globally, so tests, benchmarks and the library see the same flags. -DQM_ARCH= builds for the
# compiler's default (any x86-64); -DQM_ARCH=native for this machine only.
set(QM_ARCH "x86-64-v2" CACHE STRING "-march level on x86-64 (empty: the compiler's default)")
if(QM_ARCH AND CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
  include(CheckCXXCompilerFlag)
  check_cxx_compiler_flag("-march=${QM_ARCH}" QM_MARCH_SUPPORTED_${QM_ARCH})
  if(QM_MARCH_SUPPORTED_${QM_ARCH})
    add_compile_options(-march=${QM_ARCH})
  else()
    message(WARNING "QM_ARCH=${QM_ARCH}: the compiler does not accept -march=${QM_ARCH}; building for its default")
  endif()
endif()

if(QM_SANITIZE)
  # Applied globally so that every object, including test mains, shares one runtime.
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer -fno-sanitize-recover=all)
  # -g1: line tables and function names, all a sanitizer report's stack trace shows; placed after the
  # Debug configuration's -g, so it wins. Compiles 10-15% faster than -g and links smaller objects.
  # -O1: Eigen and the geometry are 10-14x slower at -O0 under the sanitizers (the clock mechanisms'
  # test: 209 s of CPU at -O0, 15 s at -O1), which outweighs the slower compile of the X3 parsers
  # (docs/PERFORMANCE.md, "CI time"). -O1 keeps frames and inlines little, so reports stay exact.
  add_compile_options(-g1 -O1)
  # -O1 turns on GCC 12's flow analysis for -Wmaybe-uninitialized, which the sanitizers' instrumentation
  # makes report false positives (first in Boost.PropertyTree's optional<unsigned>); -O0 never ran it,
  # and the Release build (-O3) still does. Clang has no such warning.
  if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU")
    list(APPEND QM_WARNINGS -Wno-maybe-uninitialized)
  endif()
  add_link_options(-fsanitize=address,undefined)
  add_compile_definitions(QM_ENABLE_ASSERTS=1)
  # Tests that do a Release-sized amount of geometry check a smaller sample under the sanitizers
  # (they run 30x slower there); they ask this, not the compiler's own macros.
  add_compile_definitions(QM_SANITIZED_BUILD=1)
endif()

if(QM_BUILD_FUZZ)
  # Every object carries libFuzzer's coverage hooks and the sanitizers, so a fuzz target is guided by,
  # and checks, the library code it calls; only the fuzz targets link libFuzzer itself (tests/fuzz).
  # A tree that only replays corpora (.ci/run) needs no guidance: QM_FUZZ_COVERAGE=OFF leaves the
  # hooks out, and its tests run faster.
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "QM_BUILD_FUZZ needs clang (CXX=clang++)")
  endif()
  if(QM_FUZZ_COVERAGE)
    add_compile_options(-fsanitize=fuzzer-no-link)
  endif()
  add_compile_options(-fsanitize=address,undefined -fno-omit-frame-pointer)
  add_link_options(-fsanitize=address,undefined)
  # Assertions on whatever the build type: BOOST_ASSERT guards Spirit's preconditions, QM_ASSERT
  # the models'; a fuzzer should stop at the first broken one.
  add_compile_options(-UNDEBUG)
  if(NOT QM_SANITIZE)  # which defines it already
    add_compile_definitions(QM_ENABLE_ASSERTS=1)
  endif()
endif()

function(qm_defaults target)
  get_target_property(kind ${target} TYPE)
  if(kind STREQUAL "INTERFACE_LIBRARY")
    return()
  endif()
  target_compile_options(${target} PRIVATE ${QM_WARNINGS})
  # QM_ASSERT is active in debug and test builds (STYLE.md section 4).
  target_compile_definitions(${target} PRIVATE $<$<CONFIG:Debug>:QM_ENABLE_ASSERTS=1>)
endfunction()


# qm_module(<target> DIR <dir> [LINKS <targets...>]): one library per module folder.
# Sources are the folder's *.cpp (and detail/*.cpp), excluding *_fuzz.cpp and main.cpp. Headers are
# exposed through a per-target include root holding a single link <dir> -> source folder, so
# `#include "atms/label.hpp"` works only for targets that link qm_atms: a wrong-way include fails to
# compile because its path is not there (STYLE.md section 2).
function(qm_module target)
  cmake_parse_arguments(M "" "DIR" "LINKS" ${ARGN})
  set(src_dir ${CMAKE_SOURCE_DIR}/${M_DIR})
  file(GLOB sources CONFIGURE_DEPENDS ${src_dir}/*.cpp ${src_dir}/detail/*.cpp)
  list(FILTER sources EXCLUDE REGEX "(_fuzz|/main)\\.cpp$")
  set(inc_root ${CMAKE_BINARY_DIR}/include/${target})
  file(MAKE_DIRECTORY ${inc_root})
  if(NOT EXISTS ${inc_root}/${M_DIR})
    file(CREATE_LINK ${src_dir} ${inc_root}/${M_DIR} SYMBOLIC)
  endif()
  if(sources)
    add_library(${target} STATIC ${sources})
    target_include_directories(${target} PUBLIC ${inc_root})
    target_link_libraries(${target} PUBLIC qm_support ${M_LINKS})
    qm_defaults(${target})
  else()
    add_library(${target} INTERFACE)
    target_include_directories(${target} INTERFACE ${inc_root})
    target_link_libraries(${target} INTERFACE qm_support ${M_LINKS})
  endif()
endfunction()

# qm_module_tests(<module> LIBS <targets...> [LARGE <file stems...>] [SLOW <file stems...>]): the
# tests/<module>/*_test.cpp (one test file per header) are linked into one doctest executable,
# <module>_tests, which run alone runs them all; ctest runs each file as its own entry,
# <module>_<file>, selecting its test cases by source file (one link per module, not per file: a
# sanitized link is slow). SLOW files, and their LARGE entries, are started first (ctest COST),
# so that none is left running alone at the end of a parallel run.
# The files are compiled a batch to a translation unit (QM_UNITY_TESTS, CMake's unity build), so that
# doctest and the module's headers are parsed, and their inline code compiled, once a batch instead of
# once a file. The files of a batch share one scope, and which files share a batch changes as files
# are added: a name a test file defines at file scope (in its anonymous namespace too) must be one no
# other test file of the module defines, even with other parameters (a call could silently pick the
# other file's overload), and a using-directive reaches the files after it. ctest still selects by
# file: doctest records each test case's __FILE__, which is the included file's own path.
# A LARGE file's test cases named "[large]" (the largest envisionments) are registered apart, as
# <module>_<file>_large with the ctest label `large`, which the sanitizer tree of .ci/run leaves out:
# the same code runs there on the smaller mechanisms. A selection that finds no test case fails
# (tests/doctest_main.cpp), so a renamed file cannot pass by running nothing.
function(qm_module_tests module)
  cmake_parse_arguments(T "" "" "LIBS;LARGE;SLOW" ${ARGN})
  file(GLOB tests CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/*_test.cpp)
  set(exe ${module}_tests)
  add_executable(${exe} ${tests})
  target_link_libraries(${exe} PRIVATE ${T_LIBS} qm_doctest_main doctest::doctest)
  target_compile_definitions(${exe} PRIVATE QM_ENABLE_ASSERTS=1
    QM_SOURCE_DIR="${CMAKE_SOURCE_DIR}" QM_BINARY_DIR="${CMAKE_BINARY_DIR}")
  qm_defaults(${exe})
  if(QM_UNITY_TESTS)
    set_target_properties(${exe} PROPERTIES UNITY_BUILD ON UNITY_BUILD_BATCH_SIZE ${QM_UNITY_TESTS_BATCH})
  endif()
  foreach(t ${tests})
    get_filename_component(stem ${t} NAME_WE)
    set(name ${module}_${stem})
    set(file "--source-file=*/tests/${module}/${stem}.cpp")
    if(stem IN_LIST T_LARGE)
      add_test(NAME ${name} COMMAND ${exe} ${file} "--test-case-exclude=*[large]*" WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
      add_test(NAME ${name}_large COMMAND ${exe} ${file} "--test-case=*[large]*" WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
      set_tests_properties(${name}_large PROPERTIES LABELS large)
    else()
      add_test(NAME ${name} COMMAND ${exe} ${file} WORKING_DIRECTORY ${CMAKE_BINARY_DIR})
    endif()
    if(stem IN_LIST T_SLOW)
      set_tests_properties(${name} PROPERTIES COST 100)
      if(stem IN_LIST T_LARGE)
        set_tests_properties(${name}_large PROPERTIES COST 100)
      endif()
    endif()
  endforeach()
endfunction()
