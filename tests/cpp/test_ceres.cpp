// ceres.hpp: the groups in Ceres Solver, over every group.
//
// - CeresManifold<G>: Ceres's own manifold checks
//   (EXPECT_THAT_MANIFOLD_INVARIANTS_HOLD of ceres/manifold_test_utils.h:
//   Plus(x, 0) = x, Minus(x, x) = 0, Minus(Plus(x, d), x) = d,
//   Plus(x, Minus(y, x)) = y, both Jacobians against Ridders' numerical
//   derivatives, MinusJacobian PlusJacobian = I) at random points, at
//   rotations near pi and with steps past a radian.
// - Jet scalars: the derivatives a ceres::Jet carries through exp, log,
//   compose, act and rminus against the library's analytic Jacobians, at
//   angle 0 and at random points.
// - BetweenCost<G>: its Jacobians against an autodiff cost of the same
//   residual written over Jets, and a small pose graph (a chain with a loop
//   closure, first pose held) solved from a perturbed start to the ground
//   truth that generated its measurements, with the analytic and with the
//   autodiff cost.
// - CubicBSplineCost<G>: its Jacobians against autodiff, and a B-spline
//   fitted to poses sampled from a known B-spline (its control elements are
//   the optimum).
#include <cmath>
#include <memory>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <ceres/autodiff_cost_function.h>
#include <ceres/manifold_test_utils.h>
#include <ceres/problem.h>
#include <ceres/solver.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <Eigen/Core>

#include <chasles/ceres.hpp>

#include "support/all_groups.hpp"

