// Prints the chain chain_from_urdf loads from a URDF as JSON, for the Python
// tests that compare it with Chain.from_urdf on real arms
// (tests/python/test_urdf_cpp.py; tests/run.sh passes this program's path in
// CHASLES_URDF_DUMP):
//
//   chasles_urdf_dump robot.urdf tip_link [base_link]
//
// {"names": [...], "joint_types": [...], "screws": n x 6 (v, w), "home": 4 x 4,
//  "lower", "upper", "velocity_limits", "effort_limits": n each,
//  "link_inertias": n x 10 (m, c, Ixx, Ixy, Ixz, Iyy, Iyz, Izz)}, numbers to
// 17 significant digits, infinities as Infinity (Python's json reads them).
// On a refusal: nothing on stdout; on stderr the loader's error text as it
// is (UrdfChain::error: "chain_from_urdf: " then the reason, the same text
// as the Python loader's after "Chain.from_urdf: "; for an unknown tip or
// base link "chain_from_urdf(tip_link): ..." or "chain_from_urdf(base_link):
// ...") and a newline; exit status 1. Exit status 2: wrong arguments.
#include <chasles/urdf.hpp>

#include <cmath>
#include <cstdio>
#include <string>

namespace {

constexpr int max_joints = 32;

void number(double x) {
  if (std::isinf(x))
    std::printf(x > 0 ? "Infinity" : "-Infinity");
  else
    std::printf("%.17g", x);
}

template <typename Vector>
void vector(const char* key, const Vector& v, bool last = false) {
  std::printf("\"%s\": [", key);
  for (Eigen::Index i = 0; i < v.size(); ++i) {
    if (i) std::printf(", ");
    number(v(i));
  }
  std::printf("]%s\n", last ? "" : ",");
}

void string(const std::string& s) {
  std::putchar('"');
  for (const char ch : s) {
    if (ch == '"' || ch == '\\') std::putchar('\\');
    std::putchar(ch);
  }
  std::putchar('"');
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3 && argc != 4) {
    std::fprintf(stderr, "usage: %s robot.urdf tip_link [base_link]\n", argv[0]);
    return 2;
  }
  const auto r = chasles::chain_from_urdf<double, max_joints>(argv[1], argv[2], argc == 4 ? argv[3] : "");
  if (!r) {
    std::fprintf(stderr, "%s\n", r.error.c_str());
    return 1;
  }
  const auto& c = *r.chain;
  const Eigen::Index n = c.n_joints();
  static const char* const kTypes[] = {"revolute", "continuous", "prismatic"};
  std::printf("{\"names\": [");
  for (std::size_t i = 0; i < r.joint_names.size(); ++i) {
    if (i) std::printf(", ");
    string(r.joint_names[i]);
  }
  std::printf("],\n\"joint_types\": [");
  for (Eigen::Index i = 0; i < n; ++i)
    std::printf("%s\"%s\"", i ? ", " : "", kTypes[static_cast<int>(c.joint_type(i))]);
  std::printf("],\n\"screws\": [");
  for (Eigen::Index i = 0; i < n; ++i) {
    std::printf("%s[", i ? ", " : "");
    for (int k = 0; k < 6; ++k) std::printf(k ? ", %.17g" : "%.17g", c.space_screws()(k, i));
    std::printf("]");
  }
  std::printf("],\n\"home\": [");
  const Eigen::Matrix4d M = c.home().matrix();
  for (int row = 0; row < 4; ++row) {
    std::printf("%s[", row ? ", " : "");
    for (int k = 0; k < 4; ++k) std::printf(k ? ", %.17g" : "%.17g", M(row, k));
    std::printf("]");
  }
  std::printf("],\n");
  vector("lower", c.lower());
  vector("upper", c.upper());
  vector("velocity_limits", c.velocity_limits());
  vector("effort_limits", c.effort_limits());
  std::printf("\"link_inertias\": [");
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto& body = r.chain->link_inertias()[static_cast<std::size_t>(i)];
    const Eigen::Matrix3d& I = body.inertia();
    const double row[10] = {body.mass(), body.com()(0), body.com()(1), body.com()(2), I(0, 0),
                            I(0, 1),     I(0, 2),       I(1, 1),       I(1, 2),       I(2, 2)};
    std::printf("%s[", i ? ", " : "");
    for (int k = 0; k < 10; ++k) std::printf(k ? ", %.17g" : "%.17g", row[k]);
    std::printf("]");
  }
  std::printf("]}\n");
  return 0;
}
