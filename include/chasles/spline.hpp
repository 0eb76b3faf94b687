// chasles: interpolating C2 splines through the key elements of any group
// (key rotations of SO3 and SO2, key poses of SE3 and SE2, similarities,
// extended poses, ...).
//
// Key times t_0 < ... < t_{N-1}, key elements X_i (N >= 2). On segment i,
// t in [t_i, t_{i+1}], with tau = t - t_i and h_i = t_{i+1} - t_i:
//
//   X(t) = X_i exp(r(tau)),   r(tau) = c1 tau + c2 tau^2 + c3 tau^3,
//
// a cubic in the local coordinates r = log(X_i^-1 X(t)), with r(0) = 0 and
// r(h_i) = D_i = log(X_i^-1 X_{i+1}), so X passes through every key. The body
// velocity V = (X^-1 X')^vee (w for SO3, the twist (v, w) for SE3, in the
// order of the group's tangent) and the body
// acceleration V' are
//
//   V = Jr(r) r',     V' = Jr(r) r'' + (d/dt Jr(r)) r',
//
// Jr the right Jacobian of the group (jacobians.hpp). The rates at the keys,
// w_i = V(t_i) = r'(0) (Jr(0) = I), are the unknowns; on segment i the end
// rate is r'(h_i) = Jr(D_i)^-1 w_{i+1}. Continuity of V' at each interior key
// k (left limit of segment k-1 = right limit of segment k), using Jr(D) D = D:
//
//   2/h_{k-1} Jr(D_{k-1}) w_{k-1} + 4 (1/h_{k-1} + 1/h_k) w_k + 2/h_k Jr(D_k)^-1 w_{k+1}
//     = 6 (D_{k-1}/h_{k-1}^2 + D_k/h_k^2) - n(D_{k-1}, Jr(D_{k-1})^-1 w_k),
//
// n(r, r') = (d/dt Jr(r)) r' the term quadratic in the rate. Ends:
// - natural (the default): V'(t_0) = 0 and V'(t_{N-1}) = 0, i.e.
//   4/h_0 w_0 + 2/h_0 Jr(D_0)^-1 w_1 = 6 D_0/h_0^2 and
//   2/h Jr(D) w_{N-2} + 4/h w_{N-1} = 6 D/h^2 - n(D, Jr(D)^-1 w_{N-1}) on the last segment;
// - chord: w_0 = D_0/h_0 and w_{N-1} = D_{N-2}/h_{N-2}, the end rates scipy's
//   RotationSpline uses (its interior equations are the ones above).
// This is the construction of scipy.spatial.transform.RotationSpline
// (Kolesnikov, "Smooth attitude interpolation", 2019, eqs. for the angular
// rate and acceleration), written for any group. The system is
// block-tridiagonal in the w_i with a right-hand side that depends on w
// through n only: the blocks are factored once (block Thomas algorithm) and
// the fixed point w <- solve(g - n(w)) is iterated from w_i = chord rates
// until a step |dw| <= spline_step_tolerance (W + |w|) componentwise (W the
// largest chord rate |D_i|_inf / h_i: the test does not depend on the unit of
// time, so steps of 1e-100 and 1e100 converge as steps of 1 do), at most
// spline_max_iterations times (constants.hpp). Two keys give the geodesic at
// constant velocity; keys on one screw motion exp(t xi) give exactly that
// motion (V = xi, V' = 0), whatever the times (as long as each step's angle
// is below pi, so that log recovers h_i xi).
//
// Storage: the caller owns every array (N times, N keys, N - 1 segments and a
// scratch array of N SplineWork entries for the fit). The spline is a view
// (Spline<Group>) over them. Why not a fixed-capacity class: the number of keys
// is a run-time quantity (a log of poses, a path from a planner), a capacity
// template parameter would either cap it or make every spline pay for the
// largest; caller storage lets real-time code fit into buffers reserved once
// (std::vector::reserve, static arrays) and the Python binding into its own
// vectors, and nothing here allocates. Fitting costs O(N) per iteration
// (D x D blocks, D the group's DoF), evaluation O(log N) (binary search) plus one exp.
//
// The group enters through exp, log, inverse, * and its right Jacobian and
// its inverse, and the term n(r, r') = (d/dt Jr(r)) r' of the acceleration:
// in closed form for SO(3) and SE(3) (Kolesnikov's coefficients, below), and
// for every other group from its right Jacobian by forward differentiation:
// Jr evaluated at the dual number r + e r' (e^2 = 0; Eigen's AutoDiffScalar
// with one derivative, no allocation) gives Jr(r) + e (d/dt Jr(r)), so that
// Jr(r + e r') (r' + e r'') = V + e V', exactly (no difference quotient), at
// about twice the cost of Jr. A new group has its splines with no line of
// its own.
// The evaluation's parts are free functions too (spline_segment_index,
// spline_offset, spline_segment_element, spline_segment_sample), for storage
// that is not three arrays of these types (the Python binding reads numpy's).
//
// Time steps: fit_spline takes steps h_i in [spline_min_step,
// spline_max_step] (constants.hpp: [1e-100, 1e100] in double), where the
// coefficients per unit of time (c3 ~ D/h^3) and the accelerations
// (~ D/h^2) are within the floating-point range; others are reported
// (step_out_of_range). Extrapolation: outside [t_0, t_{N-1}] the first /
// last segment's cubic continues, up to spline_max_extrapolation (1e6 in
// double) segment lengths from the end key; farther, the spline holds what
// it has there (the cubic grows as tau^3 and would overflow: NaN).
//
// Every function is noexcept and allocation-free; Scalar may be float, double
// or an Eigen::AutoDiffScalar (derivatives through the fit and the evaluation).
#pragma once

