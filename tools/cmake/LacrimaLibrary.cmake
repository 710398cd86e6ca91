# lacrima_add_library(NAME PUBLIC_DEPS ... PRIVATE_DEPS ... PRECOMPILE ...): one static library per
# top-level folder. Sources are every src/*.cpp and src/<room>/*.cpp of the folder (private headers
# are included by their path under src/, e.g. "read/shot_reader.hpp"); public headers live in
# include/lacrima/<folder>/. PRECOMPILE names third-party headers to precompile besides the
# standard ones (tools/cmake/PrecompiledHeaders.cmake).
function(lacrima_add_library name)
  cmake_parse_arguments(ARG "" "" "PUBLIC_DEPS;PRIVATE_DEPS;PRECOMPILE" ${ARGN})
  file(GLOB _sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_SOURCE_DIR}/src/*.cpp ${CMAKE_CURRENT_SOURCE_DIR}/src/*/*.cpp)
  add_library(${name} STATIC ${_sources})
  target_include_directories(${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include
                                     PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  target_link_libraries(${name} PUBLIC ${ARG_PUBLIC_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  target_compile_options(${name} PRIVATE -Wall -Wextra)
  lacrima_precompile_headers(${name} ${ARG_PRECOMPILE})
endfunction()