namespace {

using ceres::Matrix;
using ceres::Vector;
using chasles::Parameters;

template <typename G>
class CeresOfEveryGroup : public ::testing::Test {};
using DoubleGroups = ::testing::Types<chasles::SO2<double>, chasles::SE2<double>, chasles::SO3<double>,
                                      chasles::SE3<double>, chasles::Sim3<double>, chasles::SE23<double>>;
TYPED_TEST_SUITE(CeresOfEveryGroup, DoubleGroups, chasles_test::AllGroupsName);

template <typename G>
using Tangent = typename G::Tangent;
template <typename G, typename T>
using Over = typename chasles::detail::WithScalar<G, T>::type;

/// G's parameter block of g, its quaternion's sign that of `near` (if given).
template <typename G>
Vector block(const G& g, const Vector* near = nullptr) {
  Vector x(Parameters<G>::size);
  Parameters<G>::write(g, x.data(), near == nullptr ? nullptr : near->data());
  return x;
}

/// A random element: exp of a tangent with N(0, spread^2) coordinates.
template <typename G>
G random_element(std::mt19937_64& gen, double spread) {
  return G::exp(chasles_test::normal_tangent<G>(gen, spread));
}

/// Where the rotation sits in G's tangent, and its size.
template <typename G>
constexpr int rotation_start() {
  using S = typename G::Scalar;
  if (std::is_same<G, chasles::SE2<S>>::value) return 2;
  if (std::is_same<G, chasles::SE3<S>>::value || std::is_same<G, chasles::Sim3<S>>::value) return 3;
  if (std::is_same<G, chasles::SE23<S>>::value) return 6;
  return 0;
}
template <typename G>
constexpr int rotation_size() {
  using S = typename G::Scalar;
  return std::is_same<G, chasles::SO2<S>>::value || std::is_same<G, chasles::SE2<S>>::value ? 1 : 3;
}

/// delta with its rotation part shortened to an angle of at most 3 rad:
/// Minus(Plus(x, delta), x) = delta holds for angles below pi (log returns
/// the angle in [0, pi]).
template <typename G>
Tangent<G> principal(Tangent<G> delta) {
  auto w = delta.segment(rotation_start<G>(), rotation_size<G>());
  if (w.norm() > 3.0) w *= 3.0 / w.norm();
  return delta;
}

/// Ceres's manifold checks at the element `at`, with a step delta and a
/// y = at exp(e), delta and e of N(0, spread^2) coordinates (principal), y's
/// quaternion on x's side (Plus writes that sign).
template <typename G>
void expect_manifold_invariants_at(const G& at, std::mt19937_64& gen, double spread) {
  const chasles::CeresManifold<G> manifold;
  constexpr double kTolerance = 1e-9;  // Ridders' derivatives agree to about 1e-11 here
  const Vector x = block(at);
  const Vector delta = principal<G>(chasles_test::normal_tangent<G>(gen, spread));
  const Vector y = block(chasles::rplus(at, principal<G>(chasles_test::normal_tangent<G>(gen, spread))), &x);
  using namespace ceres;  // the macro names ceres' matchers unqualified
  EXPECT_THAT_MANIFOLD_INVARIANTS_HOLD(manifold, x, delta, y, kTolerance);
}

TYPED_TEST(CeresOfEveryGroup, ManifoldPassesCeresChecks) {
  using G = TypeParam;
  const chasles::CeresManifold<G> manifold;
  EXPECT_EQ(manifold.AmbientSize(), Parameters<G>::size);
  EXPECT_EQ(manifold.TangentSize(), G::DoF);
  std::mt19937_64 gen(7);
  for (int trial = 0; trial < 20; ++trial) {
    const G at = random_element<G>(gen, 1.0);
    expect_manifold_invariants_at(at, gen, trial < 10 ? 0.5 : 1.5);  // steps past a radian in the second half
  }
}

TYPED_TEST(CeresOfEveryGroup, ManifoldNearAHalfTurn) {
  using G = TypeParam;
  std::mt19937_64 gen(11);
  for (int trial = 0; trial < 5; ++trial) {
    Tangent<G> xi = chasles_test::normal_tangent<G>(gen, 0.3);
    xi.segment(rotation_start<G>(), rotation_size<G>()) *=
        (M_PI - 1e-6) / xi.segment(rotation_start<G>(), rotation_size<G>()).norm();
    expect_manifold_invariants_at(G::exp(xi), gen, 0.1);
  }
}

TYPED_TEST(CeresOfEveryGroup, PlusKeepsTheQuaternionSignOfX) {
  using G = TypeParam;
  const chasles::CeresManifold<G> manifold;
  std::mt19937_64 gen(3);
  for (int trial = 0; trial < 50; ++trial) {
    Vector x = block(random_element<G>(gen, 2.0));
    if (rotation_size<G>() == 3) x.head<4>() *= -1.0;  // -q: the same rotation
    const Vector delta = chasles_test::normal_tangent<G>(gen, 0.01);
    Vector out(Parameters<G>::size);
    ASSERT_TRUE(manifold.Plus(x.data(), delta.data(), out.data()));
    const int n = rotation_size<G>() == 3 ? 4 : 2;  // the rotation's numbers
    EXPECT_LT((out.head(n) - x.head(n)).norm(), 0.1) << "x " << x.transpose() << "\nPlus(x, delta) " << out.transpose();
  }
}

// ---- Jets ---------------------------------------------------------------

template <typename G>
using JetOf = ceres::Jet<double, G::DoF>;

/// xi as Jets whose derivatives are the identity (d xi / d xi = I).
template <typename G>
Tangent<Over<G, JetOf<G>>> seeded(const Tangent<G>& xi) {
  Tangent<Over<G, JetOf<G>>> out;
  for (int k = 0; k < G::DoF; ++k) out[k] = JetOf<G>(xi[k], k);
  return out;
}

/// The value and the derivatives (one column per seed) of Jet entries.
template <typename Derived>
Eigen::MatrixXd values(const Eigen::MatrixBase<Derived>& m) {
  Eigen::MatrixXd out(m.rows(), m.cols());
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j) out(i, j) = m(i, j).a;
  return out;
}
template <typename Derived>
Eigen::MatrixXd derivative(const Eigen::MatrixBase<Derived>& m, int k) {
  Eigen::MatrixXd out(m.rows(), m.cols());
  for (int i = 0; i < m.rows(); ++i)
    for (int j = 0; j < m.cols(); ++j) out(i, j) = m(i, j).v[k];
  return out;
}

