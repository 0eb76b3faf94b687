// chasles: rigid-body dynamics of serial chains given by their space screws:
// inverse dynamics by the recursive Newton-Euler algorithm, the mass matrix
// by the composite-rigid-body algorithm, forward dynamics by a Cholesky
// solve or the articulated-body algorithm. Written in the base (space) frame, Featherstone's spatial form
// (R. Featherstone, "Rigid Body Dynamics Algorithms", 2008, ch. 5.3 and 6.2,
// with the spatial quantities in base coordinates) on twists (v, w) and
// wrenches (f, tau); the same recursion as Lynch and Park, "Modern Robotics",
// ch. 8.3.2 (eqs. 8.50-8.53), whose link-frame form it equals after the
// change of frame of each quantity by Ad_{g_i}.
#pragma once

#include <array>
#include <cstddef>

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/detail/assert.hpp"
#include "chasles/kinematics.hpp"
#include "chasles/se3.hpp"
#include "chasles/spatial_inertia.hpp"
#include "chasles/twist.hpp"
#include "chasles/wrench.hpp"

namespace chasles {

/// How forward_dynamics ended.
enum class DynamicsStatus : unsigned char {
  ok,
  /// M(q) is not positive definite to working precision: a pivot of its
  /// Cholesky factorization is not above the rounding of its terms (see
  /// forward_dynamics_composite). A link without mass, or without
  /// rotational inertia about its joint's axis (a point mass on the axis),
  /// gives a zero pivot; an inertia that no rigid body has (a rotational
  /// inertia that is not positive definite: SpatialInertia::is_physical)
  /// can give a negative one.
  mass_matrix_not_positive_definite,
};

/// The outcome of forward_dynamics: the accelerations, the
/// status, and for a failure the joint at which the factorization stopped
/// (as ChainCheck).
template <typename JointVector>
struct ForwardDynamicsResult {
  /// qdd, the joint accelerations; all NaN unless status is ok.
  JointVector qdd;
  DynamicsStatus status;
  /// The joint k of the failed pivot (-1 when ok): joints 0..k, joint k
  /// among them, can move with (to working precision) no or a negative
  /// kinetic energy while the joints after k are held.
  Eigen::Index joint;
  explicit operator bool() const noexcept { return status == DynamicsStatus::ok; }
};

/// The dynamics of a serial chain (a Chain: kinematics.hpp), free functions
/// of it as inverse_kinematics is: its space screws S_i (the joint twists
/// at home in the world frame), its home pose M (the tool frame at home),
/// the spatial inertia of each link i (the body moved by joint i) described
/// in the world frame at the home configuration, and gravity, a 3-vector in
/// the world frame (Chain::link_inertias(), Chain::gravity(): the chain has
/// folded its base frame into all of them). The chain's joint limits play
/// no part. The chain is the model; nothing here keeps a copy of it.
///
/// Why the base frame: everything the chain is given in (S, M, inertias at
/// home) is in the base frame, so no link frames are needed. At q, link i
/// has moved by g_i = exp([S_1] q_1) ... exp([S_i] q_i) (the space pass of
/// kinematics.hpp, which forward kinematics and the space Jacobian share);
/// its joint screw is S_i(q) = Ad_{g_{i-1}} S_i (the space Jacobian's
/// column) and its inertia G_i(q) = Ad_{g_i}^-T G_i Ad_{g_i}^-1
/// (SpatialInertia::transform: only c and I_c move). Then, with V_0 = 0 and
/// the base accelerating at -gravity, A_0 = (-gravity, 0) (Featherstone's
/// way to account for gravity, as in Modern Robotics and Pinocchio):
///
///   V_i = V_{i-1} + S_i(q) qd_i                          (twists, base frame)
///   A_i = A_{i-1} + S_i(q) qdd_i + [V_i, S_i(q)] qd_i    (d/dt S_i(q) = ad_{V_{i-1}} S_i(q))
///   F_i = G_i(q) A_i - ad_{V_i}^T G_i(q) V_i + F_{i+1},  F_{n+1} = Ad_{g(q)}^-T F_tip
///   tau_i = S_i(q) . F_i
///
/// (A_i is the time derivative of the coordinates of V_i in the fixed base
/// frame; d/dt (G V) = G A - ad_V^T G V as d/dt G = -ad_V^T G - G ad_V.)
/// F_tip is the wrench that the tool applies on the environment, in the
/// tool frame g(q) = g_n M: Modern Robotics' Ftip, so the joints supply it.
///
/// Every function is noexcept, allocation-free and of cost O(n) (inverse
/// dynamics) or O(n^2) (mass matrix, forward dynamics: O(n^3) for the
/// Cholesky factorization, n <= MaxJoints). A joint vector must have n
/// entries (checked as Chain checks them).
///
/// The inertias are taken as given, as SpatialInertia takes them (and
/// Chain and the URDF loaders): forward_dynamics reports a mass matrix that
/// they leave singular or indefinite (DynamicsStatus) rather than return
/// meaningless accelerations.

namespace detail {

/// The space pass of the dynamics at q: the joint screws S_i(q) = Ad_{g_{i-1}} S_i,
/// the links' inertias G_i(q) in the base frame and the tool pose g(q).
template <typename ChainT>
struct DynamicsPass {
  using Scalar = typename ChainT::Scalar;
  template <typename Q>
  DynamicsPass(const ChainT& chain, const Eigen::MatrixBase<Q>& q) noexcept : S(6, chain.n_joints()) {
    const typename ChainT::Inertias& G = chain.link_inertias();
    tool = space_pass(chain, q, &S,
                      [&](Eigen::Index i, const SE3<Scalar>& g) {
                        const auto k = static_cast<std::size_t>(i);
                        I[k] = G[k].transform(g);
                      }) *
           chain.home();
  }
  typename ChainT::Jacobian S;
  typename ChainT::Inertias I;
  SE3<Scalar> tool;
};

/// -ad_V^T h = (w x f, v x f + w x tau): the rate of change of a momentum
/// h = (f, tau) carried by the twist V = (v, w) (Featherstone's v x* h).
template <typename Scalar>
Eigen::Matrix<Scalar, 6, 1> cross_star(const Twist<Scalar>& V, const Wrench<Scalar>& h) noexcept {
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  const Vector3 v = V.linear(), w = V.angular(), f = h.force(), t = h.torque();
  return stack<Scalar>(Vector3(w.cross(f)), Vector3(v.cross(f) + w.cross(t)));
}

/// m x y = ad_m y (motion on motion).
template <typename Scalar>
Eigen::Matrix<Scalar, 6, 1> motion_cross(const Eigen::Matrix<Scalar, 6, 1>& m,
                                         const Eigen::Matrix<Scalar, 6, 1>& y) noexcept {
  return Twist<Scalar>(m).bracket(Twist<Scalar>(y)).vector();
}

/// m x* f = -ad_m^T f (motion on force).
template <typename Scalar>
Eigen::Matrix<Scalar, 6, 1> force_cross(const Eigen::Matrix<Scalar, 6, 1>& m,
                                        const Eigen::Matrix<Scalar, 6, 1>& f) noexcept {
  return cross_star(Twist<Scalar>(m), Wrench<Scalar>(f));
}

/// The recursion of the comment above; `with_gravity` false starts from A_0 = 0.
/// Every 6-vector is carried as its two 3-vector halves (V = (v, w),
/// A = (a, al), F = (f, t)): a 6-vector assembled from two 3-vectors and
/// read back in packets stalls on store forwarding, and with AVX's
/// 4-packets in every step (inverse dynamics took 16% longer with
/// -march=native than without, until it was written so).
template <typename ChainT, typename Qd, typename Qdd>
typename ChainT::JointVector newton_euler(const ChainT& chain, const DynamicsPass<ChainT>& pass,
                                          const Eigen::MatrixBase<Qd>& qd, const Eigen::MatrixBase<Qdd>& qdd,
                                          bool with_gravity, const Wrench<typename ChainT::Scalar>& tip) noexcept {
  using Scalar = typename ChainT::Scalar;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  constexpr auto Max = static_cast<std::size_t>(ChainT::MaxJointsAtCompileTime);
  const Eigen::Index n = chain.n_joints();
  std::array<Vector3, Max> Ff, Ft;
  Vector3 v = Vector3::Zero(), w = Vector3::Zero(), al = Vector3::Zero();
  Vector3 a = with_gravity ? Vector3(-chain.gravity()) : Vector3(Vector3::Zero());
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vector3 sv = pass.S.col(i).template head<3>(), sw = pass.S.col(i).template tail<3>();
    v += sv * qd(i);
    w += sw * qd(i);
    // A_i = A_{i-1} + S qdd + [V, S] qd, [V, S] = (w x sv + v x sw, w x sw)
    a += sv * qdd(i) + (w.cross(sv) + v.cross(sw)) * qd(i);
    al += sw * qdd(i) + w.cross(sw) * qd(i);
    // G A and G V (SpatialInertia::momentum), then F = G A + V x* G V
    // (cross_star), both written out here: through momentum's halves form
    // and a halves form of cross_star, inverse dynamics measured 4-9%
    // slower (508 against 530-556 ns on a 7-joint chain, g++ 12 -O3).
    const SpatialInertia<Scalar>& G = pass.I[k];
    const Vector3& c = G.com();
    const Vector3 fa = G.mass() * (a - c.cross(al)), fv = G.mass() * (v - c.cross(w));
    const Vector3 ta = G.inertia() * al + c.cross(fa), tv = G.inertia() * w + c.cross(fv);
    Ff[k] = fa + w.cross(fv);
    Ft[k] = ta + v.cross(fv) + w.cross(tv);
  }
  typename ChainT::JointVector tau(n);
  const Wrench<Scalar> tip_base = pass.tool.act(tip);
  Vector3 f = tip_base.force(), t = tip_base.torque();
  for (Eigen::Index i = n - 1; i >= 0; --i) {
    const auto k = static_cast<std::size_t>(i);
    f += Ff[k];
    t += Ft[k];
    tau(i) = pass.S.col(i).template head<3>().dot(f) + pass.S.col(i).template tail<3>().dot(t);
  }
  return tau;
}

/// M(q) by the composite inertias I^c_i = sum_{j >= i} G_j(q); with
/// `floor`, also each joint's pivot floor tolerance * s_i of
/// forward_dynamics, from the diagonal blocks of I^c_i (tr(G_f), tr(G_t)).
/// I^c_i is summed as the three parts its matrix is made of, mass m,
/// first moment h = sum m_j c_j and rotational inertia about the origin
/// I_O = sum I_c,j + m_j (|c_j|^2 1 - c_j c_j^T), so that
///   I^c (v, w) = (m v - h x w, h x v + I_O w)
/// costs no 6 x 6 product (G = [[m 1, -[h]], [[h], I_O]]).
template <typename ChainT>
typename ChainT::MassMatrix composite(const DynamicsPass<ChainT>& pass, Eigen::Index n,
                                      typename ChainT::JointVector* floor = nullptr) noexcept {
  using Scalar = typename ChainT::Scalar;
  using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  const Scalar tolerance(ThresholdsOf<Scalar>::mass_matrix_pivot_tolerance);
  typename ChainT::MassMatrix Mq(n, n);
  Scalar m(0);
  Vector3 h = Vector3::Zero();
  Matrix3 I_O = Matrix3::Zero();
  for (Eigen::Index i = n - 1; i >= 0; --i) {
    const SpatialInertia<Scalar>& G = pass.I[static_cast<std::size_t>(i)];
    const Vector3& c = G.com();
    m += G.mass();
    h += G.mass() * c;
    I_O += G.inertia() + G.mass() * (c.squaredNorm() * Matrix3::Identity() - c * c.transpose());
    const Vector3 v = pass.S.col(i).template head<3>(), w = pass.S.col(i).template tail<3>();
    if (floor) (*floor)(i) = tolerance * (v.squaredNorm() * (Scalar(3) * m) + w.squaredNorm() * I_O.trace());
    // F = I^c_i S_i(q) = (f, t), dotted with each S_j(q) as its two halves:
    // a Vector6 F written as two 3-vectors and read back as 2-packets
    // stalled on store forwarding (a third to a half of this function's
    // time: 28% of its samples on that load, 19% on the next instruction).
    const Vector3 f = m * v - h.cross(w), t = h.cross(v) + I_O * w;
    for (Eigen::Index j = 0; j <= i; ++j) {
      Mq(j, i) = pass.S.col(j).template head<3>().dot(f) + pass.S.col(j).template tail<3>().dot(t);
      Mq(i, j) = Mq(j, i);
    }
  }
  return Mq;
}

/// The Cholesky factorization M = L L^T in place on the lower triangle of
/// A (Eigen's unblocked LLT, the same operations), stopping at the first
/// pivot d_k <= floor(k) (forward_dynamics_composite's comment; composite() computes
/// the floors): returns that k, or -1 when every pivot passes.
template <typename MassMatrix, typename JointVector>
Eigen::Index factorize(MassMatrix& A, const JointVector& floor) noexcept {
  using std::sqrt;
  using Scalar = typename MassMatrix::Scalar;
  const Eigen::Index n = A.rows();
  for (Eigen::Index k = 0; k < n; ++k) {
    const Eigen::Index rest = n - k - 1;
    Eigen::Block<MassMatrix, Eigen::Dynamic, 1> A21(A, k + 1, k, rest, 1);
    Eigen::Block<MassMatrix, 1, Eigen::Dynamic> A10(A, k, 0, 1, k);
    Eigen::Block<MassMatrix, Eigen::Dynamic, Eigen::Dynamic> A20(A, k + 1, 0, rest, k);
    Scalar d = A(k, k);
    if (k > 0) d -= A10.squaredNorm();
    if (d <= floor(k)) return k;  // false for NaN: a NaN goes on to the result
    A(k, k) = d = sqrt(d);
    if (k > 0 && rest > 0) A21.noalias() -= A20 * A10.adjoint();
    if (rest > 0) A21 /= d;
  }
  return -1;
}

/// forward_dynamics_composite at the pass of q: M(q) = L L^T into `L` (composite,
/// factorize) and qdd = M^-1 (tau - h - J_b^T F_tip) into `qdd`; returns -1,
/// or the joint of the failed pivot (then `qdd` is not solved).
template <typename ChainT, typename Qd, typename Tau>
Eigen::Index accelerations(const ChainT& chain, const DynamicsPass<ChainT>& pass, const Eigen::MatrixBase<Qd>& qd,
                           const Eigen::MatrixBase<Tau>& tau, const Wrench<typename ChainT::Scalar>& tip,
                           typename ChainT::MassMatrix& L, typename ChainT::JointVector& qdd) noexcept {
  using JointVector = typename ChainT::JointVector;
  const Eigen::Index n = chain.n_joints();
  qdd = tau - newton_euler(chain, pass, qd, JointVector::Zero(n), true, tip);
  JointVector floor(n);
  L = composite(pass, n, &floor);
  const Eigen::Index k = factorize(L, floor);
  if (k >= 0) return k;
  // M qdd = b: L y = b, then L^T qdd = y (as Eigen's LLT::solve).
  L.template triangularView<Eigen::Lower>().solveInPlace(qdd);
  L.adjoint().template triangularView<Eigen::Upper>().solveInPlace(qdd);
  return -1;
}

}  // namespace detail

