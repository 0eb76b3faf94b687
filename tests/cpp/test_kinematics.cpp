// Product-of-exponentials kinematics (chasles::Chain), typed over float and
// double, for fixed-size chains and dynamic chains with a compile-time bound:
// - planar 2R and 3R arms against their closed-form forward kinematics;
// - a UR5 (Modern Robotics, example 4.5) from its published screw axes, and
//   the same arm on a linear rail (7 joints), against an independent product
//   of 4x4 matrix exponentials (Eigen's MatrixFunctions, long double,
//   support/reference.hpp);
// - forward == forward_body, J_s = Ad_g J_b;
// - both Jacobians against central differences of the long double reference
//   forward kinematics: spatial columns vee(dg/dth_i g^-1), body columns
//   vee(g^-1 dg/dth_i).
//
// Tolerances are k * eps of the scalar under test times the scale of the data
// (support/group_traits.hpp, `near`), with k stated where used:
//   kExp  = 16: one exp or one composition, "a few ulps" (as the other suites);
//   per chain of n joints, n exps and n compositions: k = 2 n kExp.
// The reference inputs are the library's inputs (screws, M, theta) after
// rounding to the scalar under test, cast to long double: the error measured
// is the library's, not the rounding of the data.
#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>

#include <chasles/kinematics.hpp>

#include "support/group_traits.hpp"
#include "support/reference.hpp"
#include "support/scalar_types.hpp"

