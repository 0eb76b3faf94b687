// chain_from_urdf (include/chasles/urdf.hpp) on small URDF texts: the chain
// against an independent composition of the URDF transforms (origin, then
// the rotation about the axis or the translation along it), names, types and
// limits as written, link inertias moved by hand, the links hanging off the
// chain, and the refusals, each naming the element. Compiled with the
// real-time flags (-fno-exceptions -fno-rtti, strict warnings: see
// CMakeLists.txt). The real arms are compared with the Python loader in
// tests/python/test_urdf_cpp.py.
#include <chasles/euler.hpp>
#include <chasles/kinematics.hpp>
#include <chasles/urdf.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>

namespace {

using chasles::JointType;
using chasles::SE3d;
using chasles::SO3d;
using Eigen::Matrix3d;
using Eigen::Vector3d;
using Result = chasles::UrdfChain<double, 8>;
using Arm = Result::ChainType;
constexpr double inf = std::numeric_limits<double>::infinity();

std::string urdf(const std::string& joints, const std::string& links = R"(<link name="a"/><link name="b"/><link name="c"/>)") {
  return "<robot name=\"r\">" + links + joints + "</robot>";
}

std::string joint(const std::string& name, const std::string& kind, const std::string& parent, const std::string& child,
                  const std::string& extra = R"(<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/>)") {
  return "<joint name=\"" + name + "\" type=\"" + kind + "\"><parent link=\"" + parent + "\"/><child link=\"" + child +
         "\"/>" + extra + "</joint>";
}

const std::string kGood = joint("j1", "revolute", "a", "b") + joint("j2", "continuous", "b", "c", R"(<axis xyz="0 2 0"/>)");

std::string link(const std::string& name, double mass, const std::string& origin = "") {
  char text[400];
  std::snprintf(text, sizeof text,
                R"(<link name="%s"><inertial>%s<mass value="%.17g"/>)"
                R"(<inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.1"/></inertial></link>)",
                name.c_str(), origin.c_str(), mass);
  return text;
}

TEST(Urdf, SmallDescription) {
  const Result r = chasles::chain_from_urdf<double, 8>(urdf(kGood), "c");
  ASSERT_TRUE(r) << r.error;
  EXPECT_TRUE(r.error.empty());
  const Arm& arm = *r.chain;
  ASSERT_EQ(arm.joints(), 2);
  EXPECT_EQ(r.joint_names, (std::vector<std::string>{"j1", "j2"}));
  EXPECT_EQ(arm.joint_type(0), JointType::revolute);
  EXPECT_EQ(arm.joint_type(1), JointType::continuous);
  Eigen::Matrix<double, 6, 1> s1, s2;
  s1 << 0, 0, 0, 0, 0, 1;
  s2 << 0, 0, 0, 0, 1, 0;  // the axis (0, 2, 0) normalized
  EXPECT_EQ(arm.space_screws().col(0), s1);
  EXPECT_EQ(arm.space_screws().col(1), s2);
  EXPECT_EQ(arm.lower(), Eigen::Vector2d(-1, -inf));
  EXPECT_EQ(arm.upper(), Eigen::Vector2d(1, inf));
  EXPECT_EQ(arm.velocity_limits(), Eigen::Vector2d(1, inf));
  EXPECT_EQ(arm.effort_limits(), Eigen::Vector2d(1, inf));
  EXPECT_TRUE(arm.home().is_approx(SE3d(), 0.0));
  EXPECT_EQ(arm.gravity(), Arm::default_gravity());
  EXPECT_TRUE(static_cast<bool>(arm.validate()));
  // no <inertial>: zero bodies
  EXPECT_EQ(r.chain->link_inertias()[0].mass(), 0.0);
  EXPECT_EQ(r.chain->link_inertias()[1].inertia(), Matrix3d::Zero());

  const Result from_b = chasles::chain_from_urdf<double, 8>(urdf(kGood), "c", "b");
  ASSERT_TRUE(from_b) << from_b.error;
  EXPECT_EQ(from_b.joint_names, std::vector<std::string>{"j2"});
}

// exp of a joint in its own frame: the rotation about the unit axis by q, or
// the translation q axis.
SE3d joint_motion(bool prismatic, const Vector3d& axis, double q) {
  return prismatic ? SE3d(SO3d(), Vector3d(q * axis)) : SE3d(SO3d::exp(Vector3d(q * axis)), Vector3d::Zero());
}

