// chasles: Jacobians of SO(3) and SE(3), and the plus / minus operators.
//
// Convention: right (local) perturbations everywhere, as manif and
// Pinocchio. For f: G -> H the Jacobian J is defined by
//   f(X exp(dx)) = f(X) exp(J dx + o(dx)),   i.e.  J = d(f(X rplus dx) rminus f(X)) / d(dx).
// Tangent vectors are w (SO(3)) and xi = (v, w), linear part first (SE(3)).
//
// References: Sola, Deray and Atchuthan, "A micro Lie theory for state
// estimation in robotics", 2018, arXiv:1812.01537 ("Sola" below: section IV
// for the Jacobians of the operations, appendix B for SO(3), appendix D and
// eq. 180 for SE(3)); Barfoot, "State Estimation for Robotics", 2017, sec. 7.1.
//
// Every function is noexcept, allocation-free and returns fixed-size Eigen
// types by value; Scalar may be float, double or an Eigen::AutoDiffScalar.
// Every coefficient has a Taylor branch below Thresholds::taylor_theta2
// (detail/series.hpp), so there is no 0/0 anywhere and autodiff derivatives
// are exact at 0.
#pragma once

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/detail/arguments.hpp"
#include "chasles/detail/rodrigues.hpp"
#include "chasles/detail/series.hpp"
#include "chasles/se3.hpp"
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

namespace detail {

/// Q(v, w), the upper-right block of the SE(3) left Jacobian (Sola eq. 180,
/// Barfoot eq. 7.86), with V = [v], W = [w]:
///   Q = 1/2 V + C (W V + V W + W V W) + q3 (W W V + V W W - 3 W V W)
///         + q4 (W V W W + W W V W)
/// (C, q3, q4 in detail/series.hpp; Sola writes q3 as -(1 - t/2 - cos)/t^2,
/// the same number).
template <typename Scalar>
inline Matrix3Of<Scalar> se3_q(const Vector3Of<Scalar>& v, const Vector3Of<Scalar>& w) noexcept {
  const QCoefficients<Scalar> k = q_coefficients(Scalar(w.squaredNorm()));
  const Matrix3Of<Scalar> V = SO3<Scalar>::hat(v);
  const Matrix3Of<Scalar> W = SO3<Scalar>::hat(w);
  const Matrix3Of<Scalar> WV = W * V;
  const Matrix3Of<Scalar> VW = V * W;
  const Matrix3Of<Scalar> WVW = WV * W;
  const Matrix3Of<Scalar> WWV = W * WV;
  const Matrix3Of<Scalar> VWW = VW * W;
  const Matrix3Of<Scalar> WVWW = WVW * W;
  const Matrix3Of<Scalar> WWVW = W * WVW;
  return Scalar(0.5) * V + k.c * (WV + VW + WVW) + k.q3 * (WWV + VWW - Scalar(3) * WVW) + k.q4 * (WVWW + WWVW);
}

/// [[A, B], [0, A]] (6x6).
template <typename Scalar>
inline Matrix6Of<Scalar> upper_block_triangular(const Matrix3Of<Scalar>& A, const Matrix3Of<Scalar>& B) noexcept {
  Matrix6Of<Scalar> J;
  J.template topLeftCorner<3, 3>() = A;
  J.template topRightCorner<3, 3>() = B;
  J.template bottomLeftCorner<3, 3>().setZero();
  J.template bottomRightCorner<3, 3>() = A;
  return J;
}

}  // namespace detail

// ---- SO(3) Jacobians ------------------------------------------------------

/// Right Jacobian of SO(3): exp(w + dw) = exp(w) exp(J_r(w) dw + o(dw)).
///   J_r(w) = I - B [w] + C [w]^2   (Sola app. B; B, C in detail/series.hpp)
template <typename Scalar>
inline Matrix3Of<Scalar> so3_right_jacobian(const Vector3Of<Scalar>& w) noexcept {
  const auto k = detail::exp_coefficients(Scalar(w.squaredNorm()));
  return detail::rodrigues<Scalar>(w, Scalar(-k.b), k.c);
}

