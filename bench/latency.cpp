// Worst-case latency of chasles operations, for real-time use: every call of
// every operation is timed on its own, over a million calls, and the median,
// the 99th and 99.99th percentiles and the maximum are reported. The inputs
// mix every kind a controller meets (generic, exactly zero, tiny ~1e-9, at
// the Taylor cutoff, near pi, exactly pi), shuffled, so a data-dependent slow
// path shows in the tail; the median of each kind is reported too, and its
// ratio to the operation's median ("worst kind / median") must stay below 2.
//
//   build/bench/chasles_latency                  # 1e6 calls per op, markdown
//   build/bench/chasles_latency --calls 1000     # smoke run
//
// Timer: the time-stamp counter (lfence; rdtsc ... rdtscp; lfence) on x86,
// steady_clock elsewhere. The cost of an empty timed region (its median) is
// measured first and subtracted, so for the fastest operations (a few ns) the
// median is at the timer's resolution; the tail is what this table is for.
// The maximum includes whatever the operating system does to the thread
// (interrupts, preemption on a shared machine): it bounds the machine, not
// only the code. Timings are reported, never asserted.
//
// Then the robot-arm operations (run_robot): inverse kinematics on a UR5 and
// a Panda-like 7R arm per kind of problem (near the seed, 0.3 rad away,
// unreachable: the solver runs to its iteration bound, the worst case; at
// the joint limits) and mixed, with the iterations each kind took; dynamics
// of the 7R arm; SpatialInertia::transform; spline and B-spline evaluation.
// IK rows time calls / 100 calls (at least 16): a call is up to 100
// iterations.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>  // DoNotOptimize only

#include "chasles/bspline.hpp"
#include "chasles/chasles.hpp"
#include "chasles/dynamics.hpp"
#include "chasles/inverse_kinematics.hpp"
#include "chasles/jacobians.hpp"
#include "chasles/kinematics.hpp"
#include "chasles/spatial_inertia.hpp"
#include "chasles/spline.hpp"
#include "support/arms.hpp"

#if defined(__x86_64__) || defined(__i386__)
#include <x86intrin.h>
#define CHASLES_LATENCY_TSC 1
#endif

