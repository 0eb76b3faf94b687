// chasles: Sim(3), the group of similarity transforms of R^3.
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/detail/approx.hpp"
#include "chasles/detail/rodrigues.hpp"
#include "chasles/detail/series.hpp"
#include "chasles/detail/so3_log.hpp"
#include "chasles/lie_group.hpp"
#include "chasles/so3.hpp"

namespace chasles {

namespace detail {

/// e^x - 1 without cancellation: std::expm1 for the real types, and
/// tanh(x/2) (e^x + 1) (the same number) for scalar types whose library has
/// no expm1 (Eigen's AutoDiffScalar).
template <typename Scalar>
inline Scalar expm1_of(const Scalar& x) noexcept {
  if constexpr (std::is_floating_point<Scalar>::value) {
    return std::expm1(x);
  } else {
    using std::exp;
    using std::tanh;
    return tanh(Scalar(0.5) * x) * (exp(x) + Scalar(1));
  }
}

/// The coefficients of W(w, sigma) = A I + B [w] + C [w]^2, the matrix that
/// takes v to the translation of exp in Sim(3):
///   W = integral_0^1 e^(sigma u) exp(u [w]) du,
///   A = phi(sigma),  B = Im phi(z) / theta,  C = (A - Re phi(z)) / theta^2,
///   phi(z) = (e^z - 1) / z,  z = sigma + i theta,  theta = |w|
/// (on the plane orthogonal to w, [w] acts as i theta, so W acts as phi(z)
/// there and as phi(sigma) on the axis).
template <typename Scalar>
struct Sim3Coefficients {
  Scalar a;  ///< phi(sigma) = (e^sigma - 1) / sigma
  Scalar b;  ///< Im phi(sigma + i theta) / theta
  Scalar c;  ///< (phi(sigma) - Re phi(sigma + i theta)) / theta^2
  Scalar e;  ///< e^sigma
};

/// The functions of sigma alone in A, B and C: phi(sigma), e^sigma,
/// sigma^2 phi'(sigma) and sigma^2 phi''(sigma) / 2 (see sim3_coefficients).
template <typename Scalar>
struct ScaleFunctions {
  Scalar a;   ///< phi(sigma) = (e^sigma - 1) / sigma
  Scalar e;   ///< e^sigma
  Scalar nb;  ///< sigma^2 phi'(sigma)    = sigma e^sigma - (e^sigma - 1)
  Scalar nc;  ///< sigma^2 phi''(sigma)/2 = phi(sigma) - e^sigma + sigma e^sigma / 2
};

/// ScaleFunctions from sigma and em1 = e^sigma - 1 (exp: expm1(sigma);
/// log: s - 1 of the stored scale s, exact for s in [1/2, 2] and to an ulp
/// beyond, so that log needs no exponential), or below sigma^2 =
/// taylor_theta2 their series to sigma^5 (no 0/0 at sigma = 0).
template <typename Scalar, typename Em1>
inline ScaleFunctions<Scalar> scale_functions(const Scalar& s, const Em1& em1_of_sigma) noexcept {
  const Scalar one(1);
  ScaleFunctions<Scalar> f;
  if (s * s < Scalar(ThresholdsOf<Scalar>::taylor_theta2)) {
    // phi(sigma) = sum_m sigma^m / (m + 1)!, and sigma^2 I_1, sigma^2 I_2 / 2 (I_k below).
    f.a = one + s * (one / Scalar(2) +
                     s * (one / Scalar(6) + s * (one / Scalar(24) + s * (one / Scalar(120) + s / Scalar(720)))));
    f.e = one + s * f.a;
    const Scalar s2 = s * s;
    f.nb = s2 * (one / Scalar(2) +
                 s * (one / Scalar(3) +
                      s * (one / Scalar(8) + s * (one / Scalar(30) + s * (one / Scalar(144) + s / Scalar(840))))));
    f.nc = s2 * (one / Scalar(6) +
                 s * (one / Scalar(8) +
                      s * (one / Scalar(20) + s * (one / Scalar(72) + s * (one / Scalar(336) + s / Scalar(1920))))));
    return f;
  }
  const Scalar em1 = em1_of_sigma();
  f.e = em1 + one;
  f.a = em1 / s;
  f.nb = s * f.e - em1;
  f.nc = f.a - f.e + Scalar(0.5) * s * f.e;
  return f;
}

/// A, B, C (and e^sigma) from sigma and t = theta^2, to a few ulps of what
/// reaches W v (B times theta, C times theta^2) over the whole plane, given
/// the functions of sigma (scale_functions) and of theta (the rotation's
/// exp_coefficients, which exp shares with the rotation and log reads
/// from the quaternion).
///
/// Method. Expanding Im and Re of (e^z - 1) conj(z) / |z|^2, with
/// a = sin(theta)/theta, b = (1 - cos(theta))/theta^2,
/// c = (theta - sin(theta))/theta^3 (series.hpp), the 1/theta and
/// 1/theta^2 cancel exactly and leave
///   B = [sigma^2 phi'(sigma)    + theta^2 e^sigma (b - sigma c)          ] / (sigma^2 + theta^2),
///   C = [sigma^2 phi''(sigma)/2 + e^sigma (theta^2 c - sigma (1/2 - b))] / (sigma^2 + theta^2),
/// weighted means of a function of sigma alone (the limit theta -> 0:
/// phi'(sigma) = integral u e^(sigma u) du, phi''/2) and of theta
/// (the limit sigma -> 0: SE(3)'s b and c), with the weights sigma^2 and
/// theta^2 (theta^2 (c - sigma (1/2 - b) / theta^2) written without the
/// division). So the two-variable singularity is reduced to one-variable
/// functions, each computed without 0/0:
///   sigma^2 phi'(sigma)    = sigma e^sigma - expm1(sigma),
///   sigma^2 phi''(sigma)/2 = phi(sigma) - e^sigma + sigma e^sigma / 2,
/// and the functions of theta from series.hpp (series below taylor_theta2).
/// Near 0 the closed forms cancel: the first has absolute error about
/// eps |sigma|, the second eps, and dividing by r^2 = sigma^2 + theta^2 makes
/// B's error eps / r and C's eps / r^2; but B only multiplies [w] (norm
/// theta <= r) and C [w]^2 (theta^2 <= r^2), so what reaches W v errs by
/// a few eps |v| (as series.hpp's C and D, which cancel likewise). Below
/// r^2 = taylor_theta2 the double series in sigma and theta^2 to total
/// degree 5 (constants.hpp), exact to rounding and free of any division:
/// values and autodiff derivatives exact at 0; below sigma^2 = taylor_theta2
/// the functions of sigma are their series (no 0/0 at sigma = 0 when
/// theta is not small).
/// The series, with I_k(sigma) = integral_0^1 u^k e^(sigma u) du
/// = sum_m sigma^m / (m! (k + m + 1)):
///   A = sum_m sigma^m / (m + 1)!,
///   B = sum_j (-theta^2)^j I_(2j+1)(sigma) / (2j+1)!,
///   C = sum_j (-theta^2)^j I_(2j+2)(sigma) / (2j+2)!.
template <typename Scalar>
inline Sim3Coefficients<Scalar> sim3_coefficients(const Scalar& sigma, const Scalar& theta2,
                                                  const ScaleFunctions<Scalar>& f,
                                                  const ExpCoefficients<Scalar>& q) noexcept {
  const Scalar& s = sigma;
  const Scalar& t = theta2;
  const Scalar one(1);
  Sim3Coefficients<Scalar> k;
  k.a = f.a;
  k.e = f.e;
  if (s * s + t < Scalar(ThresholdsOf<Scalar>::taylor_theta2)) {
    // B: j = 0, 1, 2 with m <= 5 - 2j.
    const Scalar b0 = one / Scalar(2) +
                      s * (one / Scalar(3) +
                           s * (one / Scalar(8) + s * (one / Scalar(30) + s * (one / Scalar(144) + s / Scalar(840)))));
    const Scalar b1 = one / Scalar(24) + s * (one / Scalar(30) + s * (one / Scalar(72) + s / Scalar(252)));
    const Scalar b2 = one / Scalar(720) + s / Scalar(840);
    k.b = b0 - t * (b1 - t * b2);
    // C: likewise.
    const Scalar c0 = one / Scalar(6) +
                      s * (one / Scalar(8) + s * (one / Scalar(20) +
                                                  s * (one / Scalar(72) + s * (one / Scalar(336) + s / Scalar(1920)))));
    const Scalar c1 = one / Scalar(120) + s * (one / Scalar(144) + s * (one / Scalar(336) + s / Scalar(1152)));
    const Scalar c2 = one / Scalar(5040) + s / Scalar(5760);
    k.c = c0 - t * (c1 - t * c2);
    return k;
  }
  const Scalar inv = one / (s * s + t);
  k.b = (f.nb + t * f.e * (q.b - s * q.c)) * inv;
  k.c = (f.nc + f.e * (t * q.c - s * (Scalar(0.5) - q.b))) * inv;
  return k;
}

/// The same from sigma and theta^2 alone (expm1 and the rotation's
/// coefficients computed here): for the Jacobians.
template <typename Scalar>
inline Sim3Coefficients<Scalar> sim3_coefficients(const Scalar& sigma, const Scalar& theta2) noexcept {
  return sim3_coefficients(sigma, theta2, scale_functions(sigma, [&]() -> Scalar { return expm1_of(sigma); }),
                           exp_coefficients(theta2));
}

/// a0 I + a1 [w] + a2 [w]^2, the diagonal as a0 - a2 (w_j^2 + w_k^2).
template <typename Scalar>
inline Eigen::Matrix<Scalar, 3, 3> so3_combination(const Eigen::Matrix<Scalar, 3, 1>& w, const Scalar& a0,
                                                   const Scalar& a1, const Scalar& a2) noexcept {
  const Scalar xx = w[0] * w[0], yy = w[1] * w[1], zz = w[2] * w[2];
  const Scalar cxy = a2 * w[0] * w[1], cxz = a2 * w[0] * w[2], cyz = a2 * w[1] * w[2];
  const Scalar bx = a1 * w[0], by = a1 * w[1], bz = a1 * w[2];
  Eigen::Matrix<Scalar, 3, 3> M;
  M << a0 - a2 * (yy + zz), cxy - bz, cxz + by,  //
      cxy + bz, a0 - a2 * (xx + zz), cyz - bx,   //
      cxz - by, cyz + bx, a0 - a2 * (xx + yy);
  return M;
}

/// The coefficients of W^-1 = alpha I + beta [w] + gamma [w]^2. W acts as
/// A on the axis and as phi(z) = D + i theta B (D = A - theta^2 C) on the
/// orthogonal plane, so W^-1 acts as 1/A and 1/phi(z) = (D - i theta B) / Delta,
/// Delta = |phi(z)|^2 = D^2 + theta^2 B^2 (positive for theta < 2 pi):
///   alpha = 1/A,  beta = -B / Delta,  gamma = (B^2 - C D) / (A Delta).
/// Their errors reach W^-1 t as those of B and C reach W v.
template <typename Scalar>
struct Sim3InverseCoefficients {
  Scalar alpha, beta, gamma;
};
template <typename Scalar>
inline Sim3InverseCoefficients<Scalar> sim3_inverse_coefficients(const Sim3Coefficients<Scalar>& k,
                                                                 const Scalar& theta2) noexcept {
  const Scalar d = k.a - theta2 * k.c;
  const Scalar delta = d * d + theta2 * k.b * k.b;
  const Scalar inv_a = Scalar(1) / k.a;
  return {inv_a, Scalar(-k.b / delta), Scalar((k.b * k.b - k.c * d) * inv_a / delta)};
}

}  // namespace detail

/// A similarity transform of R^3: an element of Sim(3), stored as a
/// rotation R (an SO3), a translation t and a scale s > 0.
///
/// Conventions. Its 4x4 matrix is g = [[s R, t], [0, 1]]; it acts on points
/// as p -> s R p + t, and composes as the matrices do:
///   (R1, t1, s1) (R2, t2, s2) = (R1 R2, s1 R1 t2 + t1, s1 s2),
///   (R, t, s)^-1 = (R^T, -(1/s) R^T t, 1/s).
/// The tangent space is xi = (v, w, sigma) in R^7 (Sophus' order: linear
/// part, rotation vector, log-scale), with
///   hat(xi) = [[ [w] + sigma I, v ], [0, 0]],
/// so that exp(hat(xi)) has rotation exp([w]), scale e^sigma and
/// translation W v (detail::sim3_coefficients). Every operation is noexcept,
/// allocation-free and of bounded cost.
template <typename Scalar_>
class Sim3 {
 public:
  using Scalar = Scalar_;
  using Real = RealOf<Scalar>;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  using Vector7 = Eigen::Matrix<Scalar, 7, 1>;
  using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;
  using Matrix4 = Eigen::Matrix<Scalar, 4, 4>;
  using Matrix7 = Eigen::Matrix<Scalar, 7, 7>;
  using Rotation = SO3<Scalar>;
  using Tangent = Vector7;        ///< xi = (v, w, sigma)
  using AdjointMatrix = Matrix7;  ///< Ad_g, and the Jacobians
  static constexpr int DoF = 7;

