// chasles C++ benchmarks: what bench_ops.cpp and bench_spline.cpp share.
// Each benchmark cycles through kN pre-generated inputs, so that nothing
// constant-folds and every branch of an operation is exercised as the
// inputs' distribution says.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

namespace chasles_bench {

constexpr std::size_t kN = 1024;  // power of two: index with i & (kN - 1)

/// Runs op(inputs[i]) over the cycled inputs.
template <typename In, typename Op>
void run(benchmark::State& state, const std::vector<In>& in, Op op) {
  std::size_t i = 0;
  for (auto _ : state) {
    auto r = op(in[i & (kN - 1)]);
    benchmark::DoNotOptimize(r);
    ++i;
  }
}

/// Registers the benchmark `name`: op over the cycled inputs `in` (kN of them).
template <typename In, typename Op>
void add(const std::string& name, std::vector<In> in, Op op) {
  benchmark::RegisterBenchmark(name.c_str(), [in = std::move(in), op](benchmark::State& s) { run(s, in, op); });
}

}  // namespace chasles_bench
