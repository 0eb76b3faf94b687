// A force-torque sensor s reads a wrench F_s = (f, tau), force first. The
// tool tip t sits at g_st. The same wrench at the tip is F_t = Ad_{g_st}^T F_s
// (g_st.act_inv(F_s)): wrenches change frame by the transpose of the adjoint,
// which keeps the power V . F the same in every frame.
#include <chasles/chasles.hpp>

#include <cmath>
#include <cstdio>

int main() {
  using namespace chasles;
  using Eigen::Vector3d;
  const double pi = 3.14159265358979323846;

  // The tip is 0.2 m along the sensor's z axis, turned 30 degrees about it.
  const SE3d g_st(SO3d::exp(Vector3d(0, 0, pi / 6)), Vector3d(0, 0, 0.2));
  // A 5 N push along the tool's x axis at the tip, no torque there; what the sensor reads:
  const Wrenchd F_tip(Vector3d(5, 0, 0), Vector3d::Zero());
  const Wrenchd F_s = g_st.act(F_tip);  // Ad_{g_st}^-T F_tip: tau = p x f
  const Wrenchd F_t = g_st.act_inv(F_s);
  std::printf("sensor: f = (%.6f, %.6f, %.6f), tau = (%.6f, %.6f, %.6f)\n", F_s.force().x(), F_s.force().y(),
              F_s.force().z(), F_s.torque().x(), F_s.torque().y(), F_s.torque().z());
  std::printf("tip:    f = (%.6f, %.6f, %.6f), tau = (%.6f, %.6f, %.6f)\n", F_t.force().x(), F_t.force().y(),
              F_t.force().z(), F_t.torque().x(), F_t.torque().y(), F_t.torque().z());
  bool ok = F_t.is_approx(F_tip, 1e-12);
  ok = ok && (F_s.torque() - Vector3d(0, 0, 0.2).cross(F_s.force())).norm() < 1e-14;

  // Power: a tool velocity written in either frame does the same work.
  const Twistd V_t(Vector3d(0.1, -0.2, 0.3), Vector3d(0.4, 0.5, -0.6));
  const Twistd V_s = g_st.act(V_t);  // Ad_{g_st} V_t
  const double P_s = power(V_s, F_s), P_t = power(V_t, F_t);
  std::printf("power in the sensor frame %.12f W, in the tool frame %.12f W\n", P_s, P_t);
  ok = ok && std::abs(P_s - P_t) < 1e-12;
  std::printf("%s\n", ok ? "all checks passed" : "FAILED");
  return ok ? 0 : 1;
}
