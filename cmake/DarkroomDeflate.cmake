# libdeflate (Debian's libdeflate-dev): the EXR reader inflates with it,
# faster than zlib, and the PNG writer takes its CRC-32 and Adler-32
# (docs/performance.md, "Codecs"). Shared by the main build, the benchmarks
# and the fuzz project.
#
# Defines darkroom_deflate, an interface target with libdeflate's include
# folder and library. exr_direct.cpp inflates EXR's ZIP chunks with it
# (docs/performance.md, "EXR reading"); png_encoder.cpp (libdeflate's levels,
# kept for the benchmark) and run_deflate.cpp include it too.
if(TARGET darkroom_deflate)
  return()
endif()
find_package(PkgConfig REQUIRED)
pkg_check_modules(LIBDEFLATE QUIET IMPORTED_TARGET libdeflate)
if(NOT LIBDEFLATE_FOUND)
  # (No semicolons in the text: CMake would read them as list separators.)
  message(FATAL_ERROR "Darkroom writes PNG with libdeflate, which was not found. "
                      "Install the Debian package libdeflate-dev "
                      "(apt-get install libdeflate-dev, or run scripts/install-deps.sh as root)")
endif()
add_library(darkroom_deflate INTERFACE)
target_link_libraries(darkroom_deflate INTERFACE PkgConfig::LIBDEFLATE)