  /// The identity.
  Sim3() noexcept : R_(), t_(Vector3::Zero()), s_(1) {}
  /// From a rotation, a translation and a scale s > 0 (not checked):
  /// g = [[s R, t], [0, 1]].
  Sim3(const Rotation& R, const Vector3& t, const Scalar& s) noexcept : R_(R), t_(t), s_(s) {}
  static Sim3 identity() noexcept { return Sim3(); }

  // ---- Lie algebra ------------------------------------------------------

  /// hat(xi) = [[ [w] + sigma I, v ], [0, 0]] for xi = (v, w, sigma).
  static Matrix4 hat(const Tangent& xi) noexcept {
    Matrix4 X;
    const Scalar z(0), sg = xi[6];
    X << sg, -xi[5], xi[4], xi[0],  //
        xi[5], sg, -xi[3], xi[1],   //
        -xi[4], xi[3], sg, xi[2],   //
        z, z, z, z;
    return X;
  }
  /// v from the last column, w from the antisymmetric part of the top-left
  /// block, sigma the mean of its diagonal, as a + ((b - a) + (c - a)) / 3
  /// (exactly a when the three are equal: vee(hat(xi)) == xi); the bottom
  /// row is not read.
  static Tangent vee(const Matrix4& X) noexcept {
    using detail::half_difference;
    const Scalar a = X(0, 0);
    Tangent xi;
    xi << X(0, 3), X(1, 3), X(2, 3), half_difference(X(2, 1), X(1, 2)), half_difference(X(0, 2), X(2, 0)),
        half_difference(X(1, 0), X(0, 1)), a + ((X(1, 1) - a) + (X(2, 2) - a)) / Scalar(3);
    return xi;
  }
  /// ad_xi = [[ [w] + sigma I, [v], -v ], [0, [w], 0], [0, 0, 0]], so that
  /// ad_a b = [a, b] = vee(hat(a) hat(b) - hat(b) hat(a)).
  static Matrix7 ad(const Tangent& xi) noexcept {
    const Vector3 v = xi.template head<3>(), w = xi.template segment<3>(3);
    Matrix7 A = Matrix7::Zero();
    A.template topLeftCorner<3, 3>() = Rotation::hat(w) + xi[6] * Matrix3::Identity();
    A.template block<3, 3>(0, 3) = Rotation::hat(v);
    A.template block<3, 1>(0, 6) = -v;
    A.template block<3, 3>(3, 3) = Rotation::hat(w);
    return A;
  }

