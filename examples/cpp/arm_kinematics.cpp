// Forward kinematics of a SCARA arm by the product of exponentials, with
// chasles::Chain: fixed size (4 joints), no allocation, checked against the
// arm's closed form and the space Jacobian against a finite difference.
#include <chasles/kinematics.hpp>

#include <cmath>
#include <cstdio>

int main() {
  using namespace chasles;
  using Eigen::Vector3d;
  using Arm = Chain<double, 4>;
  const double l1 = 0.4, l2 = 0.3, h = 0.5;  // link lengths, tool height at home (m)

  Arm::Screws S;  // one column (v, w) per joint, at home, in the base frame
  S.col(0) = Arm::revolute_screw(Vector3d::Zero(), Vector3d::UnitZ());
  S.col(1) = Arm::revolute_screw(Vector3d(l1, 0, 0), Vector3d::UnitZ());
  S.col(2) = Arm::prismatic_screw(-Vector3d::UnitZ());  // the quill goes down
  S.col(3) = Arm::revolute_screw(Vector3d(l1 + l2, 0, 0), Vector3d::UnitZ());
  const Arm arm(S, SE3d(SO3d(), Vector3d(l1 + l2, 0, h)));

  const Arm::JointVector theta(0.3, -0.8, 0.1, 1.2);
  const SE3d g = arm.forward(theta);
  const Vector3d p = g.translation();
  std::printf("tool at (%.6f, %.6f, %.6f)\n", p.x(), p.y(), p.z());

  // Closed form: planar 2R position, the quill's depth, rotation about z by t1 + t2 + t4.
  const double t1 = theta[0], t2 = theta[1], d3 = theta[2], t4 = theta[3];
  const Vector3d expected(l1 * std::cos(t1) + l2 * std::cos(t1 + t2), l1 * std::sin(t1) + l2 * std::sin(t1 + t2),
                          h - d3);
  bool ok = (p - expected).norm() < 1e-14;
  ok = ok && g.rotation().is_approx(SO3d::exp(Vector3d(0, 0, t1 + t2 + t4)), 1e-14);
  ok = ok && arm.forward_body(theta).is_approx(g, 1e-14);

  // J_s theta' is the spatial twist (g' g^-1)^vee: compare with a central difference.
  const Arm::JointVector theta_dot(0.2, -0.1, 0.05, 0.3);
  const double e = 1e-6;
  const SE3d g_plus = arm.forward(Arm::JointVector(theta + e * theta_dot));
  const SE3d g_minus = arm.forward(Arm::JointVector(theta - e * theta_dot));
  const Eigen::Matrix<double, 6, 1> numeric = (g_plus * g_minus.inverse()).log() / (2 * e);
  const Eigen::Matrix<double, 6, 1> twist = arm.jacobian_space(theta) * theta_dot;
  std::printf("spatial twist J_s theta' = (%.6f, %.6f, %.6f, %.6f, %.6f, %.6f), difference %.1e\n", twist[0], twist[1],
              twist[2], twist[3], twist[4], twist[5], (twist - numeric).cwiseAbs().maxCoeff());
  ok = ok && (twist - numeric).cwiseAbs().maxCoeff() < 1e-8;
  std::printf("%s\n", ok ? "all checks passed" : "FAILED");
  return ok ? 0 : 1;
}
