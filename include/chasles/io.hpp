// chasles: operator<< for every public type, for logs and debugging.
//
// Each prints its type, then its stored numbers named as in the Python reprs
// (and in the conventions: twists (v, w), wrenches (f, tau)), matrices row
// by row, with the stream's own format (precision, fixed/scientific):
//   SO3(matrix=[[1, 0, 0], [0, 1, 0], [0, 0, 1]])
//   SE3(rotation=[[1, 0, 0], [0, 1, 0], [0, 0, 1]], translation=[1, 2, 3])
//   Twist(v=[1, 0, 0], w=[0, 0, 1])
//   Wrench(f=[0, 0, -9.81], tau=[0, 0, 0])
//   Screw(point=[0, 0, 0], direction=[0, 0, 1], pitch=0, magnitude=1)
//   Chain(n_joints=2, space_screws=[[0, 0, 0, 0, 0, 1], [0, -1, 0, 0, 0, 1]], home=SE3(...),
//         joint_types=[revolute, revolute], lower=[-inf, -inf], upper=[inf, inf],
//         gravity=[0, 0, -9.81], link_masses=[0, 0])
// (space screws one (v, w) per joint). An autodiff scalar prints its value.
//
// Like the standard streams' own operator<<, these are not noexcept (a
// stream whose exceptions() mask is set throws); they allocate nothing
// themselves. Not included by the per-class headers: a real-time build that includes
// only those gets no stream code from chasles. The umbrella chasles.hpp
// includes it. <ostream> only (no <iostream>: no static initializer).
#pragma once

#include <cstddef>
#include <ostream>

#include <Eigen/Core>

#include "chasles/jacobians.hpp"
#include "chasles/kinematics.hpp"
#include "chasles/screw.hpp"
#include "chasles/se3.hpp"
#include "chasles/so3.hpp"
#include "chasles/spatial_inertia.hpp"
#include "chasles/twist.hpp"
#include "chasles/wrench.hpp"

namespace chasles {
namespace detail {

/// [a, b, c] for a vector (of either orientation, known at compile time);
/// [[a, b], [c, d]] row by row for a matrix.
template <typename Derived>
inline std::ostream& print_numbers(std::ostream& os, const Eigen::MatrixBase<Derived>& m) {
  os << '[';
  if constexpr (Derived::IsVectorAtCompileTime) {
    for (Eigen::Index i = 0; i < m.size(); ++i) os << (i > 0 ? ", " : "") << m(i);
  } else {
    for (Eigen::Index i = 0; i < m.rows(); ++i) {
      os << (i > 0 ? ", [" : "[");
      for (Eigen::Index j = 0; j < m.cols(); ++j) os << (j > 0 ? ", " : "") << m(i, j);
      os << ']';
    }
  }
  return os << ']';
}

}  // namespace detail

/// SO3(matrix=[[...], [...], [...]]).
template <typename Scalar>
std::ostream& operator<<(std::ostream& os, const SO3<Scalar>& R) {
  os << "SO3(matrix=";
  return detail::print_numbers(os, R.matrix()) << ')';
}

/// SE3(rotation=[[...], [...], [...]], translation=[...]).
template <typename Scalar>
std::ostream& operator<<(std::ostream& os, const SE3<Scalar>& g) {
  os << "SE3(rotation=";
  detail::print_numbers(os, g.rotation().matrix()) << ", translation=";
  return detail::print_numbers(os, g.translation()) << ')';
}

/// Twist(v=[...], w=[...]): linear part first.
template <typename Scalar>
std::ostream& operator<<(std::ostream& os, const Twist<Scalar>& xi) {
  os << "Twist(v=";
  detail::print_numbers(os, xi.linear()) << ", w=";
  return detail::print_numbers(os, xi.angular()) << ')';
}

/// Wrench(f=[...], tau=[...]): force first.
template <typename Scalar>
std::ostream& operator<<(std::ostream& os, const Wrench<Scalar>& F) {
  os << "Wrench(f=";
  detail::print_numbers(os, F.force()) << ", tau=";
  return detail::print_numbers(os, F.torque()) << ')';
}

/// Screw(point=[...], direction=[...], pitch=..., magnitude=...).
template <typename Scalar>
std::ostream& operator<<(std::ostream& os, const Screw<Scalar>& s) {
  os << "Screw(point=";
  detail::print_numbers(os, s.point) << ", direction=";
  detail::print_numbers(os, s.direction) << ", pitch=" << s.pitch << ", magnitude=" << s.magnitude << ')';
  return os;
}

/// Chain(n_joints=n, space_screws=[[v, w], ...], home=SE3(...),
/// joint_types=[revolute, ...], lower=[...], upper=[...], gravity=[...],
/// link_masses=[...]): the space screws one joint at a time, each (v, w),
/// and the model (all zero masses: no inertias given). Velocity and effort
/// limits, base and tool are left out (base and tool are folded into the
/// screws and home).
template <typename Scalar, int Joints, int MaxJoints>
std::ostream& operator<<(std::ostream& os, const Chain<Scalar, Joints, MaxJoints>& chain) {
  static const char* const type_names[] = {"revolute", "continuous", "prismatic"};
  os << "Chain(n_joints=" << chain.n_joints() << ", space_screws=[";
  for (Eigen::Index i = 0; i < chain.n_joints(); ++i) {
    if (i > 0) os << ", ";
    detail::print_numbers(os, chain.space_screws().col(i));
  }
  os << "], home=" << chain.home() << ", joint_types=[";
  for (Eigen::Index i = 0; i < chain.n_joints(); ++i)
    os << (i > 0 ? ", " : "") << type_names[static_cast<int>(chain.joint_type(i))];
  os << "], lower=";
  detail::print_numbers(os, chain.lower()) << ", upper=";
  detail::print_numbers(os, chain.upper()) << ", gravity=";
  detail::print_numbers(os, chain.gravity()) << ", link_masses=[";
  for (Eigen::Index i = 0; i < chain.n_joints(); ++i)
    os << (i > 0 ? ", " : "") << chain.link_inertias()[static_cast<std::size_t>(i)].mass();
  return os << "])";
}

/// SpatialInertia(mass=m, com=[...], inertia=[[...], [...], [...]]).
template <typename Scalar>
std::ostream& operator<<(std::ostream& os, const SpatialInertia<Scalar>& I) {
  os << "SpatialInertia(mass=" << I.mass() << ", com=";
  detail::print_numbers(os, I.com()) << ", inertia=";
  return detail::print_numbers(os, I.inertia()) << ')';
}

/// ComposeJacobians(lhs=[[...]], rhs=[[...]]).
template <typename Matrix>
std::ostream& operator<<(std::ostream& os, const ComposeJacobians<Matrix>& J) {
  os << "ComposeJacobians(lhs=";
  detail::print_numbers(os, J.lhs) << ", rhs=";
  return detail::print_numbers(os, J.rhs) << ')';
}

/// ActJacobians(group=[[...]], point=[[...]]).
template <typename MatrixG>
std::ostream& operator<<(std::ostream& os, const ActJacobians<MatrixG>& J) {
  os << "ActJacobians(group=";
  detail::print_numbers(os, J.group) << ", point=";
  return detail::print_numbers(os, J.point) << ')';
}

}  // namespace chasles
