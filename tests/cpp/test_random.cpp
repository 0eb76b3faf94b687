// random.hpp: the maps from uniforms / normals checked exactly, and the
// samplers checked statistically at fixed seeds: the angle of uniform
// rotations follows the Haar CDF (theta - sin theta) / pi (Kolmogorov-
// Smirnov), their mean matrix tends to 0, and Gaussian samples have the
// tangent covariance they were given.
//
// The samplers written once over the groups (RandomOfEveryGroup, over SO2,
// SE2, SO3, SE3, Sim3 and both scalars): Gaussian samples have the tangent
// covariance given (each entry of the sample covariance within 5 of its
// standard deviations), uniform rotations of SO(2) have a uniform angle and
// those of every rotation part the Haar CDF (Kolmogorov-Smirnov at the 0.1 %
// level), the Euclidean parts of random_pose are uniform in their box (the
// scale of Sim(3) log-uniform: KS on each coordinate).
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <chasles/random.hpp>
#include <chasles/se2.hpp>
#include <chasles/se3.hpp>
#include <chasles/sim3.hpp>
#include <chasles/so2.hpp>
#include <chasles/so3.hpp>

#include "support/all_groups.hpp"
#include "support/scalar_types.hpp"

namespace {

using chasles::SE3;
using chasles::SO3;

template <typename T>
class Random : public ::testing::Test {};
using chasles_test::ScalarName;
using chasles_test::ScalarTypes;
TYPED_TEST_SUITE(Random, ScalarTypes, ScalarName);

constexpr double kPi = 3.14159265358979323846;

/// The Kolmogorov-Smirnov statistic sup |F_n - F| of samples against a CDF.
template <typename Cdf>
double ks_statistic(std::vector<double> x, Cdf cdf) {
  std::sort(x.begin(), x.end());
  const double n = double(x.size());
  double d = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double f = cdf(x[i]);
    d = std::max(d, std::max(double(i + 1) / n - f, f - double(i) / n));
  }
  return d;
}

TYPED_TEST(Random, ShoemakesMapAtKnownPoints) {
  using S = TypeParam;
  using V3 = Eigen::Matrix<S, 3, 1>;
  const S tol = S(8) * std::numeric_limits<S>::epsilon();
  // u0 = 1, u2 = 0: q = (0, 0, 0, 1), the identity.
  EXPECT_TRUE(chasles::so3_from_uniforms(V3(S(1), S(0), S(0))).is_approx(SO3<S>(), tol));
  // u0 = 0, u1 = 0: q = (0, 1, 0, 0), a half turn about y.
  const Eigen::Matrix<S, 3, 3> half_turn_y = Eigen::Matrix<S, 3, 1>(S(-1), S(1), S(-1)).asDiagonal();
  EXPECT_TRUE(chasles::so3_from_uniforms(V3(S(0), S(0), S(0))).matrix().isApprox(half_turn_y, tol));
  // u0 = 1/2, u1 = 1/4, u2 = 0: q = (1, 0, 0, 1) / sqrt(2), a quarter turn about x.
  const SO3<S> quarter_x = SO3<S>::exp(V3(S(kPi / 2), S(0), S(0)));
  EXPECT_TRUE(chasles::so3_from_uniforms(V3(S(0.5), S(0.25), S(0))).is_approx(quarter_x, tol));
}

TYPED_TEST(Random, UniformRotationAnglesFollowTheHaarDistribution) {
  using S = TypeParam;
  std::mt19937_64 gen(12345);
  const int n = 20000;
  std::vector<double> angles;
  Eigen::Matrix3d sum = Eigen::Matrix3d::Zero();
  Eigen::Vector4d quaternion_sum = Eigen::Vector4d::Zero();
  for (int i = 0; i < n; ++i) {
    const SO3<S> R = chasles::random_rotation<S>(gen);
    ASSERT_LE(SO3<S>::rotation_defect(R.matrix()), S(16) * std::numeric_limits<S>::epsilon());
    angles.push_back(double(R.angle()));
    sum += R.matrix().template cast<double>();
    // |q| components: each |q_i| has the same distribution on S^3 ...
    quaternion_sum += R.quaternion().coeffs().template cast<double>().cwiseAbs();
  }
  // Kolmogorov-Smirnov at the 0.1 % level: D < 1.95 / sqrt(n).
  const double d = ks_statistic(angles, [](double t) { return (t - std::sin(t)) / kPi; });
  EXPECT_LT(d, 1.95 / std::sqrt(double(n)));
  // ... and the KS test can fail: a uniform angle in [0, pi] is far off.
  std::vector<double> wrong(angles.size());
  for (std::size_t i = 0; i < wrong.size(); ++i) wrong[i] = kPi * (double(i) + 0.5) / double(n);
  EXPECT_GT(ks_statistic(wrong, [](double t) { return (t - std::sin(t)) / kPi; }), 0.1);
  // E[R] = 0: each entry has variance 1/3, so the mean is within 5 sigma of 0.
  EXPECT_LT((sum / n).cwiseAbs().maxCoeff(), 5 * std::sqrt(1.0 / (3.0 * n)));
  // E|q_i| = 4 / (3 pi) for a uniform point of S^3 (the same for all four).
  const double expected = 4.0 / (3.0 * kPi);
  for (int i = 0; i < 4; ++i) EXPECT_NEAR(quaternion_sum[i] / n, expected, 5 * 0.2 / std::sqrt(double(n)));
}