/// Left Jacobian of SO(3): exp(w + dw) = exp(J_l(w) dw + o(dw)) exp(w).
///   J_l(w) = I + B [w] + C [w]^2 = J_r(-w) = V(w)   (Sola app. B)
template <typename Scalar>
inline Matrix3Of<Scalar> so3_left_jacobian(const Vector3Of<Scalar>& w) noexcept {
  const auto k = detail::exp_coefficients(Scalar(w.squaredNorm()));
  return detail::rodrigues<Scalar>(w, k.b, k.c);
}

/// Inverse of the right Jacobian of SO(3):
///   J_r(w)^-1 = I + 1/2 [w] + D [w]^2,  D = (1 - (theta/2) cot(theta/2)) / theta^2
/// Finite for |w| < 2 pi, in particular at and near pi.
template <typename Scalar>
inline Matrix3Of<Scalar> so3_right_jacobian_inverse(const Vector3Of<Scalar>& w) noexcept {
  const Scalar d = detail::jacobian_inverse_coefficient(Scalar(w.squaredNorm()));
  return detail::rodrigues<Scalar>(w, Scalar(0.5), d);
}

/// Inverse of the left Jacobian of SO(3):
///   J_l(w)^-1 = I - 1/2 [w] + D [w]^2 = V(w)^-1
template <typename Scalar>
inline Matrix3Of<Scalar> so3_left_jacobian_inverse(const Vector3Of<Scalar>& w) noexcept {
  const Scalar d = detail::jacobian_inverse_coefficient(Scalar(w.squaredNorm()));
  return detail::rodrigues<Scalar>(w, Scalar(-0.5), d);
}

// ---- SE(3) Jacobians ------------------------------------------------------

/// Left Jacobian of SE(3), xi = (v, w): exp(xi + dxi) = exp(J_l dxi + o) exp(xi).
///   J_l(xi) = [[J_l(w), Q(v, w)], [0, J_l(w)]]   (Sola eq. 180; our (v, w) is Sola's (rho, theta))
template <typename Derived>
inline Matrix6Of<typename Derived::Scalar> se3_left_jacobian(const Eigen::MatrixBase<Derived>& xi) noexcept {
  using Scalar = typename Derived::Scalar;
  static_assert(Derived::IsVectorAtCompileTime && Derived::SizeAtCompileTime == 6, "xi is a 6-vector (v, w)");
  const Vector3Of<Scalar> v = xi.template head<3>();
  const Vector3Of<Scalar> w = xi.template tail<3>();
  return detail::upper_block_triangular<Scalar>(so3_left_jacobian<Scalar>(w), detail::se3_q<Scalar>(v, w));
}

/// Right Jacobian of SE(3): exp(xi + dxi) = exp(xi) exp(J_r dxi + o(dxi)).
///   J_r(xi) = J_l(-xi) = [[J_r(w), Q(-v, -w)], [0, J_r(w)]]   (Sola app. D)
template <typename Derived>
inline Matrix6Of<typename Derived::Scalar> se3_right_jacobian(const Eigen::MatrixBase<Derived>& xi) noexcept {
  using Scalar = typename Derived::Scalar;
  static_assert(Derived::IsVectorAtCompileTime && Derived::SizeAtCompileTime == 6, "xi is a 6-vector (v, w)");
  const Vector3Of<Scalar> v = -xi.template head<3>();
  const Vector3Of<Scalar> w = -xi.template tail<3>();
  return detail::upper_block_triangular<Scalar>(so3_left_jacobian<Scalar>(w), detail::se3_q<Scalar>(v, w));
}

