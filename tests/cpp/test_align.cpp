// align.hpp: so3_align, se3_align and sim3_align against independent
// oracles. Eigen::umeyama (its own SVD: JacobiSVD with the sign correction
// of Umeyama's eq. 39) on random noisy point sets, with and without scale;
// the SVD solution of Wahba's problem and scipy's sensitivity formula
// evaluated in long double; integer weights against the points repeated;
// the transform that made noise-free data, to rounding; a set whose best
// orthogonal fit is a reflection, where a rotation must come out (and be
// a local minimum among rotations); the primary-vector case (the primary
// pair aligned exactly, the rest fitted about it, opposite vectors);
// degenerate and refused inputs flagged, with both sides of the
// not-determined threshold. Float and double.
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <chasles/align.hpp>
#include <chasles/se3.hpp>
#include <chasles/sim3.hpp>
#include <chasles/so3.hpp>

#include "support/scalar_types.hpp"

namespace {

using chasles::AlignStatus;
using chasles::SE3;
using chasles::Sim3;
using chasles::SO3;
using ld = long double;

template <typename T>
class Align : public ::testing::Test {};
using chasles_test::ScalarName;
using chasles_test::ScalarTypes;
TYPED_TEST_SUITE(Align, ScalarTypes, ScalarName);

template <typename S>
using V3 = Eigen::Matrix<S, 3, 1>;
template <typename S>
using M3 = Eigen::Matrix<S, 3, 3>;
template <typename S>
using M4 = Eigen::Matrix<S, 4, 4>;

/// eps of S times a small factor: the agreement expected of two solvers of a
/// well-conditioned problem (singular values of order 1 apart).
template <typename S>
double tol() {
  return std::is_same<S, float>::value ? 2e-5 : 2e-13;
}

/// n points, coordinates uniform in [-1, 1] scaled per axis (an anisotropic cloud).
template <typename S>
std::vector<V3<S>> cloud(int n, std::mt19937_64& gen, const Eigen::Vector3d& scale = Eigen::Vector3d(3, 2, 1)) {
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<V3<S>> out;
  for (int i = 0; i < n; ++i) out.push_back(Eigen::Vector3d(u(gen), u(gen), u(gen)).cwiseProduct(scale).cast<S>());
  return out;
}

template <typename S>
SO3<S> random_rotation(std::mt19937_64& gen) {
  std::normal_distribution<double> z(0, 1);
  return SO3<S>::exp(Eigen::Vector3d(z(gen), z(gen), z(gen)).cast<S>());
}

/// The points as a 3 x n matrix (Eigen::umeyama's layout).
template <typename T, typename S>
Eigen::Matrix<T, 3, Eigen::Dynamic> columns(const std::vector<V3<S>>& p) {
  Eigen::Matrix<T, 3, Eigen::Dynamic> m(3, static_cast<Eigen::Index>(p.size()));
  for (std::size_t i = 0; i < p.size(); ++i) m.col(static_cast<Eigen::Index>(i)) = p[i].template cast<T>();
  return m;
}

/// max |a - b| / max(1, max |b|).
template <typename A, typename B>
double relative_difference(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  const Eigen::MatrixXd x = a.template cast<double>(), y = b.template cast<double>();
  return (x - y).cwiseAbs().maxCoeff() / std::max(1.0, y.cwiseAbs().maxCoeff());
}

/// The long double SVD solution of Wahba's problem for B = sum_i w_i a_i b_i^T:
/// R = U diag(1, 1, det(U V^T)) V^T, the signed singular values, scipy's
/// sensitivity mean(w) / zeta (kappa I + B B^T).
struct WahbaReference {
  Eigen::Matrix<ld, 3, 3> R, sensitivity;
  Eigen::Matrix<ld, 3, 1> s;
};

template <typename S>
WahbaReference wahba_reference(const std::vector<V3<S>>& a, const std::vector<V3<S>>& b, const std::vector<S>& w) {
  Eigen::Matrix<ld, 3, 3> B = Eigen::Matrix<ld, 3, 3>::Zero();
  ld total = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    B += ld(w[i]) * a[i].template cast<ld>() * b[i].template cast<ld>().transpose();
    total += ld(w[i]);
  }
  Eigen::JacobiSVD<Eigen::Matrix<ld, 3, 3>> svd(B, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix<ld, 3, 3> U = svd.matrixU();
  Eigen::Matrix<ld, 3, 1> s = svd.singularValues();
  if ((U * svd.matrixV().transpose()).determinant() < 0) {
    U.col(2) = -U.col(2);
    s[2] = -s[2];
  }
  WahbaReference r;
  r.R = U * svd.matrixV().transpose();
  r.s = s;
  const ld zeta = (s[0] + s[1]) * (s[1] + s[2]) * (s[2] + s[0]);
  const ld kappa = s[0] * s[1] + s[1] * s[2] + s[2] * s[0];
  r.sensitivity = (total / ld(a.size())) / zeta * (kappa * Eigen::Matrix<ld, 3, 3>::Identity() + B * B.transpose());
  return r;
}

/// sqrt(sum_i w_i |a_i - g b_i|^2) in long double, the infinite weights left out.
template <typename S>
ld rssd_reference(const M4<ld>& g, const std::vector<V3<S>>& a, const std::vector<V3<S>>& b, const std::vector<S>& w) {
  ld sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (!std::isfinite(w[i])) continue;
    const Eigen::Matrix<ld, 3, 1> r = a[i].template cast<ld>() -
                                      g.template topLeftCorner<3, 3>() * b[i].template cast<ld>() -
                                      g.template topRightCorner<3, 1>();
    sum += ld(w[i]) * r.squaredNorm();
  }
  return std::sqrt(sum);
}

