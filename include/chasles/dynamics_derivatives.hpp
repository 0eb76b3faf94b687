// chasles: analytic partial derivatives of the dynamics of serial chains:
// of inverse dynamics with respect to q and qd (with respect to qdd it is
// M(q)), of forward dynamics with respect to q, qd and tau, and the inverse
// of the mass matrix. The recursion of dynamics.hpp in the base frame,
// differentiated in closed form (the base-frame approach of J. Carpentier
// and N. Mansard, "Analytical Derivatives of Rigid Body Dynamics
// Algorithms", RSS 2018, written here for a serial chain of screws).
#pragma once

#include <array>
#include <cstddef>

#include <Eigen/Core>

#include "chasles/detail/assert.hpp"
#include "chasles/dynamics.hpp"
#include "chasles/kinematics.hpp"
#include "chasles/twist.hpp"
#include "chasles/wrench.hpp"

namespace chasles {

/// d tau / d q and d tau / d qd of inverse_dynamics (n x n each; d tau /
/// d qdd is M(q), mass_matrix).
template <typename MassMatrix>
struct InverseDynamicsDerivatives {
  MassMatrix dtau_dq;
  MassMatrix dtau_dqd;
};

/// d qdd / d q, d qdd / d qd and d qdd / d tau = M(q)^-1 of forward_dynamics,
/// with its status (all NaN unless ok, as forward_dynamics' accelerations).
template <typename MassMatrix>
struct ForwardDynamicsDerivatives {
  MassMatrix dqdd_dq;
  MassMatrix dqdd_dqd;
  MassMatrix dqdd_dtau;
  DynamicsStatus status;
  /// The joint of the failed pivot (-1 when ok), as ForwardDynamicsResult.
  Eigen::Index joint;
  explicit operator bool() const noexcept { return status == DynamicsStatus::ok; }
};

/// M(q)^-1 with the status of its Cholesky factorization (all NaN unless ok).
template <typename MassMatrix>
struct MassMatrixInverse {
  MassMatrix inverse;
  DynamicsStatus status;
  Eigen::Index joint;
  explicit operator bool() const noexcept { return status == DynamicsStatus::ok; }
};

// The derivatives, in the notation of dynamics.hpp (base frame; twists
// (v, w), wrenches (f, tau)); x is ad (m x y = ad_m y = (w x v' + v x w',
// w x w')) and x* its dual (m x* f = -ad_m^T f). Take d/dq_j: the links
// k >= j turn rigidly about S_j(q), so each base-frame quantity they carry
// moves as X -> S_j x X (a motion) or S_j x* X (a force; an inertia
// S_j x* G - G S_j x), except the part of the twists and accelerations that
// links before j give them, which stays put. From V_k = sum_{l<=k} S_l qd_l
// and A_k = A_0 + sum_{l<=k} (S_l qdd_l + V_l x S_l qd_l), for k >= j:
//
//   dV_k/dq_j  = S_j x (V_k - V_j)
//   dA_k/dq_j  = S_j x (A_k - A_j) - a_j x (V_k - V_j),    a_j = S_j x V_j
//   dV_k/dqd_j = S_j,   dA_k/dqd_j = S_j x V_k - 2 a_j
//
// (and 0 for k < j). With f_k = G_k A_k + V_k x* G_k V_k and the sums from
// the tip, I^c_i = sum_{k>=i} G_k, h^c_i = sum G_k V_k, F^c_i = sum f_k +
// F_tip (the tool's wrench, in the base frame), B^c_i = sum (V_k x* G_k -
// G_k V_k x) (= d/dt I^c_i), tau_i = S_i . F_i gives, with
// u_j = S_j x A_j - a_j x V_j:
//
//   i <= j:  dtau_i/dq_j  = S_i . (S_j x* F^c_j - I^c_j u_j - a_j x* h^c_j - B^c_j a_j)
//            dtau_i/dqd_j = S_i . (B^c_j S_j - 2 I^c_j a_j + S_j x* h^c_j)
//   i > j:   dtau_i/dq_j  = -Y_i . u_j + a_j . Z_i
//            dtau_i/dqd_j = -S_j . Z_i - 2 Y_i . a_j
//   with Y_i = I^c_i S_i, Z_i = S_i x* h^c_i - B^c_i^T S_i
//
// (for i > j, S_i moves too: (S_j x S_i) . F^c_i cancels S_i . S_j x* F^c_i,
// the pairing of a motion and a force being invariant). O(n) 6 x 6 work and
// n^2 dot products of 6-vectors.

namespace detail {

/// The derivatives of the comment above at (q, qd, qdd), q's pass given.
template <typename ChainT, typename Qd, typename Qdd>
InverseDynamicsDerivatives<typename ChainT::MassMatrix> newton_euler_derivatives(
    const ChainT& chain, const DynamicsPass<ChainT>& pass, const Eigen::MatrixBase<Qd>& qd,
    const Eigen::MatrixBase<Qdd>& qdd, const Wrench<typename ChainT::Scalar>& tip) noexcept {
  using Scalar = typename ChainT::Scalar;
  using Vector6 = Eigen::Matrix<Scalar, 6, 1>;
  using Matrix6 = Eigen::Matrix<Scalar, 6, 6>;
  constexpr auto Max = static_cast<std::size_t>(ChainT::MaxJointsAtCompileTime);
  const Eigen::Index n = chain.n_joints();
  std::array<Vector6, Max> V, A, a, u, hc, Fc;
  std::array<Matrix6, Max> Ic, Bc;
  Vector6 v = Vector6::Zero(), acc = Vector6::Zero();
  acc.template head<3>() = -chain.gravity();
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vector6 S = pass.S.col(i);
    v += S * qd(i);
    acc += S * qdd(i) + motion_cross<Scalar>(v, S) * qd(i);
    V[k] = v;
    A[k] = acc;
    a[k] = motion_cross<Scalar>(S, v);
    u[k] = motion_cross<Scalar>(S, acc) - motion_cross<Scalar>(a[k], v);
  }
  Matrix6 I_sum = Matrix6::Zero(), B_sum = Matrix6::Zero();
  Vector6 h_sum = Vector6::Zero(), F_sum = pass.tool.act(tip).vector();
  for (Eigen::Index i = n - 1; i >= 0; --i) {
    const auto k = static_cast<std::size_t>(i);
    const Matrix6 G = pass.I[k].matrix();
    const Vector6 h = G * V[k];
    const Matrix6 X = Twist<Scalar>(V[k]).ad().transpose() * G;
    I_sum += G;
    B_sum -= X + X.transpose();  // V x* G - G V x = -ad^T G - G ad = -(X + X^T), G symmetric
    h_sum += h;
    F_sum += G * A[k] + force_cross<Scalar>(V[k], h);
    Ic[k] = I_sum;
    Bc[k] = B_sum;
    hc[k] = h_sum;
    Fc[k] = F_sum;
  }
  InverseDynamicsDerivatives<typename ChainT::MassMatrix> d{typename ChainT::MassMatrix(n, n),
                                                            typename ChainT::MassMatrix(n, n)};
  for (Eigen::Index j = 0; j < n; ++j) {
    const auto k = static_cast<std::size_t>(j);
    const Vector6 S = pass.S.col(j);
    const Vector6 P = force_cross<Scalar>(S, Fc[k]) - Ic[k] * u[k] - force_cross<Scalar>(a[k], hc[k]) - Bc[k] * a[k];
    const Vector6 Qv = Bc[k] * S - Scalar(2) * (Ic[k] * a[k]) + force_cross<Scalar>(S, hc[k]);
    for (Eigen::Index i = 0; i <= j; ++i) {
      d.dtau_dq(i, j) = pass.S.col(i).dot(P);
      d.dtau_dqd(i, j) = pass.S.col(i).dot(Qv);
    }
  }
  for (Eigen::Index i = 1; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vector6 S = pass.S.col(i);
    const Vector6 Y = Ic[k] * S;
    const Vector6 Z = force_cross<Scalar>(S, hc[k]) - Bc[k].transpose() * S;
    for (Eigen::Index j = 0; j < i; ++j) {
      const auto l = static_cast<std::size_t>(j);
      d.dtau_dq(i, j) = a[l].dot(Z) - Y.dot(u[l]);
      d.dtau_dqd(i, j) = -pass.S.col(j).dot(Z) - Scalar(2) * Y.dot(a[l]);
    }
  }
  return d;
}

/// M^-1 = L^-T L^-1 for M = L L^T (L in the lower triangle of `L`): X =
/// L^-1 by forward substitution on the columns of the identity (lower
/// triangular), then the upper triangle of X^T X, mirrored: about n^3 / 3
/// products, coefficient by coefficient (no workspace).
template <typename MassMatrix>
MassMatrix cholesky_inverse(const MassMatrix& L) noexcept {
  using Scalar = typename MassMatrix::Scalar;
  const Eigen::Index n = L.rows();
  MassMatrix X = MassMatrix::Zero(n, n);
  for (Eigen::Index j = 0; j < n; ++j) {
    X(j, j) = Scalar(1) / L(j, j);
    for (Eigen::Index i = j + 1; i < n; ++i) {
      Scalar sum(0);
      for (Eigen::Index k = j; k < i; ++k) sum += L(i, k) * X(k, j);
      X(i, j) = -sum / L(i, i);
    }
  }
  MassMatrix inverse(n, n);
  for (Eigen::Index j = 0; j < n; ++j)
    for (Eigen::Index i = 0; i <= j; ++i) {
      Scalar sum(0);
      for (Eigen::Index k = j; k < n; ++k) sum += X(k, i) * X(k, j);
      inverse(i, j) = inverse(j, i) = sum;
    }
  return inverse;
}

}  // namespace detail