/// tau = M(q) qdd + C(q, qd) qd + g(q) + J_b(q)^T F_tip: the joint forces
/// that give the accelerations qdd at (q, qd) while the tool applies the
/// wrench F_tip (tool frame) on the environment. Recursive Newton-Euler.
template <typename Scalar, int N, int MaxN, typename Q, typename Qd, typename Qdd>
typename Chain<Scalar, N, MaxN>::JointVector inverse_dynamics(
    const Chain<Scalar, N, MaxN>& chain, const Eigen::MatrixBase<Q>& q, const Eigen::MatrixBase<Qd>& qd,
    const Eigen::MatrixBase<Qdd>& qdd, const Wrench<Scalar>& tip_wrench = Wrench<Scalar>()) noexcept {
  detail::check_joint_vector(chain, q);
  detail::check_joint_vector(chain, qd);
  detail::check_joint_vector(chain, qdd);
  const detail::DynamicsPass<Chain<Scalar, N, MaxN>> pass(chain, q);
  return detail::newton_euler(chain, pass, qd, qdd, true, tip_wrench);
}

/// M(q) (n x n, symmetric positive definite for physical inertias):
/// T = 1/2 qd^T M(q) qd. Composite rigid bodies in the base frame
/// (Featherstone 2008, ch. 6.2): with I^c_i = sum_{j >= i} G_j(q),
/// M_ij = S_i(q) . I^c_{max(i, j)} S_j(q).
template <typename Scalar, int N, int MaxN, typename Q>
typename Chain<Scalar, N, MaxN>::MassMatrix mass_matrix(const Chain<Scalar, N, MaxN>& chain,
                                                        const Eigen::MatrixBase<Q>& q) noexcept {
  detail::check_joint_vector(chain, q);
  const detail::DynamicsPass<Chain<Scalar, N, MaxN>> pass(chain, q);
  return detail::composite(pass, chain.n_joints());
}

