// chasles: rigid-body dynamics of serial chains given by their space screws:
// inverse dynamics by the recursive Newton-Euler algorithm, the mass matrix
// by the composite-rigid-body algorithm, forward dynamics by a Cholesky
// solve. Written in the base (space) frame, Featherstone's spatial form
// (R. Featherstone, "Rigid Body Dynamics Algorithms", 2008, ch. 5.3 and 6.2,
// with the spatial quantities in base coordinates) on twists (v, w) and
// wrenches (f, tau); the same recursion as Lynch and Park, "Modern Robotics",
// ch. 8.3.2 (eqs. 8.50-8.53), whose link-frame form it equals after the
// change of frame of each quantity by Ad_{g_i}.
#pragma once

#include <array>
#include <cstddef>
#include <limits>

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/detail/assert.hpp"
#include "chasles/kinematics.hpp"
#include "chasles/se3.hpp"
#include "chasles/spatial_inertia.hpp"
#include "chasles/twist.hpp"
#include "chasles/wrench.hpp"

namespace chasles {

/// How Dynamics::forward_dynamics ended.
enum class DynamicsStatus : unsigned char {
  ok,
  /// M(q) is not positive definite to working precision: a pivot of its
  /// Cholesky factorization is not above the rounding of its terms (see
  /// Dynamics::forward_dynamics). A link without mass, or without
  /// rotational inertia about its joint's axis (a point mass on the axis),
  /// gives a zero pivot; an inertia that no rigid body has (a rotational
  /// inertia that is not positive definite: SpatialInertia::is_physical)
  /// can give a negative one.
  mass_matrix_not_positive_definite,
};

/// The outcome of Dynamics::forward_dynamics: the accelerations, the
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

/// The dynamics of a serial chain of n one-degree-of-freedom joints: its
/// space screws S_i (6 x n, columns (v, w), the joint twists at home in the
/// base frame), its home pose M (the tool frame at home), the spatial
/// inertia of each link i (the body moved by joint i) described in the base
/// frame at the home configuration, and gravity, a 3-vector in the base
/// frame (e.g. (0, 0, -9.81)). From a Chain, Dynamics(chain) takes all four
/// from it (in the world frame, which is then the "base frame" here).
///
/// Why the base frame: everything the chain is given in (S, M, inertias at
/// home) is in the base frame, so no link frames are needed. At q, link i
/// has moved by g_i = exp([S_1] q_1) ... exp([S_i] q_i); its joint screw is
/// S_i(q) = Ad_{g_{i-1}} S_i (the space Jacobian's column) and its inertia
/// G_i(q) = Ad_{g_i}^-T G_i Ad_{g_i}^-1 (SpatialInertia::transform: only c
/// and I_c move). Then, with V_0 = 0 and the base accelerating at -gravity,
/// A_0 = (-gravity, 0) (Featherstone's way to account for gravity, as in
/// Modern Robotics and Pinocchio):
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
/// `Joints`, `MaxJoints`: as in Chain (a fixed n, or Eigen::Dynamic bounded
/// by MaxJoints). Every operation is noexcept, allocation-free and of cost
/// O(n) (inverse dynamics) or O(n^2) (mass matrix, forward dynamics: O(n^3)
/// for the Cholesky factorization, n <= MaxJoints).
///
/// The inertias are taken as given, as SpatialInertia takes them (and
/// Chain and the URDF loaders): forward_dynamics reports a mass matrix that
/// they leave singular or indefinite (DynamicsStatus) rather than return
/// meaningless accelerations.
template <typename Scalar_, int Joints, int MaxJoints = Joints>
class Dynamics {
  static_assert(MaxJoints != Eigen::Dynamic, "Dynamics: MaxJoints must be a compile-time bound");
  static_assert(MaxJoints >= 1, "Dynamics: at least one joint");
  static_assert(Joints == Eigen::Dynamic || Joints == MaxJoints,
                "Dynamics: a fixed number of joints is its own bound (MaxJoints == Joints)");

 public:
  using Scalar = Scalar_;
  using Group = SE3<Scalar>;
  using Inertia = SpatialInertia<Scalar>;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  using Vector6 = Eigen::Matrix<Scalar, 6, 1>;
  using Matrix6 = Eigen::Matrix<Scalar, 6, 6>;
  using Screws = Eigen::Matrix<Scalar, 6, Joints, Eigen::ColMajor, 6, MaxJoints>;
  using JointVector = Eigen::Matrix<Scalar, Joints, 1, Eigen::ColMajor, MaxJoints, 1>;
  using MassMatrix = Eigen::Matrix<Scalar, Joints, Joints, Eigen::ColMajor, MaxJoints, MaxJoints>;
  /// One inertia per link, the first n used.
  using Inertias = std::array<Inertia, static_cast<std::size_t>(MaxJoints)>;

