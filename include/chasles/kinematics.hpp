// chasles: forward kinematics and Jacobians of serial chains by the product
// of exponentials (Murray, Li and Sastry, "A Mathematical Introduction to
// Robotic Manipulation", ch. 3; Lynch and Park, "Modern Robotics", ch. 4-5).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/detail/assert.hpp"
#include "chasles/detail/nearest_rotation.hpp"
#include "chasles/se3.hpp"
#include "chasles/spatial_inertia.hpp"
#include "chasles/twist.hpp"

namespace chasles {

namespace detail {

/// The compile-time check of a joint vector's size against a chain's: Size,
/// the vector's size (Eigen::Dynamic when known only at run time), against
/// Joints (Eigen::Dynamic for a dynamic chain, bounded by MaxJoints). The
/// static_assert compares the two numbers directly, so that the compilers
/// print them with the message.
template <int Joints, int MaxJoints, int Size, bool BothFixed = Joints != Eigen::Dynamic && Size != Eigen::Dynamic>
struct JointVectorSize {
  static_assert(Size == Eigen::Dynamic || Size <= MaxJoints,
                "chasles::Chain: the joint vector's fixed size exceeds the chain's bound on its number of joints "
                "(the comparison shown is: size of the joint vector <= MaxJoints)");
  static constexpr bool ok = true;
};
template <int Joints, int MaxJoints, int Size>
struct JointVectorSize<Joints, MaxJoints, Size, true> {
  static_assert(Size == Joints,
                "chasles::Chain: the joint vector's fixed size is not the chain's fixed number of joints "
                "(the comparison shown is: size of the joint vector == number of joints)");
  static constexpr bool ok = true;
};

/// g with its rotation orthonormalized.
template <typename Scalar>
SE3<Scalar> projected(const SE3<Scalar>& g) noexcept {
  return SE3<Scalar>(SO3<Scalar>::from_matrix_unchecked(orthonormalized<Scalar>(g.rotation().matrix())),
                     g.translation());
}

/// A joint vector v of a chain has n entries: checked at compile time when
/// its size is fixed (against a fixed n, or MaxJoints), at run time by
/// eigen_assert (as Eigen checks sizes) when n or its size is dynamic.
template <typename ChainT, typename Derived>
void check_joint_vector(const ChainT& chain, const Eigen::MatrixBase<Derived>& v) noexcept {
  static_assert(
      JointVectorSize<ChainT::JointsAtCompileTime, ChainT::MaxJointsAtCompileTime, Derived::SizeAtCompileTime>::ok);
  static_cast<void>(chain);  // (both unused when assertions are off)
  static_cast<void>(v);
  CHASLES_ASSERT(v.size() == chain.n_joints());
}

/// The space pass at q, the one loop behind forward kinematics, the space
/// Jacobian and the dynamics: with g_0 = I and
///   g_i = g_{i-1} exp([S_i] q_i)            (link i's motion from home),
/// column i of the space Jacobian is S_i(q) = Ad_{g_{i-1}} S_i (written to
/// *J unless J is null), and link(i, g_i) is called after each product. It
/// returns g_n; with `last` false it stops before the last product (the
/// Jacobian alone has no use for it) and returns g_{n-1}.
template <typename ChainT, typename Q, typename Link>
EIGEN_ALWAYS_INLINE SE3<typename ChainT::Scalar> space_pass(const ChainT& chain, const Eigen::MatrixBase<Q>& q,
                                                            typename ChainT::Jacobian* J, Link&& link,
                                                            bool last = true) noexcept {
  using Scalar = typename ChainT::Scalar;
  using Group = SE3<Scalar>;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  const typename ChainT::Screws& S = chain.space_screws();
  const Eigen::Index n = S.cols();
  Group g;
  for (Eigen::Index i = 0; i < n; ++i) {
    if (J != nullptr) {  // Ad_g S_i = (R v + p x R w, R w) (SE3::act), written as its halves (below)
      const auto& R = g.rotation().matrix();
      const Vector3 Rw = R * S.col(i).template tail<3>();
      J->col(i).template head<3>() = R * S.col(i).template head<3>() + g.translation().cross(Rw);
      J->col(i).template tail<3>() = Rw;
    }
    if (!last && i + 1 == n) break;
    g *= Group::exp(S.col(i) * q(i));
    link(i, static_cast<const Group&>(g));
  }
  return g;
}

/// The body pass at q, the loop behind the body Jacobian: with h_{n+1} = I
/// and h_i = exp([B_i] q_i) h_{i+1}, column i of the body Jacobian is
/// Ad_{h_{i+1}^-1} B_i (written to *J unless J is null); it returns
/// g(q) = M h_1 (with `last` false it stops before the last product, as the
/// Jacobian alone needs, and returns M h_2).
template <typename ChainT, typename Q>
EIGEN_ALWAYS_INLINE SE3<typename ChainT::Scalar> body_pass(const ChainT& chain, const Eigen::MatrixBase<Q>& q,
                                                           typename ChainT::Jacobian* J, bool last = true) noexcept {
  using Scalar = typename ChainT::Scalar;
  using Group = SE3<Scalar>;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  const typename ChainT::Screws& B = chain.body_screws();
  Group h;
  for (Eigen::Index i = B.cols() - 1; i >= 0; --i) {
    if (J != nullptr) {  // Ad_h^-1 B_i = (R^T (v - p x w), R^T w) (SE3::act_inv), written as its halves (below)
      const auto Rt = h.rotation().matrix().transpose();
      const Vector3 w = B.col(i).template tail<3>();
      J->col(i).template head<3>() = Rt * (B.col(i).template head<3>() - h.translation().cross(w));
      J->col(i).template tail<3>() = Rt * w;
    }
    if (!last && i == 0) break;
    h = Group::exp(B.col(i) * q(i)) * h;
  }
  return chain.home() * h;
}

/// (Each Jacobian column is written as its two halves, not as a 6-vector
/// assembled from two 3-vectors and copied: that copy reads the halves back
/// in packets that straddle their stores, a store-forwarding stall in
/// every column, worst with AVX's 4-packets (-march=native). SE3::act's
/// formulas are written out for it: through a helper returning the two
/// halves, shared with SE3::act, the same arithmetic measured 1-2% slower.
/// Both passes are inlined into each caller, so that each gets the loop it
/// would have written alone: the Jacobian's column writes and the link
/// callback vanish where they are not asked for. exp takes the product
/// expression, one instantiation for every caller: GCC then inlines exp's
/// coefficients into it, as it stops doing once exp has several.)
///
/// A link callback of space_pass that does nothing.
struct NoLink {
  template <typename Group>
  void operator()(Eigen::Index, const Group&) const noexcept {}
};

}  // namespace detail

/// The type of a joint of a Chain: a revolute joint turns about its axis
/// between position limits, a continuous one turns without limits (its
/// limits are -inf and +inf), a prismatic one slides along its axis (URDF's
/// "revolute", "continuous" and "prismatic"), a helical one turns and
/// slides along its axis together, h metres per radian (a screw of pitch
/// h: (-w x q + h w, w); Pinocchio's helical joint; URDF has none).
enum class JointType : unsigned char { revolute, continuous, prismatic, helical };

/// What Chain::validate() asks of the norm of a joint's screw: unit (|w| = 1
/// for a joint that turns, |v| = 1 for a prismatic one: the joint variable
/// in radians or metres), or any nonzero norm k (the screw k S of a unit
/// screw S: the joint turns k radians, or slides k metres, per unit of its
/// variable; Modern Robotics' chapter 8 example has a screw of norm sqrt(2)).
enum class ScrewNorms : unsigned char { unit, any };

/// What Chain::validate() finds: the first problem, in this order, of the
/// first joint that has one.
enum class ChainStatus : unsigned char {
  ok,
  /// a revolute, continuous or helical joint whose angular part w is not a
  /// unit vector (| |w| - 1 | > screw_tolerance; ScrewNorms::unit)
  revolute_axis_not_unit,
  /// a revolute or continuous joint of nonzero pitch:
  /// |w . v| > screw_tolerance |w| (|w| + |v|)
  revolute_pitch_not_zero,
  /// a prismatic joint with a nonzero angular part (|w| > screw_tolerance |v|)
  prismatic_rotates,
  /// a prismatic joint whose linear part is not a unit vector (ScrewNorms::unit)
  prismatic_axis_not_unit,
  /// lower > upper, a NaN limit, or a continuous joint with a finite limit
  position_limits_invalid,
  /// a negative or NaN velocity or effort limit
  velocity_or_effort_limit_invalid,
  /// a NaN or infinite gravity vector
  gravity_not_finite,
  /// a link inertia with a NaN or infinite mass, center of mass or
  /// rotational inertia, or a negative mass
  link_inertia_invalid,
  /// a joint screw that is zero, or not finite (ScrewNorms::any)
  screw_zero,
};

/// ChainStatus and the joint it is about (-1 for ok and gravity_not_finite;
/// for link_inertia_invalid, the joint whose link it is).
struct ChainCheck {
  ChainStatus status;
  Eigen::Index joint;
  explicit operator bool() const noexcept { return status == ChainStatus::ok; }
};

/// A serial chain of n one-degree-of-freedom joints (revolute, prismatic or
/// any screw joint), given by its space screws S_i (the joint twists at the
/// home configuration, in the base frame; columns (v, w), linear part first)
/// and its home pose M = g(0) (tool frame in base frame). It keeps the body
/// screws B_i = Ad_{M^-1} S_i (the same twists in the tool frame at home).
///
/// `Joints` is n, or Eigen::Dynamic with `MaxJoints` a compile-time bound:
/// screws, Jacobians and joint vectors then have a fixed capacity and never
/// allocate. A dynamic chain holds 1 <= n <= MaxJoints joints (checked by
/// Eigen's assertions only, as every size in Eigen). A joint vector theta
/// must have n entries: a fixed-size one is checked at compile time (its
/// size equals a fixed n, or is at most MaxJoints), any other by
/// eigen_assert.
///
/// The robot model around the kinematics: each joint's type (JointType),
/// position limits (lower, upper), velocity and effort limits, a base frame
/// (the pose of the chain's base in the world frame), a tool frame (the pose
/// of the tool in the last link's frame at home, i.e. appended to M) and
/// gravity (a 3-vector in the world frame, default (0, 0, -9.81) m/s^2, the
/// value of URDF tools and Pinocchio) and each link's inertia (the link
/// joint i moves, a SpatialInertia described in the base frame at home, as
/// the screws; default: massless, all zero, the SpatialInertia() that adds
/// nothing to the dynamics). Base and tool are folded into the screws, the
/// home pose and the inertias on construction:
///   S_i = Ad_base S0_i,  M = base M0 tool,  G_i = G0_i.transform(base)
/// (G_i = Ad_base^-T G0_i Ad_base^-1), so that every algorithm (forward
/// kinematics, Jacobians, inverse kinematics, and the dynamics of
/// dynamics.hpp, free functions of the chain: inverse_dynamics(chain, q,
/// qd, qdd), ...) works on (S, M, G) alone, in the world frame; base() and
/// tool() stay available. The chain is the whole robot model: the
/// algorithms hold no copy of it. The home pose is projected onto SE(3) on
/// construction (detail::orthonormalized: a pose composed of URDF transforms
/// is a rigid motion only up to a defect of a few eps).
///
/// Joint names are not stored: strings allocate, and a real-time chain has
/// no use for them. The Python Chain keeps them beside its C++ chain.
///
/// Validation: the constructors cannot throw, so they check nothing;
/// validate() says whether the model is consistent (unit joint axes, zero
/// pitch for revolute joints, ordered limits, finite inertias of nonnegative
/// mass; ChainStatus).
///
/// Every operation is noexcept, allocation-free and of cost O(n).
template <typename Scalar_, int Joints, int MaxJoints = Joints>
class Chain {
  static_assert(MaxJoints != Eigen::Dynamic, "Chain: MaxJoints must be a compile-time bound");
  static_assert(MaxJoints >= 1, "Chain: at least one joint");
  static_assert(Joints == Eigen::Dynamic || Joints == MaxJoints,
                "Chain: a fixed number of joints is its own bound (MaxJoints == Joints)");

