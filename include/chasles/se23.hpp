// chasles: SE_2(3), the group of extended poses (rotation, position,
// velocity): the state of an IMU's preintegration and of invariant Kalman
// filters (Barrau and Bonnabel, "The invariant extended Kalman filter as a
// stable observer", IEEE TAC 2017).
#pragma once

#include <limits>
#include <optional>

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/detail/approx.hpp"
#include "chasles/lie_group.hpp"
#include "chasles/se3.hpp"
#include "chasles/so3.hpp"

namespace chasles {

/// An extended pose: an element of SE_2(3), stored as a rotation R (an SO3),
/// a position p and a velocity v. Its matrix is the 5x5
///   X = [[R, p, v], [0, 1, 0], [0, 0, 1]]
/// (manif's layout). It composes as X1 X2 = (R1 R2, R1 p2 + p1, R1 v2 + v1)
/// and acts on points as q_a = R q_b + p (the velocity does not move points).
///
/// The tangent is xi = (rho, nu, w): the position part, the velocity part and
/// the rotation, in the order of the matrix's columns, so that
///   [xi] = [[ [w], rho, nu ], [0, 0, 0], [0, 0, 0]].
/// (manif orders its tangent (rho, w, nu); gtsam's NavState (w, rho, nu).)
/// SE_2(3) is SE(3) with a second translation: exp, log, the adjoint and the
/// Jacobians are SE(3)'s applied to both (Barrau and Bonnabel; Sola, Deray
/// and Atchuthan 2018, app. E: "Sola" below).
///
/// Every operation is noexcept, allocation-free and of bounded cost.
template <typename Scalar_>
class SE23 {
 public:
  using Scalar = Scalar_;
  using Real = RealOf<Scalar>;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  using Vector9 = Eigen::Matrix<Scalar, 9, 1>;
  using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;
  using Matrix5 = Eigen::Matrix<Scalar, 5, 5>;
  using Matrix9 = Eigen::Matrix<Scalar, 9, 9>;
  using Rotation = SO3<Scalar>;
  using Tangent = Vector9;        ///< xi = (rho, nu, w)
  using AdjointMatrix = Matrix9;  ///< Ad_X, and the Jacobians
  static constexpr int DoF = 9;

  /// The identity: R = I, p = v = 0.
  SE23() noexcept : R_(), p_(Vector3::Zero()), v_(Vector3::Zero()) {}
  /// From a rotation, a position and a velocity.
  SE23(const Rotation& R, const Vector3& p, const Vector3& v) noexcept : R_(R), p_(p), v_(v) {}
  static SE23 identity() noexcept { return SE23(); }

  // ---- Lie algebra ------------------------------------------------------

  /// [xi] = [[ [w], rho, nu ], [0, 0, 0], [0, 0, 0]] (5x5).
  static Matrix5 hat(const Tangent& xi) noexcept {
    Matrix5 X = Matrix5::Zero();
    X.template topLeftCorner<3, 3>() = Rotation::hat(xi.template tail<3>());
    X.template block<3, 1>(0, 3) = xi.template head<3>();
    X.template block<3, 1>(0, 4) = xi.template segment<3>(3);
    return X;
  }
  /// The (rho, nu, w) of a 5x5 matrix: the inverse of hat (w from the
  /// antisymmetric part of the top-left block; the bottom rows are not read).
  static Tangent vee(const Matrix5& X) noexcept {
    Tangent xi;
    xi.template head<3>() = X.template block<3, 1>(0, 3);
    xi.template segment<3>(3) = X.template block<3, 1>(0, 4);
    xi.template tail<3>() = Rotation::vee(X.template topLeftCorner<3, 3>());
    return xi;
  }
  /// ad_xi = [[ [w], 0, [rho] ], [0, [w], [nu]], [0, 0, [w]]], the adjoint of
  /// the algebra: ad_xi eta = vee([[xi], [eta]]).
  static Matrix9 ad(const Tangent& xi) noexcept {
    const Matrix3 W = Rotation::hat(xi.template tail<3>());
    return blocks(W, Rotation::hat(xi.template head<3>()), Rotation::hat(xi.template segment<3>(3)));
  }

  // ---- exp and log ------------------------------------------------------