  /// From the space screws S (6 x n), the home pose M, the links' inertias
  /// (in the base frame at home; the first n entries) and gravity (base frame).
  template <typename Derived>
  Dynamics(const Eigen::MatrixBase<Derived>& space_screws, const Group& home, const Inertias& inertias,
           const Vector3& gravity) noexcept
      : S_(space_screws), M_(home), I_(inertias), gravity_(gravity) {}

  /// The dynamics of a Chain: its space screws, home pose, link inertias and
  /// gravity, all in the world frame (the chain has folded its base frame
  /// into them): Dynamics(chain.space_screws(), chain.home(),
  /// chain.link_inertias(), chain.gravity()). The chain's joint limits play
  /// no part.
  explicit Dynamics(const Chain<Scalar, Joints, MaxJoints>& chain) noexcept
      : Dynamics(chain.space_screws(), chain.home(), chain.link_inertias(), chain.gravity()) {}

  /// tau = M(q) qdd + C(q, qd) qd + g(q) + J_b(q)^T F_tip: the joint forces
  /// that give the accelerations qdd at (q, qd) while the tool applies the
  /// wrench F_tip (tool frame) on the environment. Recursive Newton-Euler.
  template <typename Q, typename Qd, typename Qdd>
  JointVector inverse_dynamics(const Eigen::MatrixBase<Q>& q, const Eigen::MatrixBase<Qd>& qd,
                               const Eigen::MatrixBase<Qdd>& qdd,
                               const Wrench<Scalar>& tip_wrench = Wrench<Scalar>()) const noexcept {
    check_size(q);
    check_size(qd);
    check_size(qdd);
    const Pass pass(*this, q);
    return newton_euler(pass, qd, qdd, true, tip_wrench);
  }

  /// M(q) (n x n, symmetric positive definite for physical inertias):
  /// T = 1/2 qd^T M(q) qd. Composite rigid bodies in the base frame
  /// (Featherstone 2008, ch. 6.2): with I^c_i = sum_{j >= i} G_j(q),
  /// M_ij = S_i(q) . I^c_{max(i, j)} S_j(q).
  template <typename Q>
  MassMatrix mass_matrix(const Eigen::MatrixBase<Q>& q) const noexcept {
    check_size(q);
    const Pass pass(*this, q);
    return composite(pass);
  }

  /// g(q): the joint forces that hold the chain still against gravity,
  /// inverse_dynamics(q, 0, 0). At rest every link's acceleration is the
  /// base's, A = (-gravity, 0), so link j's wrench G_j A is
  /// m_j (-gravity, c_j x -gravity): only the masses and the centers of mass
  /// c_j(q) enter, and the recursion sums them, tau_i = S_i(q) . sum_{j >= i}
  /// (m_j (-gravity), m_j c_j x -gravity). No rotational inertia is moved
  /// (bench_ops, UR5: 0.41 us against inverse_dynamics' 0.56).
  template <typename Q>
  JointVector gravity_torques(const Eigen::MatrixBase<Q>& q) const noexcept {
    check_size(q);
    const Eigen::Index n = joints();
    Screws S(6, n);
    std::array<Vector3, static_cast<std::size_t>(MaxJoints)> mc;  // m_j c_j(q)
    Group g;
    for (Eigen::Index i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      S.col(i) = g.act(Twist<Scalar>(Vector6(S_.col(i)))).vector();
      g *= Group::exp(Vector6(S_.col(i) * q(i)));
      mc[k] = I_[k].mass() * g.act(I_[k].com());
    }
    JointVector tau(n);
    Scalar m(0);
    Vector3 mc_sum = Vector3::Zero();
    for (Eigen::Index i = n - 1; i >= 0; --i) {
      const auto k = static_cast<std::size_t>(i);
      m += I_[k].mass();
      mc_sum += mc[k];
      const Vector3 f = -m * gravity_, torque = -mc_sum.cross(gravity_);
      tau(i) = S.col(i).template head<3>().dot(f) + S.col(i).template tail<3>().dot(torque);
    }
    return tau;
  }

  /// C(q, qd) qd: the Coriolis and centrifugal joint forces, without
  /// gravity: inverse_dynamics(q, qd, 0) with gravity off.
  template <typename Q, typename Qd>
  JointVector coriolis(const Eigen::MatrixBase<Q>& q, const Eigen::MatrixBase<Qd>& qd) const noexcept {
    check_size(q);
    check_size(qd);
    const Pass pass(*this, q);
    return newton_euler(pass, qd, JointVector::Zero(joints()), false, Wrench<Scalar>());
  }

