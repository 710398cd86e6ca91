# Precompiled headers: much of a lacrima translation unit's compile time is parsing the same
# third-party headers again (Eigen's Core/Geometry, GoogleTest, nlohmann::json and the standard
# library: 36-73 % of a source's compile is "phase parsing" in g++ -ftime-report). Each target
# parses them once into a precompiled header that its sources reuse.
# On by default for clang only, as measured on CI's 2 cores: clang (the sanitizer build of
# tools/hardening.sh) spent 209 s of CPU instead of 270 s on lacrima_geometry and the materials
# tests (-23 %); g++ (the Release build) spent 1,133 s instead of 1,108 s on the whole tree, no
# gain: its precompiled headers are large files that each source loads in full.
# Only headers that most of a target's sources already include are listed, so that a source
# never sees a header it would not have seen anyway in a way that matters. fmt is left out where
# a target also includes OpenImageIO, which carries its own copy of fmt with other settings.
if(CMAKE_CXX_COMPILER_ID MATCHES "Clang")
  set(_pch_default ON)
else()
  set(_pch_default OFF)
endif()
option(LACRIMA_PRECOMPILED_HEADERS "Precompile the heavy third-party headers per target" ${_pch_default})

set(LACRIMA_PCH_STANDARD
  <algorithm> <array> <cmath> <functional> <memory> <optional> <sstream> <string>
  <unordered_map> <vector>)
set(LACRIMA_PCH_EIGEN <Eigen/Core> <Eigen/Geometry>)

# lacrima_precompile_headers(target header...): the standard set plus the given headers.
function(lacrima_precompile_headers target)
  if(NOT LACRIMA_PRECOMPILED_HEADERS)
    return()
  endif()
  target_precompile_headers(${target} PRIVATE ${LACRIMA_PCH_STANDARD} ${ARGN})
endfunction()
