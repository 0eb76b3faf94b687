// mean.hpp: the geodesic (Karcher) mean solves sum_i w_i log(M^-1 X_i) = 0,
// is invariant on both sides, converges in a few Newton steps at a 1 rad
// spread; the chordal mean is the nearest rotation to the weighted sum of
// matrices (the quaternion eigenvector mean, checked against a long double
// eigen solver). Both are unchanged by the scale of the weights (from the
// largest finite number to subnormals), a mean of translations near the
// largest finite number does not overflow, and weights that are not valid
// (negative, NaN, infinite, all 0) are reported.
//
// The same mean written once for every group (MeanOfEveryGroup, over
// SO2, SE2, SO3, SE3, Sim3 and both scalars): the geodesic mean solves its
// equation (evaluated in long double), is the geodesic midpoint of two
// elements (interpolate, in long double), is invariant on both sides and
// under the scale of the weights; the chordal mean is the per-part mean
// computed independently (the angles' circular mean, the averages of the
// translations and of the scales' logarithms, in long double); on SO(2)
// the geodesic mean of clustered angles is their weighted average.
#include <algorithm>
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
#include <chasles/se2.hpp>
#include <chasles/se3.hpp>
#include <chasles/sim3.hpp>
#include <chasles/so2.hpp>
#include <chasles/so3.hpp>

#include "support/all_groups.hpp"
#include "support/scalar_types.hpp"

namespace {

using chasles::SE2;
using chasles::SE3;
using chasles::Sim3;
using chasles::SO2;
using chasles::SO3;
using LD = long double;

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

// ---- every group ------------------------------------------------------------

template <typename G>
class MeanOfEveryGroup : public ::testing::Test {
 public:
  using S = typename G::Scalar;
  using GL = decltype(std::declval<G>().template cast<LD>());
  using TL = typename GL::Tangent;
  static constexpr bool is_float = std::is_same<S, float>::value;

