# All dependencies come from Debian 12 packages; see docs/toolchain notes in README.
find_package(Threads REQUIRED)
find_package(Eigen3 3.4 CONFIG REQUIRED)
find_package(TinyGLTF CONFIG REQUIRED)
find_package(nlohmann_json CONFIG REQUIRED)
find_package(TBB CONFIG REQUIRED)
find_package(embree 3.13 CONFIG REQUIRED)
find_package(fmt CONFIG REQUIRED)
find_package(CLI11 CONFIG REQUIRED)

find_package(OpenImageIO 2.4 CONFIG REQUIRED)
# Debian bug: the imported target lists /usr/include/opencv4, which does not exist without OpenCV.
get_target_property(_oiio_inc OpenImageIO::OpenImageIO INTERFACE_INCLUDE_DIRECTORIES)
list(FILTER _oiio_inc EXCLUDE REGEX "opencv4")
set_target_properties(OpenImageIO::OpenImageIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "${_oiio_inc}")

find_package(OpenEXR 3.1 CONFIG REQUIRED)

# Debian bugs: the config lives in /usr/share/cmake and computes the include dir as "/include".
find_package(OpenColorIO 2.1 CONFIG REQUIRED HINTS /usr/share/cmake)
set_target_properties(OpenColorIO::OpenColorIO PROPERTIES INTERFACE_INCLUDE_DIRECTORIES "/usr/include")

if(LACRIMA_BUILD_TESTS)
  find_package(GTest CONFIG REQUIRED)
  find_package(benchmark CONFIG REQUIRED)
endif()

# TetGen 1.5 (Debian's libtet1.5-dev) ships no CMake config or pkg-config file: the header and the
# shared library, found by name. The library is built with TETLIBRARY (errors are thrown as int):
# define it before including tetgen.h.
find_path(TETGEN_INCLUDE_DIR tetgen.h REQUIRED)
find_library(TETGEN_LIBRARY tet REQUIRED)
add_library(TetGen::TetGen UNKNOWN IMPORTED)
set_target_properties(TetGen::TetGen PROPERTIES IMPORTED_LOCATION "${TETGEN_LIBRARY}"
                                                INTERFACE_INCLUDE_DIRECTORIES "${TETGEN_INCLUDE_DIR}")

# OpenVDB 10 (Debian's libopenvdb-dev): its FindOpenVDB.cmake module brings its own FindTBB and
# FindOpenEXR, which would shadow the config packages above; the header and the shared library are
# found by name instead. Debian builds it with Imath's half (OPENVDB_USE_IMATH_HALF) and TBB, which
# its headers include, as they include Boost headers (libboost-dev, which the package does not pull in).
find_path(OPENVDB_INCLUDE_DIR openvdb/openvdb.h REQUIRED)
find_library(OPENVDB_LIBRARY openvdb REQUIRED)
add_library(OpenVDB::openvdb UNKNOWN IMPORTED)
set_target_properties(OpenVDB::openvdb PROPERTIES IMPORTED_LOCATION "${OPENVDB_LIBRARY}"
                                                  INTERFACE_INCLUDE_DIRECTORIES "${OPENVDB_INCLUDE_DIR}"
                                                  INTERFACE_LINK_LIBRARIES "TBB::tbb;Imath::Imath")