  /// exp([xi]) for xi = (rho, nu, w) in closed form, SE(3)'s applied to both
  /// translations:
  ///   R = exp([w]),  p = V rho,  v = V nu,  V = J_l(w) = A I + B [w] + C w w^T
  /// (A, B, C in detail/series.hpp): one sincos, no 0/0 at w = 0.
  template <typename Derived>
  static SE23 exp(const Eigen::MatrixBase<Derived>& xi) noexcept {
    static_assert(Derived::IsVectorAtCompileTime && Derived::SizeAtCompileTime == 9,
                  "SE23::exp: a tangent is a 9-vector (rho, nu, w)");
    const auto e = detail::exp_with_v<Scalar>(xi.template tail<3>());
    return SE23(Rotation::from_matrix_unchecked(e.rotation), e.v(xi.template head<3>()),
                e.v(xi.template segment<3>(3)));
  }

  /// The xi = (rho, nu, w) with exp([xi]) = X, rotation angle in [0, pi]:
  /// w = log(R) (SO3's), rho = V^-1 p, nu = V^-1 v with
  ///   V^-1 = E I - 1/2 [w] + D w w^T,  E = (theta/2) cot(theta/2),
  /// from what the rotation's log already has (no trigonometric call).
  Tangent log() const noexcept {
    const auto l = detail::log_with_v_inverse(R_.matrix());
    Tangent xi;
    xi.template head<3>() = l.v_inverse(p_);
    xi.template segment<3>(3) = l.v_inverse(v_);
    xi.template tail<3>() = l.log.omega;
    return xi;
  }

  // ---- Jacobians of exp (Sola app. E: SE(3)'s, block by block) -----------

  /// Left Jacobian: exp(xi + dxi) = exp(J_l dxi + o(dxi)) exp(xi),
  ///   J_l(xi) = [[J_l(w), 0, Q(rho, w)], [0, J_l(w), Q(nu, w)], [0, 0, J_l(w)]]
  /// with Q SE(3)'s (detail::se3_q).
  static Matrix9 left_jacobian(const Tangent& xi) noexcept {
    const Vector3 w = xi.template tail<3>();
    return blocks(Rotation::left_jacobian(w), detail::se3_q<Scalar>(xi.template head<3>(), w),
                  detail::se3_q<Scalar>(xi.template segment<3>(3), w));
  }
  /// Right Jacobian: exp(xi + dxi) = exp(xi) exp(J_r dxi + o(dxi)), J_r(xi) = J_l(-xi).
  static Matrix9 right_jacobian(const Tangent& xi) noexcept { return left_jacobian(Tangent(-xi)); }
  /// J_l(xi)^-1 by the block formula: diagonal J_l(w)^-1, corners
  /// -J_l(w)^-1 Q J_l(w)^-1.
  static Matrix9 left_jacobian_inverse(const Tangent& xi) noexcept {
    const Vector3 w = xi.template tail<3>();
    const Matrix3 Ji = Rotation::left_jacobian_inverse(w);
    const Matrix3 Qp = detail::se3_q<Scalar>(xi.template head<3>(), w) * Ji;
    const Matrix3 Qv = detail::se3_q<Scalar>(xi.template segment<3>(3), w) * Ji;
    return blocks(Ji, Matrix3(-(Ji * Qp)), Matrix3(-(Ji * Qv)));
  }
  /// J_r(xi)^-1 = J_l(-xi)^-1.
  static Matrix9 right_jacobian_inverse(const Tangent& xi) noexcept { return left_jacobian_inverse(Tangent(-xi)); }

  // ---- group operations -------------------------------------------------

  /// X^-1 = (R^T, -R^T p, -R^T v).
  SE23 inverse() const noexcept {
    const auto Rt = R_.matrix().transpose();
    return SE23(R_.inverse(), -(Rt * p_), -(Rt * v_));
  }
  /// X1 X2 = (R1 R2, R1 p2 + p1, R1 v2 + v1).
  SE23 operator*(const SE23& o) const noexcept {
    return SE23(R_ * o.R_, R_.matrix() * o.p_ + p_, R_.matrix() * o.v_ + v_);
  }
  SE23& operator*=(const SE23& o) noexcept { return *this = *this * o; }

  /// Action on a point: q_a = R q_b + p (X on (q, 1, 0)).
  Vector3 act(const Vector3& q) const noexcept { return R_.matrix() * q + p_; }
  Vector3 operator*(const Vector3& q) const noexcept { return act(q); }

  /// Ad_X = [[R, 0, [p] R], [0, R, [v] R], [0, 0, R]] (9x9), so that
  /// X [xi] X^-1 = [Ad_X xi].
  Matrix9 adjoint() const noexcept {
    const Matrix3& R = R_.matrix();
    Matrix3 PR, VR;
    for (int j = 0; j < 3; ++j) {
      PR.col(j) = p_.cross(R.col(j));
      VR.col(j) = v_.cross(R.col(j));
    }
    return blocks(R, PR, VR);
  }

