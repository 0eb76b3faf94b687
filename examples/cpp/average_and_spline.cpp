// Averaging noisy poses, then a smooth trajectory through the averages.
// Five true key poses g(t_k) = exp([V0] t_k) exp([V1] t_k^2), t_k = 0..4 s,
// are each measured 50 times: g = g_true exp([L z]), z standard normal, so the
// twist log(g_true^-1 g) has the covariance L L^T (random.hpp). The geodesic
// mean M of each batch solves sum_i log(M^-1 g_i) = 0 (mean.hpp); its error
// shrinks as 1/sqrt(50) against one measurement's. Through the five means:
// the interpolating C2 spline (spline.hpp, fitted into caller storage) and the
// cumulative cubic B-spline with the means as its control poses, X_k at time
// t_k (start time t_1, spacing 1 s: defined on [t_1, t_3]; it smooths, at t_k
// it is near (X_{k-1} + 4 X_k + X_{k+1}) / 6, not at X_k). Both give analytic
// body velocities and accelerations, checked here against central differences.
#include <chasles/chasles.hpp>

#include <array>
#include <cmath>
#include <cstdio>
#include <random>

using namespace chasles;
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

namespace {

constexpr int kKeys = 5;
constexpr int kMeasurements = 50;
constexpr double kSigmaP = 0.02, kSigmaR = 0.05;  // m and rad per axis

const Vector6d V0 = (Vector6d() << 0.4, 0.0, 0.05, 0.0, 0.0, 0.3).finished();  // (v, w)
const Vector6d V1 = (Vector6d() << 0.0, 0.02, 0.0, 0.02, 0.0, 0.0).finished();

SE3d truth(double t) { return SE3d::exp(Vector6d(t * V0)) * SE3d::exp(Vector6d(t * t * V1)); }

void print_row(double t, const SE3d& g, const Vector6d& v, const Vector6d& a) {
  const Eigen::Vector3d p = g.translation();
  std::printf("%4.2f | %6.3f %6.3f %6.3f | %6.3f %6.3f %6.3f %6.3f %6.3f %6.3f |", t, p.x(), p.y(), p.z(), v[0], v[1],
              v[2], v[3], v[4], v[5]);
  std::printf(" %5.2f %5.2f %5.2f %5.2f %5.2f %5.2f\n", a[0], a[1], a[2], a[3], a[4], a[5]);
}

// log(g(t - h)^-1 g(t + h)) / (2 h): the body velocity to O(h^2).
template <typename Curve>
Vector6d central_difference(const Curve& element, double t) {
  const double h = 1e-4;
  return (element(t - h).inverse() * element(t + h)).log() / (2.0 * h);
}

}  // namespace

int main() {
  bool ok = true;
  std::mt19937_64 gen(2024);  // a fixed seed: the same numbers every run
  Matrix6d L = Matrix6d::Zero();  // the Cholesky factor of the (diagonal) covariance
  L.diagonal() << kSigmaP, kSigmaP, kSigmaP, kSigmaR, kSigmaR, kSigmaR;

  std::array<double, kKeys> times{};
  std::array<SE3d, kKeys> means;
  std::array<SE3d, kMeasurements> measured;  // reused for each key: nothing allocated
  std::printf("%d noisy measurements per key pose (sigma %g m, %g rad per axis); errors against the truth:\n",
              kMeasurements, kSigmaP, kSigmaR);
  std::printf("   t | mean: angle (rad) position (m) | one measurement: angle position | Newton steps\n");
  double sum_mean = 0.0, sum_one = 0.0;
  for (int k = 0; k < kKeys; ++k) {
    times[k] = k;
    const SE3d g = truth(times[k]);
    for (SE3d& x : measured) x = random_gaussian(gen, g, L);
    const MeanResult<SE3d> m = geodesic_mean(measured.begin(), measured.end());
    means[k] = m.mean;
    const SE3Distance<double> e_mean = distance(g, m.mean), e_one = distance(g, measured[0]);
    std::printf("%4.1f |        %.4f        %.4f |                 %.4f   %.4f | %d\n", times[k], e_mean.angle,
                e_mean.translation, e_one.angle, e_one.translation, m.iterations);
    // The mean's tangent error has the covariance L L^T / 50: a 4-sigma bound per axis.
    const double bound = 4.0 * std::sqrt(3.0 / kMeasurements);
    ok = ok && m.converged && e_mean.angle < bound * kSigmaR && e_mean.translation < bound * kSigmaP;
    sum_mean += e_mean.angle;
    sum_one += e_one.angle;
  }
  std::printf("average angle error: mean %.4f rad, one measurement %.4f rad\n", sum_mean / kKeys, sum_one / kKeys);
  ok = ok && sum_mean < sum_one;

  // The interpolating spline: the caller owns the segments and the fit's scratch.
  std::array<SplineSegment<SE3d>, kKeys - 1> segments;
  std::array<SplineWork<SE3d>, kKeys> work;
  const SplineFit fit = fit_spline<SE3d>(kKeys, times.data(), means.data(), segments.data(), work.data());
  ok = ok && fit.status == SplineStatus::ok;
  const Spline<SE3d> spline(kKeys, times.data(), means.data(), segments.data());
  double through = 0.0;
  for (int k = 0; k < kKeys; ++k) {
    const SE3Distance<double> d = distance(spline.element(times[k]), means[k]);
    through = std::fmax(through, std::fmax(d.angle, d.translation));
  }
  std::printf("the spline passes through the means: worst %.1e (rad or m), fitted in %d iterations\n", through,
              fit.iterations);
  ok = ok && through < 1e-12;

  const auto spline_element = [&](double t) { return spline.element(t); };
  std::printf("interpolating spline through the means:\n");
  std::printf("   t |    position (m)      | body velocity v (m/s), w (rad/s)          | body acceleration (/s^2)\n");
  double worst_fd = 0.0;
  for (double t : {0.5, 1.0, 2.0, 2.5, 3.5}) {
    const SplineSample<SE3d> s = spline(t);
    print_row(t, s.element, s.velocity, s.acceleration);
    worst_fd = std::fmax(worst_fd, (s.velocity - central_difference(spline_element, t)).cwiseAbs().maxCoeff());
  }

  // The B-spline: a view over the means as control poses (segments [t_1, t_2]
  // over X_0..X_3 and [t_2, t_3] over X_1..X_4).
  const CubicBSplineView<SE3d> bspline(means.data(), kKeys, times[1], 1.0);
  const auto bspline_element = [&](double t) { return bspline(t); };
  std::printf("cumulative B-spline, the means as control poses:\n");
  std::printf("   t |    position (m)      | body velocity v (m/s), w (rad/s)          | body acceleration (/s^2)\n");
  for (double t : {1.25, 1.5, 2.0, 2.5, 2.75}) {  // central differences stay inside [t_1, t_3]
    const BSplinePoint<SE3d> s = bspline.evaluate(t);
    print_row(t, s.value, s.velocity, s.acceleration);
    worst_fd = std::fmax(worst_fd, (s.velocity - central_difference(bspline_element, t)).cwiseAbs().maxCoeff());
  }
  const double off = distance(bspline(2.0), means[2]).translation;
  std::printf("the B-spline smooths: at t_2 it is %.3f m from the mean, not on it\n", off);
  std::printf("body velocities against central differences: worst %.1e\n", worst_fd);
  ok = ok && worst_fd < 1e-6;
  std::printf("%s\n", ok ? "all checks passed" : "FAILED");
  return ok ? 0 : 1;
}
