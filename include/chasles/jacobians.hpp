// chasles: the Jacobians of exp of SO(3) and SE(3) as free functions, the
// Jacobians of the action on points, and SE(3)'s plus operators on a Twist.
// What every group shares (plus and minus, between, the Jacobians of log,
// inverse, compose, plus, minus, between and interpolate) is written once in
// lie_group.hpp; each group's Jacobians of exp are its static members
// (so3.hpp, se3.hpp, so2.hpp, se2.hpp, sim3.hpp, se23.hpp).
//
// Convention: right (local) perturbations everywhere, as manif and
// Pinocchio (lie_group.hpp). Tangent vectors are w (SO(3)) and xi = (v, w),
// linear part first (SE(3)).
//
// References: Sola, Deray and Atchuthan, "A micro Lie theory for state
// estimation in robotics", 2018, arXiv:1812.01537 ("Sola" below);
// Barfoot, "State Estimation for Robotics", 2017, sec. 7.1.
//
// Every function is noexcept, allocation-free and returns fixed-size Eigen
// types by value; Scalar may be float, double or an Eigen::AutoDiffScalar.
#pragma once

#include <Eigen/Core>

#include "chasles/lie_group.hpp"
#include "chasles/se2.hpp"
#include "chasles/se23.hpp"
#include "chasles/se3.hpp"
#include "chasles/sim3.hpp"
#include "chasles/so2.hpp"
#include "chasles/so3.hpp"
#include "chasles/twist.hpp"

