// Test samples shared by the C++ suites: fixed seeds, and the elements where
// Lie-group code breaks: identity, tiny angles, near pi, exactly pi, random.
#pragma once

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include <Eigen/Core>

namespace chasles_test {

constexpr std::uint32_t kSeed = 20261121u;
constexpr long double kPi = 3.141592653589793238462643383279502884L;

/// A unit vector drawn uniformly on the sphere.
template <typename Real>
Eigen::Matrix<Real, 3, 1> random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Vector3d u(n(rng), n(rng), n(rng));
  return (u / u.norm()).cast<Real>();
}

/// Rotation vectors: zero, the special angles along fixed and random axes,
/// and `n_random` random ones with angle uniform in [0, pi].
template <typename Real>
std::vector<Eigen::Matrix<Real, 3, 1>> rotation_vectors(int n_random = 64, std::uint32_t seed = kSeed) {
  using V = Eigen::Matrix<Real, 3, 1>;
  std::mt19937_64 rng(seed);
  const Real pi = Real(kPi);
  std::vector<V> out;
  out.push_back(V::Zero());
  const Real angles[] = {Real(1e-30), Real(1e-12), Real(1e-8),      Real(1e-4),      Real(0.1),
                         Real(1),     pi / 2,      pi - Real(1e-4), pi - Real(1e-6), pi};
  const V axes[] = {V::UnitX(), V::UnitZ(), V(1, 1, 0).normalized(), V(1, -2, 3).normalized()};
  for (Real a : angles)
    for (const V& ax : axes) out.push_back(a * ax);
  std::uniform_real_distribution<double> u(0.0, double(kPi));
  for (int i = 0; i < n_random; ++i) out.push_back(Real(u(rng)) * random_unit<Real>(rng));
  return out;
}

/// (a, b) as one 6-vector, element by element: Eigen's comma initializer of a
/// float 6-vector from two 3-vectors trips GCC 12's -Warray-bounds (a false
/// positive, fatal under -Werror), as noted in include/chasles/detail/approx.hpp.
template <typename Real>
Eigen::Matrix<Real, 6, 1> stack6(const Eigen::Matrix<Real, 3, 1>& a, const Eigen::Matrix<Real, 3, 1>& b) {
  Eigen::Matrix<Real, 6, 1> out;
  for (int i = 0; i < 3; ++i) {
    out[i] = a[i];
    out[i + 3] = b[i];
  }
  return out;
}

/// Twists (v, w): the rotation vectors above paired with translations of
/// size 0, 1e-6, 1 and 100 in random directions, pure translations, and
/// random twists.
template <typename Real>
std::vector<Eigen::Matrix<Real, 6, 1>> twists(int n_random = 64, std::uint32_t seed = kSeed) {
  using V6 = Eigen::Matrix<Real, 6, 1>;
  std::mt19937_64 rng(seed + 1);
  std::vector<V6> out;
  const Real sizes[] = {Real(0), Real(1e-6), Real(1), Real(100)};
  int k = 0;
  for (const auto& w : rotation_vectors<Real>(n_random, seed)) {
    out.push_back(stack6<Real>(sizes[k++ % 4] * random_unit<Real>(rng), w));
  }
  for (Real s : sizes) {
    out.push_back(stack6<Real>(s * random_unit<Real>(rng), Eigen::Matrix<Real, 3, 1>::Zero()));
  }
  return out;
}

}  // namespace chasles_test
