# A compile-fail test: the snippet SOURCE (tests/cpp/compile_fail/*.cpp)
# must compile as it is, and must fail to compile with
# -DCHASLES_COMPILE_FAIL=k for each case k = 1..n (its "// cases: n" line;
# 1 without one), which turns on the mistaken code of that case, with a
# message that matches every regular expression of its "// expect: <regex>"
# lines. The first compile shows that each failure comes from its case only.
# Run by ctest with -DCXX=... -DSOURCE=... -DSOURCE_DIR=... -DEIGEN_INCLUDE_DIRS=<dir>|<dir>...
# A script (cmake -P) starts with no policy set, so an older CMake reads it
# its old way (Debian's 3.25: while(TRUE) is false): the project's policies.
cmake_minimum_required(VERSION 3.18)
file(STRINGS "${SOURCE}" expect_lines REGEX "^// expect: ")
if(NOT expect_lines)
  message(FATAL_ERROR "${SOURCE}: no \"// expect: <regex>\" line")
endif()
file(STRINGS "${SOURCE}" cases_line REGEX "^// cases: [0-9]+$")
set(cases 1)
if(cases_line)
  string(REGEX REPLACE "^// cases: " "" cases "${cases_line}")
endif()
set(flags -std=c++17 -fsyntax-only "-I${SOURCE_DIR}/include")
string(REPLACE "|" ";" EIGEN_INCLUDE_DIRS "${EIGEN_INCLUDE_DIRS}")
foreach(dir ${EIGEN_INCLUDE_DIRS})
  list(APPEND flags -isystem "${dir}")
endforeach()

execute_process(COMMAND "${CXX}" ${flags} "${SOURCE}" RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(rc)
  message(FATAL_ERROR "${SOURCE} does not compile even without CHASLES_COMPILE_FAIL:\n${out}")
endif()

foreach(k RANGE 1 ${cases})
  execute_process(COMMAND "${CXX}" ${flags} -DCHASLES_COMPILE_FAIL=${k} "${SOURCE}"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(NOT rc)
    message(FATAL_ERROR "${SOURCE}: case ${k} compiled: it must not")
  endif()
  foreach(line ${expect_lines})
    string(REGEX REPLACE "^// expect: " "" regex "${line}")
    if(NOT out MATCHES "${regex}")
      message(FATAL_ERROR "${SOURCE}: case ${k}: the compiler's message does not match \"${regex}\":\n${out}")
    endif()
  endforeach()
endforeach()
message(STATUS "${SOURCE}: each of its ${cases} case(s) fails to compile as expected")
