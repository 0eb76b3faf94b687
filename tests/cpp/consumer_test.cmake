# Installs chasles from BUILD_DIR into a fresh prefix, then configures,
# builds and runs tests/consumer against it with find_package(chasles), as a
# user's project would. The code it builds is taken from the documentation:
#   - README.md's C++ quick start (its one ```cpp block without a main),
#     compiled inside tests/consumer/main.cpp, which checks its values;
#   - README.md's ```cmake block (find_package and target_link_libraries),
#     included by tests/consumer/CMakeLists.txt as written;
#   - every ```cpp block of docs/*.md and every other one of README.md: each
#     is a complete program (it has an int main()), built and run; it must
#     exit with 0.
# Everything is compiled with -Wall -Wextra -Werror -fno-exceptions, assertions on.
# Run by ctest with -DBUILD_DIR=... -DSOURCE_DIR=... -DWORK_DIR=... -DCXX=<the project's compiler>
# A script (cmake -P) starts with no policy set, so an older CMake reads it
# its old way (Debian's 3.25: while(TRUE) is false): the project's policies.
cmake_minimum_required(VERSION 3.18)
file(REMOVE_RECURSE "${WORK_DIR}")
set(SNIPPETS "${WORK_DIR}/snippets")
file(MAKE_DIRECTORY "${SNIPPETS}")

# The fenced blocks of one language in a Markdown file, each written to
# OUT_PREFIX_<n>.txt (n from 1); sets OUT_VAR to the list of those files.
function(extract_blocks markdown language out_prefix out_var)
  file(READ "${markdown}" text)
  set(fence "```${language}\n")
  string(LENGTH "${fence}" fence_length)
  set(files "")
  set(n 0)
  while(TRUE)
    string(FIND "${text}" "${fence}" start)
    if(start EQUAL -1)
      break()
    endif()
    math(EXPR start "${start} + ${fence_length}")
    string(SUBSTRING "${text}" ${start} -1 text)
    string(FIND "${text}" "```" stop)
    if(stop EQUAL -1)
      message(FATAL_ERROR "${markdown}: a ```${language} block is not closed")
    endif()
    string(SUBSTRING "${text}" 0 ${stop} block)
    string(SUBSTRING "${text}" ${stop} -1 text)
    math(EXPR n "${n} + 1")
    file(WRITE "${out_prefix}_${n}.txt" "${block}")
    list(APPEND files "${out_prefix}_${n}.txt")
  endwhile()
  set(${out_var} "${files}" PARENT_SCOPE)
endfunction()

# Sorts the C++ blocks of a Markdown file: complete programs go to
# SNIPPETS/<stem>_<n>.cpp; fragments are returned in FRAGMENTS_VAR.
function(take_cpp_blocks markdown stem fragments_var)
  extract_blocks("${markdown}" cpp "${SNIPPETS}/${stem}_cpp" blocks)
  set(fragments "")
  foreach(block_file ${blocks})
    file(READ "${block_file}" block)
    get_filename_component(name "${block_file}" NAME_WE)
    if(block MATCHES "int main\\(")
      file(WRITE "${SNIPPETS}/${name}.cpp" "${block}")
    else()
      list(APPEND fragments "${block_file}")
    endif()
  endforeach()
  set(${fragments_var} "${fragments}" PARENT_SCOPE)
endfunction()

take_cpp_blocks("${SOURCE_DIR}/README.md" readme readme_fragments)
list(LENGTH readme_fragments count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "README.md should have one C++ block without a main (the quick start), not ${count}")
endif()
# The quick start runs inside main() of tests/consumer/main.cpp, which includes
# the headers: its #include lines are dropped.
file(READ "${readme_fragments}" block)
string(REGEX REPLACE "#include[^\n]*\n" "" body "${block}")
file(WRITE "${SNIPPETS}/readme_quick_start.inc" "${body}")

extract_blocks("${SOURCE_DIR}/README.md" cmake "${SNIPPETS}/readme_cmake" cmake_blocks)
list(LENGTH cmake_blocks count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "README.md should have one ```cmake block, not ${count}")
endif()
file(READ "${cmake_blocks}" block)
file(WRITE "${SNIPPETS}/readme.cmake" "${block}")

file(GLOB docs "${SOURCE_DIR}/docs/*.md")
foreach(doc ${docs})
  get_filename_component(stem "${doc}" NAME_WE)
  take_cpp_blocks("${doc}" "${stem}" fragments)
  if(fragments)
    message(FATAL_ERROR "${doc}: every C++ block must be a complete program with an int main()")
  endif()
endforeach()
file(GLOB programs "${SNIPPETS}/*.cpp")

execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${WORK_DIR}/prefix"
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "cmake --install failed: ${rc}")
endif()
# The programs that use the URDF loader need it installed (urdfdom found).
if(NOT EXISTS "${WORK_DIR}/prefix/share/cmake/chasles/chaslesUrdfTargets.cmake")
  foreach(program ${programs})
    file(READ "${program}" text)
    if(text MATCHES "chasles/urdf\\.hpp")
      list(REMOVE_ITEM programs "${program}")
      message(STATUS "no chasles::urdf installed (urdfdom not found): ${program} left out")
    endif()
  endforeach()
endif()
# The consumer is built by the compiler that built the installed
# chasles::urdf (tests/cpp/CMakeLists.txt runs this test outside the
# sanitizer build only).
set(consumer_flags "-DCMAKE_CXX_COMPILER=${CXX}")
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/tests/consumer" -B "${WORK_DIR}/build"
                        "-DCMAKE_PREFIX_PATH=${WORK_DIR}/prefix" -DCMAKE_BUILD_TYPE=Release
                        "-DSNIPPET_DIR=${SNIPPETS}" ${consumer_flags}
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "configuring the consumer failed: ${rc}")
endif()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${WORK_DIR}/build" --parallel 2 RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "building the consumer failed: ${rc}")
endif()

set(failed "")
foreach(target app ${programs})
  get_filename_component(name "${target}" NAME_WE)
  execute_process(COMMAND "${WORK_DIR}/build/${name}" RESULT_VARIABLE rc)
  if(rc)
    list(APPEND failed "${name} (${rc})")
  endif()
endforeach()
list(LENGTH programs count)
if(failed)
  message(FATAL_ERROR "failed: ${failed}")
endif()
message(STATUS "the README quick start and ${count} documentation programs ran")
