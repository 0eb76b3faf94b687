// chasles: SE(3), the group of rigid motions of R^3.
#pragma once

#include <limits>
#include <optional>
#include <type_traits>

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/detail/approx.hpp"
#include "chasles/detail/arguments.hpp"
#include "chasles/detail/series.hpp"
#include "chasles/lie_group.hpp"
#include "chasles/so3.hpp"
#include "chasles/twist.hpp"
#include "chasles/wrench.hpp"

namespace chasles {

namespace detail {

/// Q(v, w), the upper-right block of the SE(3) left Jacobian (Sola eq. 180,
/// Barfoot eq. 7.86), with V = [v], W = [w]:
///   Q = 1/2 V + C (W V + V W + W V W) + q3 (W W V + V W W - 3 W V W)
///         + q4 (W V W W + W W V W)
/// (C, q3, q4 in detail/series.hpp; Sola writes q3 as -(1 - t/2 - cos)/t^2,
/// the same number).
template <typename Scalar>
inline Eigen::Matrix<Scalar, 3, 3> se3_q(const Eigen::Matrix<Scalar, 3, 1>& v,
                                         const Eigen::Matrix<Scalar, 3, 1>& w) noexcept {
  using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;
  const QCoefficients<Scalar> k = q_coefficients(Scalar(w.squaredNorm()));
  const Matrix3 V = SO3<Scalar>::hat(v);
  const Matrix3 W = SO3<Scalar>::hat(w);
  const Matrix3 WV = W * V;
  const Matrix3 VW = V * W;
  const Matrix3 WVW = WV * W;
  const Matrix3 WWV = W * WV;
  const Matrix3 VWW = VW * W;
  const Matrix3 WVWW = WVW * W;
  const Matrix3 WWVW = W * WVW;
  return Scalar(0.5) * V + k.c * (WV + VW + WVW) + k.q3 * (WWV + VWW - Scalar(3) * WVW) + k.q4 * (WVWW + WWVW);
}

/// exp([w]) with the left Jacobian V = J_l(w) of SO(3) kept as the map
///   x -> V x = a x + u x x + (s . x) d,
/// the translational part of SE(3)'s and SE_2(3)'s exp (V applied to one
/// translation or to two). Below huge_theta2, V = A I + B [w] + C w w^T
/// (A, B, C in detail/series.hpp): u = B w, s = C w, d = w, the coefficients
/// scaling w before it meets x (|B w| <= 0.73 and |C w| |w| <= 1.2, so no
/// intermediate exceeds a few |x|: w x x itself would overflow for |w| |x|
/// past the largest finite value). Above it, the unit-axis form
/// V x = A x + (B theta) n x x + (1 - A) (n . x) n.
template <typename Scalar>
struct ExpWithV {
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  Eigen::Matrix<Scalar, 3, 3> rotation;
  Scalar a;
  Vector3 u, s, d;
  Vector3 v(const Vector3& x) const noexcept { return a * x + u.cross(x) + s.dot(x) * d; }
};
template <typename Scalar>
inline ExpWithV<Scalar> exp_with_v(const Eigen::Matrix<Scalar, 3, 1>& w) noexcept {
  const Scalar t = w.squaredNorm();
  if (!(t < Scalar(ThresholdsOf<Scalar>::huge_theta2))) {
    const auto r = long_rotation(w);
    const Eigen::Matrix<Scalar, 3, 1>& n = r.axis;
    return {rodrigues(n, r.sin_theta, r.one_minus_cos), r.a, r.b_theta * n, (Scalar(1) - r.a) * n, n};
  }
  const auto k = exp_coefficients(t);
  return {rodrigues(w, k.a, k.b), k.a, k.b * w, k.c * w, w};
}

/// log(R) with the inverse of V = J_l(w) kept as the map
///   x -> V^-1 x = E x - 1/2 w x x + (D w . x) w,
///   E = (theta/2) cot(theta/2), D = (1 - E) / theta^2,
/// from what the rotation's log already has (no trigonometric call): the
/// translational part of SE(3)'s and SE_2(3)'s log.
template <typename Scalar>
struct LogWithVInverse {
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  So3Log<Scalar> log;  ///< log.omega = w
  Scalar e, d;
  Vector3 v_inverse(const Vector3& x) const noexcept {
    const Vector3& w = log.omega;
    return e * x - Scalar(0.5) * w.cross(x) + (d * w.dot(x)) * w;
  }
};
template <typename Scalar>
inline LogWithVInverse<Scalar> log_with_v_inverse(const Eigen::Matrix<Scalar, 3, 3>& R) noexcept {
  LogWithVInverse<Scalar> l;
  l.log = so3_log(R);
  const auto k = v_inverse_coefficients(l.log.theta2, l.log.half_theta_cot, l.log.near_identity);
  l.e = k.e;
  l.d = k.d;
  return l;
}

/// [[A, B], [0, A]] (6x6).
template <typename Scalar>
inline Eigen::Matrix<Scalar, 6, 6> upper_block_triangular(const Eigen::Matrix<Scalar, 3, 3>& A,
                                                          const Eigen::Matrix<Scalar, 3, 3>& B) noexcept {
  Eigen::Matrix<Scalar, 6, 6> J;
  J.template topLeftCorner<3, 3>() = A;
  J.template topRightCorner<3, 3>() = B;
  J.template bottomLeftCorner<3, 3>().setZero();
  J.template bottomRightCorner<3, 3>() = A;
  return J;
}

}  // namespace detail

/// A rigid motion of R^3: an element of SE(3), stored as a rotation R (an
/// SO3) and a translation p. Its 4x4 matrix is g = [[R, p], [0, 1]].
///
/// `g_ab` maps coordinates in frame b to frame a: q_a = R_ab q_b + p_ab, and
/// composes along the frames: g_ac = g_ab * g_bc. The tangent space is the
/// space of twists xi = (v, w), linear part first (Murray, Li and Sastry);
/// exp([xi]) is the screw motion of Chasles' theorem. Twists change frame by
/// Ad_g = [[R, [p] R], [0, R]]; wrenches by Ad_g^-T, so power is invariant.
///
/// Every operation is noexcept, allocation-free and of bounded cost.
template <typename Scalar_>
class SE3 {
 public:
  using Scalar = Scalar_;
  using Real = RealOf<Scalar>;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  using Vector6 = Eigen::Matrix<Scalar, 6, 1>;
  using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;
  using Matrix4 = Eigen::Matrix<Scalar, 4, 4>;
  using Matrix6 = Eigen::Matrix<Scalar, 6, 6>;
  using Rotation = SO3<Scalar>;
  using Tangent = Vector6;        ///< the twist (v, w)
  using AdjointMatrix = Matrix6;  ///< Ad_g, and the Jacobians
  static constexpr int DoF = 6;

