# Writes CTEST_FILE: one ctest test per GoogleTest test suite of EXECUTABLE, each running that
# suite's tests in one process and writing their results to RESULTS_DIR/<suite>.xml (GoogleTest's
# XML, one <testcase> per test: scripts/reliability-report.sh reads these).
#
# Why suites and not single tests: starting one of the test programs costs about 0.5 s (0.9 s with
# ASan), almost all of it the dynamic loader binding OpenImageIO's 260 libraries, and the GL tests
# make a headless context on top. One process per test spent more time starting than testing.
#
# Run after each build of the executable (tests/CMakeLists.txt):
#   cmake -D EXECUTABLE=… -D CTEST_FILE=… -D RESULTS_DIR=… -D LABEL=… -D WORKING_DIRECTORY=… -P AddGTestSuites.cmake
cmake_minimum_required(VERSION 3.25)

foreach(required EXECUTABLE CTEST_FILE RESULTS_DIR LABEL WORKING_DIRECTORY)
  if(NOT DEFINED ${required})
    message(FATAL_ERROR "AddGTestSuites.cmake: ${required} is not set")
  endif()
endforeach()

execute_process(COMMAND "${EXECUTABLE}" --gtest_list_tests
                OUTPUT_VARIABLE listing ERROR_VARIABLE errors RESULT_VARIABLE status TIMEOUT 60)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} --gtest_list_tests failed (${status}):\n${listing}\n${errors}")
endif()

# Results of suites that no longer exist must not be counted.
file(REMOVE_RECURSE "${RESULTS_DIR}")
file(MAKE_DIRECTORY "${RESULTS_DIR}")

# Suite lines start in the first column and end with '.', a typed suite's with "  # TypeParam = …";
# test lines are indented. Semicolons would split a CMake list, so they go first.
string(REPLACE ";" "," listing "${listing}")
string(REPLACE "\n" ";" lines "${listing}")
set(script "")
set(count 0)
foreach(line IN LISTS lines)
  if(NOT line MATCHES "^([A-Za-z_][A-Za-z0-9_/]*)\\.(  #.*)?$")
    continue()
  endif()
  set(suite "${CMAKE_MATCH_1}")
  string(REPLACE "/" "-" file_name "${suite}")
  string(APPEND script
    "add_test([==[${suite}]==] [==[${EXECUTABLE}]==] [==[--gtest_filter=${suite}.*]==]"
    " [==[--gtest_output=xml:${RESULTS_DIR}/${file_name}.xml]==])\n"
    "set_tests_properties([==[${suite}]==] PROPERTIES LABELS ${LABEL}"
    " WORKING_DIRECTORY [==[${WORKING_DIRECTORY}]==])\n")
  math(EXPR count "${count} + 1")
endforeach()
if(count EQUAL 0)
  message(FATAL_ERROR "${EXECUTABLE} --gtest_list_tests listed no test suite:\n${listing}")
endif()
file(WRITE "${CTEST_FILE}" "${script}")
