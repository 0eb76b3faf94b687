// Inverse kinematics (inverse_kinematics.hpp), typed over float and double,
// on a fixed-size UR5 (Modern Robotics, example 4.5) and on the same arm on
// a linear rail as a dynamic chain of 7 joints with a bound of 8:
// - pose_error_jacobian against central differences of pose_error;
// - targets forward(q*) of random q* within limits, from seeds 0.3 rad away:
//   every one converges, and the solution is checked by an independent
//   oracle, the long double product of 4x4 matrix exponentials
//   (support/reference.hpp): |log(g_ref(q)^-1 T)| within the tolerance;
// - the returned error is pose_error at the returned q; iterations within
//   the bound; 0 iterations when q0 is a solution;
// - joint limits: q0 and every result within them, and a target reachable
//   only outside them is reported as not converged;
// - an unreachable target: not converged, finite, within the bound, its
//   status iteration_bound, or no_progress at the nearest configuration;
// - the status, the iterations of the attempt returned and of all attempts,
//   the attempts; the time budget (max_time) over restarts; restarts that
//   depend on the generator only.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <chasles/inverse_kinematics.hpp>

#include "support/arms.hpp"
#include "support/group_traits.hpp"
#include "support/reference.hpp"

namespace {

using namespace chasles_test;
using chasles::Chain;
using chasles::IKOptions;
using chasles::IKStatus;
using chasles::SE3;

/// |log(g^-1 T)| parts by the long double reference forward kinematics.
template <typename C>
std::pair<LD, LD> reference_error(const C& chain, const SE3<typename C::Scalar>& target,
                                  const typename C::JointVector& q) {
  using M4L = Eigen::Matrix<LD, 4, 4>;
  using V6L = Eigen::Matrix<LD, 6, 1>;
  M4L g = M4L::Identity();
  for (Eigen::Index i = 0; i < chain.n_joints(); ++i)
    g = g * chasles_ref::exp6(V6L(chain.space_screws().col(i).template cast<LD>() * LD(q(i))));
  g = g * chain.home().matrix().template cast<LD>();
  const M4L T = target.matrix().template cast<LD>();
  const SE3<LD> d = SE3<LD>::from_matrix_unchecked(M4L(g.inverse() * T));
  const V6L e = d.log();
  return {e.template head<3>().norm(), e.template tail<3>().norm()};
}

template <typename C>
class InverseKinematics : public ::testing::Test {};

template <typename S_, int N, int MaxN>
struct Case {
  using Chain = chasles::Chain<S_, N, MaxN>;
  static constexpr int joints = MaxN == N ? N : 7;
};
using Cases = ::testing::Types<Case<float, 6, 6>, Case<double, 6, 6>, Case<float, Eigen::Dynamic, 8>,
                               Case<double, Eigen::Dynamic, 8>>;
TYPED_TEST_SUITE(InverseKinematics, Cases);

constexpr double kPi = 3.14159265358979323846;

TYPED_TEST(InverseKinematics, ErrorJacobianMatchesCentralDifferences) {
  using C = typename TypeParam::Chain;
  using S = typename C::Scalar;
  using JV = typename C::JointVector;
  const int n = TypeParam::joints;
  const C chain = ur5_chain<C>(n);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-2.5, 2.5);
  for (int trial = 0; trial < 20; ++trial) {
    JV q(n), qt(n);
    for (int i = 0; i < n; ++i) q(i) = S(u(rng)), qt(i) = q(i) + S(0.4 * u(rng));  // error up to ~1 rad
    const SE3<S> T = chain.forward(qt);
    const typename C::Jacobian J = chasles::pose_error_jacobian(chain, T, q);
    // Central differences in double whatever S (the Jacobian's formula is what is
    // checked, not the rounding of S): step 1e-5, truncation h^2/6 |e'''| < 1e-10.
    using CD = Chain<double, C::JointsAtCompileTime, C::MaxJointsAtCompileTime>;
    const CD chain_d(chain.space_screws().template cast<double>(), chain.home().template cast<double>());
    const SE3<double> Td = T.template cast<double>();
    const typename CD::JointVector qd = q.template cast<double>();
    for (int i = 0; i < n; ++i) {
      const double h = 1e-5;
      typename CD::JointVector qp = qd, qm = qd;
      qp(i) += h;
      qm(i) -= h;
      const Eigen::Matrix<double, 6, 1> fd =
          (chasles::pose_error(chain_d, Td, qp) - chasles::pose_error(chain_d, Td, qm)) / (2 * h);
      // float: the Jacobian's own rounding, ~100 eps_f relative to its scale (<= 2).
      const double tol = std::is_same_v<S, float> ? 200 * 1.2e-7 : 1e-8;
      EXPECT_LE(max_abs_diff(J.col(i), fd), tol) << "column " << i << ", trial " << trial;
    }
  }
}

