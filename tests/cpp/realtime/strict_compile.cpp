// Every header and every operation, for float, double and an autodiff
// scalar, compiled with -fno-exceptions -fno-rtti and the warnings of
// tests/cpp/strict_flags.cmake as errors (tests/cpp/CMakeLists.txt, and with
// both GCC and Clang by strict_headers.cmake): a build that succeeds is the
// test.
#include <cmath>
#include <cstdio>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "chasles/chasles.hpp"
#include "chasles/constants.hpp"
#include "chasles/detail/approx.hpp"
#include "chasles/detail/arguments.hpp"
#include "chasles/detail/assert.hpp"
#include "chasles/detail/nearest_rotation.hpp"
#include "chasles/detail/series.hpp"
#include "chasles/jacobians.hpp"
#include "chasles/kinematics.hpp"
#include "chasles/screw.hpp"
#include "chasles/se3.hpp"
#include "chasles/so3.hpp"
#include "chasles/twist.hpp"
#include "chasles/wrench.hpp"
#include "realtime/exercise_all.hpp"

int main() {
  using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 6, 1>>;
  const double a = chasles_test::exercise_all<double>();
  const float b = chasles_test::exercise_all<float>();
  const AD c = chasles_test::exercise_all<AD>();
  const bool ok = std::isfinite(a) && std::isfinite(b) && std::isfinite(c.value());
  std::printf("strict compile: %s\n", ok ? "ok" : "non-finite checksum");
  return ok ? 0 : 1;
}
