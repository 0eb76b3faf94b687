// The arms the C++ tests, benchmarks and fuzz targets share: the UR5 of
// Modern Robotics (on a prismatic rail for a seventh joint) and a
// Panda-like 7R arm with link inertias and position limits.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>

#include <Eigen/Core>

#include "chasles/kinematics.hpp"
#include "chasles/se3.hpp"
#include "chasles/spatial_inertia.hpp"

namespace chasles_test {

/// The UR5 of Modern Robotics (Lynch and Park, example 4.5), metres: its six
/// space screws (v, w) after a prismatic rail along (1, 2, 0) / sqrt(5)
/// (column 0).
template <typename S>
Eigen::Matrix<S, 6, 7> railed_ur5_screws() {
  const S W1 = S(0.109), L1 = S(0.425), L2 = S(0.392), H1 = S(0.089), H2 = S(0.095);
  Eigen::Matrix<S, 6, 7> screws;
  screws.col(0) << S(1 / std::sqrt(5.0)), S(2 / std::sqrt(5.0)), 0, 0, 0, 0;
  screws.col(1) << 0, 0, 0, 0, 0, 1;
  screws.col(2) << -H1, 0, 0, 0, 1, 0;
  screws.col(3) << -H1, 0, L1, 0, 1, 0;
  screws.col(4) << -H1, 0, L1 + L2, 0, 1, 0;
  screws.col(5) << -W1, L1 + L2, 0, 0, 0, -1;
  screws.col(6) << H2 - H1, 0, L1 + L2, 0, 1, 0;
  return screws;
}

/// The UR5's home pose (example 4.5).
template <typename S>
chasles::SE3<S> ur5_home() {
  const S W1 = S(0.109), W2 = S(0.082), L1 = S(0.425), L2 = S(0.392), H1 = S(0.089), H2 = S(0.095);
  Eigen::Matrix<S, 4, 4> M;
  M << -1, 0, 0, L1 + L2, 0, 0, 1, W1 + W2, 0, 1, 0, H1 - H2, 0, 0, 0, 1;
  return chasles::SE3<S>::from_matrix_unchecked(M);
}

/// Chain type C (a chasles::Chain) of the UR5: n = 6, or n = 7 on its rail.
template <typename C>
C ur5_chain(int n = 6) {
  using S = typename C::Scalar;
  const typename C::Screws screws = railed_ur5_screws<S>().rightCols(n);
  return C(screws, ur5_home<S>());
}

/// A Panda-like 7R arm: the Franka Panda's joint axes and points at zero and
/// its position limits, links as uniform boxes of its link masses.
template <typename S>
struct PandaLike {
  Eigen::Matrix<S, 6, 7> screws;
  chasles::SE3<S> home;
  std::array<chasles::SpatialInertia<S>, 7> inertias;
  Eigen::Matrix<S, 7, 1> lower, upper;

  PandaLike() {
    using V3 = Eigen::Vector3d;
    const V3 axis[7] = {V3(0, 0, 1), V3(0, -1, 0), V3(0, 0, 1), V3(0, 1, 0), V3(0, 0, 1), V3(0, 1, 0), V3(0, 0, -1)};
    const V3 point[7] = {V3(0, 0, 0.333), V3(0, 0, 0.333), V3(0, 0, 0.649),    V3(0.0825, 0, 0.649),
                         V3(0, 0, 1.033), V3(0, 0, 1.033), V3(0.088, 0, 1.033)};
    const double mass[7] = {4.97, 0.65, 3.23, 3.59, 1.23, 1.67, 0.74};
    const V3 box[7] = {V3(0.1, 0.1, 0.3),    V3(0.1, 0.1, 0.3),   V3(0.1, 0.1, 0.3),  V3(0.1, 0.1, 0.3),
                       V3(0.08, 0.08, 0.35), V3(0.08, 0.08, 0.1), V3(0.06, 0.06, 0.1)};
    const V3 com[7] = {V3(0, -0.03, 0.28), V3(0, -0.07, 0.37), V3(0.04, 0.02, 0.6), V3(-0.04, 0.04, 0.7),
                       V3(0, 0.04, 0.8),   V3(0.04, 0, 1.02),  V3(0.09, 0, 0.98)};
    const double lo[7] = {-2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973};
    const double hi[7] = {2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973};
    for (int i = 0; i < 7; ++i) {
      screws.col(i) = chasles::Chain<double, 7>::revolute_screw(point[i], axis[i]).template cast<S>();
      const double x = box[i][0], y = box[i][1], z = box[i][2], m = mass[i];
      // A uniform box about its center: m (b^2 + c^2) / 12 about each axis.
      const V3 moments(m * (y * y + z * z) / 12, m * (x * x + z * z) / 12, m * (x * x + y * y) / 12);
      inertias[static_cast<std::size_t>(i)] =
          chasles::SpatialInertia<double>(m, com[i], moments.asDiagonal().toDenseMatrix()).template cast<S>();
      lower(i) = S(lo[i]);
      upper(i) = S(hi[i]);
    }
    Eigen::Matrix4d M;
    M << 1, 0, 0, 0.088, 0, -1, 0, 0, 0, 0, -1, 0.926, 0, 0, 0, 1;
    home = chasles::SE3<double>::from_matrix_unchecked(M).template cast<S>();
  }
};

}  // namespace chasles_test
