// Built against an installed chasles by tests/cpp/consumer_test.cmake: the
// README's C++ quick start, taken from README.md as written, runs inside
// main() and its values are checked against the seed's worked example.
#include <chasles/chasles.hpp>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>

int main() {
#include "readme_quick_start.inc"

  const Eigen::Vector3d p = g.translation();
  double err = std::abs(p.x() - l1 * std::sin(theta)) + std::abs(p.y() - l1 * (1 - std::cos(theta))) + std::abs(p.z());
  err += (xi.vector() - theta * (Eigen::Matrix<double, 6, 1>() << l1, 0, 0, 0, 0, 1).finished()).norm();
  err += (s.point - Eigen::Vector3d(0, l1, 0)).norm() + std::abs(s.pitch) + std::abs(s.magnitude - theta);
  err += (q - Eigen::Vector3d(0, l1, 5)).norm();
  const Twistd V(Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(0.1, 0.2, 0.3));
  err += std::abs(power(g.act(V), F_a) - power(V, F_b));
  const bool accepted = R.has_value() && R->is_approx(g.rotation(), 0.0);
  const bool refused = !SO3d::from_matrix(Eigen::Matrix3d(2.0 * M)).has_value();
  std::ostringstream printed;  // what the quick start prints, as its comment says
  printed << g;
  const bool prints = printed.str() ==
                      "SE3(rotation=[[0.764842, -0.644218, 0], [0.644218, 0.764842, 0], [0, 0, 1]], "
                      "translation=[1.28844, 0.470316, 0])";
  std::printf("translation %.17g %.17g %.17g, error %.3g, rotation accepted: %s, twice it refused: %s, prints: %s\n",
              p.x(), p.y(), p.z(), err, accepted ? "yes" : "no", refused ? "yes" : "no", prints ? "yes" : "no");
  return err < 1e-14 && accepted && refused && prints ? 0 : 1;
}
