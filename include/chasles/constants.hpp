// chasles: Lie groups of rigid-body motion.
//
// Every numeric threshold of the library, per real type, with how it was chosen.
// Nothing else in include/ holds a tolerance or a cutoff: the series in
// detail/series.hpp and the checked constructors read them from here.
#pragma once

#include <Eigen/Core>

namespace chasles {

/// The floating-point type under a Scalar: float for float, double for double
/// and for automatic-differentiation scalars over double
/// (`Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>`).
template <typename Scalar>
using RealOf = typename Eigen::NumTraits<Scalar>::Literal;

/// Thresholds for one real type. Only float, double and long double are
/// defined: a new real type must state its own numbers here.
template <typename Real>
struct Thresholds;

// How the numbers are chosen.
//
// taylor_theta2: the cutoff, on theta^2, below which exp, log and their
//   coefficient functions use their Taylor series instead of the closed
//   forms. Every series in detail/series.hpp is kept up to t^2 (t = theta^2)
//   and its first omitted term, relative to its leading term, has a
//   coefficient of magnitude at most 1 (the largest is 1/7, for atan(x)/x
//   in log, whose x^2 = tan^2(theta/2) is t/4). Below t = eps^(1/3) that
//   term is under eps,
//   so the series is exact to the last place; the cutoff is the truncation
//   degree rule eps^(1/(k+1)) with k = 2. Above it the closed forms have no
//   0/0 and lose no more than a few ulps (see docs of each closed form).
//   Both sides are compared one ulp apart in tests/cpp/test_thresholds.cpp.
//   Every caller compares the same quantity, theta^2 (or 4 tan^2(theta/2)
//   in log, equal to theta^2 to within the series' own accuracy), never theta,
//   so that no square root of 0 is ever formed (its derivative is infinite).
//
// rotation_tolerance: default for the checked constructors
//   (`from_matrix`): the largest accepted defect max(|M^T M - I|_max,
//   |det M - 1|). sqrt(eps): data written with at least half the digits of
//   the type passes (a double rotation printed with 9 significant digits has
//   a defect near 1e-9); data worse than that is no longer a rotation to
//   working precision, and the caller should say so by projecting it
//   explicitly (`from_matrix_projected`).
//
// huge_theta2: above this theta^2 (and when theta^2 overflows) exp takes a
//   cold path that never forms w w^T or theta^2, working with the unit axis
//   and theta/2. Chosen a factor 1e8 below the largest finite value, so
//   that w w^T and the products with it cannot overflow on the fast path.
//   Past theta ~ 2 pi / eps the input's angle is not known to within a turn,
//   so only the axis and the bounded translation carry information there.
//   It is also the largest squared norm that from_quaternion normalizes
//   directly.
//
// tiny_norm2: the smallest squared norm that from_quaternion normalizes
//   directly, 1 / huge_theta2: 1e8 times the reciprocal of the largest
//   finite value, so 2 / |q|^2 is finite and |q|^2 is a sum of squares
//   that have not underflowed to subnormals. Below it (or above
//   huge_theta2) q is first scaled by its largest component.

template <>
struct Thresholds<float> {
  static constexpr float epsilon = 1.1920929e-07f;
  static constexpr float taylor_theta2 = 4.9215667e-03f;       // eps^(1/3)
  static constexpr float rotation_tolerance = 3.4526698e-04f;  // eps^(1/2)
  static constexpr float huge_theta2 = 3.4e30f;                // max / 1e8
  static constexpr float tiny_norm2 = 1.0f / huge_theta2;
  static constexpr float mean_step_tolerance = 3.4526698e-04f;  // eps^(1/2)
  static constexpr int mean_max_iterations = 20;
  static constexpr float euler_lock2 = 1.4210855e-14f;  // eps^2
  static constexpr float inertia_tolerance = 3.4526698e-04f;  // eps^(1/2)
};

template <>
struct Thresholds<double> {
  static constexpr double epsilon = 2.220446049250313e-16;
  static constexpr double taylor_theta2 = 6.0554544523933395e-06;      // eps^(1/3)
  static constexpr double rotation_tolerance = 1.4901161193847656e-08;  // eps^(1/2)
  static constexpr double huge_theta2 = 1.7e300;                        // max / 1e8
  static constexpr double tiny_norm2 = 1.0 / huge_theta2;
  static constexpr double mean_step_tolerance = 1.4901161193847656e-08;  // eps^(1/2)
  static constexpr int mean_max_iterations = 20;
  static constexpr double euler_lock2 = 4.930380657631324e-32;  // eps^2
  static constexpr double inertia_tolerance = 1.4901161193847656e-08;  // eps^(1/2)
};

template <>
struct Thresholds<long double> {
  // x87 extended precision (64-bit mantissa); on platforms where long double
  // is double, these are merely conservative.
  static constexpr long double epsilon = 1.0842021724855044340e-19L;
  static constexpr long double taylor_theta2 = 4.7683715820312500000e-07L;       // eps^(1/3)
  static constexpr long double rotation_tolerance = 3.2927225399135962334e-10L;  // eps^(1/2)
  static constexpr long double huge_theta2 = 1.7e300L;  // as double: safe for both long double formats
  static constexpr long double tiny_norm2 = 1.0L / huge_theta2;
  static constexpr long double mean_step_tolerance = 3.2927225399135962334e-10L;  // eps^(1/2)
  static constexpr int mean_max_iterations = 20;
  static constexpr long double euler_lock2 = 1.1754943508222875079687e-38L;  // eps^2
  static constexpr long double inertia_tolerance = 3.2927225399135962334e-10L;  // eps^(1/2)
};

// mean_step_tolerance: the geodesic (Karcher) mean (mean.hpp) stops after
//   a Newton step delta with |delta| <= mean_step_tolerance * (1 + rms),
//   rms the weighted root mean square of the residuals |log(M^-1 X_i)|.
//   sqrt(eps): Newton's method on sum_i w_i log(M^-1 X_i) = 0 converges
//   quadratically, so after a step of that size the remaining error is of
//   the order of its square, eps (times the curvature of the spread); a
//   tolerance near eps instead could never be met when the rounding of the
//   sum (about sqrt(N) eps) exceeds it. tests/cpp/test_mean.cpp checks the
//   residual sum against 1e-14 (double) after convergence.
//
// mean_max_iterations: the bound on those Newton steps, 20 (the cap of
//   other libraries' Karcher means, which take plain gradient steps: 10 to
//   13 of them at a 1 rad spread); Newton takes 2 (float) or 3 (double)
//   there, so the bound is only reached by spreads near pi, where the mean
//   is not unique.
//
// inertia_tolerance: SpatialInertia::is_physical accepts a rotational
//   inertia whose asymmetry is at most this times its largest entry, and
//   principal moments that break the triangle inequality I_1 + I_2 >= I_3
//   by at most this times the trace. sqrt(eps), as rotation_tolerance: a
//   thin plate (I_3 = I_1 + I_2 exactly) written with half the digits of the
//   type passes; anything further off is not a body. tests/cpp/
//   test_spatial_inertia.cpp checks both sides.
//
/// The thresholds that apply to a Scalar (autodiff scalars use their real type's).
template <typename Scalar>
using ThresholdsOf = Thresholds<RealOf<Scalar>>;

}  // namespace chasles