/// g(q): the joint forces that hold the chain still against gravity,
/// inverse_dynamics(chain, q, 0, 0). At rest every link's acceleration is
/// the base's, A = (-gravity, 0), so link j's wrench G_j A is
/// m_j (-gravity, c_j x -gravity): only the masses and the centers of mass
/// c_j(q) enter, and the recursion sums them, tau_i = S_i(q) . sum_{j >= i}
/// (m_j (-gravity), m_j c_j x -gravity). No rotational inertia is moved
/// (bench_ops, UR5: 0.41 us against inverse_dynamics' 0.56).
template <typename Scalar, int N, int MaxN, typename Q>
typename Chain<Scalar, N, MaxN>::JointVector gravity_torques(const Chain<Scalar, N, MaxN>& chain,
                                                             const Eigen::MatrixBase<Q>& q) noexcept {
  using ChainT = Chain<Scalar, N, MaxN>;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  detail::check_joint_vector(chain, q);
  const Eigen::Index n = chain.n_joints();
  const typename ChainT::Inertias& G = chain.link_inertias();
  typename ChainT::Jacobian S(6, n);
  std::array<Vector3, static_cast<std::size_t>(MaxN)> mc;  // m_j c_j(q)
  detail::space_pass(chain, q, &S, [&](Eigen::Index i, const SE3<Scalar>& g) {
    const auto k = static_cast<std::size_t>(i);
    mc[k] = G[k].mass() * g.act(G[k].com());
  });
  const Vector3& gravity = chain.gravity();
  typename ChainT::JointVector tau(n);
  Scalar m(0);
  Vector3 mc_sum = Vector3::Zero();
  for (Eigen::Index i = n - 1; i >= 0; --i) {
    const auto k = static_cast<std::size_t>(i);
    m += G[k].mass();
    mc_sum += mc[k];
    const Vector3 f = -m * gravity, torque = -mc_sum.cross(gravity);
    tau(i) = S.col(i).template head<3>().dot(f) + S.col(i).template tail<3>().dot(torque);
  }
  return tau;
}

