// mean.hpp: the geodesic (Karcher) mean solves sum_i w_i log(M^-1 X_i) = 0,
// is invariant on both sides, converges in a few Newton steps at a 1 rad
// spread; the chordal mean is the nearest rotation to the weighted sum of
// matrices (the quaternion eigenvector mean, checked against a long double
// eigen solver). Both are unchanged by the scale of the weights (from the
// largest finite number to subnormals), a mean of translations near the
// largest finite number does not overflow, and weights that are not valid
// (negative, NaN, infinite, all 0) are reported.
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <chasles/mean.hpp>
#include <chasles/random.hpp>
#include <chasles/se3.hpp>
#include <chasles/so3.hpp>

#include "support/scalar_types.hpp"

namespace {

using chasles::SE3;
using chasles::SO3;

template <typename T>
class Mean : public ::testing::Test {};
using chasles_test::ScalarName;
using chasles_test::ScalarTypes;
TYPED_TEST_SUITE(Mean, ScalarTypes, ScalarName);

/// N rotations exp(spread * z) about a centre, z standard normal per axis.
template <typename S>
std::vector<SO3<S>> cloud(int n, double spread, unsigned seed, const SO3<S>& centre) {
  std::mt19937_64 gen(seed);
  std::normal_distribution<double> normal(0, 1);
  std::vector<SO3<S>> out;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d z(normal(gen), normal(gen), normal(gen));
    out.push_back(centre * SO3<S>::exp((spread * z).cast<S>()));
  }
  return out;
}

template <typename S>
S tolerance() {
  return std::is_same<S, float>::value ? S(2e-5) : S(1e-14);
}

TYPED_TEST(Mean, GeodesicMeanSolvesTheKarcherEquationAtOneRadianSpread) {
  using S = TypeParam;
  const SO3<S> centre = SO3<S>::exp(Eigen::Matrix<S, 3, 1>(S(0.3), S(-2), S(1)));
  const auto X = cloud<S>(1000, 1.0 / std::sqrt(3.0), 11, centre);  // rms angle 1 rad
  std::vector<S> w(X.size());
  std::mt19937_64 gen(3);
  std::uniform_real_distribution<S> u(S(0.1), S(2));
  for (auto& wi : w) wi = u(gen);
  const auto r = chasles::geodesic_mean(X.begin(), X.end(), w.begin());
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.iterations, 3);  // Newton: quadratic convergence (gradient steps: 10 to 13)
  std::printf("[ info ] %s: %d Newton steps at a 1 rad spread (N = 1000)\n",
              std::is_same<S, float>::value ? "float" : "double", r.iterations);
  Eigen::Matrix<double, 3, 1> sum = Eigen::Matrix<double, 3, 1>::Zero();
  double total = 0;
  for (std::size_t i = 0; i < X.size(); ++i) {
    sum += double(w[i]) * (r.mean.inverse() * X[i]).log().template cast<double>();
    total += double(w[i]);
  }
  EXPECT_LE((sum / total).norm(), double(tolerance<S>()));
}

TYPED_TEST(Mean, GeodesicMeanIsInvariantOnBothSides) {
  using S = TypeParam;
  const auto X = cloud<S>(200, 0.6, 5, SO3<S>());
  const SO3<S> g = SO3<S>::exp(Eigen::Matrix<S, 3, 1>(S(1), S(2), S(-0.5)));
  std::vector<SO3<S>> left, right;
  for (const auto& x : X) {
    left.push_back(g * x);
    right.push_back(x * g);
  }
  const SO3<S> m = chasles::geodesic_mean(X.begin(), X.end()).mean;
  const S tol = S(50) * tolerance<S>();
  EXPECT_TRUE(chasles::geodesic_mean(left.begin(), left.end()).mean.is_approx(g * m, tol));
  EXPECT_TRUE(chasles::geodesic_mean(right.begin(), right.end()).mean.is_approx(m * g, tol));
}

