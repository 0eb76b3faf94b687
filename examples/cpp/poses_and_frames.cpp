// Pose composition and frame changes: a camera c on a robot base b in the
// world w. g_ab maps coordinates in b to coordinates in a (q_a = g_ab * q_b)
// and poses compose along the frames: g_wc = g_wb * g_bc.
#include <chasles/chasles.hpp>

#include <cmath>
#include <cstdio>

int main() {
  using namespace chasles;
  using Eigen::Vector3d;
  const double pi = 3.14159265358979323846;

  // The base: 2 m along x and 1 m along y of the world, turned 90 degrees about z.
  const SE3d g_wb(SO3d::exp(Vector3d(0, 0, pi / 2)), Vector3d(2, 1, 0));
  // The camera: 0.5 m up the base's z axis, its optical axis z along the base's x.
  Eigen::Matrix3d R_bc;
  R_bc << 0, 0, 1, -1, 0, 0, 0, -1, 0;
  const std::optional<SO3d> checked = SO3d::from_matrix(R_bc);  // std::nullopt if not a rotation
  if (!checked) return 1;
  const SE3d g_bc(*checked, Vector3d(0, 0, 0.5));

  const SE3d g_wc = g_wb * g_bc;  // the camera in the world
  const Vector3d q_c(0, 0, 3);    // a point 3 m in front of the camera
  const Vector3d q_w = g_wc * q_c;
  std::printf("the point in the world: %.6f %.6f %.6f\n", q_w.x(), q_w.y(), q_w.z());

  bool ok = (q_w - Vector3d(2, 4, 0.5)).norm() < 1e-14;     // the base's x is the world's y
  ok = ok && (q_w - g_wb * (g_bc * q_c)).norm() < 1e-14;    // either way round
  ok = ok && (g_wc.inverse() * q_w - q_c).norm() < 1e-14;   // and back
  ok = ok && (g_wc.matrix() - g_wb.matrix() * g_bc.matrix()).norm() < 1e-14;

  // A second camera d relative to the first, and that displacement as one screw motion.
  const SE3d g_wd = g_wc * SE3d(SO3d::exp(Vector3d(0, pi / 2, 0)), Vector3d(1, 0, 3));
  const SE3d g_cd = g_wc.inverse() * g_wd;
  const Twistd xi(g_cd.log());
  const Screw<double> s = xi.screw();
  std::printf("g_cd as a screw: axis through (%.6f, %.6f, %.6f) along (%.6f, %.6f, %.6f), pitch %.6f, angle %.6f\n",
              s.point.x(), s.point.y(), s.point.z(), s.direction.x(), s.direction.y(), s.direction.z(), s.pitch,
              s.magnitude);
  ok = ok && (g_wc * g_cd).is_approx(g_wd, 1e-12) && SE3d::exp(xi).is_approx(g_cd, 1e-12);
  ok = ok && std::abs(s.magnitude - pi / 2) < 1e-14;
  std::printf("%s\n", ok ? "all checks passed" : "FAILED");
  return ok ? 0 : 1;
}