TYPED_TEST(Random, RandomPosesHaveTheirTranslationInTheBox) {
  using S = TypeParam;
  using V3 = Eigen::Matrix<S, 3, 1>;
  std::mt19937_64 gen(99);
  const V3 low(S(-1), S(2), S(0)), high(S(1), S(5), S(0.5));
  const int n = 5000;
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) {
    const SE3<S> g = chasles::random_pose<S>(gen, low, high);
    for (int k = 0; k < 3; ++k) {
      EXPECT_GE(g.translation()[k], low[k]);
      EXPECT_LE(g.translation()[k], high[k]);
    }
    sum += g.translation().template cast<double>();
  }
  const Eigen::Vector3d centre = ((low + high) / S(2)).template cast<double>();
  const Eigen::Vector3d width = (high - low).template cast<double>();
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(sum[k] / n, centre[k], 5 * width[k] / std::sqrt(12.0 * n));
}

TYPED_TEST(Random, GaussianSamplesHaveTheTangentCovarianceGiven) {
  using S = TypeParam;
  using M6 = Eigen::Matrix<S, 6, 6>;
  std::mt19937_64 gen(2026);
  Eigen::Matrix<double, 6, 6> A;
  A << 2, 0, 0, 0, 0, 0,  //
      0.5, 1, 0, 0, 0, 0,   //
      0, 0.3, 0.8, 0, 0, 0,  //
      0.1, 0, 0, 0.3, 0, 0,  //
      0, 0.2, 0, 0.05, 0.2, 0,  //
      0, 0, 0.1, 0, 0.1, 0.4;
  const Eigen::Matrix<double, 6, 6> cov = A * A.transpose();
  const M6 L = cov.llt().matrixL().toDenseMatrix().template cast<S>();
  const SE3<S> mean = SE3<S>::exp((Eigen::Matrix<S, 6, 1>() << 1, -2, 3, 0.4, 0.5, -0.6).finished());
  const int n = 40000;
  Eigen::Matrix<double, 6, 6> second = Eigen::Matrix<double, 6, 6>::Zero();
  Eigen::Matrix<double, 3, 3> second3 = Eigen::Matrix<double, 3, 3>::Zero();
  const Eigen::Matrix<S, 3, 3> L3 = L.template bottomRightCorner<3, 3>();
  for (int i = 0; i < n; ++i) {
    const Eigen::Matrix<double, 6, 1> e =
        (mean.inverse() * chasles::random_gaussian(gen, mean, L)).log().template cast<double>();
    second += e * e.transpose();
    const Eigen::Vector3d r =
        (mean.rotation().inverse() * chasles::random_gaussian(gen, mean.rotation(), L3)).log().template cast<double>();
    second3 += r * r.transpose();
  }
  second /= n;
  second3 /= n;
  // Each entry of the sample covariance has standard deviation
  // sqrt((c_ii c_jj + c_ij^2) / n); 5 of them.
  for (int i = 0; i < 6; ++i)
    for (int j = 0; j < 6; ++j)
      EXPECT_NEAR(second(i, j), cov(i, j), 5 * std::sqrt((cov(i, i) * cov(j, j) + cov(i, j) * cov(i, j)) / n))
          << i << ", " << j;
  const Eigen::Matrix3d cov3 = (L3 * L3.transpose()).template cast<double>();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(second3(i, j), cov3(i, j), 5 * std::sqrt((cov3(i, i) * cov3(j, j) + cov3(i, j) * cov3(i, j)) / n));
}

TYPED_TEST(Random, GaussianMapIsTheRightPerturbation) {
  using S = TypeParam;
  using V6 = Eigen::Matrix<S, 6, 1>;
  const SE3<S> mean = SE3<S>::exp((V6() << 0.3, -0.1, 2, 1.0, -0.5, 0.2).finished());
  const Eigen::Matrix<S, 6, 6> L = Eigen::Matrix<S, 6, 1>(S(1), S(2), S(3), S(0.1), S(0.2), S(0.3)).asDiagonal();
  const V6 z = (V6() << 0.5, -1, 0.25, 2, -1, 0.5).finished();
  const SE3<S> x = chasles::se3_gaussian_from_normals(mean, L, z);
  const V6 e = (mean.inverse() * x).log();
  EXPECT_TRUE(e.isApprox(V6(L * z), S(64) * std::numeric_limits<S>::epsilon()));
}

