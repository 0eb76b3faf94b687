// A pose graph solved end to end with Ceres: read a g2o file, solve, write
// the result.
//
//   example_pose_graph PATH.g2o [--out OUT.g2o]
//
// reads a 3D (VERTEX_SE3:QUAT / EDGE_SE3:QUAT) or 2D (VERTEX_SE2 /
// EDGE_SE2) pose graph, holds its first vertex fixed and minimizes
//
//   chi2 = sum over edges of e^T Omega e,  e = log(Z_ij^-1 X_i^-1 X_j)
//
// (twice GTSAM's graph error for its BetweenFactor) with Ceres: one
// parameter block per pose on chasles::CeresManifold, one
// chasles::BetweenCost per edge (analytic Jacobians), Levenberg-Marquardt
// over a sparse Cholesky factorization. It prints the initial and final
// chi2, the iterations and the time, and "all checks passed" when Ceres
// converged to a lower chi2 (and, with --out, the written file reads back
// to the same poses). The information matrix of an edge is over e in the
// tangent's order, (v, w) = g2o's (x, y, z, qx, qy, qz), as GTSAM and
// chasles.read_g2o read it. A malformed line is refused with its number.
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <ceres/problem.h>
#include <ceres/solver.h>
#include <Eigen/Cholesky>
#include <Eigen/Core>
#ifdef _OPENMP
#include <omp.h>
#endif

#include <chasles/ceres.hpp>