/// C(q, qd) qd: the Coriolis and centrifugal joint forces, without
/// gravity: inverse_dynamics(chain, q, qd, 0) with gravity off.
template <typename Scalar, int N, int MaxN, typename Q, typename Qd>
typename Chain<Scalar, N, MaxN>::JointVector coriolis(const Chain<Scalar, N, MaxN>& chain,
                                                      const Eigen::MatrixBase<Q>& q,
                                                      const Eigen::MatrixBase<Qd>& qd) noexcept {
  using JointVector = typename Chain<Scalar, N, MaxN>::JointVector;
  detail::check_joint_vector(chain, q);
  detail::check_joint_vector(chain, qd);
  const detail::DynamicsPass<Chain<Scalar, N, MaxN>> pass(chain, q);
  return detail::newton_euler(chain, pass, qd, JointVector::Zero(chain.n_joints()), false, Wrench<Scalar>());
}

/// h(q, qd) = C(q, qd) qd + g(q): inverse_dynamics(chain, q, qd, 0), gravity on.
template <typename Scalar, int N, int MaxN, typename Q, typename Qd>
typename Chain<Scalar, N, MaxN>::JointVector bias(const Chain<Scalar, N, MaxN>& chain, const Eigen::MatrixBase<Q>& q,
                                                  const Eigen::MatrixBase<Qd>& qd) noexcept {
  using JointVector = typename Chain<Scalar, N, MaxN>::JointVector;
  detail::check_joint_vector(chain, q);
  detail::check_joint_vector(chain, qd);
  const detail::DynamicsPass<Chain<Scalar, N, MaxN>> pass(chain, q);
  return detail::newton_euler(chain, pass, qd, JointVector::Zero(chain.n_joints()), true, Wrench<Scalar>());
}

