# tests/cli/light_executable_links.cmake: the light qm-atms links none of the geometry stack
# (cli/geometry_dispatch.hpp, docs/perf/startup.md): no libfcl (BIND_NOW: 29,183 relocations at every
# start), liboctomap or libccd among its dynamic dependencies, and no geometry code (our namespaces
# qm::geometry, qm::bridge, qm::envision) in it. The same checks on qm-atms-geometry must find them,
# so the test would notice a check that can no longer see what it looks for.
#   cmake -DREADELF=... -DNM=... -DLIGHT=path/qm-atms -DFULL=path/qm-atms-geometry -P light_executable_links.cmake
foreach(v READELF NM LIGHT FULL)
  if(NOT ${v})
    message(FATAL_ERROR "light_executable_links: ${v} not given")
  endif()
endforeach()

# The NEEDED entries of an executable's dynamic section, and whether its symbols name geometry code.
function(inspect exe needed_var geometry_var)
  execute_process(COMMAND ${READELF} -dW ${exe} OUTPUT_VARIABLE dynamic RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "readelf -d ${exe} failed")
  endif()
  string(REGEX MATCHALL "\\(NEEDED\\)[^\n]*\\[[^]]*\\]" lines "${dynamic}")
  set(${needed_var} "${lines}" PARENT_SCOPE)
  # Symbols as the linker left them (a Release build is not stripped): the mangled namespaces.
  execute_process(COMMAND ${NM} -C ${exe} OUTPUT_VARIABLE symbols RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "nm ${exe} failed")
  endif()
  string(REGEX MATCH "qm::(geometry|bridge|envision)::[^\n]*" hit "${symbols}")
  set(${geometry_var} "${hit}" PARENT_SCOPE)
endfunction()

inspect(${LIGHT} light_needed light_geometry)
inspect(${FULL} full_needed full_geometry)
message(STATUS "qm-atms needs: ${light_needed}")
foreach(lib fcl octomap ccd)
  if(light_needed MATCHES "lib${lib}")
    message(SEND_ERROR "qm-atms links lib${lib}: ${light_needed}")
  endif()
endforeach()
if(light_geometry)
  message(SEND_ERROR "qm-atms holds geometry code: ${light_geometry}")
endif()
if(NOT full_needed MATCHES "libfcl")
  message(SEND_ERROR "qm-atms-geometry does not link libfcl, so this check cannot see it: ${full_needed}")
endif()
if(NOT full_geometry)
  message(SEND_ERROR "qm-atms-geometry holds no qm::geometry symbol, so this check cannot see one")
endif()