template <typename S>
M4<ld> homogeneous(const M3<S>& R) {
  M4<ld> g = M4<ld>::Identity();
  g.template topLeftCorner<3, 3>() = R.template cast<ld>();
  return g;
}

// ---- se3_align and sim3_align against Eigen::umeyama ---------------------------------

TYPED_TEST(Align, Se3AndSim3EqualEigenUmeyamaOnRandomNoisyPoints) {
  using S = TypeParam;
  std::mt19937_64 gen(11);
  std::normal_distribution<double> noise(0, 0.05);
  std::uniform_real_distribution<double> log_scale(-2, 2), u(-5, 5);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 3 + trial % 40;
    const std::vector<V3<S>> B = cloud<S>(n, gen);
    const SO3<S> R = random_rotation<S>(gen);
    const S s = S(std::exp(log_scale(gen)));
    const V3<S> t = Eigen::Vector3d(u(gen), u(gen), u(gen)).cast<S>();
    std::vector<V3<S>> A;
    for (const V3<S>& p : B)
      A.push_back(s * (R * p) + t + Eigen::Vector3d(noise(gen), noise(gen), noise(gen)).cast<S>());
    const auto rigid = chasles::se3_align(A.begin(), A.end(), B.begin());
    const auto similar = chasles::sim3_align(A.begin(), A.end(), B.begin());
    ASSERT_EQ(rigid.status, AlignStatus::ok) << trial;
    ASSERT_EQ(similar.status, AlignStatus::ok) << trial;
    EXPECT_FALSE(rigid.has_sensitivity);
    // Eigen's own, in double for float (the better reference; and Eigen::umeyama
    // on float 3 x N matrices trips GCC 12's -Warray-bounds at -O3 in Eigen's code)
    using T = std::conditional_t<std::is_same<S, float>::value, double, S>;
    const Eigen::Matrix<T, 4, 4> rigid_ref = Eigen::umeyama(columns<T>(B), columns<T>(A), false);
    const Eigen::Matrix<T, 4, 4> similar_ref = Eigen::umeyama(columns<T>(B), columns<T>(A), true);
    EXPECT_LE(relative_difference(rigid.transform.matrix(), rigid_ref), tol<S>()) << trial;
    EXPECT_LE(relative_difference(similar.transform.matrix(), similar_ref), tol<S>()) << trial;
    EXPECT_NEAR(double(similar.transform.matrix().template topLeftCorner<3, 3>().determinant()),
                std::pow(double(similar.transform.scale()), 3), 1e3 * tol<S>());
    // rssd: the residuals of the result, summed in long double
    const ld rssd_rigid =
        rssd_reference(rigid.transform.matrix().template cast<ld>().eval(), A, B, std::vector<S>(A.size(), S(1)));
    const ld rssd_similar =
        rssd_reference(similar.transform.matrix().template cast<ld>().eval(), A, B, std::vector<S>(A.size(), S(1)));
    EXPECT_NEAR(double(rigid.rssd), double(rssd_rigid), 10 * tol<S>() * double(rssd_rigid)) << trial;
    EXPECT_NEAR(double(similar.rssd), double(rssd_similar), 10 * tol<S>() * double(rssd_similar)) << trial;
  }
}