  /// The identity motion.
  SE3() noexcept : R_(), p_(Vector3::Zero()) {}
  /// From a rotation and a translation: g = [[R, p], [0, 1]].
  SE3(const Rotation& R, const Vector3& p) noexcept : R_(R), p_(p) {}

  static SE3 identity() noexcept { return SE3(); }

  /// Not a constructor: a 4x4 matrix becomes an SE3 through one of the three
  /// explicit forms, `from_matrix` (checked), `from_matrix_projected` or
  /// `from_matrix_unchecked`. This declaration only turns `SE3 g(M);` and
  /// `SE3 g = M;` into a compile error that says so.
  template <typename Derived,
            std::enable_if_t<Derived::RowsAtCompileTime == 4 && Derived::ColsAtCompileTime == 4, int> = 0>
  SE3(const Eigen::MatrixBase<Derived>& /*M*/) noexcept : R_(), p_() {
    static_assert(detail::always_false<Derived>::value,
                  "chasles::SE3 is not constructible from a matrix: use SE3::from_matrix(M) (checked: an "
                  "std::optional, empty when M is not a rigid motion), SE3::from_matrix_projected(M) (the nearest "
                  "rotation) or SE3::from_matrix_unchecked(M) (for data known to be a rigid motion)");
  }

  // ---- Lie algebra ------------------------------------------------------