TEST(Urdf, ForwardKinematicsIsTheCompositionOfTheUrdfTransforms) {
  // base -j1 (revolute)-> l1 -f (fixed)-> l2 -j2 (prismatic)-> l3 -j3 (continuous)-> tip -t (fixed)-> tool
  const double o[5][6] = {{0.1, -0.2, 0.3, 0.4, -0.5, 0.6},
                          {0.0, 0.5, -0.1, 1.2, 0.3, -2.0},
                          {-0.3, 0.2, 0.7, -0.9, 1.1, 0.2},
                          {0.4, 0.4, -0.6, 2.5, -1.3, 0.8},
                          {0.05, 0.0, 0.12, 0.0, 1.5707963267948966, 0.0}};
  const Vector3d axes[3] = {Vector3d(0.3, -1.0, 2.0), Vector3d(1, 1, 0), Vector3d(0, 0, -3)};
  auto origin = [&](int k) {
    char text[200];
    std::snprintf(text, sizeof text, R"(<origin xyz="%.17g %.17g %.17g" rpy="%.17g %.17g %.17g"/>)", o[k][0], o[k][1],
                  o[k][2], o[k][3], o[k][4], o[k][5]);
    return std::string(text);
  };
  auto axis = [&](int k) {
    char text[120];
    std::snprintf(text, sizeof text, R"(<axis xyz="%.17g %.17g %.17g"/>)", axes[k](0), axes[k](1), axes[k](2));
    return std::string(text);
  };
  const std::string limit = R"(<limit lower="-2" upper="2" effort="3" velocity="4"/>)";
  const std::string text = urdf(
      joint("j1", "revolute", "base", "l1", origin(0) + axis(0) + limit) + joint("f", "fixed", "l1", "l2", origin(1)) +
          joint("j2", "prismatic", "l2", "l3", origin(2) + axis(1) + limit) +
          joint("j3", "continuous", "l3", "tip", origin(3) + axis(2)) + joint("t", "fixed", "tip", "tool", origin(4)),
      R"(<link name="base"/><link name="l1"/><link name="l2"/><link name="l3"/><link name="tip"/><link name="tool"/>)");
  const Result r = chasles::chain_from_urdf<double, 8>(text, "tool");
  ASSERT_TRUE(r) << r.error;
  const Arm& arm = *r.chain;
  ASSERT_EQ(arm.joints(), 3);
  EXPECT_TRUE(static_cast<bool>(arm.validate()));
  EXPECT_EQ(arm.joint_type(1), JointType::prismatic);
  auto O = [&](int k) { return SE3d(chasles::from_rpy(o[k][3], o[k][4], o[k][5]), Vector3d(o[k][0], o[k][1], o[k][2])); };
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Arm::JointVector q = Eigen::Vector3d(u(gen), u(gen), u(gen));
    const SE3d expected = O(0) * joint_motion(false, axes[0].normalized(), q(0)) * O(1) * O(2) *
                          joint_motion(true, axes[1].normalized(), q(1)) * O(3) *
                          joint_motion(false, axes[2].normalized(), q(2)) * O(4);
    EXPECT_LT((arm.forward(q).matrix() - expected.matrix()).cwiseAbs().maxCoeff(), 1e-14) << trial;
  }
}

TEST(Urdf, LinkInertiasInTheBaseFrameAtHome) {
  // b's inertial frame: 0.2 along b's x, rotated by rpy; b: 1 m up z from a, turned by pi/2 about z.
  const std::string text =
      "<robot name=\"r\"><link name=\"a\"/>" +
      std::string(R"(<link name="b"><inertial><origin xyz="0.2 0 0" rpy="0.3 -0.4 0.5"/><mass value="2"/>)"
                  R"(<inertia ixx="0.1" ixy="0.01" ixz="-0.02" iyy="0.2" iyz="0.03" izz="0.3"/></inertial></link>)") +
      joint("j", "revolute", "a", "b", R"(<origin xyz="0 0 1" rpy="0 0 1.5707963267948966"/><axis xyz="1 0 0"/>)"
                                       R"(<limit lower="-1" upper="1" effort="1" velocity="1"/>)") +
      "</robot>";
  const Result r = chasles::chain_from_urdf<double, 8>(text, "b");
  ASSERT_TRUE(r) << r.error;
  const chasles::SpatialInertia<double>& body = r.chain->link_inertias()[0];
  EXPECT_EQ(body.mass(), 2.0);
  EXPECT_LT((body.com() - Vector3d(0, 0.2, 1)).norm(), 1e-15);
  Matrix3d I;
  I << 0.1, 0.01, -0.02, 0.01, 0.2, 0.03, -0.02, 0.03, 0.3;
  const Matrix3d R = (chasles::from_rpy(0.0, 0.0, 1.5707963267948966) * chasles::from_rpy(0.3, -0.4, 0.5)).matrix();
  EXPECT_LT((body.inertia() - R * I * R.transpose()).cwiseAbs().maxCoeff(), 1e-15);
  // the screw: about x of b, i.e. the base y, through (0, 0, 1)
  EXPECT_LT((r.chain->space_screws().col(0) - Arm::revolute_screw(Vector3d(0, 0, 1), Vector3d(0, 1, 0))).norm(), 1e-15);
}