TYPED_TEST(InverseKinematics, SolvesReachableTargetsFromNearbySeeds) {
  using C = typename TypeParam::Chain;
  using S = typename C::Scalar;
  using JV = typename C::JointVector;
  const int n = TypeParam::joints;
  const C chain = ur5_chain<C>(n);
  JV lower(n), upper(n);
  for (int i = 0; i < n; ++i) lower(i) = S(-2 * kPi), upper(i) = S(2 * kPi);
  if (n == 7) lower(0) = S(-1), upper(0) = S(1);  // the rail
  const IKOptions<S> options;
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-kPi, kPi), jitter(-0.3, 0.3);
  std::vector<int> iterations;
  for (int trial = 0; trial < 200; ++trial) {
    JV qt(n), q0(n);
    for (int i = 0; i < n; ++i) {
      qt(i) = S(i == 0 && n == 7 ? 0.9 * u(rng) / kPi : u(rng));
      q0(i) = qt(i) + S(jitter(rng));
    }
    const SE3<S> T = chain.forward(qt);
    const auto r = chasles::inverse_kinematics(chain, T, q0, lower, upper, options);
    ASSERT_TRUE(r.converged) << "trial " << trial << ": " << r.iterations << " iterations, error "
                             << r.error.transpose();
    iterations.push_back(r.iterations);
    EXPECT_LE(r.iterations, options.max_iterations);
    EXPECT_TRUE((r.q.array() >= lower.array()).all() && (r.q.array() <= upper.array()).all());
    EXPECT_EQ(r.error, chasles::pose_error(chain, T, r.q));
    EXPECT_LE(r.error.template head<3>().norm(), options.position_tolerance);
    EXPECT_LE(r.error.template tail<3>().norm(), options.orientation_tolerance);
    // The independent oracle: the long double forward kinematics at r.q reaches T
    // to the tolerance plus the rounding of the library's forward kinematics
    // (float: 2 n kExp eps as test_kinematics.cpp, over the arm's reach of ~1 m).
    const auto [dp, dw] = reference_error(chain, T, r.q);
    const LD slack = std::is_same_v<S, float> ? LD(2 * n * 16) * eps<S>() : LD(1e-13);
    EXPECT_LE(dp, LD(options.position_tolerance) + slack) << "trial " << trial;
    EXPECT_LE(dw, LD(options.orientation_tolerance) + slack) << "trial " << trial;
  }
  // From 0.3 rad away, damped Gauss-Newton needs few iterations (quadratic
  // convergence; 5 to 7 at the median here).
  std::nth_element(iterations.begin(), iterations.begin() + 100, iterations.end());
  EXPECT_LE(iterations[100], 10);
}

