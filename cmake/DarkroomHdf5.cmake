# HDF5 (Debian's serial C library, libhdf5-dev): pycinema's and ParaView's
# Cinema products are .h5 files (docs/formats.md, "pycinema's HDF5 images"),
# read and written by the data library. Shared by the main build and the fuzz
# project (tests/fuzz/CMakeLists.txt), so both find the same library.
#
# Defines darkroom_hdf5, an interface target with HDF5's include folder (as
# a system folder: its headers are not held to our warnings), definitions and
# libraries. Only the .cpp files of the format include hdf5.h.
if(TARGET darkroom_hdf5)
  return()
endif()
# FindHDF5's C component test-compiles a C file: the fuzz project is C++ only.
enable_language(C)
find_package(HDF5 QUIET COMPONENTS C)
if(NOT HDF5_FOUND OR NOT HDF5_C_INCLUDE_DIRS)
  # (No semicolons in the text: CMake would read them as list separators.)
  message(FATAL_ERROR "Darkroom reads and writes pycinema's .h5 images with the HDF5 C library, "
                      "which was not found. Install the Debian package libhdf5-dev "
                      "(apt-get install libhdf5-dev, or run scripts/install-deps.sh as root)")
endif()
add_library(darkroom_hdf5 INTERFACE)
target_include_directories(darkroom_hdf5 SYSTEM INTERFACE ${HDF5_C_INCLUDE_DIRS})
target_compile_definitions(darkroom_hdf5 INTERFACE ${HDF5_C_DEFINITIONS})
target_link_libraries(darkroom_hdf5 INTERFACE ${HDF5_C_LIBRARIES})