namespace chasles {

template <typename Scalar>
using Matrix3Of = Eigen::Matrix<Scalar, 3, 3>;
template <typename Scalar>
using Matrix6Of = Eigen::Matrix<Scalar, 6, 6>;
template <typename Scalar>
using Vector3Of = Eigen::Matrix<Scalar, 3, 1>;
template <typename Scalar>
using Vector6Of = Eigen::Matrix<Scalar, 6, 1>;

// ---- the Jacobians of exp, by name ----------------------------------------

/// SO3::right_jacobian: exp(w + dw) = exp(w) exp(J_r(w) dw + o(dw)).
template <typename Scalar>
inline Matrix3Of<Scalar> so3_right_jacobian(const Vector3Of<Scalar>& w) noexcept {
  return SO3<Scalar>::right_jacobian(w);
}
/// SO3::left_jacobian: exp(w + dw) = exp(J_l(w) dw + o(dw)) exp(w).
template <typename Scalar>
inline Matrix3Of<Scalar> so3_left_jacobian(const Vector3Of<Scalar>& w) noexcept {
  return SO3<Scalar>::left_jacobian(w);
}
/// SO3::right_jacobian_inverse.
template <typename Scalar>
inline Matrix3Of<Scalar> so3_right_jacobian_inverse(const Vector3Of<Scalar>& w) noexcept {
  return SO3<Scalar>::right_jacobian_inverse(w);
}
/// SO3::left_jacobian_inverse.
template <typename Scalar>
inline Matrix3Of<Scalar> so3_left_jacobian_inverse(const Vector3Of<Scalar>& w) noexcept {
  return SO3<Scalar>::left_jacobian_inverse(w);
}
/// SE3::left_jacobian of xi = (v, w), any 6-vector expression.
template <typename Derived>
inline Matrix6Of<typename Derived::Scalar> se3_left_jacobian(const Eigen::MatrixBase<Derived>& xi) noexcept {
  return SE3<typename Derived::Scalar>::left_jacobian(xi);
}
/// SE3::right_jacobian.
template <typename Derived>
inline Matrix6Of<typename Derived::Scalar> se3_right_jacobian(const Eigen::MatrixBase<Derived>& xi) noexcept {
  return SE3<typename Derived::Scalar>::right_jacobian(xi);
}
/// SE3::left_jacobian_inverse.
template <typename Derived>
inline Matrix6Of<typename Derived::Scalar> se3_left_jacobian_inverse(const Eigen::MatrixBase<Derived>& xi) noexcept {
  return SE3<typename Derived::Scalar>::left_jacobian_inverse(xi);
}
/// SE3::right_jacobian_inverse.
template <typename Derived>
inline Matrix6Of<typename Derived::Scalar> se3_right_jacobian_inverse(const Eigen::MatrixBase<Derived>& xi) noexcept {
  return SE3<typename Derived::Scalar>::right_jacobian_inverse(xi);
}

// ---- SE(3) plus on a Twist ------------------------------------------------

/// g rplus xi = g exp(xi) for a Twist xi.
template <typename Scalar>
inline SE3<Scalar> rplus(const SE3<Scalar>& g, const Twist<Scalar>& xi) noexcept {
  return rplus(g, xi.vector());
}
/// xi lplus g = exp(xi) g for a Twist xi.
template <typename Scalar>
inline SE3<Scalar> lplus(const Twist<Scalar>& xi, const SE3<Scalar>& g) noexcept {
  return lplus(xi.vector(), g);
}

// ---- the action on points -------------------------------------------------

/// The two Jacobians of the action p_out = g p.
template <typename MatrixG>
struct ActJacobians {
  MatrixG group;  ///< d(g p) / dg (point size x DoF)
  Eigen::Matrix<typename MatrixG::Scalar, MatrixG::RowsAtCompileTime, MatrixG::RowsAtCompileTime>
      point;  ///< d(g p) / dp = R
};

/// SO(3): d(R p)/dR = -R [p], d(R p)/dp = R   (Sola app. B).
template <typename Scalar>
inline ActJacobians<Matrix3Of<Scalar>> act_jacobians(const SO3<Scalar>& g, const Vector3Of<Scalar>& p) noexcept {
  const Matrix3Of<Scalar>& R = g.matrix();
  return {Matrix3Of<Scalar>(-(R * SO3<Scalar>::hat(p))), R};
}

/// SE(3): d(g p)/dg = [R, -R [p]] (3x6, columns (v, w)), d(g p)/dp = R   (Sola app. D).
template <typename Scalar>
inline ActJacobians<Eigen::Matrix<Scalar, 3, 6>> act_jacobians(const SE3<Scalar>& g,
                                                               const Vector3Of<Scalar>& p) noexcept {
  const Matrix3Of<Scalar>& R = g.rotation().matrix();
  Eigen::Matrix<Scalar, 3, 6> Jg;
  Jg.template leftCols<3>() = R;
  Jg.template rightCols<3>() = -(R * SO3<Scalar>::hat(p));
  return {Jg, R};
}

/// SO(2): d(R p)/dtheta = R J p (J the rotation by pi/2), d(R p)/dp = R.
template <typename Scalar>
inline ActJacobians<Eigen::Matrix<Scalar, 2, 1>> act_jacobians(const SO2<Scalar>& g,
                                                               const Eigen::Matrix<Scalar, 2, 1>& p) noexcept {
  const Eigen::Matrix<Scalar, 2, 2> R = g.matrix();
  return {Eigen::Matrix<Scalar, 2, 1>(R * Eigen::Matrix<Scalar, 2, 1>(-p[1], p[0])), R};
}

/// SE(2): d(g p)/dg = [R, R J p] (2x3, columns (vx, vy, w)), d(g p)/dp = R.
template <typename Scalar>
inline ActJacobians<Eigen::Matrix<Scalar, 2, 3>> act_jacobians(const SE2<Scalar>& g,
                                                               const Eigen::Matrix<Scalar, 2, 1>& p) noexcept {
  const Eigen::Matrix<Scalar, 2, 2> R = g.rotation().matrix();
  Eigen::Matrix<Scalar, 2, 3> Jg;
  Jg.template leftCols<2>() = R;
  Jg.col(2) = R * Eigen::Matrix<Scalar, 2, 1>(-p[1], p[0]);
  return {Jg, R};
}

/// Sim(3): d(g p)/dg = [s R, -s R [p], s R p] (3x7, columns (v, w, sigma)),
/// d(g p)/dp = s R (g exp(xi) p = g (p + v + w x p + sigma p) to first order).
template <typename Scalar>
inline ActJacobians<Eigen::Matrix<Scalar, 3, 7>> act_jacobians(const Sim3<Scalar>& g,
                                                               const Vector3Of<Scalar>& p) noexcept {
  const Matrix3Of<Scalar> sR = g.scale() * g.rotation().matrix();
  Eigen::Matrix<Scalar, 3, 7> Jg;
  Jg.template leftCols<3>() = sR;
  Jg.template block<3, 3>(0, 3) = -(sR * SO3<Scalar>::hat(p));
  Jg.col(6) = sR * p;
  return {Jg, sR};
}

/// SE_2(3): d(X p)/dX = [R, 0, -R [p]] (3x9, columns (rho, nu, w)),
/// d(X p)/dp = R (X exp(xi) p = X (p + rho + w x p) to first order; nu moves
/// no point).
template <typename Scalar>
inline ActJacobians<Eigen::Matrix<Scalar, 3, 9>> act_jacobians(const SE23<Scalar>& g,
                                                               const Vector3Of<Scalar>& p) noexcept {
  const Matrix3Of<Scalar>& R = g.rotation().matrix();
  Eigen::Matrix<Scalar, 3, 9> Jg;
  Jg.template leftCols<3>() = R;
  Jg.template block<3, 3>(0, 3).setZero();
  Jg.template rightCols<3>() = -(R * SO3<Scalar>::hat(p));
  return {Jg, R};
}

}  // namespace chasles
