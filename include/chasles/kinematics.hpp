// chasles: forward kinematics and Jacobians of serial chains by the product
// of exponentials (Murray, Li and Sastry, "A Mathematical Introduction to
// Robotic Manipulation", ch. 3; Lynch and Park, "Modern Robotics", ch. 4-5).
#pragma once

#include <cmath>

#include <Eigen/Core>

#include "chasles/detail/assert.hpp"
#include "chasles/se3.hpp"
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

}  // namespace detail

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
  static constexpr int JointsAtCompileTime = Joints;
  static constexpr int MaxJointsAtCompileTime = MaxJoints;

  /// From the space screws S (6 x n, columns (v, w)) and the home pose M.
  template <typename Derived>
  Chain(const Eigen::MatrixBase<Derived>& space_screws, const Group& home) noexcept
      : S_(space_screws), B_(6, space_screws.cols()), M_(home) {
    const Group M_inv = home.inverse();
    for (Eigen::Index i = 0; i < S_.cols(); ++i) B_.col(i) = M_inv.act(Twist<Scalar>(Vector6(S_.col(i)))).vector();
  }

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
    Group g;
    for (Eigen::Index i = 0; i < joints(); ++i) g *= Group::exp(S_.col(i) * theta(i));
    return g * M_;
  }

  /// Body form: g(theta) = M exp([B_1] th_1) ... exp([B_n] th_n); equal to
  /// `forward` (M exp([B]) M^-1 = exp([Ad_M B]) = exp([S])).
  template <typename Derived>
  Group forward_body(const Eigen::MatrixBase<Derived>& theta) const noexcept {
    check_size(theta);
    Group g = M_;
    for (Eigen::Index i = 0; i < joints(); ++i) g *= Group::exp(B_.col(i) * theta(i));
    return g;
  }

  /// The space Jacobian J_s (6 x n), V^s = (g' g^-1)^vee = J_s theta':
  ///   column i = Ad_{exp([S_1] th_1) ... exp([S_{i-1}] th_{i-1})} S_i.
  template <typename Derived>
  Jacobian jacobian_space(const Eigen::MatrixBase<Derived>& theta) const noexcept {
    check_size(theta);
    const Eigen::Index n = joints();
    Jacobian J(6, n);
    Group g;
    for (Eigen::Index i = 0; i < n; ++i) {
      J.col(i) = g.act(Twist<Scalar>(Vector6(S_.col(i)))).vector();
      if (i + 1 < n) g *= Group::exp(S_.col(i) * theta(i));
    }
    return J;
  }

  /// The body Jacobian J_b (6 x n), V^b = (g^-1 g')^vee = J_b theta':
  ///   column i = Ad_{(exp([B_{i+1}] th_{i+1}) ... exp([B_n] th_n))^-1} B_i;
  /// J_s = Ad_{g(theta)} J_b.
  template <typename Derived>
  Jacobian jacobian_body(const Eigen::MatrixBase<Derived>& theta) const noexcept {
    check_size(theta);
    const Eigen::Index n = joints();
    Jacobian J(6, n);
    Group h;  // exp([B_{i+1}] th_{i+1}) ... exp([B_n] th_n)
    for (Eigen::Index i = n - 1; i >= 0; --i) {
      J.col(i) = h.act_inv(Twist<Scalar>(Vector6(B_.col(i)))).vector();
      if (i > 0) h = Group::exp(B_.col(i) * theta(i)) * h;
    }
    return J;
  }

  /// n, the number of joints.
  Eigen::Index joints() const noexcept { return S_.cols(); }
  /// S (6 x n): the joint screws at home, in the base frame.
  const Screws& space_screws() const noexcept { return S_; }
  /// B = Ad_{M^-1} S (6 x n): the joint screws at home, in the tool frame.
  const Screws& body_screws() const noexcept { return B_; }
  /// M = g(0), the tool frame at home.
  const Group& home() const noexcept { return M_; }

 private:
  /// theta has n entries: checked at compile time when its size is fixed
  /// (against a fixed n, or MaxJoints), at run time by eigen_assert (as Eigen
  /// checks sizes) when n or its size is dynamic.
  template <typename Derived>
  void check_size(const Eigen::MatrixBase<Derived>& theta) const noexcept {
    static_assert(detail::JointVectorSize<Joints, MaxJoints, Derived::SizeAtCompileTime>::ok);
    static_cast<void>(theta);  // (unused when assertions are off)
    CHASLES_ASSERT(theta.size() == joints());
  }

  Screws S_;
  Screws B_;
  Group M_;
};

}  // namespace chasles