namespace {

using chasles::Parameters;

/// What a group's g2o lines hold.
template <typename G>
struct G2o;
template <>
struct G2o<chasles::SE3d> {
  static constexpr const char* vertex = "VERTEX_SE3:QUAT";
  static constexpr const char* edge = "EDGE_SE3:QUAT";
  static constexpr int numbers = 7;  // x y z qx qy qz qw
  /// The pose of g2o's numbers; empty for a quaternion of zero norm.
  static std::optional<chasles::SE3d> pose(const double* x) {
    const Eigen::Vector4d q(x[3], x[4], x[5], x[6]);
    if (!(q.squaredNorm() > 0.0)) return std::nullopt;
    return chasles::SE3d(chasles::SO3d::from_quaternion(Eigen::Quaterniond(q)), Eigen::Vector3d(x[0], x[1], x[2]));
  }
  static std::vector<double> numbers_of(const chasles::SE3d& g) {
    const Eigen::Vector4d q = g.rotation().quaternion().coeffs();
    const Eigen::Vector3d& p = g.translation();
    return {p[0], p[1], p[2], q[0], q[1], q[2], q[3]};
  }
};
template <>
struct G2o<chasles::SE2d> {
  static constexpr const char* vertex = "VERTEX_SE2";
  static constexpr const char* edge = "EDGE_SE2";
  static constexpr int numbers = 3;  // x y theta
  static std::optional<chasles::SE2d> pose(const double* x) {
    return chasles::SE2d(chasles::SO2d::exp(x[2]), Eigen::Vector2d(x[0], x[1]));
  }
  static std::vector<double> numbers_of(const chasles::SE2d& g) {
    return {g.translation()[0], g.translation()[1], g.rotation().angle()};
  }
};

/// One line of a g2o file, split: its tag, its integers (a vertex's id, an
/// edge's two) and its numbers.
struct Line {
  int number;
  std::string tag;
  std::vector<long long> ids;
  std::vector<double> values;
};

template <typename G>
struct Graph {
  std::vector<long long> ids;
  std::vector<Eigen::VectorXd> blocks;  // the poses, in Parameters<G>'s layout
  struct Edge {
    int i, j;
    G measurement;
    typename G::AdjointMatrix information;
  };
  std::vector<Edge> edges;
};

/// Prints "PATH: line N: what" and returns false.
bool refuse(const std::string& path, int line, const std::string& what) {
  std::fprintf(stderr, "%s: line %d: %s\n", path.c_str(), line, what.c_str());
  return false;
}

/// Splits the file into lines, refusing those that are not a vertex or an
/// edge of SE(3) or SE(2) with the right count of finite numbers. Blank
/// lines, # comments and FIX lines are skipped.
bool read_lines(const std::string& path, std::vector<Line>& out, bool& planar) {
  std::ifstream file(path);
  if (!file) {
    std::fprintf(stderr, "%s: cannot open\n", path.c_str());
    return false;
  }
  std::string text;
  int number = 0;
  std::optional<bool> group_planar;
  while (std::getline(file, text)) {
    ++number;
    std::istringstream words(text);
    Line line{number, "", {}, {}};
    if (!(words >> line.tag) || line.tag[0] == '#' || line.tag == "FIX") continue;
    const bool se3 = line.tag == G2o<chasles::SE3d>::vertex || line.tag == G2o<chasles::SE3d>::edge;
    const bool se2 = line.tag == G2o<chasles::SE2d>::vertex || line.tag == G2o<chasles::SE2d>::edge;
    if (!se3 && !se2) return refuse(path, number, "unknown tag " + line.tag + " (expected VERTEX_SE3:QUAT, ...)");
    if (group_planar && *group_planar != se2) return refuse(path, number, "a line of the other group");
    group_planar = se2;
    const bool vertex = line.tag.rfind("VERTEX", 0) == 0;
    const int k = se3 ? 7 : 3, d = se3 ? 6 : 3;
    const std::size_t want_ids = vertex ? 1 : 2, want_values = vertex ? k : k + d * (d + 1) / 2;
    std::string word;
    while (words >> word) {
      const char* begin = word.c_str();
      char* end = nullptr;
      if (line.ids.size() < want_ids) {
        errno = 0;
        const long long id = std::strtoll(begin, &end, 10);
        if (*end != '\0' || end == begin) return refuse(path, number, "not an integer id: " + word);
        if (errno == ERANGE) return refuse(path, number, "a vertex id beyond 64 bits: " + word);
        line.ids.push_back(id);
      } else {
        const double x = std::strtod(begin, &end);
        if (*end != '\0' || end == begin) return refuse(path, number, "not a number: " + word);
        if (!std::isfinite(x)) return refuse(path, number, "expected finite numbers, got " + word);
        line.values.push_back(x);
      }
    }
    if (line.ids.size() != want_ids || line.values.size() != want_values)
      return refuse(path, number,
                    line.tag + " expects " + std::to_string(want_ids + want_values) + " values, got " +
                        std::to_string(line.ids.size() + line.values.size()));
    out.push_back(std::move(line));
  }
  if (!group_planar) {
    std::fprintf(stderr, "%s: no vertex or edge\n", path.c_str());
    return false;
  }
  planar = *group_planar;
  return true;
}

/// The graph of the lines (vertices in the file's order).
template <typename G>
bool build(const std::string& path, const std::vector<Line>& lines, Graph<G>& graph) {
  constexpr int d = G::DoF;
  std::map<long long, int> index;
  for (const Line& line : lines) {
    const std::optional<G> pose = G2o<G>::pose(line.values.data());
    if (!pose) return refuse(path, line.number, "a quaternion of zero norm");
    if (line.tag == G2o<G>::vertex) {
      if (!index.emplace(line.ids[0], static_cast<int>(graph.ids.size())).second)
        return refuse(path, line.number, "vertex " + std::to_string(line.ids[0]) + " is defined twice");
      graph.ids.push_back(line.ids[0]);
      graph.blocks.emplace_back(Parameters<G>::size);
      Parameters<G>::write(*pose, graph.blocks.back().data());
    }
  }
  for (const Line& line : lines) {
    if (line.tag != G2o<G>::edge) continue;
    typename Graph<G>::Edge edge{0, 0, *G2o<G>::pose(line.values.data()), G::AdjointMatrix::Zero()};
    for (int end = 0; end < 2; ++end) {
      const auto found = index.find(line.ids[end]);
      if (found == index.end())
        return refuse(path, line.number, "an edge to vertex " + std::to_string(line.ids[end]) + ", not defined");
      (end == 0 ? edge.i : edge.j) = found->second;
    }
    const double* upper = line.values.data() + G2o<G>::numbers;  // the upper triangle, row by row
    for (int r = 0; r < d; ++r)
      for (int c = r; c < d; ++c) edge.information(r, c) = edge.information(c, r) = *upper++;
    if (Eigen::LLT<typename G::AdjointMatrix>(edge.information).info() != Eigen::Success)
      return refuse(path, line.number, "an information matrix that is not positive definite");
    graph.edges.push_back(edge);
  }
  return true;
}

/// sum over edges of e^T Omega e at the blocks' poses.
template <typename G>
double chi2(const Graph<G>& graph) {
  double sum = 0.0;
  for (const auto& edge : graph.edges) {
    const G a = Parameters<G>::read(graph.blocks[edge.i].data());
    const G b = Parameters<G>::read(graph.blocks[edge.j].data());
    const typename G::Tangent e = chasles::rminus(chasles::between(a, b), edge.measurement);
    sum += e.dot(edge.information * e);
  }
  return sum;
}

template <typename G>
bool write_g2o(const std::string& path, const Graph<G>& graph) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (file == nullptr) return false;
  for (std::size_t v = 0; v < graph.ids.size(); ++v) {
    std::fprintf(file, "%s %lld", G2o<G>::vertex, graph.ids[v]);
    for (double x : G2o<G>::numbers_of(Parameters<G>::read(graph.blocks[v].data()))) std::fprintf(file, " %.17g", x);
    std::fputc('\n', file);
  }
  for (const auto& edge : graph.edges) {
    std::fprintf(file, "%s %lld %lld", G2o<G>::edge, graph.ids[edge.i], graph.ids[edge.j]);
    for (double x : G2o<G>::numbers_of(edge.measurement)) std::fprintf(file, " %.17g", x);
    for (int r = 0; r < G::DoF; ++r)
      for (int c = r; c < G::DoF; ++c) std::fprintf(file, " %.17g", edge.information(r, c));
    std::fputc('\n', file);
  }
  return std::fclose(file) == 0;
}

