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

#include "chasles/chasles.hpp"
#include "chasles/jacobians.hpp"
#include "chasles/kinematics.hpp"

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
/// shuffled inputs; returns the row.
template <typename In, typename Op>
Row measure(const std::string& name, const std::vector<In>& in, const std::vector<Kind>& kinds, Op op,
            std::size_t calls, const Timer& timer) {
  std::vector<double> t(calls);
  std::vector<std::vector<double>> by_kind(kKinds);
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
    by_kind[kinds[i % in.size()]].push_back(t[i]);
  }
  Row row{name, 0, 0, 0, 0, 0, ""};
  row.max = *std::max_element(t.begin(), t.end());
  row.p9999 = percentile(t, 0.9999);
  row.p99 = percentile(t, 0.99);
  row.median = percentile(t, 0.5);
  for (int k = 0; k < kKinds; ++k) {
    if (by_kind[k].empty()) continue;
    const double m = percentile(by_kind[k], 0.5);
    if (m >= row.worst_kind_median) {
      row.worst_kind_median = m;
      row.worst_kind = kKindNames[k];
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
  typename C::Screws screws;
  const S W1 = S(0.109), W2 = S(0.082), L1 = S(0.425), L2 = S(0.392), H1 = S(0.089), H2 = S(0.095);
  screws.col(0) << 0, 0, 0, 0, 0, 1;
  screws.col(1) << -H1, 0, 0, 0, 1, 0;
  screws.col(2) << -H1, 0, L1, 0, 1, 0;
  screws.col(3) << -H1, 0, L1 + L2, 0, 1, 0;
  screws.col(4) << -W1, L1 + L2, 0, 0, 0, -1;
  screws.col(5) << H2 - H1, 0, L1 + L2, 0, 1, 0;
  Eigen::Matrix<S, 4, 4> home;
  home << -1, 0, 0, L1 + L2, 0, 0, 1, W1 + W2, 0, 1, 0, H1 - H2, 0, 0, 0, 1;
  const C chain(screws, SE3<S>::from_matrix_unchecked(home));
  std::vector<typename C::JointVector> joints(kN);
  for (std::size_t i = 0; i < kN; ++i)
    for (int j = 0; j < 6; ++j) joints[i](j) = (n(rng) < 0 ? -1 : 1) * rotation_vector<S>(kinds[i], rng).norm();

  std::vector<Row> rows;
  rows.push_back(measure("SO3/exp", ws, kinds, [](const V3& w) { return SO3<S>::exp(w); }, calls, timer));
  rows.push_back(measure("SO3/log", Rs, kinds, [](const SO3<S>& R) { return R.log(); }, calls, timer));
  rows.push_back(measure("SO3/compose", Rpairs, kinds, [](const auto& p) { return p.first * p.second; }, calls,
                         timer));
  rows.push_back(measure("SO3/act", Rpoints, kinds, [](const auto& p) { return V3(p.first * p.second); }, calls,
                         timer));
  rows.push_back(measure("SO3/as_quaternion", Rs, kinds, [](const SO3<S>& R) { return R.quaternion(); }, calls,
                         timer));
  rows.push_back(measure("SO3/from_quaternion", qs, kinds,
                         [](const Eigen::Quaternion<S>& q) { return SO3<S>::from_quaternion(q); }, calls, timer));
  rows.push_back(measure("SO3/from_matrix (checked)", Ms, kinds, [](const M3& M) { return SO3<S>::from_matrix(M); },
                         calls, timer));
  rows.push_back(measure("SO3/from_matrix_projected", Ms, kinds,
                         [](const M3& M) { return SO3<S>::from_matrix_projected(M); }, calls, timer));
  // Projection of arbitrary matrices (Gaussian entries: reflections, near
  // singular ones), where the Jacobi sweeps (at most 12) take longest.
  rows.push_back(measure("SO3/from_matrix_projected (any matrix)", arbitrary, kinds,
                         [](const M3& M) { return SO3<S>::from_matrix_projected(M); }, calls, timer));
  rows.push_back(measure("SO3/interpolate", Rpairs, kinds,
                         [](const auto& p) { return interpolate(p.first, p.second, S(0.3)); }, calls, timer));
  rows.push_back(measure("SE3/exp", xis, kinds, [](const V6& xi) { return SE3<S>::exp(xi); }, calls, timer));
  rows.push_back(measure("SE3/log", gs, kinds, [](const SE3<S>& g) { return g.log(); }, calls, timer));
  rows.push_back(measure("SE3/compose", gpairs, kinds, [](const auto& p) { return p.first * p.second; }, calls,
                         timer));
  rows.push_back(measure("SE3/inverse", gs, kinds, [](const SE3<S>& g) { return g.inverse(); }, calls, timer));
  rows.push_back(measure("SE3/act", gpoints, kinds, [](const auto& p) { return V3(p.first * p.second); }, calls,
                         timer));
  rows.push_back(measure("SE3/adjoint", gs, kinds, [](const SE3<S>& g) { return g.adjoint(); }, calls, timer));
  rows.push_back(measure("SE3/interpolate", gpairs, kinds,
                         [](const auto& p) { return interpolate(p.first, p.second, S(0.3)); }, calls, timer));
  rows.push_back(measure("Twist/screw", xis, kinds, [](const V6& xi) { return Twist<S>(xi).screw(); }, calls,
                         timer));
  rows.push_back(measure("SE3/right_jacobian", xis, kinds, [](const V6& xi) { return se3_right_jacobian(xi); },
                         calls, timer));
  rows.push_back(measure("Chain/forward (6 joints)", joints, kinds,
                         [&chain](const typename C::JointVector& q) { return chain.forward(q); }, calls, timer));
  rows.push_back(measure("Chain/jacobian_space (6 joints)", joints, kinds,
                         [&chain](const typename C::JointVector& q) { return chain.jacobian_space(q); }, calls,
                         timer));
  return rows;
}

void print(const char* scalar, const std::vector<Row>& rows, std::size_t calls) {
  std::printf("### Latency per call, %s, %zu calls per op (ns)\n\n", scalar, calls);
  std::printf("| op | median | p99 | p99.99 | max | slowest kind | its median | / median |\n");
  std::printf("| --- | ---: | ---: | ---: | ---: | --- | ---: | ---: |\n");
  for (const Row& r : rows)
    std::printf("| %s | %.1f | %.1f | %.1f | %.0f | %s | %.1f | %.2f |\n", r.op.c_str(), r.median, r.p99, r.p9999,
                r.max, r.worst_kind.c_str(), r.worst_kind_median,
                r.median > 0 ? r.worst_kind_median / r.median : 0.0);
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
  return 0;
}