/// qdd = M(q)^-1 (tau - h(q, qd) - J_b(q)^T F_tip) by the composite inertias
/// (mass_matrix) and a Cholesky factorization M(q) = L L^T (in place on the fixed-capacity matrix: no
/// allocation; the operations of Eigen's unblocked LLT), with the status:
/// ok, or mass_matrix_not_positive_definite with NaN accelerations and the
/// joint k of the first pivot d_k = M_kk - sum_{j<k} L_kj^2 that is not
/// above the rounding of the terms M_kk is made of:
///
///   d_k <= mass_matrix_pivot_tolerance * s_k,
///   s_k = |v_k|^2 tr(G_f) + |w_k|^2 tr(G_t)        (S_k(q) = (v_k, w_k))
///
/// with G_f, G_t the force and torque diagonal blocks of the composite
/// inertia I^c_k = sum_{j >= k} G_j(q): tr(G_f) = 3 sum m_j and
/// tr(G_t) = sum tr(I_c,j) + 2 m_j |c_j(q)|^2. M_kk = S_k . I^c_k S_k is
/// at most 2 s_k, and the base-frame sums that make it round to a few eps
/// s_k whatever its own size (constants.hpp says how the tolerance was
/// measured). s_k is a scale of joint k's own units (kg m^2 for a
/// revolute joint, kg for a prismatic one), so the test does not depend on
/// the unit of length or of mass. A massless link at the end (s_k = 0),
/// a point mass on its joint's axis, two joints that move the same way
/// (coaxial, with a massless link between them) fail; so does any
/// indefinite M(q). A NaN in q, qd, tau or the model gives NaN
/// accelerations with status ok (as everywhere: no check of the input).
/// One space pass serves both M and h.
template <typename Scalar, int N, int MaxN, typename Q, typename Qd, typename Tau>
ForwardDynamicsResult<typename Chain<Scalar, N, MaxN>::JointVector> forward_dynamics_composite(
    const Chain<Scalar, N, MaxN>& chain, const Eigen::MatrixBase<Q>& q, const Eigen::MatrixBase<Qd>& qd,
    const Eigen::MatrixBase<Tau>& tau, const Wrench<Scalar>& tip_wrench = Wrench<Scalar>()) noexcept {
  using ChainT = Chain<Scalar, N, MaxN>;
  using JointVector = typename ChainT::JointVector;
  detail::check_joint_vector(chain, q);
  detail::check_joint_vector(chain, qd);
  detail::check_joint_vector(chain, tau);
  const Eigen::Index n = chain.n_joints();
  const detail::DynamicsPass<ChainT> pass(chain, q);
  typename ChainT::MassMatrix L;
  JointVector qdd;
  const Eigen::Index k = detail::accelerations(chain, pass, qd, tau, tip_wrench, L, qdd);
  if (k >= 0)
    return {JointVector::Constant(n, detail::quiet_nan<Scalar>()), DynamicsStatus::mass_matrix_not_positive_definite,
            k};
  return {qdd, DynamicsStatus::ok, -1};
}

