// The real-time exercise for double, compiled once: exercise_all.hpp declares
// its instantiations extern, and each scalar has a file of its own
// (exercise_float.cpp, exercise_double.cpp, exercise_autodiff.cpp), the
// object chasles_realtime_exercise of tests/cpp/CMakeLists.txt: g++ at -O3
// took 500 s of CPU for the three in one file, 276 s for them apart (75 s
// float, 75 s double, 126 s autodiff: its cost grows faster than the file),
// and the three build in parallel. Built
// with -fno-exceptions -fno-rtti and the warnings of
// tests/cpp/strict_flags.cmake as errors (chasles_strict_compile and
// chasles_realtime_tests link it): a build that succeeds is the test of
// every operation under those flags.
#include "realtime/exercise_all.hpp"

namespace chasles_test {

template double exercise_all<double>() noexcept;

}  // namespace chasles_test
