// Velocities from sampled poses: between samples g_k and g_k+1, dt apart,
// g_k^-1 g_k+1 = exp([xi_k]), so xi_k / dt is the body twist that carries
// g_k to g_k+1 in dt, a finite difference that stays on SE(3). Checked
// against the exact body twist of g(t) = exp([V0] t) exp([V1] t^2).
#include <chasles/chasles.hpp>

#include <cmath>
#include <cstdio>

using namespace chasles;
using Vector6d = Eigen::Matrix<double, 6, 1>;

namespace {

const Vector6d V0 = (Vector6d() << 0.5, 0.0, 0.1, 0.0, 0.0, 0.8).finished();  // (v, w)
const Vector6d V1 = (Vector6d() << 0.0, 0.2, 0.0, 0.3, 0.0, 0.0).finished();

SE3d pose(double t) { return SE3d::exp(Vector6d(t * V0)) * SE3d::exp(Vector6d(t * t * V1)); }

/// (g^-1 g')^vee by the product rule: Ad_{exp([V1] t^2)}^-1 V0 + 2 t V1.
Vector6d exact_body_twist(double t) {
  return SE3d::exp(Vector6d(t * t * V1)).act_inv(Twistd(V0)).vector() + 2.0 * t * V1;
}

}  // namespace

int main() {
  const double dt = 0.01;
  double worst = 0.0, worst_spatial = 0.0;
  SE3d previous = pose(0.0);
  for (int k = 0; k < 200; ++k) {
    const SE3d next = pose((k + 1) * dt);
    const Vector6d body = (previous.inverse() * next).log() / dt;
    const Vector6d spatial = (next * previous.inverse()).log() / dt;  // (g' g^-1)^vee
    worst = std::fmax(worst, (body - exact_body_twist((k + 0.5) * dt)).cwiseAbs().maxCoeff());
    // V^s = Ad_g V^b: g exp([xi]) g^-1 = exp([Ad_g xi]).
    worst_spatial = std::fmax(worst_spatial, (spatial - previous.adjoint() * body).cwiseAbs().maxCoeff());
    previous = next;
  }
  std::printf("body twists over 200 steps of dt = %g: worst error %.2e (O(dt^2) = %.0e)\n", dt, worst, dt * dt);
  std::printf("spatial twists against Ad_g times body twists: worst difference %.2e\n", worst_spatial);
  const bool ok = worst < dt * dt && worst_spatial < 1e-12;
  std::printf("%s\n", ok ? "all checks passed" : "FAILED");
  return ok ? 0 : 1;
}