/// d tau / d q and d tau / d qd of inverse_dynamics(chain, q, qd, qdd,
/// tip_wrench) at (q, qd, qdd), analytic (the comment above; d tau / d qdd
/// = M(q)). For any joint screw (revolute, prismatic, helical, of any norm).
/// noexcept, allocation-free, O(n^2).
template <typename Scalar, int N, int MaxN, typename Q, typename Qd, typename Qdd>
InverseDynamicsDerivatives<typename Chain<Scalar, N, MaxN>::MassMatrix> inverse_dynamics_derivatives(
    const Chain<Scalar, N, MaxN>& chain, const Eigen::MatrixBase<Q>& q, const Eigen::MatrixBase<Qd>& qd,
    const Eigen::MatrixBase<Qdd>& qdd, const Wrench<Scalar>& tip_wrench = Wrench<Scalar>()) noexcept {
  detail::check_joint_vector(chain, q);
  detail::check_joint_vector(chain, qd);
  detail::check_joint_vector(chain, qdd);
  const detail::DynamicsPass<Chain<Scalar, N, MaxN>> pass(chain, q);
  return detail::newton_euler_derivatives(chain, pass, qd, qdd, tip_wrench);
}

/// M(q)^-1 by the Cholesky factorization of forward_dynamics_composite (its status and
/// pivot test); Pinocchio's computeMinverse. O(n^3).
template <typename Scalar, int N, int MaxN, typename Q>
MassMatrixInverse<typename Chain<Scalar, N, MaxN>::MassMatrix> mass_matrix_inverse(
    const Chain<Scalar, N, MaxN>& chain, const Eigen::MatrixBase<Q>& q) noexcept {
  using ChainT = Chain<Scalar, N, MaxN>;
  using MassMatrix = typename ChainT::MassMatrix;
  detail::check_joint_vector(chain, q);
  const Eigen::Index n = chain.n_joints();
  const detail::DynamicsPass<ChainT> pass(chain, q);
  typename ChainT::JointVector floor(n);
  MassMatrix L = detail::composite(pass, n, &floor);
  const Eigen::Index k = detail::factorize(L, floor);
  if (k >= 0)
    return {MassMatrix::Constant(n, n, detail::quiet_nan<Scalar>()), DynamicsStatus::mass_matrix_not_positive_definite,
            k};
  return {detail::cholesky_inverse(L), DynamicsStatus::ok, -1};
}

