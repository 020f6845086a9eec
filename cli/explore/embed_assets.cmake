# Writes OUT, a C++ source holding the explorer page's files (DIR/index.html, explore.js,
# envision.js, explore.css) as raw string literals, so that `qm-atms explore` needs no file at run time.
# Run as: cmake -DDIR=... -DOUT=... -P embed_assets.cmake
set(text "// Generated from cli/explore/ by embed_assets.cmake: do not edit.\n#include \"explore_assets.hpp\"\n\nnamespace qm::cli {\n\nstd::span<const ExploreAsset> explore_assets() noexcept {\n    static const ExploreAsset assets[] = {\n")
foreach(name index.html explore.js envision.js explore.css)
  file(READ ${DIR}/${name} content)
  string(FIND "${content}" ")qm_asset\"" clash)
  if(NOT clash EQUAL -1)
    message(FATAL_ERROR "${name} holds the raw string's delimiter")
  endif()
  string(APPEND text "        {\"${name}\", R\"qm_asset(${content})qm_asset\"},\n")
endforeach()
string(APPEND text "    };\n    return assets;\n}\n\n}  // namespace qm::cli\n")
file(WRITE ${OUT}.tmp "${text}")
file(COPY_FILE ${OUT}.tmp ${OUT} ONLY_IF_DIFFERENT)