/// qdd of forward_dynamics_composite by the articulated-body algorithm (Featherstone
/// 2008, ch. 7.3), O(n), in the base frame, where no link frames are needed:
/// with V_i and c_i = (V_i x S_i(q)) qd_i from the base out, the articulated
/// inertias and bias forces from the tip in (I^A_i = G_i(q) plus the
/// children's I^a, p^A_i = V_i x* G_i(q) V_i (+ F_tip at the tool) plus
/// their p^a):
///   U_i = I^A_i S_i,  D_i = S_i . U_i,  u_i = tau_i - S_i . p^A_i,
///   I^a_i = I^A_i - U_i U_i^T / D_i,  p^a_i = p^A_i + I^a_i c_i + U_i u_i / D_i,
/// then from the base out, A_0 = (-gravity, 0):
///   qdd_i = (u_i - U_i . (A_{i-1} + c_i)) / D_i,  A_i = A_{i-1} + c_i + S_i qdd_i.
/// The status is forward_dynamics_composite's, with the pivots D_i tested as its d_k
/// are (D_i <= mass_matrix_pivot_tolerance * s_i, s_i from I^A_i's diagonal
/// blocks), from the tip in: where M(q) is not positive definite the joint
/// named may differ from forward_dynamics_composite's (which factorizes from the base
/// out). Equal to forward_dynamics_composite to rounding (tests/cpp/test_dynamics.cpp).
template <typename Scalar, int N, int MaxN, typename Q, typename Qd, typename Tau>
ForwardDynamicsResult<typename Chain<Scalar, N, MaxN>::JointVector> forward_dynamics_articulated(
    const Chain<Scalar, N, MaxN>& chain, const Eigen::MatrixBase<Q>& q, const Eigen::MatrixBase<Qd>& qd,
    const Eigen::MatrixBase<Tau>& tau, const Wrench<Scalar>& tip_wrench = Wrench<Scalar>()) noexcept {
  using ChainT = Chain<Scalar, N, MaxN>;
  using JointVector = typename ChainT::JointVector;
  using Vector6 = Eigen::Matrix<Scalar, 6, 1>;
  using Matrix6 = Eigen::Matrix<Scalar, 6, 6>;
  constexpr auto Max = static_cast<std::size_t>(MaxN);
  detail::check_joint_vector(chain, q);
  detail::check_joint_vector(chain, qd);
  detail::check_joint_vector(chain, tau);
  const Eigen::Index n = chain.n_joints();
  const detail::DynamicsPass<ChainT> pass(chain, q);
  const Scalar tolerance(ThresholdsOf<Scalar>::mass_matrix_pivot_tolerance);
  std::array<Matrix6, Max> IA;
  std::array<Vector6, Max> pA, c, U;
  JointVector D(n), u(n), qdd(n);
  Vector6 V = Vector6::Zero();
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    const Vector6 S = pass.S.col(i);
    V += S * qd(i);
    c[k] = detail::motion_cross<Scalar>(V, S) * qd(i);
    IA[k] = pass.I[k].matrix();
    pA[k] = detail::force_cross<Scalar>(V, Vector6(IA[k] * V));
  }
  pA[static_cast<std::size_t>(n - 1)] += pass.tool.act(tip_wrench).vector();
  for (Eigen::Index i = n - 1; i >= 0; --i) {
    const auto k = static_cast<std::size_t>(i);
    const Vector6 S = pass.S.col(i);
    U[k] = IA[k] * S;
    D(i) = S.dot(U[k]);
    u(i) = tau(i) - S.dot(pA[k]);
    const Scalar s = S.template head<3>().squaredNorm() * IA[k].template topLeftCorner<3, 3>().trace() +
                     S.template tail<3>().squaredNorm() * IA[k].template bottomRightCorner<3, 3>().trace();
    if (D(i) <= tolerance * s)  // false for NaN: a NaN goes on to the result
      return {JointVector::Constant(n, detail::quiet_nan<Scalar>()), DynamicsStatus::mass_matrix_not_positive_definite,
              i};
    if (i > 0) {
      const Matrix6 Ia = IA[k] - U[k] * U[k].transpose() / D(i);
      IA[k - 1] += Ia;
      pA[k - 1] += pA[k] + Ia * c[k] + U[k] * (u(i) / D(i));
    }
  }
  Vector6 A = Vector6::Zero();
  A.template head<3>() = -chain.gravity();
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    A += c[k];
    qdd(i) = (u(i) - U[k].dot(A)) / D(i);
    A += pass.S.col(i) * qdd(i);
  }
  return {qdd, DynamicsStatus::ok, -1};
}