TYPED_TEST(Mean, ChordalMeanIsTheQuaternionEigenvectorMean) {
  using S = TypeParam;
  const auto X = cloud<S>(300, 0.8, 8, SO3<S>::exp(Eigen::Matrix<S, 3, 1>(S(2), S(0), S(1))));
  std::array<S, 300> w;
  for (std::size_t i = 0; i < w.size(); ++i) w[i] = S(1) + S(i % 7);
  // Markley et al.: the top eigenvector of sum_i w_i q_i q_i^T, in long double.
  Eigen::Matrix<long double, 4, 4> Q = Eigen::Matrix<long double, 4, 4>::Zero();
  for (std::size_t i = 0; i < X.size(); ++i) {
    const Eigen::Matrix<long double, 4, 1> q = X[i].quaternion().coeffs().template cast<long double>();
    Q += (long double)w[i] * q * q.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<long double, 4, 4>> es(Q);
  const Eigen::Matrix<long double, 4, 1> top = es.eigenvectors().col(3);
  const SO3<S> reference = SO3<S>::from_quaternion(Eigen::Quaternion<S>(S(top[3]), S(top[0]), S(top[1]), S(top[2])));
  const SO3<S> m = chasles::chordal_mean(X.begin(), X.end(), w.begin());
  EXPECT_TRUE(m.is_approx(reference, S(20) * std::numeric_limits<S>::epsilon()));
  // The geodesic mean differs from it at this spread (the two are not the same mean).
  EXPECT_FALSE(chasles::geodesic_mean(X.begin(), X.end(), w.begin()).mean.is_approx(m, S(1e-4)));
}

TYPED_TEST(Mean, SE3GeodesicMeanIsBiInvariantAndChordalIsPerPart) {
  using S = TypeParam;
  std::mt19937_64 gen(21);
  std::normal_distribution<S> normal(S(0), S(1));
  std::vector<SE3<S>> X, left, right;
  const SE3<S> g = SE3<S>::exp((Eigen::Matrix<S, 6, 1>() << 1, -1, 2, 0.3, 0.8, -0.2).finished());
  Eigen::Matrix<S, 3, 1> p_sum = Eigen::Matrix<S, 3, 1>::Zero();
  for (int i = 0; i < 300; ++i) {
    Eigen::Matrix<S, 6, 1> z;
    for (int k = 0; k < 6; ++k) z[k] = S(0.5) * normal(gen);
    X.push_back(SE3<S>::exp(z));
    left.push_back(g * X.back());
    right.push_back(X.back() * g);
    p_sum += X.back().translation();
  }
  const auto r = chasles::geodesic_mean(X.begin(), X.end());
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.iterations, 5);
  Eigen::Matrix<double, 6, 1> sum = Eigen::Matrix<double, 6, 1>::Zero();
  for (const auto& x : X) sum += (r.mean.inverse() * x).log().template cast<double>();
  EXPECT_LE((sum / double(X.size())).norm(), double(tolerance<S>()));
  const S tol = S(100) * tolerance<S>();
  EXPECT_TRUE(chasles::geodesic_mean(left.begin(), left.end()).mean.is_approx(g * r.mean, tol));
  EXPECT_TRUE(chasles::geodesic_mean(right.begin(), right.end()).mean.is_approx(r.mean * g, tol));
  const SE3<S> c = chasles::chordal_mean(X.begin(), X.end());
  EXPECT_TRUE(c.translation().isApprox(p_sum / S(300), S(16) * std::numeric_limits<S>::epsilon()));
}

TYPED_TEST(Mean, IterationBoundIsKeptAndReported) {
  using S = TypeParam;
  const auto X = cloud<S>(100, 1.0, 4, SO3<S>());
  const auto r = chasles::geodesic_mean(X.begin(), X.end(), 1);
  EXPECT_EQ(r.iterations, 1);
  EXPECT_FALSE(r.converged);
  std::array<SO3<S>, 3> same{SO3<S>(), SO3<S>(), SO3<S>()};
  const auto s = chasles::geodesic_mean(same.begin(), same.end());
  EXPECT_TRUE(s.converged);
  EXPECT_EQ(s.iterations, 1);
  EXPECT_TRUE(s.mean.is_approx(SO3<S>(), S(0)));
}

// ---- the scale of the weights and of the translations, and invalid weights --------------

/// Two rotations about z, 0.2 and 0.6 rad: every mean of equal weights is 0.4 rad about z.
template <typename S>
std::array<SO3<S>, 2> two_rotations() {
  return {SO3<S>::exp(Eigen::Matrix<S, 3, 1>(S(0), S(0), S(0.2))),
          SO3<S>::exp(Eigen::Matrix<S, 3, 1>(S(0), S(0), S(0.6)))};
}

TYPED_TEST(Mean, MeansAreUnchangedByTheScaleOfTheWeights) {
  // Weights at the largest finite number (their sum overflows) and at the
  // smallest subnormal (their products with the matrices underflow) give
  // the mean of the same weights scaled to 1, to rounding.
  using S = TypeParam;
  const S big = std::numeric_limits<S>::max(), tiny = std::numeric_limits<S>::denorm_min();
  const S tol = S(4) * std::numeric_limits<S>::epsilon();
  const auto X = two_rotations<S>();
  const std::array<S, 2> unit{S(1), S(1)}, three_one{S(3), S(1)};
  const SO3<S> chordal = chasles::chordal_mean(X.begin(), X.end(), unit.begin());
  const SO3<S> geodesic = chasles::geodesic_mean(X.begin(), X.end(), unit.begin()).mean;
  EXPECT_NEAR(double(chordal.log()[2]), 0.4, double(tol));
  EXPECT_NEAR(double(geodesic.log()[2]), 0.4, double(tol));
  const SO3<S> chordal31 = chasles::chordal_mean(X.begin(), X.end(), three_one.begin());
  const SO3<S> geodesic31 = chasles::geodesic_mean(X.begin(), X.end(), three_one.begin()).mean;
  for (const S scale : {big, tiny}) {
    const std::array<S, 2> w{scale, scale};
    EXPECT_TRUE(chasles::chordal_mean(X.begin(), X.end(), w.begin()).is_approx(chordal, tol)) << scale;
    const auto r = chasles::geodesic_mean(X.begin(), X.end(), w.begin());
    EXPECT_TRUE(r.converged && r.weights_valid);
    EXPECT_TRUE(r.mean.is_approx(geodesic, tol)) << scale;
  }
  // Uneven weights: 3:1 at the top of the range and among subnormals.
  for (const std::array<S, 2>& w : {std::array<S, 2>{big, big / S(3)}, std::array<S, 2>{S(3) * tiny, tiny}}) {
    EXPECT_TRUE(chasles::chordal_mean(X.begin(), X.end(), w.begin()).is_approx(chordal31, tol));
    EXPECT_TRUE(chasles::geodesic_mean(X.begin(), X.end(), w.begin()).mean.is_approx(geodesic31, tol));
  }
}

