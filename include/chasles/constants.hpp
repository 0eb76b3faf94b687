// chasles: Lie groups of rigid-body motion.
//
// Every numeric threshold of the library, per real type, with how it was chosen.
// Nothing else in include/ holds a tolerance or a cutoff: the series in
// detail/series.hpp and the checked constructors read them from here.
#pragma once

#include <limits>
#include <type_traits>

#include <Eigen/Core>

namespace chasles {

/// The floating-point type under a Scalar: float for float, double for double
/// and for automatic-differentiation scalars over double
/// (`Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>`, whose
/// `NumTraits::Literal` is double). A scalar type whose `Literal` is itself
/// names its real type by specializing RealType (chasles/ceres.hpp does
/// for `ceres::Jet`).
template <typename Scalar>
struct RealType {
  using type = typename Eigen::NumTraits<Scalar>::Literal;
  /// x as its real type: x itself, or an autodiff scalar's value (of
  /// autodiff scalars of autodiff scalars too: the splines differentiate a
  /// Jacobian once more, spline.hpp).
  static type value(const Scalar& x) noexcept {
    if constexpr (std::is_floating_point<Scalar>::value) {
      return x;
    } else {
      return RealType<std::decay_t<decltype(x.value())>>::value(x.value());
    }
  }
};
template <typename Scalar>
using RealOf = typename RealType<Scalar>::type;

namespace detail {
/// The real value of a scalar (the value of an autodiff scalar): for a
/// comparison or a branch, never differentiated.
template <typename Scalar>
inline RealOf<Scalar> real_value(const Scalar& x) noexcept {
  return RealType<Scalar>::value(x);
}
/// The quiet NaN of a scalar type (of its real type for an autodiff scalar).
template <typename Scalar>
inline Scalar quiet_nan() noexcept {
  return Scalar(std::numeric_limits<RealOf<Scalar>>::quiet_NaN());
}

}  // namespace detail

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
//   Every caller compares the same quantity, theta^2 (or, in log,
//   sin^2(theta) and, off SO(3), 4 tan^2(theta/2): equal to theta^2 to
//   within the series' own accuracy), never theta,
//   so that no square root of 0 is ever formed (its derivative is infinite).
//
// exp_polynomial_theta2: up to this theta^2, exp's coefficients A, B, C
//   (detail/series.hpp, exp_coefficients) are polynomials in theta^2 for
//   float and double, fitted on [0, 10]: past pi^2 (9.87), so every
//   rotation vector of a log (angle <= pi) and every joint step of an arm
//   up to 3.16 rad is on the fast path, and little further, since the
//   degree the accuracy needs grows with the interval (on [0, 10] A needs
//   degree 10 in double). Beyond it the closed forms (sqrt, sincos). Long
//   double has no polynomials (0: never taken).
// exp_polynomial_center: the polynomials are in t - 7, not t: centered
//   near the top of the interval, where the coefficients multiply the
//   largest matrices, their terms cancel least (series.hpp measures it).
//
// log_quaternion_norm2: the largest |u|^2 of the so(3) log's unnormalized
//   quaternion u = K (K e_k) (detail::so3_log) that its rational atan takes
//   as it is. A rotation has |u| = 16 |q_k| in [8, 16], so |u|^2 <= 256,
//   and M clamped to [-2, 2] (the log's overflow path) gives |u|^2 < 3.5e4.
//   The atan's homogeneous forms and their products (detail/series.hpp)
//   grow as |u|^(2N'+1): finite up to |u|^2 = 2.26e8 in float (N' = 4) and
//   1.26e36 in double (N' = 8) (tests/tools/fit_atan_rational.py bounds
//   them). 1e6 is 3900 times a rotation's and 226 times below float's
//   overflow. Past it (a matrix with entries past about 3) u is normalized
//   first, on a cold path.
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
//
// huge_norm2: the largest squared norm |q|^2 that from_quaternion
//   normalizes directly: 1e8 below the largest finite value (as
//   huge_theta2, for the same reason: the products with q's components
//   cannot overflow). Above it q is first scaled by its largest component.
//
// tiny_norm2: the smallest squared norm that from_quaternion normalizes
//   directly, 1 / huge_norm2: 1e8 times the reciprocal of the largest
//   finite value, so 2 / |q|^2 is finite and |q|^2 is a sum of squares
//   that have not underflowed to subnormals. Below it q is first scaled by
//   its largest component. SO3::angle uses it for |u_v|^2 likewise.
//
// taylor_theta2 also bounds Sim(3)'s series (sim3.hpp, detail::
//   sim3_coefficients), by the same rule. Its W coefficients A, B, C are
//   functions of (sigma, theta^2); below sigma^2 + theta^2 = taylor_theta2
//   they are the double series in sigma and theta^2 kept to total degree 5
//   in r = |(sigma, theta)|, the omitted degree-6 terms having coefficients
//   that sum to less than 1 (the largest is 1/720): under r^6 < eps. Below
//   sigma^2 = taylor_theta2 alone (with theta^2 above it) the functions of
//   sigma, phi(sigma) = (e^sigma - 1)/sigma, sigma^2 phi'(sigma) and
//   sigma^2 phi''(sigma)/2, are their series in sigma to sigma^5 (the
//   same bound); the functions of theta^2 are series.hpp's as before.
//
// sim3_jacobian_norm, sim3_jacobian_degree: Sim(3)'s Jacobians of exp
//   take phi(ad_xi) = sum_k ad^k / (k+1)! (7x7) by scaling and squaring:
//   ad / 2^s with its 1-norm at most sim3_jacobian_norm, Taylor series of
//   exp and phi to degree m = sim3_jacobian_degree (phi's first omitted
//   term, of norm <= 0.5^(m+1) / (m+2)!, and exp's, <= 0.5^(m+2) / (m+2)!,
//   both under eps / 8), then s doublings.

template <>
struct Thresholds<float> {
  static constexpr float epsilon = 1.1920929e-07f;
  static constexpr float taylor_theta2 = 4.9215667e-03f;       // eps^(1/3)
  static constexpr float exp_polynomial_theta2 = 10.0f;        // past pi^2
  static constexpr float exp_polynomial_center = 7.0f;
  static constexpr float log_quaternion_norm2 = 1e6f;
  static constexpr float rotation_tolerance = 3.4526698e-04f;  // eps^(1/2)
  static constexpr float huge_theta2 = 3.4e30f;                // max / 1e8
  static constexpr float huge_norm2 = 3.4e30f;                 // max / 1e8
  static constexpr float tiny_norm2 = 1.0f / huge_norm2;
  static constexpr float mean_step_tolerance = 3.4526698e-04f;  // eps^(1/2)
  static constexpr int mean_max_iterations = 20;
  static constexpr float euler_lock2 = 1.4210855e-14f;  // eps^2
  static constexpr float ik_tolerance = 2.4221818e-05f;  // eps^(2/3)
  static constexpr int ik_max_iterations = 100;
  static constexpr int ik_stall_iterations = 8;
  static constexpr float ik_stall_ratio = 0.9f;
  static constexpr float spline_series_theta2 = 4.0f;
  static constexpr float spline_step_tolerance = 6.4e-06f;  // eps^(3/4)
  static constexpr int spline_max_iterations = 30;
  static constexpr float spline_min_step = 1e-6f;
  static constexpr float spline_max_step = 1e6f;
  static constexpr float spline_max_extrapolation = 100.0f;
  static constexpr float screw_tolerance = 3.4526698e-04f;  // eps^(1/2)
  static constexpr float inertia_tolerance = 3.4526698e-04f;  // eps^(1/2)
  static constexpr float mass_matrix_pivot_tolerance = 4.7683716e-07f;  // 4 eps
  static constexpr float sim3_jacobian_norm = 0.5f;
  static constexpr int sim3_jacobian_degree = 7;  // 0.5^9 / 9! = 5.4e-9 < eps / 8
  static constexpr float align_tolerance = 3.4526698e-04f;  // eps^(1/2)
  static constexpr float covariance_pivot_tolerance = 1.9073486e-06f;  // 16 eps
};

template <>
struct Thresholds<double> {
  static constexpr double epsilon = 2.220446049250313e-16;
  static constexpr double taylor_theta2 = 6.0554544523933395e-06;      // eps^(1/3)
  static constexpr double exp_polynomial_theta2 = 10.0;                 // past pi^2
  static constexpr double exp_polynomial_center = 7.0;
  static constexpr double log_quaternion_norm2 = 1e6;
  static constexpr double rotation_tolerance = 1.4901161193847656e-08;  // eps^(1/2)
  static constexpr double huge_theta2 = 1.7e300;                        // max / 1e8
  static constexpr double huge_norm2 = 1.7e300;                         // max / 1e8
  static constexpr double tiny_norm2 = 1.0 / huge_norm2;
  static constexpr double mean_step_tolerance = 1.4901161193847656e-08;  // eps^(1/2)
  static constexpr int mean_max_iterations = 20;
  static constexpr double euler_lock2 = 4.930380657631324e-32;  // eps^2
  static constexpr double ik_tolerance = 3.666852862501036e-11;  // eps^(2/3)
  static constexpr int ik_max_iterations = 100;
  static constexpr int ik_stall_iterations = 8;
  static constexpr double ik_stall_ratio = 0.9;
  static constexpr double spline_series_theta2 = 4.0;
  static constexpr double spline_step_tolerance = 1.8189894035458565e-12;  // eps^(3/4)
  static constexpr int spline_max_iterations = 30;
  static constexpr double spline_min_step = 1e-100;
  static constexpr double spline_max_step = 1e100;
  static constexpr double spline_max_extrapolation = 1e6;
  static constexpr double screw_tolerance = 1.4901161193847656e-08;  // eps^(1/2)
  static constexpr double inertia_tolerance = 1.4901161193847656e-08;  // eps^(1/2)
  static constexpr double mass_matrix_pivot_tolerance = 8.881784197001252e-16;  // 4 eps
  static constexpr double sim3_jacobian_norm = 0.5;
  static constexpr int sim3_jacobian_degree = 13;  // 0.5^15 / 15! = 2.3e-17 < eps / 8
  static constexpr double align_tolerance = 1.4901161193847656e-08;  // eps^(1/2)
  static constexpr double covariance_pivot_tolerance = 3.552713678800501e-15;  // 16 eps
};

template <>
struct Thresholds<long double> {
  // x87 extended precision (64-bit mantissa); on platforms where long double
  // is double, these are merely conservative.
  static constexpr long double epsilon = 1.0842021724855044340e-19L;
  static constexpr long double taylor_theta2 = 4.7683715820312500000e-07L;       // eps^(1/3)
  static constexpr long double exp_polynomial_theta2 = 0.0L;  // none: series and closed forms
  static constexpr long double exp_polynomial_center = 0.0L;
  static constexpr long double log_quaternion_norm2 = 1e6L;
  static constexpr long double rotation_tolerance = 3.2927225399135962334e-10L;  // eps^(1/2)
  static constexpr long double huge_theta2 = 1.7e300L;  // as double: safe for both long double formats
  static constexpr long double huge_norm2 = 1.7e300L;  // as double: safe for both long double formats
  static constexpr long double tiny_norm2 = 1.0L / huge_norm2;
  static constexpr long double mean_step_tolerance = 3.2927225399135962334e-10L;  // eps^(1/2)
  static constexpr int mean_max_iterations = 20;
  static constexpr long double euler_lock2 = 1.1754943508222875079687e-38L;  // eps^2
  static constexpr long double ik_tolerance = 2.2737367544323206e-13L;  // eps^(2/3)
  static constexpr int ik_max_iterations = 100;
  static constexpr int ik_stall_iterations = 8;
  static constexpr long double ik_stall_ratio = 0.9L;
  static constexpr long double spline_series_theta2 = 4.0L;
  static constexpr long double spline_step_tolerance = 5.9749283938523554e-15L;  // eps^(3/4)
  static constexpr int spline_max_iterations = 30;
  static constexpr long double spline_min_step = 1e-100L;  // as double: safe for both long double formats
  static constexpr long double spline_max_step = 1e100L;
  static constexpr long double spline_max_extrapolation = 1e6L;
  static constexpr long double screw_tolerance = 3.2927225399135962334e-10L;  // eps^(1/2)
  static constexpr long double inertia_tolerance = 3.2927225399135962334e-10L;  // eps^(1/2)
  static constexpr long double mass_matrix_pivot_tolerance = 4.3368086899420177360e-19L;  // 4 eps
  static constexpr long double sim3_jacobian_norm = 0.5L;
  static constexpr int sim3_jacobian_degree = 16;  // 0.5^18 / 18! = 6e-22 < eps / 8
  static constexpr long double align_tolerance = 3.2927225399135962334e-10L;  // eps^(1/2)
  static constexpr long double covariance_pivot_tolerance = 1.7347234759768070944e-18L;  // 16 eps
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
// ik_tolerance: the default position (length unit) and orientation (rad)
//   tolerances of inverse_kinematics (inverse_kinematics.hpp) on the body
//   error twist e = log(g(q)^-1 T). eps^(2/3): far enough above the error's
//   rounding floor (forward kinematics and log of an arm of metre scale
//   round to about n eps, 1e-15 to 1e-14 in double) that an iteration never
//   stalls on rounding before meeting it, and below the square root of that
//   floor, so that the Gauss-Newton step that brings e under the tolerance
//   has, by quadratic convergence, nearly reached the floor. 3.7e-11 in
//   double (about 1.7e5 eps), 2.4e-5 in float (about 200 eps).
//
// ik_max_iterations: the bound on its iterations (trial steps), 100.
//   Measured on the UR5 in double over 2000 random targets: from seeds
//   0.3 rad away the median is 6 and the 99th percentile 20 (one target in
//   2000 ends in a local minimum); from seeds uniform in [-2 pi, 2 pi] the
//   median is 23 and 46% do not converge within 100. The bound is a budget,
//   beyond which a restart from another seed pays better than more
//   iterations (with 10 restarts 992 of 1000 such targets converge;
//   bench/bench_ik.py measures the same on four real arms).
//
// ik_stall_iterations, ik_stall_ratio: an attempt of inverse_kinematics
//   that a restart follows ends with status no_progress when its cost
//   |e|^2 / 2 is above 0.9 of what it was 8 iterations before: stalled at a
//   local minimum, where the restart pays better. Chosen on TRAC-IK's
//   protocol (bench/ik_protocols.py: 10000 random targets within the
//   limits, seeds at the middle of the limits, double, restarts within
//   5 ms) on UR5, Panda and xArm7. Without it a failing attempt waits for
//   its step to fall below rounding (the UR5's, a median of 38 iterations,
//   mostly on a plateau of the cost); with it, the iterations per solve
//   fall by a third to a half (UR5 30.6 to 20.4 on average, Panda 36.6 to
//   18.5, xArm7 21.1 to 13.1; from random seeds, PickNik's protocol, Panda
//   82 to 33) and the 90th percentile of the time by as much, every target
//   still solved to 1e-10. Windows of 6 to 12 and ratios of 0.5 to 0.9
//   measured within 10% of each other; a ratio of 0.99 or a window of 4 cut
//   2-6% of the attempts that would have converged. Some slow attempts are
//   cut too, which is why the last attempt, or the only one, is not: a
//   Jaco2 target from a seed 0.3 rad away crawls from |e|^2 / 2 = 7.3e-10
//   to 6.7e-10 over 8 iterations, then converges.
//
// spline_series_theta2: below this theta^2 (s) the coefficients of the
//   right Jacobian and their first and second derivatives in s (spline.hpp,
//   detail::jacobian_coefficients) use their Taylor series, kept to s^12:
//   the first omitted term of the worst of them (b'' = d^2/ds^2 of
//   (theta - sin theta)/theta^3) is 156 s^11 / 29! <= 7e-23 at s = 4,
//   relative 2e-19, below the double and float eps (the series' coefficients
//   are stored as doubles, so long double gets double accuracy there). Above
//   it the closed forms' cancellation (b'' has the worst: numerator terms of
//   size ~40 for a value ~0.17 at theta = 2) costs at most ~250 ulps, and
//   less as theta grows; a cutoff at the usual eps^(1/3) would cost up to
//   1e13 ulps there (the closed form of b'' loses eps / theta^6).
//   tests/cpp/test_spline.cpp checks both sides against long double. The
//   series has no 0/0, so autodiff derivatives are exact at 0.
//
// spline_step_tolerance: the spline fit's fixed point (spline.hpp) stops
//   after a step with |dw_j| <= tol (W + |w_j|) for every rate component,
//   W the largest chord rate component |D_i|_inf / h_i (the scale of the
//   rates, so that the test does not depend on the unit of time: with 1 in
//   place of W, steps of 1e100 stopped after one iteration, their rates
//   ~1e-100 far below the tolerance; scipy's RotationSpline tests
//   |dw| <= 1e-9 (1 + |w|)). eps^(3/4): the
//   iteration converges linearly, so the error left after such a step is
//   that step times q / (1 - q), q the contraction factor; a tolerance near
//   eps could be missed forever by the rounding of the block solve (a few
//   eps times the condition number of the block-tridiagonal matrix).
//
// spline_max_iterations: the bound on those iterations, 30 (scipy stops
//   silently after 10). Measured in double over 300 random key sets (steps
//   exp(z), z ~ N(0, sigma^2 I), 0.3 to 1 s apart): sigma < 0.2 (steps
//   under ~0.6 rad) at most 7 iterations; sigma 0.2 to 0.5 at most 14;
//   sigma 0.5 to 0.8 at most 23, and one natural-end fit with steps of
//   2.7 rad at 7 rad/s did not converge in 30 (reported not_converged;
//   the Python classes raise). Keys on one screw motion take 1 or 2.
//
// spline_min_step, spline_max_step: the key time steps h = t_{i+1} - t_i a
//   spline fit accepts (fit_spline reports step_out_of_range otherwise). The
//   cubics' coefficients are per unit of time: c1 ~ D/h, c2 ~ D/h^2,
//   c3 ~ D/h^3 for a step D = log(X_i^-1 X_{i+1}), the fit's equations hold
//   6 D/h^2 and the body acceleration is ~ D/h^2. With h in [1e-100, 1e100]
//   (double) h^3 and 1/h^3 lie within [1e-300, 1e300], the normal range with
//   a margin of 1e8 for |D| (a step of 1e8 in translation, or 1e-8 before c3
//   becomes subnormal at the largest h); at h = 1e-160 c3 ~ 1e480 overflows
//   and the accelerations ~ 1e320 with it, at h = 1e200 h^2 overflows in the
//   fit and c2, c3 underflow to zero. float: [1e-6, 1e6] (its range is
//   1e-38 to 3e38: h^3 and D/h^2 stay within 1e18 of 1 and the products of
//   the rates in spline_body_rates, of order |r|^2 |r'|, stay finite with
//   spline_max_extrapolation below). long double: as double.
//
// spline_max_extrapolation: outside [t_0, t_{N-1}] the first / last
//   segment's cubic continues up to this many segment lengths h from the
//   end key (t_0 - K h_0 and t_{N-1} + K h_{N-2}); farther, the spline holds
//   the element, velocity and acceleration it has there (Spline::offset).
//   The cubic grows as tau^3: unbounded, r(tau) overflowed at t = 1e110 and
//   the results were NaN. At K = 1e6 (double) |r| ~ K^3 |D| = 1e18 |D|, the
//   rotation angle's ulp is already ~100 rad (the element carries no more
//   information farther out), and the products of spline_body_rates (of
//   order |r|^2 |r'| ~ K^8 |D|^3 / h for the smallest step) stay below
//   1e200. float: 100 (|r| ~ 1e6 |D|, products below 1e30).
//
// screw_tolerance: Chain::validate() (kinematics.hpp) accepts a revolute
//   or helical joint's angular part w with | |w| - 1 | <= tol, a revolute
//   joint's pitch with |w . v| <= tol |w| (|w| + |v|) (zero pitch; the same
//   test makes Chain's constructor infer a helical joint where it fails), a
//   prismatic joint's linear part v with | |v| - 1 | <= tol and |w| <= tol
//   (with ScrewNorms::any, no norm is asked and |w| <= tol |v|: the tests are
//   relative to the screw's norm). sqrt(eps), as rotation_tolerance: an axis written with
//   half the digits of the type passes (0.70710678 twice has | |w| - 1 | ~ 1e-9);
//   a screw table in Modern Robotics' (w, v) order does not, read as (v, w):
//   its "angular part" is then v = -w x q, of norm the distance of the axis
//   from the origin (0.089 to 0.8 m for a UR5), far from 1 at any tolerance
//   a unit vector could need.
// inertia_tolerance: SpatialInertia::is_physical accepts a rotational
//   inertia whose asymmetry is at most this times its largest entry, and
//   principal moments that break the triangle inequality I_1 + I_2 >= I_3
//   by at most this times the trace. sqrt(eps), as rotation_tolerance: a
//   thin plate (I_3 = I_1 + I_2 exactly) written with half the digits of the
//   type passes; anything further off is not a body. tests/cpp/
//   test_spatial_inertia.cpp checks both sides.
//
// mass_matrix_pivot_tolerance: forward_dynamics (dynamics.hpp)
//   reports M(q) not positive definite at the first Cholesky pivot
//   d_k <= tol s_k, s_k = |v_k|^2 tr(G_f) + |w_k|^2 tr(G_t) the scale of the
//   terms M_kk is summed from (M_kk <= 2 s_k; s_k in joint k's own units, so
//   d_k / s_k does not depend on the units of length and mass). 4 eps, from
//   d_k / s_k measured in float and double over random q:
//   - exactly singular M, where the computed pivot is rounding (every link
//     a point mass on its joint's axis; a massless link between two coaxial
//     joints; random arms of 2 to 8 and of 16 to 32 joints, 10000 each):
//     |d_k| / s_k <= 2.8 eps for 2 to 8 joints, <= 3.5 eps up to 32;
//   - physical arms: random arms of 1 to 32 joints with links of uniform
//     boxes (as tests/cpp/test_dynamics.cpp's, 22000): >= 2.6e-6 (22 float
//     eps); the chains from the root to each leaf link of the
//     example-robot-data robots (507, 500 q each within the limits):
//     >= 8.4e-7 (8 float eps: TIAGo's arm, M_77 = 4e-6 kg m^2 against 18 at
//     its torso), but for chains singular themselves: a massless link
//     (romeo's gripper, 0) and three joints about one point with massless
//     links between (iCub's neck and feet, human.urdf's shoulders and
//     hips), which come near gimbal lock at some q: down to 7e-15 (31 eps)
//     in double, where they pass, and rounding in float, where they fail.
//   So 4 eps is above the rounding of a zero pivot and below every physical
//   arm in float (the narrow case: 3.5 and 8 eps); a pivot that passes is
//   known to better than its own size. In double the gap is 1e9 wide.
//
// align_tolerance: so3_align, se3_align and sim3_align (align.hpp) report
//   the rotation not determined (AlignStatus::not_determined) when
//   s2 + s3 <= tol s1, s1 >= s2 >= |s3| the signed singular values of the
//   (centred) cross-covariance B = sum_i w_i a_i b_i^T (s3 < 0 where the
//   best orthogonal fit is a reflection); with a primary vector, when the
//   amplitude |(S, C)| of the fit about it is <= tol sum_i w_i |a_i| |b_i|.
//   The rotation maximizes tr(R^T B), and a change dB of B turns it by
//   about |dB| / (s2 + s3) rad (the smallest of the sums s_j + s_k, the
//   curvature of tr(R^T B) about the worst axis, which is 0 exactly where
//   the maximizer is not unique: parallel vectors, collinear points). B
//   is summed from the rounded data, |dB| about eps s1, so at the tolerance the
//   rounding alone can turn the rotation by eps / tol = sqrt(eps) rad: it is
//   known to fewer than half the digits of the type, the rule of
//   rotation_tolerance. (scipy warns only below 1e-16 s1, about where
//   s2 + s3 is rounding itself, in double.) Points off a line by d have
//   s2 of order d^2 (the covariance is quadratic in the data), so the
//   rotation about the line is reported not determined for d below about
//   eps^(1/4) of the line's length: tests/cpp/test_align.cpp puts points
//   20 times either side of that, in float and in double.
//
// covariance_pivot_tolerance: the Cholesky factor of a covariance
//   (gaussian.hpp, detail::psd_cholesky) takes a pivot d_k <= tol m, m the
//   largest diagonal entry, as a direction of zero variance (its column of
//   the factor is zero) and a pivot below -tol m as a matrix that is not
//   positive semidefinite. d_k = S_kk - sum_j L_kj^2 is a sum of at most 8
//   rounded terms of size <= m (every L_kj^2 <= S_kk): its rounding is at
//   most about 9 eps m, which 16 eps covers, so that the exactly singular
//   covariance of a coordinate held fixed (or a rank-deficient one rounded)
//   is never refused nor given a pivot of rounding noise.
//
/// The thresholds that apply to a Scalar (autodiff scalars use their real type's).
template <typename Scalar>
using ThresholdsOf = Thresholds<RealOf<Scalar>>;

}  // namespace chasles