  // ---- access and conversions -------------------------------------------

  const Rotation& rotation() const noexcept { return R_; }
  /// The position p (the column that acts on points, as SE3's translation).
  const Vector3& translation() const noexcept { return p_; }
  const Vector3& velocity() const noexcept { return v_; }

  /// X = [[R, p, v], [0, 1, 0], [0, 0, 1]] (5x5).
  Matrix5 matrix() const noexcept {
    Matrix5 X = Matrix5::Identity();
    X.template topLeftCorner<3, 3>() = R_.matrix();
    X.template block<3, 1>(0, 3) = p_;
    X.template block<3, 1>(0, 4) = v_;
    return X;
  }

  /// How far a 5x5 matrix is from an extended pose: the rotation defect of
  /// its top-left block (SO3::rotation_defect) or the largest deviation of
  /// its bottom rows from [[0, 1, 0], [0, 0, 1]], whichever is larger; +inf
  /// when an entry is not finite.
  static Scalar transform_defect(const Matrix5& M) noexcept {
    using std::abs;
    if (!detail::all_finite(M)) return Scalar(std::numeric_limits<Real>::infinity());
    Scalar d = Rotation::rotation_defect(M.template topLeftCorner<3, 3>());
    for (int i = 3; i < 5; ++i) {
      for (int j = 0; j < 5; ++j) {
        const Scalar e = abs(M(i, j) - Scalar(i == j ? 1 : 0));
        if (e > d) d = e;
      }
    }
    return d;
  }
  /// Checked construction: M itself if `transform_defect(M) <= tolerance`,
  /// otherwise nothing (default tolerance sqrt(eps), constants.hpp).
  static std::optional<SE23> from_matrix(
      const Matrix5& M, const Scalar& tolerance = Scalar(ThresholdsOf<Scalar>::rotation_tolerance)) noexcept {
    if (transform_defect(M) <= tolerance) return from_matrix_unchecked(M);
    return std::nullopt;
  }
  /// Unchecked construction from [[R, p, v], [*]]: for valid data; the bottom
  /// rows are not read.
  static SE23 from_matrix_unchecked(const Matrix5& M) noexcept {
    return SE23(Rotation::from_matrix_unchecked(M.template topLeftCorner<3, 3>()), M.template block<3, 1>(0, 3),
                M.template block<3, 1>(0, 4));
  }
  /// The nearest rotation to the top-left block (SO3::from_matrix_projected),
  /// the position and the velocity columns; the bottom rows are not read.
  static SE23 from_matrix_projected(const Matrix5& M) noexcept {
    return SE23(Rotation::from_matrix_projected(M.template topLeftCorner<3, 3>()), M.template block<3, 1>(0, 3),
                M.template block<3, 1>(0, 4));
  }

  /// The same extended pose with the nearest rotation (removes drift).
  SE23 normalized() const noexcept { return SE23(R_.normalized(), p_, v_); }

  template <typename NewScalar>
  SE23<NewScalar> cast() const noexcept {
    return SE23<NewScalar>(R_.template cast<NewScalar>(), p_.template cast<NewScalar>(), v_.template cast<NewScalar>());
  }

  /// Rotations within tol (absolute), positions and velocities within
  /// tol * max(1, |x|_max) (relative beyond unit scale). No `==`.
  bool is_approx(const SE23& other, const Real& tol) const noexcept {
    return R_.is_approx(other.R_, tol) && detail::approx_equal(p_, other.p_, tol) &&
           detail::approx_equal(v_, other.v_, tol);
  }

 private:
  /// [[A, 0, P], [0, A, V], [0, 0, A]] (9x9): the shape of ad, Ad and the Jacobians.
  static Matrix9 blocks(const Matrix3& A, const Matrix3& P, const Matrix3& V) noexcept {
    Matrix9 M = Matrix9::Zero();
    for (int k = 0; k < 3; ++k) M.template block<3, 3>(3 * k, 3 * k) = A;
    M.template block<3, 3>(0, 6) = P;
    M.template block<3, 3>(3, 6) = V;
    return M;
  }

  Rotation R_;
  Vector3 p_;
  Vector3 v_;
};

using SE23f = SE23<float>;
using SE23d = SE23<double>;

}  // namespace chasles
