// Built against an installed chasles by tests/cpp/consumer_test.cmake, through
// find_package(chasles): the README's C++ quick start, checked against the
// seed's worked example.
#include <chasles/chasles.hpp>

#include <cmath>
#include <cstdio>

int main() {
  using namespace chasles;
  const Eigen::Matrix3d M = Eigen::Matrix3d::Identity();

  // ---- README quick start (keep in sync with README.md) ----
  // Rotate by theta about the z axis through (0, l1, 0): a screw of pitch 0.
  const double l1 = 2.0, theta = 0.7;
  const SE3d g = SE3d::from_screw({0, l1, 0}, Eigen::Vector3d::UnitZ(), 0.0, theta);
  const Twistd xi(g.log());                       // (v, w) = theta * (l1, 0, 0, 0, 0, 1)
  const Screw<double> s = xi.screw();             // axis through (0, l1, 0), pitch 0, magnitude theta
  const Eigen::Vector3d q = g * Eigen::Vector3d(0, l1, 5);  // points on the axis stay put
  const Wrenchd F_b({0, 0, -9.81}, {0, 0, 0});
  const Wrenchd F_a = g.act(F_b);                 // Ad_g^-T F_b: power V.F is frame independent
  const auto R = SO3d::from_matrix(M);            // checked: std::nullopt if M is not a rotation
  // ---- end of the quick start ----

  const Eigen::Vector3d p = g.translation();
  double err = std::abs(p.x() - l1 * std::sin(theta)) + std::abs(p.y() - l1 * (1 - std::cos(theta))) +
               std::abs(p.z());
  err += (xi.vector() - theta * (Eigen::Matrix<double, 6, 1>() << l1, 0, 0, 0, 0, 1).finished()).norm();
  err += (s.point - Eigen::Vector3d(0, l1, 0)).norm() + std::abs(s.pitch) + std::abs(s.magnitude - theta);
  err += (q - Eigen::Vector3d(0, l1, 5)).norm();
  const Twistd V(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0.1, 0.2, 0.3));
  err += std::abs(power(g.act(V), F_a) - power(V, F_b));
  std::printf("translation %.17g %.17g %.17g, error %.3g, identity checked: %s\n", p.x(), p.y(), p.z(), err,
              R ? "accepted" : "refused");
  return err < 1e-14 && R ? 0 : 1;
}