template <typename G>
int solve(const std::string& path, const std::vector<Line>& lines, const char* out) {
  Graph<G> graph;
  if (!build(path, lines, graph)) return 1;
  std::printf("%s: %zu poses, %zu edges (%s)\n", path.c_str(), graph.ids.size(), graph.edges.size(),
              G::DoF == 6 ? "SE3" : "SE2");
  ceres::Problem::Options problem_options;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;  // one manifold for every pose
  ceres::Problem problem(problem_options);
  chasles::CeresManifold<G> manifold;
  for (Eigen::VectorXd& block : graph.blocks) problem.AddParameterBlock(block.data(), Parameters<G>::size, &manifold);
  for (const auto& edge : graph.edges) {
    // Omega = U^T U (U upper triangular): |U e|^2 = e^T Omega e.
    const typename G::AdjointMatrix U = Eigen::LLT<typename G::AdjointMatrix>(edge.information).matrixU();
    problem.AddResidualBlock(new chasles::BetweenCost<G>(edge.measurement, U), nullptr, graph.blocks[edge.i].data(),
                             graph.blocks[edge.j].data());
  }
  if (!graph.blocks.empty()) problem.SetParameterBlockConstant(graph.blocks[0].data());

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  options.max_num_iterations = 100;
  // LM's damping starts at 1e-6 of the diagonal: Ceres's default (1e-4),
  // which it lowers at most threefold per good step, takes 12 iterations on
  // the sphere of tests/python/test_pose_graph.py where this takes 8, as
  // GTSAM and chasles' Python solve do.
  options.initial_trust_region_radius = 1e6;
  options.function_tolerance = 1e-12;  // a step that lowers chi2 by less, relative, ends the solve
  options.gradient_tolerance = 1e-12;
  options.parameter_tolerance = 1e-12;
  ceres::Solver::Summary summary;
  const double initial = chi2(graph);
  const auto start = std::chrono::steady_clock::now();
  ceres::Solve(options, &problem, &summary);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const double final_chi2 = chi2(graph);
  std::printf("initial chi2: %.15g\n", initial);
  std::printf("final chi2: %.15g\n", final_chi2);
  std::printf("iterations: %d\n", summary.num_successful_steps + summary.num_unsuccessful_steps);
  std::printf("solve time: %.4f s (%s)\n", seconds, ceres::TerminationTypeToString(summary.termination_type));

  bool ok = summary.termination_type == ceres::CONVERGENCE && final_chi2 <= initial;
  if (!ok) std::printf("not converged: %s\n", summary.BriefReport().c_str());
  if (out != nullptr) {
    if (!write_g2o(out, graph)) {
      std::fprintf(stderr, "%s: cannot write\n", out);
      return 1;
    }
    std::printf("wrote %s\n", out);
    // Read back: the same chi2 (17 significant digits round-trip the numbers).
    std::vector<Line> again;
    bool planar = false;
    Graph<G> back;
    ok = ok && read_lines(out, again, planar) && build(out, again, back) &&
         std::abs(chi2(back) - final_chi2) <= 1e-9 * (1.0 + final_chi2);
  }
  if (ok) std::printf("all checks passed\n");
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
#ifdef _OPENMP
  // CHOLMOD's OpenMP regions ask for a fixed number of threads (OMP_NUM_THREADS
  // does not lower it): on 2 cores their waits doubled the sphere2500 solve
  // (1.0 s against 0.52 s). Dynamic adjustment lets the runtime use fewer.
  omp_set_dynamic(1);
#endif
  const char* path = nullptr;
  const char* out = nullptr;
  for (int k = 1; k < argc; ++k) {
    if (std::strcmp(argv[k], "--out") == 0 && k + 1 < argc) {
      out = argv[++k];
    } else if (path == nullptr && argv[k][0] != '-') {
      path = argv[k];
    } else {
      path = nullptr;
      break;
    }
  }
  if (path == nullptr) {
    std::fprintf(stderr, "usage: %s PATH.g2o [--out OUT.g2o]\n", argv[0]);
    return 2;
  }
  std::vector<Line> lines;
  bool planar = false;
  if (!read_lines(path, lines, planar)) return 1;
  return planar ? solve<chasles::SE2d>(path, lines, out) : solve<chasles::SE3d>(path, lines, out);
}