  // ---- exp and log ------------------------------------------------------

  /// exp(hat(xi)) for xi = (v, w, sigma): R = exp([w]), s = e^sigma, t = W v,
  ///   W = integral_0^1 e^(sigma u) exp(u [w]) du = A I + B [w] + C [w]^2,
  ///   A = (e^sigma - 1)/sigma, B = Im phi(z) / theta, C = (A - Re phi(z)) / theta^2,
  ///   phi(z) = (e^z - 1)/z, z = sigma + i theta, theta = |w|;
  /// detail::sim3_coefficients says how they are computed to a few ulps
  /// over the whole (sigma, theta) plane (no 0/0: autodiff derivatives
  /// exact at 0). W v = A v + B w x v + C w x (w x v). (Unlike SE3::exp,
  /// no cold path for |w|^2 past huge_theta2: there the translation is NaN.)
  static Sim3 exp(const Tangent& xi) noexcept {
    const Vector3 v = xi.template head<3>(), w = xi.template segment<3>(3);
    const Scalar& sigma = xi[6];
    const Scalar t = w.squaredNorm();
    // A, B and C of theta computed once, for the rotation (Rodrigues, as
    // SO3::exp below huge_theta2; past it SO3::exp's cold path) and for W.
    const auto q = detail::exp_coefficients(t);
    const auto k = detail::sim3_coefficients(
        sigma, t, detail::scale_functions(sigma, [&]() -> Scalar { return detail::expm1_of(sigma); }), q);
    const Rotation R = t < Scalar(ThresholdsOf<Scalar>::huge_theta2)
                           ? Rotation::from_matrix_unchecked(detail::rodrigues(w, q.a, q.b))
                           : Rotation::exp(w);
    const Vector3 wv = w.cross(v);
    return Sim3(R, Vector3(k.a * v + k.b * wv + k.c * w.cross(wv)), k.e);
  }