TYPED_TEST(Align, NoiseFreeDataGiveTheirTransformToRounding) {
  using S = TypeParam;
  std::mt19937_64 gen(12);
  std::uniform_real_distribution<double> log_scale(-3, 3), u(-100, 100);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 3 + trial % 20;
    const std::vector<V3<S>> B = cloud<S>(n, gen);
    const SO3<S> R = random_rotation<S>(gen);
    const S s = S(std::exp(log_scale(gen)));
    const V3<S> t = Eigen::Vector3d(u(gen), u(gen), u(gen)).cast<S>();
    const Sim3<S> truth(R, t, s);
    const SE3<S> rigid_truth(R, t);
    std::vector<V3<S>> A, A_rigid, a_vectors;
    for (const V3<S>& p : B) {
      A.push_back(truth * p);
      A_rigid.push_back(rigid_truth * p);
      a_vectors.push_back(R * p);
    }
    const auto similar = chasles::sim3_align(A.begin(), A.end(), B.begin());
    const auto rigid = chasles::se3_align(A_rigid.begin(), A_rigid.end(), B.begin());
    const auto rotation = chasles::so3_align(a_vectors.begin(), a_vectors.end(), B.begin());
    ASSERT_TRUE(similar && rigid && rotation) << trial;
    const double eps = double(std::numeric_limits<S>::epsilon());
    // The data are rounded: A_i = s R B_i + t to about eps (s |B_i| + |t|)
    // absolutely, which is eps (1 + |t| / s) relative to the spread of the
    // s R B_i (the box 3 x 2 x 1): what the fit can recover.
    const double data = 1 + double(t.norm() / s);
    EXPECT_LE(relative_difference(similar.transform.rotation().matrix(), R.matrix()), 64 * eps * data) << trial;
    EXPECT_LE(std::abs(double(similar.transform.scale() / s) - 1), 64 * eps * data) << trial;
    EXPECT_LE((similar.transform.translation() - t).norm(), 64 * eps * (double(s) + double(t.norm())) * data) << trial;
    const double rigid_data = 1 + double(t.norm());
    EXPECT_LE(relative_difference(rigid.transform.rotation().matrix(), R.matrix()), 64 * eps * rigid_data) << trial;
    EXPECT_LE((rigid.transform.translation() - t).norm(), 64 * eps * rigid_data * rigid_data) << trial;
    EXPECT_LE(relative_difference(rotation.transform.matrix(), R.matrix()), 64 * eps) << trial;
    // the residuals are the data's rounding
    const double n_root = std::sqrt(double(n));
    EXPECT_LE(double(similar.rssd), 16 * eps * (4 * double(s) + double(t.norm())) * n_root) << trial;
    EXPECT_LE(double(rigid.rssd), 16 * eps * (4 + double(t.norm())) * n_root) << trial;
    EXPECT_LE(double(rotation.rssd), 16 * eps * 4 * n_root) << trial;
  }
}

// ---- weights ---------------------------------------------------------------------------

TYPED_TEST(Align, IntegerWeightsEqualThePointsRepeated) {
  using S = TypeParam;
  std::mt19937_64 gen(13);
  std::uniform_int_distribution<int> count(0, 4);
  std::normal_distribution<double> noise(0, 0.1);
  for (int trial = 0; trial < 50; ++trial) {
    const int n = 4 + trial % 10;
    const std::vector<V3<S>> B = cloud<S>(n, gen);
    const SO3<S> R = random_rotation<S>(gen);
    std::vector<V3<S>> A, A_repeated, B_repeated;
    std::vector<S> w;
    for (int i = 0; i < n; ++i) {
      A.push_back(S(1.5) * (R * B[std::size_t(i)]) + Eigen::Vector3d(noise(gen), noise(gen), noise(gen)).cast<S>());
      const int k = i < 3 ? 1 + count(gen) : count(gen);  // some weights 0, never all
      w.push_back(S(k));
      for (int j = 0; j < k; ++j) {
        A_repeated.push_back(A.back());
        B_repeated.push_back(B[std::size_t(i)]);
      }
    }
    const auto se3_w = chasles::se3_align(A.begin(), A.end(), B.begin(), w.begin());
    const auto se3_r = chasles::se3_align(A_repeated.begin(), A_repeated.end(), B_repeated.begin());
    const auto sim3_w = chasles::sim3_align(A.begin(), A.end(), B.begin(), w.begin());
    const auto sim3_r = chasles::sim3_align(A_repeated.begin(), A_repeated.end(), B_repeated.begin());
    const auto so3_w = chasles::so3_align(A.begin(), A.end(), B.begin(), w.begin());
    const auto so3_r = chasles::so3_align(A_repeated.begin(), A_repeated.end(), B_repeated.begin());
    ASSERT_TRUE(se3_w && se3_r && sim3_w && sim3_r && so3_w && so3_r) << trial;
    EXPECT_LE(relative_difference(se3_w.transform.matrix(), se3_r.transform.matrix()), tol<S>());
    EXPECT_LE(relative_difference(sim3_w.transform.matrix(), sim3_r.transform.matrix()), tol<S>());
    EXPECT_LE(relative_difference(so3_w.transform.matrix(), so3_r.transform.matrix()), tol<S>());
    EXPECT_NEAR(double(se3_w.rssd), double(se3_r.rssd), tol<S>() * double(se3_r.rssd));
    EXPECT_NEAR(double(so3_w.rssd), double(so3_r.rssd), tol<S>() * double(so3_r.rssd));
    // scipy's sensitivity takes mean(w): the repeated set has the mean 1
    const S mean_w = std::accumulate(w.begin(), w.end(), S(0)) / S(n);
    EXPECT_LE(relative_difference(so3_w.sensitivity / mean_w, so3_r.sensitivity), 10 * tol<S>());
  }
}