  /// [xi] = [[ [w], v ], [0, 0]] for xi = (v, w).
  static Matrix4 hat(const Vector6& xi) noexcept { return Twist<Scalar>(xi).hat(); }
  /// The (v, w) of a 4x4 twist matrix.
  static Vector6 vee(const Matrix4& X) noexcept { return Twist<Scalar>::vee(X).vector(); }
  /// ad_xi = [[ [w], [v] ], [0, [w]]], the adjoint of the algebra.
  static Matrix6 ad(const Vector6& xi) noexcept { return Twist<Scalar>(xi).ad(); }

  // ---- exp and log ------------------------------------------------------

  /// exp([xi]) for xi = (v, w), theta = |w|, in closed form:
  ///   R = exp([w]),  p = V v,  V = I + B [w] + C [w]^2
  ///                            = A I + B [w] + C w w^T
  /// (A, B, C in detail/series.hpp). Covers w = 0 (V = I, pure
  /// translation) and tiny w without a branch of its own: the series keep
  /// the B [w] v term, of order theta |v|, that a w = 0 special case drops.
  ///
  /// Takes any 6-vector expression (an Eigen::Map of a caller's buffer, a
  /// segment of a larger vector) and reads it in place.
  template <typename Derived>
  static SE3 exp(const Eigen::MatrixBase<Derived>& xi) noexcept {
    // In place, not through a Vector6: that copy stores xi in packets that
    // the loads of w straddle, a store-forwarding stall that doubled the
    // cost in batch loops.
    static_assert(Derived::IsVectorAtCompileTime && Derived::SizeAtCompileTime == 6,
                  "SE3::exp: a twist is a 6-vector (v, w)");
    const auto e = detail::exp_with_v<Scalar>(xi.template tail<3>());
    return SE3(Rotation::from_matrix_unchecked(e.rotation), e.v(xi.template head<3>()));
  }
  static SE3 exp(const Twist<Scalar>& xi) noexcept { return exp(xi.vector()); }

  /// The twist xi = (v, w) with exp([xi]) = g, rotation angle in [0, pi]:
  /// w = log(R) (SO3::log), v = V^-1 p with
  ///   V^-1 = I - 1/2 [w] + D [w]^2 = E I - 1/2 [w] + D w w^T,
  ///   E = (theta/2) cot(theta/2), D = (1 - E) / theta^2,
  /// from what the rotation's log already has (no trigonometric call).
  Vector6 log() const noexcept {
    const auto l = detail::log_with_v_inverse(R_.matrix());
    return detail::stack<Scalar>(l.v_inverse(p_), l.log.omega);
  }

  // ---- Jacobians of exp (Sola app. D and eq. 180, our (v, w) being Sola's (rho, theta)) ----

  /// Left Jacobian: exp(xi + dxi) = exp(J_l dxi + o(dxi)) exp(xi),
  ///   J_l(xi) = [[J_l(w), Q(v, w)], [0, J_l(w)]].
  template <typename Derived>
  static Matrix6 left_jacobian(const Eigen::MatrixBase<Derived>& xi) noexcept {
    static_assert(Derived::IsVectorAtCompileTime && Derived::SizeAtCompileTime == 6, "xi is a 6-vector (v, w)");
    const Vector3 v = xi.template head<3>(), w = xi.template tail<3>();
    return detail::upper_block_triangular<Scalar>(Rotation::left_jacobian(w), detail::se3_q<Scalar>(v, w));
  }
  /// Right Jacobian: exp(xi + dxi) = exp(xi) exp(J_r dxi + o(dxi)),
  ///   J_r(xi) = J_l(-xi) = [[J_r(w), Q(-v, -w)], [0, J_r(w)]].
  template <typename Derived>
  static Matrix6 right_jacobian(const Eigen::MatrixBase<Derived>& xi) noexcept {
    static_assert(Derived::IsVectorAtCompileTime && Derived::SizeAtCompileTime == 6, "xi is a 6-vector (v, w)");
    const Vector3 v = -xi.template head<3>(), w = -xi.template tail<3>();
    return detail::upper_block_triangular<Scalar>(Rotation::left_jacobian(w), detail::se3_q<Scalar>(v, w));
  }
  /// J_l(xi)^-1 by the block formula [[J_l^-1, -J_l^-1 Q J_l^-1], [0, J_l^-1]],
  /// J_l^-1 = J_l(w)^-1, Q = Q(v, w).
  template <typename Derived>
  static Matrix6 left_jacobian_inverse(const Eigen::MatrixBase<Derived>& xi) noexcept {
    static_assert(Derived::IsVectorAtCompileTime && Derived::SizeAtCompileTime == 6, "xi is a 6-vector (v, w)");
    const Vector3 v = xi.template head<3>(), w = xi.template tail<3>();
    const Matrix3 Ji = Rotation::left_jacobian_inverse(w);
    const Matrix3 QJi = detail::se3_q<Scalar>(v, w) * Ji;
    return detail::upper_block_triangular<Scalar>(Ji, Matrix3(-(Ji * QJi)));
  }
  /// J_r(xi)^-1 = J_l(-xi)^-1.
  template <typename Derived>
  static Matrix6 right_jacobian_inverse(const Eigen::MatrixBase<Derived>& xi) noexcept {
    static_assert(Derived::IsVectorAtCompileTime && Derived::SizeAtCompileTime == 6, "xi is a 6-vector (v, w)");
    return left_jacobian_inverse(Vector6(-xi));
  }

