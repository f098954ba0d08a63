# MPI and Fortran: the scale-out parts (docs/scale-out.md).
#
# DARKROOM_WITH_MPI (ON by default) builds the MPI library (mpi/), the
# runner's distributed capture and batch shading, MPI support in the in situ
# API and the tests that run under mpirun. DARKROOM_WITH_FORTRAN (ON by
# default) builds the in situ API's Fortran module and its Fortran test.
#
# Both are part of what CI tests, so with tests enabled a missing piece stops
# configuration and names the Debian package; without tests a warning says
# what is left out. A build for a machine without MPI: -DDARKROOM_WITH_MPI=OFF.
option(DARKROOM_WITH_MPI "Build the MPI parts (distributed capture, batch shading over ranks, in situ over ranks)" ON)
option(DARKROOM_WITH_FORTRAN "Build the in situ API's Fortran module (gfortran)" ON)

function(_darkroom_missing what)
  if(DARKROOM_BUILD_TESTS)
    message(FATAL_ERROR "${what}")
  else()
    message(WARNING "${what}. Built without it.")
  endif()
endfunction()

if(DARKROOM_WITH_FORTRAN)
  include(CheckLanguage)
  check_language(Fortran)
  if(CMAKE_Fortran_COMPILER)
    enable_language(Fortran)
  else()
    _darkroom_missing("The in situ API's Fortran module needs a Fortran compiler: install the Debian package "
                      "gfortran (apt-get install gfortran, or run scripts/install-deps.sh as root); "
                      "-DDARKROOM_WITH_FORTRAN=OFF builds without it")
    set(DARKROOM_WITH_FORTRAN OFF)
  endif()
endif()

if(DARKROOM_WITH_MPI)
  set(_mpi_languages C CXX)
  if(DARKROOM_WITH_FORTRAN)
    list(APPEND _mpi_languages Fortran)
  endif()
  # FindMPI's C component needs the C language.
  enable_language(C)
  find_package(MPI COMPONENTS ${_mpi_languages})
  if(NOT MPI_FOUND OR NOT EXISTS "${MPIEXEC_EXECUTABLE}")
    _darkroom_missing("Darkroom's MPI parts need MPI (headers, libraries and mpirun): install the Debian packages "
                      "libopenmpi-dev openmpi-bin (apt-get install libopenmpi-dev openmpi-bin, or run "
                      "scripts/install-deps.sh as root); -DDARKROOM_WITH_MPI=OFF builds without MPI")
    set(DARKROOM_WITH_MPI OFF)
  endif()
endif()

# Under DARKROOM_SANITIZE the MPI tests (label mpi) record malloc stacks with
# the DWARF unwinder: OpenMPI is built without frame pointers, so the fast
# one keeps a single frame, often in a component MPI_Finalize has unloaded,
# and a leak of OpenMPI's could neither be told from ours nor suppressed by
# its library (tests/sanitizers/lsan.supp). The rest of the suite keeps the
# fast unwinder: the slow one made a test binary 2.4 times slower.
set(DARKROOM_MPI_TEST_ENV_MODIFICATION "")
if(DARKROOM_SANITIZE)
  set(DARKROOM_MPI_TEST_ENV_MODIFICATION "ASAN_OPTIONS=path_list_append:fast_unwind_on_malloc=0")
endif()

# darkroom_mpi_test(NAME RANKS n COMMAND cmd args...)
#
# A ctest entry run as `mpirun -np n --oversubscribe cmd args` (the test
# machines have fewer cores than ranks). As root, OpenMPI refuses to start
# unless told it may: the two variables below say so for the tests only.
function(darkroom_mpi_test NAME)
  cmake_parse_arguments(ARG "" "RANKS;TIMEOUT" "COMMAND;LABELS" ${ARGN})
  if(NOT DARKROOM_WITH_MPI OR NOT DARKROOM_BUILD_TESTS)
    return()
  endif()
  if(NOT ARG_RANKS)
    set(ARG_RANKS 4)
  endif()
  if(NOT ARG_TIMEOUT)
    set(ARG_TIMEOUT 300)
  endif()
  add_test(NAME ${NAME}
    COMMAND ${MPIEXEC_EXECUTABLE} ${MPIEXEC_NUMPROC_FLAG} ${ARG_RANKS} --oversubscribe ${MPIEXEC_PREFLAGS}
            ${ARG_COMMAND} ${MPIEXEC_POSTFLAGS}
    WORKING_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
  set_tests_properties(${NAME} PROPERTIES
    LABELS "mpi;${ARG_LABELS}"
    TIMEOUT ${ARG_TIMEOUT}
    # Several ranks on few cores: do not run beside other tests' threads.
    RUN_SERIAL TRUE
    ENVIRONMENT "OMPI_ALLOW_RUN_AS_ROOT=1;OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1;OMPI_MCA_rmaps_base_oversubscribe=1;DARKROOM_PLUGIN_PATH=")
  if(DARKROOM_MPI_TEST_ENV_MODIFICATION)
    set_tests_properties(${NAME} PROPERTIES ENVIRONMENT_MODIFICATION "${DARKROOM_MPI_TEST_ENV_MODIFICATION}")
  endif()
endfunction()
