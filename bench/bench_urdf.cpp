// The URDF loader, chain_from_urdf (include/chasles/urdf.hpp), per load:
// the arm of examples/data (from its file, and from its text in memory),
// a long side branch (25,000 fixed links, 3.3 MB of text) and, when given, a
// URDF file of the caller's (for instance the UR5 of example-robot-data, a
// Python package: pip download example-robot-data, then unzip it and find
// ur5_robot.urdf under cmeel.prefix/share):
//
//   CHASLES_BENCH_URDF=path/ur5_robot.urdf CHASLES_BENCH_URDF_TIP=tool0
//     build/bench/chasles_bench_urdf --benchmark_repetitions=5
//
// Without CHASLES_BENCH_URDF, that benchmark is skipped (not registered).
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>

#include <benchmark/benchmark.h>

#include "chasles/urdf.hpp"

namespace {

using Loaded = chasles::UrdfChain<double, 16>;

void load(benchmark::State& state, const std::string& source, const std::string& tip) {
  for (auto _ : state) {
    Loaded r = chasles::chain_from_urdf<double, 16>(source, tip);
    if (!r) {
      state.SkipWithError(r.error.c_str());
      break;
    }
    benchmark::DoNotOptimize(r);
  }
}

std::string read(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

/// a -j1-> b (revolute) and b's side branch of n fixed links.
std::string side_branch(int n) {
  std::string text = R"(<robot name="r"><link name="a"/><link name="b"/>)";
  for (int k = 0; k < n; ++k) text += "<link name=\"s" + std::to_string(k) + "\"/>";
  text += R"(<joint name="j1" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 0 1"/>)"
          R"(<limit lower="-1" upper="1" effort="1" velocity="1"/></joint>)";
  for (int k = 0; k < n; ++k)
    text += "<joint name=\"f" + std::to_string(k) + "\" type=\"fixed\"><parent link=\"" +
            (k ? "s" + std::to_string(k - 1) : std::string("b")) + "\"/><child link=\"s" + std::to_string(k) +
            "\"/><origin xyz=\"0.001 0 0\"/></joint>";
  return text + "</robot>";
}

}  // namespace

int main(int argc, char** argv) {
  const std::string arm = std::string(CHASLES_SOURCE_DIR) + "/examples/data/three_joint_arm.urdf";
  benchmark::RegisterBenchmark("URDF/load/three_joint_arm/file", load, arm, "tool");
  benchmark::RegisterBenchmark("URDF/load/three_joint_arm/text", load, read(arm), "tool");
  benchmark::RegisterBenchmark("URDF/load/side_branch_25000/text", load, side_branch(25000), "b")
      ->Unit(benchmark::kMillisecond);
  if (const char* path = std::getenv("CHASLES_BENCH_URDF")) {
    const char* tip = std::getenv("CHASLES_BENCH_URDF_TIP");
    benchmark::RegisterBenchmark("URDF/load/given/file", load, std::string(path), std::string(tip ? tip : "tool0"));
  }
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