#include <algorithm>
#include <limits>
#include <type_traits>

#include <Eigen/Core>

#include <unsupported/Eigen/AutoDiff>
#include "chasles/constants.hpp"
#include "chasles/detail/approx.hpp"
#include "chasles/detail/assert.hpp"
#include "chasles/detail/small_solve.hpp"

#include "chasles/jacobians.hpp"
#include "chasles/lie_group.hpp"
#include "chasles/se2.hpp"
#include "chasles/se23.hpp"
#include "chasles/se3.hpp"
#include "chasles/sim3.hpp"
#include "chasles/so2.hpp"
#include "chasles/so3.hpp"

namespace chasles {

/// The end conditions of an interpolating spline (see spline.hpp).
enum class SplineEnds {
  natural,  ///< body acceleration zero at the first and the last key
  chord,    ///< body velocity at the first / last key = the rate of the first / last segment's geodesic (scipy)
};

/// How a fit ended.
enum class SplineStatus {
  ok,                    ///< fitted; the iteration converged
  too_few_keys,          ///< N < 2
  times_not_increasing,  ///< some t_{i+1} - t_i is not > 0 and finite (or a time is NaN)
  step_out_of_range,     ///< some t_{i+1} - t_i is outside [spline_min_step, spline_max_step] (constants.hpp)
  not_converged,  ///< the fixed point did not converge in spline_max_iterations (coefficients are the last iterate)
};

/// Result of fit_spline.
struct SplineFit {
  SplineStatus status;
  int iterations;  ///< fixed-point iterations taken (0 when there is nothing to iterate)
};

/// One segment's cubic: r(tau) = c1 tau + c2 tau^2 + c3 tau^3.
template <typename Group>
struct SplineSegment {
  using Tangent = Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>;
  Tangent c1, c2, c3;
};

/// Scratch for one key during the fit (the caller gives N of them).
template <typename Group>
struct SplineWork {
  using Scalar = typename Group::Scalar;
  using Tangent = Eigen::Matrix<Scalar, Group::DoF, 1>;
  using Matrix = Eigen::Matrix<Scalar, Group::DoF, Group::DoF>;
  Tangent delta;  ///< D_i = log(X_i^-1 X_{i+1}) (unused for the last key)
  Tangent rate;  ///< w_i, the body velocity at key i
  Tangent rhs;  ///< g_i, the part of the right-hand side that does not depend on w
  Tangent tmp;  ///< forward-sweep values
  Matrix jr_inv;  ///< Jr(D_i)^-1
  Matrix lower;  ///< the block left of the diagonal in row i
  Matrix diag_inv;  ///< inverse of the eliminated diagonal block
  Matrix upper;  ///< the eliminated block right of the diagonal, diag_inv * C_i
};

/// Pose (or rotation), body velocity and body acceleration at one time.
template <typename Group>
struct SplineSample {
  using Tangent = Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>;
  Group element;
  Tangent velocity;  ///< (X^-1 X')^vee: w (SO3), the twist (v, w) (SE3), in the group's tangent
  Tangent acceleration;  ///< d/dt of velocity
};

namespace detail {

/// The coefficients of Jl(phi) = I + a [phi] + b [phi]^2 and Jr(phi) = I - a [phi] + b [phi]^2
/// of SO(3) as functions of s = theta^2, with their first and second derivatives in s:
///   a = (1 - cos theta) / s,  b = (theta - sin theta) / (s theta),
///   a1 = (theta sin theta - 2 (1 - cos theta)) / (2 s^2),
///   b1 = (3 sin theta - 2 theta - theta cos theta) / (2 s^2 theta),
///   a2 = (s cos theta - 5 theta sin theta + 8 (1 - cos theta)) / (4 s^3),
///   b2 = (s sin theta + 7 theta cos theta + 8 theta - 15 sin theta) / (4 s^3 theta).
/// Below s = spline_series_theta2 the Taylor series a = sum_k (-1)^k s^k / (2k+2)!,
/// b = sum_k (-1)^k s^k / (2k+3)! and their term-by-term derivatives, to k = 12.
template <typename Scalar>
struct JacobianCoefficients {
  Scalar a, b, a1, b1, a2, b2;
};

/// The Taylor coefficients (-1)^k / (2k+2)! of a and (-1)^k / (2k+3)! of b, k = 0..12.
constexpr double kSplineSeriesA[13] = {0.5,
                                       -0.041666666666666664,
                                       0.001388888888888889,
                                       -2.48015873015873e-05,
                                       2.755731922398589e-07,
                                       -2.08767569878681e-09,
                                       1.1470745597729725e-11,
                                       -4.779477332387385e-14,
                                       1.5619206968586225e-16,
                                       -4.110317623312165e-19,
                                       8.896791392450574e-22,
                                       -1.6117375710961184e-24,
                                       2.4795962632247976e-27};
constexpr double kSplineSeriesB[13] = {0.16666666666666666,     -0.008333333333333333,   0.0001984126984126984,
                                       -2.7557319223985893e-06, 2.505210838544172e-08,   -1.6059043836821613e-10,
                                       7.647163731819816e-13,   -2.8114572543455206e-15, 8.22063524662433e-18,
                                       -1.9572941063391263e-20, 3.868170170630684e-23,   -6.446950284384474e-26,
                                       9.183689863795546e-29};

template <typename Scalar>
inline JacobianCoefficients<Scalar> jacobian_coefficients(const Scalar& s) noexcept {
  using std::cos;
  using std::sin;
  using std::sqrt;
  JacobianCoefficients<Scalar> k;
  if (s < Scalar(ThresholdsOf<Scalar>::spline_series_theta2)) {
    constexpr int K = 12;
    k.a = k.b = k.a1 = k.b1 = k.a2 = k.b2 = Scalar(0);
    for (int i = K; i >= 0; --i) {
      const double ai = kSplineSeriesA[i];
      const double bi = kSplineSeriesB[i];
      k.a = k.a * s + Scalar(ai);
      k.b = k.b * s + Scalar(bi);
      if (i >= 1) {
        k.a1 = k.a1 * s + Scalar(i * ai);
        k.b1 = k.b1 * s + Scalar(i * bi);
      }
      if (i >= 2) {
        k.a2 = k.a2 * s + Scalar(i * (i - 1) * ai);
        k.b2 = k.b2 * s + Scalar(i * (i - 1) * bi);
      }
    }
    return k;
  }
  const Scalar theta = sqrt(s);
  const Scalar sn = sin(theta);
  const Scalar c = cos(theta);
  const Scalar omc = Scalar(1) - c;
  const Scalar s2 = s * s;
  const Scalar s3 = s2 * s;
  k.a = omc / s;
  k.b = (theta - sn) / (s * theta);
  k.a1 = (theta * sn - Scalar(2) * omc) / (Scalar(2) * s2);
  k.b1 = (Scalar(3) * sn - Scalar(2) * theta - theta * c) / (Scalar(2) * s2 * theta);
  k.a2 = (s * c - Scalar(5) * theta * sn + Scalar(8) * omc) / (Scalar(4) * s3);
  k.b2 = (s * sn + Scalar(7) * theta * c + Scalar(8) * theta - Scalar(15) * sn) / (Scalar(4) * s3 * theta);
  return k;
}

/// Body velocity and acceleration of E(t) = exp(r(t)) on SO(3) from r, r', r'' (phi = r):
///   w = Jr(phi) phi' = phi' - a phi x phi' + b phi x (phi x phi'),
///   w' = Jr(phi) phi'' + (d/dt Jr) phi',
///   (d/dt Jr) phi' = -a1 s' phi x phi' + b1 s' phi x (phi x phi') + b phi' x (phi x phi'),  s' = 2 phi . phi'
/// (Kolesnikov 2019; scipy's _angular_acceleration_nonlinear_term with k1 = -2 a1, k2 = 2 b1, k3 = b).
template <typename Scalar>
inline void spline_rates(const SO3<Scalar>* /*tag*/, const Eigen::Matrix<Scalar, 3, 1>& phi,
                         const Eigen::Matrix<Scalar, 3, 1>& d1, const Eigen::Matrix<Scalar, 3, 1>& d2,
                         Eigen::Matrix<Scalar, 3, 1>& velocity, Eigen::Matrix<Scalar, 3, 1>& acceleration) noexcept {
  using V3 = Eigen::Matrix<Scalar, 3, 1>;
  const JacobianCoefficients<Scalar> k = jacobian_coefficients<Scalar>(phi.squaredNorm());
  const Scalar s1 = Scalar(2) * phi.dot(d1);
  const V3 cp = phi.cross(d1);
  const V3 ccp = phi.cross(cp);
  velocity = d1 - k.a * cp + k.b * ccp;
  const V3 c2 = phi.cross(d2);
  acceleration = d2 - k.a * c2 + k.b * phi.cross(c2) - k.a1 * s1 * cp + k.b1 * s1 * ccp + k.b * d1.cross(cp);
}

/// Body twist (v, w) and its derivative of E(t) = exp(r(t)) on SE(3), r = (rho, phi),
/// E = (R, p) with R = exp(phi), p = Jl(phi) rho:
///   w, w' as on SO(3);  v = R^T p',  v' = R^T p'' - w x v,
///   p' = Jl' rho + Jl rho',  p'' = Jl'' rho + 2 Jl' rho' + Jl rho'',
///   Jl' x = a' phi x x + a phi' x x + b' phi x (phi x x) + b (phi' x (phi x x) + phi x (phi' x x)),
///   Jl'' x = a'' phi x x + 2 a' phi' x x + a phi'' x x + b'' phi x (phi x x)
///          + 2 b' (phi' x (phi x x) + phi x (phi' x x))
///          + b (phi'' x (phi x x) + 2 phi' x (phi' x x) + phi x (phi'' x x)),
///   a' = a1 s', a'' = a2 s'^2 + a1 s'', s' = 2 phi . phi', s'' = 2 (phi' . phi' + phi . phi'')
/// (Barfoot 2017, eq. 7.86 for p = Jl rho; the derivatives by the chain rule in s = theta^2).
template <typename Scalar>
inline void spline_rates(const SE3<Scalar>* /*tag*/, const Eigen::Matrix<Scalar, 6, 1>& r,
                         const Eigen::Matrix<Scalar, 6, 1>& d1, const Eigen::Matrix<Scalar, 6, 1>& d2,
                         Eigen::Matrix<Scalar, 6, 1>& velocity, Eigen::Matrix<Scalar, 6, 1>& acceleration) noexcept {
  using V3 = Eigen::Matrix<Scalar, 3, 1>;
  const V3 rho = r.template head<3>(), phi = r.template tail<3>();
  const V3 rho1 = d1.template head<3>(), phi1 = d1.template tail<3>();
  const V3 rho2 = d2.template head<3>(), phi2 = d2.template tail<3>();
  const JacobianCoefficients<Scalar> k = jacobian_coefficients<Scalar>(phi.squaredNorm());
  const Scalar s1 = Scalar(2) * phi.dot(phi1);
  const Scalar s2 = Scalar(2) * (phi1.squaredNorm() + phi.dot(phi2));
  const Scalar ad1 = k.a1 * s1, bd1 = k.b1 * s1;
  const Scalar ad2 = k.a2 * s1 * s1 + k.a1 * s2, bd2 = k.b2 * s1 * s1 + k.b1 * s2;
  // Jl x, Jl' x, Jl'' x.
  const auto jl = [&](const V3& x) -> V3 { return x + k.a * phi.cross(x) + k.b * phi.cross(phi.cross(x)); };
  const auto jl1 = [&](const V3& x) -> V3 {
    return ad1 * phi.cross(x) + k.a * phi1.cross(x) + bd1 * phi.cross(phi.cross(x)) +
           k.b * (phi1.cross(phi.cross(x)) + phi.cross(phi1.cross(x)));
  };
  const V3 px = phi.cross(rho), p1x = phi1.cross(rho), p2x = phi2.cross(rho);
  const V3 jl2rho = ad2 * px + Scalar(2) * ad1 * p1x + k.a * p2x + bd2 * phi.cross(px) +
                    Scalar(2) * bd1 * (phi1.cross(px) + phi.cross(p1x)) +
                    k.b * (phi2.cross(px) + Scalar(2) * phi1.cross(p1x) + phi.cross(p2x));
  const V3 p1 = jl1(rho) + jl(rho1);
  const V3 p2 = jl2rho + Scalar(2) * jl1(rho1) + jl(rho2);
  V3 w, w1;
  spline_rates(static_cast<const SO3<Scalar>*>(nullptr), phi, phi1, phi2, w, w1);
  const Eigen::Matrix<Scalar, 3, 3> Rt = SO3<Scalar>::exp(phi).matrix().transpose();
  const V3 v = Rt * p1;
  velocity = detail::stack<Scalar>(v, w);
  acceleration = detail::stack<Scalar>(V3(Rt * p2 - w.cross(v)), w1);
}

/// Body velocity and acceleration of E(t) = exp(r(t)) on any group from r, r', r'':
///   V = Jr(r) r',  V' = Jr(r) r'' + (d/dt Jr(r)) r',
/// both at once from Jr at the dual number r + e r' applied to r' + e r''
/// (see the file comment), for any group (SO3 and SE3 use their closed forms above).
template <typename Group>
inline void spline_rates_dual(const Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>& r,
                              const Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>& d1,
                              const Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>& d2,
                              Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>& velocity,
                              Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>& acceleration) noexcept {
  using Scalar = typename Group::Scalar;
  using Dual = Eigen::AutoDiffScalar<Eigen::Matrix<Scalar, 1, 1>>;
  using DualGroup = typename WithScalar<Group, Dual>::type;
  using DualTangent = Eigen::Matrix<Dual, Group::DoF, 1>;
  using Derivative = Eigen::Matrix<Scalar, 1, 1>;
  DualTangent x, rate;
  for (int k = 0; k < Group::DoF; ++k) {
    x[k] = Dual(r[k], Derivative(d1[k]));
    rate[k] = Dual(d1[k], Derivative(d2[k]));
  }
  const DualTangent v = DualGroup::right_jacobian(x) * rate;
  for (int k = 0; k < Group::DoF; ++k) {
    velocity[k] = v[k].value();
    acceleration[k] = v[k].derivatives()[0];
  }
}
template <typename Group>
inline void spline_rates(const Group* /*tag*/, const Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>& r,
                         const Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>& d1,
                         const Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>& d2,
                         Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>& velocity,
                         Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>& acceleration) noexcept {
  spline_rates_dual<Group>(r, d1, d2, velocity, acceleration);
}

/// Jr(d) and Jr(d)^-1 of the group.
template <typename Group>
inline typename Group::AdjointMatrix spline_jr(const Group* /*tag*/, const typename Group::Tangent& d) noexcept {
  return Group::right_jacobian(d);
}
template <typename Group>
inline typename Group::AdjointMatrix spline_jr_inv(const Group* /*tag*/, const typename Group::Tangent& d) noexcept {
  return Group::right_jacobian_inverse(d);
}

}  // namespace detail

/// Body velocity and acceleration of exp(r(t)) from r, r', r'' (see spline.hpp):
/// V = Jr(r) r', V' = Jr(r) r'' + (d/dt Jr(r)) r'.
template <typename Group>
inline void spline_body_rates(const Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>& r,
                              const Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>& r1,
                              const Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>& r2,
                              Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>& velocity,
                              Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>& acceleration) noexcept {
  detail::spline_rates(static_cast<const Group*>(nullptr), r, r1, r2, velocity, acceleration);
}

/// Fits the interpolating C2 spline through (times[i], keys[i]), i < n: writes the n - 1
/// segments' cubics into `segments`, using `work` (n entries) as scratch. Nothing is
/// allocated; the cost is O(n) per iteration, at most spline_max_iterations iterations.
/// On too_few_keys / times_not_increasing / step_out_of_range nothing is written to
/// `segments` (times_not_increasing is reported before step_out_of_range, whatever the order of the steps).
template <typename Group>
inline SplineFit fit_spline(int n, const typename Group::Scalar* times, const Group* keys,
                            SplineSegment<Group>* segments, SplineWork<Group>* work,
                            SplineEnds ends = SplineEnds::natural) noexcept {
  using Scalar = typename Group::Scalar;
  using Tangent = Eigen::Matrix<Scalar, Group::DoF, 1>;
  using Matrix = Eigen::Matrix<Scalar, Group::DoF, Group::DoF>;
  constexpr const Group* tag = nullptr;
  if (n < 2) return {SplineStatus::too_few_keys, 0};
  for (int i = 0; i + 1 < n; ++i) {
    const Scalar h = times[i + 1] - times[i];
    // !(h > 0) also catches NaN (and inf - inf); !(h < inf) catches an infinite time.
    if (!(h > Scalar(0)) || !(h < Scalar(std::numeric_limits<RealOf<Scalar>>::infinity())))
      return {SplineStatus::times_not_increasing, 0};
  }
  for (int i = 0; i + 1 < n; ++i) {
    // c3 ~ D/h^3 and the accelerations ~ D/h^2 must be representable (constants.hpp).
    const Scalar h = times[i + 1] - times[i];
    if (h < Scalar(ThresholdsOf<Scalar>::spline_min_step) || h > Scalar(ThresholdsOf<Scalar>::spline_max_step))
      return {SplineStatus::step_out_of_range, 0};
  }
  const Matrix I = Matrix::Identity();
  const bool natural = ends == SplineEnds::natural;
  Scalar rate_scale(0);  // W, the largest chord rate component: the scale of the rates
  for (int i = 0; i + 1 < n; ++i) {
    const Scalar h = times[i + 1] - times[i];
    work[i].delta = (keys[i].inverse() * keys[i + 1]).log();
    work[i].jr_inv = detail::spline_jr_inv(tag, work[i].delta);
    work[i].rate = work[i].delta / h;  // the chord rates start the iteration
    for (int j = 0; j < Group::DoF; ++j) {
      using std::abs;
      if (abs(work[i].rate[j]) > rate_scale) rate_scale = abs(work[i].rate[j]);
    }
  }
  work[n - 1].delta.setZero();
  work[n - 1].jr_inv = I;
  work[n - 1].rate = work[n - 2].delta / (times[n - 1] - times[n - 2]);
  // Rows: lower_i w_{i-1} + B_i w_i + C_i w_{i+1} = rhs_i - n_i(w).
  for (int i = 0; i < n; ++i) {
    SplineWork<Group>& wk = work[i];
    Matrix B, C = Matrix::Zero();
    wk.lower.setZero();
    const bool first = i == 0, last = i == n - 1;
    if ((first || last) && !natural) {
      B = I;
      wk.rhs = first ? Tangent(work[0].delta / (times[1] - times[0]))
                     : Tangent(work[n - 2].delta / (times[n - 1] - times[n - 2]));
    } else {
      B.setZero();
      wk.rhs.setZero();
      if (!first) {
        const Scalar h = times[i] - times[i - 1];
        wk.lower = (Scalar(2) / h) * detail::spline_jr(tag, work[i - 1].delta);
        B += (Scalar(4) / h) * I;
        wk.rhs += (Scalar(6) / (h * h)) * work[i - 1].delta;
      }
      if (!last) {
        const Scalar h = times[i + 1] - times[i];
        C = (Scalar(2) / h) * wk.jr_inv;
        B += (Scalar(4) / h) * I;
        wk.rhs += (Scalar(6) / (h * h)) * wk.delta;
      }
    }
    // Block Thomas elimination: B'_i = B_i - lower_i U_{i-1}, U_i = B'_i^-1 C_i.
    if (!first) B -= wk.lower * work[i - 1].upper;
    wk.diag_inv = detail::inverse_partial_pivot(B);
    wk.upper = wk.diag_inv * C;
  }
  // n_i(w) = (d/dt Jr) r' at the end of segment i-1, r' = Jr(D_{i-1})^-1 w_i.
  const auto nonlinear = [&](int i) -> Tangent {
    Tangent vel, acc;
    if (i == 0 || (i == n - 1 && !natural)) return Tangent::Zero();
    const Tangent m1 = work[i - 1].jr_inv * work[i].rate;
    detail::spline_rates(tag, work[i - 1].delta, m1, Tangent(Tangent::Zero()), vel, acc);
    return acc;
  };
  const Scalar tol = Scalar(ThresholdsOf<Scalar>::spline_step_tolerance);
  const int max_iterations = ThresholdsOf<Scalar>::spline_max_iterations;
  int iterations = 0;
  bool converged = false;
  while (iterations < max_iterations && !converged) {
    ++iterations;
    for (int i = 0; i < n; ++i) {
      Tangent b = work[i].rhs - nonlinear(i);
      if (i > 0) b -= work[i].lower * work[i - 1].tmp;
      work[i].tmp = work[i].diag_inv * b;
    }
    converged = true;
    for (int i = n - 1; i >= 0; --i) {
      Tangent w = work[i].tmp;
      if (i < n - 1) w -= work[i].upper * work[i + 1].rate;
      for (int j = 0; j < Group::DoF; ++j) {
        using std::abs;
        if (!(abs(w[j] - work[i].rate[j]) <= tol * (rate_scale + abs(w[j])))) converged = false;
      }
      work[i].rate = w;
    }
  }
  // Hermite cubic with r(0) = 0, r'(0) = m0, r(h) = D, r'(h) = m1.
  for (int i = 0; i + 1 < n; ++i) {
    const Scalar h = times[i + 1] - times[i];
    const Tangent& D = work[i].delta;
    const Tangent m0 = work[i].rate;
    const Tangent m1 = work[i].jr_inv * work[i + 1].rate;
    segments[i].c1 = m0;
    segments[i].c2 = (Scalar(3) * D - Scalar(2) * h * m0 - h * m1) / (h * h);
    segments[i].c3 = (Scalar(-2) * D + h * m0 + h * m1) / (h * h * h);
  }
  return {converged ? SplineStatus::ok : SplineStatus::not_converged, iterations};
}

/// The segment of time t among n >= 2 increasing key times: the largest i <= n - 2 with
/// times[i] <= t (0 before times[0]; n - 2 for a NaN t). `times` is anything indexed by
/// times[i] (a pointer, an Eigen vector or map). A binary search: O(log n) reads.
template <typename Times, typename Scalar>
inline int spline_segment_index(int n, const Times& times, const Scalar& t) noexcept {
  // std::upper_bound over times[1 .. n-2]: the first j with t < times[j], minus one. Over a
  // pointer, std::upper_bound itself: its branches let the processor load ahead, where the loop
  // below, compiled without them, waits on each load (2x slower at 10^6 keys, out of cache).
  if constexpr (std::is_pointer<Times>::value) {
    return static_cast<int>(std::upper_bound(times + 1, times + n - 1, t) - times) - 1;
  }
  int first = 1, count = n - 2;
  while (count > 0) {
    const int half = count / 2;
    if (!(t < times[first + half])) {
      first += half + 1;
      count -= half + 1;
    } else {
      count = half;
    }
  }
  return first - 1;
}

/// The offset tau = t - t_i of time t on the segment [t_i, t_{i+1}] (h = t_{i+1} - t_i), held
/// to [-K h, (1 + K) h], K = spline_max_extrapolation: past the ends of a spline the cubic
/// continues K segment lengths (the offset from the end key is at most K h; it grows as tau^3
/// and would overflow: NaN), then the spline holds. Within the segment it is t - t_i. NaN
/// stays NaN. The subtraction t - t_i may overflow to +-inf (t = 1e308, t_i = -1e308): held.
template <typename Scalar>
inline Scalar spline_offset(const Scalar& t, const Scalar& t_i, const Scalar& t_next) noexcept {
  Scalar tau = t - t_i;
  const Scalar h = t_next - t_i;
  const Scalar K(ThresholdsOf<Scalar>::spline_max_extrapolation);
  if (tau < -K * h) tau = -K * h;
  if (tau > (K + Scalar(1)) * h) tau = (K + Scalar(1)) * h;
  return tau;
}

/// The element key exp(r(tau)) of a segment with cubic c and start key `key`, at offset tau.
template <typename Group>
inline Group spline_segment_element(const Group& key, const SplineSegment<Group>& c,
                                    const typename Group::Scalar& tau) noexcept {
  using Tangent = Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>;
  return key * Group::exp(Tangent(((c.c3 * tau + c.c2) * tau + c.c1) * tau));
}

/// Element, body velocity and body acceleration of a segment with cubic c and start key
/// `key`, at offset tau: key exp(r), V = Jr(r) r', V' = Jr(r) r'' + (d/dt Jr(r)) r'.
template <typename Group>
inline SplineSample<Group> spline_segment_sample(const Group& key, const SplineSegment<Group>& c,
                                                 const typename Group::Scalar& tau) noexcept {
  using Scalar = typename Group::Scalar;
  using Tangent = Eigen::Matrix<Scalar, Group::DoF, 1>;
  const Tangent r = ((c.c3 * tau + c.c2) * tau + c.c1) * tau;
  const Tangent r1 = (Scalar(3) * tau * c.c3 + Scalar(2) * c.c2) * tau + c.c1;
  const Tangent r2 = Scalar(6) * tau * c.c3 + Scalar(2) * c.c2;
  SplineSample<Group> out{key * Group::exp(r), Tangent(), Tangent()};
  spline_body_rates<Group>(r, r1, r2, out.velocity, out.acceleration);
  return out;
}

/// A fitted spline: a view over the caller's n times, n keys and n - 1 segments
/// (filled by fit_spline). Evaluation is noexcept, allocation-free and O(log n).
/// Outside [t_0, t_{n-1}] the first / last segment's cubic continues (as scipy's
/// RotationSpline, whose PPoly extrapolates) up to spline_max_extrapolation segment
/// lengths from the end key, and holds farther (spline_offset).
/// Precondition (the caller's, asserted with eigen_assert): n >= 2 and the three
/// pointers non-null (a fit with fewer than two keys reports too_few_keys).
template <typename Group>
class Spline {
 public:
  using Scalar = typename Group::Scalar;
  using Tangent = Eigen::Matrix<Scalar, Group::DoF, 1>;