  /// n elements centre exp(z_i), z_i with N(0, spread^2) coordinates, and weights in [0.1, 2].
  static std::vector<G> cloud(int n, double spread, unsigned seed, const G& centre) {
    std::mt19937_64 gen(seed);
    std::vector<G> out;
    for (int i = 0; i < n; ++i) out.push_back(centre * G::exp(chasles_test::normal_tangent<G>(gen, spread)));
    return out;
  }
  static std::vector<S> weights(int n, unsigned seed) {
    std::mt19937_64 gen(seed);
    std::uniform_real_distribution<double> u(0.1, 2.0);
    std::vector<S> w;
    for (int i = 0; i < n; ++i) w.push_back(S(u(gen)));
    return w;
  }
  /// sum_i w_i log(M^-1 X_i) / sum_i w_i, in long double.
  static TL residual(const G& M, const std::vector<G>& X, const std::vector<S>& w) {
    const GL Minv = M.template cast<LD>().inverse();
    TL sum = TL::Zero();
    LD total = 0;
    for (std::size_t i = 0; i < X.size(); ++i) {
      sum += LD(w[i]) * (Minv * X[i].template cast<LD>()).log();
      total += LD(w[i]);
    }
    return sum / total;
  }
  /// The largest difference of the matrices of a and b, in long double, relative to max(1, their size).
  static LD distance(const G& a, const G& b) {
    // Evaluated: matrix() returns a temporary for SO2, SE2 and SE23.
    const auto A = a.matrix().template cast<LD>().eval();
    const auto B = b.matrix().template cast<LD>().eval();
    return (A - B).cwiseAbs().maxCoeff() / std::max(LD(1), std::max(A.cwiseAbs().maxCoeff(), B.cwiseAbs().maxCoeff()));
  }
  static LD distance(const G& a, const GL& b) {
    const auto A = a.matrix().template cast<LD>().eval();
    const auto B = b.matrix().eval();
    return (A - B).cwiseAbs().maxCoeff() / std::max(LD(1), std::max(A.cwiseAbs().maxCoeff(), B.cwiseAbs().maxCoeff()));
  }
  static LD eps() { return LD(std::numeric_limits<S>::epsilon()); }
  static G centre() {
    std::mt19937_64 gen(77);
    return G::exp(chasles_test::normal_tangent<G>(gen, 1.0));
  }
};
TYPED_TEST_SUITE(MeanOfEveryGroup, chasles_test::AllGroups, chasles_test::AllGroupsName);

TYPED_TEST(MeanOfEveryGroup, GeodesicMeanSolvesTheBarycenterEquation) {
  using G = TypeParam;
  using F = TestFixture;
  for (const double spread : {0.05, 0.4}) {
    const auto X = F::cloud(200, spread, 11, F::centre());
    const auto w = F::weights(200, 3);
    const auto r = chasles::geodesic_mean(X.begin(), X.end(), w.begin());
    EXPECT_TRUE(r.converged && r.weights_valid);
    EXPECT_LE(r.iterations, 4) << spread;  // Newton from the chordal mean
    // The step test stops within sqrt(eps) (1 + rms) of the solution, and the
    // last (quadratic) step leaves about eps of it; 200 terms of rounding.
    const LD tol = 64 * F::eps() * (1 + LD(spread) * std::sqrt(LD(G::DoF)));
    EXPECT_LE(F::residual(r.mean, X, w).norm(), tol) << spread << " after " << r.iterations;
    // The chordal mean is not the geodesic one (the test of the residual can fail).
    const G c = chasles::chordal_mean(X.begin(), X.end(), w.begin());
    if (!F::is_float && spread > 0.1) EXPECT_GT(F::residual(c, X, w).norm(), 1e6 * tol);
  }
}

TYPED_TEST(MeanOfEveryGroup, GeodesicMeanOfTwoIsTheirInterpolation) {
  using G = TypeParam;
  using F = TestFixture;
  using S = typename F::S;
  std::mt19937_64 gen(5);
  for (int trial = 0; trial < 20; ++trial) {
    const G a = G::exp(chasles_test::normal_tangent<G>(gen, 1.0));
    const G b = a * G::exp(chasles_test::normal_tangent<G>(gen, 0.7));
    const std::array<G, 2> X{a, b};
    const std::array<S, 2> w{S(1 + trial % 3), S(1 + trial % 5)};
    const auto r = chasles::geodesic_mean(X.begin(), X.end(), w.begin());
    EXPECT_TRUE(r.converged);
    // a exp(t log(a^-1 b)) with t = w_b / (w_a + w_b): log(M^-1 a) = -t xi and
    // log(M^-1 b) = (1 - t) xi, whose weighted sum is 0.
    const LD t = LD(w[1]) / (LD(w[0]) + LD(w[1]));
    const auto reference = chasles::interpolate(a.template cast<LD>(), b.template cast<LD>(), t);
    EXPECT_LE(F::distance(r.mean, reference), 64 * F::eps()) << trial;
  }
}

TYPED_TEST(MeanOfEveryGroup, GeodesicMeanIsInvariantOnBothSides) {
  using G = TypeParam;
  using F = TestFixture;
  const auto X = F::cloud(100, 0.4, 8, G());
  const auto w = F::weights(100, 9);
  std::mt19937_64 gen(10);
  const G g = G::exp(chasles_test::normal_tangent<G>(gen, 1.0));
  std::vector<G> left, right;
  for (const auto& x : X) {
    left.push_back(g * x);
    right.push_back(x * g);
  }
  const G m = chasles::geodesic_mean(X.begin(), X.end(), w.begin()).mean;
  const LD tol = 256 * F::eps();
  EXPECT_LE(F::distance(chasles::geodesic_mean(left.begin(), left.end(), w.begin()).mean, g * m), tol);
  EXPECT_LE(F::distance(chasles::geodesic_mean(right.begin(), right.end(), w.begin()).mean, m * g), tol);
  // The chordal mean is invariant on the left (each part's average commutes with g's action).
  const G c = chasles::chordal_mean(X.begin(), X.end(), w.begin());
  EXPECT_LE(F::distance(chasles::chordal_mean(left.begin(), left.end(), w.begin()), g * c), tol);
}

TYPED_TEST(MeanOfEveryGroup, MeansAreUnchangedByTheScaleOfTheWeights) {
  using G = TypeParam;
  using F = TestFixture;
  using S = typename F::S;
  const auto X = F::cloud(20, 0.4, 12, F::centre());
  std::vector<S> w;  // 1 .. 8: exact multiples of the smallest subnormal below
  for (int i = 0; i < 20; ++i) w.push_back(S(1 + (i * 5) % 8));
  const G chordal = chasles::chordal_mean(X.begin(), X.end(), w.begin());
  const G geodesic = chasles::geodesic_mean(X.begin(), X.end(), w.begin()).mean;
  // Scaled so that the largest weight is near the largest finite number, or the smallest is the smallest subnormal.
  for (const S scale : {std::numeric_limits<S>::max() / S(8), std::numeric_limits<S>::denorm_min()}) {
    std::vector<S> scaled;
    for (const S wi : w) scaled.push_back(wi * scale);
    EXPECT_LE(F::distance(chasles::chordal_mean(X.begin(), X.end(), scaled.begin()), chordal), 64 * F::eps());
    const auto r = chasles::geodesic_mean(X.begin(), X.end(), scaled.begin());
    EXPECT_TRUE(r.converged && r.weights_valid);
    EXPECT_LE(F::distance(r.mean, geodesic), 64 * F::eps()) << scale;
  }
}

/// The chordal mean computed part by part, independently of GroupParts, in long double.
template <typename S>
Eigen::Matrix<LD, 2, 2> rotation_mean_reference(const std::vector<SO2<S>>& R, const std::vector<S>& w) {
  LD c = 0, s = 0;
  for (std::size_t i = 0; i < R.size(); ++i) {
    const LD theta = std::atan2(LD(R[i].complex()[1]), LD(R[i].complex()[0]));
    c += LD(w[i]) * std::cos(theta);
    s += LD(w[i]) * std::sin(theta);
  }
  const LD n = std::hypot(c, s);
  return (Eigen::Matrix<LD, 2, 2>() << c / n, -s / n, s / n, c / n).finished();
}
template <typename S>
Eigen::Matrix<LD, 3, 3> rotation_mean_reference(const std::vector<SO3<S>>& R, const std::vector<S>& w) {
  Eigen::Matrix<LD, 4, 4> Q = Eigen::Matrix<LD, 4, 4>::Zero();  // Markley et al.'s eigenvector
  for (std::size_t i = 0; i < R.size(); ++i) {
    const Eigen::Matrix<LD, 4, 1> q = R[i].quaternion().coeffs().template cast<LD>();
    Q += LD(w[i]) * q * q.transpose();
  }
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<LD, 4, 4>> es(Q);
  const Eigen::Matrix<LD, 4, 1> top = es.eigenvectors().col(3);
  return Eigen::Quaternion<LD>(top[3], top[0], top[1], top[2]).normalized().toRotationMatrix();
}
/// The matrix of the per-part mean of elements with a rotation, a translation and (Sim3) a scale or
/// (SE23) a velocity.
template <typename G, typename S>
auto part_mean_reference(const std::vector<G>& X, const std::vector<S>& w) {
  using Rot = std::decay_t<decltype(X[0].rotation())>;
  constexpr int r = std::decay_t<decltype(std::declval<Rot>().matrix())>::RowsAtCompileTime;
  constexpr int n = std::decay_t<decltype(X[0].matrix())>::RowsAtCompileTime;
  constexpr bool kSE23 = std::is_same<G, chasles::SE23<S>>::value;
  std::vector<Rot> R;
  Eigen::Matrix<LD, r, 1> t = Eigen::Matrix<LD, r, 1>::Zero(), v = t;
  LD log_scale = 0, total = 0;
  for (std::size_t i = 0; i < X.size(); ++i) {
    R.push_back(X[i].rotation());
    t += LD(w[i]) * X[i].translation().template cast<LD>();
    if constexpr (std::is_same<G, Sim3<S>>::value) log_scale += LD(w[i]) * std::log(LD(X[i].scale()));
    if constexpr (kSE23) v += LD(w[i]) * X[i].velocity().template cast<LD>();
    total += LD(w[i]);
  }
  Eigen::Matrix<LD, n, n> M = Eigen::Matrix<LD, n, n>::Identity();
  M.template topLeftCorner<r, r>() = std::exp(log_scale / total) * rotation_mean_reference(R, w);
  M.template block<r, 1>(0, r) = t / total;
  if constexpr (kSE23) M.template block<r, 1>(0, r + 1) = v / total;
  return M;
}

TYPED_TEST(MeanOfEveryGroup, ChordalMeanIsThePerPartMean) {
  using G = TypeParam;
  using F = TestFixture;
  using S = typename F::S;
  const auto X = F::cloud(300, 0.5, 14, F::centre());
  const auto w = F::weights(300, 15);
  const G c = chasles::chordal_mean(X.begin(), X.end(), w.begin());
  const auto M = c.matrix().template cast<LD>().eval();  // matrix() may be a temporary
  if constexpr (std::is_same<G, SO2<S>>::value || std::is_same<G, SO3<S>>::value) {
    EXPECT_LE((M - rotation_mean_reference(X, w)).cwiseAbs().maxCoeff(), 32 * F::eps());
  } else {
    const auto reference = part_mean_reference(X, w);
    const LD scale = std::max(LD(1), reference.cwiseAbs().maxCoeff());
    EXPECT_LE((M - reference).cwiseAbs().maxCoeff(), 32 * F::eps() * scale);
  }
}

TEST(MeanOfSO2, GeodesicMeanOfClusteredAnglesIsTheirWeightedAverage) {
  // Angles theta0 + d_i, |d_i| < pi/2, across the cut at pi: log(M^-1 R_i)
  // is linear there, so the Karcher mean is theta0 + sum w_i d_i / sum w_i.
  std::mt19937_64 gen(16);
  std::uniform_real_distribution<double> d(-1.2, 1.2), u(0.1, 2.0);
  for (const double theta0 : {0.0, 3.0, -3.1, 1.5}) {
    std::vector<SO2<double>> X;
    std::vector<double> w;
    LD sum = 0, total = 0;
    for (int i = 0; i < 50; ++i) {
      const double di = d(gen);
      X.push_back(SO2<double>::exp(theta0 + di));
      w.push_back(u(gen));
      sum += LD(w.back()) * LD(di);
      total += LD(w.back());
    }
    const auto r = chasles::geodesic_mean(X.begin(), X.end(), w.begin());
    EXPECT_TRUE(r.converged);
    const LD expected = LD(theta0) + sum / total;
    // the angle difference, wrapped to (-pi, pi]
    const LD diff = std::remainder(LD(r.mean.angle()) - expected, 2 * std::acos(LD(-1)));
    EXPECT_LE(std::fabs(diff), 8 * std::numeric_limits<double>::epsilon()) << theta0;
  }
}

TEST(MeanOfSim3, GeodesicMeanOfScalingsIsTheGeometricMean) {
  // (I, 0, s_i): the tangents are (0, 0, log s_i - log s), so the mean is exp(weighted mean of log s_i).
  std::vector<Sim3<double>> X;
  std::vector<double> w;
  LD sum = 0, total = 0;
  for (int i = 0; i < 30; ++i) {
    const double s = std::exp(0.3 * (i % 7) - 1.0), wi = 1.0 + (i % 4);
    X.emplace_back(SO3<double>(), Eigen::Vector3d::Zero(), s);
    w.push_back(wi);
    sum += LD(wi) * std::log(LD(s));
    total += LD(wi);
  }
  const auto r = chasles::geodesic_mean(X.begin(), X.end(), w.begin());
  EXPECT_TRUE(r.converged);
  EXPECT_NEAR(double(r.mean.scale()), double(std::exp(sum / total)), 8 * std::numeric_limits<double>::epsilon());
  EXPECT_TRUE(r.mean.rotation().is_approx(SO3<double>(), 0.0));
  EXPECT_EQ(r.mean.translation(), Eigen::Vector3d::Zero());
}

}  // namespace