// ---- so3_align: Wahba's problem ----------------------------------------------------------

TYPED_TEST(Align, So3EqualsTheSvdSolutionAndScipysSensitivity) {
  using S = TypeParam;
  std::mt19937_64 gen(14);
  std::normal_distribution<double> z(0, 1);
  std::uniform_real_distribution<double> weight(0, 3);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 2 + trial % 30;
    std::vector<V3<S>> a, b;
    std::vector<S> w;
    const SO3<S> R = random_rotation<S>(gen);
    for (int i = 0; i < n; ++i) {
      b.push_back(Eigen::Vector3d(z(gen), z(gen), z(gen)).cast<S>());
      a.push_back(R * b.back() + S(0.3) * Eigen::Vector3d(z(gen), z(gen), z(gen)).cast<S>());
      w.push_back(S(weight(gen)));
    }
    const auto r = chasles::so3_align(a.begin(), a.end(), b.begin(), w.begin());
    const WahbaReference ref = wahba_reference(a, b, w);
    ASSERT_EQ(r.status, AlignStatus::ok) << trial;
    ASSERT_TRUE(r.has_sensitivity);
    // the rotation's condition is s1 / (s2 + s3) (constants.hpp, align_tolerance)
    const double condition = double(ref.s[0] / (ref.s[1] + ref.s[2]));
    EXPECT_LE(relative_difference(r.transform.matrix(), ref.R), tol<S>() * condition) << trial;
    EXPECT_LE(relative_difference(r.singular_values, ref.s), tol<S>()) << trial;
    EXPECT_LE(relative_difference(r.sensitivity, ref.sensitivity), tol<S>() * condition * condition) << trial;
    const ld rssd = rssd_reference(homogeneous(r.transform.matrix()), a, b, w);
    EXPECT_NEAR(double(r.rssd), double(rssd), 10 * tol<S>() * double(rssd)) << trial;
  }
}

TYPED_TEST(Align, So3OfTwoVectorsIsDeterminedAndOfParallelOnesIsNot) {
  using S = TypeParam;
  const std::vector<V3<S>> b = {V3<S>(1, 0, 0), V3<S>(0, 1, 0)};
  const SO3<S> R = SO3<S>::exp(V3<S>(S(0.4), S(-1.2), S(2)));
  const std::vector<V3<S>> a = {R * b[0], R * b[1]};
  const auto two = chasles::so3_align(a.begin(), a.end(), b.begin());
  EXPECT_EQ(two.status, AlignStatus::ok);
  EXPECT_LE(relative_difference(two.transform.matrix(), R.matrix()), tol<S>());
  // both pairs parallel: the rotation about them is free
  const std::vector<V3<S>> bp = {V3<S>(1, 0, 0), V3<S>(2, 0, 0)};
  const std::vector<V3<S>> ap = {R * bp[0], R * bp[1]};
  const auto parallel = chasles::so3_align(ap.begin(), ap.end(), bp.begin());
  EXPECT_EQ(parallel.status, AlignStatus::not_determined);
  EXPECT_FALSE(parallel.has_sensitivity);
  EXPECT_LE((parallel.transform * bp[0] - ap[0]).norm(), 4 * tol<S>());  // still a minimizer
  // all weights 0: nothing to fit (scipy returns the identity)
  const std::vector<S> zeros = {S(0), S(0)};
  const auto none = chasles::so3_align(a.begin(), a.end(), b.begin(), zeros.begin());
  EXPECT_EQ(none.status, AlignStatus::not_determined);
  EXPECT_TRUE(none.transform.matrix().isIdentity(0));
  EXPECT_EQ(double(none.rssd), 0.0);
}