/// Inverse of the left Jacobian of SE(3), by the block formula
///   J_l(xi)^-1 = [[J_l^-1, -J_l^-1 Q J_l^-1], [0, J_l^-1]],  J_l^-1 = J_l(w)^-1, Q = Q(v, w).
template <typename Derived>
inline Matrix6Of<typename Derived::Scalar> se3_left_jacobian_inverse(const Eigen::MatrixBase<Derived>& xi) noexcept {
  using Scalar = typename Derived::Scalar;
  static_assert(Derived::IsVectorAtCompileTime && Derived::SizeAtCompileTime == 6, "xi is a 6-vector (v, w)");
  const Vector3Of<Scalar> v = xi.template head<3>();
  const Vector3Of<Scalar> w = xi.template tail<3>();
  const Matrix3Of<Scalar> Ji = so3_left_jacobian_inverse<Scalar>(w);
  const Matrix3Of<Scalar> QJi = detail::se3_q<Scalar>(v, w) * Ji;
  return detail::upper_block_triangular<Scalar>(Ji, Matrix3Of<Scalar>(-(Ji * QJi)));
}

/// Inverse of the right Jacobian of SE(3): J_r(xi)^-1 = J_l(-xi)^-1.
template <typename Derived>
inline Matrix6Of<typename Derived::Scalar> se3_right_jacobian_inverse(const Eigen::MatrixBase<Derived>& xi) noexcept {
  using Scalar = typename Derived::Scalar;
  static_assert(Derived::IsVectorAtCompileTime && Derived::SizeAtCompileTime == 6, "xi is a 6-vector (v, w)");
  return se3_left_jacobian_inverse(Vector6Of<Scalar>(-xi));
}

// ---- plus and minus -------------------------------------------------------
//
// Argument order: rplus(g, xi) = g exp(xi) and rminus(g, h) = log(h^-1 g),
// so that rplus(h, rminus(g, h)) == g: "g minus h", as manif's
// g.rminus(h) = log(h^-1 g). (jaxlie's rminus(a, b) = log(a^-1 b) takes the
// other order.) The left versions: lplus(xi, g) = exp(xi) g and
// lminus(g, h) = log(g h^-1), so that lplus(lminus(g, h), h) == g.
// (Sola section III.)

// Beside a vector of the group's own type, the tangent vector of rplus and
// lplus may be any Eigen vector expression of the right size (0.1 * dx, a
// Map, a segment), of any scalar type that converts to the group's (a double
// expression for a float group), or a Twist for SE(3); it is converted
// explicitly (detail/arguments.hpp).

/// g rplus xi = g exp(xi).
template <typename Scalar>
inline SO3<Scalar> rplus(const SO3<Scalar>& g, const Vector3Of<Scalar>& xi) noexcept {
  return g * SO3<Scalar>::exp(xi);
}
template <typename Scalar, typename Derived>
inline SO3<Scalar> rplus(const SO3<Scalar>& g, const Eigen::MatrixBase<Derived>& xi) noexcept {
  return rplus(g, detail::tangent_of<Scalar, 3>(xi));
}
/// g rplus xi = g exp(xi), xi = (v, w).
template <typename Scalar>
inline SE3<Scalar> rplus(const SE3<Scalar>& g, const Vector6Of<Scalar>& xi) noexcept {
  return g * SE3<Scalar>::exp(xi);
}
template <typename Scalar, typename Derived>
inline SE3<Scalar> rplus(const SE3<Scalar>& g, const Eigen::MatrixBase<Derived>& xi) noexcept {
  return rplus(g, detail::tangent_of<Scalar, 6>(xi));
}
template <typename Scalar>
inline SE3<Scalar> rplus(const SE3<Scalar>& g, const Twist<Scalar>& xi) noexcept {
  return rplus(g, xi.vector());
}

/// g rminus h = log(h^-1 g): the xi with h exp(xi) = g.
template <typename Scalar>
inline Vector3Of<Scalar> rminus(const SO3<Scalar>& g, const SO3<Scalar>& h) noexcept {
  return (h.inverse() * g).log();
}
/// g rminus h = log(h^-1 g) = (v, w): the xi with h exp(xi) = g.
template <typename Scalar>
inline Vector6Of<Scalar> rminus(const SE3<Scalar>& g, const SE3<Scalar>& h) noexcept {
  return (h.inverse() * g).log();
}

