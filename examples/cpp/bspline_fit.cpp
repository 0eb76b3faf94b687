// A trajectory estimated in continuous time: a cubic B-spline on SE(3)
// fitted to noisy timestamped poses with Ceres.
//
//   example_bspline_fit
//
// The true motion is a screw-like path (a helix whose attitude turns about
// two axes), sampled at 200 times over 10 s; each sample is perturbed on
// the right by noise of standard deviations 0.02 rad and 0.05 m. The fit
// minimizes sum_k |L log(Z_k^-1 X(t_k))|^2 (L = the square root of the
// noise's information) over the control elements of a spline with knots
// 0.5 s apart: one chasles::CubicBSplineCost per sample (analytic
// Jacobians), the control elements on chasles::CeresManifold. It prints the
// initial and final chi2, chi2 per degree of freedom, the iterations, and
// the error of the fitted curve against the true motion, and "all checks
// passed" when Ceres converged, chi2 per degree of freedom is within its
// statistical range of 1, and the fitted curve is closer to the truth than
// the samples are.
#include <cmath>
#include <cstdio>
#include <random>
#include <vector>

#include <ceres/problem.h>
#include <ceres/solver.h>
#include <Eigen/Core>

#include <chasles/ceres.hpp>

namespace {

using chasles::SE3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;

/// The true motion at time t.
SE3d truth(double t) {
  const Eigen::Vector3d p(2.0 * std::cos(0.6 * t), 2.0 * std::sin(0.6 * t), 0.3 * t);
  const chasles::SO3d R = chasles::SO3d::exp(Eigen::Vector3d(0.0, 0.0, 0.6 * t)) *
                          chasles::SO3d::exp(Eigen::Vector3d(0.4 * std::sin(0.9 * t), 0.0, 0.0));
  return SE3d(R, p);
}

/// The mean over times of |rminus(fit, truth)|'s rotation and translation parts.
void errors(const chasles::CubicBSplineView<SE3d>& spline, const std::vector<double>& times, double& rotation,
            double& translation) {
  rotation = translation = 0.0;
  for (double t : times) {
    const Vector6 e = chasles::rminus(spline(t), truth(t));
    rotation += e.tail<3>().norm() / static_cast<double>(times.size());
    translation += e.head<3>().norm() / static_cast<double>(times.size());
  }
}

}  // namespace

int main() {
  const double sigma_w = 0.02, sigma_v = 0.05, t0 = 0.0, dt = 0.5, t_end = 10.0;
  const int samples = 200;
  std::mt19937_64 gen(2026);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> times;
  std::vector<SE3d> measured;
  for (int k = 0; k < samples; ++k) {
    const double t = t0 + (t_end - t0) * k / (samples - 1);
    Vector6 noise;
    for (int i = 0; i < 6; ++i) noise[i] = (i < 3 ? sigma_v : sigma_w) * normal(gen);
    times.push_back(t);
    measured.push_back(truth(t) * SE3d::exp(noise));
  }
  // Control element j sits near t0 + (j - 1) dt; they start at the samples nearest those times.
  const int count = static_cast<int>(std::ceil((t_end - t0) / dt)) + 3;
  std::vector<Eigen::Matrix<double, 7, 1>> blocks(static_cast<std::size_t>(count));
  for (int j = 0; j < count; ++j) {
    const double knot = std::min(std::max(t0 + (j - 1) * dt, t0), t_end);
    const int k = static_cast<int>(std::lround((knot - t0) / (t_end - t0) * (samples - 1)));
    chasles::Parameters<SE3d>::write(measured[static_cast<std::size_t>(k)], blocks[static_cast<std::size_t>(j)].data());
  }
  std::vector<SE3d> control(static_cast<std::size_t>(count));
  const auto read_control = [&] {
    for (std::size_t j = 0; j < control.size(); ++j) control[j] = chasles::Parameters<SE3d>::read(blocks[j].data());
    return chasles::CubicBSplineView<SE3d>(control.data(), count, t0, dt);
  };

  ceres::Problem::Options problem_options;
  problem_options.manifold_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
  ceres::Problem problem(problem_options);
  chasles::CeresManifold<SE3d> manifold;
  for (auto& block : blocks) problem.AddParameterBlock(block.data(), 7, &manifold);
  Vector6 weights;
  weights << 1 / sigma_v, 1 / sigma_v, 1 / sigma_v, 1 / sigma_w, 1 / sigma_w, 1 / sigma_w;
  const SE3d::AdjointMatrix L = weights.asDiagonal();
  const chasles::CubicBSplineView<SE3d> layout = read_control();
  for (int k = 0; k < samples; ++k) {
    const chasles::BSplineTime<double> at = layout.locate(times[static_cast<std::size_t>(k)]);
    const auto i = static_cast<std::size_t>(at.segment);
    problem.AddResidualBlock(new chasles::CubicBSplineCost<SE3d>(at.u, measured[static_cast<std::size_t>(k)], L),
                             nullptr, blocks[i].data(), blocks[i + 1].data(), blocks[i + 2].data(),
                             blocks[i + 3].data());
  }
  double rotation0 = 0, translation0 = 0;
  errors(read_control(), times, rotation0, translation0);

  ceres::Solver::Options options;
  options.linear_solver_type = ceres::DENSE_QR;  // 23 control elements: 138 unknowns
  options.function_tolerance = 1e-12;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);

  double rotation = 0, translation = 0;
  errors(read_control(), times, rotation, translation);
  const int dof = 6 * samples - 6 * count;
  const double chi2 = 2 * summary.final_cost, per_dof = chi2 / dof;
  std::printf("%d poses over [%g, %g] s, a spline of %d control elements %g s apart\n", samples, t0, t_end, count, dt);
  std::printf("initial chi2: %.6g\n", 2 * summary.initial_cost);
  std::printf("final chi2: %.6g (%.4f per degree of freedom, %d)\n", chi2, per_dof, dof);
  std::printf("iterations: %d (%s)\n", summary.num_successful_steps + summary.num_unsuccessful_steps,
              ceres::TerminationTypeToString(summary.termination_type));
  std::printf(
      "mean error against the truth: %.4f rad, %.4f m (start %.4f rad, %.4f m; the samples' noise %g rad, %g m)\n",
      rotation, translation, rotation0, translation0, sigma_w, sigma_v);
  // chi2 / dof has standard deviation sqrt(2 / dof) (0.04 here); the spline's
  // own bias (the helix is not a spline) adds a little.
  const bool ok = summary.termination_type == ceres::CONVERGENCE && std::abs(per_dof - 1) < 5 * std::sqrt(2.0 / dof) &&
                  rotation < sigma_w && translation < sigma_v;
  if (ok) std::printf("all checks passed\n");
  return ok ? 0 : 1;
}