namespace {

using namespace chasles_test;
using chasles::Chain;
using chasles::ChainCheck;
using chasles::SE3;

using V3L = Eigen::Matrix<LD, 3, 1>;
using V6L = Eigen::Matrix<LD, 6, 1>;
using M4L = Eigen::Matrix<LD, 4, 4>;
using M6L = Eigen::Matrix<LD, 6, 6>;
using ScrewsL = Eigen::Matrix<LD, 6, Eigen::Dynamic>;
using VecL = Eigen::Matrix<LD, Eigen::Dynamic, 1>;

constexpr LD kExp = 16;
LD k_chain(Eigen::Index n) { return 2 * LD(n) * kExp; }

// ---- the long double reference ----------------------------------------------

/// exp([S_1] th_1) ... exp([S_n] th_n) M by MatrixFunctions in long double.
M4L fk_ref(const ScrewsL& S, const M4L& M, const VecL& theta) {
  M4L g = M4L::Identity();
  for (Eigen::Index i = 0; i < S.cols(); ++i) g = g * chasles_ref::exp6(V6L(S.col(i) * theta(i)));
  return g * M;
}

V6L vee(const M4L& X) {
  V6L xi;
  xi << X(0, 3), X(1, 3), X(2, 3), X(2, 1), X(0, 2), X(1, 0);
  return xi;
}

M4L inverse(const M4L& g) {
  M4L h = M4L::Identity();
  h.topLeftCorner<3, 3>() = g.topLeftCorner<3, 3>().transpose();
  h.topRightCorner<3, 1>() = -(g.topLeftCorner<3, 3>().transpose() * g.topRightCorner<3, 1>());
  return h;
}

/// dg/dth_i by the five-point central difference in long double, step
/// h = 1e-3: truncation h^4/30 |g^(5)| <= 1e-13 for the arms here (screws of
/// norm <= 1.5), rounding ~ eps_LD / h = 1e-16.
M4L fk_derivative(const ScrewsL& S, const M4L& M, const VecL& theta, Eigen::Index i) {
  const LD h = 1e-3L;
  auto at = [&](LD d) {
    VecL t = theta;
    t(i) += d;
    return fk_ref(S, M, t);
  };
  return (-at(2 * h) + 8 * at(h) - 8 * at(-h) + at(-2 * h)) / (12 * h);
}
constexpr LD kDifferenceError = 1e-12L;  // the bound above with a margin of 10

// ---- the arms -----------------------------------------------------------------

struct Arm {
  ScrewsL S;  // (v, w) columns
  M4L M;
};

/// Planar nR arm in the xy plane: joint i about z through (l_1 + ... + l_{i-1}, 0, 0),
/// tool at (l_1 + ... + l_n, 0, 0).
Arm planar(const std::vector<LD>& l) {
  Arm a{ScrewsL(6, Eigen::Index(l.size())), M4L::Identity()};
  LD x = 0;
  for (std::size_t i = 0; i < l.size(); ++i) {
    a.S.col(Eigen::Index(i)) << 0, -x, 0, 0, 0, 1;  // -z x (x, 0, 0) = (0, -x, 0)
    x += l[i];
  }
  a.M(0, 3) = x;
  return a;
}

// UR5, Modern Robotics example 4.5 (metres).
constexpr LD W1 = 0.109L, W2 = 0.082L, L1 = 0.425L, L2 = 0.392L, H1 = 0.089L, H2 = 0.095L;

Arm ur5() {
  Arm a{ScrewsL(6, 6), M4L::Identity()};
  // Published as (w, v); stored as (v, w).
  a.S.col(0) << 0, 0, 0, 0, 0, 1;
  a.S.col(1) << -H1, 0, 0, 0, 1, 0;
  a.S.col(2) << -H1, 0, L1, 0, 1, 0;
  a.S.col(3) << -H1, 0, L1 + L2, 0, 1, 0;
  a.S.col(4) << -W1, L1 + L2, 0, 0, 0, -1;
  a.S.col(5) << H2 - H1, 0, L1 + L2, 0, 1, 0;
  a.M << -1, 0, 0, L1 + L2,  //
      0, 0, 1, W1 + W2,      //
      0, 1, 0, H1 - H2,      //
      0, 0, 0, 1;
  return a;
}

/// The UR5 on a linear rail along (1, 2, 0) / sqrt(5): a prismatic joint first.
Arm ur5_on_rail() {
  const Arm u = ur5();
  Arm a{ScrewsL(6, 7), u.M};
  a.S.col(0) << 1 / std::sqrt(5.0L), 2 / std::sqrt(5.0L), 0, 0, 0, 0;
  a.S.rightCols(6) = u.S;
  return a;
}

// ---- the chains under test ----------------------------------------------------

/// The arm in the library's scalar, and back in long double after rounding.
template <typename C>
C make_chain(Arm& a) {
  using S = typename C::Scalar;
  typename C::Screws S_(6, a.S.cols());
  S_ = a.S.template cast<S>();
  const Eigen::Matrix<S, 4, 4> M = a.M.template cast<S>();
  a.S = S_.template cast<LD>();
  a.M = M.template cast<LD>();
  return C(S_, SE3<S>::from_matrix_unchecked(M));
}

template <typename S>
std::vector<VecL> thetas(Eigen::Index n, int count = 24) {
  std::mt19937 rng(20260501u + std::uint32_t(n));
  std::uniform_real_distribution<double> u(-3.3, 3.3);
  std::vector<VecL> out;
  out.push_back(VecL::Zero(n));
  for (int k = 0; k < count; ++k) {
    VecL t(n);
    for (Eigen::Index i = 0; i < n; ++i) t(i) = LD(S(u(rng)));  // representable in S
    out.push_back(t);
  }
  return out;
}

template <typename C>
typename C::JointVector joint_vector(const VecL& t) {
  typename C::JointVector v(t.size());
  for (Eigen::Index i = 0; i < t.size(); ++i) v(i) = typename C::Scalar(t(i));
  return v;
}

/// Every property for one chain type and one arm.
template <typename C>
void check_chain(Arm arm) {
  using S = typename C::Scalar;
  const C chain = make_chain<C>(arm);
  const Eigen::Index n = arm.S.cols();
  ASSERT_EQ(chain.n_joints(), n);
  const LD k = k_chain(n);
  EXPECT_TRUE(near<S>(chain.space_screws(), arm.S, 0));
  EXPECT_TRUE(near<S>(chain.home().matrix(), arm.M, 0));
  // B_i = Ad_{M^-1} S_i.
  const M4L M_inv = inverse(arm.M);
  for (Eigen::Index i = 0; i < n; ++i) {
    const V6L Bi = vee(M_inv * chasles_ref::hat6(V6L(arm.S.col(i))) * arm.M);
    EXPECT_TRUE(near<S>(chain.body_screws().col(i), Bi, 4)) << "body screw " << i;
  }
  for (const VecL& t : thetas<S>(n)) {
    const typename C::JointVector th = joint_vector<C>(t);
    const M4L g = fk_ref(arm.S, arm.M, t);
    const SE3<S> gs = chain.forward(th), gb = chain.forward_body(th);
    EXPECT_TRUE(near<S>(gs.matrix(), g, k)) << "forward, theta = " << t.transpose();
    EXPECT_TRUE(near<S>(gb.matrix(), g, k)) << "forward_body, theta = " << t.transpose();

    const typename C::Jacobian Js = chain.jacobian_space(th), Jb = chain.jacobian_body(th);
    ASSERT_EQ(Js.cols(), n);
    ASSERT_EQ(Jb.cols(), n);
    const M4L g_inv = inverse(g);
    for (Eigen::Index i = 0; i < n; ++i) {
      const M4L dg = fk_derivative(arm.S, arm.M, t, i);
      const V6L js = vee(dg * g_inv), jb = vee(g_inv * dg);
      const LD scale = std::max({LD(1), max_abs(js), max_abs(jb)});
      const LD tol = k * eps<S>() * scale + kDifferenceError;
      EXPECT_LE(max_abs_diff(Js.col(i), js), tol) << "space column " << i << ", theta = " << t.transpose();
      EXPECT_LE(max_abs_diff(Jb.col(i), jb), tol) << "body column " << i << ", theta = " << t.transpose();
    }
    // J_s = Ad_g J_b, with the adjoint of the library's own g.
    const Eigen::Matrix<S, 6, 6> Ad = gs.adjoint();
    for (Eigen::Index i = 0; i < n; ++i)
      EXPECT_TRUE(near<S>(Js.col(i), Eigen::Matrix<S, 6, 1>(Ad * Jb.col(i)), k)) << "J_s = Ad_g J_b, column " << i;
  }
}

template <typename S>
class Kinematics : public ::testing::Test {};

TYPED_TEST_SUITE(Kinematics, ScalarTypes, ScalarName);

// ---- screws of joints -----------------------------------------------------------

TYPED_TEST(Kinematics, RevoluteAndPrismaticScrews) {
  using S = TypeParam;
  using C = Chain<S, 6>;
  using V3 = typename C::Vector3;
  const Arm u = ur5();
  // UR5 joints: axes and points on them, as drawn in Modern Robotics fig. 4.11.
  const V3 z(0, 0, 1), y(0, 1, 0);
  const V3 q1(0, 0, 0), q2(0, 0, S(H1)), q3(S(L1), 0, S(H1)), q4(S(L1 + L2), 0, S(H1));
  const V3 q5(S(L1 + L2), S(W1), 0), q6(S(L1 + L2), 0, S(H1 - H2));
  const typename C::Vector6 s[6] = {C::revolute_screw(q1, z),      C::revolute_screw(q2, S(3) * y),
                                    C::revolute_screw(q3, y),      C::revolute_screw(q4, y),
                                    C::revolute_screw(q5, V3(-z)), C::revolute_screw(q6, y)};
  for (int i = 0; i < 6; ++i) EXPECT_TRUE(near<S>(s[i], V6L(u.S.col(i)), 4)) << "joint " << i + 1;
  const typename C::Vector6 p = C::prismatic_screw(V3(0, S(3), S(4)));
  EXPECT_TRUE(near<S>(p, V6L((V6L() << 0, 0.6L, 0.8L, 0, 0, 0).finished()), 4));
}

// ---- closed form: planar arms ---------------------------------------------------

TYPED_TEST(Kinematics, Planar2RClosedForm) {
  using S = TypeParam;
  Arm arm = planar({1.5L, 0.75L});
  const Chain<S, 2> chain = make_chain<Chain<S, 2>>(arm);
  for (const VecL& t : thetas<S>(2)) {
    const LD l1 = arm.S(1, 1) * -1, l2 = arm.M(0, 3) - l1;
    const LD a = t(0), b = t(0) + t(1);
    M4L g = M4L::Identity();
    g.topLeftCorner<2, 2>() << std::cos(b), -std::sin(b), std::sin(b), std::cos(b);
    g(0, 3) = l1 * std::cos(a) + l2 * std::cos(b);
    g(1, 3) = l1 * std::sin(a) + l2 * std::sin(b);
    const Eigen::Matrix<S, 2, 1> th(S(t(0)), S(t(1)));
    EXPECT_TRUE(near<S>(chain.forward(th).matrix(), g, k_chain(2))) << t.transpose();
    EXPECT_TRUE(near<S>(chain.forward_body(th).matrix(), g, k_chain(2))) << t.transpose();
  }
}

TYPED_TEST(Kinematics, Planar3RClosedFormAndChecks) {
  using S = TypeParam;
  Arm arm = planar({1.0L, 0.5L, 0.25L});
  const Chain<S, 3> chain = make_chain<Chain<S, 3>>(arm);
  for (const VecL& t : thetas<S>(3)) {
    const LD l1 = 1.0L, l2 = 0.5L, l3 = 0.25L;  // exact in float and double
    const LD a = t(0), b = a + t(1), c = b + t(2);
    M4L g = M4L::Identity();
    g.topLeftCorner<2, 2>() << std::cos(c), -std::sin(c), std::sin(c), std::cos(c);
    g(0, 3) = l1 * std::cos(a) + l2 * std::cos(b) + l3 * std::cos(c);
    g(1, 3) = l1 * std::sin(a) + l2 * std::sin(b) + l3 * std::sin(c);
    const Eigen::Matrix<S, 3, 1> th(S(t(0)), S(t(1)), S(t(2)));
    EXPECT_TRUE(near<S>(chain.forward(th).matrix(), g, k_chain(3))) << t.transpose();
    // Planar Jacobian in closed form: the tool point's velocity and the rate of c.
    const typename Chain<S, 3>::Jacobian Js = chain.jacobian_space(th);
    // Body Jacobian column i: velocity of the tool origin in the tool frame
    // from joint i, R(c)^T z x (p - q_i), and wz = 1.
    const LD px = g(0, 3), py = g(1, 3);
    const LD qx[3] = {0, l1 * std::cos(a), l1 * std::cos(a) + l2 * std::cos(b)};
    const LD qy[3] = {0, l1 * std::sin(a), l1 * std::sin(a) + l2 * std::sin(b)};
    const typename Chain<S, 3>::Jacobian Jb = chain.jacobian_body(th);
    for (int i = 0; i < 3; ++i) {
      const LD vx = -(py - qy[i]), vy = px - qx[i];  // z x (p - q_i)
      const LD bx = std::cos(c) * vx + std::sin(c) * vy, by = -std::sin(c) * vx + std::cos(c) * vy;
      V6L jb;
      jb << bx, by, 0, 0, 0, 1;
      EXPECT_TRUE(near<S>(Jb.col(i), jb, k_chain(3))) << "body column " << i << ", theta = " << t.transpose();
      // Spatial column i: -z x q_i, z.
      V6L js;
      js << qy[i], -qx[i], 0, 0, 0, 1;
      EXPECT_TRUE(near<S>(Js.col(i), js, k_chain(3))) << "space column " << i << ", theta = " << t.transpose();
    }
  }
}

// ---- UR5 and UR5 on a rail: fixed and dynamic chains --------------------------

TYPED_TEST(Kinematics, UR5Fixed) { check_chain<Chain<TypeParam, 6>>(ur5()); }
TYPED_TEST(Kinematics, UR5DynamicMax8) { check_chain<Chain<TypeParam, Eigen::Dynamic, 8>>(ur5()); }
TYPED_TEST(Kinematics, UR5OnRailFixed) { check_chain<Chain<TypeParam, 7>>(ur5_on_rail()); }
TYPED_TEST(Kinematics, UR5OnRailDynamicMax8) { check_chain<Chain<TypeParam, Eigen::Dynamic, 8>>(ur5_on_rail()); }

TYPED_TEST(Kinematics, UR5HomeAndPublishedPose) {
  using S = TypeParam;
  Arm arm = ur5();
  const Chain<S, 6> chain = make_chain<Chain<S, 6>>(arm);
  EXPECT_TRUE(near<S>(chain.forward(Eigen::Matrix<S, 6, 1>::Zero()).matrix(), arm.M, 0));
  // Modern Robotics example 4.5: theta = (0, -pi/2, 0, 0, pi/2, 0) gives
  // T = [[0, -1, 0, 0.095], [1, 0, 0, 0.109], [0, 0, 1, 0.988], [0, 0, 0, 1]].
  const S h = S(chasles_ref::kPi / 2);
  Eigen::Matrix<S, 6, 1> th;
  th << 0, -h, 0, 0, h, 0;
  M4L T;
  T << 0, -1, 0, 0.095L, 1, 0, 0, 0.109L, 0, 0, 1, 0.988L, 0, 0, 0, 1;
  // Exact sums of the link lengths; pi/2 rounded to S moves the tool by
  // about eps times a lever arm below 1, inside the chain's bound.
  EXPECT_TRUE(near<S>(chain.forward(th).matrix(), T, k_chain(6)));
}

// Dynamic chains of different lengths share one type and never allocate in
// between: a 2-joint and a 7-joint chain of Chain<S, Dynamic, 8>.
TYPED_TEST(Kinematics, DynamicLengths) {
  using S = TypeParam;
  using C = Chain<S, Eigen::Dynamic, 8>;
  Arm a2 = planar({1.5L, 0.75L});
  const C c2 = make_chain<C>(a2);
  EXPECT_EQ(c2.n_joints(), 2);
  const typename C::JointVector th = joint_vector<C>((VecL(2) << 0.3L, -1.1L).finished());
  EXPECT_EQ(c2.jacobian_space(th).cols(), 2);
  EXPECT_TRUE(c2.forward(th).is_approx(c2.forward_body(th), static_cast<S>(k_chain(2) * eps<S>())));
}

// ---- a chain composed of URDF-style joint transforms: large angles -------------

/// A Panda-like arm as a URDF gives it: joint i's frame is the product of the
/// joint origins (xyz, then rotations from rpy) up to it, its axis z in that
/// frame; the tool 0.107 m along the last z. Composed in S, the axes are unit
/// and the home rotation orthogonal only up to a few eps (defect ~7e-16 in
/// double), as for every real URDF.
template <typename S>
Arm urdf_style_arm() {
  struct Origin {
    LD x, y, z, roll, pitch, yaw;
  };
  const LD h = chasles_ref::kPi / 2;
  const Origin o[7] = {
      {0, 0, 0.333L, 0, 0, 0},         {0, 0, 0, -h, 0, 0}, {0, -0.316L, 0, h, 0, 0},     {0.0825L, 0, 0, h, 0, 0},
      {-0.0825L, 0.384L, 0, -h, 0, 0}, {0, 0, 0, h, 0, 0},  {0.088L, 0, 0, h, 0.3L, 0.7L}};
  using M4 = Eigen::Matrix<S, 4, 4>;
  using M3 = Eigen::Matrix<S, 3, 3>;
  using V3 = Eigen::Matrix<S, 3, 1>;
  auto rot = [](int axis, S a) {  // exact-in-S rotation matrices about x, y, z
    M3 R = M3::Identity();
    const S c = std::cos(a), s = std::sin(a);
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    R(i, i) = c, R(i, j) = -s, R(j, i) = s, R(j, j) = c;
    return R;
  };
  M4 T = M4::Identity();
  Arm a{ScrewsL(6, 7), M4L::Identity()};
  for (int i = 0; i < 7; ++i) {
    M4 O = M4::Identity();
    O.template topLeftCorner<3, 3>() = rot(2, S(o[i].yaw)) * rot(1, S(o[i].pitch)) * rot(0, S(o[i].roll));
    O.template topRightCorner<3, 1>() << S(o[i].x), S(o[i].y), S(o[i].z);
    T = M4(T * O);
    const V3 w = T.template topLeftCorner<3, 3>().col(2), q = T.template topRightCorner<3, 1>();
    a.S.col(i) << (-w.cross(q)).template cast<LD>(), w.template cast<LD>();
  }
  M4 F = M4::Identity();
  F(2, 3) = S(0.107L);
  a.M = M4(T * F).template cast<LD>();
  return a;
}

/// The long double reference for large angles: exp of each S_i th_i formed
/// in long double, with the cos and sin of long double (the angles are
/// exact in S).
TYPED_TEST(Kinematics, LargeAnglesBodyAgreesWithSpace) {
  using S = TypeParam;
  using C = Chain<S, 7>;
  Arm arm = urdf_style_arm<S>();
  const Eigen::Matrix<S, 4, 4> M = arm.M.template cast<S>();
  // the home pose's defect, as composed: a few eps, not zero
  EXPECT_GT(SE3<S>::transform_defect(M), S(0));
  const C chain(typename C::Screws(arm.S.template cast<S>()), SE3<S>::from_matrix_unchecked(M));
  // projected on construction: orthogonal to rounding
  EXPECT_LE(SE3<S>::transform_defect(chain.home().matrix()), 2 * eps<S>());
  std::mt19937 rng(20261124u);
  for (const LD range : {3.3L, 50.0L, 1000.0L}) {
    std::uniform_real_distribution<double> u(-double(range), double(range));
    LD worst_space = 0, worst_body = 0;
    for (int k = 0; k < 400; ++k) {
      typename C::JointVector th;
      VecL t(7);
      for (int i = 0; i < 7; ++i) th(i) = S(u(rng)), t(i) = LD(th(i));
      const M4L ref = fk_ref(arm.S, chain.home().matrix().template cast<LD>(), t);
      worst_space = std::max(worst_space, (chain.forward(th).matrix().template cast<LD>() - ref).cwiseAbs().maxCoeff());
      worst_body =
          std::max(worst_body, (chain.forward_body(th).matrix().template cast<LD>() - ref).cwiseAbs().maxCoeff());
    }
    // The floor of both forms is the rounding of S_i th_i, an angle error
    // of eps |th| per joint, over a few eps of composition at small angles.
    // Measured here, in units of eps (1 + range) for ranges 3.3, 50, 1000:
    // double space 1.1, 0.7, 0.6, body 1.6, 1.2, 0.9; float space 1.6,
    // 0.6, 0.5, body 2.0, 1.3, 1.1. Before the body screws' invariants were
    // restored and the home projected, the body form was 3.8 to 5.2 eps
    // (1 + range) on a 6-joint arm of this kind, 4.6 to 5.2 times the space
    // form at ranges 50 and 1000.
    const LD bound = LD(eps<S>()) * (16 + 2 * range);
    EXPECT_LE(worst_space, bound) << "space, |theta| <= " << double(range);
    EXPECT_LE(worst_body, bound) << "body, |theta| <= " << double(range);
    EXPECT_LE(worst_body, 3 * std::max(worst_space, LD(8 * eps<S>())))
        << "body against space, |theta| <= " << double(range);
  }
}

// ---- the robot model: types, limits, base, tool, gravity, validation ----------

TYPED_TEST(Kinematics, HomeProjectionKeepsExactRotations) {
  using S = TypeParam;
  Arm arm = ur5();
  const Chain<S, 6> chain = make_chain<Chain<S, 6>>(arm);
  EXPECT_TRUE(chain.home().matrix() == arm.M.template cast<S>()) << "an exact rotation is kept bit for bit";
  // A home rotation off by 1e-9 (inside from_matrix's tolerance): projected.
  Eigen::Matrix<S, 4, 4> M = arm.M.template cast<S>();
  M(0, 0) *= S(1) + S(std::sqrt(double(eps<S>())) / 4);
  const Chain<S, 6> off(typename Chain<S, 6>::Screws(arm.S.template cast<S>()), SE3<S>::from_matrix_unchecked(M));
  EXPECT_GT(SE3<S>::transform_defect(M), 10 * eps<S>());
  EXPECT_LE(SE3<S>::transform_defect(off.home().matrix()), 2 * eps<S>());
  // Another chain's home taken as it is: the same chain, bit for bit.
  const Chain<S, 6> again(off.space_screws(), off.home(), typename Chain<S, 6>::HomeAsGiven());
  EXPECT_TRUE(again.home().matrix() == off.home().matrix());
  EXPECT_TRUE(again.body_screws() == off.body_screws());
}

TYPED_TEST(Kinematics, ModelFoldsBaseAndTool) {
  using S = TypeParam;
  using C = Chain<S, Eigen::Dynamic, 8>;
  using V3 = typename C::Vector3;
  Arm arm = ur5_on_rail();
  const C plain = make_chain<C>(arm);
  EXPECT_EQ(plain.joint_type(0), chasles::JointType::prismatic);
  for (int i = 1; i < 7; ++i) EXPECT_EQ(plain.joint_type(i), chasles::JointType::revolute);
  EXPECT_TRUE(plain.lower().array().isInf().all() && plain.upper().array().isInf().all());
  EXPECT_TRUE((plain.lower().array() < 0).all() && (plain.upper().array() > 0).all());
  EXPECT_TRUE(plain.gravity() == V3(0, 0, S(-9.81)));
  EXPECT_TRUE(static_cast<bool>(plain.validate()));

  typename C::JointTypes types{};
  types.fill(chasles::JointType::revolute);
  types[0] = chasles::JointType::prismatic;
  types[6] = chasles::JointType::continuous;
  typename C::JointVector lo(7), hi(7), vel(7), eff(7);
  const S inf = std::numeric_limits<S>::infinity();
  for (int i = 0; i < 7; ++i) lo(i) = S(-1 - i), hi(i) = S(1 + i), vel(i) = S(2), eff(i) = S(100 + i);
  lo(6) = -inf, hi(6) = inf;
  const SE3<S> base = SE3<S>::exp(Eigen::Matrix<S, 6, 1>(S(0.5), S(-0.2), S(1), S(0.3), S(-0.1), S(0.7)));
  const SE3<S> tool = SE3<S>::exp(Eigen::Matrix<S, 6, 1>(S(0), S(0), S(0.1), S(0), S(0.4), S(0)));
  const V3 gravity(S(0.1), S(0), S(-9.8));
  const C model(plain.space_screws(), plain.home(), types, lo, hi, vel, eff, base, tool, gravity);
  EXPECT_TRUE(static_cast<bool>(model.validate()));
  EXPECT_EQ(model.joint_type(6), chasles::JointType::continuous);
  EXPECT_TRUE(model.lower() == lo && model.upper() == hi && model.velocity_limits() == vel &&
              model.effort_limits() == eff);
  EXPECT_TRUE(model.gravity() == gravity);
  EXPECT_TRUE(model.base().is_approx(base, 4 * eps<S>()));
  EXPECT_TRUE(model.tool().is_approx(tool, 4 * eps<S>()));
  // forward(theta) = base forward0(theta) tool, Jacobians likewise
  for (const VecL& t : thetas<S>(7)) {
    const typename C::JointVector th = joint_vector<C>(t);
    const SE3<S> expected = base * plain.forward(th) * tool;
    const LD k = k_chain(7) + 3 * kExp;
    EXPECT_TRUE(near<S>(model.forward(th).matrix(), expected.matrix().template cast<LD>(), k));
    EXPECT_TRUE(near<S>(model.forward_body(th).matrix(), expected.matrix().template cast<LD>(), k));
    const Eigen::Matrix<S, 6, 6> Ad = base.adjoint();
    EXPECT_TRUE(near<S>(model.jacobian_space(th), typename C::Jacobian(Ad * plain.jacobian_space(th)), k));
    const Eigen::Matrix<S, 6, 6> Ad_tool_inv = tool.inverse().adjoint();
    EXPECT_TRUE(near<S>(model.jacobian_body(th), typename C::Jacobian(Ad_tool_inv * plain.jacobian_body(th)), k));
  }
}

TYPED_TEST(Kinematics, ValidateBothSidesOfTheTolerance) {
  using S = TypeParam;
  using C = Chain<S, 2>;
  using chasles::ChainStatus;
  using chasles::JointType;
  const S tol = S(chasles::ThresholdsOf<S>::screw_tolerance);
  const S inf = std::numeric_limits<S>::infinity();
  // (gravity has no default argument: clang 14 crashes on C::default_gravity() as one inside a lambda)
  const typename C::Vector3 earth = C::default_gravity();
  auto check = [&](const typename C::Vector6& s0, JointType type, S lo = -1, S hi = 1, S vel = 1, S eff = 1,
                   const typename C::Vector3* gravity = nullptr) {
    typename C::Screws screws;
    screws.col(0) = s0;
    screws.col(1) = C::revolute_screw(typename C::Vector3(1, 0, 0), typename C::Vector3(0, 0, 1));
    typename C::JointTypes types{type, JointType::revolute};
    const typename C::JointVector lower(lo, -1), upper(hi, 1), v(vel, 1), e(eff, 1);
    return C(screws, SE3<S>(), types, lower, upper, v, e, SE3<S>(), SE3<S>(), gravity ? *gravity : earth).validate();
  };
  using V6 = typename C::Vector6;
  const ChainCheck ok = check(V6(0, 0, 0, 0, 0, 1), JointType::revolute);
  EXPECT_EQ(ok.status, ChainStatus::ok);
  EXPECT_EQ(ok.joint, -1);
  // |w| = 1 +- 0.5 tol passes, 1 +- 2 tol fails
  for (const S f : {S(0.5), S(-0.5)})
    EXPECT_EQ(check(V6(0, 0, 0, 0, 0, 1 + f * tol), JointType::revolute).status, ChainStatus::ok);
  for (const S f : {S(2), S(-2)}) {
    const ChainCheck c = check(V6(0, 0, 0, 0, 0, 1 + f * tol), JointType::continuous, -inf, inf);
    EXPECT_EQ(c.status, ChainStatus::revolute_axis_not_unit);
    EXPECT_EQ(c.joint, 0);
  }
  // pitch: w . v = 0.5 tol (1 + |v|) passes, 2 tol (1 + |v|) fails
  EXPECT_EQ(check(V6(1, 0, S(0.5) * tol * S(1 + 1), 0, 0, 1), JointType::revolute).status, ChainStatus::ok);
  EXPECT_EQ(check(V6(1, 0, 4 * tol, 0, 0, 1), JointType::revolute).status, ChainStatus::revolute_pitch_not_zero);
  // prismatic: |v| = 1 and w = 0
  EXPECT_EQ(check(V6(0, S(0.6), S(0.8), 0, 0, 0), JointType::prismatic).status, ChainStatus::ok);
  EXPECT_EQ(check(V6(0, S(0.6), S(0.8), 0, S(0.5) * tol, 0), JointType::prismatic).status, ChainStatus::ok);
  EXPECT_EQ(check(V6(0, S(0.6), S(0.8), 0, 2 * tol, 0), JointType::prismatic).status, ChainStatus::prismatic_rotates);
  EXPECT_EQ(check(V6(0, 0, 1 + 2 * tol, 0, 0, 0), JointType::prismatic).status, ChainStatus::prismatic_axis_not_unit);
  EXPECT_EQ(check(V6(0, 0, 0, 0, 0, 1), JointType::prismatic).status, ChainStatus::prismatic_rotates);
  EXPECT_EQ(check(V6(0, 0, 1, 0, 0, 0), JointType::revolute).status, ChainStatus::revolute_axis_not_unit);
  // helical: |w| = 1 and any pitch; inferred where the pitch is not zero
  EXPECT_EQ(check(V6(1, 0, S(0.3), 0, 0, 1), JointType::helical).status, ChainStatus::ok);
  EXPECT_EQ(check(V6(1, 0, 0, 0, 0, 1), JointType::helical).status, ChainStatus::ok);  // pitch 0: a revolute
  EXPECT_EQ(check(V6(0, 0, S(0.3), 0, 0, 1 + 2 * tol), JointType::helical).status, ChainStatus::revolute_axis_not_unit);
  {
    typename C::Screws screws;
    screws.col(0) = V6(1, 0, S(0.3), 0, 0, 1);  // pitch 0.3
    screws.col(1) = V6(1, 0, S(0.5) * tol * S(1 + 1), 0, 0, 1);  // pitch within the tolerance: revolute
    const C inferred(screws, SE3<S>());
    EXPECT_EQ(inferred.joint_type(0), JointType::helical);
    EXPECT_EQ(inferred.joint_type(1), JointType::revolute);
  }
  // ScrewNorms::any: any nonzero norm, the pitch test relative to it; zero or not finite refused
  {
    auto any = [&](const V6& s0, JointType type) {
      typename C::Screws screws;
      screws.col(0) = s0;
      screws.col(1) = V6(0, 0, 0, 0, 0, 1);
      typename C::JointTypes types{type, JointType::revolute};
      const typename C::JointVector lower(-1, -1), upper(1, 1);
      return C(screws, SE3<S>(), types, lower, upper, upper, upper).validate(chasles::ScrewNorms::any);
    };
    EXPECT_EQ(any(V6(0, 1, 0, 1, 0, 1), JointType::revolute).status, ChainStatus::ok);  // |w| = sqrt(2)
    EXPECT_EQ(any(V6(0, 0, 3, 0, 0, 0), JointType::prismatic).status, ChainStatus::ok);
    EXPECT_EQ(any(V6(3, 0, 0, 0, 0, 3), JointType::revolute).status, ChainStatus::ok);   // w . v = 0
    EXPECT_EQ(any(V6(0, 0, 3, 0, 0, 3), JointType::revolute).status, ChainStatus::revolute_pitch_not_zero);
    EXPECT_EQ(any(V6(0, 0, 3, 0, 0, 3), JointType::helical).status, ChainStatus::ok);
    EXPECT_EQ(any(V6(0, 0, 3, 0, 3, 0), JointType::prismatic).status, ChainStatus::prismatic_rotates);
    EXPECT_EQ(any(V6(0, 0, 0, 0, 0, 0), JointType::revolute).status, ChainStatus::screw_zero);
    EXPECT_EQ(any(V6(0, 0, 0, 0, 0, 0), JointType::prismatic).status, ChainStatus::screw_zero);
    EXPECT_EQ(any(V6(0, 0, 0, 0, 0, inf), JointType::revolute).status, ChainStatus::screw_zero);
    EXPECT_EQ(any(V6(0, 0, 0, 0, 0, 1), JointType::revolute).joint, -1);
  }
  // limits
  const V6 z(0, 0, 0, 0, 0, 1);
  EXPECT_EQ(check(z, JointType::revolute, 1, 1).status, ChainStatus::ok);
  EXPECT_EQ(check(z, JointType::revolute, 1, S(0.5)).status, ChainStatus::position_limits_invalid);
  EXPECT_EQ(check(z, JointType::revolute, std::numeric_limits<S>::quiet_NaN(), 1).status,
            ChainStatus::position_limits_invalid);
  EXPECT_EQ(check(z, JointType::continuous, -inf, inf).status, ChainStatus::ok);
  EXPECT_EQ(check(z, JointType::continuous, -1, 1).status, ChainStatus::position_limits_invalid);
  EXPECT_EQ(check(z, JointType::revolute, -1, 1, 0, 0).status, ChainStatus::ok);
  EXPECT_EQ(check(z, JointType::revolute, -1, 1, inf, inf).status, ChainStatus::ok);
  EXPECT_EQ(check(z, JointType::revolute, -1, 1, -1, 1).status, ChainStatus::velocity_or_effort_limit_invalid);
  EXPECT_EQ(check(z, JointType::revolute, -1, 1, 1, -1).status, ChainStatus::velocity_or_effort_limit_invalid);
  const typename C::Vector3 infinite_gravity(0, 0, inf);
  const ChainCheck g = check(z, JointType::revolute, -1, 1, 1, 1, &infinite_gravity);
  EXPECT_EQ(g.status, ChainStatus::gravity_not_finite);
  EXPECT_EQ(g.joint, -1);
  // the second joint is checked too, and named
  typename C::Screws screws;
  screws.col(0) << 0, 0, 0, 0, 0, 1;
  screws.col(1) << 0, 0, 0, 0, 0, 2;
  const ChainCheck second = C(screws, SE3<S>()).validate();
  EXPECT_EQ(second.status, ChainStatus::revolute_axis_not_unit);
  EXPECT_EQ(second.joint, 1);
}

TYPED_TEST(Kinematics, LinkInertiasDefaultToMasslessAndMoveWithTheBase) {
  using S = TypeParam;
  using C = Chain<S, Eigen::Dynamic, 8>;
  using I = typename C::Inertia;
  Arm arm = ur5_on_rail();
  const C plain = make_chain<C>(arm);
  // default: every entry (the first n and the unused ones) is SpatialInertia(), zero
  for (const I& G : plain.link_inertias()) {
    EXPECT_EQ(G.mass(), S(0));
    EXPECT_TRUE(G.com().isZero(0) && G.inertia().isZero(0));
  }
  typename C::Inertias given{};
  for (std::size_t i = 0; i < 7; ++i) {
    typename C::Vector3 moments(S(0.1) + S(0.01) * S(i), S(0.2), S(0.25));
    given[i] =
        I(S(1) + S(i), typename C::Vector3(S(0.1) * S(i), S(-0.2), S(0.3)), typename I::Matrix3(moments.asDiagonal()));
  }
  const SE3<S> base = SE3<S>::exp(Eigen::Matrix<S, 6, 1>(S(0.5), S(-0.2), S(1), S(0.3), S(-0.1), S(0.7)));
  const typename C::JointVector inf = C::JointVector::Constant(7, std::numeric_limits<S>::infinity());
  const C model(plain.space_screws(), plain.home(), plain.joint_types(), -inf, inf, inf, inf, base, SE3<S>(),
                C::default_gravity(), given);
  EXPECT_TRUE(static_cast<bool>(model.validate()));
  // moved by the base frame exactly as SpatialInertia::transform(base) moves them (the base as stored)
  for (std::size_t i = 0; i < 7; ++i) {
    const I expected = given[i].transform(model.base());
    EXPECT_EQ(model.link_inertias()[i].mass(), expected.mass());
    EXPECT_TRUE(model.link_inertias()[i].com() == expected.com());
    EXPECT_TRUE(model.link_inertias()[i].inertia() == expected.inertia());
  }
  EXPECT_EQ(model.link_inertias()[7].mass(), S(0));  // unused entries stay zero
  // and with an identity base, as given
  const C unbased(plain.space_screws(), plain.home(), plain.joint_types(), -inf, inf, inf, inf, SE3<S>(), SE3<S>(),
                  C::default_gravity(), given);
  for (std::size_t i = 0; i < 7; ++i)
    EXPECT_TRUE(unbased.link_inertias()[i].com() == given[i].com() &&
                unbased.link_inertias()[i].inertia() == given[i].inertia());
}

TYPED_TEST(Kinematics, ValidateLinkInertias) {
  using S = TypeParam;
  using C = Chain<S, 2>;
  using I = typename C::Inertia;
  using chasles::ChainStatus;
  typename C::Screws screws;
  screws.col(0) << 0, 0, 0, 0, 0, 1;
  screws.col(1) << 0, -1, 0, 0, 0, 1;
  const typename C::JointVector inf = C::JointVector::Constant(2, std::numeric_limits<S>::infinity());
  const auto check = [&](const I& second) {
    typename C::Inertias inertias{};
    inertias[0] = I(S(1), typename C::Vector3(S(0.1), 0, 0), I::Matrix3::Identity());
    inertias[1] = second;
    const typename C::Vector3 earth(0, 0, S(-9.81));
    return C(screws, SE3<S>(), typename C::JointTypes{}, -inf, inf, inf, inf, SE3<S>(), SE3<S>(), earth, inertias)
        .validate();
  };
  using V3 = typename C::Vector3;
  using M3 = typename I::Matrix3;
  EXPECT_EQ(check(I()).status, ChainStatus::ok);                             // massless
  EXPECT_EQ(check(I(S(2), V3(1, 2, 3), M3::Zero())).status, ChainStatus::ok);  // a point mass
  const S nan = std::numeric_limits<S>::quiet_NaN(), big = std::numeric_limits<S>::infinity();
  const S tiny = std::numeric_limits<S>::denorm_min();
  EXPECT_EQ(check(I(S(0), V3::Zero(), M3::Zero())).status, ChainStatus::ok);
  const ChainCheck negative = check(I(-tiny, V3::Zero(), M3::Zero()));
  EXPECT_EQ(negative.status, ChainStatus::link_inertia_invalid);
  EXPECT_EQ(negative.joint, 1);
  EXPECT_EQ(check(I(nan, V3::Zero(), M3::Zero())).status, ChainStatus::link_inertia_invalid);
  EXPECT_EQ(check(I(big, V3::Zero(), M3::Zero())).status, ChainStatus::link_inertia_invalid);
  EXPECT_EQ(check(I(S(1), V3(0, nan, 0), M3::Zero())).status, ChainStatus::link_inertia_invalid);
  EXPECT_EQ(check(I(S(1), V3(0, 0, -big), M3::Zero())).status, ChainStatus::link_inertia_invalid);
  M3 bad = M3::Identity();
  bad(2, 1) = big;
  EXPECT_EQ(check(I(S(1), V3::Zero(), bad)).status, ChainStatus::link_inertia_invalid);
  bad(2, 1) = nan;
  EXPECT_EQ(check(I(S(1), V3::Zero(), bad)).status, ChainStatus::link_inertia_invalid);
  // the largest finite numbers are finite
  const S max = std::numeric_limits<S>::max();
  EXPECT_EQ(check(I(max, V3(max, -max, max), M3::Constant(max))).status, ChainStatus::ok);
}

}  // namespace

