# Google Highway (Debian: libhwy-dev) for the SIMD kernels of the passes and
# the SDK. Kernels are compiled for every x86 target Highway knows (SSSE3 ...
# AVX-512) and the best one the CPU has is chosen at run time.
#
# darkroom_use_highway(TARGET) links it, puts the calling folder on the
# include path (a kernel names itself as HWY_TARGET_INCLUDE "src/x.cpp") and
# turns off floating-point contraction for the target: the AVX2/AVX-512
# copies of a kernel could otherwise fuse a*b+c into one FMA and round
# differently from the SSE4 copy, and a pass's pixels must not depend on
# which CPU ran it (docs/simd.md).
find_package(hwy 1.0 CONFIG QUIET)
if(NOT hwy_FOUND)
  message(FATAL_ERROR "Google Highway was not found: install the Debian package libhwy-dev "
                      "(scripts/install-deps.sh installs everything Darkroom needs)")
endif()

function(darkroom_use_highway TARGET)
  target_link_libraries(${TARGET} PRIVATE hwy::hwy)
  target_include_directories(${TARGET} PRIVATE ${CMAKE_CURRENT_SOURCE_DIR})
  target_compile_options(${TARGET} PRIVATE -ffp-contract=off)
endfunction()