TYPED_TEST(InverseKinematics, RandomSeedsWithRestarts) {
  using C = typename TypeParam::Chain;
  using S = typename C::Scalar;
  using JV = typename C::JointVector;
  const int n = TypeParam::joints;
  const C chain = ur5_chain<C>(n);
  JV lower(n), upper(n);
  for (int i = 0; i < n; ++i) lower(i) = S(-2 * kPi), upper(i) = S(2 * kPi);
  if (n == 7) lower(0) = S(-1), upper(0) = S(1);
  std::mt19937 rng(17), gen(19);
  std::uniform_real_distribution<double> u(0, 1);
  const auto uniform_within = [&] {
    JV q(n);
    for (int i = 0; i < n; ++i) q(i) = lower(i) + (upper(i) - lower(i)) * S(u(rng));
    return q;
  };
  int converged = 0, converged_first = 0;
  const IKOptions<S> options;
  const auto no_deadline = chasles::detail::IKDeadline::after(options.max_time);
  for (int trial = 0; trial < 100; ++trial) {
    const SE3<S> T = chain.forward(uniform_within());
    const JV q0 = uniform_within();
    const auto r = chasles::inverse_kinematics(chain, T, q0, lower, upper, options, gen, 10);
    // The first attempt of r: one that a restart follows, so cut short when it stalls.
    const auto r1 = chasles::detail::ik_attempt(chain, T, q0, lower, upper, options, no_deadline, true);
    converged += r.converged;
    converged_first += r1.converged;
    EXPECT_LE(r.iterations, options.max_iterations) << "iterations count the attempt returned";
    EXPECT_LE(r.total_iterations, 11 * options.max_iterations);
    EXPECT_GE(r.total_iterations, r1.iterations);
    EXPECT_GE(r.attempts, 1);
    EXPECT_LE(r.attempts, 11);
    EXPECT_EQ(r.converged, r.status == IKStatus::converged);
    if (!r.converged) {
      EXPECT_EQ(r.attempts, 11) << "every restart is taken when none converges";
      EXPECT_TRUE(r.status == IKStatus::iteration_bound || r.status == IKStatus::no_progress);
    }
    if (r1.converged) {
      EXPECT_EQ(r.attempts, 1) << "a converged first attempt stops the restarts";
      EXPECT_EQ(r.total_iterations, r1.iterations);
      EXPECT_EQ(r.iterations, r1.iterations);
    }
    EXPECT_TRUE((r.q.array() >= lower.array()).all() && (r.q.array() <= upper.array()).all());
    EXPECT_EQ(r.error, chasles::pose_error(chain, T, r.q));
    if (r1.converged) {
      EXPECT_EQ(r.q, r1.q) << "a converged first attempt is kept";
    }
    if (r.converged) {
      EXPECT_LE(r.error.template head<3>().norm(), options.position_tolerance);
    }
  }
  // From one random seed about half converge (a local minimum of |e| or the
  // iteration bound otherwise); with 10 restarts at least 97 of 100 (99.3% of
  // 1000 measured on the UR5 in double).
  EXPECT_GE(converged, 97);
  EXPECT_GT(converged, converged_first);
}

TYPED_TEST(InverseKinematics, ZeroIterationsAtASolution) {
  using C = typename TypeParam::Chain;
  using S = typename C::Scalar;
  const int n = TypeParam::joints;
  const C chain = ur5_chain<C>(n);
  typename C::JointVector q(n);
  for (int i = 0; i < n; ++i) q(i) = S(0.1) * S(i + 1);
  const auto r = chasles::inverse_kinematics(chain, chain.forward(q), q);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(r.status, IKStatus::converged);
  EXPECT_EQ(r.iterations, 0);
  EXPECT_EQ(r.total_iterations, 0);
  EXPECT_EQ(r.attempts, 1);
  EXPECT_EQ(r.q, q);
  // The solution is checked before the budget: a spent budget still finds it.
  IKOptions<S> spent;
  spent.max_time = 0;
  EXPECT_EQ(chasles::inverse_kinematics(chain, chain.forward(q), q, spent).status, IKStatus::converged);
}

TYPED_TEST(InverseKinematics, RespectsJointLimits) {
  using C = typename TypeParam::Chain;
  using S = typename C::Scalar;
  using JV = typename C::JointVector;
  const int n = TypeParam::joints;
  const C chain = ur5_chain<C>(n);
  JV lower(n), upper(n), qt(n), q0(n);
  for (int i = 0; i < n; ++i) {
    lower(i) = S(-0.5), upper(i) = S(0.5);
    qt(i) = S(0.3) * S(i % 2 ? 1 : -1);
    q0(i) = S(2);  // outside: clamped to 0.5 first
  }
  const auto r = chasles::inverse_kinematics(chain, chain.forward(qt), q0, lower, upper);
  EXPECT_TRUE(r.converged);
  EXPECT_TRUE((r.q.array() >= lower.array()).all() && (r.q.array() <= upper.array()).all());

  // The target forward(qt) with joint 1 (the shoulder) at 1.2: a solution
  // outside [-0.5, 0.5]. Within the limits the error stays large and it is
  // reported as not converged, q still within the limits.
  JV qfar = qt;
  qfar(n - 5) = S(1.2);
  const auto rf = chasles::inverse_kinematics(chain, chain.forward(qfar), JV(JV::Zero(n)), lower, upper);
  EXPECT_FALSE(rf.converged);
  EXPECT_TRUE((rf.q.array() >= lower.array()).all() && (rf.q.array() <= upper.array()).all());
  EXPECT_GT(rf.error.norm(), S(1e-3));
}

