// The real-time exercise compiled once: the explicit instantiations of
// exercise_all (exercise_all.hpp declares them extern), for float, double
// and the autodiff scalar, under -fno-exceptions -fno-rtti and the warnings
// of tests/cpp/strict_flags.cmake as errors (tests/cpp/CMakeLists.txt: the
// object chasles_realtime_exercise, which chasles_strict_compile and
// chasles_realtime_tests link). A build that succeeds is the test of every
// operation under those flags.
#include "realtime/exercise_all.hpp"

namespace chasles_test {

template float exercise_all<float>() noexcept;
template double exercise_all<double>() noexcept;
template AutoDiff exercise_all<AutoDiff>() noexcept;

}  // namespace chasles_test
