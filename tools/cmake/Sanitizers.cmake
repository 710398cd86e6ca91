# LACRIMA_SANITIZE: comma-separated sanitizers for every target, e.g. "address,undefined"
# (tools/hardening.sh builds build-asan with it). UB is made fatal so that a test fails on it
# instead of printing a report and passing.
set(LACRIMA_SANITIZE "" CACHE STRING "Sanitizers to build with (-fsanitize=...), e.g. address,undefined")

if(LACRIMA_SANITIZE)
  set(_lacrima_sanitize_flags -fsanitize=${LACRIMA_SANITIZE} -fno-omit-frame-pointer)
  if(LACRIMA_SANITIZE MATCHES "undefined")
    list(APPEND _lacrima_sanitize_flags -fno-sanitize-recover=undefined)
  endif()
  add_compile_options(${_lacrima_sanitize_flags})
  add_link_options(${_lacrima_sanitize_flags})
  message(STATUS "lacrima: building with ${_lacrima_sanitize_flags}")
endif()

# LACRIMA_FUZZ (clang only): instrument every target for libFuzzer coverage and build the fuzz
# targets of tests/fuzz, which link the libFuzzer driver themselves.
option(LACRIMA_FUZZ "Build the libFuzzer targets of tests/fuzz (needs clang)" OFF)
if(LACRIMA_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "LACRIMA_FUZZ needs clang (configure with CC=clang CXX=clang++)")
  endif()
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
