// Test support: the typed suites that run over every group of the library
// and both scalars (test_mean, test_random, test_distance, test_spline,
// test_bspline: what is written once over the group's interface). A new
// group joins all of them by its name below and its two entries in
// AllGroups.
#pragma once

#include <random>
#include <string>
#include <type_traits>

#include <gtest/gtest.h>
#include <Eigen/Core>

#include <chasles/se2.hpp>
#include <chasles/se23.hpp>
#include <chasles/se3.hpp>
#include <chasles/sim3.hpp>
#include <chasles/so2.hpp>
#include <chasles/so3.hpp>

namespace chasles_test {

template <typename G>
struct GroupLabel;
template <typename S>
struct GroupLabel<chasles::SO2<S>> {
  static constexpr const char* name = "SO2";
};
template <typename S>
struct GroupLabel<chasles::SE2<S>> {
  static constexpr const char* name = "SE2";
};
template <typename S>
struct GroupLabel<chasles::SO3<S>> {
  static constexpr const char* name = "SO3";
};
template <typename S>
struct GroupLabel<chasles::SE3<S>> {
  static constexpr const char* name = "SE3";
};
template <typename S>
struct GroupLabel<chasles::Sim3<S>> {
  static constexpr const char* name = "Sim3";
};
template <typename S>
struct GroupLabel<chasles::SE23<S>> {
  static constexpr const char* name = "SE23";
};

using AllGroups =
    ::testing::Types<chasles::SO2<float>, chasles::SO2<double>, chasles::SE2<float>, chasles::SE2<double>,
                     chasles::SO3<float>, chasles::SO3<double>, chasles::SE3<float>, chasles::SE3<double>,
                     chasles::Sim3<float>, chasles::Sim3<double>, chasles::SE23<float>, chasles::SE23<double>>;

/// GoogleTest's names for AllGroups: "SO2f", "Sim3d", ...
struct AllGroupsName {
  template <typename G>
  static std::string GetName(int) {
    return std::string(GroupLabel<G>::name) + (std::is_same<typename G::Scalar, float>::value ? "f" : "d");
  }
};

/// A tangent vector with independent N(0, spread^2) coordinates.
template <typename G, typename Generator>
typename G::Tangent normal_tangent(Generator& gen, double spread) {
  std::normal_distribution<double> normal(0.0, spread);
  typename G::Tangent x;
  for (int k = 0; k < G::DoF; ++k) x[k] = typename G::Scalar(normal(gen));
  return x;
}

}  // namespace chasles_test