TYPED_TEST(Mean, TranslationMeansDoNotOverflow) {
  // Two poses at x = the largest finite number: their mean is there, not
  // inf (chordal) or NaN (geodesic); at x = -max and max it is 0.
  using S = TypeParam;
  const S big = std::numeric_limits<S>::max();
  const auto R = two_rotations<S>();
  const std::array<SE3<S>, 2> X{SE3<S>(R[0], Eigen::Matrix<S, 3, 1>(big, S(0), S(1))),
                                SE3<S>(R[1], Eigen::Matrix<S, 3, 1>(big, S(0), S(3)))};
  const S tol = S(4) * std::numeric_limits<S>::epsilon();
  const std::array<S, 2> w{big, big};
  const std::array<SE3<S>, 3> means{chasles::chordal_mean(X.begin(), X.end()),
                                    chasles::chordal_mean(X.begin(), X.end(), w.begin()),
                                    chasles::geodesic_mean(X.begin(), X.end()).mean};
  for (const SE3<S>& m : means) {
    EXPECT_EQ(m.translation()[0], big);
    EXPECT_EQ(m.translation()[1], S(0));
    EXPECT_NEAR(double(m.translation()[2]), 2.0, double(tol));
    EXPECT_NEAR(double(m.rotation().log()[2]), 0.4, double(tol));
  }
  const std::array<SE3<S>, 2> apart{SE3<S>(R[0], Eigen::Matrix<S, 3, 1>(-big, S(0), S(0))),
                                    SE3<S>(R[0], Eigen::Matrix<S, 3, 1>(big, S(0), S(0)))};
  EXPECT_EQ(chasles::chordal_mean(apart.begin(), apart.end()).translation(), (Eigen::Matrix<S, 3, 1>::Zero()));
}

TYPED_TEST(Mean, InvalidWeightsAreReported) {
  // A negative, NaN or infinite weight, all weights 0 or no element: not a
  // mean. mean_weights_valid says so, geodesic_mean reports it
  // (weights_valid false, 0 iterations, not converged), both give the identity.
  using S = TypeParam;
  const auto X = two_rotations<S>();
  const S nan = std::numeric_limits<S>::quiet_NaN(), inf = std::numeric_limits<S>::infinity();
  for (const std::array<S, 2>& w :
       {std::array<S, 2>{S(-1), S(2)}, std::array<S, 2>{nan, S(1)}, std::array<S, 2>{S(1), inf},
        std::array<S, 2>{S(0), S(0)}, std::array<S, 2>{S(2), -std::numeric_limits<S>::denorm_min()}}) {
    EXPECT_FALSE(chasles::mean_weights_valid(X.begin(), X.end(), w.begin())) << w[0] << " " << w[1];
    EXPECT_TRUE(chasles::chordal_mean(X.begin(), X.end(), w.begin()).is_approx(SO3<S>(), S(0)));
    const auto r = chasles::geodesic_mean(X.begin(), X.end(), w.begin());
    EXPECT_FALSE(r.weights_valid);
    EXPECT_FALSE(r.converged);
    EXPECT_EQ(r.iterations, 0);
    EXPECT_TRUE(r.mean.is_approx(SO3<S>(), S(0)));
  }
  EXPECT_FALSE(chasles::geodesic_mean(X.begin(), X.begin()).weights_valid);  // no element
  const std::array<S, 2> zero_one{S(0), S(1)};
  EXPECT_TRUE(chasles::mean_weights_valid(X.begin(), X.end(), zero_one.begin()));
  const auto r = chasles::geodesic_mean(X.begin(), X.end(), zero_one.begin());
  EXPECT_TRUE(r.weights_valid && r.converged);
  EXPECT_TRUE(r.mean.is_approx(X[1], S(4) * std::numeric_limits<S>::epsilon()));
}

}  // namespace