TYPED_TEST(InverseKinematics, UnreachableTargetIsReportedWithinTheBound) {
  using C = typename TypeParam::Chain;
  using S = typename C::Scalar;
  using JV = typename C::JointVector;
  const int n = TypeParam::joints;
  const C chain = ur5_chain<C>(n);
  const SE3<S> far(chain.home().rotation(),
                   chain.home().translation() + Eigen::Matrix<S, 3, 1>(S(5), S(5), S(5)));  // ~9 m from a 1 m arm
  JV lower(n), upper(n);
  for (int i = 0; i < n; ++i) lower(i) = S(-kPi), upper(i) = S(kPi);
  IKOptions<S> options;
  options.max_iterations = 25;
  const auto r = chasles::inverse_kinematics(chain, far, JV(JV::Zero(n)), lower, upper, options);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.status, IKStatus::iteration_bound);
  EXPECT_EQ(r.iterations, 25);
  EXPECT_TRUE(r.q.allFinite() && r.error.allFinite());
  EXPECT_GT(r.error.template head<3>().norm(), S(3));

  // Given iterations enough, the 6-joint arm reaches the configuration
  // nearest the target and stops there when the step falls below rounding,
  // before the bound. (The railed arm, held at two limits, in double still
  // gains 1e-9 of its cost per iteration after 10000: it may end at the bound.)
  options.max_iterations = 2000;
  const auto stalled = chasles::inverse_kinematics(chain, far, JV(JV::Zero(n)), lower, upper, options);
  if (n == 6) {
    EXPECT_EQ(stalled.status, IKStatus::no_progress);
    EXPECT_LT(stalled.iterations, options.max_iterations);
  } else {
    EXPECT_TRUE(stalled.status == IKStatus::iteration_bound || stalled.status == IKStatus::no_progress);
  }
  EXPECT_LE(stalled.error.norm(), r.error.norm());
}

// An attempt that a restart follows ends as soon as it stalls: on an
// unreachable target its cost stops falling within a few windows of
// ik_stall_iterations, where the same attempt with no restart after it runs
// on until its step falls below rounding or to the bound. With restarts,
// every attempt but the last is cut so.
TYPED_TEST(InverseKinematics, AStalledAttemptEndsWhenARestartRemains) {
  using C = typename TypeParam::Chain;
  using S = typename C::Scalar;
  using JV = typename C::JointVector;
  const int n = TypeParam::joints;
  const C chain = ur5_chain<C>(n);
  const SE3<S> far(chain.home().rotation(), chain.home().translation() + Eigen::Matrix<S, 3, 1>(S(5), S(5), S(5)));
  JV lower(n), upper(n);
  for (int i = 0; i < n; ++i) lower(i) = S(-kPi), upper(i) = S(kPi);
  IKOptions<S> options;
  options.max_iterations = 2000;
  constexpr int window = chasles::ThresholdsOf<S>::ik_stall_iterations;
  const auto none = chasles::detail::IKDeadline::after(options.max_time);
  const JV zero = JV::Zero(n);
  const auto cut = chasles::detail::ik_attempt(chain, far, zero, lower, upper, options, none, true);
  const auto last = chasles::detail::ik_attempt(chain, far, zero, lower, upper, options, none, false);
  EXPECT_EQ(cut.status, IKStatus::no_progress);
  EXPECT_GE(cut.iterations, window);
  EXPECT_LE(cut.iterations, 4 * window);
  EXPECT_GT(last.iterations, 4 * window);  // 48 to 143 iterations, by scalar and arm
  EXPECT_LE(last.error.norm(), cut.error.norm());

  // Two restarts: the attempts from q0 and from the first random seed are
  // cut, the last is not. The seeds drawn as inverse_kinematics draws them
  // (uniform within the limits, from the same generator state).
  std::mt19937_64 gen(5), same(5);
  std::uniform_real_distribution<chasles::RealOf<S>> uniform(0, 1);
  JV seed[2] = {JV(n), JV(n)};
  for (JV& s : seed)
    for (int i = 0; i < n; ++i) s(i) = lower(i) + (upper(i) - lower(i)) * S(uniform(same));
  const auto second = chasles::detail::ik_attempt(chain, far, seed[0], lower, upper, options, none, true);
  const auto third = chasles::detail::ik_attempt(chain, far, seed[1], lower, upper, options, none, false);
  const auto r = chasles::inverse_kinematics(chain, far, zero, lower, upper, options, gen, 2);
  EXPECT_EQ(r.attempts, 3);
  EXPECT_EQ(second.status, IKStatus::no_progress);
  EXPECT_LE(second.iterations, 4 * window);
  EXPECT_EQ(r.total_iterations, cut.iterations + second.iterations + third.iterations);
}