  /// h(q, qd) = C(q, qd) qd + g(q): inverse_dynamics(q, qd, 0), gravity on.
  template <typename Q, typename Qd>
  JointVector bias(const Eigen::MatrixBase<Q>& q, const Eigen::MatrixBase<Qd>& qd) const noexcept {
    check_size(q);
    check_size(qd);
    const Pass pass(*this, q);
    return newton_euler(pass, qd, JointVector::Zero(joints()), true, Wrench<Scalar>());
  }

  /// qdd = M(q)^-1 (tau - h(q, qd) - J_b(q)^T F_tip), by a Cholesky
  /// factorization M(q) = L L^T (in place on the fixed-capacity matrix: no
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
  /// One kinematic pass serves both M and h.
  template <typename Q, typename Qd, typename Tau>
  ForwardDynamicsResult<JointVector> forward_dynamics(const Eigen::MatrixBase<Q>& q, const Eigen::MatrixBase<Qd>& qd,
                                                      const Eigen::MatrixBase<Tau>& tau,
                                                      const Wrench<Scalar>& tip_wrench = Wrench<Scalar>()) const
      noexcept {
    check_size(q);
    check_size(qd);
    check_size(tau);
    const Pass pass(*this, q);
    JointVector qdd = tau - newton_euler(pass, qd, JointVector::Zero(joints()), true, tip_wrench);
    JointVector floor(joints());
    MassMatrix L = composite(pass, &floor);
    const Eigen::Index k = factorize(L, floor);
    if (k >= 0) {
      const Scalar nan(std::numeric_limits<RealOf<Scalar>>::quiet_NaN());
      return {JointVector::Constant(joints(), nan), DynamicsStatus::mass_matrix_not_positive_definite, k};
    }
    // M qdd = b: L y = b, then L^T qdd = y (as Eigen's LLT::solve).
    L.template triangularView<Eigen::Lower>().solveInPlace(qdd);
    L.adjoint().template triangularView<Eigen::Upper>().solveInPlace(qdd);
    return {qdd, DynamicsStatus::ok, -1};
  }

  /// T = sum_i 1/2 V_i . G_i(q) V_i, the links' kinetic energy computed
  /// from their twists (independently of M(q): T = 1/2 qd^T M(q) qd).
  template <typename Q, typename Qd>
  Scalar kinetic_energy(const Eigen::MatrixBase<Q>& q, const Eigen::MatrixBase<Qd>& qd) const noexcept {
    check_size(q);
    check_size(qd);
    const Pass pass(*this, q);
    Twist<Scalar> V;
    Scalar T(0);
    for (Eigen::Index i = 0; i < joints(); ++i) {
      V = V + Twist<Scalar>(Vector6(pass.S.col(i) * qd(i)));
      T += pass.I[static_cast<std::size_t>(i)].kinetic_energy(V);
    }
    return T;
  }

  /// U = -sum_i m_i gravity . c_i(q), the links' potential energy (zero
  /// at the base origin); g(q) = dU/dq.
  template <typename Q>
  Scalar potential_energy(const Eigen::MatrixBase<Q>& q) const noexcept {
    check_size(q);
    const Pass pass(*this, q);
    Scalar U(0);
    for (std::size_t i = 0; i < static_cast<std::size_t>(joints()); ++i)
      U -= pass.I[i].mass() * gravity_.dot(pass.I[i].com());
    return U;
  }

  /// n, the number of joints.
  Eigen::Index joints() const noexcept { return S_.cols(); }
  const Screws& space_screws() const noexcept { return S_; }
  const Group& home() const noexcept { return M_; }
  /// The links' inertias in the base frame at home (the first n entries).
  const Inertias& inertias() const noexcept { return I_; }
  const Vector3& gravity() const noexcept { return gravity_; }
  void set_gravity(const Vector3& gravity) noexcept { gravity_ = gravity; }

 private:
  /// The kinematic pass at q: the joint screws S_i(q) = Ad_{g_{i-1}} S_i,
  /// the links' inertias G_i(q) in the base frame and the tool pose g(q).
  struct Pass {
    template <typename Q>
    Pass(const Dynamics& d, const Eigen::MatrixBase<Q>& q) noexcept : S(6, d.joints()) {
      Group g;
      for (Eigen::Index i = 0; i < d.joints(); ++i) {
        const auto k = static_cast<std::size_t>(i);
        S.col(i) = g.act(Twist<Scalar>(Vector6(d.S_.col(i)))).vector();
        g *= Group::exp(Vector6(d.S_.col(i) * q(i)));
        I[k] = d.I_[k].transform(g);
      }
      tool = g * d.M_;
    }
    Screws S;
    Inertias I;
    Group tool;
  };

