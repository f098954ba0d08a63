# darkroom_add_gtest(NAME SOURCES src... [LIBRARIES lib...] [DEPENDS target...] [LABEL label])
#
# One GoogleTest executable registered with ctest; LABEL puts its tests in a
# group ctest can select (`ctest -L accuracy`). Tests find the build's
# plugins, the source tree and ../shared/data through compile definitions.
if(DARKROOM_BUILD_TESTS)
  include(GoogleTest)
  find_package(GTest REQUIRED)
endif()

function(darkroom_add_gtest NAME)
  if(NOT DARKROOM_BUILD_TESTS)
    return()
  endif()
  cmake_parse_arguments(ARG "" "LABEL" "SOURCES;LIBRARIES;DEPENDS" ${ARGN})
  add_executable(${NAME} ${ARG_SOURCES})
  target_link_libraries(${NAME} PRIVATE darkroom_testsupport GTest::gtest_main GTest::gmock ${ARG_LIBRARIES})
  target_compile_definitions(${NAME} PRIVATE
    DARKROOM_TEST_PLUGIN_DIR="${DARKROOM_PLUGIN_OUTPUT_DIRECTORY}"
    DARKROOM_SOURCE_DIR="${PROJECT_SOURCE_DIR}"
    DARKROOM_BINARY_DIR="${PROJECT_BINARY_DIR}"
    DARKROOM_SHARED_DATA_DIR="${PROJECT_SOURCE_DIR}/../shared/data")
  set_target_properties(${NAME} PROPERTIES RUNTIME_OUTPUT_DIRECTORY ${PROJECT_BINARY_DIR}/tests)
  if(ARG_DEPENDS)
    add_dependencies(${NAME} ${ARG_DEPENDS})
  endif()
  set(properties ENVIRONMENT "DARKROOM_PLUGIN_PATH=")
  if(ARG_LABEL)
    list(APPEND properties LABELS ${ARG_LABEL})
  endif()
  # Tests that start mpirun themselves (cmake/DarkroomMpi.cmake says why).
  if(ARG_LABEL STREQUAL "mpi" AND DARKROOM_MPI_TEST_ENV_MODIFICATION)
    list(APPEND properties ENVIRONMENT_MODIFICATION "${DARKROOM_MPI_TEST_ENV_MODIFICATION}")
  endif()
  gtest_discover_tests(${NAME} DISCOVERY_MODE PRE_TEST
    WORKING_DIRECTORY ${PROJECT_BINARY_DIR}/tests
    PROPERTIES ${properties})
endfunction()
