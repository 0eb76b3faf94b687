// Built against an installed chasles by tests/cpp/consumer_test.cmake:
// the seed's worked example, through find_package(chasles).
#include <chasles/chasles.hpp>

#include <cmath>
#include <cstdio>

int main() {
  using namespace chasles;
  const double l1 = 2.0, theta = 0.7;
  // Rotation about the z axis through (0, l1, 0), pitch 0.
  const SE3d g = SE3d::from_screw(Eigen::Vector3d(0, l1, 0), Eigen::Vector3d::UnitZ(), 0.0, theta);
  const Eigen::Vector3d p = g.translation();
  const double err = std::abs(p.x() - l1 * std::sin(theta)) + std::abs(p.y() - l1 * (1 - std::cos(theta))) +
                     std::abs(p.z());
  std::printf("translation %.17g %.17g %.17g, error %.3g\n", p.x(), p.y(), p.z(), err);
  return err < 1e-15 ? 0 : 1;
}