  /// The xi = (v, w, sigma) with exp(hat(xi)) = g, rotation angle in [0, pi]:
  /// w = log(R) (SO3's, through the quaternion), sigma = log(s) (s is
  /// stored), and v = W^-1 t with W^-1 = alpha I + beta [w] + gamma [w]^2 in
  /// closed form (detail::sim3_inverse_coefficients: the exact inverse, no
  /// linear solve).
  Tangent log() const noexcept {
    using std::log;
    const auto r = detail::so3_log(R_.matrix());
    const Scalar sigma = log(s_);
    // e^sigma - 1 as s - 1 (detail::scale_functions): no exponential.
    const auto k = detail::sim3_coefficients(sigma, r.theta2,
                                             detail::scale_functions(sigma, [&]() -> Scalar { return s_ - Scalar(1); }),
                                             detail::exp_coefficients(r.theta2));
    const auto ki = detail::sim3_inverse_coefficients<Scalar>(k, r.theta2);
    const Vector3& w = r.omega;
    const Vector3 wt = w.cross(t_);
    const Vector3 v = ki.alpha * t_ + ki.beta * wt + ki.gamma * w.cross(wt);
    // Entry by entry: Eigen's comma initializer of a float 7-vector from
    // 3-vectors trips GCC 12's -Warray-bounds (a false positive, as
    // detail/approx.hpp's stack notes).
    Tangent xi;
    for (int i = 0; i < 3; ++i) {
      xi[i] = v[i];
      xi[3 + i] = w[i];
    }
    xi[6] = sigma;
    return xi;
  }

