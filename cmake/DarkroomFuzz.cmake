# The readers' fuzz harnesses (tests/fuzz, docs/formats.md "Fuzzing") as
# tests: `fuzz_build` builds them into <build>/fuzz with clang, libFuzzer,
# AddressSanitizer and UBSan (the main build's g++ has no libFuzzer), then
# `fuzz_<reader>` runs each for a few seconds over its seed corpus. Label
# `fuzz`. Without clang or libFuzzer, configuring fails: never a silent skip.
include(${PROJECT_SOURCE_DIR}/tests/fuzz/harnesses.cmake)

set(DARKROOM_FUZZ_SECONDS 5 CACHE STRING "Seconds each fuzz test runs its harness")

find_program(DARKROOM_CLANGXX NAMES clang++ clang++-14)
if(NOT DARKROOM_CLANGXX)
  message(FATAL_ERROR "The fuzz tests need clang++ and libFuzzer: install the Debian packages "
                      "clang and libclang-rt-14-dev (scripts/install-deps.sh installs them)")
endif()
# libFuzzer is a separate Debian package from clang: link a do-nothing
# harness to find out, once per build folder.
if(NOT DARKROOM_LIBFUZZER_LINKS)
  set(check ${CMAKE_BINARY_DIR}/CMakeFiles/libfuzzer-check)
  file(WRITE ${check}/check.cpp
       "#include <cstddef>\n#include <cstdint>\n"
       "extern \"C\" int LLVMFuzzerTestOneInput(const std::uint8_t*, std::size_t) { return 0; }\n")
  execute_process(COMMAND ${DARKROOM_CLANGXX} -fsanitize=fuzzer,address,undefined check.cpp -o check
                  WORKING_DIRECTORY ${check} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(rc)
    message(FATAL_ERROR "The fuzz tests need libFuzzer, which ${DARKROOM_CLANGXX} cannot link: install "
                        "the Debian package libclang-rt-14-dev (scripts/install-deps.sh installs it).\n${out}")
  endif()
  set(DARKROOM_LIBFUZZER_LINKS ON CACHE INTERNAL "clang++ links -fsanitize=fuzzer")
endif()

set(fuzz_binary ${CMAKE_BINARY_DIR}/fuzz)
add_test(NAME fuzz_build
         COMMAND ${CMAKE_COMMAND} -DSOURCE=${PROJECT_SOURCE_DIR}/tests/fuzz -DBINARY=${fuzz_binary}
                 -DCXX=${DARKROOM_CLANGXX} -DWERROR=${DARKROOM_WERROR}
                 -P ${PROJECT_SOURCE_DIR}/tests/fuzz/build.cmake)
set_tests_properties(fuzz_build PROPERTIES FIXTURES_SETUP fuzz_harnesses LABELS fuzz TIMEOUT 900)

foreach(name IN LISTS DARKROOM_FUZZ_HARNESSES)
  # New inputs go to the first folder (under the build tree); the committed
  # corpus and the generated seeds are only read. Crashes land in crashes/.
  set(corpora ${fuzz_binary}/work/${name})
  if(EXISTS ${PROJECT_SOURCE_DIR}/tests/fuzz/corpus/${name})
    list(APPEND corpora ${PROJECT_SOURCE_DIR}/tests/fuzz/corpus/${name})
  endif()
  if(name IN_LIST DARKROOM_FUZZ_GENERATED_SEEDS)
    list(APPEND corpora ${fuzz_binary}/seeds/${name})
  endif()
  file(MAKE_DIRECTORY ${fuzz_binary}/work/${name} ${fuzz_binary}/crashes)
  # A fixed seed: the suite's short runs replay the same mutations on every
  # machine, so a test run passes or fails for its code, not its luck; the
  # long runs that explore (scripts/fuzz.sh) take a fresh seed each time.
  add_test(NAME fuzz_${name}
           COMMAND ${fuzz_binary}/fuzz_${name} -seed=1 -max_total_time=${DARKROOM_FUZZ_SECONDS} -timeout=30
                   -print_final_stats=1 -artifact_prefix=${fuzz_binary}/crashes/${name}- ${corpora})
  set_tests_properties(fuzz_${name} PROPERTIES FIXTURES_REQUIRED fuzz_harnesses LABELS fuzz TIMEOUT 120)
endforeach()