TEST(Urdf, LinksHangingOffTheChainRideOnTheirChainLink) {
  // a -j1-> b -j2-> c (the chain, tip c); b carries a sensor (fixed, 1 m up
  // x) and c a finger (prismatic, off the chain: at zero, 1 m along y).
  const std::string text =
      "<robot name=\"r\">" + link("a", 5.0) + link("b", 1.0) + link("c", 2.0) + link("sensor", 1.0) +
      link("finger", 2.0) + joint("j1", "revolute", "a", "b") + joint("j2", "revolute", "b", "c") +
      joint("s", "fixed", "b", "sensor", R"(<origin xyz="1 0 0"/>)") +
      joint("f", "prismatic", "c", "finger",
            R"(<origin xyz="0 1 0"/><axis xyz="1 0 0"/><limit lower="0" upper="1" effort="1" velocity="1"/>)") +
      "</robot>";
  const Result r = chasles::chain_from_urdf<double, 8>(text, "c");
  ASSERT_TRUE(r) << r.error;
  EXPECT_EQ(r.chain->link_inertias()[0].mass(), 2.0);  // b + sensor (the base link a is the base's)
  EXPECT_EQ(r.chain->link_inertias()[1].mass(), 4.0);  // c + finger
  EXPECT_LT((r.chain->link_inertias()[0].com() - Vector3d(0.5, 0, 0)).norm(), 1e-15);
  EXPECT_LT((r.chain->link_inertias()[1].com() - Vector3d(0, 0.5, 0)).norm(), 1e-15);
  // parallel axis: each part 0.5 m from the merged center
  const Vector3d diagonal(0.2, 0.2 + 0.5, 0.2 + 0.5);
  EXPECT_LT((r.chain->link_inertias()[0].inertia() - Matrix3d(diagonal.asDiagonal())).cwiseAbs().maxCoeff(), 1e-15);
  // a link below the tip rides on the last joint
  const Result to_b = chasles::chain_from_urdf<double, 8>(text, "b");
  ASSERT_TRUE(to_b) << to_b.error;
  EXPECT_EQ(to_b.chain->link_inertias()[0].mass(), 1.0 + 1.0 + 2.0 + 2.0);
}

