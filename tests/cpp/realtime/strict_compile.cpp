// Every header, and the operator<< of every type (io.hpp: outside
// exercise_all, which the allocation test also runs), for float, double and
// an autodiff scalar, compiled with -fno-exceptions -fno-rtti and the
// warnings of tests/cpp/strict_flags.cmake as errors (tests/cpp/CMakeLists.txt):
// a build that succeeds is the test. Every operation is compiled under the
// same flags in exercise_*.cpp, which this program links, and runs for
// each scalar built.
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <sstream>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "chasles/align.hpp"
#include "chasles/bspline.hpp"
#include "chasles/chasles.hpp"
#include "chasles/constants.hpp"
#include "chasles/detail/approx.hpp"
#include "chasles/detail/arguments.hpp"
#include "chasles/detail/assert.hpp"
#include "chasles/detail/nearest_rotation.hpp"
#include "chasles/detail/series.hpp"
#include "chasles/detail/small_solve.hpp"
#include "chasles/detail/weights.hpp"
#include "chasles/distance.hpp"
#include "chasles/dynamics.hpp"
#include "chasles/euler.hpp"
#include "chasles/io.hpp"
#include "chasles/jacobians.hpp"
#include "chasles/kinematics.hpp"
#include "chasles/mean.hpp"
#include "chasles/random.hpp"
#include "chasles/screw.hpp"
#include "chasles/se3.hpp"
#include "chasles/so3.hpp"
#include "chasles/spatial_inertia.hpp"
#include "chasles/spline.hpp"
#include "chasles/twist.hpp"
#include "chasles/wrench.hpp"
#include "realtime/exercise_all.hpp"

namespace {

/// Prints one object of every public type; returns the length of the text.
template <typename S>
std::size_t print_all() {
  using namespace chasles;
  using V3 = Eigen::Matrix<S, 3, 1>;
  const V3 w(S(0.3), S(-0.2), S(0.1)), p(S(1), S(2), S(3));
  const SO3<S> R = SO3<S>::exp(w);
  const SE3<S> g(R, p);
  const Twist<S> xi(p, w);
  typename Chain<S, 2>::Screws screws;
  screws.col(0) = Chain<S, 2>::revolute_screw(p, w);
  screws.col(1) = Chain<S, 2>::prismatic_screw(w);
  typename Chain<S, Eigen::Dynamic, 4>::Screws dynamic_screws(6, 1);
  dynamic_screws.col(0) = screws.col(0);
  std::ostringstream os;
  os << R << g << xi << Wrench<S>(p, w) << xi.screw() << Chain<S, 2>(screws, g)
     << Chain<S, Eigen::Dynamic, 4>(dynamic_screws, g) << compose_jacobians(g, g) << act_jacobians(R, p)
     << SpatialInertia<S>(S(1), p, Eigen::Matrix<S, 3, 3>::Identity());
  return os.str().size();
}

}  // namespace

int main() {
  // The exercise of each scalar built (CHASLES_EXERCISE_SCALARS, tests/cpp/CMakeLists.txt).
  bool ok = print_all<double>() > 0 && print_all<float>() > 0 && print_all<chasles_test::AutoDiff>() > 0;
  int ran = 0;
#ifdef CHASLES_EXERCISE_FLOAT
  ok = ok && std::isfinite(chasles_test::exercise_all<float>());
  ++ran;
#endif
#ifdef CHASLES_EXERCISE_DOUBLE
  ok = ok && std::isfinite(chasles_test::exercise_all<double>());
  ++ran;
#endif
#ifdef CHASLES_EXERCISE_AUTODIFF
  ok = ok && std::isfinite(chasles_test::exercise_all<chasles_test::AutoDiff>().value());
  ++ran;
#endif
  std::printf("strict compile: %s (the exercise of %d scalars)\n", ok ? "ok" : "non-finite checksum", ran);
  return ok && ran > 0 ? 0 : 1;
}
