// chasles: distances between the elements of a group: the geodesic
// distance of rotations (SO(2), SO(3)), and for the groups with Euclidean
// parts (group_parts.hpp) the distances of the parts, kept apart.
#pragma once

#include <type_traits>

#include <Eigen/Core>

#include "chasles/group_parts.hpp"
#include "chasles/lie_group.hpp"
#include "chasles/se3.hpp"
#include "chasles/so3.hpp"

namespace chasles {

/// The geodesic (bi-invariant Riemannian) distance between two elements of
/// a rotation group, d(a, b) = |log(a^-1 b)|, in [0, pi]: on SO(2) the
/// absolute angle of a^-1 b (SO3 has its own overload below, the same
/// number from the angle). Symmetric, d(g a, g b) = d(a g, b g) = d(a, b).
template <typename G, std::enable_if_t<detail::IsRotationGroup<G>::value, int> = 0>
inline typename G::Scalar distance(const G& a, const G& b) noexcept {
  using std::abs;
  const typename G::Tangent x = (a.inverse() * b).log();
  if constexpr (G::DoF == 1) {
    return abs(x[0]);  // not sqrt(x^2), which underflows below 1e-154
  } else {
    return x.norm();
  }
}

/// The distances of the parts of two elements of a group with Euclidean
/// parts (GroupParts: SE(2), SE(3), Sim(3), SE_2(3)), as the vector
///   (d(R_a, R_b), |block_1(b) - block_1(a)|, ..., |block_B(b) - block_B(a)|),
/// the rotations' geodesic distance (the angle of R_a^-1 R_b, in [0, pi])
/// and the Euclidean distance of each block of the Euclidean parts: on
/// SE(2) (angle, |t_b - t_a|); on Sim(3) (angle, |t_b - t_a|,
/// |log(s_b / s_a)|); on SE_2(3) (angle, |p_b - p_a|, |v_b - v_a|). These groups have no bi-invariant metric, so the
/// parts are kept apart for the caller to weigh. Each is symmetric and
/// unchanged by a rigid change of the fixed frame, d(g a, g b) = d(a, b)
/// for g a rotation and a translation; a change of scale (Sim(3)) scales the
/// translation distance with it. (SE3 has its own overload below, the
/// same numbers as a struct.)
template <typename G, std::enable_if_t<detail::HasParts<G>::value && !detail::IsRotationGroup<G>::value, int> = 0>
inline Eigen::Matrix<typename G::Scalar, 1 + GroupParts<G>::B, 1> distance(const G& a, const G& b) noexcept {
  using Parts = GroupParts<G>;
  Eigen::Matrix<typename G::Scalar, 1 + Parts::B, 1> d;
  d[0] = distance(Parts::rotation(a), Parts::rotation(b));
  d.template tail<Parts::B>() = Parts::block_norms(typename Parts::Vector(Parts::vector(b) - Parts::vector(a)));
  return d;
}

/// The geodesic (bi-invariant Riemannian) distance between two rotations:
/// the angle of a^-1 b, in [0, pi],
///   d(a, b) = |log(a^-1 b)| = (a^-1 b).angle()
/// (Hartley, Trumpf, Dai and Li, "Rotation averaging", IJCV 2013: the
/// "angular distance"). Symmetric, d(g a, g b) = d(a g, b g) = d(a, b);
/// scipy: `(a.inv() * b).magnitude()`.
template <typename Scalar>
inline Scalar distance(const SO3<Scalar>& a, const SO3<Scalar>& b) noexcept {
  return (a.inverse() * b).angle();
}

/// The two parts of the distance between two rigid motions (SE(3) has no
/// bi-invariant metric, so they are kept apart rather than mixed with a
/// length scale chosen for the user).
template <typename Scalar>
struct SE3Distance {
  Scalar angle;        ///< the angle of R_a^-1 R_b, in [0, pi] (distance of the rotations)
  Scalar translation;  ///< |p_b - p_a|, the distance between the two origins
};

/// The distance between two rigid motions, as (angle, translation):
///   angle = d(R_a, R_b) = |log(R_a^-1 R_b)|,  translation = |p_b - p_a|.
/// |p_b - p_a| is the distance between the origins of the frames a and b,
/// equal to the length of the translation of a^-1 b (= R_a^T (p_b - p_a)).
/// Both parts are invariant under a change of the fixed frame,
/// d(g a, g b) = d(a, b), the translation part being the plain Euclidean
/// distance of the two positions; it is not the translation of log(a^-1 b)
/// (which depends on the rotation through V^-1).
template <typename Scalar>
inline SE3Distance<Scalar> distance(const SE3<Scalar>& a, const SE3<Scalar>& b) noexcept {
  return {distance(a.rotation(), b.rotation()), (b.translation() - a.translation()).norm()};
}

}  // namespace chasles
