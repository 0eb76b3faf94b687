// A fixed-size joint vector of the wrong size, for each method of a fixed
// 6-joint chain (sizes 3, 4, 5 and 7: each its own error, with the numbers).
// expect: number of joints
// expect: 3 == 6
// expect: 4 == 6
// expect: 5 == 6
// expect: 7 == 6
#include <chasles/kinematics.hpp>

int main() {
  using Arm = chasles::Chain<double, 6>;
  Arm::Screws S;
  for (int i = 0; i < 6; ++i)
    S.col(i) = Arm::revolute_screw(Eigen::Vector3d(double(i), 0, 0), Eigen::Vector3d::UnitZ());
  const Arm arm(S, chasles::SE3d());
  const Arm::JointVector q = Arm::JointVector::Zero();
  double sum = arm.forward(q).translation().sum() + arm.forward_body(0.5 * q).translation().sum() +
               arm.jacobian_space(q).sum() + arm.jacobian_body(q).sum();
#if CHASLES_COMPILE_FAIL == 1
  sum += arm.forward(Eigen::Vector3d::Zero()).translation().sum();
  sum += arm.forward_body(Eigen::Vector4d::Zero()).translation().sum();
  sum += arm.jacobian_space(Eigen::Matrix<double, 5, 1>::Zero()).sum();
  sum += arm.jacobian_body(Eigen::Matrix<double, 7, 1>::Zero()).sum();
#endif
  return sum == sum ? 0 : 1;
}
