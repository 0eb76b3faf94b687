// chasles: random rotations and rigid motions: uniform (Haar) rotations,
// poses with a uniform rotation and a translation uniform in a box, and
// Gaussian samples about a pose with a tangent covariance.
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

#include "chasles/se3.hpp"
#include "chasles/so3.hpp"

namespace chasles {

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

/// A uniform (Haar) random rotation: so3_from_uniforms of three uniforms
/// drawn from gen.
template <typename Scalar, typename Generator>
inline SO3<Scalar> random_rotation(Generator& gen) noexcept {
  std::uniform_real_distribution<Scalar> uniform(Scalar(0), Scalar(1));
  const Scalar u0 = uniform(gen), u1 = uniform(gen), u2 = uniform(gen);
  return so3_from_uniforms(Eigen::Matrix<Scalar, 3, 1>(u0, u1, u2));
}

/// A random rigid motion: a uniform rotation and a translation uniform in
/// the box [low, high] (componentwise), independent of each other.
template <typename Scalar, typename Generator>
inline SE3<Scalar> random_pose(Generator& gen, const Eigen::Matrix<Scalar, 3, 1>& low,
                               const Eigen::Matrix<Scalar, 3, 1>& high) noexcept {
  const SO3<Scalar> R = random_rotation<Scalar>(gen);
  std::uniform_real_distribution<Scalar> uniform(Scalar(0), Scalar(1));
  Eigen::Matrix<Scalar, 3, 1> p;
  for (int i = 0; i < 3; ++i) p[i] = low[i] + (high[i] - low[i]) * uniform(gen);
  return SE3<Scalar>(R, p);
}

/// A Gaussian sample about `mean` from standard normals z: the right
/// perturbation X = mean exp(L z), so that the tangent error
/// log(mean^-1 X) = L z has the covariance L L^T (L the lower Cholesky
/// factor of the covariance; the Jacobians' right, local convention).
template <typename Scalar>
inline SO3<Scalar> so3_gaussian_from_normals(const SO3<Scalar>& mean, const Eigen::Matrix<Scalar, 3, 3>& L,
                                             const Eigen::Matrix<Scalar, 3, 1>& z) noexcept {
  return mean * SO3<Scalar>::exp(L * z);
}

/// The same on SE(3): X = mean exp(L z), z of order (v, w) like the twists,
/// covariance L L^T (6x6) of the twist log(mean^-1 X).
template <typename Scalar>
inline SE3<Scalar> se3_gaussian_from_normals(const SE3<Scalar>& mean, const Eigen::Matrix<Scalar, 6, 6>& L,
                                             const Eigen::Matrix<Scalar, 6, 1>& z) noexcept {
  return mean * SE3<Scalar>::exp(Eigen::Matrix<Scalar, 6, 1>(L * z));
}

/// A Gaussian rotation about `mean` with tangent covariance L L^T, standard
/// normals drawn from gen.
template <typename Scalar, typename Generator>
inline SO3<Scalar> random_gaussian(Generator& gen, const SO3<Scalar>& mean,
                                   const Eigen::Matrix<Scalar, 3, 3>& L) noexcept {
  std::normal_distribution<Scalar> normal(Scalar(0), Scalar(1));
  Eigen::Matrix<Scalar, 3, 1> z;
  for (int i = 0; i < 3; ++i) z[i] = normal(gen);
  return so3_gaussian_from_normals(mean, L, z);
}

/// A Gaussian rigid motion about `mean` with tangent covariance L L^T
/// (twist order (v, w)), standard normals drawn from gen.
template <typename Scalar, typename Generator>
inline SE3<Scalar> random_gaussian(Generator& gen, const SE3<Scalar>& mean,
                                   const Eigen::Matrix<Scalar, 6, 6>& L) noexcept {
  std::normal_distribution<Scalar> normal(Scalar(0), Scalar(1));
  Eigen::Matrix<Scalar, 6, 1> z;
  for (int i = 0; i < 6; ++i) z[i] = normal(gen);
  return se3_gaussian_from_normals(mean, L, z);
}

}  // namespace chasles