// ---- every group ------------------------------------------------------------

template <typename G>
class RandomOfEveryGroup : public ::testing::Test {};
TYPED_TEST_SUITE(RandomOfEveryGroup, chasles_test::AllGroups, chasles_test::AllGroupsName);

/// A lower-triangular factor with a positive diagonal of 0.05 .. 0.4 and off-diagonal entries of +-0.1.
template <typename G>
Eigen::Matrix<double, G::DoF, G::DoF> covariance_factor(unsigned seed) {
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> diag(0.05, 0.4), off(-0.1, 0.1);
  Eigen::Matrix<double, G::DoF, G::DoF> L = Eigen::Matrix<double, G::DoF, G::DoF>::Zero();
  for (int i = 0; i < G::DoF; ++i) {
    L(i, i) = diag(gen);
    for (int j = 0; j < i; ++j) L(i, j) = off(gen);
  }
  return L;
}

TYPED_TEST(RandomOfEveryGroup, GaussianSamplesHaveTheTangentCovarianceGiven) {
  using G = TypeParam;
  using S = typename G::Scalar;
  constexpr int D = G::DoF;
  const Eigen::Matrix<double, D, D> Ld = covariance_factor<G>(31);
  const Eigen::Matrix<double, D, D> cov = Ld * Ld.transpose();
  const typename G::AdjointMatrix L = Ld.template cast<S>();
  std::mt19937_64 gen(2027);
  const G mean = G::exp(chasles_test::normal_tangent<G>(gen, 1.0));
  const int n = 40000;
  Eigen::Matrix<double, D, D> second = Eigen::Matrix<double, D, D>::Zero();
  Eigen::Matrix<double, D, 1> first = Eigen::Matrix<double, D, 1>::Zero();
  for (int i = 0; i < n; ++i) {
    const Eigen::Matrix<double, D, 1> e =
        (mean.inverse() * chasles::random_gaussian(gen, mean, L)).log().template cast<double>();
    first += e;
    second += e * e.transpose();
  }
  first /= n;
  second /= n;
  // Each entry of the sample second moment has standard deviation
  // sqrt((c_ii c_jj + c_ij^2) / n), each mean sqrt(c_ii / n); 5 of them.
  for (int i = 0; i < D; ++i) {
    EXPECT_NEAR(first[i], 0.0, 5 * std::sqrt(cov(i, i) / n)) << i;
    for (int j = 0; j < D; ++j)
      EXPECT_NEAR(second(i, j), cov(i, j), 5 * std::sqrt((cov(i, i) * cov(j, j) + cov(i, j) * cov(i, j)) / n))
          << i << ", " << j;
  }
}

TYPED_TEST(RandomOfEveryGroup, GaussianMapIsTheRightPerturbation) {
  using G = TypeParam;
  using S = typename G::Scalar;
  std::mt19937_64 gen(4);
  const G mean = G::exp(chasles_test::normal_tangent<G>(gen, 1.0));
  const typename G::AdjointMatrix L = covariance_factor<G>(5).template cast<S>();
  for (int trial = 0; trial < 10; ++trial) {
    const typename G::Tangent z = chasles_test::normal_tangent<G>(gen, 1.0);
    const G x = chasles::gaussian_from_normals(mean, L, z);
    // log(mean^-1 x) = L z (its angle is below pi), compared in long double.
    const auto e = (mean.template cast<long double>().inverse() * x.template cast<long double>()).log();
    const auto expected = (L.template cast<long double>() * z.template cast<long double>()).eval();
    EXPECT_LE(
        (e - expected).cwiseAbs().maxCoeff(),
        64 * std::numeric_limits<S>::epsilon() * (1 + mean.matrix().template cast<long double>().cwiseAbs().maxCoeff()))
        << trial;
  }
}

/// The rotation angle of a rotation: in [-pi, pi] for SO(2), in [0, pi] for SO(3).
template <typename S>
double angle_of(const chasles::SO2<S>& R) {
  return double(R.angle());
}
template <typename S>
double angle_of(const SO3<S>& R) {
  return double(R.angle());
}
/// The Haar CDF of the angle: uniform on [-pi, pi] for SO(2), (t - sin t) / pi on [0, pi] for SO(3).
template <typename S>
double haar_cdf(const chasles::SO2<S>*, double t) {
  return (t + kPi) / (2 * kPi);
}
template <typename S>
double haar_cdf(const SO3<S>*, double t) {
  return (t - std::sin(t)) / kPi;
}

