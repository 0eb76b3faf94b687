// Forward dynamics against the number of joints: the composite-rigid-body
// algorithm with a Cholesky solve (forward_dynamics_composite: O(n^2) + O(n^3)) beside
// the articulated-body algorithm (forward_dynamics_articulated: O(n)), and
// the derivatives of inverse dynamics (O(n^2)), on random chains of 2 to 32
// joints (Chain<double, Dynamic, 32>: revolute joints about random axes,
// boxes of 1 to 4 kg). Run with random interleaving and repetitions, so
// that the two algorithms of one length share the machine's state:
//
//   chasles_bench_chain_length --benchmark_repetitions=10
//       --benchmark_enable_random_interleaving=true --benchmark_report_aggregates_only=true
//
// (one command line)
//
// and compare the "min" rows (the least-disturbed repetition, a statistic
// added here to Google Benchmark's mean, median and stddev). The crossover
// sets chasles::articulated_body_min_joints (dynamics.hpp), from which
// forward_dynamics takes the articulated-body algorithm.
#include <chasles/dynamics.hpp>
#include <chasles/dynamics_derivatives.hpp>
#include <chasles/kinematics.hpp>

#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "harness.hpp"

namespace {

using chasles_bench::kN;

/// chasles_bench::add, with the minimum over the repetitions among the statistics.
template <typename In, typename Op>
void add(const std::string& name, std::vector<In> in, Op op) {
  benchmark::RegisterBenchmark(name.c_str(), [in = std::move(in), op](benchmark::State& s) {
    chasles_bench::run(s, in, op);
  })->ComputeStatistics("min", [](const std::vector<double>& v) { return *std::min_element(v.begin(), v.end()); });
}
using Chain = chasles::Chain<double, Eigen::Dynamic, 32>;

struct State {
  Chain::JointVector q, qd, tau;
};

void register_length(int n) {
  std::mt19937_64 rng(101 + std::uint64_t(n));
  std::uniform_real_distribution<double> u(-1, 1), m(1, 4), side(0.05, 0.3);
  Chain::Screws S(6, n);
  Chain::Inertias inertias;
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d axis(u(rng), u(rng), u(rng));
    S.col(i) = Chain::revolute_screw(point, axis);
    const double mass = m(rng), x = side(rng), y = side(rng), z = side(rng);
    const Eigen::Vector3d moments(mass * (y * y + z * z) / 12, mass * (x * x + z * z) / 12,
                                  mass * (x * x + y * y) / 12);
    inertias[std::size_t(i)] =
        chasles::SpatialInertia<double>(mass, point + Eigen::Vector3d(0.05, 0, 0), moments.asDiagonal());
    point += Eigen::Vector3d(0.1, 0.02 * u(rng), 0.02 * u(rng));
  }
  const Chain chain(S, chasles::SE3d(), inertias);
  std::vector<State> states;
  for (std::size_t k = 0; k < kN; ++k) {
    State s{Chain::JointVector(n), Chain::JointVector(n), Chain::JointVector(n)};
    for (int j = 0; j < n; ++j) s.q(j) = 3 * u(rng), s.qd(j) = 2 * u(rng), s.tau(j) = 10 * u(rng);
    states.push_back(s);
  }
  const std::string tail = "/" + std::to_string(n);
  add("forward_dynamics/crba_cholesky" + tail, states,
      [chain](const State& x) { return chasles::forward_dynamics_composite(chain, x.q, x.qd, x.tau).qdd; });
  add("forward_dynamics/articulated" + tail, states,
      [chain](const State& x) { return chasles::forward_dynamics_articulated(chain, x.q, x.qd, x.tau).qdd; });
  add("inverse_dynamics_derivatives" + tail, states,
      [chain](const State& x) { return chasles::inverse_dynamics_derivatives(chain, x.q, x.qd, x.tau).dtau_dq; });
}

}  // namespace

int main(int argc, char** argv) {
  for (const int n : {2, 4, 6, 7, 8, 10, 12, 16, 20, 24, 26, 28, 30, 32}) register_length(n);
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