// ---- never a reflection -------------------------------------------------------------------

TYPED_TEST(Align, AReflectedSetGivesTheBestRotationNotTheReflection) {
  using S = TypeParam;
  std::mt19937_64 gen(15);
  for (int trial = 0; trial < 50; ++trial) {
    // A = Q P B with P the mirror z -> -z: the best orthogonal map is Q P (det -1)
    const std::vector<V3<S>> B = cloud<S>(10, gen);
    const SO3<S> Q = random_rotation<S>(gen);
    const M3<S> P = V3<S>(1, 1, -1).asDiagonal();
    std::vector<V3<S>> A;
    for (const V3<S>& p : B) A.push_back(Q.matrix() * (P * p));
    // the unconstrained Procrustes solution is that reflection
    using T = std::conditional_t<std::is_same<S, float>::value, double, S>;
    Eigen::Matrix<T, 3, 3> H = Eigen::Matrix<T, 3, 3>::Zero();
    const Eigen::Matrix<T, 3, Eigen::Dynamic> Ac = columns<T>(A), Bc = columns<T>(B);
    const Eigen::Matrix<T, 3, 1> ma = Ac.rowwise().mean(), mb = Bc.rowwise().mean();
    H = (Ac.colwise() - ma) * (Bc.colwise() - mb).transpose();
    Eigen::JacobiSVD<Eigen::Matrix<T, 3, 3>> svd(H, Eigen::ComputeFullU | Eigen::ComputeFullV);
    ASSERT_LT((svd.matrixU() * svd.matrixV().transpose()).determinant(), 0);

    for (const auto& r : {chasles::se3_align(A.begin(), A.end(), B.begin()).transform.matrix(),
                          chasles::sim3_align(A.begin(), A.end(), B.begin()).transform.matrix(),
                          homogeneous(chasles::so3_align(A.begin(), A.end(), B.begin()).transform.matrix())
                              .template cast<S>()
                              .eval()}) {
      const M3<S> Rr = r.template topLeftCorner<3, 3>();
      EXPECT_GT(double(Rr.determinant()), 0) << trial;
    }
    const auto rigid = chasles::se3_align(A.begin(), A.end(), B.begin());
    ASSERT_TRUE(rigid) << trial;
    EXPECT_NEAR(double(rigid.transform.rotation().matrix().determinant()), 1.0, 10 * tol<S>());
    EXPECT_LT(double(rigid.singular_values[2]), 0);  // the sign the correction took
    // Eigen's sign-corrected answer
    const Eigen::Matrix<T, 4, 4> ref = Eigen::umeyama(Bc, Ac, false);
    EXPECT_LE(relative_difference(rigid.transform.matrix(), ref), tol<S>() * 10) << trial;
    // and a minimum among rotations: no small turn about any axis lowers the cost
    const auto cost = [&](const SO3<S>& R) {
      ld sum = 0;
      for (std::size_t i = 0; i < A.size(); ++i) {
        const V3<S> d = A[i] - (R * B[i] + rigid.transform.translation());
        sum += ld(d.squaredNorm());
      }
      return sum;
    };
    const ld best = cost(rigid.transform.rotation());
    for (int k = 0; k < 3; ++k)
      for (const double h : {1e-2, -1e-2}) {
        const SO3<S> turned = rigid.transform.rotation() * SO3<S>::exp(V3<S>(V3<S>::Unit(k) * S(h)));
        EXPECT_GT(double(cost(turned)), double(best)) << trial << " axis " << k;
      }
  }
}

// ---- the primary vector ----------------------------------------------------------------------