/// The tangents the Jet checks run at: 0, small, random, near a half turn.
template <typename G>
std::vector<Tangent<G>> jet_points() {
  std::mt19937_64 gen(5);
  std::vector<Tangent<G>> out{Tangent<G>::Zero(), chasles_test::normal_tangent<G>(gen, 1e-9)};
  for (int i = 0; i < 6; ++i) out.push_back(chasles_test::normal_tangent<G>(gen, 0.7));
  return out;
}

TYPED_TEST(CeresOfEveryGroup, JetDerivativesOfExpComposeAndLog) {
  using G = TypeParam;
  using GJ = Over<G, JetOf<G>>;
  std::mt19937_64 gen(9);
  const G h = random_element<G>(gen, 1.0);
  for (const Tangent<G>& xi : jet_points<G>()) {
    const GJ g = GJ::exp(seeded<G>(xi));
    const auto M = G::exp(xi).matrix();
    const typename G::AdjointMatrix Jr = G::right_jacobian(xi);
    EXPECT_LT((values(g.matrix()) - M).norm(), 1e-15 * (1 + M.norm()));
    // exp(xi + d) = exp(xi) exp(J_r(xi) d): d exp / d xi_k = M hat(J_r e_k).
    const GJ gh = g * h.template cast<JetOf<G>>();
    for (int k = 0; k < G::DoF; ++k) {
      const auto dM = (M * G::hat(Jr.col(k))).eval();
      EXPECT_LT((derivative(g.matrix(), k) - dM).norm(), 1e-13 * (1 + dM.norm())) << "exp, k = " << k;
      EXPECT_LT((derivative(gh.matrix(), k) - dM * h.matrix()).norm(),
                1e-13 * (1 + dM.norm()) * (1 + h.matrix().norm()))
          << "compose, k = " << k;
    }
    // log(exp(xi)) = xi: its derivative is the identity, at angle 0 too.
    const Tangent<GJ> l = g.log();
    EXPECT_LT((values(l) - xi).norm(), 1e-14 * (1 + xi.norm()));
    for (int k = 0; k < G::DoF; ++k)
      EXPECT_LT((derivative(l, k) - Tangent<G>::Unit(k)).norm(), 1e-12)
          << "log, k = " << k << ", xi " << xi.transpose();
    // rminus(exp(xi), h): d/dxi = J_g(rminus) J_r(xi) (rminus_jacobians).
    const Tangent<GJ> r = chasles::rminus(g, h.template cast<JetOf<G>>());
    const typename G::AdjointMatrix expected = chasles::rminus_jacobians(G::exp(xi), h).lhs * Jr;
    for (int k = 0; k < G::DoF; ++k)
      EXPECT_LT((derivative(r, k) - expected.col(k)).norm(), 1e-12 * (1 + expected.norm())) << "rminus, k = " << k;
  }
}

TEST(CeresJets, ActOfSE3AndSO3) {
  using J6 = ceres::Jet<double, 6>;
  using J3 = ceres::Jet<double, 3>;
  const Eigen::Vector3d p(0.3, -1.2, 2.0);
  for (const Tangent<chasles::SE3d>& xi : jet_points<chasles::SE3d>()) {
    const Eigen::Matrix<J6, 3, 1> q = chasles::SE3<J6>::exp(seeded<chasles::SE3d>(xi)).act(p.cast<J6>());
    const Eigen::Matrix4d M = chasles::SE3d::exp(xi).matrix();
    const chasles::SE3d::AdjointMatrix Jr = chasles::SE3d::right_jacobian(xi);
    for (int k = 0; k < 6; ++k) {
      const Eigen::Vector4d dq = M * chasles::SE3d::hat(Jr.col(k)) * p.homogeneous();
      EXPECT_LT((derivative(q, k) - dq.head<3>()).norm(), 1e-13 * (1 + dq.norm()));
    }
    const Eigen::Vector3d w = xi.tail<3>();
    const Eigen::Matrix<J3, 3, 1> u = chasles::SO3<J3>::exp(seeded<chasles::SO3d>(w)).act(p.cast<J3>());
    const Eigen::Matrix3d R = chasles::SO3d::exp(w).matrix();
    const Eigen::Matrix3d JrR = chasles::SO3d::right_jacobian(w);
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector3d du = R * chasles::SO3d::hat(JrR.col(k)) * p;
      EXPECT_LT((derivative(u, k) - du).norm(), 1e-13 * (1 + du.norm()));
    }
  }
}

