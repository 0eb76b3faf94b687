// chasles: twists, the elements of se(3).
#pragma once

#include <Eigen/Core>

#include "chasles/detail/approx.hpp"
#include "chasles/detail/arguments.hpp"
#include "chasles/screw.hpp"
#include "chasles/so3.hpp"

namespace chasles {

template <typename Scalar_>
class SE3;

/// A twist xi = (v, w) in se(3): linear part first, angular part second
/// (Murray, Li and Sastry's order; Modern Robotics writes (w, v), see
/// `to_modern_robotics`). Its 4x4 matrix is [xi] = [[ [w], v ], [0, 0]].
///
/// A twist is a velocity (spatial: (g' g^-1)^vee, body: (g^-1 g')^vee) or,
/// scaled by theta, exponential coordinates of a rigid motion: exp([xi]).
/// Twists change frame by the adjoint, xi_a = Ad_{g_ab} xi_b
/// (`SE3::act(Twist)`); wrenches change frame by its inverse transpose.
template <typename Scalar_>
class Twist {
 public:
  using Scalar = Scalar_;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  using Vector6 = Eigen::Matrix<Scalar, 6, 1>;
  using Matrix4 = Eigen::Matrix<Scalar, 4, 4>;
  using Matrix6 = Eigen::Matrix<Scalar, 6, 6>;
  static constexpr int linear_offset = 0;   ///< where v starts in vector()
  static constexpr int angular_offset = 3;  ///< where w starts in vector()

  /// The zero twist.
  Twist() noexcept : xi_(Vector6::Zero()) {}
  /// From the linear part v and the angular part w.
  Twist(const Vector3& v, const Vector3& w) noexcept : xi_(detail::stack<Scalar>(v, w)) {}
  /// From the 6-vector (v, w).
  explicit Twist(const Vector6& xi) noexcept : xi_(xi) {}

  const Vector6& vector() const noexcept { return xi_; }
  Vector6& vector() noexcept { return xi_; }
  auto linear() const noexcept { return xi_.template segment<3>(linear_offset); }
  auto linear() noexcept { return xi_.template segment<3>(linear_offset); }
  auto angular() const noexcept { return xi_.template segment<3>(angular_offset); }
  auto angular() noexcept { return xi_.template segment<3>(angular_offset); }

  /// (w, v), the Modern Robotics order.
  Vector6 to_modern_robotics() const noexcept { return detail::stack<Scalar>(angular(), linear()); }
  /// From (w, v), the Modern Robotics order.
  static Twist from_modern_robotics(const Vector6& wv) noexcept {
    return Twist(Vector3(wv.template tail<3>()), Vector3(wv.template head<3>()));
  }

  /// [xi] = [[ [w], v ], [0, 0]] (4x4).
  Matrix4 hat() const noexcept {
    Matrix4 X = Matrix4::Zero();
    X.template topLeftCorner<3, 3>() = SO3<Scalar>::hat(angular());
    X.template topRightCorner<3, 1>() = linear();
    return X;
  }
  /// The twist of a 4x4 matrix [[S, v], [*, *]]: v and vee of S's
  /// antisymmetric part; the bottom row is ignored.
  static Twist vee(const Matrix4& X) noexcept {
    return Twist(Vector3(X.template topRightCorner<3, 1>()), SO3<Scalar>::vee(X.template topLeftCorner<3, 3>()));
  }

  /// ad_xi = [[ [w], [v] ], [0, [w]]] (6x6), so ad_xi eta = [xi, eta].
  Matrix6 ad() const noexcept {
    Matrix6 A = Matrix6::Zero();
    const Eigen::Matrix<Scalar, 3, 3> W = SO3<Scalar>::hat(angular());
    A.template topLeftCorner<3, 3>() = W;
    A.template bottomRightCorner<3, 3>() = W;
    A.template topRightCorner<3, 3>() = SO3<Scalar>::hat(linear());
    return A;
  }
  /// The Lie bracket [xi, eta] = ([xi][eta] - [eta][xi])^vee
  ///   = (w1 x v2 + v1 x w2, w1 x w2).
  Twist bracket(const Twist& eta) const noexcept {
    const Vector3 v1 = linear(), w1 = angular(), v2 = eta.linear(), w2 = eta.angular();
    return Twist(Vector3(w1.cross(v2) + v1.cross(w2)), Vector3(w1.cross(w2)));
  }

