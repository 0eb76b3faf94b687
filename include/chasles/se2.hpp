// chasles: SE(2), the group of rigid motions of the plane.
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/detail/approx.hpp"
#include "chasles/detail/series.hpp"
#include "chasles/lie_group.hpp"
#include "chasles/so2.hpp"

namespace chasles {

namespace detail {

/// What exp and its Jacobians of SE(2) need of theta: (c, s) = (cos, sin)
/// and the two coefficients of V = [[a, -b], [b, a]], a = sin(theta) / theta,
/// b = (1 - cos(theta)) / theta. Below taylor_theta2 (constants.hpp) the
/// series a = 1 - t/6 + t^2/120, b = theta (1/2 - t/24 + t^2/720), t =
/// theta^2, and (c, s) from them (no libm call, exact at 0, autodiff
/// derivatives exact there). Above, one sincos and one divide: a = s / theta, and
/// 1 - cos theta as s^2 / (1 + c) where c > 0, where 1 - c would cancel.
template <typename Scalar>
struct PlanarExp {
  Scalar c, s, a, b;
};
template <typename Scalar>
inline PlanarExp<Scalar> planar_exp(const Scalar& theta) noexcept {
  using std::cos;
  using std::sin;
  const Scalar t = theta * theta;
  if (t < Scalar(ThresholdsOf<Scalar>::taylor_theta2)) {
    const Scalar a = Scalar(1) - t / Scalar(6) * (Scalar(1) - t / Scalar(20));
    const Scalar b_over = Scalar(0.5) - t / Scalar(24) * (Scalar(1) - t / Scalar(30));
    return {Scalar(1) - t * b_over, theta * a, a, theta * b_over};
  }
  const Scalar c = cos(theta), s = sin(theta);
  if (c > Scalar(0)) {  // one divide: a = s (1 + c) r, b = s^2 r, r = 1 / ((1 + c) theta)
    const Scalar one_plus_c = Scalar(1) + c, r = Scalar(1) / (one_plus_c * theta);
    return {c, s, s * one_plus_c * r, s * s * r};
  }
  const Scalar r = Scalar(1) / theta;
  return {c, s, s * r, (Scalar(1) - c) * r};
}

}  // namespace detail

/// A rigid motion of the plane: an element of SE(2), stored as a rotation R
/// (an SO2) and a translation t. Its 3x3 matrix is g = [[R, t], [0, 1]].
///
/// g_ab maps frame b to frame a: q_a = R q_b + t, composing along the frames
/// as SE3. The tangent space is xi = (vx, vy, w), linear part first (as SE3,
/// jaxlie and manif), hat(xi) = [[0, -w, vx], [w, 0, vy], [0, 0, 0]]. Every
/// operation is noexcept, allocation-free and of bounded cost.
template <typename Scalar_>
class SE2 {
 public:
  using Scalar = Scalar_;
  using Real = RealOf<Scalar>;
  using Vector2 = Eigen::Matrix<Scalar, 2, 1>;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  using Matrix2 = Eigen::Matrix<Scalar, 2, 2>;
  using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;
  using Rotation = SO2<Scalar>;
  using Tangent = Vector3;        ///< xi = (vx, vy, w)
  using AdjointMatrix = Matrix3;  ///< Ad_g, and the Jacobians
  static constexpr int DoF = 3;

  /// The identity motion.
  SE2() noexcept : R_(), t_(Vector2::Zero()) {}
  /// From a rotation and a translation: g = [[R, t], [0, 1]].
  SE2(const Rotation& R, const Vector2& t) noexcept : R_(R), t_(t) {}
  static SE2 identity() noexcept { return SE2(); }

  // ---- Lie algebra ------------------------------------------------------

  /// [xi] = [[0, -w, vx], [w, 0, vy], [0, 0, 0]].
  static Matrix3 hat(const Tangent& xi) noexcept {
    Matrix3 X;
    X << Scalar(0), -xi[2], xi[0], xi[2], Scalar(0), xi[1], Scalar(0), Scalar(0), Scalar(0);
    return X;
  }
  /// (vx, vy) from the last column, w from the antisymmetric part of the
  /// top-left block; the bottom row is not read.
  static Tangent vee(const Matrix3& X) noexcept {
    return Tangent(X(0, 2), X(1, 2), detail::half_difference(X(1, 0), X(0, 1)));
  }
  /// ad_xi = [[0, -w, vy], [w, 0, -vx], [0, 0, 0]]: ad_a b = [a, b].
  static Matrix3 ad(const Tangent& xi) noexcept {
    Matrix3 A;
    A << Scalar(0), -xi[2], xi[1], xi[2], Scalar(0), -xi[0], Scalar(0), Scalar(0), Scalar(0);
    return A;
  }