 public:
  using Scalar = Scalar_;
  using Group = SE3<Scalar>;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  using Vector6 = Eigen::Matrix<Scalar, 6, 1>;
  /// 6 x n: one screw (or one Jacobian column) per joint.
  using Screws = Eigen::Matrix<Scalar, 6, Joints, Eigen::ColMajor, 6, MaxJoints>;
  using Jacobian = Screws;
  /// n x 1: joint positions theta.
  using JointVector = Eigen::Matrix<Scalar, Joints, 1, Eigen::ColMajor, MaxJoints, 1>;
  /// One JointType per joint (the first n are used).
  using JointTypes = std::array<JointType, static_cast<std::size_t>(MaxJoints)>;
  using Inertia = SpatialInertia<Scalar>;
  /// One inertia per link (the first n are used; the others stay zero).
  using Inertias = std::array<Inertia, static_cast<std::size_t>(MaxJoints)>;
  /// n x n: the joint-space mass matrix (dynamics.hpp).
  using MassMatrix = Eigen::Matrix<Scalar, Joints, Joints, Eigen::ColMajor, MaxJoints, MaxJoints>;
  static constexpr int JointsAtCompileTime = Joints;
  static constexpr int MaxJointsAtCompileTime = MaxJoints;

  /// From the space screws S (6 x n, columns (v, w)) and the home pose M:
  /// joint types inferred (prismatic where w = 0; helical where the pitch
  /// is not zero, |w . v| > screw_tolerance |w| (|w| + |v|); revolute
  /// elsewhere), no limits (+-inf), identity base and tool, default
  /// gravity, massless links.
  template <typename Derived>
  Chain(const Eigen::MatrixBase<Derived>& space_screws, const Group& home) noexcept
      : S_(space_screws),
        B_(6, space_screws.cols()),
        M_(detail::projected(home)),
        lower_(JointVector::Constant(space_screws.cols(), -infinity())),
        upper_(JointVector::Constant(space_screws.cols(), infinity())),
        velocity_(JointVector::Constant(space_screws.cols(), infinity())),
        effort_(JointVector::Constant(space_screws.cols(), infinity())),
        gravity_(default_gravity()) {
    types_.fill(JointType::revolute);
    for (Eigen::Index i = 0; i < S_.cols(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      if (!(S_.col(i).template tail<3>().squaredNorm() > Scalar(0)))
        types_[k] = JointType::prismatic;
      else if (!pitch_is_zero(S_.col(i)))
        types_[k] = JointType::helical;
    }
    compute_body_screws();
  }

  /// The same with the home pose taken as it is, not projected: for a home
  /// pose that is already one (another chain's home(), which this
  /// reproduces bit for bit); and optionally the links' inertias (in the
  /// base frame at home) and gravity, as in the next constructor.
  struct HomeAsGiven {};
  template <typename Derived>
  Chain(const Eigen::MatrixBase<Derived>& space_screws, const Group& home, HomeAsGiven,
        const Inertias& link_inertias = Inertias(), const Vector3& gravity = default_gravity()) noexcept
      : Chain(space_screws, home) {
    M_ = home;
    inertias_ = link_inertias;
    gravity_ = gravity;
    compute_body_screws();
  }

  /// The dynamics model: the space screws S (6 x n), the home pose M
  /// (projected onto SE(3)), the links' inertias (in the base frame at
  /// home, the first n entries) and gravity; joint types inferred, no
  /// limits, identity base and tool.
  template <typename Derived>
  Chain(const Eigen::MatrixBase<Derived>& space_screws, const Group& home, const Inertias& link_inertias,
        const Vector3& gravity = default_gravity()) noexcept
      : Chain(space_screws, home) {
    inertias_ = link_inertias;
    gravity_ = gravity;
  }

  /// The full model, from arrays: the screws S0 (6 x n, in the base frame)
  /// and home pose M0 of the chain without its base and tool, each joint's
  /// type, position limits (lower, upper: +-inf where there are none, and
  /// always for continuous joints), velocity and effort limits (+inf where
  /// there are none), the base frame (in the world frame), the tool frame
  /// (after M0), gravity (in the world frame) and the links' inertias G0
  /// (in the base frame at home, the first n entries; default: massless,
  /// SpatialInertia(), all zero). Stores S = Ad_base S0, M = base M0 tool
  /// (projected onto SE(3)), G = G0.transform(base). Checks nothing:
  /// validate().
  template <typename Derived>
  Chain(const Eigen::MatrixBase<Derived>& space_screws, const Group& home, const JointTypes& types,
        const JointVector& lower, const JointVector& upper, const JointVector& velocity_limits,
        const JointVector& effort_limits, const Group& base = Group(), const Group& tool = Group(),
        const Vector3& gravity = default_gravity(), const Inertias& link_inertias = Inertias()) noexcept
      : S_(space_screws),
        B_(6, space_screws.cols()),
        types_(types),
        lower_(lower),
        upper_(upper),
        velocity_(velocity_limits),
        effort_(effort_limits),
        base_(detail::projected(base)),
        tool_(detail::projected(tool)),
        gravity_(gravity) {
    CHASLES_ASSERT(lower.size() == S_.cols() && upper.size() == S_.cols() && velocity_limits.size() == S_.cols() &&
                   effort_limits.size() == S_.cols());
    for (Eigen::Index i = 0; i < S_.cols(); ++i) {
      const auto k = static_cast<std::size_t>(i);
      S_.col(i) = base_.act(Twist<Scalar>(Vector6(S_.col(i)))).vector();
      inertias_[k] = link_inertias[k].transform(base_);
    }
    M_ = detail::projected(Group(base_ * detail::projected(home) * tool_));
    compute_body_screws();
  }

  /// The chain another chain stores, from its accessors: space screws,
  /// home pose and link inertias in the world frame (base and tool already
  /// folded in), types, limits, base, tool and gravity, all taken as they
  /// are, so that the copy computes what the original does, bit for bit
  /// (the body screws are computed again, by the same arithmetic).
  struct Stored {};
  template <typename Derived>
  Chain(Stored, const Eigen::MatrixBase<Derived>& space_screws, const Group& home, const JointTypes& types,
        const JointVector& lower, const JointVector& upper, const JointVector& velocity_limits,
        const JointVector& effort_limits, const Group& base, const Group& tool, const Vector3& gravity,
        const Inertias& link_inertias) noexcept
      : S_(space_screws),
        B_(6, space_screws.cols()),
        M_(home),
        types_(types),
        lower_(lower),
        upper_(upper),
        velocity_(velocity_limits),
        effort_(effort_limits),
        base_(base),
        tool_(tool),
        gravity_(gravity),
        inertias_(link_inertias) {
    compute_body_screws();
  }

  /// (0, 0, -9.81): gravity in m/s^2 along -z, as URDF tools and Pinocchio.
  static Vector3 default_gravity() noexcept { return Vector3(Scalar(0), Scalar(0), Scalar(-9.81)); }

  /// The screw of a revolute joint about the axis through `point` (q)
  /// along `direction` (w, normalized here; w != 0): (-w x q, w). The point
  /// comes first, as in every screw of chasles (SE3::from_screw).
  static Vector6 revolute_screw(const Vector3& point, const Vector3& direction) noexcept {
    using std::sqrt;
    const Vector3 w = direction / sqrt(direction.squaredNorm());
    return detail::stack<Scalar>(Vector3(-w.cross(point)), w);
  }
  /// The screw of a prismatic joint along v (normalized here; v != 0): (v, 0).
  static Vector6 prismatic_screw(const Vector3& direction) noexcept {
    using std::sqrt;
    return detail::stack<Scalar>(Vector3(direction / sqrt(direction.squaredNorm())), Vector3::Zero());
  }

  /// Space form: g(theta) = exp([S_1] th_1) ... exp([S_n] th_n) M.
  template <typename Derived>
  Group forward(const Eigen::MatrixBase<Derived>& theta) const noexcept {
    check_size(theta);
    return detail::space_pass(*this, theta, nullptr, detail::NoLink()) * M_;
  }

  /// g(theta) = M (exp([B_1] th_1) (... exp([B_n] th_n))), and the body
  /// Jacobian J_b (6 x n) in `jacobian_body`, from one body pass (the
  /// products that the Jacobian's columns need make the pose too): what
  /// inverse kinematics needs at each configuration it tries. Equal to
  /// `forward` up to rounding (the products associated from the right).
  template <typename Derived>
  Group forward_body(const Eigen::MatrixBase<Derived>& theta, Jacobian& jacobian_body) const noexcept {
    check_size(theta);
    jacobian_body.resize(6, n_joints());
    return detail::body_pass(*this, theta, &jacobian_body);
  }

  /// Body form: g(theta) = M exp([B_1] th_1) ... exp([B_n] th_n); equal to
  /// `forward` (M exp([B]) M^-1 = exp([Ad_M B]) = exp([S])).
  template <typename Derived>
  Group forward_body(const Eigen::MatrixBase<Derived>& theta) const noexcept {
    check_size(theta);
    Group g = M_;
    for (Eigen::Index i = 0; i < n_joints(); ++i) g *= Group::exp(B_.col(i) * theta(i));
    return g;
  }

  /// The space Jacobian J_s (6 x n), V^s = (g' g^-1)^vee = J_s theta':
  ///   column i = Ad_{exp([S_1] th_1) ... exp([S_{i-1}] th_{i-1})} S_i.
  template <typename Derived>
  Jacobian jacobian_space(const Eigen::MatrixBase<Derived>& theta) const noexcept {
    check_size(theta);
    Jacobian J(6, n_joints());
    detail::space_pass(*this, theta, &J, detail::NoLink(), false);
    return J;
  }

  /// The body Jacobian J_b (6 x n), V^b = (g^-1 g')^vee = J_b theta':
  ///   column i = Ad_{(exp([B_{i+1}] th_{i+1}) ... exp([B_n] th_n))^-1} B_i;
  /// J_s = Ad_{g(theta)} J_b.
  template <typename Derived>
  Jacobian jacobian_body(const Eigen::MatrixBase<Derived>& theta) const noexcept {
    check_size(theta);
    Jacobian J(6, n_joints());
    detail::body_pass(*this, theta, &J, false);
    return J;
  }

  /// dJ_s/dt at joint velocities theta_dot: column i is d/dt S_i(theta) =
  /// [V_{i-1}, S_i(theta)] (V_{i-1} = sum_{j<i} S_j(theta) theta_dot_j, the
  /// twist of the link before joint i, base frame; the bracket of
  /// Twist::bracket). With it the tool's acceleration (the time derivative
  /// of V^s's coordinates) is J_s theta_ddot + J_s_dot theta_dot.
  template <typename Q, typename Qd>
  Jacobian jacobian_space_dot(const Eigen::MatrixBase<Q>& theta,
                              const Eigen::MatrixBase<Qd>& theta_dot) const noexcept {
    check_size(theta);
    check_size(theta_dot);
    Jacobian J(6, n_joints()), Jd(6, n_joints());
    detail::space_pass(*this, theta, &J, detail::NoLink(), false);
    Twist<Scalar> V;
    for (Eigen::Index i = 0; i < n_joints(); ++i) {
      const Twist<Scalar> Si{Vector6(J.col(i))};
      Jd.col(i) = V.bracket(Si).vector();
      V = V + Si * theta_dot(i);
    }
    return Jd;
  }

  /// dJ_b/dt at joint velocities theta_dot: J_b = Ad_{g^-1} J_s and
  /// d/dt Ad_{g^-1} = -Ad_{g^-1} ad_{V^s}, so column i is
  /// Ad_{g^-1} [V_{i-1} - V^s, S_i(theta)] (V^s = J_s theta_dot, the tool's
  /// spatial twist). The tool's body acceleration is J_b theta_ddot +
  /// J_b_dot theta_dot.
  template <typename Q, typename Qd>
  Jacobian jacobian_body_dot(const Eigen::MatrixBase<Q>& theta, const Eigen::MatrixBase<Qd>& theta_dot) const noexcept {
    check_size(theta);
    check_size(theta_dot);
    Jacobian J(6, n_joints()), Jd(6, n_joints());
    const Group g = detail::space_pass(*this, theta, &J, detail::NoLink()) * M_;
    const Vector6 Vs = J.lazyProduct(theta_dot);
    Vector6 V = Vector6::Zero();
    for (Eigen::Index i = 0; i < n_joints(); ++i) {
      const Twist<Scalar> Si{Vector6(J.col(i))};
      Jd.col(i) = g.act_inv(Twist<Scalar>(Vector6(V - Vs)).bracket(Si)).vector();
      V += J.col(i) * theta_dot(i);
    }
    return Jd;
  }

  /// n, the number of joints.
  Eigen::Index n_joints() const noexcept { return S_.cols(); }
  /// S (6 x n): the joint screws at home, in the base frame.
  const Screws& space_screws() const noexcept { return S_; }
  /// B = Ad_{M^-1} S (6 x n): the joint screws at home, in the tool frame.
  const Screws& body_screws() const noexcept { return B_; }
  /// M = g(0), the tool frame at home (base and tool included).
  const Group& home() const noexcept { return M_; }
  /// The type of joint i.
  JointType joint_type(Eigen::Index i) const noexcept {
    CHASLES_ASSERT(i >= 0 && i < n_joints());
    return types_[static_cast<std::size_t>(i)];
  }
  /// The types (the first n are used).
  const JointTypes& joint_types() const noexcept { return types_; }
  /// Lower position limits (-inf where none).
  const JointVector& lower() const noexcept { return lower_; }
  /// Upper position limits (+inf where none).
  const JointVector& upper() const noexcept { return upper_; }
  /// Velocity limits, >= 0 (+inf where none).
  const JointVector& velocity_limits() const noexcept { return velocity_; }
  /// Effort limits (torque or force), >= 0 (+inf where none).
  const JointVector& effort_limits() const noexcept { return effort_; }
  /// The base frame, in the world frame (already folded into S and M).
  const Group& base() const noexcept { return base_; }
  /// The tool frame, after the last link at home (already folded into M).
  const Group& tool() const noexcept { return tool_; }
  /// Gravity, in the world frame.
  const Vector3& gravity() const noexcept { return gravity_; }
  /// The links' inertias (link i: the body joint i moves) in the world
  /// frame at home (the given ones moved by the base frame); the first n
  /// are used, the others are zero. Massless (zero) unless given.
  const Inertias& link_inertias() const noexcept { return inertias_; }

  /// Whether each joint is what its type says (unit axes unless `norms` is
  /// ScrewNorms::any, zero pitch for revolute joints: see ChainStatus), its
  /// limits are ordered and nonnegative, gravity is finite, and the link
  /// inertias are finite with masses >= 0; the first problem found. A link
  /// inertia need not be a rigid body's (SpatialInertia::is_physical): a
  /// massless link (zero, the default) and a point mass (I_c = 0) are valid
  /// models, as in URDF files. Tolerance: Thresholds::screw_tolerance
  /// (constants.hpp), relative to the screw's norm.
  ChainCheck validate(ScrewNorms norms = ScrewNorms::unit) const noexcept {
    using std::abs;
    using std::sqrt;
    const Scalar tol(ThresholdsOf<Scalar>::screw_tolerance);
    const bool unit = norms == ScrewNorms::unit;
    for (Eigen::Index i = 0; i < n_joints(); ++i) {
      const Vector3 v = S_.col(i).template head<3>(), w = S_.col(i).template tail<3>();
      const Scalar nv = sqrt(v.squaredNorm()), nw = sqrt(w.squaredNorm());
      const JointType type = types_[static_cast<std::size_t>(i)];
      if (!unit && !(nv + nw > Scalar(0) && nv + nw < infinity())) return {ChainStatus::screw_zero, i};
      if (type == JointType::prismatic) {
        if (!(nw <= tol * (unit ? Scalar(1) : nv))) return {ChainStatus::prismatic_rotates, i};
        if (unit && !(abs(nv - Scalar(1)) <= tol)) return {ChainStatus::prismatic_axis_not_unit, i};
      } else {
        if (unit ? !(abs(nw - Scalar(1)) <= tol) : !(nw > Scalar(0))) return {ChainStatus::revolute_axis_not_unit, i};
        if (type != JointType::helical && !pitch_is_zero(S_.col(i))) return {ChainStatus::revolute_pitch_not_zero, i};
      }
      const Scalar lo = lower_(i), hi = upper_(i);
      if (!(lo <= hi) || (type == JointType::continuous && (lo > -infinity() || hi < infinity())))
        return {ChainStatus::position_limits_invalid, i};
      if (!(velocity_(i) >= Scalar(0)) || !(effort_(i) >= Scalar(0)))
        return {ChainStatus::velocity_or_effort_limit_invalid, i};
    }
    if (!(abs(gravity_(0)) + abs(gravity_(1)) + abs(gravity_(2)) < infinity()))
      return {ChainStatus::gravity_not_finite, -1};
    for (Eigen::Index i = 0; i < n_joints(); ++i) {
      const Inertia& G = inertias_[static_cast<std::size_t>(i)];
      bool finite = G.mass() >= Scalar(0) && G.mass() < infinity();  // false for NaN
      for (int r = 0; r < 3; ++r) {
        finite = finite && abs(G.com()(r)) < infinity();
        for (int c = 0; c < 3; ++c) finite = finite && abs(G.inertia()(r, c)) < infinity();
      }
      if (!finite) return {ChainStatus::link_inertia_invalid, i};
    }
    return {ChainStatus::ok, -1};
  }

 private:
  /// theta has n entries: checked at compile time when its size is fixed
  /// (against a fixed n, or MaxJoints), at run time by eigen_assert (as Eigen
  /// checks sizes) when n or its size is dynamic.
  template <typename Derived>
  void check_size(const Eigen::MatrixBase<Derived>& theta) const noexcept {
    detail::check_joint_vector(*this, theta);
  }

  static Scalar infinity() noexcept { return Scalar(std::numeric_limits<RealOf<Scalar>>::infinity()); }

  /// Whether a screw (v, w) has zero pitch to screw_tolerance: w . v / |w|^2
  /// is the pitch (Lynch and Park, 3.3.2.2), tested as
  /// |w . v| <= tol |w| (|w| + |v|) (for |w| = 1: tol (1 + |v|)).
  template <typename Column>
  static bool pitch_is_zero(const Column& screw) noexcept {
    using std::abs;
    using std::sqrt;
    const Vector3 v = screw.template head<3>(), w = screw.template tail<3>();
    const Scalar nw = sqrt(w.squaredNorm());
    return abs(w.dot(v)) <= Scalar(ThresholdsOf<Scalar>::screw_tolerance) * nw * (nw + sqrt(v.squaredNorm()));
  }

  /// B_i = Ad_{M^-1} S_i, then with the two invariants of S_i under Ad
  /// restored: |w|, and w . v (|v| when w = 0). Rounding in Ad moves them by
  /// a few eps, and exp([B_i] th_i) multiplies that by th_i (an angle error
  /// eps |th| from |w|, a slide along the axis eps |q| |th| from the pitch):
  /// restored, forward_body agrees with forward at large angles as at small
  /// ones (tests/cpp/test_kinematics.cpp, LargeAngles).
  void compute_body_screws() noexcept {
    using std::sqrt;
    const Group M_inv = M_.inverse();
    for (Eigen::Index i = 0; i < S_.cols(); ++i) {
      const Vector6 b = M_inv.act(Twist<Scalar>(Vector6(S_.col(i)))).vector();
      const Vector3 vs = S_.col(i).template head<3>(), ws = S_.col(i).template tail<3>();
      Vector3 vb = b.template head<3>(), wb = b.template tail<3>();
      const Scalar ws2 = ws.squaredNorm(), wb2 = wb.squaredNorm();
      if (ws2 > Scalar(0) && wb2 > Scalar(0)) {
        wb *= sqrt(ws2 / wb2);                                         // |w_b| = |w_s|
        vb += ((ws.dot(vs) - wb.dot(vb)) / wb.squaredNorm()) * wb;  // w_b . v_b = w_s . v_s
      } else if (!(ws2 > Scalar(0))) {
        const Scalar vb2 = vb.squaredNorm();
        if (vb2 > Scalar(0)) vb *= sqrt(vs.squaredNorm() / vb2);  // |v_b| = |v_s|
      }
      for (int k = 0; k < 3; ++k) B_(k, i) = vb(k), B_(k + 3, i) = wb(k);
    }
  }

  Screws S_;
  Screws B_;
  Group M_;
  JointTypes types_{};
  JointVector lower_, upper_, velocity_, effort_;
  Group base_, tool_;
  Vector3 gravity_;
  Inertias inertias_{};
};

}  // namespace chasles
