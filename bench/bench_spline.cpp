// chasles C++ benchmarks of spline evaluation against the number of keys:
// one evaluation (element, body velocity and body acceleration) of the
// interpolating splines (Spline<SO3d>, Spline<SE3d>) and of the cubic
// B-splines (CubicBSplineView<SO3d>, <SE3d>) over 10, 10^3, 10^5 and 10^6
// keys, at times cycled through 1024 pre-generated times uniform over the
// whole range (nothing constant-folds, every segment is as likely). The
// evaluation is a binary search over the key times (a division for the
// uniform B-spline) plus O(1) work: the time per evaluation stays flat from
// 10 to 10^6 keys, up to the cache misses of the search.
//
//   build/bench/chasles_bench_spline --benchmark_repetitions=5
//     --benchmark_report_aggregates_only=true
//
// Names: Spline/<group>/<op>/<keys>, BSpline/<group>/<op>/<keys>, double.
#include <cstddef>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "chasles/bspline.hpp"
#include "chasles/spline.hpp"
#include "harness.hpp"

namespace {

using chasles_bench::add;
using chasles_bench::kN;
constexpr int kKeys[] = {10, 1000, 100000, 1000000};

/// n elements of a random walk: steps exp(z), z ~ N(0, 0.35^2 I) per tangent coordinate.
template <typename Group>
std::vector<Group> walk(int n, std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0, 0.35);
  std::vector<Group> out;
  out.reserve(static_cast<std::size_t>(n));
  Group X = Group::identity();
  for (int i = 0; i < n; ++i) {
    Eigen::Matrix<double, Group::DoF, 1> z;
    for (int j = 0; j < Group::DoF; ++j) z[j] = normal(rng);
    X = X * Group::exp(z);
    out.push_back(X);
  }
  return out;
}

/// Spline/<group>/evaluate/<n> and Spline/<group>/element/<n>: the spline
/// through n keys 0.3 to 1 s apart, fitted once.
template <typename Group>
void register_spline(const std::string& group, int n) {
  struct Storage {
    std::vector<double> times;
    std::vector<Group> keys;
    std::vector<chasles::SplineSegment<Group>> segments;
  };
  const auto st = std::make_shared<Storage>();
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> step(0.3, 1.0);
  st->keys = walk<Group>(n, rng);
  double t = 0;
  for (int i = 0; i < n; ++i, t += step(rng)) st->times.push_back(t);
  st->segments.resize(static_cast<std::size_t>(n - 1));
  {
    std::vector<chasles::SplineWork<Group>> work(static_cast<std::size_t>(n));
    chasles::fit_spline(n, st->times.data(), st->keys.data(), st->segments.data(), work.data());
  }
  std::uniform_real_distribution<double> u(0, st->times.back());
  std::vector<double> ts;
  for (std::size_t i = 0; i < kN; ++i) ts.push_back(u(rng));
  const chasles::Spline<Group> spline(n, st->times.data(), st->keys.data(), st->segments.data());
  const std::string keys = std::to_string(n);
  add("Spline/" + group + "/evaluate/" + keys, ts, [spline, st](double time) { return spline(time); });
  add("Spline/" + group + "/element/" + keys, ts, [spline, st](double time) { return spline.element(time); });
}

/// BSpline/<group>/evaluate/<n> and BSpline/<group>/element/<n>: n control
/// elements, start time 0, spacing 1.
template <typename Group>
void register_bspline(const std::string& group, int n) {
  std::mt19937_64 rng(31);
  const auto control = std::make_shared<std::vector<Group>>(walk<Group>(n, rng));
  std::uniform_real_distribution<double> u(0, double(n - 3));
  std::vector<double> ts;
  for (std::size_t i = 0; i < kN; ++i) ts.push_back(u(rng));
  const chasles::CubicBSplineView<Group> view(control->data(), n, 0.0, 1.0);
  const std::string keys = std::to_string(n);
  add("BSpline/" + group + "/evaluate/" + keys, ts, [view, control](double t) { return view.evaluate(t); });
  add("BSpline/" + group + "/element/" + keys, ts, [view, control](double t) { return view(t); });
}

}  // namespace

int main(int argc, char** argv) {
  for (const int n : kKeys) {
    register_spline<chasles::SO3d>("SO3", n);
    register_spline<chasles::SE3d>("SE3", n);
    register_bspline<chasles::SO3d>("SO3", n);
    register_bspline<chasles::SE3d>("SE3", n);
  }
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