  Spline(int n, const Scalar* times, const Group* keys, const SplineSegment<Group>* segments) noexcept
      : n_(n), times_(times), keys_(keys), segments_(segments) {
    CHASLES_ASSERT(n >= 2 && times != nullptr && keys != nullptr && segments != nullptr);
  }

  int size() const noexcept { return n_; }

  /// The segment holding t: the largest i <= n - 2 with t_i <= t (0 before t_0); a NaN time gives NaN results.
  int segment(const Scalar& t) const noexcept { return spline_segment_index(n_, times_, t); }

  /// The offset of t on segment i, t - t_i, held past the ends (spline_offset).
  Scalar offset(int i, const Scalar& t) const noexcept { return spline_offset(t, times_[i], times_[i + 1]); }

  /// Element, body velocity and body acceleration of segment i at tau = t - t_i
  /// (for one-sided limits at a key: segment k - 1 at tau = h_{k-1}, segment k at 0).
  SplineSample<Group> sample(int i, const Scalar& tau) const noexcept {
    return spline_segment_sample(keys_[i], segments_[i], tau);
  }

  /// The element alone at time t (no rates): X_i exp(r(t - t_i)).
  Group element(const Scalar& t) const noexcept {
    const int i = segment(t);
    return spline_segment_element(keys_[i], segments_[i], offset(i, t));
  }

  /// Element, body velocity and body acceleration at time t.
  SplineSample<Group> operator()(const Scalar& t) const noexcept {
    const int i = segment(t);
    return sample(i, offset(i, t));
  }

 private:
  int n_;
  const Scalar* times_;
  const Group* keys_;
  const SplineSegment<Group>* segments_;
};

template <typename Scalar>
using SO3Spline = Spline<SO3<Scalar>>;
template <typename Scalar>
using SE3Spline = Spline<SE3<Scalar>>;
template <typename Scalar>
using SO2Spline = Spline<SO2<Scalar>>;
template <typename Scalar>
using SE2Spline = Spline<SE2<Scalar>>;
template <typename Scalar>
using Sim3Spline = Spline<Sim3<Scalar>>;
template <typename Scalar>
using SE23Spline = Spline<SE23<Scalar>>;

}  // namespace chasles