TYPED_TEST(Align, APrimaryVectorIsAlignedExactlyAndTheOthersFittedAboutIt) {
  using S = TypeParam;
  std::mt19937_64 gen(16);
  std::normal_distribution<double> z(0, 1);
  const S inf = std::numeric_limits<S>::infinity();
  for (int trial = 0; trial < 100; ++trial) {
    const int n = 2 + trial % 6;
    std::vector<V3<S>> a, b;
    std::vector<S> w;
    for (int i = 0; i < n; ++i) {
      a.push_back(Eigen::Vector3d(z(gen), z(gen), z(gen)).cast<S>());
      b.push_back(Eigen::Vector3d(z(gen), z(gen), z(gen)).cast<S>());
      w.push_back(S(1 + i));
    }
    const std::size_t p = std::size_t(trial) % std::size_t(n);
    w[p] = inf;
    const auto r = chasles::so3_align(a.begin(), a.end(), b.begin(), w.begin());
    ASSERT_EQ(r.status, AlignStatus::ok) << trial;
    EXPECT_FALSE(r.has_sensitivity);
    EXPECT_TRUE(std::isnan(double(r.sensitivity(0, 0))));
    // the primary directions aligned exactly
    const V3<S> u = a[p].normalized();
    EXPECT_LE((r.transform * b[p].normalized() - u).norm(), tol<S>()) << trial;
    // the others: a minimum of the cost over turns about u (the only freedom left)
    const auto cost = [&](const SO3<S>& R) {
      ld sum = 0;
      for (std::size_t i = 0; i < a.size(); ++i)
        if (i != p) sum += ld(w[i]) * ld((a[i] - R * b[i]).squaredNorm());
      return sum;
    };
    const ld best = cost(r.transform);
    EXPECT_NEAR(double(r.rssd), std::sqrt(double(best)), 10 * tol<S>() * std::sqrt(double(best)));
    for (const double h : {1e-2, -1e-2})
      EXPECT_GT(double(cost(SO3<S>::exp(V3<S>(u * S(h))) * r.transform)), double(best));
    // the limit of a large finite weight (scipy's test_align_vectors_near_inf):
    // the primary pair then pulls w_p |a_p| |b_p| against the others'
    // sum_i w_i |a_i| |b_i|, so the rotations differ by about their ratio
    if (std::is_same<S, double>::value) {
      std::vector<S> large = w;
      large[p] = S(1e6);
      ld others = 0;
      for (std::size_t i = 0; i < a.size(); ++i)
        if (i != p) others += ld(w[i]) * ld(a[i].norm()) * ld(b[i].norm());
      const double ratio = double(others / (ld(large[p]) * ld(a[p].norm()) * ld(b[p].norm())));
      const auto limit = chasles::so3_align(a.begin(), a.end(), b.begin(), large.begin());
      EXPECT_LE(relative_difference(r.transform.matrix(), limit.transform.matrix()), 4 * ratio) << trial;
    }
  }
}

TYPED_TEST(Align, OnePairGivesTheShortestRotationAlsoForOppositeVectors) {
  using S = TypeParam;
  std::mt19937_64 gen(17);
  std::normal_distribution<double> z(0, 1);
  for (int trial = 0; trial < 100; ++trial) {
    // opposite (b = -2.5 a, whose cross product is rounding), nearly opposite
    // (within 1e-6 rad), and random
    const V3<S> a = Eigen::Vector3d(z(gen), z(gen), z(gen)).cast<S>();
    const V3<S> off = Eigen::Vector3d(z(gen), z(gen), z(gen)).cast<S>() * S(1e-6) * a.norm();
    const V3<S> b = trial % 4 == 0   ? V3<S>(-S(2.5) * a)
                    : trial % 4 == 1 ? V3<S>(-a + off)
                                     : V3<S>(Eigen::Vector3d(z(gen), z(gen), z(gen)).cast<S>());
    const auto r = chasles::so3_align(&a, &a + 1, &b);
    ASSERT_EQ(r.status, AlignStatus::ok) << trial;
    EXPECT_LE((r.transform * b.normalized() - a.normalized()).norm(), tol<S>()) << trial;
    // shortest: the angle between them, about an axis orthogonal to both
    const Eigen::Matrix<ld, 3, 1> al = a.template cast<ld>(), bl = b.template cast<ld>();
    const double angle = double(std::atan2(bl.cross(al).norm(), al.dot(bl)));
    EXPECT_NEAR(double(r.transform.angle()), angle, 10 * tol<S>()) << trial;
    EXPECT_LE(std::abs(double(r.transform.log().dot(a.normalized()))), 10 * tol<S>()) << trial;
    // rssd: the single pair's weight counts (scipy's)
    EXPECT_NEAR(double(r.rssd), std::abs(double(a.norm() - b.norm())), 10 * tol<S>() * double(a.norm() + b.norm()));
  }
}

// ---- degenerate and refused inputs ----------------------------------------------------------

