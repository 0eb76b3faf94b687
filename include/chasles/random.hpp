// chasles: random elements of the groups: uniform (Haar) rotations of the
// compact groups SO(2) and SO(3); elements with a uniform rotation and their
// Euclidean part uniform in a box (group_parts.hpp: the translation of
// SE(2) and SE(3), the translation and the scale's logarithm of Sim(3)); and
// Gaussian samples about any element with a tangent covariance, written once
// over the group's exp.
//
// Each sampler is a deterministic map of uniforms or standard normals (the
// `*_from_*` functions, what the Python package calls with numpy's
// Generator as the source of randomness) and an overload that draws them
// from any standard UniformRandomBitGenerator (std::mt19937_64, ...) with
// the standard distributions, which do not allocate. Real scalars only
// (float, double): the distributions are not defined for autodiff scalars.
#pragma once

#include <random>

#include <Eigen/Core>

#include "chasles/group_parts.hpp"
#include "chasles/lie_group.hpp"
#include "chasles/se3.hpp"
#include "chasles/so2.hpp"
#include "chasles/so3.hpp"

namespace chasles {

/// The uniform random plane rotation of one uniform u in [0, 1): the angle
/// theta = pi (2u - 1), uniform in [-pi, pi) (2u - 1 is exact for the
/// uniforms of numpy and of std::uniform_real_distribution, multiples of
/// 2^-53), so that R is uniform (Haar) on SO(2); u = 1/2 gives the identity.
template <typename Scalar>
inline SO2<Scalar> so2_from_uniforms(const Eigen::Matrix<Scalar, 1, 1>& u) noexcept {
  return SO2<Scalar>::exp(Scalar(3.14159265358979323846) * (Scalar(2) * u[0] - Scalar(1)));
}

/// The uniform (Haar) random rotation of three uniforms u in [0, 1)^3, by
/// Shoemake's method ("Uniform random rotations", Graphics Gems III, 1992):
///   q = (sqrt(1 - u0) sin(2 pi u1), sqrt(1 - u0) cos(2 pi u1),
///        sqrt(u0) sin(2 pi u2),     sqrt(u0) cos(2 pi u2))   (x, y, z, w),
/// a unit quaternion uniform on S^3, so R(q) is uniform on SO(3): its
/// angle theta has the density (1 - cos theta) / pi on [0, pi].
template <typename Scalar>
inline SO3<Scalar> so3_from_uniforms(const Eigen::Matrix<Scalar, 3, 1>& u) noexcept {
  using std::cos;
  using std::sin;
  using std::sqrt;
  const Scalar two_pi = Scalar(2 * 3.14159265358979323846);
  const Scalar r1 = sqrt(Scalar(1) - u[0]), r2 = sqrt(u[0]);
  const Scalar a = two_pi * u[1], b = two_pi * u[2];
  return SO3<Scalar>::from_quaternion(Eigen::Quaternion<Scalar>(r2 * cos(b), r1 * sin(a), r1 * cos(a), r2 * sin(b)));
}

/// The map from U uniforms to a uniform (Haar) rotation of a compact
/// rotation group: so2_from_uniforms (U = 1), so3_from_uniforms (U = 3).
template <typename Rotation>
struct UniformRotation;
template <typename Scalar>
struct UniformRotation<SO2<Scalar>> {
  static constexpr int U = 1;
  static SO2<Scalar> map(const Eigen::Matrix<Scalar, 1, 1>& u) noexcept { return so2_from_uniforms(u); }
};
template <typename Scalar>
struct UniformRotation<SO3<Scalar>> {
  static constexpr int U = 3;
  static SO3<Scalar> map(const Eigen::Matrix<Scalar, 3, 1>& u) noexcept { return so3_from_uniforms(u); }
};

/// The element with the uniform rotation of the uniforms u (U of them, as
/// UniformRotation) and the Euclidean part low + (high - low) v, v the K
/// uniforms in [0, 1) (componentwise; GroupParts): the map behind
/// random_pose, for the Python package's samplers.
template <typename G>
inline G element_from_uniforms(
    const Eigen::Matrix<typename G::Scalar, UniformRotation<typename GroupParts<G>::Rotation>::U, 1>& u,
    const typename GroupParts<G>::Vector& v, const typename GroupParts<G>::Vector& low,
    const typename GroupParts<G>::Vector& high) noexcept {
  using Parts = GroupParts<G>;
  typename Parts::Vector p;
  for (int i = 0; i < Parts::K; ++i) p[i] = low[i] + (high[i] - low[i]) * v[i];
  return Parts::make(UniformRotation<typename Parts::Rotation>::map(u), p);
}

/// A uniform (Haar) random element of a compact rotation group (SO2, SO3):
/// UniformRotation's map of U uniforms drawn from gen, in order.
template <typename G, typename Generator>
inline G random_uniform(Generator& gen) noexcept {
  using Scalar = typename G::Scalar;
  std::uniform_real_distribution<Scalar> uniform(Scalar(0), Scalar(1));
  Eigen::Matrix<Scalar, UniformRotation<G>::U, 1> u;
  for (int i = 0; i < UniformRotation<G>::U; ++i) u[i] = uniform(gen);
  return UniformRotation<G>::map(u);
}

/// A uniform (Haar) random rotation: so3_from_uniforms of three uniforms
/// drawn from gen.
template <typename Scalar, typename Generator>
inline SO3<Scalar> random_rotation(Generator& gen) noexcept {
  return random_uniform<SO3<Scalar>>(gen);
}

/// A random element with a uniform rotation (drawn first, as
/// random_uniform) and its Euclidean part uniform in the box [low, high]
/// (componentwise, K uniforms drawn next; GroupParts), independent of each
/// other: the translation of SE(2) and SE(3) (poses in a box), the
/// translation and the scale's logarithm of Sim(3) (a scale log-uniform in
/// [e^low_3, e^high_3]).
template <typename G, typename Generator, detail::EnableIfLieGroup<G> = 0>
inline G random_pose(Generator& gen, const typename GroupParts<G>::Vector& low,
                     const typename GroupParts<G>::Vector& high) noexcept {
  using Scalar = typename G::Scalar;
  using Parts = GroupParts<G>;
  using Rotation = typename Parts::Rotation;
  const Rotation R = random_uniform<Rotation>(gen);
  std::uniform_real_distribution<Scalar> uniform(Scalar(0), Scalar(1));
  typename Parts::Vector p;
  for (int i = 0; i < Parts::K; ++i) p[i] = low[i] + (high[i] - low[i]) * uniform(gen);
  return Parts::make(R, p);
}

/// A random rigid motion: a uniform rotation and a translation uniform in
/// the box [low, high] (componentwise), independent of each other
/// (random_pose<SE3<Scalar>>, the Scalar deduced).
template <typename Scalar, typename Generator, std::enable_if_t<!detail::IsLieGroup<Scalar>::value, int> = 0>
inline SE3<Scalar> random_pose(Generator& gen, const Eigen::Matrix<Scalar, 3, 1>& low,
                               const Eigen::Matrix<Scalar, 3, 1>& high) noexcept {
  return random_pose<SE3<Scalar>>(gen, low, high);
}

/// A Gaussian sample about `mean` from standard normals z: the right
/// perturbation X = mean exp(L z), so that the tangent error
/// log(mean^-1 X) = L z has the covariance L L^T (L the lower Cholesky
/// factor of the covariance; the Jacobians' right, local convention), z in
/// the order of the group's tangent ((v, w) for the twists), for every group.
template <typename G, detail::EnableIfLieGroup<G> = 0>
inline G gaussian_from_normals(const G& mean, const typename G::AdjointMatrix& L,
                               const typename G::Tangent& z) noexcept {
  return mean * G::exp(typename G::Tangent(L * z));
}

/// gaussian_from_normals on SO(3) (covariance of the rotation vector).
template <typename Scalar>
inline SO3<Scalar> so3_gaussian_from_normals(const SO3<Scalar>& mean, const Eigen::Matrix<Scalar, 3, 3>& L,
                                             const Eigen::Matrix<Scalar, 3, 1>& z) noexcept {
  return gaussian_from_normals(mean, L, z);
}

/// gaussian_from_normals on SE(3): z of order (v, w) like the twists,
/// covariance L L^T (6x6) of the twist log(mean^-1 X).
template <typename Scalar>
inline SE3<Scalar> se3_gaussian_from_normals(const SE3<Scalar>& mean, const Eigen::Matrix<Scalar, 6, 6>& L,
                                             const Eigen::Matrix<Scalar, 6, 1>& z) noexcept {
  return gaussian_from_normals(mean, L, z);
}

/// A Gaussian element about `mean` with tangent covariance L L^T (in the
/// order of the group's tangent), DoF standard normals drawn from gen:
/// mean exp(L z), for every group.
template <typename G, typename Generator, detail::EnableIfLieGroup<G> = 0>
inline G random_gaussian(Generator& gen, const G& mean, const typename G::AdjointMatrix& L) noexcept {
  using Scalar = typename G::Scalar;
  std::normal_distribution<Scalar> normal(Scalar(0), Scalar(1));
  typename G::Tangent z;
  for (int i = 0; i < G::DoF; ++i) z[i] = normal(gen);
  return gaussian_from_normals(mean, L, z);
}

}  // namespace chasles