// ---- BetweenCost and a small pose graph ------------------------------------

/// The residual of BetweenCost written over Jets, for ceres::AutoDiffCostFunction.
template <typename G>
struct AutodiffBetween {
  G measurement;
  typename G::AdjointMatrix sqrt_information;
  template <typename T>
  bool operator()(const T* a, const T* b, T* residual) const {
    using GT = Over<G, T>;
    const GT A = Parameters<GT>::read(a);
    const GT B = Parameters<GT>::read(b);
    const Tangent<GT> e = chasles::rminus(chasles::between(A, B), measurement.template cast<T>());
    Eigen::Map<Tangent<GT>>{residual} = sqrt_information.template cast<T>() * e;
    return true;
  }
};

template <typename G>
ceres::CostFunction* autodiff_between(const G& z, const typename G::AdjointMatrix& L) {
  return new ceres::AutoDiffCostFunction<AutodiffBetween<G>, G::DoF, Parameters<G>::size, Parameters<G>::size>(
      new AutodiffBetween<G>{z, L});
}

/// A lower-triangular square root of an information matrix, well conditioned.
template <typename G>
typename G::AdjointMatrix sqrt_information(std::mt19937_64& gen) {
  std::uniform_real_distribution<double> diag(1.0, 10.0), off(-1.0, 1.0);
  typename G::AdjointMatrix L = G::AdjointMatrix::Zero();
  for (int i = 0; i < G::DoF; ++i) {
    L(i, i) = diag(gen);
    for (int j = 0; j < i; ++j) L(i, j) = off(gen);
  }
  return L;
}

TYPED_TEST(CeresOfEveryGroup, BetweenCostJacobiansMatchAutodiff) {
  using G = TypeParam;
  constexpr int n = Parameters<G>::size;
  std::mt19937_64 gen(13);
  for (int trial = 0; trial < 10; ++trial) {
    const G z = random_element<G>(gen, 1.0);
    const typename G::AdjointMatrix L = sqrt_information<G>(gen);
    const chasles::BetweenCost<G> analytic(z, L);
    std::unique_ptr<ceres::CostFunction> autodiff(autodiff_between(z, L));
    const Vector a = block(random_element<G>(gen, 1.0)), b = block(random_element<G>(gen, 1.0));
    const double* blocks[2] = {a.data(), b.data()};
    Eigen::Matrix<double, G::DoF, 1> r1, r2;
    Eigen::Matrix<double, G::DoF, n, Eigen::RowMajor> ja1, jb1, ja2, jb2;
    double* j1[2] = {ja1.data(), jb1.data()};
    double* j2[2] = {ja2.data(), jb2.data()};
    ASSERT_TRUE(analytic.Evaluate(blocks, r1.data(), j1));
    ASSERT_TRUE(autodiff->Evaluate(blocks, r2.data(), j2));
    EXPECT_LT((r1 - r2).norm(), 1e-12 * (1 + r2.norm()));
    // The Jacobians in the blocks' coordinates differ along the directions a
    // manifold step never takes (the quaternion's norm): compare them times
    // the Plus Jacobian, what Ceres uses.
    const auto Pa = Parameters<G>::plus_jacobian(a.data());
    const auto Pb = Parameters<G>::plus_jacobian(b.data());
    EXPECT_LT((ja1 * Pa - ja2 * Pa).norm(), 1e-10 * (1 + (ja2 * Pa).norm())) << "d r / d a";
    EXPECT_LT((jb1 * Pb - jb2 * Pb).norm(), 1e-10 * (1 + (jb2 * Pb).norm())) << "d r / d b";
  }
}

