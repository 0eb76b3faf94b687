// operator<< of every public type (include/chasles/io.hpp): the type, then
// its numbers named as in the Python reprs, with the stream's own format.
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <chasles/chasles.hpp>

namespace {

using namespace chasles;

template <typename T>
std::string str(const T& x, int precision = 6) {
  std::ostringstream os;
  os << std::setprecision(precision) << x;
  return os.str();
}

TEST(Io, Groups) {
  EXPECT_EQ(str(SO3d()), "SO3(matrix=[[1, 0, 0], [0, 1, 0], [0, 0, 1]])");
  EXPECT_EQ(str(SE3f(SO3f(), Eigen::Vector3f(1, 2, 3))),
            "SE3(rotation=[[1, 0, 0], [0, 1, 0], [0, 0, 1]], translation=[1, 2, 3])");
  // Row by row: a quarter turn about z maps x to y.
  Eigen::Matrix3d Rz;
  Rz << 0, -1, 0, 1, 0, 0, 0, 0, 1;
  EXPECT_EQ(str(SO3d::from_matrix_unchecked(Rz)), "SO3(matrix=[[0, -1, 0], [1, 0, 0], [0, 0, 1]])");
}

TEST(Io, TwistWrenchScrew) {
  const Twistd xi(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, 2));
  EXPECT_EQ(str(xi), "Twist(v=[1, 0, 0], w=[0, 0, 2])");
  EXPECT_EQ(str(Wrenchf(Eigen::Vector3f(0, 0, -9.81f), Eigen::Vector3f(0.5f, 0, 0))),
            "Wrench(f=[0, 0, -9.81], tau=[0.5, 0, 0])");
  EXPECT_EQ(str(xi.screw()), "Screw(point=[0, 0.5, 0], direction=[0, 0, 1], pitch=0, magnitude=2)");
  EXPECT_EQ(str(Twistd(Eigen::Vector3d(0, 3, 0), Eigen::Vector3d::Zero()).screw()),
            "Screw(point=[0, 0, 0], direction=[0, 1, 0], pitch=inf, magnitude=3)");
}

TEST(Io, Chain) {
  using Arm = Chain<double, 2>;
  Arm::Screws S;  // revolute about z through 0 and through (1, 0, 0)
  S.col(0) << 0, 0, 0, 0, 0, 1;
  S.col(1) << 0, -1, 0, 0, 0, 1;
  const Arm arm(S, SE3d(SO3d(), Eigen::Vector3d(2, 0, 0)));
  EXPECT_EQ(str(arm),
            "Chain(n_joints=2, space_screws=[[0, 0, 0, 0, 0, 1], [0, -1, 0, 0, 0, 1]], "
            "home=SE3(rotation=[[1, 0, 0], [0, 1, 0], [0, 0, 1]], translation=[2, 0, 0]), "
            "joint_types=[revolute, revolute], lower=[-inf, -inf], upper=[inf, inf], gravity=[0, 0, -9.81], "
            "link_masses=[0, 0])");
  // A dynamic chain of one joint: still a list of screws.
  using Dyn = Chain<float, Eigen::Dynamic, 4>;
  Dyn::Screws D(6, 1);
  D.col(0) = Dyn::prismatic_screw(Eigen::Vector3f(0, 0, 2));
  EXPECT_EQ(str(Dyn(D, SE3f())),
            "Chain(n_joints=1, space_screws=[[0, 0, 1, 0, 0, 0]], "
            "home=SE3(rotation=[[1, 0, 0], [0, 1, 0], [0, 0, 1]], translation=[0, 0, 0]), "
            "joint_types=[prismatic], lower=[-inf], upper=[inf], gravity=[0, 0, -9.81], link_masses=[0])");
  // The full model: types, limits, gravity and the links' masses.
  Arm::JointTypes types{};
  types[0] = JointType::continuous;
  types[1] = JointType::revolute;
  Arm::Inertias inertias{};
  inertias[1] = SpatialInertia<double>(2.5, Eigen::Vector3d(1, 0, 0), Eigen::Matrix3d::Identity());
  const Arm model(S, SE3d(), types, Arm::JointVector(-INFINITY, -1), Arm::JointVector(INFINITY, 1.5),
                  Arm::JointVector(1, 2), Arm::JointVector(3, 4), SE3d(), SE3d(), Eigen::Vector3d(0, -9.8, 0),
                  inertias);
  EXPECT_EQ(str(model),
            "Chain(n_joints=2, space_screws=[[0, 0, 0, 0, 0, 1], [0, -1, 0, 0, 0, 1]], "
            "home=SE3(rotation=[[1, 0, 0], [0, 1, 0], [0, 0, 1]], translation=[0, 0, 0]), "
            "joint_types=[continuous, revolute], lower=[-inf, -1], upper=[inf, 1.5], gravity=[0, -9.8, 0], "
            "link_masses=[0, 2.5])");
}

TEST(Io, JacobianResults) {
  const SO3d I;
  EXPECT_EQ(str(compose_jacobians(I, I)),
            "ComposeJacobians(lhs=[[1, 0, 0], [0, 1, 0], [0, 0, 1]], rhs=[[1, 0, 0], [0, 1, 0], [0, 0, 1]])");
  // -R [p] = -[x]: the negated zeros print as -0.
  EXPECT_EQ(str(act_jacobians(I, Eigen::Vector3d(1, 0, 0))),
            "ActJacobians(group=[[-0, -0, -0], [-0, -0, 1], [-0, -1, -0]], point=[[1, 0, 0], [0, 1, 0], [0, 0, 1]])");
}

TEST(Io, StreamFormatAndAutodiff) {
  std::ostringstream os;
  os << std::fixed << std::setprecision(2) << Twistd(Eigen::Vector3d(1, 0, 0), Eigen::Vector3d(0, 0, 0.125));
  EXPECT_EQ(os.str(), "Twist(v=[1.00, 0.00, 0.00], w=[0.00, 0.00, 0.12])");
  using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;
  EXPECT_EQ(str(Twist<AD>(Eigen::Matrix<AD, 6, 1>::Constant(AD(0.5, 1, 0)))),
            "Twist(v=[0.5, 0.5, 0.5], w=[0.5, 0.5, 0.5])");
}

}  // namespace
