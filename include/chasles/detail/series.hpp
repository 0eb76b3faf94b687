// chasles: the coefficient functions of exp and log, each written once.
//
// With theta = |w| and t = theta^2, the exponentials of so(3) and se(3) are
//   exp([w])   = I + A [w] + B [w]^2                               (Rodrigues)
//   V(w)       = I + B [w] + C [w]^2,   exp([xi]) = [exp([w]), V v; 0, 1]
// and the inverse of V, used by the se(3) log, is
//   V(w)^-1    = I - 1/2 [w] + D [w]^2
// with
//   A = sin(theta) / theta              = 1 - t/6 + t^2/120 - ...
//   B = (1 - cos(theta)) / theta^2      = 1/2 - t/24 + t^2/720 - ...
//   C = (theta - sin(theta)) / theta^3  = 1/6 - t/120 + t^2/5040 - ...
//   D = (1 - (theta/2) cot(theta/2)) / theta^2 = 1/12 + t/720 + t^2/30240 + ...
// (Murray, Li and Sastry, A Mathematical Introduction to Robotic Manipulation,
// 1994, eqs. 2.14 and 2.36; Sola, Deray and Atchuthan, A micro Lie theory for
// state estimation in robotics, 2018, eqs. 143 and 174.)
//
// Below Thresholds::taylor_theta2 the series are used: they form no 0/0, so
// values and autodiff derivatives are exact at theta = 0. Above it the closed
// forms are used, written without cancellation where the coefficient is
// multiplied by something of order 1 (B via the half angle). C and D do
// cancel near 0, but each only ever multiplies [w]^2, of size t, so the
// absolute error it adds is a few eps: the results stay exact to a few ulps.
#pragma once

#include <cmath>
#include <type_traits>

#include <Eigen/Core>

#include "chasles/constants.hpp"