  // ---- Jacobians of exp -------------------------------------------------
  //
  // J_l(xi) = phi(ad_xi) = sum_k ad_xi^k / (k+1)!, J_r(xi) = J_l(-xi) (Sola
  // section III). ad_xi is block upper triangular, so is J_l:
  //   J_l = [[W, Q, q], [0, J_l^SO3(w), 0], [0, 0, 1]],
  // W the matrix of exp, J_l^SO3 SO3's left Jacobian, both in closed form
  // here. Q and q (the coupling of v with w and sigma) have no closed form
  // in common use; they are taken from phi(ad_xi) computed by scaling and
  // squaring: X = ad_xi / 2^s with |X|_1 <= 1/2, the Taylor series of
  // exp(X) and phi(X) (constants.hpp: sim3_jacobian_norm and _degree), then
  // s doublings phi(2X) = (exp(X) + I) phi(X) / 2, exp(2X) = exp(X)^2 (the
  // 14x14 block [[ad, I], [0, 0]]'s exponential, in 7x7 pieces): fixed size,
  // allocation-free, s bounded by the exponent range. The product keeps the
  // block structure's zeros exact. The inverses by the block formula
  //   J_l^-1 = [[W^-1, -W^-1 Q J^-1, -W^-1 q], [0, J^-1, 0], [0, 0, 1]],
  // W^-1 in closed form (as log), J^-1 SO3's left Jacobian inverse.
  // Q and q are linear in v (ad_xi's v part enters its powers once), so
  // they are computed for v scaled by a power of 2 to |v|_max <= 1 and
  // scaled back exactly: |v| then adds no doublings. Accuracy, against the
  // top-right block of the 14x14 exponential summed in long double
  // (test_sim3: JacobianOfExpIsTheBlockExponential), 3000 random xi with
  // |w| <= 3, |sigma| <= 5, |v| from 0.01 to 100: within 9.4 eps of the
  // largest entry in double and float (without the scaling of v: 359 eps
  // at |v| ~ 100, |sigma| ~ 5, where 7 to 9 more doublings of entries
  // e^sigma |v| lost digits).

