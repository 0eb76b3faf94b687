// The real-time exercise for AutoDiff, compiled once: exercise_all.hpp declares
// its instantiations extern, and each scalar has a file of its own, built when
// CHASLES_EXERCISE_SCALARS names it (tests/cpp/CMakeLists.txt: what each
// costs, and which build compiles which), with -fno-exceptions -fno-rtti and
// the warnings of tests/cpp/strict_flags.cmake as errors: a build that
// succeeds is the test of every operation under those flags.
#include "realtime/exercise_all.hpp"

namespace chasles_test {

template AutoDiff exercise_all<AutoDiff>() noexcept;

}  // namespace chasles_test