namespace chasles {
namespace detail {

/// A, B and C of the exponential at t = theta^2.
template <typename Scalar>
struct ExpCoefficients {
  Scalar a;  ///< sin(theta) / theta
  Scalar b;  ///< (1 - cos(theta)) / theta^2
  Scalar c;  ///< (theta - sin(theta)) / theta^3
};

/// A, B, C from theta^2 alone: one sincos of theta/2 above the cutoff.
/// The compiler drops `c` where a caller does not read it.
template <typename Scalar>
inline ExpCoefficients<Scalar> exp_coefficients(const Scalar& theta2) noexcept {
  using std::cos;
  using std::sin;
  using std::sqrt;
  ExpCoefficients<Scalar> k;
  if (theta2 < ThresholdsOf<Scalar>::taylor_theta2) {
    const Scalar& t = theta2;
    k.a = Scalar(1) - t * (Scalar(1) / Scalar(6) - t * (Scalar(1) / Scalar(120)));
    k.b = Scalar(0.5) - t * (Scalar(1) / Scalar(24) - t * (Scalar(1) / Scalar(720)));
    k.c = Scalar(1) / Scalar(6) - t * (Scalar(1) / Scalar(120) - t * (Scalar(1) / Scalar(5040)));
  } else {
    const Scalar theta = sqrt(theta2);
    const Scalar sh = sin(Scalar(0.5) * theta);
    const Scalar ch = cos(Scalar(0.5) * theta);
    // sin(theta) = 2 sin(theta/2) cos(theta/2); 1 - cos(theta) = 2 sin^2(theta/2):
    // no cancellation at small theta.
    const Scalar inv = Scalar(1) / theta;  // one divide for all three
    k.a = Scalar(2) * sh * ch * inv;
    k.b = Scalar(2) * sh * sh * inv * inv;
    k.c = (Scalar(1) - k.a) * inv * inv;
  }
  return k;
}

/// atan(x): std::atan for the real types; atan2(x, 1) for scalar types
/// whose library has atan2 but no atan (Eigen's AutoDiffScalar).
template <typename Scalar>
inline Scalar arctan(const Scalar& x) noexcept {
  if constexpr (std::is_floating_point<Scalar>::value) {
    return std::atan(x);
  } else {
    using std::atan2;
    return atan2(x, Scalar(1));
  }
}

/// atan(x) / x as a series in x2 = x^2, for the so(3) log near the
/// identity (x = tan(theta/2)): 1 - x^2/3 + x^4/5 - x^6/7 + ...
template <typename Scalar>
inline Scalar atan_over_x_series(const Scalar& x2) noexcept {
  return Scalar(1) - x2 * (Scalar(1) / Scalar(3) - x2 * (Scalar(1) / Scalar(5)));
}

/// E and D of V^-1 = E I - 1/2 [w] + D w w^T, the inverse of V used by the
/// se(3) log (expanding [w]^2 = w w^T - theta^2 I in I - 1/2 [w] + D [w]^2):
///   E = 1 - D theta^2 = (theta/2) cot(theta/2) = 1 - t/12 - t^2/720 - ...
///   D = (1 - E) / theta^2                       = 1/12 + t/720 + t^2/30240 + ...
/// E in closed form comes from the so(3) log (`half_theta_cot`, from the
/// quaternion: no subtraction, 0 at pi). D cancels near the cutoff but
/// multiplies w w^T (of size t). `near_identity` is the so(3) log's choice
/// of branch.
template <typename Scalar>
struct VInverseCoefficients {
  Scalar e;
  Scalar d;
};

template <typename Scalar>
inline VInverseCoefficients<Scalar> v_inverse_coefficients(const Scalar& theta2, const Scalar& half_theta_cot,
                                                           bool near_identity) noexcept {
  VInverseCoefficients<Scalar> k;
  if (near_identity) {
    const Scalar& t = theta2;
    k.d = Scalar(1) / Scalar(12) + t * (Scalar(1) / Scalar(720) + t * (Scalar(1) / Scalar(30240)));
    k.e = Scalar(1) - t * k.d;
  } else {
    k.e = half_theta_cot;
    k.d = (Scalar(1) - k.e) / theta2;
  }
  return k;
}

/// D = (1 - (theta/2) cot(theta/2)) / theta^2 from theta^2 alone, for the
/// inverses of the SO(3) Jacobians (I -/+ 1/2 [w] + D [w]^2):
///   series below Thresholds::taylor_theta2:  1/12 + t/720 + t^2/30240;
///   above it, E = (theta/2) cos(theta/2) / sin(theta/2) from the half angle,
///   then (1 - E) / theta^2. Finite up to and beyond pi (sin(theta/2) >= 1/sqrt(2)
///   on [0, 3pi/2]); it diverges only at theta = 2 pi, where the inverse
///   Jacobian does not exist. 1 - E cancels near the cutoff, but D only ever
///   multiplies [w]^2 (of size t), so the absolute error it adds is a few eps.
///   No 0/0 on either branch: autodiff derivatives are exact at 0.
template <typename Scalar>
inline Scalar jacobian_inverse_coefficient(const Scalar& theta2) noexcept {
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (theta2 < ThresholdsOf<Scalar>::taylor_theta2) {
    const Scalar& t = theta2;
    return Scalar(1) / Scalar(12) + t * (Scalar(1) / Scalar(720) + t * (Scalar(1) / Scalar(30240)));
  }
  const Scalar half = Scalar(0.5) * sqrt(theta2);
  const Scalar e = half * cos(half) / sin(half);
  return (Scalar(1) - e) / theta2;
}

/// The two coefficients of Q(v, w) (the upper-right block of the SE(3) left
/// Jacobian) beyond A, B, C: with t = theta^2,
///   q3 = (theta^2 + 2 cos(theta) - 2) / (2 theta^4)          = (1/2 - B) / t
///      = 1/24 - t/720 + t^2/40320 - ...
///   q4 = (2 theta - 3 sin(theta) + theta cos(theta)) / (2 theta^5) = (3 C - B) / (2 t)
///      = 1/120 - t/2520 + t^2/120960 - ...
/// (Barfoot, State Estimation for Robotics, 2017, eq. 7.86; Sola et al. 2018,
/// eq. 180). Below the cutoff the series; above it the forms in B and C,
/// which cancel near the cutoff: q3 multiplies terms of size t |v| and q4
/// terms of size t^2 |v|, so the absolute error they add is a few eps |v|.
template <typename Scalar>
struct QCoefficients {
  Scalar b;   ///< (1 - cos(theta)) / theta^2
  Scalar c;   ///< (theta - sin(theta)) / theta^3
  Scalar q3;  ///< (1/2 - B) / theta^2
  Scalar q4;  ///< (3 C - B) / (2 theta^2)
};

template <typename Scalar>
inline QCoefficients<Scalar> q_coefficients(const Scalar& theta2) noexcept {
  const ExpCoefficients<Scalar> k = exp_coefficients(theta2);
  QCoefficients<Scalar> q;
  q.b = k.b;
  q.c = k.c;
  if (theta2 < ThresholdsOf<Scalar>::taylor_theta2) {
    const Scalar& t = theta2;
    q.q3 = Scalar(1) / Scalar(24) - t * (Scalar(1) / Scalar(720) - t * (Scalar(1) / Scalar(40320)));
    q.q4 = Scalar(1) / Scalar(120) - t * (Scalar(1) / Scalar(2520) - t * (Scalar(1) / Scalar(120960)));
  } else {
    const Scalar inv = Scalar(1) / theta2;
    q.q3 = (Scalar(0.5) - k.b) * inv;
    q.q4 = Scalar(0.5) * (Scalar(3) * k.c - k.b) * inv;
  }
  return q;
}

/// A rotation vector w too long for |w|^2 to be formed (|w|^2 at or above
/// Thresholds::huge_theta2, or overflowing): its unit axis and the
/// coefficients of exp in unit-axis form,
///   exp([w]) = I + sin(theta) [n] + (1 - cos(theta)) [n]^2,
///   V(w) v   = A v + (B theta) (n x v) + (1 - A) (n . v) n,
/// from theta/2, which is finite for every finite w. The cold path of exp.
template <typename Scalar>
struct LongRotation {
  Eigen::Matrix<Scalar, 3, 1> axis;  ///< n = w / |w|
  Scalar sin_theta;                  ///< sin(theta)
  Scalar one_minus_cos;              ///< 1 - cos(theta)
  Scalar a;                          ///< sin(theta) / theta
  Scalar b_theta;                    ///< (1 - cos(theta)) / theta
};

template <typename Scalar>
inline LongRotation<Scalar> long_rotation(const Eigen::Matrix<Scalar, 3, 1>& w) noexcept {
  using std::abs;
  using std::cos;
  using std::sin;
  using std::sqrt;
  Scalar m = abs(w[0]);
  if (abs(w[1]) > m) m = abs(w[1]);
  if (abs(w[2]) > m) m = abs(w[2]);
  const Eigen::Matrix<Scalar, 3, 1> u = w / m;  // max |u_i| = 1
  const Scalar nu = sqrt(u.squaredNorm());      // in [1, sqrt(3)]
  const Scalar half = (Scalar(0.5) * m) * nu;   // theta / 2, finite
  const Scalar sh = sin(half);
  const Scalar ch = cos(half);
  LongRotation<Scalar> r;
  r.axis = u / nu;
  r.sin_theta = Scalar(2) * sh * ch;
  r.one_minus_cos = Scalar(2) * sh * sh;
  r.a = sh * ch / half;
  r.b_theta = sh * sh / half;
  return r;
}

}  // namespace detail
}  // namespace chasles
