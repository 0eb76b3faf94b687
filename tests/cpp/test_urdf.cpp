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

#include <console_bridge/console.h>
#include <sys/stat.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <limits>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace {

using chasles::JointType;
using chasles::SE3d;
using chasles::SO3d;
using Eigen::Matrix3d;
using Eigen::Vector3d;
using Result = chasles::UrdfChain<double, 8>;
using Arm = Result::ChainType;
constexpr double inf = std::numeric_limits<double>::infinity();

std::string urdf(const std::string& joints,
                 const std::string& links = R"(<link name="a"/><link name="b"/><link name="c"/>)") {
  return "<robot name=\"r\">" + links + joints + "</robot>";
}

std::string joint(
    const std::string& name, const std::string& kind, const std::string& parent, const std::string& child,
    const std::string& extra = R"(<axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="1" velocity="1"/>)") {
  return "<joint name=\"" + name + "\" type=\"" + kind + "\"><parent link=\"" + parent + "\"/><child link=\"" + child +
         "\"/>" + extra + "</joint>";
}

const std::string kGood =
    joint("j1", "revolute", "a", "b") + joint("j2", "continuous", "b", "c", R"(<axis xyz="0 2 0"/>)");

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
  ASSERT_EQ(arm.n_joints(), 2);
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
  ASSERT_EQ(arm.n_joints(), 3);
  EXPECT_TRUE(static_cast<bool>(arm.validate()));
  EXPECT_EQ(arm.joint_type(1), JointType::prismatic);
  auto O = [&](int k) {
    return SE3d(chasles::from_rpy(o[k][3], o[k][4], o[k][5]), Vector3d(o[k][0], o[k][1], o[k][2]));
  };
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
      joint("j", "revolute", "a", "b",
            R"(<origin xyz="0 0 1" rpy="0 0 1.5707963267948966"/><axis xyz="1 0 0"/>)"
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
  EXPECT_EQ(r.chain->n_joints(), 2);
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
      {urdf(joint("j1", "fixed", "a", "b", "") + joint("j2", "fixed", "b", "a", "")), "a", "",
       "a loop through link 'b'"},
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
      {urdf(joint("j1", "fixed", "a", "b", ""), two), "b", "",
       "no revolute, continuous or prismatic joint from 'a' to 'b'"},
      {urdf(joint("j1", "screwy", "a", "b", ""), two), "b", "", "Joint [j1] has no known type [screwy]"},
      {"<robot><link name='a'/>", "a", "", "urdfdom refused the description"},
      {"<model name='r'/>", "a", "", "Could not find the 'robot' element"},
      {urdf(kGood + joint("j3", "fixed", "a", "d", ""), four + R"(<link name="e"/>)"), "c", "", "Two root links found"},
      // urdfdom logs these, yet returns a model with zeros for what it could not read:
      // the loader reads them itself
      {urdf(joint("j1", "continuous", "a", "b", ""),
            R"(<link name="a"/><link name="b"><inertial><mass value="1"/></inertial></link>)"),
       "b", "", "link 'b' <inertia>: expected finite numbers"},
      {urdf(
           joint("j1", "continuous", "a", "b", ""),
           R"(<link name="a"/><link name="b"><inertial><inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>)"),
       "b", "", "link 'b' <mass>: expected finite numbers"},
      {urdf(joint("j1", "continuous", "a", "b", ""),
            R"(<link name="a"/><link name="b"><inertial><mass value="1"/><inertia ixx="1"/></inertial></link>)"),
       "b", "", "link 'b' <inertia>: expected finite numbers"},
  };
  for (const Bad& bad : cases) {
    const Result r = chasles::chain_from_urdf<double, 8>(bad.text, bad.tip, bad.base);
    EXPECT_FALSE(r) << bad.text;
    EXPECT_NE(r.error.find(bad.error), std::string::npos)
        << "expected \"" << bad.error << "\" in \"" << r.error << "\"";
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

// ---- Hostile input: each of these was accepted wrongly, crashed, leaked or
// depended on console_bridge's global state before the loader's checks.

/// Whether every number of the chain is finite and the chain validates.
bool sound(const Arm& arm) {
  bool ok = static_cast<bool>(arm.validate()) && arm.space_screws().allFinite() && arm.home().matrix().allFinite();
  for (Eigen::Index i = 0; i < arm.n_joints(); ++i) {
    const auto& G = arm.link_inertias()[static_cast<std::size_t>(i)];
    ok = ok && std::isfinite(G.mass()) && G.com().allFinite() && G.inertia().allFinite();
  }
  return ok;
}

void expect_refused(const std::string& text, const std::string& tip, const std::string& message,
                    const std::string& base = "") {
  const Result r = chasles::chain_from_urdf<double, 8>(text, tip, base);
  EXPECT_FALSE(r) << text.substr(0, 300);
  EXPECT_EQ(r.error, "chain_from_urdf: " + message) << text.substr(0, 300);
}

/// a -j1-> b (revolute) with b's side branch of n fixed links s0 -> s1 -> ...
std::string side_branch(int n) {
  std::string text = "<robot name=\"r\">" + link("a", 1.0) + link("b", 1.0);
  text.reserve(static_cast<std::size_t>(n) * 120);
  for (int k = 0; k < n; ++k)  // a mass on every 100th
    text += k % 100 ? "<link name=\"s" + std::to_string(k) + "\"/>" : link("s" + std::to_string(k), 0.5);
  text += joint("j1", "revolute", "a", "b");
  for (int k = 0; k < n; ++k)
    text += joint("f" + std::to_string(k), "fixed", k ? "s" + std::to_string(k - 1) : std::string("b"),
                  "s" + std::to_string(k), R"(<origin xyz="0.001 0 0"/>)");
  return text + "</robot>";
}

TEST(UrdfHostile, LongSideBranchLoadsFast) {
  const std::string text = side_branch(25000);  // 3.3 MB; overflowed the stack of a recursive walk
  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu = std::clock();
  const Result r = chasles::chain_from_urdf<double, 8>(text, "b");
  const double cpu_seconds = static_cast<double>(std::clock() - cpu) / CLOCKS_PER_SEC;
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(r) << r.error;
  std::printf("[ timing ] a side branch of 25000 fixed links (%zu bytes): %.3f s (CPU %.3f s)\n", text.size(), seconds,
              cpu_seconds);
  EXPECT_DOUBLE_EQ(r.chain->link_inertias()[0].mass(), 1.0 + 250 * 0.5);
  EXPECT_TRUE(sound(*r.chain));
}

using Loaded = chasles::UrdfChain<double, 8>;
Loaded load(const std::string& text, const std::string& tip) { return chasles::chain_from_urdf<double, 8>(text, tip); }

std::string nested(int levels, bool self_closing_last = false) {
  std::string text = "<robot name=\"r\">";
  for (int k = 1; k < levels - (self_closing_last ? 1 : 0); ++k) text += "<x>";
  if (self_closing_last) text += "<x/>";
  for (int k = 1; k < levels - (self_closing_last ? 1 : 0); ++k) text += "</x>";
  return text + "</robot>";
}

TEST(UrdfHostile, DeepDocumentsAreRefusedBeforeTheParser) {
  const std::string deep = "chain_from_urdf: the XML nests elements more than 64 deep, the bound on a URDF description";
  // 50,000 levels overflowed the stack inside urdfdom's XML parser (20,000: 16 s)
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(load(nested(50000), "a").error, deep);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  EXPECT_EQ(load(nested(65), "a").error, deep);
  EXPECT_EQ(load(nested(65, true), "a").error, deep);
  // 64 deep is urdfdom's to judge (no link 'a': it gets that far)
  EXPECT_NE(load(nested(64), "a").error, deep);
  EXPECT_NE(load(nested(64, true), "a").error, deep);
  // comments, CDATA, processing instructions, quoted '>' and '<' do not nest
  std::string hidden = "<?xml version=\"1.0\"?><!DOCTYPE robot><robot name=\"r\">";
  for (int k = 0; k < 100; ++k) hidden += "<!-- <x> --><![CDATA[<x>]]><?pi <x>?><y a=\"<x>\" b='>'/>";
  hidden += link("a", 1.0) + link("b", 1.0) + joint("j1", "revolute", "a", "b") + "</robot>";
  const Result r = chasles::chain_from_urdf<double, 8>(hidden, "b");
  EXPECT_TRUE(r) << r.error;
  // a processing instruction ends at its first '>' for the count, as for the parser
  std::string sneaky = "<robot name=\"r\"><?pi >";
  for (int k = 0; k < 70; ++k) sneaky += "<x>";
  EXPECT_EQ(load(sneaky + "?>", "a").error, deep);
}

TEST(UrdfHostile, ManyAttributesAreRefusedBeforeTheParser) {
  // urdfdom's XML parser checks each attribute against the element's
  // others: 20,000 attributes took 1.7 s of CPU, a 2.7 MB element minutes.
  auto with = [](int n) {
    std::string attributes;
    for (int k = 0; k < n; ++k) attributes += " a" + std::to_string(k) + "=\"1\"";
    return urdf(kGood, "<link name=\"a\"" + attributes + R"(/><link name="b"/><link name="c"/>)");
  };
  const auto start = std::chrono::steady_clock::now();
  expect_refused(with(270000), "c", "an element has more than 256 attributes, the bound on a URDF description");
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 5.0);
  expect_refused(with(257), "c", "an element has more than 256 attributes, the bound on a URDF description");
  const Result r = chasles::chain_from_urdf<double, 8>(with(255), "c");  // with name: 256
  EXPECT_TRUE(r) << r.error;
}