  /// Left Jacobian: exp(xi + dxi) = exp(J_l dxi + o(dxi)) exp(xi).
  static Matrix7 left_jacobian(const Tangent& xi) noexcept { return jacobian(xi); }
  /// Right Jacobian: exp(xi + dxi) = exp(xi) exp(J_r dxi + o(dxi)), J_r(xi) = J_l(-xi).
  static Matrix7 right_jacobian(const Tangent& xi) noexcept { return jacobian(Tangent(-xi)); }
  /// J_l(xi)^-1, by the block formula (finite for |w| < 2 pi).
  static Matrix7 left_jacobian_inverse(const Tangent& xi) noexcept { return jacobian_inverse(xi); }
  /// J_r(xi)^-1 = J_l(-xi)^-1.
  static Matrix7 right_jacobian_inverse(const Tangent& xi) noexcept { return jacobian_inverse(Tangent(-xi)); }

  // ---- group operations -------------------------------------------------

  /// g^-1 = (R^T, -(1/s) R^T t, 1/s).
  Sim3 inverse() const noexcept {
    const Scalar inv = Scalar(1) / s_;
    return Sim3(R_.inverse(), Vector3(-(inv * (R_.matrix().transpose() * t_))), inv);
  }
  /// (R1, t1, s1) (R2, t2, s2) = (R1 R2, s1 R1 t2 + t1, s1 s2).
  Sim3 operator*(const Sim3& o) const noexcept {
    return Sim3(R_ * o.R_, Vector3(s_ * (R_.matrix() * o.t_) + t_), s_ * o.s_);
  }
  Sim3& operator*=(const Sim3& o) noexcept { return *this = *this * o; }

  /// Action on a point: p -> s R p + t.
  Vector3 act(const Vector3& p) const noexcept { return s_ * (R_.matrix() * p) + t_; }
  Vector3 operator*(const Vector3& p) const noexcept { return act(p); }

  /// Ad_g = [[s R, [t] R, -t], [0, R, 0], [0, 0, 1]] (7x7), so that
  /// g exp(xi) g^-1 = exp(Ad_g xi).
  Matrix7 adjoint() const noexcept {
    const Matrix3& R = R_.matrix();
    Matrix7 A = Matrix7::Zero();
    A.template topLeftCorner<3, 3>() = s_ * R;
    for (int j = 0; j < 3; ++j) A.template block<3, 1>(0, 3 + j) = t_.cross(R.col(j));
    A.template block<3, 1>(0, 6) = -t_;
    A.template block<3, 3>(3, 3) = R;
    A(6, 6) = Scalar(1);
    return A;
  }

  // ---- access and conversions -------------------------------------------

  const Rotation& rotation() const noexcept { return R_; }
  const Vector3& translation() const noexcept { return t_; }
  const Scalar& scale() const noexcept { return s_; }

  /// g = [[s R, t], [0, 1]] (4x4).
  Matrix4 matrix() const noexcept {
    Matrix4 g;
    g.template topLeftCorner<3, 3>() = s_ * R_.matrix();
    g.template topRightCorner<3, 1>() = t_;
    g.template bottomRows<1>() << Scalar(0), Scalar(0), Scalar(0), Scalar(1);
    return g;
  }

