// The arguments that chasles takes in any type that converts to a group's
// Scalar (include/chasles/detail/arguments.hpp): a tangent vector as any
// Eigen expression (rplus(X, 0.1 * dx)), a Twist for SE(3), interpolate's t
// as any arithmetic type (interpolate(a, b, 0.5) on float groups), and
// twists and wrenches scaled by a double or an int. Building this file is
// the test that all of these compile (it is built with -Wconversion
// -Wdouble-promotion as errors: the conversions are chasles' own, explicit,
// and leave the caller's code warning-free); running it checks that each
// gives the very numbers of the same call spelled in the group's Scalar.
#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <chasles/chasles.hpp>

namespace {

using namespace chasles;

TEST(Arguments, So3TangentExpressionsOnFloat) {
  const SO3f X = SO3f::exp(Eigen::Vector3f(0.3f, -0.2f, 0.1f));
  const Eigen::Vector3f dx(0.5f, 1.0f, -2.0f);
  const Eigen::Vector3f step = Eigen::Vector3f(0.1f * dx);  // what 0.1 * dx is, in float
  EXPECT_TRUE(rplus(X, 0.1 * dx).matrix() == rplus(X, step).matrix());
  EXPECT_TRUE(lplus(0.1 * dx, X).matrix() == lplus(step, X).matrix());
  // A segment of a larger vector, a Map of a buffer, a double vector.
  Eigen::Matrix<float, 6, 1> buffer;
  buffer << 9.0f, 0.05f, 0.1f, -0.2f, 9.0f, 9.0f;
  const Eigen::Vector3f seg = buffer.segment<3>(1);
  EXPECT_TRUE(rplus(X, buffer.segment<3>(1)).matrix() == rplus(X, seg).matrix());
  EXPECT_TRUE(rplus(X, Eigen::Map<const Eigen::Vector3f>(buffer.data() + 1)).matrix() == rplus(X, seg).matrix());
  const Eigen::Vector3d dxd(0.05, 0.1, -0.2);
  EXPECT_TRUE(rplus(X, dxd).matrix() == rplus(X, Eigen::Vector3f(dxd.cast<float>())).matrix());
  EXPECT_TRUE(lplus(dxd, X).matrix() == lplus(Eigen::Vector3f(dxd.cast<float>()), X).matrix());
}

TEST(Arguments, Se3TangentExpressionsAndTwistsOnFloat) {
  const Eigen::Matrix<float, 6, 1> xi0 = (Eigen::Matrix<float, 6, 1>() << 1, 2, 3, 0.3f, -0.2f, 0.1f).finished();
  const SE3f X = SE3f::exp(xi0);
  const Eigen::Matrix<float, 6, 1> dx = (Eigen::Matrix<float, 6, 1>() << 0.5f, 1, -2, 0.1f, 0.2f, 0.3f).finished();
  const Eigen::Matrix<float, 6, 1> step = Eigen::Matrix<float, 6, 1>(0.1f * dx);
  EXPECT_TRUE(rplus(X, 0.1 * dx).matrix() == rplus(X, step).matrix());
  EXPECT_TRUE(lplus(0.1 * dx, X).matrix() == lplus(step, X).matrix());
  const Twistf tw(dx);
  EXPECT_TRUE((0.1 * tw).vector() == step);
  EXPECT_TRUE((tw * 0.1).vector() == step);
  EXPECT_TRUE(rplus(X, 0.1 * tw).matrix() == rplus(X, step).matrix());
  EXPECT_TRUE(rplus(X, tw * 0.1).matrix() == rplus(X, step).matrix());
  EXPECT_TRUE(lplus(0.1 * tw, X).matrix() == lplus(step, X).matrix());
  EXPECT_TRUE(rplus(X, tw).matrix() == rplus(X, dx).matrix());
  EXPECT_TRUE((2 * tw).vector() == (Eigen::Matrix<float, 6, 1>(2.0f * dx)));
  const Wrenchf F(dx);
  EXPECT_TRUE((0.1 * F).vector() == step);
  EXPECT_TRUE((F * 0.1).vector() == step);
  EXPECT_TRUE((F * 2).vector() == (Eigen::Matrix<float, 6, 1>(2.0f * dx)));
}

TEST(Arguments, InterpolateWithAnyArithmeticT) {
  const SO3f a = SO3f::exp(Eigen::Vector3f(0.3f, -0.2f, 0.1f)), b = SO3f::exp(Eigen::Vector3f(-1.0f, 0.5f, 2.0f));
  EXPECT_TRUE(interpolate(a, b, 0.5).matrix() == interpolate(a, b, 0.5f).matrix());
  EXPECT_TRUE(interpolate(a, b, 0.3).matrix() == interpolate(a, b, 0.3f).matrix());
  EXPECT_TRUE(interpolate(a, b, 1).matrix() == interpolate(a, b, 1.0f).matrix());
  EXPECT_TRUE(interpolate_jacobian_t(a, b, 0.5) == interpolate_jacobian_t(a, b, 0.5f));
  const SE3f g = SE3f::exp((Eigen::Matrix<float, 6, 1>() << 1, 2, 3, 0.3f, -0.2f, 0.1f).finished());
  const SE3f h = SE3f::exp((Eigen::Matrix<float, 6, 1>() << -1, 0, 2, -1.0f, 0.5f, 2.0f).finished());
  EXPECT_TRUE(interpolate(g, h, 0.25).matrix() == interpolate(g, h, 0.25f).matrix());
  EXPECT_TRUE(interpolate(g, h, 0).matrix() == interpolate(g, h, 0.0f).matrix());
  EXPECT_TRUE(interpolate_jacobian_t(g, h, 0.5) == interpolate_jacobian_t(g, h, 0.5f));
  // double groups: an int t, and a float t.
  const SE3d gd = g.cast<double>(), hd = h.cast<double>();
  EXPECT_TRUE(interpolate(gd, hd, 1).matrix() == interpolate(gd, hd, 1.0).matrix());
  EXPECT_TRUE(interpolate(gd, hd, 0.5f).matrix() == interpolate(gd, hd, 0.5).matrix());
}

TEST(Arguments, AutodiffGroups) {
  using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;
  const SO3<AD> a = SO3<AD>::identity();
  const SO3<AD> b = SO3<AD>::exp(Eigen::Matrix<AD, 3, 1>(AD(0.0), AD(0.0), AD(1.0)));
  // t as a double, and as an autodiff scalar carrying d/dt.
  const SO3<AD> half = interpolate(a, b, 0.5);
  const SO3<AD> half_t = interpolate(a, b, AD(0.5, 1, 0));
  EXPECT_DOUBLE_EQ(half.matrix()(1, 0).value(), half_t.matrix()(1, 0).value());
  EXPECT_DOUBLE_EQ(half_t.matrix()(1, 0).derivatives()[0], std::cos(0.5));  // d sin(t) / dt
  // A double tangent vector on an autodiff group.
  EXPECT_DOUBLE_EQ(rplus(a, Eigen::Vector3d(0, 0, 0.5)).matrix()(1, 0).value(), std::sin(0.5));
}

}  // namespace