/// A chain of 5 poses with a loop closure, measurements exact, solved from
/// a perturbed start: the optimum is the ground truth (zero cost).
template <typename G>
void solve_small_graph(bool use_autodiff) {
  std::mt19937_64 gen(17);
  std::vector<G> truth;
  for (int i = 0; i < 5; ++i) truth.push_back(random_element<G>(gen, 1.0));
  const std::vector<std::pair<int, int>> edges{{0, 1}, {1, 2}, {2, 3}, {3, 4}, {4, 0}, {1, 3}};
  std::vector<Vector> x;
  for (const G& g : truth) x.push_back(block(chasles::rplus(g, Tangent<G>(chasles_test::normal_tangent<G>(gen, 0.2)))));
  x[0] = block(truth[0]);
  ceres::Problem problem;
  for (Vector& xi : x) problem.AddParameterBlock(xi.data(), Parameters<G>::size, new chasles::CeresManifold<G>);
  problem.SetParameterBlockConstant(x[0].data());
  for (const auto& [i, j] : edges) {
    const G z = chasles::between(truth[i], truth[j]);
    const typename G::AdjointMatrix L = sqrt_information<G>(gen);
    ceres::CostFunction* cost = use_autodiff ? autodiff_between(z, L) : new chasles::BetweenCost<G>(z, L);
    problem.AddResidualBlock(cost, nullptr, x[i].data(), x[j].data());
  }
  ceres::Solver::Options options;
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-16;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  EXPECT_TRUE(summary.IsSolutionUsable()) << summary.BriefReport();
  EXPECT_LT(summary.final_cost, 1e-20) << summary.BriefReport();
  for (int i = 0; i < 5; ++i) {
    const G solved = Parameters<G>::read(x[i].data());
    EXPECT_LT(chasles::rminus(solved, truth[i]).norm(), 1e-9) << "pose " << i << ": " << summary.BriefReport();
  }
}

TYPED_TEST(CeresOfEveryGroup, SmallPoseGraphSolvesToTheTruth) {
  solve_small_graph<TypeParam>(false);
  solve_small_graph<TypeParam>(true);
}

// ---- CubicBSplineCost and a B-spline fit -----------------------------------

/// The residual of CubicBSplineCost written over Jets.
template <typename G>
struct AutodiffBSpline {
  double u;
  G measurement;
  typename G::AdjointMatrix sqrt_information;
  template <typename T>
  bool operator()(const T* x0, const T* x1, const T* x2, const T* x3, T* residual) const {
    using GT = Over<G, T>;
    const GT four[4] = {Parameters<GT>::read(x0), Parameters<GT>::read(x1), Parameters<GT>::read(x2),
                        Parameters<GT>::read(x3)};
    const Tangent<GT> e = chasles::rminus(chasles::cubic_bspline_segment(four, T(u)), measurement.template cast<T>());
    Eigen::Map<Tangent<GT>>{residual} = sqrt_information.template cast<T>() * e;
    return true;
  }
};

template <typename G>
ceres::CostFunction* bspline_cost(bool use_autodiff, double u, const G& z, const typename G::AdjointMatrix& L) {
  constexpr int n = Parameters<G>::size;
  if (use_autodiff)
    return new ceres::AutoDiffCostFunction<AutodiffBSpline<G>, G::DoF, n, n, n, n>(new AutodiffBSpline<G>{u, z, L});
  return new chasles::CubicBSplineCost<G>(u, z, L);
}

