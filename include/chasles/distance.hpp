// chasles: distances between rotations and between rigid motions.
#pragma once

#include <Eigen/Core>

#include "chasles/se3.hpp"
#include "chasles/so3.hpp"

namespace chasles {

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