  /// The screw of the twist (Chasles): with w != 0, pitch w.v / |w|^2, axis
  /// through w x v / |w|^2 along w / |w|, magnitude |w|; with w = 0 (or
  /// w so small that the axis is beyond the largest finite distance), pitch
  /// +inf, direction v / |v|, magnitude |v|: a pure translation.
  Screw<Scalar> screw() const noexcept { return detail::screw_of_pair(Vector3(angular()), Vector3(linear())); }
  /// w.v / |w|^2 (+inf for w = 0).
  Scalar pitch() const noexcept { return screw().pitch; }

  /// The unit twist of a screw times theta:
  ///   theta * (-w_hat x q + h w_hat, w_hat)
  /// for the axis through `point` q along `direction` w_hat (normalized
  /// here), `pitch` h; with h = +inf, the translation theta * (w_hat, 0).
  static Twist from_screw(const Vector3& point, const Vector3& direction, const Scalar& pitch,
                          const Scalar& theta) noexcept {
    Vector3 w, v;
    detail::pair_of_screw(point, direction, pitch, theta, w, v);
    return Twist(v, w);
  }
  static Twist from_screw(const Screw<Scalar>& s) noexcept {
    return from_screw(s.point, s.direction, s.pitch, s.magnitude);
  }

  /// The spatial twist of a trajectory at (g, g'): V^s = (g' g^-1)^vee,
  /// w^s = (R' R^T)^vee, v^s = p' - w^s x p.
  static Twist spatial(const SE3<Scalar>& g, const Matrix4& g_dot) noexcept {
    const Vector3 w = SO3<Scalar>::vee(g_dot.template topLeftCorner<3, 3>() * g.rotation().matrix().transpose());
    const Vector3 p_dot = g_dot.template topRightCorner<3, 1>();
    return Twist(Vector3(p_dot - w.cross(g.translation())), w);
  }
  /// The body twist of a trajectory at (g, g'): V^b = (g^-1 g')^vee,
  /// w^b = (R^T R')^vee, v^b = R^T p'.
  static Twist body(const SE3<Scalar>& g, const Matrix4& g_dot) noexcept {
    const auto Rt = g.rotation().matrix().transpose();
    return Twist(Vector3(Rt * g_dot.template topRightCorner<3, 1>()),
                 SO3<Scalar>::vee(Rt * g_dot.template topLeftCorner<3, 3>()));
  }

  template <typename NewScalar>
  Twist<NewScalar> cast() const noexcept {
    return Twist<NewScalar>(xi_.template cast<NewScalar>());
  }

  Twist operator+(const Twist& o) const noexcept { return Twist(Vector6(xi_ + o.xi_)); }
  Twist operator-(const Twist& o) const noexcept { return Twist(Vector6(xi_ - o.xi_)); }
  Twist operator-() const noexcept { return Twist(Vector6(-xi_)); }
  Twist operator*(const Scalar& s) const noexcept { return Twist(Vector6(xi_ * s)); }
  /// x * s for s of another arithmetic type (0.1 for a float twist), converted explicitly.
  template <typename T, detail::EnableIfOtherArithmetic<Scalar, T> = 0>
  Twist operator*(const T& s) const noexcept {
    return *this * detail::scalar_of<Scalar>(s);
  }

  /// max |xi - other| <= tol * max(1, max |xi|, max |other|).
  bool is_approx(const Twist& other, const RealOf<Scalar>& tol) const noexcept {
    return detail::approx_equal(xi_, other.xi_, tol);
  }

 private:
  Vector6 xi_;
};

/// s * x, the same as x * s.
template <typename Scalar>
inline Twist<Scalar> operator*(const typename Twist<Scalar>::Scalar& s, const Twist<Scalar>& x) noexcept {
  return x * s;
}
template <typename Scalar, typename T, detail::EnableIfOtherArithmetic<Scalar, T> = 0>
inline Twist<Scalar> operator*(const T& s, const Twist<Scalar>& x) noexcept {
  return x * detail::scalar_of<Scalar>(s);
}

using Twistf = Twist<float>;
using Twistd = Twist<double>;

}  // namespace chasles