/// xi lplus g = exp(xi) g.
template <typename Scalar>
inline SO3<Scalar> lplus(const Vector3Of<Scalar>& xi, const SO3<Scalar>& g) noexcept {
  return SO3<Scalar>::exp(xi) * g;
}
template <typename Derived, typename Scalar>
inline SO3<Scalar> lplus(const Eigen::MatrixBase<Derived>& xi, const SO3<Scalar>& g) noexcept {
  return lplus(detail::tangent_of<Scalar, 3>(xi), g);
}
/// xi lplus g = exp(xi) g, xi = (v, w).
template <typename Scalar>
inline SE3<Scalar> lplus(const Vector6Of<Scalar>& xi, const SE3<Scalar>& g) noexcept {
  return SE3<Scalar>::exp(xi) * g;
}
template <typename Derived, typename Scalar>
inline SE3<Scalar> lplus(const Eigen::MatrixBase<Derived>& xi, const SE3<Scalar>& g) noexcept {
  return lplus(detail::tangent_of<Scalar, 6>(xi), g);
}
template <typename Scalar>
inline SE3<Scalar> lplus(const Twist<Scalar>& xi, const SE3<Scalar>& g) noexcept {
  return lplus(xi.vector(), g);
}

/// g lminus h = log(g h^-1): the xi with exp(xi) h = g.
template <typename Scalar>
inline Vector3Of<Scalar> lminus(const SO3<Scalar>& g, const SO3<Scalar>& h) noexcept {
  return (g * h.inverse()).log();
}
/// g lminus h = log(g h^-1) = (v, w): the xi with exp(xi) h = g.
template <typename Scalar>
inline Vector6Of<Scalar> lminus(const SE3<Scalar>& g, const SE3<Scalar>& h) noexcept {
  return (g * h.inverse()).log();
}

// ---- Jacobians of the group operations (right convention) ----------------

/// d log(g) / dg = J_r(log g)^-1   (Sola section IV).
template <typename Scalar>
inline Matrix3Of<Scalar> log_jacobian(const SO3<Scalar>& g) noexcept {
  return so3_right_jacobian_inverse<Scalar>(g.log());
}
template <typename Scalar>
inline Matrix6Of<Scalar> log_jacobian(const SE3<Scalar>& g) noexcept {
  return se3_right_jacobian_inverse(g.log());
}

/// d(g^-1) / dg = -Ad_g   (Sola section IV).
template <typename Scalar>
inline Matrix3Of<Scalar> inverse_jacobian(const SO3<Scalar>& g) noexcept {
  return -g.adjoint();
}
template <typename Scalar>
inline Matrix6Of<Scalar> inverse_jacobian(const SE3<Scalar>& g) noexcept {
  return -g.adjoint();
}

/// The two Jacobians of a composition a * b.
template <typename Matrix>
struct ComposeJacobians {
  Matrix lhs;  ///< d(a b) / da = Ad_{b^-1}
  Matrix rhs;  ///< d(a b) / db = I
};

template <typename Scalar>
inline ComposeJacobians<Matrix3Of<Scalar>> compose_jacobians(const SO3<Scalar>& /*a*/, const SO3<Scalar>& b) noexcept {
  return {b.inverse().adjoint(), Matrix3Of<Scalar>::Identity()};
}
template <typename Scalar>
inline ComposeJacobians<Matrix6Of<Scalar>> compose_jacobians(const SE3<Scalar>& /*a*/, const SE3<Scalar>& b) noexcept {
  return {b.inverse().adjoint(), Matrix6Of<Scalar>::Identity()};
}