TYPED_TEST(Align, CollinearPointsAreNotDeterminedOnBothSidesOfTheThreshold) {
  using S = TypeParam;
  // points on the x axis, then moved off it by +-d in y at two of them: the
  // cross-covariance's s2 / s1 is about d^2 / 10; the threshold sqrt(eps)
  // is met at d of about 0.06 (float) and 4e-4 (double)
  const bool is_float = std::is_same<S, float>::value;
  const SE3<S> g(SO3<S>::exp(V3<S>(S(0.3), S(0.2), S(-0.1))), V3<S>(1, 2, 3));
  for (const double d : {0.0, is_float ? 3e-3 : 2e-5, is_float ? 1.0 : 1e-2}) {
    std::vector<V3<S>> B;
    for (int i = 0; i < 6; ++i) B.push_back(V3<S>(S(i), S(0), S(0)));
    B[1][1] = S(d);
    B[4][1] = S(-d);
    std::vector<V3<S>> A;
    for (const V3<S>& p : B) A.push_back(g * p);
    const AlignStatus expected = d > (is_float ? 0.5 : 1e-3) ? AlignStatus::ok : AlignStatus::not_determined;
    const auto rigid = chasles::se3_align(A.begin(), A.end(), B.begin());
    const auto similar = chasles::sim3_align(A.begin(), A.end(), B.begin());
    EXPECT_EQ(rigid.status, expected) << d;
    EXPECT_EQ(similar.status, expected) << d;
    // the line itself is fitted either way
    EXPECT_LE(double(rigid.rssd), 1e3 * tol<S>()) << d;
  }
}

TYPED_TEST(Align, RefusedInputsAreReported) {
  using S = TypeParam;
  const S inf = std::numeric_limits<S>::infinity(), nan = std::numeric_limits<S>::quiet_NaN();
  std::mt19937_64 gen(18);
  const std::vector<V3<S>> B = cloud<S>(5, gen);
  std::vector<V3<S>> A = B;
  const auto status_se3 = [&](const std::vector<V3<S>>& a, const std::vector<V3<S>>& b, const std::vector<S>& w) {
    const auto r = chasles::se3_align(a.begin(), a.end(), b.begin(), w.begin());
    const auto s = chasles::sim3_align(a.begin(), a.end(), b.begin(), w.begin());
    EXPECT_EQ(r.status, s.status);
    if (r.status != AlignStatus::ok && r.status != AlignStatus::not_determined) {
      EXPECT_TRUE(r.transform.matrix().isIdentity(0));
      EXPECT_TRUE(std::isnan(double(r.rssd)));
    }
    return r.status;
  };
  const auto status_so3 = [&](const std::vector<V3<S>>& a, const std::vector<V3<S>>& b, const std::vector<S>& w) {
    return chasles::so3_align(a.begin(), a.end(), b.begin(), w.begin()).status;
  };
  const std::vector<S> ones(5, S(1));
  EXPECT_EQ(status_se3(A, B, ones), AlignStatus::ok);
  EXPECT_EQ(status_so3(A, B, ones), AlignStatus::ok);
  // too few
  const std::vector<V3<S>> two(B.begin(), B.begin() + 2), none;
  EXPECT_EQ(status_se3(two, two, ones), AlignStatus::too_few);
  EXPECT_EQ(status_so3(two, two, ones), AlignStatus::ok);  // two vectors determine a rotation
  EXPECT_EQ(status_so3(none, none, ones), AlignStatus::too_few);
  // weights
  for (const S bad : {S(-1), nan}) {
    std::vector<S> w = ones;
    w[2] = bad;
    EXPECT_EQ(status_se3(A, B, w), AlignStatus::weights_not_valid) << bad;
    EXPECT_EQ(status_so3(A, B, w), AlignStatus::weights_not_valid) << bad;
  }
  std::vector<S> one_inf = ones, two_inf = ones;
  one_inf[1] = inf;
  two_inf[1] = two_inf[3] = inf;
  EXPECT_EQ(status_se3(A, B, one_inf), AlignStatus::weights_not_valid);
  EXPECT_EQ(status_so3(A, B, one_inf), AlignStatus::ok);
  EXPECT_EQ(status_so3(A, B, two_inf), AlignStatus::weights_not_valid);
  EXPECT_EQ(status_se3(A, B, std::vector<S>(5, S(0))), AlignStatus::weights_not_valid);
  std::vector<S> two_positive(5, S(0));
  two_positive[0] = two_positive[3] = S(1);
  EXPECT_EQ(status_se3(A, B, two_positive), AlignStatus::not_determined);  // two points: a line
  // coordinates
  for (const S bad : {nan, inf}) {
    std::vector<V3<S>> Ab = A;
    Ab[4][2] = bad;
    EXPECT_EQ(status_se3(Ab, B, ones), AlignStatus::not_finite) << bad;
    EXPECT_EQ(status_se3(B, Ab, ones), AlignStatus::not_finite) << bad;
    EXPECT_EQ(status_so3(Ab, B, ones), AlignStatus::not_finite) << bad;
    EXPECT_EQ(status_so3(B, Ab, ones), AlignStatus::not_finite) << bad;
    // with a weight 0 (0 * inf is NaN), and in the primary vector (left out of the sums)
    std::vector<S> zero_there = ones;
    zero_there[4] = S(0);
    EXPECT_EQ(status_se3(Ab, B, zero_there), AlignStatus::not_finite) << bad;
    EXPECT_EQ(status_so3(B, Ab, zero_there), AlignStatus::not_finite) << bad;
    std::vector<S> primary_there = ones;
    primary_there[4] = inf;
    EXPECT_EQ(status_so3(Ab, B, primary_there), AlignStatus::not_finite) << bad;
    EXPECT_EQ(status_so3(B, Ab, primary_there), AlignStatus::not_finite) << bad;
    const std::vector<V3<S>> single = {Ab[4]}, single_b = {B[4]};
    EXPECT_EQ(status_so3(single, single_b, ones), AlignStatus::not_finite) << bad;
    EXPECT_EQ(status_so3(single_b, single, ones), AlignStatus::not_finite) << bad;
  }
  // sums that overflow
  const S big = std::numeric_limits<S>::max() / S(4);
  std::vector<V3<S>> huge = A;
  for (V3<S>& p : huge) p *= big;
  EXPECT_EQ(status_se3(huge, huge, ones), AlignStatus::not_finite);
  EXPECT_EQ(status_so3(huge, huge, ones), AlignStatus::not_finite);
  // a primary vector of length 0, in a or in b
  std::vector<V3<S>> zero_a = A;
  zero_a[1] = V3<S>::Zero();
  EXPECT_EQ(status_so3(zero_a, B, one_inf), AlignStatus::zero_primary);
  EXPECT_EQ(status_so3(B, zero_a, one_inf), AlignStatus::zero_primary);
  EXPECT_EQ(status_so3(zero_a, B, ones), AlignStatus::ok);  // an ordinary vector may be 0
  const std::vector<V3<S>> single = {V3<S>::Zero()}, single_b = {V3<S>(1, 0, 0)};
  EXPECT_EQ(status_so3(single, single_b, ones), AlignStatus::zero_primary);
  // a primary vector with the others all parallel to it: the turn about it is free
  std::vector<V3<S>> on_axis(5, V3<S>(1, 2, 3));
  EXPECT_EQ(status_so3(on_axis, on_axis, one_inf), AlignStatus::not_determined);
}