  /// The scale of a 4x4 matrix [[s R, t], ...]: s = |s R|_F / sqrt(3), the
  /// root mean square of the block's column norms. Chosen over cbrt(det):
  /// a sum of nine squares, no cancellation (relative error about eps/2,
  /// where det's six signed triple products cancel), never negative, and
  /// no cbrt (which autodiff scalars lack). Both agree to first order for
  /// a block off s R by a small symmetric factor. Measured in double on
  /// 200000 blocks s R (R from random unit quaternions, s log-uniform in
  /// [0.01, 100]) against the s used, the rotation's own rounding included:
  /// this one errs by 0.51 eps on average and 3.3 at worst, cbrt(det) by
  /// 0.66 and 4.3.
  static Scalar matrix_scale(const Matrix4& M) noexcept {
    using std::sqrt;
    return sqrt(M.template topLeftCorner<3, 3>().squaredNorm() / Scalar(3));
  }

  /// How far a 4x4 matrix is from a similarity: the rotation defect of its
  /// top-left block divided by its scale (SO3::rotation_defect), or the
  /// deviation of its bottom row from (0, 0, 0, 1), whichever is larger;
  /// +inf when an entry is not finite or the scale is not positive.
  static Scalar transform_defect(const Matrix4& M) noexcept {
    using std::abs;
    const Scalar inf(std::numeric_limits<Real>::infinity());
    if (!detail::all_finite(M)) return inf;
    const Scalar s = matrix_scale(M);
    if (!(s > Scalar(0))) return inf;
    Scalar d = Rotation::rotation_defect(Matrix3(M.template topLeftCorner<3, 3>() / s));
    for (int j = 0; j < 4; ++j) {
      const Scalar e = abs(M(3, j) - Scalar(j == 3 ? 1 : 0));
      if (e > d) d = e;
    }
    return d;
  }
  /// Checked construction (default tolerance sqrt(eps), constants.hpp).
  static std::optional<Sim3> from_matrix(
      const Matrix4& M, const Scalar& tolerance = Scalar(ThresholdsOf<Scalar>::rotation_tolerance)) noexcept {
    if (transform_defect(M) <= tolerance) return from_matrix_unchecked(M);
    return std::nullopt;
  }
  /// Unchecked construction from [[s R, t], [*, *]]: s = matrix_scale(M),
  /// R = block / s; the bottom row is not read.
  static Sim3 from_matrix_unchecked(const Matrix4& M) noexcept {
    const Scalar s = matrix_scale(M);
    return Sim3(Rotation::from_matrix_unchecked(Matrix3(M.template topLeftCorner<3, 3>() / s)),
                M.template topRightCorner<3, 1>(), s);
  }
  /// The nearest similarity's rotation and scale: R the nearest rotation to
  /// the block (SO3::from_matrix_projected; the block's scale does not
  /// change it), s = tr(R^T block) / 3, the least-squares scale given R
  /// (1 when that is not positive, as for a non-finite M); the translation
  /// column. The bottom row is not read.
  static Sim3 from_matrix_projected(const Matrix4& M) noexcept {
    const Matrix3 B = M.template topLeftCorner<3, 3>();
    const Rotation R = Rotation::from_matrix_projected(B);
    Scalar s = (R.matrix().transpose() * B).trace() / Scalar(3);
    if (!(s > Scalar(0)) || !detail::is_finite(s)) s = Scalar(1);
    return Sim3(R, M.template topRightCorner<3, 1>(), s);
  }

  /// The same similarity with the nearest rotation (removes drift).
  Sim3 normalized() const noexcept { return Sim3(R_.normalized(), t_, s_); }

  template <typename NewScalar>
  Sim3<NewScalar> cast() const noexcept {
    return Sim3<NewScalar>(R_.template cast<NewScalar>(), t_.template cast<NewScalar>(), NewScalar(s_));
  }

  /// Rotations within tol (absolute), translations within tol * max(1, |t|_max),
  /// scales within tol * max(1, s). No `==`.
  bool is_approx(const Sim3& other, const Real& tol) const noexcept {
    return R_.is_approx(other.R_, tol) && detail::approx_equal(t_, other.t_, tol) &&
           detail::approx_equal(Eigen::Matrix<Scalar, 1, 1>(s_), Eigen::Matrix<Scalar, 1, 1>(other.s_), tol);
  }