/// The two Jacobians of the action p_out = g p.
template <typename MatrixG>
struct ActJacobians {
  MatrixG group;                     ///< d(g p) / dg (3 x DoF)
  Eigen::Matrix<typename MatrixG::Scalar, 3, 3> point;  ///< d(g p) / dp = R
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

/// The two Jacobians of a function of two arguments f(x, y), right-local in
/// both: f(x (+) dx, y (+) dy) = f(x, y) (+) (J_x dx + J_y dy + o(dx, dy)),
/// where (+) is rplus on a group and + on a tangent vector.
template <typename Matrix>
struct BinaryJacobians {
  Matrix lhs;  ///< d f / d(first argument)
  Matrix rhs;  ///< d f / d(second argument)
};

/// rplus(g, xi) = g exp(xi):  J_g = Ad_{exp(xi)}^-1 = Ad_{exp(-xi)},  J_xi = J_r(xi)
/// (Sola section IV: g exp(dg) exp(xi) = g exp(xi) exp(Ad_{exp(-xi)} dg)).
template <typename Scalar>
inline BinaryJacobians<Matrix3Of<Scalar>> rplus_jacobians(const SO3<Scalar>& /*g*/,
                                                          const Vector3Of<Scalar>& xi) noexcept {
  return {SO3<Scalar>::exp(xi).inverse().adjoint(), so3_right_jacobian<Scalar>(xi)};
}
template <typename Scalar>
inline BinaryJacobians<Matrix6Of<Scalar>> rplus_jacobians(const SE3<Scalar>& /*g*/,
                                                          const Vector6Of<Scalar>& xi) noexcept {
  return {SE3<Scalar>::exp(xi).inverse().adjoint(), se3_right_jacobian(xi)};
}

/// rminus(g, h) = log(h^-1 g) = xi:  J_g = J_r(xi)^-1,  J_h = -J_l(xi)^-1
/// (Sola section IV; the Jacobians of the branch log returns, finite for
/// |w| < 2 pi, so at and near pi too).
template <typename Scalar>
inline BinaryJacobians<Matrix3Of<Scalar>> rminus_jacobians(const SO3<Scalar>& g, const SO3<Scalar>& h) noexcept {
  const Vector3Of<Scalar> xi = rminus(g, h);
  return {so3_right_jacobian_inverse<Scalar>(xi), Matrix3Of<Scalar>(-so3_left_jacobian_inverse<Scalar>(xi))};
}
template <typename Scalar>
inline BinaryJacobians<Matrix6Of<Scalar>> rminus_jacobians(const SE3<Scalar>& g, const SE3<Scalar>& h) noexcept {
  const Vector6Of<Scalar> xi = rminus(g, h);
  return {se3_right_jacobian_inverse(xi), Matrix6Of<Scalar>(-se3_left_jacobian_inverse(xi))};
}

/// lplus(xi, g) = exp(xi) g:  J_xi = Ad_{g^-1} J_r(xi),  J_g = I.
/// exp(xi + dxi) g = exp(J_l dxi) exp(xi) g = exp(xi) g exp(Ad_{(exp(xi) g)^-1} J_l dxi),
/// and Ad_{g^-1} Ad_{exp(-xi)} J_l(xi) = Ad_{g^-1} J_r(xi) (J_r = Ad_{exp(-xi)} J_l, Sola section III).
template <typename Scalar>
inline BinaryJacobians<Matrix3Of<Scalar>> lplus_jacobians(const Vector3Of<Scalar>& xi, const SO3<Scalar>& g) noexcept {
  return {Matrix3Of<Scalar>(g.inverse().adjoint() * so3_right_jacobian<Scalar>(xi)), Matrix3Of<Scalar>::Identity()};
}
template <typename Scalar>
inline BinaryJacobians<Matrix6Of<Scalar>> lplus_jacobians(const Vector6Of<Scalar>& xi, const SE3<Scalar>& g) noexcept {
  return {Matrix6Of<Scalar>(g.inverse().adjoint() * se3_right_jacobian(xi)), Matrix6Of<Scalar>::Identity()};
}

/// lminus(g, h) = log(g h^-1) = xi:  J_g = J_r(xi)^-1 Ad_h,  J_h = -J_r(xi)^-1 Ad_h.
/// g exp(dg) h^-1 = exp(xi) exp(Ad_h dg), so d xi = J_r(xi)^-1 Ad_h dg; and
/// g (h exp(dh))^-1 = exp(xi) exp(-Ad_h dh)   (Sola section IV).
template <typename Scalar>
inline BinaryJacobians<Matrix3Of<Scalar>> lminus_jacobians(const SO3<Scalar>& g, const SO3<Scalar>& h) noexcept {
  const Matrix3Of<Scalar> J = so3_right_jacobian_inverse<Scalar>(lminus(g, h)) * h.adjoint();
  return {J, Matrix3Of<Scalar>(-J)};
}
template <typename Scalar>
inline BinaryJacobians<Matrix6Of<Scalar>> lminus_jacobians(const SE3<Scalar>& g, const SE3<Scalar>& h) noexcept {
  const Matrix6Of<Scalar> J = se3_right_jacobian_inverse(lminus(g, h)) * h.adjoint();
  return {J, Matrix6Of<Scalar>(-J)};
}

/// between(a, b) = a^-1 b, the motion from a to b.
template <typename Scalar>
inline SO3<Scalar> between(const SO3<Scalar>& a, const SO3<Scalar>& b) noexcept {
  return a.inverse() * b;
}
template <typename Scalar>
inline SE3<Scalar> between(const SE3<Scalar>& a, const SE3<Scalar>& b) noexcept {
  return a.inverse() * b;
}

/// between(a, b) = a^-1 b:  J_a = -Ad_{b^-1 a},  J_b = I
/// ((a exp(da))^-1 b = exp(-da) a^-1 b = a^-1 b exp(-Ad_{b^-1 a} da); Sola section IV, manif's between).
template <typename Scalar>
inline BinaryJacobians<Matrix3Of<Scalar>> between_jacobians(const SO3<Scalar>& a, const SO3<Scalar>& b) noexcept {
  return {Matrix3Of<Scalar>(-(b.inverse() * a).adjoint()), Matrix3Of<Scalar>::Identity()};
}
template <typename Scalar>
inline BinaryJacobians<Matrix6Of<Scalar>> between_jacobians(const SE3<Scalar>& a, const SE3<Scalar>& b) noexcept {
  return {Matrix6Of<Scalar>(-(b.inverse() * a).adjoint()), Matrix6Of<Scalar>::Identity()};
}

/// d interpolate(a, b, t) / dt in the right-local convention:
///   a exp((t + dt) xi) = a exp(t xi) exp(J_r(t xi) xi dt),  xi = log(a^-1 b) = b rminus a,
/// and J_r(t xi) xi = xi exactly (ad_xi xi = 0: every power of [t xi] beyond
/// the first annihilates xi), so the rate is the constant tangent xi.
template <typename Scalar>
inline Vector3Of<Scalar> interpolate_jacobian_t(const SO3<Scalar>& a, const SO3<Scalar>& b,
                                                const Scalar& /*t*/) noexcept {
  return rminus(b, a);
}
template <typename Scalar>
inline Vector6Of<Scalar> interpolate_jacobian_t(const SE3<Scalar>& a, const SE3<Scalar>& b,
                                                const Scalar& /*t*/) noexcept {
  return rminus(b, a);
}
/// (t of another arithmetic type, as for interpolate.)
template <typename Scalar, typename T, detail::EnableIfOtherArithmetic<Scalar, T> = 0>
inline Vector3Of<Scalar> interpolate_jacobian_t(const SO3<Scalar>& a, const SO3<Scalar>& b, const T& /*t*/) noexcept {
  return rminus(b, a);
}
template <typename Scalar, typename T, detail::EnableIfOtherArithmetic<Scalar, T> = 0>
inline Vector6Of<Scalar> interpolate_jacobian_t(const SE3<Scalar>& a, const SE3<Scalar>& b, const T& /*t*/) noexcept {
  return rminus(b, a);
}

}  // namespace chasles