TYPED_TEST(RandomOfEveryGroup, RotationsAreHaarAndEuclideanPartsUniformInTheirBox) {
  using G = TypeParam;
  using S = typename G::Scalar;
  using Parts = chasles::GroupParts<G>;
  using Rotation = typename Parts::Rotation;
  constexpr int K = Parts::K;
  std::mt19937_64 gen(808);
  const int n = 20000;
  using Vector = typename Parts::Vector;
  Vector low, high;
  for (int k = 0; k < K; ++k) {
    low[k] = S(-1.5 + 0.5 * k);
    high[k] = S(0.5 + 0.25 * k);
  }
  std::vector<double> angles;
  std::vector<std::vector<double>> coordinates(K);
  for (int i = 0; i < n; ++i) {
    G g;
    if constexpr (K == 0) {
      g = chasles::random_uniform<G>(gen);
    } else {
      g = chasles::random_pose<G>(gen, low, high);
    }
    const Rotation R = Parts::rotation(g);
    angles.push_back(angle_of(R));
    // The Euclidean coordinates, read back through the group's own accessors, not GroupParts.
    Eigen::Matrix<double, K, 1> v;
    if constexpr (std::is_same<G, chasles::Sim3<S>>::value) {
      v << g.translation().template cast<double>(), std::log(double(g.scale()));
    } else if constexpr (std::is_same<G, chasles::SE23<S>>::value) {
      v << g.translation().template cast<double>(), g.velocity().template cast<double>();
    } else if constexpr (K > 0) {
      v = g.translation().template cast<double>();
    }
    for (int k = 0; k < K; ++k) {
      // within the box, to the rounding of the scale's logarithm
      ASSERT_GE(v[k], double(low[k]) - 1e-6) << k;
      ASSERT_LE(v[k], double(high[k]) + 1e-6) << k;
      coordinates[k].push_back(v[k]);
    }
  }
  // Kolmogorov-Smirnov at the 0.1 % level: D < 1.95 / sqrt(n).
  const double bound = 1.95 / std::sqrt(double(n));
  EXPECT_LT(ks_statistic(angles, [](double t) { return haar_cdf(static_cast<const Rotation*>(nullptr), t); }), bound);
  for (int k = 0; k < K; ++k) {
    const double lo = double(low[k]), hi = double(high[k]);
    EXPECT_LT(
        ks_statistic(coordinates[k], [&](double x) { return std::min(1.0, std::max(0.0, (x - lo) / (hi - lo))); }),
        bound)
        << k;
  }
}

TYPED_TEST(RandomOfEveryGroup, TheMapOfUniformsIsTheSampler) {
  // random_pose / random_uniform draw the rotation's uniforms, then the box's: element_from_uniforms of the same draws.
  using G = TypeParam;
  using S = typename G::Scalar;
  using Parts = chasles::GroupParts<G>;
  using Rotation = typename Parts::Rotation;
  constexpr int U = chasles::UniformRotation<Rotation>::U, K = Parts::K;
  typename Parts::Vector low, high;
  for (int k = 0; k < K; ++k) {
    low[k] = S(-2 + k);
    high[k] = S(1 + k);
  }
  std::mt19937_64 a(1), b(1);
  std::uniform_real_distribution<S> uniform(S(0), S(1));
  for (int trial = 0; trial < 5; ++trial) {
    G sampled;
    if constexpr (K == 0) {
      sampled = chasles::random_uniform<G>(a);
    } else {
      sampled = chasles::random_pose<G>(a, low, high);
    }
    Eigen::Matrix<S, U, 1> u;
    typename Parts::Vector v;
    for (int i = 0; i < U; ++i) u[i] = uniform(b);
    for (int k = 0; k < K; ++k) v[k] = uniform(b);
    EXPECT_EQ(sampled.matrix(), chasles::element_from_uniforms<G>(u, v, low, high).matrix());
  }
}

TEST(RandomSO2, TheMapOfAUniformIsTheAngle) {
  using V1 = Eigen::Matrix<double, 1, 1>;
  EXPECT_TRUE(chasles::so2_from_uniforms(V1(0.5)).is_approx(chasles::SO2<double>(), 0.0));
  EXPECT_NEAR(chasles::so2_from_uniforms(V1(0.25)).angle(), -kPi / 2, 4e-16);
  EXPECT_NEAR(chasles::so2_from_uniforms(V1(0.75)).angle(), kPi / 2, 4e-16);
  EXPECT_NEAR(std::fabs(chasles::so2_from_uniforms(V1(0.0)).angle()), kPi, 4e-16);
}

}  // namespace
