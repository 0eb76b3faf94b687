# Compiles every header of include/chasles with one compiler (CXX) under the
# strict warnings of strict_flags.cmake, as errors, with chasles' headers
# through a plain -I (so their warnings count) and Eigen's through -isystem
# (its own warnings are not ours):
#   - each header alone (it is self-contained, and does not pull in
#     <iostream>, whose static initializer a real-time build may forbid);
#   - tests/cpp/realtime/strict_compile.cpp, which calls every operation for
#     float, double and an autodiff scalar: with -O2 -DNDEBUG (a release
#     build, with the optimizer's warnings) and with assertions on.
# Run by ctest with -DCXX=... -DCOMPILER_ID=gcc|clang -DBUILDS_PROJECT=ON|OFF -DSOURCE_DIR=...
# -DEIGEN_INCLUDE_DIRS=<dir>|<dir>... -DWORK_DIR=...; a CXX that was not
# found prints "SKIPPED" (ctest reports the test as skipped).
if(NOT CXX OR CXX MATCHES "-NOTFOUND$")
  message("SKIPPED: no ${COMPILER_ID} C++ compiler found")
  return()
endif()
include("${CMAKE_CURRENT_LIST_DIR}/strict_flags.cmake")
set(flags -std=c++17 ${CHASLES_STRICT_FLAGS})
if(COMPILER_ID STREQUAL "clang")
  list(APPEND flags ${CHASLES_STRICT_CLANG_FLAGS})
endif()
list(APPEND flags "-I${SOURCE_DIR}/include" "-I${SOURCE_DIR}/tests/cpp")
string(REPLACE "|" ";" EIGEN_INCLUDE_DIRS "${EIGEN_INCLUDE_DIRS}")
foreach(dir ${EIGEN_INCLUDE_DIRS})
  list(APPEND flags -isystem "${dir}")
endforeach()

file(REMOVE_RECURSE "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

set(failed "")
function(compile what)
  execute_process(COMMAND "${CXX}" ${flags} ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
  if(rc)
    message("${what}: failed\n${out}")
    set(failed "${failed} ${what}" PARENT_SCOPE)
  else()
    message("${what}: ok")
  endif()
endfunction()

file(GLOB_RECURSE headers RELATIVE "${SOURCE_DIR}/include" "${SOURCE_DIR}/include/chasles/*.hpp")
list(SORT headers)
foreach(header ${headers})
  string(MAKE_C_IDENTIFIER "${header}" stem)
  set(tu "${WORK_DIR}/${stem}.cpp")
  file(WRITE "${tu}" "#include \"${header}\"
#if defined(__GLIBCXX__) && defined(_GLIBCXX_IOSTREAM)
#error \"${header} pulls in <iostream>\"
#endif
int main() { return 0; }
")
  compile("${header} alone" -fsyntax-only "${tu}")
endforeach()

set(exercise "${SOURCE_DIR}/tests/cpp/realtime/strict_compile.cpp")
# The compiler that builds the project already compiles the exercise with
# these flags, optimized and without assertions (the chasles_strict_compile
# target): compiling it again here would repeat the most expensive step of
# the suite (about 5 CPU minutes with g++) for no new check.
if(NOT BUILDS_PROJECT)
  compile("strict_compile.cpp, -O2 -DNDEBUG" -O2 -DNDEBUG -c "${exercise}" -o "${WORK_DIR}/strict_compile.o")
endif()
compile("strict_compile.cpp, assertions on" -fsyntax-only "${exercise}")

if(failed)
  message(FATAL_ERROR "strict compile with ${CXX} failed:${failed}")
endif()
