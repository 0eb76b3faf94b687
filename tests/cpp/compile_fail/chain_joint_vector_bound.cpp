// A fixed-size joint vector larger than a dynamic chain's bound MaxJoints
// (a dynamic chain checks the exact size at run time, this at compile time).
// expect: MaxJoints
// expect: 9 <= 8
#include <chasles/kinematics.hpp>

int main() {
  using Arm = chasles::Chain<double, Eigen::Dynamic, 8>;
  Arm::Screws S(6, 2);
  S.col(0) = Arm::revolute_screw(Eigen::Vector3d::Zero(), Eigen::Vector3d::UnitZ());
  S.col(1) = Arm::prismatic_screw(Eigen::Vector3d::UnitX());
  const Arm arm(S, chasles::SE3d());
  double sum = arm.forward(Eigen::Vector2d(0.1, 0.2)).translation().sum();
#if CHASLES_COMPILE_FAIL == 1
  sum += arm.forward(Eigen::Matrix<double, 9, 1>::Zero()).translation().sum();
#endif
  return sum == sum ? 0 : 1;
}