// ---- the caller's buffer ---------------------------------------------------------------------

/// Rows of a row-major n x 3 buffer, as the Python bindings pass them.
template <typename S>
struct RowIterator {
  const S* p;
  Eigen::Map<const V3<S>> operator*() const { return Eigen::Map<const V3<S>>(p); }
  RowIterator& operator++() {
    p += 3;
    return *this;
  }
  bool operator!=(const RowIterator& o) const { return p != o.p; }
};

TYPED_TEST(Align, MapsOfACallersBufferGiveTheSameBits) {
  using S = TypeParam;
  std::mt19937_64 gen(19);
  const std::vector<V3<S>> B = cloud<S>(8, gen);
  std::vector<V3<S>> A;
  for (const V3<S>& p : B) A.push_back(V3<S>(p[1], p[2] + S(1), p[0]));
  std::vector<S> a_rows, b_rows;
  for (std::size_t i = 0; i < B.size(); ++i)
    for (int k = 0; k < 3; ++k) {
      a_rows.push_back(A[i][k]);
      b_rows.push_back(B[i][k]);
    }
  const RowIterator<S> a0{a_rows.data()}, a1{a_rows.data() + a_rows.size()}, b0{b_rows.data()};
  EXPECT_EQ(chasles::sim3_align(a0, a1, b0).transform.matrix(),
            chasles::sim3_align(A.begin(), A.end(), B.begin()).transform.matrix());
  EXPECT_EQ(chasles::so3_align(a0, a1, b0).transform.matrix(),
            chasles::so3_align(A.begin(), A.end(), B.begin()).transform.matrix());
}

}  // namespace