/// d qdd / d q, d qdd / d qd and d qdd / d tau of forward_dynamics(chain, q,
/// qd, tau, tip_wrench) at (q, qd, tau): with qdd = M(q)^-1 (tau - h(q, qd)
/// - J_b^T F_tip), differentiating tau = ID(q, qd, qdd) gives
///   d qdd / d q = -M^-1 dtau/dq,  d qdd / d qd = -M^-1 dtau/dqd,  d qdd / d tau = M^-1
/// (the inverse dynamics' derivatives at the accelerations computed). The
/// status is forward_dynamics_composite's (all NaN unless ok). O(n^3).
template <typename Scalar, int N, int MaxN, typename Q, typename Qd, typename Tau>
ForwardDynamicsDerivatives<typename Chain<Scalar, N, MaxN>::MassMatrix> forward_dynamics_derivatives(
    const Chain<Scalar, N, MaxN>& chain, const Eigen::MatrixBase<Q>& q, const Eigen::MatrixBase<Qd>& qd,
    const Eigen::MatrixBase<Tau>& tau, const Wrench<Scalar>& tip_wrench = Wrench<Scalar>()) noexcept {
  using ChainT = Chain<Scalar, N, MaxN>;
  using MassMatrix = typename ChainT::MassMatrix;
  using JointVector = typename ChainT::JointVector;
  detail::check_joint_vector(chain, q);
  detail::check_joint_vector(chain, qd);
  detail::check_joint_vector(chain, tau);
  const Eigen::Index n = chain.n_joints();
  const detail::DynamicsPass<ChainT> pass(chain, q);
  MassMatrix L;
  JointVector qdd;
  const Eigen::Index k = detail::accelerations(chain, pass, qd, tau, tip_wrench, L, qdd);
  if (k >= 0) {
    const MassMatrix all_nan = MassMatrix::Constant(n, n, detail::quiet_nan<Scalar>());
    return {all_nan, all_nan, all_nan, DynamicsStatus::mass_matrix_not_positive_definite, k};
  }
  InverseDynamicsDerivatives<MassMatrix> d = detail::newton_euler_derivatives(chain, pass, qd, qdd, tip_wrench);
  const MassMatrix Minv = detail::cholesky_inverse(L);
  return {MassMatrix(-Minv.lazyProduct(d.dtau_dq)), MassMatrix(-Minv.lazyProduct(d.dtau_dqd)), Minv, DynamicsStatus::ok,
          -1};
}

}  // namespace chasles
