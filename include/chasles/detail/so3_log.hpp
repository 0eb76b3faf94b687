// chasles: the logarithm of SO(3), through Horn's quaternion (the numerics
// behind SO3::log, SO3::angle's sibling, and SE3::log).
#pragma once

#include <cmath>
#include <cstddef>
#include <type_traits>

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/detail/approx.hpp"
#include "chasles/detail/nearest_rotation.hpp"
#include "chasles/detail/series.hpp"

namespace chasles {
namespace detail {

/// What the so(3) log knows besides w, for the se(3) log to reuse.
template <typename Scalar>
struct So3Log {
  Eigen::Matrix<Scalar, 3, 1> omega;  ///< the rotation vector, angle in [0, pi]
  Scalar theta2;                      ///< |omega|^2
  Scalar half_theta_cot;              ///< (theta/2) cot(theta/2); only set when !near_identity
  bool near_identity;                 ///< the Taylor branch was taken
};

/// The log of a 3x3 matrix that is, or is near, a rotation, through its
/// quaternion: robust over the whole of SO(3), and as accurate for a matrix
/// off SO(3) as projecting it onto SO(3) first.
///
/// The quaternion of the rotation nearest to M is the dominant eigenvector
/// of Horn's symmetric 4x4 K = N(M) + I (detail/nearest_rotation.hpp). For
/// a rotation K = 4 q q^T, rank one, so any column of it is a multiple of q;
/// the column of K's largest diagonal entry (4 q_k^2 >= 1: the diagonal
/// sums to 4) is Shepperd's choice and has no small entry to divide by. For
/// M off SO(3) by d, that column is off q's direction by O(d) in a way that
/// the nearest rotation is not; one power step, u = K (K e_k), takes it to
/// the dominant eigenvector to O(d^2), since K's other eigenvalues are O(d)
/// against 4. So log(M) errs by what log(projected M) errs, to first order.
/// No normalization is needed: with u = (u_w, u_v), u_w >= 0 (the sign of
/// u fixed so that theta is in [0, pi]),
///   w = 2 atan2(|u_v|, u_w) u_v / |u_v|  = (2 / u_w) (atan(x) / x) u_v,
///   x = |u_v| / u_w = tan(theta / 2);
/// for float and double atan comes from a rational fit (detail/series.hpp,
/// AtanRational; the code says how), for long double from libm. A small
/// angle that reaches this far (a matrix far from SO(3) with tr M <= 1:
/// rotations near the identity take the skew path below) takes the second
/// form with the series of atan(x)/x below the cutoff (x^2 below the
/// cutoff / 4, as theta^2 / 4 is): no sqrt of 0, no 0/0. At exactly pi,
/// u_w = 0 and either sign of u is the same rotation.
/// Finite for every finite M: K (K e_k) and its squares below only
/// overflow for entries of M far outside [-1, 1] (u grows as |M|^2, its
/// squares as |M|^4: u itself may be finite while they are not); u is then
/// recomputed from M clamped to [-2, 2]. A finite u with |u|^2 past
/// log_quaternion_norm2 (entries past about 3) is normalized, so that the
/// rational atan's homogeneous forms cannot overflow.
///
/// Near the identity no quaternion is needed. The skew part of a rotation
/// is sin(theta) [n], so s = vee((M - M^T) / 2) = sin(theta) n and
///   w = (asin(|s|) / |s|) s,  asin(x) / x = 1 + x^2/6 + 3 x^4/40 + ...,
/// exact to rounding for |s|^2 = sin^2(theta) below taylor_theta2 (the first
/// omitted term, 5/112 x^6, is under eps there). tr M > 1 (theta < pi/2)
/// tells it from theta near pi, where sin(theta) is small too. Off SO(3),
/// M = R (I + S) with S symmetric of size d (the polar form) has skew part
/// sin(theta) [n] + O(theta d): the skew part alone differs from projecting
/// first by at most theta d, under 0.0025 d in double (0.07 d in float)
/// at the cutoff, and only the skew part of a perturbation moves it, as it
/// moves the projection. Six loads, no power step, no division.
template <typename Scalar>
inline So3Log<Scalar> so3_log(const Eigen::Matrix<Scalar, 3, 3>& M) noexcept {
  using std::sqrt;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  So3Log<Scalar> out;
  {
    // The skew part vee((M - M^T) / 2) = sin(theta) n, formed as SO3::vee forms it.
    const Scalar half(0.5);
    const Vector3 s(half * M(2, 1) - half * M(1, 2), half * M(0, 2) - half * M(2, 0), half * M(1, 0) - half * M(0, 1));
    const Scalar s2 = s.squaredNorm();
    if (s2 < ThresholdsOf<Scalar>::taylor_theta2 && M(0, 0) + M(1, 1) + M(2, 2) > Scalar(1)) {
      const Scalar f = asin_over_x_series(s2);
      out.omega = f * s;
      out.theta2 = f * f * s2;
      out.near_identity = true;
      return out;
    }
  }
  const HornMatrix<Scalar> K(M);
  Quaternion4<Scalar> u = quaternion_power_step(K);
  Scalar uv2 = u.x * u.x + u.y * u.y + u.z * u.z;
  Scalar uw2 = u.w * u.w;
  const Scalar u2 = uv2 + uw2;
  if (!(u2 <= Scalar(ThresholdsOf<Scalar>::log_quaternion_norm2))) {
    // Cold: not near a rotation. Overflowed, u is recomputed from M clamped
    // to [-2, 2]; merely large (constants.hpp), it is normalized.
    if (is_finite(u2)) {
      const Scalar inv = Scalar(1) / sqrt(u2);
      u = {inv * u.w, inv * u.x, inv * u.y, inv * u.z};
    } else {
      u = clamped_quaternion_power_step(M);
    }
    uv2 = u.x * u.x + u.y * u.y + u.z * u.z;
    uw2 = u.w * u.w;
  }
  // u and -u are the same rotation: the one with u_w >= 0 has theta in [0, pi].
  const Scalar sign = u.w < Scalar(0) ? Scalar(-1) : Scalar(1);
  const Vector3 uv(sign * u.x, sign * u.y, sign * u.z);
  const Scalar uw = sign * u.w;
  if (uv2 < Scalar(ThresholdsOf<Scalar>::taylor_theta2 / 4) * uw2) {
    // x^2 = tan^2(theta/2) < cutoff / 4: 4 x^2 is theta^2 to within the
    // series' accuracy. Reached only by matrices far from SO(3) (a small
    // rotation angle with tr M <= 1), where u_v may be 0.
    const Scalar inv_w = Scalar(1) / uw;
    const Scalar x2 = uv2 * inv_w * inv_w;
    const Scalar f = Scalar(2) * inv_w * atan_over_x_series(x2);
    out.omega = f * uv;
    out.theta2 = f * f * uv2;
    out.near_identity = true;
    return out;
  }
  out.near_identity = false;
  if constexpr (AtanRational<RealOf<Scalar>>::available) {
    // theta/2 = atan2(n, u_w), n = |u_v|, from the rational atan of
    // detail/series.hpp: with a <= b the smaller and the larger of n and
    // u_w, atan(a/b) = (a/b) g, g = 1 - z h(z), z = a^2/b^2, h = P/Q, and
    //   g = (B Q~ - A P~) / (B Q~) = G / (B Q~),   A = a^2, B = b^2,
    // P~ and Q~ the homogeneous forms (no z formed: A and B are u_v2 and
    // u_w2). Then f = theta / n, the factor of u_v:
    //   theta < pi/2 (n < u_w): f = 2 g / u_w = 2 G / (u_w B Q~), one divide;
    //   past it: theta = pi - 2 (u_w/n) g = pi - 2 u_w G / (n B Q~), and
    //   f = theta / n: the angle first, then one divide by n, as the libm
    //   form does (dividing pi and the rest by n apart doubles their
    //   rounding just past pi/2, where pi/n is twice f).
    // Selects, not branches: which side an input is on depends on the data.
    using R = AtanRational<RealOf<Scalar>>;
    constexpr std::size_t np = std::extent<decltype(R::p)>::value;
    const bool acute = uv2 < uw2;
    const Scalar A = acute ? uv2 : uw2, B = acute ? uw2 : uv2;
    Scalar p, q;
    if constexpr (std::is_floating_point<Scalar>::value) {
      using Pair = Eigen::Array<Scalar, 2, 1>;  // P and Q side by side
      const Pair pq = homogeneous_estrin<Pair, np>(A, B, [](std::size_t i) { return Pair(R::p[i], R::q[i]); });
      p = pq[0], q = pq[1];
    } else {
      p = homogeneous_estrin<Scalar, np>(A, B, [](std::size_t i) { return Scalar(R::p[i]); });
      q = homogeneous_estrin<Scalar, np>(A, B, [](std::size_t i) { return Scalar(R::q[i]); });
    }
    const Scalar bq = B * q;
    const Scalar g2 = Scalar(2) * (bq - A * p);  // 2 G
    const Scalar n = sqrt(uv2);
    const Scalar ratio = (acute ? g2 : uw * g2) / ((acute ? uw : n) * bq);
    const Scalar f = acute ? ratio : (Scalar(3.14159265358979323846) - ratio) / n;
    out.omega = f * uv;
    out.theta2 = f * f * uv2;
    out.half_theta_cot = Scalar(0.5) * f * uw;  // (theta/2) u_w / n = (theta/2) cot(theta/2)
  } else {
    const Scalar n = sqrt(uv2);
    // theta/2 = atan2(n, u_w) in [0, pi/2], as atan of the smaller over the
    // larger (a ratio in [0, 1]) and pi/2 minus it past pi/4: selects, not a
    // branch, and one libm atan costs less than half of an atan2.
    const bool acute = n < uw;  // theta < pi/2
    const Scalar small = acute ? n : uw, large = acute ? uw : n;
    const Scalar a = arctan<Scalar>(small / large);
    const Scalar half_theta = acute ? a : Scalar(0.5 * 3.14159265358979323846) - a;
    const Scalar f = Scalar(2) * half_theta / n;
    out.omega = f * uv;
    out.theta2 = Scalar(4) * half_theta * half_theta;
    out.half_theta_cot = half_theta * uw / n;  // (theta/2) cos(theta/2) / sin(theta/2)
  }
  return out;
}

}  // namespace detail
}  // namespace chasles