  // ---- group operations -------------------------------------------------

  /// g^-1 = [[R^T, -R^T p], [0, 1]].
  SE3 inverse() const noexcept {
    // -R^T p from the stored R (reading back a just-stored R^T stalls).
    return SE3(R_.inverse(), -(R_.matrix().transpose() * p_));
  }

  /// Composition g_ab * g_bc = g_ac = [[R_ab R_bc, R_ab p_bc + p_ab], [0, 1]].
  SE3 operator*(const SE3& other) const noexcept { return SE3(R_ * other.R_, R_.matrix() * other.p_ + p_); }
  SE3& operator*=(const SE3& other) noexcept {
    p_ = R_.matrix() * other.p_ + p_;
    R_ *= other.R_;
    return *this;
  }

  /// Action on a point: q_a = R q_b + p.
  Vector3 act(const Vector3& q) const noexcept { return R_.matrix() * q + p_; }
  Vector3 operator*(const Vector3& q) const noexcept { return act(q); }

  /// A twist from frame b to frame a: xi_a = Ad_g xi_b = (R v + p x R w, R w).
  Twist<Scalar> act(const Twist<Scalar>& xi) const noexcept {
    const Vector3 Rw = R_.matrix() * xi.angular();
    return Twist<Scalar>(Vector3(R_.matrix() * xi.linear() + p_.cross(Rw)), Rw);
  }
  /// A twist from frame a to frame b: xi_b = Ad_g^-1 xi_a = (R^T (v - p x w), R^T w).
  Twist<Scalar> act_inv(const Twist<Scalar>& xi) const noexcept {
    const auto Rt = R_.matrix().transpose();
    return Twist<Scalar>(Vector3(Rt * (xi.linear() - p_.cross(xi.angular()))), Vector3(Rt * xi.angular()));
  }
  /// A wrench from frame b to frame a: F_a = Ad_g^-T F_b = (R f, p x R f + R tau).
  Wrench<Scalar> act(const Wrench<Scalar>& F) const noexcept {
    const Vector3 Rf = R_.matrix() * F.force();
    return Wrench<Scalar>(Rf, Vector3(p_.cross(Rf) + R_.matrix() * F.torque()));
  }
  /// A wrench from frame a to frame b: F_b = Ad_g^T F_a = (R^T f, R^T (tau - p x f)).
  Wrench<Scalar> act_inv(const Wrench<Scalar>& F) const noexcept {
    const auto Rt = R_.matrix().transpose();
    return Wrench<Scalar>(Vector3(Rt * F.force()), Vector3(Rt * (F.torque() - p_.cross(F.force()))));
  }