/// The number of joints from which forward_dynamics takes the
/// articulated-body algorithm: the composite inertias and Cholesky
/// factorization cost O(n^2) and O(n^3) with smaller constants, and are
/// faster on shorter chains. Measured by bench/bench_chain_length.cpp
/// (random revolute chains, double, g++ 12 -O3 portable, the least-disturbed
/// of 10 interleaved repetitions), articulated-body over composite: 1.15 at
/// 20 joints, 1.08 at 24, 1.01 at 28, 0.98 at 30, 0.96 at 32.
inline constexpr Eigen::Index articulated_body_min_joints = 30;

/// qdd = M(q)^-1 (tau - h(q, qd) - J_b(q)^T F_tip), the joint accelerations
/// that the joint forces tau give at (q, qd) while the tool applies the
/// wrench F_tip (tool frame) on the environment, with the status of
/// forward_dynamics_composite: by forward_dynamics_composite below
/// articulated_body_min_joints joints, by forward_dynamics_articulated from
/// there on (the two agree to rounding; where M(q) is not positive definite
/// they may name different joints).
template <typename Scalar, int N, int MaxN, typename Q, typename Qd, typename Tau>
ForwardDynamicsResult<typename Chain<Scalar, N, MaxN>::JointVector> forward_dynamics(
    const Chain<Scalar, N, MaxN>& chain, const Eigen::MatrixBase<Q>& q, const Eigen::MatrixBase<Qd>& qd,
    const Eigen::MatrixBase<Tau>& tau, const Wrench<Scalar>& tip_wrench = Wrench<Scalar>()) noexcept {
  if constexpr (MaxN >= articulated_body_min_joints) {
    if (chain.n_joints() >= articulated_body_min_joints)
      return forward_dynamics_articulated(chain, q, qd, tau, tip_wrench);
  }
  return forward_dynamics_composite(chain, q, qd, tau, tip_wrench);
}

