// The C++ robot-arm quick start: load an arm from its URDF (chasles::urdf,
// over urdfdom), then forward kinematics, inverse kinematics for a target and
// the gravity torques, with the chain, its link inertias and its gravity
// (README.md, "C++: loading a URDF").
//
//   example_robot_arm path/to/arm.urdf tip_link
//
// (ctest runs it on examples/data/three_joint_arm.urdf, tip "tool".) After
// the quick start, checks: the inverse kinematics reaches the target, and
// the gravity torques are the gradient of the potential energy (a central
// difference).
#include <chasles/dynamics.hpp>
#include <chasles/inverse_kinematics.hpp>
#include <chasles/urdf.hpp>

#include <cmath>
#include <cstdio>

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s robot.urdf tip_link\n", argv[0]);
    return 2;
  }
  // ---- the quick start
  using Robot = chasles::UrdfChain<double, 7>;  // up to 7 joints
  using Arm = Robot::ChainType;                  // chasles::Chain<double, Eigen::Dynamic, 7>
  const Robot robot = chasles::chain_from_urdf<double, 7>(argv[1], argv[2]);
  if (!robot) return std::fprintf(stderr, "%s\n", robot.error.c_str()), 1;
  const Arm& arm = *robot.chain;
  const chasles::SE3d target = arm.forward(Arm::JointVector::Constant(arm.n_joints(), 0.4));  // forward kinematics
  const auto ik = chasles::inverse_kinematics(arm, target, Arm::JointVector::Zero(arm.n_joints()),  // from q = 0
                                              arm.lower(), arm.upper());
  const Arm::JointVector tau = chasles::gravity_torques(arm, ik.q);  // N m (N if prismatic)
  // ---- printing and checks
  const Eigen::Vector3d p = target.translation();
  std::printf("%d joints:", static_cast<int>(arm.n_joints()));
  for (const std::string& name : robot.joint_names) std::printf(" %s", name.c_str());
  std::printf("\ntool at q = 0.4: (%.6f, %.6f, %.6f) m\n", p.x(), p.y(), p.z());
  std::printf("inverse kinematics from zero: %s in %d iterations, q =", ik.converged ? "converged" : "NOT converged",
              ik.iterations);
  for (Eigen::Index i = 0; i < ik.q.size(); ++i) std::printf(" %.6f", ik.q(i));
  std::printf("\ngravity torques there:");
  for (Eigen::Index i = 0; i < tau.size(); ++i) std::printf(" %.6f", tau(i));
  std::printf(" N m\n");

  bool ok = ik.converged && arm.forward(ik.q).is_approx(target, 1e-9);
  const double h = 1e-6;
  for (Eigen::Index i = 0; i < arm.n_joints(); ++i) {
    Arm::JointVector plus = ik.q, minus = ik.q;
    plus(i) += h;
    minus(i) -= h;
    const double dV = (chasles::potential_energy(arm, plus) - chasles::potential_energy(arm, minus)) / (2 * h);
    ok = ok && std::abs(tau(i) - dV) < 1e-6 * (1 + std::abs(tau(i)));
  }
  std::printf("%s\n", ok ? "all checks passed" : "FAILED");
  return ok ? 0 : 1;
}