namespace {

constexpr double kPi = 3.14159265358979323846;

inline std::uint64_t stamp_begin() noexcept {
#ifdef CHASLES_LATENCY_TSC
  _mm_lfence();
  const std::uint64_t t = __rdtsc();
  _mm_lfence();
  return t;
#else
  return std::uint64_t(std::chrono::steady_clock::now().time_since_epoch().count());
#endif
}

inline std::uint64_t stamp_end() noexcept {
#ifdef CHASLES_LATENCY_TSC
  unsigned aux;
  const std::uint64_t t = __rdtscp(&aux);  // waits for the timed work to finish
  _mm_lfence();
  return t;
#else
  return std::uint64_t(std::chrono::steady_clock::now().time_since_epoch().count());
#endif
}

/// Nanoseconds per tick: the TSC measured against steady_clock over 50 ms.
double ns_per_tick() {
#ifdef CHASLES_LATENCY_TSC
  const auto c0 = std::chrono::steady_clock::now();
  const std::uint64_t t0 = __rdtsc();
  while (std::chrono::steady_clock::now() - c0 < std::chrono::milliseconds(50)) {
  }
  const auto c1 = std::chrono::steady_clock::now();
  const std::uint64_t t1 = __rdtsc();
  return std::chrono::duration<double, std::nano>(c1 - c0).count() / double(t1 - t0);
#else
  using period = std::chrono::steady_clock::period;
  return 1e9 * double(period::num) / double(period::den);
#endif
}

/// The kinds of input, each a share of the shuffled calls.
enum Kind { kGeneric, kZero, kTiny, kCutoff, kNearPi, kPi_, kKinds };
const char* const kKindNames[kKinds] = {"generic", "zero", "tiny", "cutoff", "near_pi", "pi"};

/// A rotation vector of the given kind. "cutoff" puts theta^2 on the Taylor
/// threshold of the scalar type, where the series and the closed form meet.
template <typename S>
Eigen::Matrix<S, 3, 1> rotation_vector(Kind kind, std::mt19937_64& rng) {
  std::normal_distribution<double> n(0, 1);
  std::uniform_real_distribution<double> u(0.1, 3.0);
  Eigen::Vector3d axis(n(rng), n(rng), n(rng));
  axis.normalize();
  double angle = 0;
  switch (kind) {
    case kGeneric: angle = u(rng); break;
    case kZero: angle = 0; break;
    case kTiny: angle = 1e-9 * (1 + u(rng)); break;
    case kCutoff: angle = std::sqrt(double(chasles::Thresholds<S>::taylor_theta2)); break;
    case kNearPi: angle = kPi - 1e-6 * u(rng); break;
    case kPi_: {
      // Exactly pi about a coordinate axis (the rotation matrix is exact).
      axis = Eigen::Vector3d::Unit(int(rng() % 3));
      angle = kPi;
      break;
    }
    default: break;
  }
  return (angle * axis).cast<S>();
}

struct Row {
  std::string op;
  double median, p99, p9999, max;
  double worst_kind_median;
  std::string worst_kind;
};

double percentile(std::vector<double>& v, double q) {
  const std::size_t k = std::min(v.size() - 1, std::size_t(q * double(v.size() - 1) + 0.5));
  std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
  return v[k];
}

struct Timer {
  double ns_tick;
  double overhead_ticks;  // median of an empty timed region
};

/// Times op(inputs[i]) call by call over `calls` calls cycling through the
/// shuffled inputs; returns the row. `kinds[i]` indexes `kind_names` (the
/// rotation kinds above unless given).
template <typename In, typename Op, typename K>
Row measure(const std::string& name, const std::vector<In>& in, const std::vector<K>& kinds, Op op, std::size_t calls,
            const Timer& timer, const char* const* kind_names = kKindNames, int kind_count = kKinds) {
  std::vector<double> t(calls);
  std::vector<std::vector<double>> by_kind(static_cast<std::size_t>(kind_count));
  for (std::size_t i = 0; i < std::min<std::size_t>(calls, 4096); ++i) {  // warm up
    auto r = op(in[i % in.size()]);
    benchmark::DoNotOptimize(r);
  }
  for (std::size_t i = 0; i < calls; ++i) {
    const In& x = in[i % in.size()];
    const std::uint64_t t0 = stamp_begin();
    auto r = op(x);
    benchmark::DoNotOptimize(r);
    const std::uint64_t t1 = stamp_end();
    t[i] = std::max(0.0, (double(t1 - t0) - timer.overhead_ticks) * timer.ns_tick);
    by_kind[static_cast<std::size_t>(kinds[i % in.size()])].push_back(t[i]);
  }
  Row row{name, 0, 0, 0, 0, 0, ""};
  row.max = *std::max_element(t.begin(), t.end());
  row.p9999 = percentile(t, 0.9999);
  row.p99 = percentile(t, 0.99);
  row.median = percentile(t, 0.5);
  for (int k = 0; k < kind_count; ++k) {
    if (by_kind[static_cast<std::size_t>(k)].empty()) continue;
    const double m = percentile(by_kind[static_cast<std::size_t>(k)], 0.5);
    if (m >= row.worst_kind_median) {
      row.worst_kind_median = m;
      row.worst_kind = kind_names[k];
    }
  }
  return row;
}

Timer calibrate() {
  Timer timer{ns_per_tick(), 0};
  std::vector<double> empty(200000);
  for (auto& e : empty) {
    const std::uint64_t t0 = stamp_begin();
    const std::uint64_t t1 = stamp_end();
    e = double(t1 - t0);
  }
  timer.overhead_ticks = percentile(empty, 0.5);
  return timer;
}

template <typename S>
std::vector<Row> run_all(std::size_t calls, const Timer& timer) {
  using namespace chasles;
  using V3 = Eigen::Matrix<S, 3, 1>;
  using V6 = Eigen::Matrix<S, 6, 1>;
  using M3 = Eigen::Matrix<S, 3, 3>;
  constexpr std::size_t kN = 4096;  // inputs per op: 4096 cycled, shuffled kinds
  std::mt19937_64 rng(2024);
  std::normal_distribution<double> n(0, 1);
  std::vector<Kind> kinds(kN);
  for (std::size_t i = 0; i < kN; ++i) kinds[i] = Kind(i % kKinds);
  std::shuffle(kinds.begin(), kinds.end(), rng);

  std::vector<V3> ws, points;
  std::vector<V6> xis;
  std::vector<SO3<S>> Rs;
  std::vector<SE3<S>> gs;
  std::vector<M3> Ms;
  std::vector<M3> arbitrary;
  std::vector<Eigen::Quaternion<S>> qs;
  for (std::size_t i = 0; i < kN; ++i) {
    M3 A;
    for (int k = 0; k < 9; ++k) A(k) = S(n(rng));
    arbitrary.push_back(A);
    ws.push_back(rotation_vector<S>(kinds[i], rng));
    points.push_back(V3(S(n(rng)), S(n(rng)), S(n(rng))));
    V6 xi;
    xi << points.back(), ws.back();
    xis.push_back(xi);
    Rs.push_back(SO3<S>::exp(ws.back()));
    gs.push_back(SE3<S>::exp(xi));
    Ms.push_back(Rs.back().matrix());
    qs.push_back(Rs.back().quaternion());
  }
  std::vector<std::pair<SO3<S>, SO3<S>>> Rpairs;
  std::vector<std::pair<SE3<S>, SE3<S>>> gpairs;
  std::vector<std::pair<SO3<S>, V3>> Rpoints;
  std::vector<std::pair<SE3<S>, V3>> gpoints;
  for (std::size_t i = 0; i < kN; ++i) {
    // The partner of a pair is a rotation of the same kind relative to the
    // first, so interpolation meets the same angles.
    Rpairs.emplace_back(Rs[i], Rs[i] * Rs[(i + 1) % kN]);
    gpairs.emplace_back(gs[i], gs[i] * gs[(i + 1) % kN]);
    Rpoints.emplace_back(Rs[i], points[(i + 7) % kN]);
    gpoints.emplace_back(gs[i], points[(i + 7) % kN]);
  }
  // A UR5 (Modern Robotics, example 4.5) with joint angles drawn from the
  // same kinds (each joint's angle is a rotation vector's norm, signed).
  using C = Chain<S, 6>;
  const C chain = chasles_test::ur5_chain<C>();
  std::vector<typename C::JointVector> joints(kN);
  for (std::size_t i = 0; i < kN; ++i)
    for (int j = 0; j < 6; ++j) joints[i](j) = (n(rng) < 0 ? -1 : 1) * rotation_vector<S>(kinds[i], rng).norm();

  std::vector<Row> rows;
  rows.push_back(measure("SO3/exp", ws, kinds, [](const V3& w) { return SO3<S>::exp(w); }, calls, timer));
  rows.push_back(measure("SO3/log", Rs, kinds, [](const SO3<S>& R) { return R.log(); }, calls, timer));
  rows.push_back(measure("SO3/compose", Rpairs, kinds, [](const auto& p) { return p.first * p.second; }, calls, timer));
  rows.push_back(
      measure("SO3/act", Rpoints, kinds, [](const auto& p) { return V3(p.first * p.second); }, calls, timer));
  rows.push_back(measure("SO3/as_quaternion", Rs, kinds, [](const SO3<S>& R) { return R.quaternion(); }, calls, timer));
  rows.push_back(measure(
      "SO3/from_quaternion", qs, kinds, [](const Eigen::Quaternion<S>& q) { return SO3<S>::from_quaternion(q); }, calls,
      timer));
  rows.push_back(measure(
      "SO3/from_matrix (checked)", Ms, kinds, [](const M3& M) { return SO3<S>::from_matrix(M); }, calls, timer));
  rows.push_back(measure(
      "SO3/from_matrix_projected", Ms, kinds, [](const M3& M) { return SO3<S>::from_matrix_projected(M); }, calls,
      timer));
  // Projection of arbitrary matrices (Gaussian entries: reflections, near
  // singular ones), where the Jacobi sweeps (at most 12) take longest.
  rows.push_back(measure(
      "SO3/from_matrix_projected (any matrix)", arbitrary, kinds,
      [](const M3& M) { return SO3<S>::from_matrix_projected(M); }, calls, timer));
  rows.push_back(measure(
      "SO3/interpolate", Rpairs, kinds, [](const auto& p) { return interpolate(p.first, p.second, S(0.3)); }, calls,
      timer));
  rows.push_back(measure("SE3/exp", xis, kinds, [](const V6& xi) { return SE3<S>::exp(xi); }, calls, timer));
  rows.push_back(measure("SE3/log", gs, kinds, [](const SE3<S>& g) { return g.log(); }, calls, timer));
  rows.push_back(measure("SE3/compose", gpairs, kinds, [](const auto& p) { return p.first * p.second; }, calls, timer));
  rows.push_back(measure("SE3/inverse", gs, kinds, [](const SE3<S>& g) { return g.inverse(); }, calls, timer));
  rows.push_back(
      measure("SE3/act", gpoints, kinds, [](const auto& p) { return V3(p.first * p.second); }, calls, timer));
  rows.push_back(measure("SE3/adjoint", gs, kinds, [](const SE3<S>& g) { return g.adjoint(); }, calls, timer));
  rows.push_back(measure(
      "SE3/interpolate", gpairs, kinds, [](const auto& p) { return interpolate(p.first, p.second, S(0.3)); }, calls,
      timer));
  rows.push_back(measure("Twist/screw", xis, kinds, [](const V6& xi) { return Twist<S>(xi).screw(); }, calls, timer));
  rows.push_back(
      measure("SE3/right_jacobian", xis, kinds, [](const V6& xi) { return se3_right_jacobian(xi); }, calls, timer));
  rows.push_back(measure(
      "Chain/forward (6 joints)", joints, kinds,
      [&chain](const typename C::JointVector& q) { return chain.forward(q); }, calls, timer));
  rows.push_back(measure(
      "Chain/jacobian_space (6 joints)", joints, kinds,
      [&chain](const typename C::JointVector& q) { return chain.jacobian_space(q); }, calls, timer));
  return rows;
}

// ---------------------------------------------------------------------------
// Robot-arm operations: inverse kinematics, dynamics, spatial inertia,
// splines.

/// The kinds of inverse kinematics problem.
enum IKKind { kNear, kAway, kUnreachable, kAtLimits, kIKKinds };
const char* const kIKKindNames[kIKKinds] = {"near seed", "0.3 rad", "unreachable", "at limits"};

/// Iterations per IK row (the same inputs, solved once beforehand).
struct IKIterations {
  std::string op;
  int min, max;
  double median;
  int converged, count;
};

/// IK problems on `chain` within [lower, upper] (every entry finite): per
/// kind, 64 targets forward(q*) of q* drawn within the limits (0.3 rad inside
/// them) with the seed q* + U(-0.01, 0.01) ("near seed") or q* + U(-0.3, 0.3)
/// per joint ("0.3 rad"); targets 3 times as far from the base as a reachable
/// one, seeded at its q*, kept when the solver runs to its iteration bound
/// ("unreachable": the worst case); q* with two joints exactly at a limit
/// and the seed 0.3 rad away ("at limits").
template <typename C>
void ik_rows(const std::string& arm, const C& chain, const typename C::JointVector& lower,
             const typename C::JointVector& upper, std::size_t calls, const Timer& timer, std::vector<Row>& rows,
             std::vector<IKIterations>& table) {
  using S = typename C::Scalar;
  using JV = typename C::JointVector;
  struct Problem {
    chasles::SE3<S> target;
    JV seed;
  };
  const int n = int(chain.n_joints());
  const chasles::IKOptions<S> options;
  std::mt19937_64 rng(7 + std::uint64_t(n));
  std::uniform_real_distribution<double> u(0, 1), near(-0.01, 0.01), away(-0.3, 0.3);
  const auto solve = [&](const Problem& p) {
    return chasles::inverse_kinematics(chain, p.target, p.seed, lower, upper, options);
  };
  const auto inside = [&] {
    JV q(n);
    for (int i = 0; i < n; ++i) {
      const double a = double(lower(i)) + 0.3, b = double(upper(i)) - 0.3;
      q(i) = S(a + (b - a) * u(rng));
    }
    return q;
  };
  std::vector<std::vector<Problem>> by_kind(kIKKinds);
  constexpr std::size_t kPerKind = 64;
  for (std::size_t k = 0; k < kPerKind; ++k) {
    const JV q = inside();
    JV s1(n), s2(n);
    for (int i = 0; i < n; ++i) s1(i) = q(i) + S(near(rng)), s2(i) = q(i) + S(away(rng));
    by_kind[kNear].push_back({chain.forward(q), s1});
    by_kind[kAway].push_back({chain.forward(q), s2});
    JV ql = q;
    const int a = int(rng() % std::uint64_t(n)), b = int((a + 1 + int(rng() % std::uint64_t(n - 1))) % n);
    ql(a) = lower(a);
    ql(b) = upper(b);
    JV s3(n);
    for (int i = 0; i < n; ++i) s3(i) = ql(i) + S(away(rng));
    by_kind[kAtLimits].push_back({chain.forward(ql), s3});
  }
  // Unreachable: a reachable pose moved out from the base by a factor 3 to
  // 100, seeded at its q*. The solver settles on the nearest pose, slowly
  // (a large residual: linear convergence), and stops at the bound or when
  // its step is below rounding, whichever comes first; the farther, the
  // more often at the bound (UR5 in double: 8% of the targets at 3 times,
  // 40% at 100 times; in float 0.5% to 4%). Kept: up to 64 of 2000 that ran
  // to the bound (the worst case), or if none did, the 64 that took the
  // most iterations (the iteration table shows which).
  std::vector<std::pair<int, Problem>> candidates;
  const double factors[4] = {3.0, 10.0, 30.0, 100.0};
  std::size_t at_bound = 0;
  for (int attempt = 0; attempt < 2000 && at_bound < kPerKind; ++attempt) {
    const JV q = inside();
    const chasles::SE3<S> g = chain.forward(q);
    const Problem p{chasles::SE3<S>(g.rotation(), Eigen::Matrix<S, 3, 1>(g.translation() * S(factors[attempt % 4]))),
                    q};
    const auto r = solve(p);
    if (r.converged) continue;
    candidates.emplace_back(r.iterations, p);
    at_bound += r.iterations == options.max_iterations;
  }
  std::stable_sort(candidates.begin(), candidates.end(),
                   [](const auto& a, const auto& b) { return a.first > b.first; });
  const std::size_t keep = std::min(candidates.size(), at_bound > 0 ? at_bound : kPerKind);
  for (std::size_t i = 0; i < keep; ++i) by_kind[kUnreachable].push_back(candidates[i].second);
  const std::size_t ik_calls = std::max<std::size_t>(calls / 100, 16);
  std::vector<Problem> mixed;
  std::vector<int> mixed_kinds;
  for (int k = 0; k < kIKKinds; ++k) {
    const std::vector<Problem>& ps = by_kind[std::size_t(k)];
    if (ps.empty()) continue;
    const std::string op = "IK/" + arm + " " + kIKKindNames[k];
    std::vector<int> kinds(ps.size(), k), its;
    int converged = 0;
    for (const Problem& p : ps) {
      const auto r = solve(p);
      its.push_back(r.iterations);
      converged += r.converged;
    }
    std::sort(its.begin(), its.end());
    table.push_back({op, its.front(), its.back(), double(its[its.size() / 2]), converged, int(ps.size())});
    rows.push_back(
        measure(op, ps, kinds, [&](const Problem& p) { return solve(p).q; }, ik_calls, timer, kIKKindNames, kIKKinds));
    for (const Problem& p : ps) mixed.push_back(p), mixed_kinds.push_back(k);
  }
  // The same problems shuffled together: the tail of a mix.
  std::vector<std::size_t> order(mixed.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::shuffle(order.begin(), order.end(), rng);
  std::vector<Problem> shuffled;
  std::vector<int> shuffled_kinds;
  for (std::size_t i : order) shuffled.push_back(mixed[i]), shuffled_kinds.push_back(mixed_kinds[i]);
  rows.push_back(measure(
      "IK/" + arm + " mixed", shuffled, shuffled_kinds, [&](const Problem& p) { return solve(p).q; }, ik_calls, timer,
      kIKKindNames, kIKKinds));
}

/// The kinds of dynamics input.
enum DynKind { kDynGeneric, kDynRest, kDynHuge, kDynKinds };
const char* const kDynKindNames[kDynKinds] = {"generic", "at rest", "huge velocities"};

/// The robot-arm rows: IK (UR5, Panda-like), dynamics (Panda-like, inputs
/// generic, at rest, at huge velocities 1e4 rad/s), SpatialInertia::transform
/// over poses of every rotation kind, spline and B-spline evaluation at
/// times in segments whose relative motion is of every rotation kind.
template <typename S>
std::vector<Row> run_robot(std::size_t calls, const Timer& timer, std::vector<IKIterations>& table) {
  using namespace chasles;
  using V3 = Eigen::Matrix<S, 3, 1>;
  using V6 = Eigen::Matrix<S, 6, 1>;
  std::vector<Row> rows;
  const chasles_test::PandaLike<S> panda;

  // Inverse kinematics: the UR5 within [-2 pi, 2 pi] per joint, the Panda-like arm within its limits.
  {
    const Chain<S, 6> u5 = chasles_test::ur5_chain<Chain<S, 6>>();
    const typename Chain<S, 6>::JointVector lo = Chain<S, 6>::JointVector::Constant(S(-2 * kPi)),
                                            hi = Chain<S, 6>::JointVector::Constant(S(2 * kPi));
    ik_rows("UR5 (6 joints)", u5, lo, hi, calls, timer, rows, table);
    const Chain<S, 7> arm(panda.screws, panda.home);
    ik_rows("Panda-like (7 joints)", arm, panda.lower, panda.upper, calls, timer, rows, table);
  }

  // Dynamics of the Panda-like arm.
  {
    using D = Chain<S, 7>;
    using JV = typename D::JointVector;
    const D dyn(panda.screws, panda.home, typename D::HomeAsGiven(), panda.inertias, V3(S(0), S(0), S(-9.81)));
    struct State {
      JV q, qd, qdd, tau;
    };
    constexpr std::size_t kN = 4096;
    std::mt19937_64 rng(99);
    std::uniform_real_distribution<double> u(-1, 1);
    std::vector<State> states;
    std::vector<int> kinds;
    for (std::size_t i = 0; i < kN; ++i) {
      const int k = int(i % kDynKinds);
      const double v = k == kDynRest ? 0 : k == kDynHuge ? 1e4 : 2;
      State st;
      for (int j = 0; j < 7; ++j) {
        st.q(j) = S(kPi * u(rng));
        st.qd(j) = S(v * u(rng));
        st.qdd(j) = S(2.5 * v * u(rng));
        st.tau(j) = S(20 * u(rng));
      }
      states.push_back(st);
      kinds.push_back(k);
    }
    std::vector<std::size_t> order(kN);
    for (std::size_t i = 0; i < kN; ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<State> xs;
    std::vector<int> ks;
    for (std::size_t i : order) xs.push_back(states[i]), ks.push_back(kinds[i]);
    rows.push_back(measure(
        "Dynamics/inverse_dynamics (7 joints)", xs, ks,
        [&dyn](const State& s) { return inverse_dynamics(dyn, s.q, s.qd, s.qdd); }, calls, timer, kDynKindNames,
        kDynKinds));
    rows.push_back(measure(
        "Dynamics/mass_matrix (7 joints)", xs, ks, [&dyn](const State& s) { return mass_matrix(dyn, s.q); }, calls,
        timer, kDynKindNames, kDynKinds));
    rows.push_back(measure(
        "Dynamics/gravity_torques (7 joints)", xs, ks, [&dyn](const State& s) { return gravity_torques(dyn, s.q); },
        calls, timer, kDynKindNames, kDynKinds));
    rows.push_back(measure(
        "Dynamics/forward_dynamics (7 joints)", xs, ks,
        [&dyn](const State& s) { return forward_dynamics(dyn, s.q, s.qd, s.tau); }, calls, timer, kDynKindNames,
        kDynKinds));
  }

  // SpatialInertia::transform over poses of every rotation kind, and splines
  // through 64 keys whose consecutive relative motions are of every kind.
  {
    constexpr std::size_t kN = 4096, kKeys = 64;
    std::mt19937_64 rng(2025);
    std::normal_distribution<double> nd(0, 1);
    std::vector<Kind> kinds(kN);
    for (std::size_t i = 0; i < kN; ++i) kinds[i] = Kind(i % kKinds);
    std::shuffle(kinds.begin(), kinds.end(), rng);
    std::vector<SE3<S>> gs;
    for (std::size_t i = 0; i < kN; ++i) {
      V6 xi;
      xi << V3(S(nd(rng)), S(nd(rng)), S(nd(rng))), rotation_vector<S>(kinds[i], rng);
      gs.push_back(SE3<S>::exp(xi));
    }
    const SpatialInertia<S>& body = panda.inertias[3];
    rows.push_back(measure(
        "SpatialInertia/transform", gs, kinds, [&body](const SE3<S>& g) { return body.transform(g); }, calls, timer));

    // Keys: X_{i+1} = X_i exp(xi_i) with xi_i of kind i % kKinds; times 0, 0.5, 1, ...
    std::vector<SE3<S>> keys{SE3<S>::identity()};
    std::vector<SO3<S>> rkeys{SO3<S>::identity()};
    std::vector<Kind> segment_kind;
    std::vector<S> times{S(0)};
    for (std::size_t i = 0; i + 1 < kKeys; ++i) {
      const Kind k = Kind(i % kKinds);
      V6 xi;
      xi << V3(S(nd(rng)), S(nd(rng)), S(nd(rng))), rotation_vector<S>(k, rng);
      keys.push_back(keys.back() * SE3<S>::exp(xi));
      rkeys.push_back(rkeys.back() * SO3<S>::exp(V3(xi.template tail<3>())));
      segment_kind.push_back(k);
      times.push_back(S(0.5 * double(i + 1)));
    }
    std::vector<SplineSegment<SE3<S>>> seg(kKeys - 1);
    std::vector<SplineWork<SE3<S>>> work(kKeys);
    std::vector<SplineSegment<SO3<S>>> rseg(kKeys - 1);
    std::vector<SplineWork<SO3<S>>> rwork(kKeys);
    fit_spline(int(kKeys), times.data(), keys.data(), seg.data(), work.data());
    fit_spline(int(kKeys), times.data(), rkeys.data(), rseg.data(), rwork.data());
    const SE3Spline<S> spline(int(kKeys), times.data(), keys.data(), seg.data());
    const SO3Spline<S> rspline(int(kKeys), times.data(), rkeys.data(), rseg.data());
    // B-splines over the same keys as control points, spacing 0.5 from 0.
    const SE3BSplineView<S> bspline(keys.data(), std::ptrdiff_t(kKeys), S(0), S(0.5));
    const SO3BSplineView<S> rbspline(rkeys.data(), std::ptrdiff_t(kKeys), S(0), S(0.5));
    std::vector<S> ts(kN);
    std::vector<Kind> tkinds(kN);
    std::uniform_real_distribution<double> within(0, 1);
    for (std::size_t i = 0; i < kN; ++i) {
      const std::size_t s = rng() % (kKeys - 1);
      ts[i] = S(0.5 * (double(s) + within(rng)));
      tkinds[i] = segment_kind[s];
    }
    rows.push_back(measure(
        "SE3Spline/operator() (64 keys)", ts, tkinds, [&spline](const S& t) { return spline(t).velocity; }, calls,
        timer));
    rows.push_back(measure(
        "SE3Spline/element (64 keys)", ts, tkinds, [&spline](const S& t) { return spline.element(t); }, calls, timer));
    rows.push_back(measure(
        "SO3Spline/operator() (64 keys)", ts, tkinds, [&rspline](const S& t) { return rspline(t).velocity; }, calls,
        timer));
    rows.push_back(measure(
        "SE3BSplineView/evaluate (64 points)", ts, tkinds,
        [&bspline](const S& t) { return bspline.evaluate(t).velocity; }, calls, timer));
    rows.push_back(measure(
        "SE3BSplineView/operator() (64 points)", ts, tkinds, [&bspline](const S& t) { return bspline(t); }, calls,
        timer));
    rows.push_back(measure(
        "SO3BSplineView/evaluate (64 points)", ts, tkinds,
        [&rbspline](const S& t) { return rbspline.evaluate(t).velocity; }, calls, timer));
  }
  return rows;
}

void print_iterations(const char* scalar, const std::vector<IKIterations>& table) {
  std::printf("### Inverse kinematics iterations per problem, %s (bound %d)\n\n", scalar,
              chasles::ThresholdsOf<double>::ik_max_iterations);
  std::printf("| problems | min | median | max | converged |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: |\n");
  for (const IKIterations& r : table)
    std::printf("| %s | %d | %.0f | %d | %d / %d |\n", r.op.c_str(), r.min, r.median, r.max, r.converged, r.count);
  std::printf("\n");
}

void print(const char* scalar, const std::vector<Row>& rows, std::size_t calls) {
  std::printf("### Latency per call, %s, %zu calls per op (ns)\n\n", scalar, calls);
  std::printf("| op | median | p99 | p99.99 | max | slowest kind | its median | / median |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: | --- | ---: | ---: |\n");
  for (const Row& r : rows)
    std::printf("| %s | %.1f | %.1f | %.1f | %.0f | %s | %.1f | %.2f |\n", r.op.c_str(), r.median, r.p99, r.p9999,
                r.max, r.worst_kind.c_str(), r.worst_kind_median, r.median > 0 ? r.worst_kind_median / r.median : 0.0);
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  std::size_t calls = 1000000;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--calls") == 0 && i + 1 < argc) {
      calls = std::strtoull(argv[++i], nullptr, 10);
    } else {
      std::fprintf(stderr, "usage: %s [--calls N]\n", argv[0]);
      return 2;
    }
  }
  if (calls == 0) {
    std::fprintf(stderr, "--calls must be positive\n");
    return 2;
  }
  const Timer timer = calibrate();
  std::printf("Timer: %s, empty timed region %.1f ns (subtracted)\n\n",
#ifdef CHASLES_LATENCY_TSC
              "rdtsc/rdtscp",
#else
              "steady_clock",
#endif
              timer.overhead_ticks * timer.ns_tick);
  print("double", run_all<double>(calls, timer), calls);
  print("float", run_all<float>(calls, timer), calls);
  std::printf("Robot-arm operations. IK rows: %zu calls each (calls / 100, at least 16).\n\n",
              std::max<std::size_t>(calls / 100, 16));
  for (const bool dbl : {true, false}) {
    std::vector<IKIterations> table;
    const std::vector<Row> rows = dbl ? run_robot<double>(calls, timer, table) : run_robot<float>(calls, timer, table);
    print(dbl ? "double, robot arms" : "float, robot arms", rows, calls);
    print_iterations(dbl ? "double" : "float", table);
  }
  return 0;
}
