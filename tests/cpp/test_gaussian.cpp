// gaussian.hpp: Gaussians on every group, against Monte Carlo and exact
// identities.
//
// - Monte Carlo: for each operation (inverse, compose and between, with
//   independent operands and with a cross-covariance, the action on a
//   point, log, interpolate), 20000 samples of the operands are pushed
//   through the exact operation, and the sample covariance of the result's
//   perturbation (rminus for a group, the difference for a point or a
//   tangent) is compared with the propagated covariance: every entry within
//   5 of its standard deviations sqrt((c_ii c_jj + c_ij^2) / n), at a
//   small uncertainty (standard deviations 0.005 to 0.04), where first
//   order's own error (relative, of the order of the variance) is far
//   below that.
// - Exact: the Mahalanobis distance of mean exp(L z) is |z|^2 (NaN for a
//   singular covariance); the left and right covariances convert both ways;
//   a zero covariance samples the mean;
//   psd_cholesky factors positive definite, singular and indefinite
//   matrices as documented.
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <type_traits>

#include <gtest/gtest.h>
#include <Eigen/Core>

#include <chasles/euler.hpp>
#include <chasles/gaussian.hpp>

#include "support/all_groups.hpp"

namespace {

using chasles::Gaussian;

template <typename G>
class GaussianOfEveryGroup : public ::testing::Test {};
using DoubleGroups = ::testing::Types<chasles::SO2<double>, chasles::SE2<double>, chasles::SO3<double>,
                                      chasles::SE3<double>, chasles::Sim3<double>, chasles::SE23<double>>;
TYPED_TEST_SUITE(GaussianOfEveryGroup, DoubleGroups, chasles_test::AllGroupsName);

/// The size of the points a group acts on.
template <typename G>
constexpr int point_size() {
  using S = typename G::Scalar;
  return std::is_same<G, chasles::SO2<S>>::value || std::is_same<G, chasles::SE2<S>>::value ? 2 : 3;
}

/// A covariance L L^T with L lower triangular, diagonal in [0.005, 0.04]
/// and off-diagonal entries in [-0.01, 0.01] (scaled by `scale`).
template <int N>
Eigen::Matrix<double, N, N> covariance(unsigned seed, double scale = 1.0) {
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> diag(0.005, 0.04), off(-0.01, 0.01);
  Eigen::Matrix<double, N, N> L = Eigen::Matrix<double, N, N>::Zero();
  for (int i = 0; i < N; ++i) {
    L(i, i) = scale * diag(gen);
    for (int j = 0; j < i; ++j) L(i, j) = scale * off(gen);
  }
  return L * L.transpose();
}

constexpr int kSamples = 20000;

/// The sample covariance of n draws of an N-vector.
template <int N, typename Draw>
Eigen::Matrix<double, N, N> sample_covariance(Draw draw, int n = kSamples) {
  Eigen::Matrix<double, N, 1> first = Eigen::Matrix<double, N, 1>::Zero();
  Eigen::Matrix<double, N, N> second = Eigen::Matrix<double, N, N>::Zero();
  for (int i = 0; i < n; ++i) {
    const Eigen::Matrix<double, N, 1> e = draw();
    first += e;
    second += e * e.transpose();
  }
  first /= n;
  return second / n - first * first.transpose();
}

/// Every entry of the Monte Carlo covariance within 5 standard deviations of
/// the propagated one.
template <int N>
void expect_covariance(const Eigen::Matrix<double, N, N>& mc, const Eigen::Matrix<double, N, N>& c, const char* what) {
  for (int i = 0; i < N; ++i)
    for (int j = 0; j < N; ++j)
      EXPECT_NEAR(mc(i, j), c(i, j), 5 * std::sqrt((c(i, i) * c(j, j) + c(i, j) * c(i, j)) / kSamples))
          << what << " entry " << i << ", " << j;
}

TYPED_TEST(GaussianOfEveryGroup, PropagatedCovariancesMatchMonteCarlo) {
  using G = TypeParam;
  using T = typename G::Tangent;
  constexpr int D = G::DoF;
  constexpr int P = point_size<G>();
  std::mt19937_64 gen(7);
  const Gaussian<G> a(G::exp(chasles_test::normal_tangent<G>(gen, 1.0)), covariance<D>(11));
  const Gaussian<G> b(G::exp(chasles_test::normal_tangent<G>(gen, 1.0)), covariance<D>(12));

  const Gaussian<G> inv = a.inverse();
  expect_covariance<D>(sample_covariance<D>([&] { return T(chasles::rminus(a.sample(gen).inverse(), inv.mean())); }),
                       inv.cov(), "inverse");
  const Gaussian<G> ab = a * b;
  expect_covariance<D>(
      sample_covariance<D>([&] { return T(chasles::rminus(G(a.sample(gen) * b.sample(gen)), ab.mean())); }), ab.cov(),
      "compose");
  const Gaussian<G> rel = a.between(b);
  expect_covariance<D>(sample_covariance<D>([&] {
                         return T(chasles::rminus(chasles::between(a.sample(gen), b.sample(gen)), rel.mean()));
                       }),
                       rel.cov(), "between");

  // Correlated operands: (e_a, e_b) jointly Gaussian with the cross-covariance C.
  Eigen::Matrix<double, 2 * D, 2 * D> joint = covariance<2 * D>(13);
  const Eigen::Matrix<double, D, D> C = joint.template topRightCorner<D, D>();
  const Gaussian<G> ac(a.mean(), joint.template topLeftCorner<D, D>()),
      bc(b.mean(), joint.template bottomRightCorner<D, D>());
  const Eigen::Matrix<double, 2 * D, 2 * D> Lj = chasles::detail::psd_cholesky(joint);
  std::normal_distribution<double> normal;
  auto draw_pair = [&] {
    Eigen::Matrix<double, 2 * D, 1> z;
    for (int k = 0; k < 2 * D; ++k) z[k] = normal(gen);
    const Eigen::Matrix<double, 2 * D, 1> e = Lj * z;
    return std::make_pair(G(ac.mean() * G::exp(T(e.template head<D>()))),
                          G(bc.mean() * G::exp(T(e.template tail<D>()))));
  };
  const Gaussian<G> abc = ac.compose(bc, C);
  expect_covariance<D>(sample_covariance<D>([&] {
                         const auto xy = draw_pair();
                         return T(chasles::rminus(G(xy.first * xy.second), abc.mean()));
                       }),
                       abc.cov(), "compose, correlated");
  const Gaussian<G> relc = ac.between(bc, C);
  expect_covariance<D>(sample_covariance<D>([&] {
                         const auto xy = draw_pair();
                         return T(chasles::rminus(chasles::between(xy.first, xy.second), relc.mean()));
                       }),
                       relc.cov(), "between, correlated");

  // The action on a point, exact and uncertain.
  using Point = Eigen::Matrix<double, P, 1>;
  const Point p = Point::LinSpaced(0.7, -1.3);
  const auto q = a.act(p);
  expect_covariance<P>(sample_covariance<P>([&] { return Point(a.sample(gen).act(p) - q.mean); }), q.cov, "act");
  const Eigen::Matrix<double, P, P> Sp = covariance<P>(14);
  const Eigen::Matrix<double, P, P> Lp = chasles::detail::psd_cholesky(Sp);
  const auto qp = a.act(p, Sp);
  expect_covariance<P>(sample_covariance<P>([&] {
                         Point z;
                         for (int k = 0; k < P; ++k) z[k] = normal(gen);
                         return Point(a.sample(gen).act(Point(p + Lp * z)) - qp.mean);
                       }),
                       qp.cov, "act, uncertain point");

  const auto l = a.log();
  expect_covariance<D>(sample_covariance<D>([&] { return T(a.sample(gen).log() - l.mean); }), l.cov, "log");

  const Gaussian<G> mid = a.interpolate(b, 0.3);
  expect_covariance<D>(sample_covariance<D>([&] {
                         return T(chasles::rminus(chasles::interpolate(a.sample(gen), b.sample(gen), 0.3), mid.mean()));
                       }),
                       mid.cov(), "interpolate");
}

TYPED_TEST(GaussianOfEveryGroup, ExactIdentities) {
  using G = TypeParam;
  using T = typename G::Tangent;
  using Cov = typename G::AdjointMatrix;
  constexpr int D = G::DoF;
  constexpr double eps = std::numeric_limits<double>::epsilon();
  std::mt19937_64 gen(3);
  const Gaussian<G> a(G::exp(chasles_test::normal_tangent<G>(gen, 1.0)), covariance<D>(21, 10.0));
  const Cov L = a.factor();
  EXPECT_LE((L * L.transpose() - a.cov()).cwiseAbs().maxCoeff(), 16 * eps * a.cov().cwiseAbs().maxCoeff());
  // mean exp(L z) is at Mahalanobis distance |z|^2 (rminus returns L z).
  for (int trial = 0; trial < 10; ++trial) {
    const T z = chasles_test::normal_tangent<G>(gen, 1.0);
    const G x = chasles::gaussian_from_normals(a.mean(), L, z);
    EXPECT_NEAR(a.mahalanobis(x), z.squaredNorm(), 1e-9 * (1 + z.squaredNorm())) << trial;
  }
  EXPECT_LE(a.mahalanobis(a.mean()), 1e-20);
  // Left and right perturbations, both ways; the inverse twice.
  const Gaussian<G> back = Gaussian<G>::from_left(a.mean(), a.left_covariance());
  const double scale = a.cov().cwiseAbs().maxCoeff() * (1 + a.mean().adjoint().cwiseAbs().maxCoeff());
  EXPECT_LE((back.cov() - a.cov()).cwiseAbs().maxCoeff(), 1e3 * eps * scale);
  EXPECT_LE((a.inverse().inverse().cov() - a.cov()).cwiseAbs().maxCoeff(), 1e3 * eps * scale);
  EXPECT_TRUE(a.inverse().cov().isApprox(a.inverse().cov().transpose(), 0.0));  // symmetric, exactly
  // A zero covariance: the samples are the mean, and no distance is defined.
  const Gaussian<G> sure(a.mean(), Cov::Zero());
  EXPECT_TRUE(sure.sample(gen).matrix() == a.mean().matrix());
  EXPECT_TRUE(std::isnan(sure.mahalanobis(a.mean())));
}

// Barfoot and Furgale's experiment (2014, section III.D): a pose with the
// covariance alpha diag(10, 5, 5, 1/2, 1, 1/2) composed with itself, first
// order against fourth order against 10^5 Monte Carlo samples, at a small
// and a large uncertainty (rotation standard deviations up to 0.03 and 0.7
// rad). Errors in the Frobenius norm, relative to Monte Carlo's. Measured
// with 10^6 samples (three seeds): at alpha = 0.5 first order errs by
// 7.5-7.7 %, fourth order by 0.7-0.9 %; at 0.1, 1.4-1.5 % and 0.2-0.3 %.
TEST(GaussianSE3, FourthOrderCompoundingOfLargeUncertainty) {
  using G = chasles::SE3<double>;
  using M6 = Eigen::Matrix<double, 6, 6>;
  using V6 = Eigen::Matrix<double, 6, 1>;
  std::mt19937_64 gen(17);
  V6 xi;
  xi << 1.0, 0.5, -0.3, 0.2, -0.4, 0.6;
  const G mean = G::exp(xi);
  V6 shape;
  shape << 10, 5, 5, 0.5, 1, 0.5;
  constexpr int n = 100000;
  for (const double alpha : {1e-3, 0.5}) {
    const Gaussian<G> a(mean, M6(alpha * shape.asDiagonal()));
    const Gaussian<G> first = a * a, fourth = chasles::compose_fourth_order(a, a);
    const M6 mc =
        sample_covariance<6>([&] { return V6(chasles::rminus(G(a.sample(gen) * a.sample(gen)), first.mean())); }, n);
    const double e1 = (first.cov() - mc).norm() / mc.norm(), e4 = (fourth.cov() - mc).norm() / mc.norm();
    // The sampling error of the Monte Carlo covariance in the Frobenius norm,
    // relative: sqrt(sum_ij (c_ii c_jj + c_ij^2) / n) / |C| = sqrt((tr(C)^2 + |C|^2) / n) / |C|.
    const double noise = std::sqrt((mc.trace() * mc.trace() + mc.squaredNorm()) / n) / mc.norm();
    std::printf("  alpha %g: first order %.4f, fourth order %.4f (Monte Carlo noise about %.4f)\n", alpha, e1, e4,
                noise);
    // (Fourth order is not exact: at alpha 0.5 its own error, measured with
    // 4e6 samples, is 0.8 %, under the 3 x 0.66 % noise of these 1e5.)
    EXPECT_LT(e4, 3 * noise) << alpha;
    if (alpha > 0.1) {
      EXPECT_GT(e1, 5 * noise);  // first order visibly off
      EXPECT_LT(e4, e1 / 4);
    }
    EXPECT_TRUE(fourth.mean().matrix() == first.mean().matrix());
  }
}

// ROS's PoseWithCovariance: the covariance of (x, y, z, roll, pitch, yaw)
// against central differences of (translation, as_rpy) at g exp(e), and
// the conversion back.
TEST(GaussianSE3, RosCovarianceAgainstDifferences) {
  using G = chasles::SE3<double>;
  using M6 = Eigen::Matrix<double, 6, 6>;
  using V6 = Eigen::Matrix<double, 6, 1>;
  const auto ros = [](const G& x) {
    V6 u;
    u << x.translation(), chasles::as_rpy(x.rotation()).angles;
    return u;
  };
  for (const double pitch : {0.3, -1.2, 1.5}) {
    const G g(chasles::from_rpy(0.4, pitch, -2.5), Eigen::Vector3d(1.0, -2.0, 0.5));
    M6 J;
    const double h = 1e-6;
    for (int i = 0; i < 6; ++i) {
      const V6 e = V6::Unit(i) * h;
      J.col(i) = (ros(chasles::rplus(g, e)) - ros(chasles::rplus(g, V6(-e)))) / (2 * h);
    }
    const M6 cov = covariance<6>(11);
    const Gaussian<G> x(g, cov);
    const M6 want = J * cov * J.transpose();
    const M6 got = chasles::to_ros_covariance(x);
    EXPECT_LE((got - want).cwiseAbs().maxCoeff(), 1e-8 * want.cwiseAbs().maxCoeff()) << pitch;
    const M6 back = chasles::from_ros_covariance(g, got).cov();
    EXPECT_LE((back - cov).cwiseAbs().maxCoeff(), 1e-12 * cov.cwiseAbs().maxCoeff() / std::cos(pitch)) << pitch;
  }
  // At the gimbal lock roll and yaw are one angle: no covariance of the three.
  const Gaussian<G> locked(G(chasles::from_rpy(0.4, std::acos(-1.0) / 2, -2.5), Eigen::Vector3d::Zero()),
                           covariance<6>(12));
  EXPECT_TRUE(chasles::to_ros_covariance(locked).hasNaN());
}

TEST(PsdCholesky, PositiveDefiniteSingularAndIndefinite) {
  using M = Eigen::Matrix<double, 4, 4>;
  const M A = covariance<4>(5);
  const M L = chasles::detail::psd_cholesky(A);
  EXPECT_TRUE(L.isLowerTriangular(0.0));
  EXPECT_LE((L * L.transpose() - A).cwiseAbs().maxCoeff(), 8 * std::numeric_limits<double>::epsilon() * A.maxCoeff());
  // A coordinate held fixed (its row and column zero): a zero column, and the rest factored.
  M B = A;
  B.row(1).setZero();
  B.col(1).setZero();
  const M LB = chasles::detail::psd_cholesky(B);
  EXPECT_TRUE(LB.col(1).isZero(0.0));
  EXPECT_LE((LB * LB.transpose() - B).cwiseAbs().maxCoeff(), 8 * std::numeric_limits<double>::epsilon() * B.maxCoeff());
  // Rank one, v v^T: rounding leaves pivots of noise, taken as zero.
  const Eigen::Vector4d v(0.3, -1.1, 0.7, 2.0);
  const M R1 = v * v.transpose();
  const M L1 = chasles::detail::psd_cholesky(R1);
  EXPECT_TRUE(L1.rightCols<3>().isZero(0.0));
  EXPECT_LE((L1 * L1.transpose() - R1).cwiseAbs().maxCoeff(),
            8 * std::numeric_limits<double>::epsilon() * R1.maxCoeff());
  // Indefinite: NaN.
  M C = A;
  C(2, 2) = -0.1;
  EXPECT_TRUE(chasles::detail::psd_cholesky(C).hasNaN());
}

}  // namespace