 private:
  /// W, the top-left block of exp's Jacobians.
  static Matrix3 w_matrix(const Vector3& w, const Scalar& sigma) noexcept {
    const auto k = detail::sim3_coefficients<Scalar>(sigma, Scalar(w.squaredNorm()));
    return detail::so3_combination<Scalar>(w, k.a, k.b, k.c);
  }
  /// W^-1.
  static Matrix3 w_inverse(const Vector3& w, const Scalar& sigma) noexcept {
    const Scalar t = w.squaredNorm();
    const auto ki = detail::sim3_inverse_coefficients<Scalar>(detail::sim3_coefficients<Scalar>(sigma, t), t);
    return detail::so3_combination<Scalar>(w, ki.alpha, ki.beta, ki.gamma);
  }

  /// phi(ad_xi) by scaling and squaring (see above), with its diagonal
  /// blocks W and J_l^SO3 in closed form.
  static Matrix7 jacobian(const Tangent& xi) noexcept {
    using std::abs;
    using std::ldexp;
    // Q and q are linear in v: computed for v / 2^m, |v / 2^m|_max <= 1,
    // and scaled back by 2^m (exact), so that |v| adds no doublings.
    Real vmax(0);
    for (int i = 0; i < 3; ++i) vmax = abs(detail::real_value(xi[i])) > vmax ? abs(detail::real_value(xi[i])) : vmax;
    int vexp = 0;
    if (vmax > Real(1)) std::frexp(vmax, &vexp);
    Tangent xs = xi;
    xs.template head<3>() *= Scalar(ldexp(Real(1), -vexp));
    Matrix7 X = ad(xs);
    // The 1-norm (largest column sum) of ad, halved until <= the bound.
    Real norm(0);
    for (int j = 0; j < 7; ++j) {
      Real c(0);
      for (int i = 0; i < 7; ++i) c += abs(detail::real_value(X(i, j)));
      if (c > norm) norm = c;
    }
    int halvings = 0;
    while (norm > ThresholdsOf<Scalar>::sim3_jacobian_norm && halvings < 4096) {
      norm *= Real(0.5);
      ++halvings;
    }
    X *= Scalar(ldexp(Real(1), -halvings));
    const Matrix7 I = Matrix7::Identity();
    Matrix7 P = I;  // phi(X) = I + X/2 (I + X/3 (I + ...)), Horner
    for (int k = ThresholdsOf<Scalar>::sim3_jacobian_degree; k >= 1; --k) P = I + (X * P) / Scalar(Real(k + 1));
    Matrix7 E = I + X * P;  // exp(X)
    for (int i = 0; i < halvings; ++i) {
      P = (Scalar(0.5) * (E + I)) * P;
      E = E * E;
    }
    P.template topRightCorner<3, 4>() *= Scalar(ldexp(Real(1), vexp));
    const Vector3 w = xi.template segment<3>(3);
    P.template topLeftCorner<3, 3>() = w_matrix(w, xi[6]);
    P.template block<3, 3>(3, 3) = Rotation::left_jacobian(w);
    return P;
  }
  static Matrix7 jacobian_inverse(const Tangent& xi) noexcept {
    const Vector3 w = xi.template segment<3>(3);
    const Matrix7 J = jacobian(xi);
    const Matrix3 Wi = w_inverse(w, xi[6]);
    const Matrix3 Ji = Rotation::left_jacobian_inverse(w);
    Matrix7 out = Matrix7::Zero();
    out.template topLeftCorner<3, 3>() = Wi;
    out.template block<3, 3>(0, 3) = -(Wi * (J.template block<3, 3>(0, 3) * Ji));
    out.template block<3, 1>(0, 6) = -(Wi * J.template block<3, 1>(0, 6));
    out.template block<3, 3>(3, 3) = Ji;
    out(6, 6) = Scalar(1);
    return out;
  }

  Rotation R_;
  Vector3 t_;
  Scalar s_;
};

using Sim3f = Sim3<float>;
using Sim3d = Sim3<double>;

}  // namespace chasles