TEST(UrdfHostile, CyclicDescriptionsAreRefusedWithoutLeaks) {
  // Under LeakSanitizer (tests/run.sh, build/sanitize) a leak fails this
  // test: urdfdom's links hold each other by shared_ptr, and each refused
  // load of such a file leaked about 2 kB.
  const std::string abc = R"(<link name="a"/><link name="b"/><link name="c"/><link name="d"/>)";
  struct Case {
    std::string joints, tip, error;
  };
  const Case cases[] = {
      // two links each the parent of the other, below the root d
      {joint("j1", "fixed", "a", "b", "") + joint("j2", "fixed", "b", "a", "") + joint("j3", "fixed", "d", "c", ""),
       "a", "a loop through link 'b'"},
      // a three-link cycle and no root
      {joint("j1", "fixed", "a", "b", "") + joint("j2", "fixed", "b", "c", "") + joint("j3", "fixed", "c", "a", ""),
       "a", "a loop through link 'b'"},
      // a link its own parent
      {joint("j1", "fixed", "a", "a", "") + joint("j2", "fixed", "c", "b", ""), "a", "a loop through link 'a'"},
      // a link the child of two joints (below the root, and on a cycle)
      {joint("j1", "revolute", "a", "b") + joint("j2", "fixed", "b", "c", "") + joint("j3", "fixed", "c", "b", ""), "c",
       "link 'b' is the child of joints 'j1' and 'j3': a loop (URDF describes trees)"},
      {joint("j1", "revolute", "a", "b") + joint("j2", "revolute", "a", "c") + joint("j3", "fixed", "b", "d", "") +
           joint("j4", "fixed", "c", "d", ""),
       "d", "link 'd' is the child of joints 'j3' and 'j4': a loop (URDF describes trees)"},
  };
  for (int round = 0; round < 20; ++round)
    for (const Case& c : cases) expect_refused(urdf(c.joints, abc), c.tip, c.error);
  // The scan sees the joints the XML parser sees: attribute values without
  // quotes, form feeds between attributes (the parser reads both), and
  // text that is not UTF-8 (the parser would read a '<' after the byte 0xD4
  // as part of a character, where the scan sees a tag: found by fuzz_urdf).
  const std::string unquoted = R"(<joint name="j1" type="fixed"><parent link=a/><child link=a/></joint>)";
  const std::string form_feed = "<joint\fname=\"j1\"\ftype=\"fixed\"><parent\flink=\"a\"/><child\flink=\"a\"/></joint>";
  for (int round = 0; round < 20; ++round) {
    expect_refused(urdf(unquoted, abc), "a", "a loop through link 'a'");
    expect_refused(urdf(form_feed, abc), "a", "a loop through link 'a'");
    expect_refused("<?xml version=\"1.0\"?><robot name=\"r\"><link name=\"a\"/>\xD4<link name=2b\"/>" +
                       joint("j1", "fixed", "a", "a", "") + "</robot>",
                   "a", "the description is not UTF-8 text (byte 53 of the text)");
  }
  // The XML declaration ends where the parser ends it: a '<' in its quoted
  // version hid the robot and its loop from the scan (the parser read the
  // value whole), and urdfdom leaked the loop (found by fuzz_urdf). Every
  // quote that the parser could read as opening a value is followed.
  const std::string loop = abc + joint("j1", "fixed", "a", "b", "") + joint("j2", "fixed", "b", "a", "");
  const std::string body = "<robot name=\"r\">" + loop + "</robot>";
  const std::string hidden_by =
      "not well-formed XML: the declaration or processing instruction at byte 0 has a quote "
      "that opens no value, or a value that holds a quote or a '>'";
  std::string nested;
  for (int k = 0; k < 20; ++k) nested += "<x>";
  for (int round = 0; round < 20; ++round) {
    expect_refused("<?xml version=\">" + nested + "<1.0\"?>" + body, "a", hidden_by);
    expect_refused("<?xml encoding='>" + nested + "' version=\"1.0\"?>" + body, "a", hidden_by);
    // a quote the scan could take for a closing one where the parser opens a value
    expect_refused("<?xml a=\"b version=\f\">" + nested + "\"?>" + body, "a", hidden_by);
    expect_refused("<?xml a=\"b version=\xEF\xBB\xBF\">" + nested + "\"?>" + body, "a", hidden_by);
    expect_refused("<?xml x\"y version=\">" + nested + "\"?>" + body, "a", hidden_by);
  }
  // what XML allows there loads, or meets the loop check
  for (const char* declaration : {"<?xml version=\"1.0\"?>", "<?xml version = '1.0' encoding=\"UTF-8\" ?>",
                                  "<?xml version=\"1.0\" standalone='yes'?><?xml-stylesheet href=\"a.xsl\"?>"}) {
    expect_refused(declaration + body, "a", "a loop through link 'b'");
    const Result r =
        chasles::chain_from_urdf<double, 8>(std::string(declaration) + "<robot name=\"r\">" + link("a", 1.0) +
                                                link("b", 1.0) + joint("j1", "revolute", "a", "b") + "</robot>",
                                            "b");
    EXPECT_TRUE(r) << declaration << ": " << r.error;
  }
  // names are compared as the parser decodes them
  expect_refused(urdf(R"(<joint name="j1" type="fixed"><parent link="&#97;"/><child link="a"/></joint>)", abc), "a",
                 "a loop through link 'a'");
  expect_refused(urdf(R"(<joint name="j1" type="fixed"><parent link="&#233;"/><child link="&#xE9;"/></joint>)",
                      abc + R"(<link name="&#233;"/>)"),
                 "a", "link '&#233;': a character reference (&#...;) in a name is not supported");
  // UTF-8 text loads
  const Result utf8 = chasles::chain_from_urdf<double, 8>(
      "<?xml version=\"1.0\" encoding=\"UTF-8\"?><!-- \xC3\xA9l\xC3\xA8ve \xE2\x86\x92 \xF0\x9F\xA4\x96 -->" +
          urdf(kGood),
      "c");
  EXPECT_TRUE(utf8) << utf8.error;
}

TEST(UrdfHostile, NumbersThatAreNotFiniteOrOverflowAreRefused) {
  const std::string two = R"(<link name="a"/><link name="b"/>)";
  const std::string limit = R"(<limit lower="-1" upper="1" effort="1" velocity="1"/>)";
  auto one = [&](const std::string& extra, const std::string& links = "") {
    return urdf(joint("j1", "revolute", "a", "b", extra), links.empty() ? two : links);
  };
  expect_refused(one(R"(<origin xyz="nan 0 0"/>)" + limit), "b", "joint 'j1' <origin xyz>: expected finite numbers");
  expect_refused(one(R"(<origin rpy="0 inf 0"/>)" + limit), "b", "joint 'j1' <origin rpy>: expected finite numbers");
  expect_refused(one(R"(<origin xyz="1e400 0 0"/>)" + limit), "b", "joint 'j1' <origin xyz>: expected finite numbers");
  expect_refused(one(R"(<origin xyz="1)" + std::string(400, '0') + R"(e-50 0 0"/>)" + limit), "b",
                 "joint 'j1' <origin xyz>: expected finite numbers");
  {  // too small for a double: its nearest double, a zero of its sign (as Python's float reads it)
    const auto r =
        chasles::chain_from_urdf<double, 8>(one(R"(<origin xyz="1e-400 -1e-400 0.001e-398"/>)" + limit), "b");
    ASSERT_TRUE(r) << r.error;
    EXPECT_EQ(r.chain->home().translation(), Eigen::Vector3d::Zero());
    const auto s = chasles::chain_from_urdf<double, 8>(one(R"(<origin xyz="100e-402 4.9e-324 0"/>)" + limit), "b");
    ASSERT_TRUE(s) << s.error;
    EXPECT_EQ(s.chain->home().translation(), Eigen::Vector3d(0, 4.9e-324, 0));
  }
  expect_refused(one(R"(<axis xyz="0 nan 1"/>)" + limit), "b", "joint 'j1' <axis xyz>: expected finite numbers");
  expect_refused(one(R"(<limit lower="-1" upper="nan" effort="1" velocity="1"/>)"), "b",
                 "joint 'j1' <limit>: expected finite numbers");
  expect_refused(one(R"(<limit lower="1" upper="0" effort="1" velocity="1"/>)"), "b",
                 "joint 'j1' <limit>: lower 1 > upper 0");
  expect_refused(one(R"(<limit lower="-1" upper="1" effort="1" velocity="-1"/>)"), "b",
                 "joint 'j1' <limit>: negative velocity -1");
  expect_refused(one(R"(<limit lower="-1" upper="1" effort="-1.5" velocity="1"/>)"), "b",
                 "joint 'j1' <limit>: negative effort -1.5");
  expect_refused(urdf(joint("j1", "continuous", "a", "b", R"(<limit effort="-1" velocity="1"/>)"), two), "b",
                 "joint 'j1' <limit>: negative effort -1");
  const std::string inertia = R"(<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/>)";
  auto body = [&](const std::string& inertial) {
    return one(limit, "<link name=\"a\"/><link name=\"b\"><inertial>" + inertial + "</inertial></link>");
  };
  expect_refused(body(R"(<mass value="nan"/>)" + inertia), "b", "link 'b' <mass>: expected finite numbers");
  expect_refused(body(R"(<mass value="1e400"/>)" + inertia), "b", "link 'b' <mass>: expected finite numbers");
  expect_refused(body(R"(<mass/>)" + inertia), "b", "link 'b' <mass>: expected finite numbers");
  expect_refused(body(inertia), "b", "link 'b' <mass>: expected finite numbers");
  expect_refused(body(R"(<mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="inf" iyz="0" izz="1"/>)"), "b",
                 "link 'b' <inertia>: expected finite numbers");
  expect_refused(body(R"(<mass value="1"/><inertia ixx="1" ixy="0" ixz="0" iyy="1" izz="1"/>)"), "b",
                 "link 'b' <inertia>: expected finite numbers");
  expect_refused(body(R"(<origin xyz="0 0 -inf"/><mass value="1"/>)" + inertia), "b",
                 "link 'b' <inertial> <origin xyz>: expected finite numbers");
  // finite numbers that overflow when combined
  const std::string big = R"(<origin xyz="1e308 0 0"/><axis xyz="0 0 1"/>)" + limit;
  const std::string three = R"(<link name="a"/><link name="b"/><link name="c"/>)";
  expect_refused(urdf(joint("j1", "revolute", "a", "b", big) + joint("j2", "revolute", "b", "c", big), three), "c",
                 "joint 'j2': the pose of link 'c' at home is not finite (overflow)");
  expect_refused(urdf(joint("j1", "revolute", "a", "b", limit) + joint("f", "fixed", "b", "c", ""),
                      "<link name=\"a\"/>" + link("b", 1e308) + link("c", 1e308)),
                 "b", "joint 'j1': the mass properties of the links it moves are not finite (overflow)");
  // an axis of 1e308 is a direction
  const Result axis = chasles::chain_from_urdf<double, 8>(one(R"(<axis xyz="1e308 1e308 0"/>)" + limit), "b");
  ASSERT_TRUE(axis) << axis.error;
  EXPECT_LT((axis.chain->space_screws().col(0).tail<3>() - Vector3d(1, 1, 0).normalized()).norm(), 1e-15);
  EXPECT_TRUE(sound(*axis.chain));
  // finite in double, not in float: the chain's own validation names the joint
  const chasles::UrdfChain<float, 8> heavy = chasles::chain_from_urdf<float, 8>(
      urdf(joint("j1", "revolute", "a", "b", limit), "<link name=\"a\"/>" + link("b", 1e300)), "b");
  EXPECT_FALSE(heavy);
  EXPECT_EQ(heavy.error,
            "chain_from_urdf: joint 'j1': the mass properties of the links it moves are not finite (overflow)");
  const chasles::UrdfChain<float, 8> far = chasles::chain_from_urdf<float, 8>(
      urdf(joint("j1", "revolute", "a", "b", R"(<origin xyz="0 0 1e300"/>)" + limit), two), "b");
  EXPECT_FALSE(far);
  EXPECT_EQ(far.error, "chain_from_urdf: joint 'j1': the pose of link 'b' at home is not finite (overflow)");
}

TEST(UrdfHostile, NegativeMassesAndDuplicateNamesAreRefused) {
  const std::string limit = R"(<limit lower="-1" upper="1" effort="1" velocity="1"/>)";
  // on the chain, and in a fixed link whose mass was summed into its parent's
  expect_refused(urdf(joint("j1", "revolute", "a", "b", limit), "<link name=\"a\"/>" + link("b", -1.5)), "b",
                 "link 'b' <mass>: negative mass -1.5 (a mass is >= 0)");
  expect_refused(urdf(joint("j1", "revolute", "a", "b", limit) + joint("f", "fixed", "b", "c", ""),
                      "<link name=\"a\"/>" + link("b", 2.0) + link("c", -1.0)),
                 "b", "link 'c' <mass>: negative mass -1 (a mass is >= 0)");
  expect_refused(urdf(kGood, R"(<link name="a"/><link name="b"/><link name="c"/><link name="b"/>)"), "c",
                 "duplicate link name 'b'");
  expect_refused(urdf(kGood + joint("j1", "fixed", "c", "d", ""),
                      R"(<link name="a"/><link name="b"/><link name="c"/><link name="d"/>)"),
                 "c", "duplicate joint name 'j1'");
}

TEST(UrdfHostile, TheVerdictDoesNotDependOnConsoleBridge) {
  const std::string nan_mass = urdf(joint("j1", "continuous", "a", "b", ""),
                                    R"(<link name="a"/><link name="b"><inertial><mass value="nan"/>)"
                                    R"(<inertia ixx="1" ixy="0" ixz="0" iyy="1" iyz="0" izz="1"/></inertial></link>)");
  const console_bridge::LogLevel level = console_bridge::getLogLevel();
  console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_NONE);  // was: loaded with mass 0
  expect_refused(nan_mass, "b", "link 'b' <mass>: expected finite numbers");
  expect_refused(
      urdf(joint("j1", "revolute", "a", "b", R"(<axis xyz="0 0 1"/>)"), R"(<link name="a"/><link name="b"/>)"), "b",
      "urdfdom refused the description: no reason given (console_bridge's log level hides its messages)");
  console_bridge::setLogLevel(level);
  // Other threads log errors while these load valid descriptions (was: 12 of
  // 800 loads failed with the other threads' messages).
  struct Quiet : console_bridge::OutputHandler {
    void log(const std::string&, console_bridge::LogLevel, const char*, int) override { ++count; }
    std::atomic<int> count{0};
  } quiet;
  console_bridge::useOutputHandler(&quiet);
  std::atomic<bool> done{false};
  std::atomic<int> failures{0}, loads{0};
  std::vector<std::thread> threads;
  for (int t = 0; t < 2; ++t)
    threads.emplace_back([&] {
      while (!done) CONSOLE_BRIDGE_logError("an error of another part of the application");
    });
  for (int t = 0; t < 2; ++t)
    threads.emplace_back([&] {
      for (int k = 0; k < 200; ++k) {
        if (!chasles::chain_from_urdf<double, 8>(urdf(kGood), "c")) ++failures;
        ++loads;
      }
    });
  for (std::size_t t = 2; t < threads.size(); ++t) threads[t].join();
  done = true;
  threads[0].join();
  threads[1].join();
  console_bridge::restorePreviousOutputHandler();
  EXPECT_EQ(loads, 400);
  EXPECT_EQ(failures, 0);
  EXPECT_GT(quiet.count, 0);  // the other threads' messages reached the application's handler
}

TEST(UrdfHostile, SourcesTextOrRegularFileWithinTheBound) {
  // XML text after a byte-order mark (was taken for a path)
  const Result bom = chasles::chain_from_urdf<double, 8>("\xEF\xBB\xBF  " + urdf(kGood), "c");
  EXPECT_TRUE(bom) << bom.error;
  const std::string dir = ::testing::TempDir();
  const std::string dir_path = dir.size() > 1 && dir.back() == '/' ? dir.substr(0, dir.size() - 1) : dir;
  expect_refused(dir_path, "c", "'" + dir_path + "' is a directory, not a URDF file");
  expect_refused("/dev/zero", "c", "'/dev/zero' is not a regular file");
  expect_refused("/no/such/file.urdf", "c", "cannot open the file '/no/such/file.urdf'");
  std::string huge = urdf(kGood);
  huge.resize((std::size_t{64} << 20) + 1, ' ');
  expect_refused(huge, "c", "the description is larger than 64 MiB, the bound on a URDF description");
  huge.resize(std::size_t{64} << 20);  // at the bound: read
  const Result at_bound = chasles::chain_from_urdf<double, 8>(huge, "c");
  EXPECT_TRUE(at_bound) << at_bound.error;
  const std::string path = dir + "chasles_test_urdf_huge.urdf";
  std::FILE* f = std::fopen(path.c_str(), "wb");
  ASSERT_NE(f, nullptr);
  huge.resize((std::size_t{64} << 20) + 1, ' ');
  std::fwrite(huge.data(), 1, huge.size(), f);
  std::fclose(f);
  expect_refused(path, "c", "'" + path + "' is larger than 64 MiB, the bound on a URDF description");
  std::remove(path.c_str());
}

}  // namespace
