# Compiles every header of include/chasles alone with one compiler (CXX)
# under the strict warnings of strict_flags.cmake, as errors, with chasles'
# headers through a plain -I (so their warnings count) and Eigen's through
# -isystem (its own warnings are not ours): each header is self-contained,
# and does not pull in <iostream>, whose static initializer a real-time
# build may forbid. (Every operation of every header, for float, double and
# an autodiff scalar, is compiled under the same flags by the object
# chasles_realtime_exercise, which chasles_strict_compile links:
# tests/cpp/CMakeLists.txt.)
# Run by ctest with -DCXX=... -DCOMPILER_ID=gcc|clang -DSOURCE_DIR=...
# -DEIGEN_INCLUDE_DIRS=<dir>|<dir>... [-DWITH_CERES=ON -DCERES_INCLUDE_DIRS=<dir>|...]
# -DWORK_DIR=...
# A script (cmake -P) starts with no policy set, so an older CMake reads it
# its old way (Debian's 3.25: while(TRUE) is false): the project's policies.
cmake_minimum_required(VERSION 3.18)
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
# chasles/ceres.hpp needs Ceres's headers (-DWITH_CERES=ON and their
# directories beyond the compiler's in -DCERES_INCLUDE_DIRS=<dir>|...);
# without Ceres the header is skipped, and said so.
if(WITH_CERES)
  string(REPLACE "|" ";" CERES_INCLUDE_DIRS "${CERES_INCLUDE_DIRS}")
  foreach(dir ${CERES_INCLUDE_DIRS})
    list(APPEND flags -isystem "${dir}")
  endforeach()
else()
  list(REMOVE_ITEM headers chasles/ceres.hpp)
  message("chasles/ceres.hpp alone: skipped (Ceres not found)")
endif()
foreach(header ${headers})
  string(MAKE_C_IDENTIFIER "${header}" stem)
  set(tu "${WORK_DIR}/${stem}.cpp")
  # (Ceres's own headers include <iostream>, through glog: not a real-time header.)
  set(check_iostream "#if defined(__GLIBCXX__) && defined(_GLIBCXX_IOSTREAM)
#error \"${header} pulls in <iostream>\"
#endif
")
  if(header STREQUAL "chasles/ceres.hpp")
    set(check_iostream "")
  endif()
  file(WRITE "${tu}" "#include \"${header}\"
${check_iostream}int main() { return 0; }
")
  compile("${header} alone" -fsyntax-only "${tu}")
endforeach()

if(failed)
  message(FATAL_ERROR "strict compile with ${CXX} failed:${failed}")
endif()