  /// -ad_V^T h = (w x f, v x f + w x tau): the rate of change of a momentum
  /// h = (f, tau) carried by the twist V = (v, w) (Featherstone's v x* h).
  static Vector6 cross_star(const Twist<Scalar>& V, const Wrench<Scalar>& h) noexcept {
    const Vector3 v = V.linear(), w = V.angular(), f = h.force(), t = h.torque();
    return detail::stack<Scalar>(Vector3(w.cross(f)), Vector3(v.cross(f) + w.cross(t)));
  }

  /// The recursion of the class comment; `with_gravity` false starts from A_0 = 0.
  template <typename Qd, typename Qdd>
  JointVector newton_euler(const Pass& pass, const Eigen::MatrixBase<Qd>& qd, const Eigen::MatrixBase<Qdd>& qdd,
                           bool with_gravity, const Wrench<Scalar>& tip) const noexcept {
    const Eigen::Index n = joints();
    std::array<Vector6, static_cast<std::size_t>(MaxJoints)> F;
    Twist<Scalar> V;
    Vector6 A = Vector6::Zero();
    if (with_gravity) A.template head<3>() = -gravity_;
    for (Eigen::Index i = 0; i < n; ++i) {
      const auto k = static_cast<std::size_t>(i);
      const Vector6 Si = pass.S.col(i);
      V = V + Twist<Scalar>(Vector6(Si * qd(i)));
      A += Si * qdd(i) + V.bracket(Twist<Scalar>(Si)).vector() * qd(i);
      F[k] = pass.I[k].momentum(Twist<Scalar>(A)).vector() + cross_star(V, pass.I[k].momentum(V));
    }
    JointVector tau(n);
    Vector6 Fi = pass.tool.act(tip).vector();
    for (Eigen::Index i = n - 1; i >= 0; --i) {
      Fi += F[static_cast<std::size_t>(i)];
      tau(i) = pass.S.col(i).dot(Fi);
    }
    return tau;
  }

  /// M(q) by the composite inertias I^c_i = sum_{j >= i} G_j(q); with
  /// `floor`, also each joint's pivot floor tolerance * s_i of
  /// forward_dynamics, from the diagonal blocks of I^c_i (tr(G_f), tr(G_t)).
  MassMatrix composite(const Pass& pass, JointVector* floor = nullptr) const noexcept {
    const Eigen::Index n = joints();
    const Scalar tolerance(ThresholdsOf<Scalar>::mass_matrix_pivot_tolerance);
    MassMatrix Mq(n, n);
    Matrix6 Ic = Matrix6::Zero();
    for (Eigen::Index i = n - 1; i >= 0; --i) {
      Ic += pass.I[static_cast<std::size_t>(i)].matrix();
      if (floor) {
        const Scalar force = Ic.diagonal().template head<3>().sum(), torque = Ic.diagonal().template tail<3>().sum();
        (*floor)(i) = tolerance * (pass.S.col(i).template head<3>().squaredNorm() * force +
                                   pass.S.col(i).template tail<3>().squaredNorm() * torque);
      }
      const Vector6 F = Ic * pass.S.col(i);
      for (Eigen::Index j = 0; j <= i; ++j) {
        Mq(j, i) = pass.S.col(j).dot(F);
        Mq(i, j) = Mq(j, i);
      }
    }
    return Mq;
  }

  /// The Cholesky factorization M = L L^T in place on the lower triangle of
  /// A (Eigen's unblocked LLT, the same operations), stopping at the first
  /// pivot d_k <= floor(k) (forward_dynamics' comment; composite() computes
  /// the floors): returns that k, or -1 when every pivot passes.
  Eigen::Index factorize(MassMatrix& A, const JointVector& floor) const noexcept {
    using std::sqrt;
    const Eigen::Index n = joints();
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

  template <typename Derived>
  void check_size(const Eigen::MatrixBase<Derived>& v) const noexcept {
    static_assert(detail::JointVectorSize<Joints, MaxJoints, Derived::SizeAtCompileTime>::ok);
    static_cast<void>(v);
    CHASLES_ASSERT(v.size() == joints());
  }

  Screws S_;
  Group M_;
  Inertias I_;
  Vector3 gravity_;
};

}  // namespace chasles