/// T = sum_i 1/2 V_i . G_i(q) V_i, the links' kinetic energy computed
/// from their twists (independently of M(q): T = 1/2 qd^T M(q) qd).
template <typename Scalar, int N, int MaxN, typename Q, typename Qd>
Scalar kinetic_energy(const Chain<Scalar, N, MaxN>& chain, const Eigen::MatrixBase<Q>& q,
                      const Eigen::MatrixBase<Qd>& qd) noexcept {
  using Vector6 = Eigen::Matrix<Scalar, 6, 1>;
  detail::check_joint_vector(chain, q);
  detail::check_joint_vector(chain, qd);
  const detail::DynamicsPass<Chain<Scalar, N, MaxN>> pass(chain, q);
  Twist<Scalar> V;
  Scalar T(0);
  for (Eigen::Index i = 0; i < chain.n_joints(); ++i) {
    V = V + Twist<Scalar>(Vector6(pass.S.col(i) * qd(i)));
    T += pass.I[static_cast<std::size_t>(i)].kinetic_energy(V);
  }
  return T;
}

/// U = -sum_i m_i gravity . c_i(q), the links' potential energy (zero
/// at the base origin); g(q) = dU/dq.
template <typename Scalar, int N, int MaxN, typename Q>
Scalar potential_energy(const Chain<Scalar, N, MaxN>& chain, const Eigen::MatrixBase<Q>& q) noexcept {
  detail::check_joint_vector(chain, q);
  const detail::DynamicsPass<Chain<Scalar, N, MaxN>> pass(chain, q);
  Scalar U(0);
  for (std::size_t i = 0; i < static_cast<std::size_t>(chain.n_joints()); ++i)
    U -= pass.I[i].mass() * chain.gravity().dot(pass.I[i].com());
  return U;
}

}  // namespace chasles