  /// Ad_g = [[R, [p] R], [0, R]] (6x6), so that g [xi] g^-1 = [Ad_g xi].
  Matrix6 adjoint() const noexcept {
    Matrix6 A;
    const Matrix3& R = R_.matrix();
    A.template topLeftCorner<3, 3>() = R;
    // [p] R column by column, p x R e_j: no 3x3 temporary for hat(p), whose
    // vector reloads in the product stall on its scalar stores.
    for (int j = 0; j < 3; ++j) A.template block<3, 1>(0, 3 + j) = p_.cross(R.col(j));
    A.template bottomLeftCorner<3, 3>().setZero();
    A.template bottomRightCorner<3, 3>() = R;
    return A;
  }

  // ---- access and conversions -------------------------------------------

  const Rotation& rotation() const noexcept { return R_; }
  const Vector3& translation() const noexcept { return p_; }

  /// g = [[R, p], [0, 1]] (4x4).
  Matrix4 matrix() const noexcept {
    Matrix4 g;
    g.template topLeftCorner<3, 3>() = R_.matrix();
    g.template topRightCorner<3, 1>() = p_;
    g.template bottomRows<1>() << Scalar(0), Scalar(0), Scalar(0), Scalar(1);
    return g;
  }

  /// How far a 4x4 matrix is from a rigid motion: the rotation defect of its
  /// top-left block (SO3::rotation_defect) or the largest deviation of its
  /// bottom row from (0, 0, 0, 1), whichever is larger; +inf when an entry
  /// of M is not finite.
  static Scalar transform_defect(const Matrix4& M) noexcept {
    using std::abs;
    if (!detail::all_finite(M)) return Scalar(std::numeric_limits<Real>::infinity());
    Scalar d = Rotation::rotation_defect(M.template topLeftCorner<3, 3>());
    for (int j = 0; j < 4; ++j) {
      const Scalar e = abs(M(3, j) - Scalar(j == 3 ? 1 : 0));
      if (e > d) d = e;
    }
    return d;
  }

  /// Checked construction: M itself if `transform_defect(M) <= tolerance`,
  /// otherwise nothing (default tolerance sqrt(eps), constants.hpp).
  static std::optional<SE3> from_matrix(
      const Matrix4& M, const Scalar& tolerance = Scalar(ThresholdsOf<Scalar>::rotation_tolerance)) noexcept {
    if (transform_defect(M) <= tolerance) return from_matrix_unchecked(M);
    return std::nullopt;
  }

  /// Unchecked construction from [[R, p], [*, *]]: for valid data; the
  /// bottom row is not read.
  static SE3 from_matrix_unchecked(const Matrix4& M) noexcept {
    return SE3(Rotation::from_matrix_unchecked(M.template topLeftCorner<3, 3>()), M.template topRightCorner<3, 1>());
  }

  /// Projecting construction: the nearest rotation to the top-left block
  /// (SO3::from_matrix_projected) and the translation column; the bottom row
  /// is not read.
  static SE3 from_matrix_projected(const Matrix4& M) noexcept {
    return SE3(Rotation::from_matrix_projected(M.template topLeftCorner<3, 3>()), M.template topRightCorner<3, 1>());
  }

  /// The screw motion about the axis through `point` q along `direction`
  /// w_hat (normalized here), `pitch` h, by theta:
  /// exp(theta * (-w_hat x q + h w_hat, w_hat)); h = +inf is the translation
  /// theta * w_hat.
  static SE3 from_screw(const Vector3& point, const Vector3& direction, const Scalar& pitch,
                        const Scalar& theta) noexcept {
    return exp(Twist<Scalar>::from_screw(point, direction, pitch, theta));
  }

  /// The same motion with the nearest rotation (removes drift).
  SE3 normalized() const noexcept { return SE3(R_.normalized(), p_); }

  template <typename NewScalar>
  SE3<NewScalar> cast() const noexcept {
    return SE3<NewScalar>(R_.template cast<NewScalar>(), p_.template cast<NewScalar>());
  }

  /// Rotations within tol (absolute) and translations within
  /// tol * max(1, |p|_max) (relative beyond unit scale). No `==`.
  bool is_approx(const SE3& other, const Real& tol) const noexcept {
    return R_.is_approx(other.R_, tol) && detail::approx_equal(p_, other.p_, tol);
  }

 private:
  Rotation R_;
  Vector3 p_;
};

using SE3f = SE3<float>;
using SE3d = SE3<double>;

}  // namespace chasles