  // ---- exp and log ------------------------------------------------------

  /// exp([xi]) for xi = (v, w): R = exp(w), t = V v with
  ///   V = [[a, -b], [b, a]],  a = sin(w) / w,  b = (1 - cos(w)) / w
  /// (Sola, Deray and Atchuthan 2018, app. C). One sincos (detail::planar_exp).
  static SE2 exp(const Tangent& xi) noexcept {
    const auto k = detail::planar_exp<Scalar>(xi[2]);
    return SE2(Rotation::from_complex_unchecked(k.c, k.s),
               Vector2(k.a * xi[0] - k.b * xi[1], k.b * xi[0] + k.a * xi[1]));
  }

  /// The xi = (v, w) with exp([xi]) = g, w = atan2(s, c) in [-pi, pi]:
  ///   v = V^-1 t = [[e, w/2], [-w/2, e]] t,  e = (w/2) cot(w/2),
  /// w and e from the half angle without a libm call or a cancellation, 0 at
  /// w = pi exactly (detail::planar_log).
  Tangent log() const noexcept {
    const auto k = detail::planar_log<Scalar>(R_.complex()[0], R_.complex()[1]);
    const Scalar half = Scalar(0.5) * k.theta;
    return Tangent(k.e * t_[0] + half * t_[1], k.e * t_[1] - half * t_[0], k.theta);
  }

  // ---- Jacobians of exp (Sola app. C) ---------------------------------------

  /// Left Jacobian: exp(xi + dxi) = exp(J_l dxi + o(dxi)) exp(xi),
  ///   J_l = [[a, -b, C vx + B vy], [b, a, -B vx + C vy], [0, 0, 1]],
  /// B = (1 - cos w) / w^2, C = (w - sin w) / w^3 (detail/series.hpp).
  static Matrix3 left_jacobian(const Tangent& xi) noexcept { return jacobian(xi, Scalar(1)); }
  /// Right Jacobian: J_r(xi) = J_l(-xi).
  static Matrix3 right_jacobian(const Tangent& xi) noexcept { return jacobian(xi, Scalar(-1)); }
  /// J_l^-1 = [[V^-1, -V^-1 u], [0, 1]], u the top of J_l's last column and
  /// V^-1 = [[e, w/2], [-w/2, e]], e = 1 - D w^2 (D of SO3's inverse
  /// Jacobians: finite for |w| < 2 pi).
  static Matrix3 left_jacobian_inverse(const Tangent& xi) noexcept { return jacobian_inverse(xi, Scalar(1)); }
  /// J_r^-1(xi) = J_l^-1(-xi).
  static Matrix3 right_jacobian_inverse(const Tangent& xi) noexcept { return jacobian_inverse(xi, Scalar(-1)); }

  // ---- group operations -------------------------------------------------

  /// g^-1 = [[R^T, -R^T t], [0, 1]].
  SE2 inverse() const noexcept {
    const Rotation Ri = R_.inverse();
    return SE2(Ri, -Ri.act(t_));
  }
  /// g_ab g_bc = [[R_ab R_bc, R_ab t_bc + t_ab], [0, 1]].
  SE2 operator*(const SE2& o) const noexcept { return SE2(R_ * o.R_, R_.act(o.t_) + t_); }
  SE2& operator*=(const SE2& o) noexcept { return *this = *this * o; }

  /// Action on a point: q_a = R q_b + t.
  Vector2 act(const Vector2& q) const noexcept { return R_.act(q) + t_; }
  Vector2 operator*(const Vector2& q) const noexcept { return act(q); }

  /// Ad_g = [[R, (ty, -tx)], [0, 1]] (3x3), so that g [xi] g^-1 = [Ad_g xi].
  Matrix3 adjoint() const noexcept {
    const Vector2& cs = R_.complex();
    Matrix3 A;
    A << cs[0], -cs[1], t_[1], cs[1], cs[0], -t_[0], Scalar(0), Scalar(0), Scalar(1);
    return A;
  }

  // ---- access and conversions -------------------------------------------

  const Rotation& rotation() const noexcept { return R_; }
  const Vector2& translation() const noexcept { return t_; }