TYPED_TEST(CeresOfEveryGroup, CubicBSplineCostJacobiansMatchAutodiff) {
  using G = TypeParam;
  constexpr int n = Parameters<G>::size;
  std::mt19937_64 gen(19);
  for (const double u : {0.0, 0.4, 1.0}) {
    const G z = random_element<G>(gen, 1.0);
    const typename G::AdjointMatrix L = sqrt_information<G>(gen);
    std::unique_ptr<ceres::CostFunction> analytic(bspline_cost(false, u, z, L)), autodiff(bspline_cost(true, u, z, L));
    std::vector<Vector> x;
    const G start = random_element<G>(gen, 1.0);
    for (int k = 0; k < 4; ++k)
      x.push_back(block(chasles::rplus(start, Tangent<G>(chasles_test::normal_tangent<G>(gen, 0.4 * (k + 1))))));
    const double* blocks[4] = {x[0].data(), x[1].data(), x[2].data(), x[3].data()};
    Eigen::Matrix<double, G::DoF, 1> r1, r2;
    Eigen::Matrix<double, G::DoF, n, Eigen::RowMajor> j1[4], j2[4];
    double* p1[4] = {j1[0].data(), j1[1].data(), j1[2].data(), j1[3].data()};
    double* p2[4] = {j2[0].data(), j2[1].data(), j2[2].data(), j2[3].data()};
    ASSERT_TRUE(analytic->Evaluate(blocks, r1.data(), p1));
    ASSERT_TRUE(autodiff->Evaluate(blocks, r2.data(), p2));
    EXPECT_LT((r1 - r2).norm(), 1e-12 * (1 + r2.norm()));
    for (int k = 0; k < 4; ++k) {
      const auto P = Parameters<G>::plus_jacobian(x[k].data());
      EXPECT_LT((j1[k] * P - j2[k] * P).norm(), 1e-10 * (1 + (j2[k] * P).norm())) << "u " << u << ", control " << k;
    }
  }
}

/// Poses sampled without noise from a B-spline of 8 known control elements
/// (spacing 0.5), fitted from control elements perturbed by 0.2: the fit is
/// the known spline (zero cost, the same control elements). (The analytic
/// cost only: CubicBSplineCostJacobiansMatchAutodiff compares it with the
/// autodiff one, whose solve took 37 CPU-s for Sim3 in the sanitizer build.)
template <typename G>
void fit_known_bspline() {
  std::mt19937_64 gen(23);
  std::vector<G> truth{random_element<G>(gen, 1.0)};
  for (int i = 1; i < 8; ++i)
    truth.push_back(chasles::rplus(truth.back(), Tangent<G>(chasles_test::normal_tangent<G>(gen, 0.3))));
  const double t0 = 1.0, dt = 0.5;
  const chasles::CubicBSplineView<G> spline(truth.data(), 8, t0, dt);
  std::vector<Vector> x;
  for (const G& g : truth) x.push_back(block(chasles::rplus(g, Tangent<G>(chasles_test::normal_tangent<G>(gen, 0.2)))));
  ceres::Problem problem;
  for (Vector& xi : x) problem.AddParameterBlock(xi.data(), Parameters<G>::size, new chasles::CeresManifold<G>);
  for (int k = 0; k <= 40; ++k) {
    const double t = t0 + k * (spline.end_time() - t0) / 40;
    const chasles::BSplineTime<double> at = spline.locate(t);
    const auto i = static_cast<std::size_t>(at.segment);
    problem.AddResidualBlock(bspline_cost(false, at.u, spline(t), G::AdjointMatrix::Identity()), nullptr, x[i].data(),
                             x[i + 1].data(), x[i + 2].data(), x[i + 3].data());
  }
  ceres::Solver::Options options;
  options.function_tolerance = options.gradient_tolerance = options.parameter_tolerance = 1e-16;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  EXPECT_LT(summary.final_cost, 1e-20) << summary.BriefReport();
  for (std::size_t i = 0; i < truth.size(); ++i)
    EXPECT_LT(chasles::rminus(Parameters<G>::read(x[i].data()), truth[i]).norm(), 1e-8)
        << "control " << i << ": " << summary.BriefReport();
}

TYPED_TEST(CeresOfEveryGroup, BSplineFitRecoversAKnownSpline) { fit_known_bspline<TypeParam>(); }

}  // namespace