// The time budget: a spent budget stops before the first step; a budget of
// 0.2 s with unbounded restarts on an unreachable target is spent (it
// cannot end otherwise), and the call returns after it. The seeds depend on
// the generator only: equal generators, no budget, equal results.
TYPED_TEST(InverseKinematics, TimeBudgetAndRestarts) {
  using C = typename TypeParam::Chain;
  using S = typename C::Scalar;
  using JV = typename C::JointVector;
  const int n = TypeParam::joints;
  const C chain = ur5_chain<C>(n);
  JV lower(n), upper(n), q0(n);
  for (int i = 0; i < n; ++i) lower(i) = S(-kPi), upper(i) = S(kPi), q0(i) = S(4);  // q0 clamped to pi
  const SE3<S> far(chain.home().rotation(), chain.home().translation() + Eigen::Matrix<S, 3, 1>(S(5), S(5), S(5)));
  IKOptions<S> options;
  options.max_time = 0;
  std::mt19937_64 gen(3);
  const auto spent = chasles::inverse_kinematics(chain, far, q0, lower, upper, options, gen, 1000);
  EXPECT_EQ(spent.status, IKStatus::time_budget);
  EXPECT_FALSE(spent.converged);
  EXPECT_EQ(spent.iterations, 0);
  EXPECT_EQ(spent.attempts, 1);
  EXPECT_EQ(spent.q, JV(JV::Constant(n, S(kPi))));
  EXPECT_EQ(spent.error, chasles::pose_error(chain, far, spent.q));

  options.max_time = 0.2;  // restarts within it even when a loaded machine pauses the process
  options.max_iterations = 10;
  const auto t0 = std::chrono::steady_clock::now();
  const auto budget = chasles::inverse_kinematics(chain, far, q0, lower, upper, options, gen, 1 << 30);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  EXPECT_EQ(budget.status, IKStatus::time_budget);
  EXPECT_GT(budget.attempts, 1);
  EXPECT_LE(budget.iterations, options.max_iterations);
  EXPECT_GE(budget.total_iterations, budget.iterations);
  EXPECT_GE(elapsed, options.max_time);
  EXPECT_LT(elapsed, options.max_time + 10.0) << "the budget ends the call (10 s: slack for a loaded machine)";
  EXPECT_EQ(budget.error, chasles::pose_error(chain, far, budget.q));

  // A reachable target with restarts and no budget: the same generator state gives the same result.
  JV qt(n);
  for (int i = 0; i < n; ++i) qt(i) = S(0.4) * S(i % 3) - S(0.5);
  options = IKOptions<S>();
  options.max_iterations = 5;  // a few attempts fail, so that the restarts draw seeds
  std::mt19937_64 g1(11), g2(11);
  const auto a = chasles::inverse_kinematics(chain, chain.forward(qt), q0, lower, upper, options, g1, 50);
  const auto b = chasles::inverse_kinematics(chain, chain.forward(qt), q0, lower, upper, options, g2, 50);
  EXPECT_GT(a.attempts, 1);
  EXPECT_EQ(a.q, b.q);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.attempts, b.attempts);
  EXPECT_EQ(a.total_iterations, b.total_iterations);
}

}  // namespace
