# cmake -DSOURCE=<tests/fuzz> -DBINARY=<build>/fuzz -DCXX=<clang++> [-DWERROR=ON] -P build.cmake
# Configures (once) and builds the fuzz harnesses with clang; the ctest
# fixture `fuzz_build` (cmake/DarkroomFuzz.cmake) and scripts/fuzz.sh run it.
if(NOT EXISTS ${BINARY}/build.ninja)
  execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE} -B ${BINARY} -G Ninja
                          -DCMAKE_CXX_COMPILER=${CXX} -DDARKROOM_WERROR=${WERROR}
                  RESULT_VARIABLE rc)
  if(rc)
    message(FATAL_ERROR "configuring the fuzz harnesses in ${BINARY} failed")
  endif()
endif()
execute_process(COMMAND ${CMAKE_COMMAND} --build ${BINARY} RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the fuzz harnesses in ${BINARY} failed")
endif()