TEST(Urdf, FloatChainAndPathSource) {
  const std::string path = ::testing::TempDir() + "chasles_test_urdf.urdf";
  std::FILE* f = std::fopen(path.c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs(urdf(kGood).c_str(), f);
  std::fclose(f);
  const chasles::UrdfChain<float, 3> r = chasles::chain_from_urdf<float, 3>(path, "c");
  ASSERT_TRUE(r) << r.error;
  EXPECT_EQ(r.chain->joints(), 2);
  EXPECT_EQ(r.chain->space_screws().col(1), (Eigen::Matrix<float, 6, 1>() << 0, 0, 0, 0, 1, 0).finished());
  std::remove(path.c_str());
  const Result missing = chasles::chain_from_urdf<double, 8>(path, "c");
  EXPECT_FALSE(missing);
  EXPECT_FALSE(missing.chain.has_value());
  EXPECT_NE(missing.error.find("cannot open the file '" + path + "'"), std::string::npos) << missing.error;
}

struct Bad {
  std::string text, tip, base, error;
};

TEST(Urdf, RefusalsNameTheElement) {
  const std::string four = R"(<link name="a"/><link name="b"/><link name="c"/><link name="d"/>)";
  const std::string two = R"(<link name="a"/><link name="b"/>)";
  const std::string limit = R"(<limit lower="0" upper="1" effort="1" velocity="1"/>)";
  const Bad cases[] = {
      {urdf(kGood + joint("j3", "floating", "c", "d", ""), four), "d", "", "joint 'j3' is floating"},
      {urdf(kGood + joint("j3", "planar", "c", "d", ""), four), "d", "", "joint 'j3' is planar"},
      {urdf(kGood + joint("j3", "revolute", "c", "d", R"(<mimic joint="j2"/>)" + limit), four), "d", "",
       "joint 'j3': <mimic>"},
      {urdf(joint("j1", "revolute", "a", "x")), "b", "", "child link [x] of joint [j1] not found"},
      {urdf(kGood + joint("j3", "fixed", "c", "b", "")), "c", "", "link 'b' is the child of joints"},
      // the loop a -> b -> a below the root c: urdfdom accepts it
      {urdf(joint("j1", "fixed", "a", "b", "") + joint("j2", "fixed", "b", "a", "")), "a", "", "a loop through link 'b'"},
      {urdf(kGood), "nowhere", "", "chain_from_urdf(tip_link): no link named 'nowhere'"},
      {urdf(kGood), "c", "nowhere", "chain_from_urdf(base_link): no link named 'nowhere'"},
      {urdf(kGood), "b", "c", "tip_link 'b' is not below base_link 'c'"},
      {urdf(joint("j1", "revolute", "a", "b", R"(<axis xyz="0 0 1"/>)"), two), "b", "",
       "Joint [j1] is of type REVOLUTE but it does not specify limits"},
      {urdf(joint("j1", "prismatic", "a", "b", R"(<axis xyz="0 0 1"/>)"), two), "b", "",
       "Joint [j1] is of type PRISMATIC without limits"},
      {urdf(joint("j1", "revolute", "a", "b", R"(<axis xyz="0 0 0"/>)" + limit), two), "b", "",
       "joint 'j1': <axis xyz> is zero"},
      {urdf(joint("j1", "revolute", "a", "b", R"(<axis xyz="0 0 inf"/>)" + limit), two), "b", "",
       "joint 'j1' <axis xyz>: expected finite numbers"},
      {urdf(joint("j1", "revolute", "a", "b", R"(<axis xyz="0 0 1"/><limit lower="0" upper="1" effort="1"/>)"), two),
       "b", "", "joint limit: no velocity"},
      {urdf(joint("j1", "fixed", "a", "b", ""), two), "b", "", "no revolute, continuous or prismatic joint from 'a' to 'b'"},
      {urdf(joint("j1", "screwy", "a", "b", ""), two), "b", "", "Joint [j1] has no known type [screwy]"},
      {"<robot><link name='a'/>", "a", "", "urdfdom refused the description"},
      {"<model name='r'/>", "a", "", "Could not find the 'robot' element"},
      {urdf(kGood + joint("j3", "fixed", "a", "d", ""), four + R"(<link name="e"/>)"), "c", "", "Two root links found"},
      // urdfdom logs these, yet returns a model with zeros for what it could not read:
      // the loader reads them itself
      {urdf(joint("j1", "continuous", "a", "b", ""), R"(<link name="a"/><link name="b"><inertial><mass value="1"/></inertial></link>)"),
       "b", "", "link 'b' <inertia>: expected finite numbers"},
      {urdf(joint("j1", "continuous", "a", "b", ""),
            R"(<link name="a"/><link name="b"><inertial><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>)"),
       "b", "", "link 'b' <mass>: expected finite numbers"},
      {urdf(joint("j1", "continuous", "a", "b", ""),
            R"(<link name="a"/><link name="b"><inertial><mass value="1"/><inertia ixx="1"/></inertial></link>)"),
       "b", "", "link 'b' <inertia>: expected finite numbers"},
  };
  for (const Bad& bad : cases) {
    const Result r = chasles::chain_from_urdf<double, 8>(bad.text, bad.tip, bad.base);
    EXPECT_FALSE(r) << bad.text;
    EXPECT_NE(r.error.find(bad.error), std::string::npos) << "expected \"" << bad.error << "\" in \"" << r.error << "\"";
    EXPECT_EQ(r.error.rfind("chain_from_urdf", 0), 0u) << r.error;
  }
}

TEST(Urdf, MoreJointsThanMaxJointsIsRefused) {
  const Result r = chasles::chain_from_urdf<double, 8>(urdf(kGood), "c");
  ASSERT_TRUE(r);
  const chasles::UrdfChain<double, 1> small = chasles::chain_from_urdf<double, 1>(urdf(kGood), "c");
  EXPECT_FALSE(small);
  EXPECT_NE(small.error.find("has 2 moving joints, more than MaxJoints = 1"), std::string::npos) << small.error;
  EXPECT_TRUE((chasles::chain_from_urdf<double, 1>(urdf(kGood), "c", "b")));
}

}  // namespace