  /// g = [[R, t], [0, 1]] (3x3).
  Matrix3 matrix() const noexcept {
    const Vector2& cs = R_.complex();
    Matrix3 g;
    g << cs[0], -cs[1], t_[0], cs[1], cs[0], t_[1], Scalar(0), Scalar(0), Scalar(1);
    return g;
  }

  /// How far a 3x3 matrix is from a rigid motion: the rotation defect of its
  /// top-left block or the deviation of its bottom row from (0, 0, 1),
  /// whichever is larger; +inf when an entry is not finite.
  static Scalar transform_defect(const Matrix3& M) noexcept {
    using std::abs;
    if (!detail::all_finite(M)) return Scalar(std::numeric_limits<Real>::infinity());
    Scalar d = Rotation::rotation_defect(M.template topLeftCorner<2, 2>());
    for (int j = 0; j < 3; ++j) {
      const Scalar e = abs(M(2, j) - Scalar(j == 2 ? 1 : 0));
      if (e > d) d = e;
    }
    return d;
  }
  /// Checked construction (default tolerance sqrt(eps), constants.hpp).
  static std::optional<SE2> from_matrix(
      const Matrix3& M, const Scalar& tolerance = Scalar(ThresholdsOf<Scalar>::rotation_tolerance)) noexcept {
    if (transform_defect(M) <= tolerance) return from_matrix_unchecked(M);
    return std::nullopt;
  }
  /// Unchecked construction from [[R, t], [*, *]] (SO2::from_matrix_unchecked
  /// of the block); the bottom row is not read.
  static SE2 from_matrix_unchecked(const Matrix3& M) noexcept {
    return SE2(Rotation::from_matrix_unchecked(M.template topLeftCorner<2, 2>()), M.template topRightCorner<2, 1>());
  }
  /// The nearest rotation to the top-left block, and the translation column.
  static SE2 from_matrix_projected(const Matrix3& M) noexcept {
    return SE2(Rotation::from_matrix_projected(M.template topLeftCorner<2, 2>()), M.template topRightCorner<2, 1>());
  }

  /// The same motion with the nearest rotation (removes drift).
  SE2 normalized() const noexcept { return SE2(R_.normalized(), t_); }

  template <typename NewScalar>
  SE2<NewScalar> cast() const noexcept {
    return SE2<NewScalar>(R_.template cast<NewScalar>(), t_.template cast<NewScalar>());
  }

  /// Rotations within tol (absolute) and translations within
  /// tol * max(1, |t|_max). No `==`.
  bool is_approx(const SE2& other, const Real& tol) const noexcept {
    return R_.is_approx(other.R_, tol) && detail::approx_equal(t_, other.t_, tol);
  }

 private:
  /// J_l(sign * xi): [[V, u], [0, 1]].
  static Matrix3 jacobian(const Tangent& xi, const Scalar& sign) noexcept {
    const Scalar vx = sign * xi[0], vy = sign * xi[1], w = sign * xi[2];
    const auto p = detail::planar_exp<Scalar>(w);
    const auto k = detail::exp_coefficients<Scalar>(Scalar(w * w));
    const Scalar cw = k.c * w;  // (w - sin w) / w^2
    Matrix3 J;
    J << p.a, -p.b, cw * vx + k.b * vy, p.b, p.a, cw * vy - k.b * vx, Scalar(0), Scalar(0), Scalar(1);
    return J;
  }
  /// J_l(sign * xi)^-1: [[V^-1, -V^-1 u], [0, 1]].
  static Matrix3 jacobian_inverse(const Tangent& xi, const Scalar& sign) noexcept {
    const Scalar vx = sign * xi[0], vy = sign * xi[1], w = sign * xi[2];
    const Scalar t = w * w;
    const auto k = detail::exp_coefficients<Scalar>(t);
    const Scalar e = Scalar(1) - detail::jacobian_inverse_coefficient(t) * t, half = Scalar(0.5) * w;
    const Scalar cw = k.c * w;
    const Scalar ux = cw * vx + k.b * vy, uy = cw * vy - k.b * vx;
    Matrix3 J;
    J << e, half, -(e * ux + half * uy), -half, e, -(e * uy - half * ux), Scalar(0), Scalar(0), Scalar(1);
    return J;
  }

  Rotation R_;
  Vector2 t_;
};

using SE2f = SE2<float>;
using SE2d = SE2<double>;

}  // namespace chasles