namespace {

// ---- the time derivatives of the Jacobians ------------------------------------

TEST(JacobianDot, EqualsTheDerivativeAlongTheMotion) {
  // jacobian_space_dot and jacobian_body_dot at (q, qd) against the
  // five-point central difference of the Jacobians along q + t qd, in long
  // double (step 1e-4: truncation h^4/30 |J^(5)| ~ 1e-12 with |J^(5)| ~
  // (sum |qd_i|)^5 <= 14^5, rounding 1e-19 / h), on the railed UR5 and on it with
  // two joints made helical (pitches 0.2 and -0.5 m/rad).
  using C = Chain<double, Eigen::Dynamic, 8>;
  using CL = Chain<LD, Eigen::Dynamic, 8>;
  Arm arm = ur5_on_rail();
  Arm helical = arm;
  helical.S.col(2).head<3>() += 0.2L * helical.S.col(2).tail<3>();
  helical.S.col(5).head<3>() -= 0.5L * helical.S.col(5).tail<3>();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  for (Arm a : {arm, helical}) {
    const C chain = make_chain<C>(a);
    const CL chain_l(CL::Screws(a.S), SE3<LD>::from_matrix_unchecked(a.M));
    for (int trial = 0; trial < 10; ++trial) {
      C::JointVector q(7), qd(7);
      for (int i = 0; i < 7; ++i) q(i) = u(rng), qd(i) = u(rng);
      const CL::JointVector ql = q.cast<LD>(), qdl = qd.cast<LD>();
      const LD h = 1e-4L;
      auto along = [&](auto jacobian, LD t) { return jacobian(CL::JointVector(ql + t * qdl)); };
      auto five_point = [&](auto jacobian) {
        return Eigen::Matrix<LD, 6, Eigen::Dynamic>(
            (-along(jacobian, 2 * h) + 8 * along(jacobian, h) - 8 * along(jacobian, -h) + along(jacobian, -2 * h)) /
            (12 * h));
      };
      const auto Js = [&](const CL::JointVector& x) { return chain_l.jacobian_space(x); };
      const auto Jb = [&](const CL::JointVector& x) { return chain_l.jacobian_body(x); };
      const LD scale = 10;  // |J_dot| for these arms and velocities
      EXPECT_LE(max_abs_diff(to_ld(chain.jacobian_space_dot(q, qd)), five_point(Js)), 1e-11L * scale) << trial;
      EXPECT_LE(max_abs_diff(to_ld(chain.jacobian_body_dot(q, qd)), five_point(Jb)), 1e-11L * scale) << trial;
    }
  }
}

}  // namespace
