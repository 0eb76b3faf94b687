// Twists and wrenches, typed over float and double: Chasles' theorem (every
// motion is a screw motion), screws of twists and of wrenches (Poinsot),
// spatial and body twists of trajectories against finite differences, frame
// changes against the adjoint matrices, power invariance, the Modern
// Robotics order, the Lie bracket and hat/vee of se(3).
//
// Tolerances are k * eps of the scalar under test times the scale of the
// data (support/group_traits.hpp, `near`):
//   kOp    = 4:  one product of a 3x3 or 6x6 matrix by a vector, or one cross
//              product plus one addition.
//   kChain = 16: a few such operations in a row, exp or log ("a few ulps"),
//              screw parameters (a division by |w|^2 after a cross product).
// Expected values are computed in long double from the inputs, so the error
// measured is the library's.
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/LU>

#include <chasles/chasles.hpp>

#include "support/group_traits.hpp"
#include "support/samples.hpp"
#include "support/scalar_types.hpp"

namespace {

using namespace chasles_test;
using chasles::SE3;
using chasles::SO3;
using chasles::Twist;
using chasles::Wrench;

constexpr LD kOp = 4;
constexpr LD kChain = 16;

template <typename S>
using V3 = Eigen::Matrix<S, 3, 1>;
template <typename S>
using V6 = Eigen::Matrix<S, 6, 1>;
using V3L = Eigen::Matrix<LD, 3, 1>;
using V6L = Eigen::Matrix<LD, 6, 1>;
using M3L = Eigen::Matrix<LD, 3, 3>;
using M4L = Eigen::Matrix<LD, 4, 4>;
using M6L = Eigen::Matrix<LD, 6, 6>;

template <typename Derived>
bool all_equal(const Eigen::MatrixBase<Derived>& a, const Eigen::MatrixBase<Derived>& b) {
  return (a.array() == b.array()).all();
}

template <typename S>
V6<S> stack(const V3<S>& a, const V3<S>& b) {
  return stack6<S>(a, b);
}

/// [w] in long double, written out.
inline M3L skew(const V3L& w) {
  M3L W;
  W << 0, -w[2], w[1], w[2], 0, -w[0], -w[1], w[0], 0;
  return W;
}

/// Rodrigues' formula for a unit axis n, in long double (the seed's boxed
/// formula): I + sin(theta) [n] + (1 - cos(theta)) [n]^2.
inline M3L rodrigues(const V3L& n, LD theta) {
  const M3L N = skew(n);
  return M3L::Identity() + std::sin(theta) * N + (2 * std::sin(theta / 2) * std::sin(theta / 2)) * N * N;
}

/// The twist coordinates of a matrix of se(3), read directly.
inline V6L vee_ld(const M4L& X) {
  V6L xi;
  xi << X(0, 3), X(1, 3), X(2, 3), X(2, 1), X(0, 2), X(1, 0);
  return xi;
}
inline M4L hat_ld(const V6L& xi) {
  M4L X = M4L::Zero();
  X.topLeftCorner<3, 3>() = skew(xi.tail<3>());
  X.topRightCorner<3, 1>() = xi.head<3>();
  return X;
}

template <typename S>
class TwistWrench : public ::testing::Test {
 public:
  std::mt19937_64 rng{kSeed + 101};
  std::normal_distribution<double> n01{0.0, 1.0};
  std::uniform_real_distribution<double> u01{0.0, 1.0};

  V3<S> gauss3(double scale = 1) { return V3<S>(S(scale * n01(rng)), S(scale * n01(rng)), S(scale * n01(rng))); }
  V3<S> unit3() { return random_unit<S>(rng); }
  /// A random motion: rotation angle uniform in [0, pi), translation of size ~scale.
  SE3<S> motion(double scale = 2) { return SE3<S>(SO3<S>::exp(V3<S>(S(3.1 * u01(rng)) * unit3())), gauss3(scale)); }
  Twist<S> twist(double v_scale = 1, double w_scale = 1) { return Twist<S>(gauss3(v_scale), gauss3(w_scale)); }
};

TYPED_TEST_SUITE(TwistWrench, ScalarTypes, ScalarName);

// ---- Chasles' theorem and screws of twists ------------------------------------------

TYPED_TEST(TwistWrench, ChaslesEveryMotionIsAScrewMotion) {
  using S = TypeParam;
  std::vector<SE3<S>> gs = elements<SE3<S>>();
  for (int i = 0; i < 32; ++i) gs.push_back(this->motion());
  for (std::size_t i = 0; i < gs.size(); ++i) {
    const SE3<S>& g = gs[i];
    const LD gscale = GroupTraits<SE3<S>>::scale(g);
    const Twist<S> xi(g.log());
    EXPECT_TRUE(near<S>(SE3<S>::exp(xi).matrix(), g.matrix(), kChain, gscale)) << "sample " << i;
    const chasles::Screw<S> s = xi.screw();
    // The screw of log(g), rebuilt by from_screw, is g.
    const SE3<S> h = SE3<S>::from_screw(s.point, s.direction, s.pitch, s.magnitude);
    const LD qscale = gscale + max_abs(s.point);
    EXPECT_TRUE(near<S>(h.matrix(), g.matrix(), kChain, qscale)) << "sample " << i;
    if (s.magnitude == S(0)) {
      // The identity, or a rotation so small that |w|^2 underflows (w = 1e-30
      // in float): the identity to working precision.
      EXPECT_TRUE(near<S>(g.matrix(), SE3<S>::identity().matrix(), kOp)) << "sample " << i;
      continue;
    }
    // Geometrically, independently of exp: points of the axis slide along
    // it by pitch * magnitude (by magnitude for a translation), and a point
    // off the axis turns about it by Rodrigues' formula.
    const V3L q = to_ld(s.point), d = to_ld(s.direction);
    const bool translation = std::isinf(s.pitch);
    const LD slide = translation ? LD(s.magnitude) : LD(s.pitch) * LD(s.magnitude);
    for (LD lambda : {LD(0), LD(1.5), LD(-3)}) {
      const V3<S> p = (q + lambda * d).template cast<S>();
      EXPECT_TRUE(near<S>(g.act(p), to_ld(p) + slide * d, kChain, qscale + std::fabs(lambda))) << "sample " << i;
    }
    const V3<S> off(S(0.5), S(-1), S(2));
    const V3L expected =
        translation ? V3L(to_ld(off) + slide * d) : V3L(q + rodrigues(d, s.magnitude) * (to_ld(off) - q) + slide * d);
    EXPECT_TRUE(near<S>(g.act(off), expected, kChain, qscale + 2)) << "sample " << i;
  }
}

TYPED_TEST(TwistWrench, PitchAndAxisHandComputed) {
  using S = TypeParam;
  // The screw through q = (1, 2, 0) along z, pitch 1/2, by theta = 2:
  // v = theta (-z x q + h z) = 2 ((2, -1, 0) + (0, 0, 1/2)) = (4, -2, 1),
  // w = (0, 0, 2). Back: pitch w.v / |w|^2 = 2/4, point w x v / |w|^2 =
  // (4, 8, 0) / 4, magnitude 2. Every step is exact in binary floating point.
  const Twist<S> xi = Twist<S>::from_screw(V3<S>(1, 2, 0), V3<S>(0, 0, 1), S(0.5), S(2));
  EXPECT_TRUE(all_equal(xi.vector(), stack<S>(V3<S>(4, -2, 1), V3<S>(0, 0, 2))));
  const auto s = xi.screw();
  EXPECT_EQ(s.pitch, S(0.5));
  EXPECT_EQ(xi.pitch(), S(0.5));
  EXPECT_TRUE(all_equal(s.point, V3<S>(1, 2, 0)));
  EXPECT_TRUE(all_equal(s.direction, V3<S>(0, 0, 1)));
  EXPECT_EQ(s.magnitude, S(2));

  // A rotation about the x axis through the origin: pitch 0, point 0.
  const auto r = Twist<S>(V3<S>(0, 0, 0), V3<S>(3, 0, 0)).screw();
  EXPECT_EQ(r.pitch, S(0));
  EXPECT_TRUE(all_equal(r.point, V3<S>(0, 0, 0)));
  EXPECT_TRUE(all_equal(r.direction, V3<S>(1, 0, 0)));
  EXPECT_EQ(r.magnitude, S(3));

  // v = (1, 0, 0), w = z: the seed's revolute joint with l1 = 1, axis
  // through (0, 1, 0).
  const auto j = Twist<S>(V3<S>(1, 0, 0), V3<S>(0, 0, 1)).screw();
  EXPECT_EQ(j.pitch, S(0));
  EXPECT_TRUE(all_equal(j.point, V3<S>(0, 1, 0)));

  // w = 0: a translation, pitch +inf, direction v / |v|, magnitude |v|.
  const auto t = Twist<S>(V3<S>(0, 3, 4), V3<S>(0, 0, 0)).screw();
  EXPECT_TRUE(std::isinf(t.pitch) && t.pitch > 0);
  EXPECT_TRUE(near<S>(t.direction, V3L(0, 0.6L, 0.8L), kOp));
  EXPECT_EQ(t.magnitude, S(5));
  EXPECT_TRUE(all_equal(t.point, V3<S>(0, 0, 0)));

  // A general case against the formulas, in long double: h = w.v / |w|^2,
  // q = w x v / |w|^2.
  for (int i = 0; i < 64; ++i) {
    const Twist<S> x = this->twist(2, 1);
    const V3L v = to_ld(x.linear()), w = to_ld(x.angular());
    const auto sx = x.screw();
    const LD w2 = w.squaredNorm();
    EXPECT_TRUE(near_scalar<S>(sx.pitch, w.dot(v) / w2, kChain, v.norm() / std::sqrt(w2)));
    EXPECT_TRUE(near<S>(sx.point, V3L(w.cross(v) / w2), kChain, v.norm() / std::sqrt(w2)));
    EXPECT_TRUE(near<S>(sx.direction, V3L(w / std::sqrt(w2)), kOp));
    EXPECT_TRUE(near_scalar<S>(sx.magnitude, std::sqrt(w2), kOp));
  }
}

TYPED_TEST(TwistWrench, ScrewToTwistToScrewRoundTrips) {
  using S = TypeParam;
  const S inf = std::numeric_limits<S>::infinity();
  for (int i = 0; i < 64; ++i) {
    const V3<S> q = this->gauss3(3), d = this->unit3();
    const S theta = S(0.1 + 3 * this->u01(this->rng));
    for (S h : {S(0), S(0.25), S(-1.5)}) {
      // The direction is normalized by from_screw: pass 3 d.
      const Twist<S> xi = Twist<S>::from_screw(q, V3<S>(S(3) * d), h, theta);
      const V3L ql = to_ld(q), dl = to_ld(d);
      // theta * (-d x q + h d, d), in long double.
      const V6L expected = (V6L() << LD(theta) * (-dl.cross(ql) + LD(h) * dl), LD(theta) * dl).finished();
      EXPECT_TRUE(near<S>(xi.vector(), expected, kChain, max_abs(q) * theta));
      const auto s = xi.screw();
      EXPECT_TRUE(near_scalar<S>(s.pitch, h, kChain, max_abs(q)));
      EXPECT_TRUE(near_scalar<S>(s.magnitude, theta, kOp));
      EXPECT_TRUE(near<S>(s.direction, dl, kOp));
      // The point of the line nearest the origin: q - (q.d) d.
      EXPECT_TRUE(near<S>(s.point, V3L(ql - ql.dot(dl) * dl), kChain, max_abs(q)));
      // And back: the same twist.
      EXPECT_TRUE(near<S>(Twist<S>::from_screw(s).vector(), xi.vector(), kChain, max_abs(q) * theta));
      // A negative magnitude is the same screw turned the other way.
      const auto neg = Twist<S>::from_screw(q, d, h, -theta).screw();
      EXPECT_TRUE(near<S>(neg.direction, V3L(-dl), kOp));
      EXPECT_TRUE(near_scalar<S>(neg.magnitude, theta, kOp));
      EXPECT_TRUE(near_scalar<S>(neg.pitch, h, kChain, max_abs(q)));
    }
    // Infinite pitch: the translation theta * d, whatever q.
    const Twist<S> tr = Twist<S>::from_screw(q, d, inf, theta);
    EXPECT_TRUE(all_equal(tr.angular().eval(), V3<S>::Zero().eval()));
    EXPECT_TRUE(near<S>(tr.linear(), V3L(LD(theta) * to_ld(d)), kOp));
    const auto st = tr.screw();
    EXPECT_TRUE(std::isinf(st.pitch));
    EXPECT_TRUE(near_scalar<S>(st.magnitude, theta, kOp));
    EXPECT_TRUE(near<S>(st.direction, to_ld(d), kOp));
    EXPECT_TRUE(near<S>(Twist<S>::from_screw(st).vector(), tr.vector(), kOp));
    EXPECT_TRUE(near<S>(SE3<S>::from_screw(q, d, inf, theta).translation(), V3L(LD(theta) * to_ld(d)), kOp));
    EXPECT_TRUE(all_equal(SE3<S>::from_screw(q, d, inf, theta).rotation().matrix(), SO3<S>().matrix()));
  }
  // The zero twist: magnitude 0, pitch 0, direction 0; and back to zero.
  const auto z = Twist<S>().screw();
  EXPECT_EQ(z.magnitude, S(0));
  EXPECT_EQ(z.pitch, S(0));
  EXPECT_TRUE(all_equal(z.direction, V3<S>::Zero().eval()));
  EXPECT_TRUE(all_equal(z.point, V3<S>::Zero().eval()));
  EXPECT_TRUE(all_equal(Twist<S>::from_screw(z).vector(), V6<S>::Zero().eval()));
  // A zero magnitude or a zero direction gives the zero twist.
  EXPECT_TRUE(
      all_equal(Twist<S>::from_screw(V3<S>(1, 2, 3), V3<S>(0, 0, 1), S(0.5), S(0)).vector(), V6<S>::Zero().eval()));
  EXPECT_TRUE(
      all_equal(Twist<S>::from_screw(V3<S>(1, 2, 3), V3<S>(0, 0, 0), S(0.5), S(1)).vector(), V6<S>::Zero().eval()));
  // Twist -> screw -> twist for the shared samples (w = 0 included).
  for (const auto& x : twists<S>(16)) {
    const Twist<S> xi(x);
    const auto s = xi.screw();
    // With a tiny w the screw's point and pitch are huge (|v| / |w|), and
    // the twist is rebuilt from them by cancellation: scale by |q| |w|.
    const LD scale = std::max(LD(1), max_abs(x)) + max_abs(s.point) * to_ld(xi.angular()).norm();
    EXPECT_TRUE(near<S>(Twist<S>::from_screw(s).vector(), x, kChain, scale)) << "xi = " << x.transpose();
  }
}

TYPED_TEST(TwistWrench, ScrewMotionMovesAxisPointsByPitchTimesAngle) {
  using S = TypeParam;
  for (int i = 0; i < 32; ++i) {
    const V3<S> q = this->gauss3(2), d = this->unit3();
    const V3L ql = to_ld(q), dl = to_ld(d);
    for (S h : {S(0), S(0.3), S(-2)})
      for (S theta : {S(0.5), S(2), S(3.14159265358979), S(-1)}) {
        const SE3<S> g = SE3<S>::from_screw(q, d, h, theta);
        const LD scale = 1 + max_abs(q) + std::fabs(LD(h) * LD(theta));
        for (LD lambda : {LD(0), LD(1.5), LD(-10)}) {
          const V3<S> p = (ql + lambda * dl).template cast<S>();
          // h = 0: p is fixed; otherwise it moves by h theta along the axis.
          const V3L expected = to_ld(p) + LD(h) * LD(theta) * dl;
          EXPECT_TRUE(near<S>(g.act(p), expected, kChain, scale + std::fabs(lambda)))
              << "h = " << h << ", theta = " << theta << ", lambda = " << double(lambda);
        }
        // A point off the axis: q + R (p - q) + h theta d, with R by Rodrigues.
        const V3<S> p(S(1), S(-0.5), S(0.25));
        const V3L expected = ql + rodrigues(dl, theta) * (to_ld(p) - ql) + LD(h) * LD(theta) * dl;
        EXPECT_TRUE(near<S>(g.act(p), expected, kChain, scale + 1));
      }
  }
}

// ---- spatial and body twists of trajectories ------------------------------------

/// g'(t) by the 7-point central difference in long double:
///   g' = (-g(t-3h) + 9 g(t-2h) - 45 g(t-h) + 45 g(t+h) - 9 g(t+2h) + g(t+3h)) / (60 h),
/// truncation error h^6 / 140 |g^(7)| and rounding error about
/// (110 / 60) eps_ld |g| / h. With h = 2^-9 (t +- kh exact) and the
/// trajectories below (|w|, |v| of order 1, so |g^(7)| <~ 100 |g|), the two
/// are about 4e-17 and 4e-16 |g|: under two double eps, under float's by far.
template <typename F>
M4L derivative(const F& g, LD t) {
  const LD h = std::ldexp(LD(1), -9);
  return (-g(t - 3 * h) + 9 * g(t - 2 * h) - 45 * g(t - h) + 45 * g(t + h) - 9 * g(t + 2 * h) + g(t + 3 * h)) /
         (60 * h);
}

TYPED_TEST(TwistWrench, SpatialAndBodyTwistsAgainstFiniteDifferences) {
  using S = TypeParam;
  using GL = SE3<LD>;
  // The error of the twists is that of g and g' rounded to S (g' is used as
  // given), plus the FD error above: kChain eps of S times the scale.
  for (int i = 0; i < 16; ++i) {
    const Twist<S> xi = this->twist(1, 0.6);
    const SE3<S> g0 = this->motion(1.5);
    const V6L x = to_ld(xi.vector());
    const GL g0l = g0.template cast<LD>();
    auto right = [&](LD t) { return M4L((g0l * GL::exp(V6L(t * x))).matrix()); };  // g0 exp(t xi)
    auto left = [&](LD t) { return M4L((GL::exp(V6L(t * x)) * g0l).matrix()); };   // exp(t xi) g0
    for (LD t : {LD(0), LD(0.375), LD(1.25)}) {
      const LD scale = (1 + max_abs(g0.translation()) + std::fabs(t) * max_abs(x)) * (1 + max_abs(x));
      // g0 exp(t xi): V^b = xi, V^s = Ad_g xi = (G [xi] G^-1)^vee.
      {
        const M4L G = right(t), Gd = derivative(right, t);
        const SE3<S> g = SE3<S>::from_matrix_unchecked(G.template cast<S>());
        const Eigen::Matrix<S, 4, 4> gd = Gd.template cast<S>();
        const V6L spatial_expected = vee_ld(G * hat_ld(x) * G.inverse());
        const Twist<S> Vb = Twist<S>::body(g, gd), Vs = Twist<S>::spatial(g, gd);
        EXPECT_TRUE(near<S>(Vb.vector(), x, kChain, scale)) << "right, t = " << double(t);
        EXPECT_TRUE(near<S>(Vs.vector(), spatial_expected, kChain, scale)) << "right, t = " << double(t);
        EXPECT_TRUE(near<S>(Vs.vector(), V6<S>(g.adjoint() * Vb.vector()), kChain, scale));
        EXPECT_TRUE(near<S>(Vs.vector(), g.act(Vb).vector(), kChain, scale));
      }
      // exp(t xi) g0: V^s = xi, V^b = Ad_g^-1 xi.
      {
        const M4L G = left(t), Gd = derivative(left, t);
        const SE3<S> g = SE3<S>::from_matrix_unchecked(G.template cast<S>());
        const Eigen::Matrix<S, 4, 4> gd = Gd.template cast<S>();
        const V6L body_expected = vee_ld(G.inverse() * hat_ld(x) * G);
        const Twist<S> Vb = Twist<S>::body(g, gd), Vs = Twist<S>::spatial(g, gd);
        EXPECT_TRUE(near<S>(Vs.vector(), x, kChain, scale)) << "left, t = " << double(t);
        EXPECT_TRUE(near<S>(Vb.vector(), body_expected, kChain, scale)) << "left, t = " << double(t);
        EXPECT_TRUE(near<S>(Vs.vector(), V6<S>(g.adjoint() * Vb.vector()), kChain, scale));
      }
    }
  }
}

TYPED_TEST(TwistWrench, AdIsDerivativeOfAdjointAlongExp) {
  // d/dt Ad_{exp(t a)} at t = 0 is ad_a: fixes the sign and block layout of ad().
  using S = TypeParam;
  using GL = SE3<LD>;
  for (int i = 0; i < 16; ++i) {
    const Twist<S> a = this->twist(1, 1);
    const V6L x = to_ld(a.vector());
    const LD h = std::ldexp(LD(1), -9);
    auto Ad = [&](LD t) { return M6L(GL::exp(V6L(t * x)).adjoint()); };
    const M6L d = (-Ad(-3 * h) + 9 * Ad(-2 * h) - 45 * Ad(-h) + 45 * Ad(h) - 9 * Ad(2 * h) + Ad(3 * h)) / (60 * h);
    EXPECT_TRUE(near<S>(a.ad(), d, kChain, 1 + max_abs(x)));
    EXPECT_TRUE(all_equal(a.ad(), SE3<S>::ad(a.vector())));
  }
}

// ---- frame changes and power ---------------------------------------------------

TYPED_TEST(TwistWrench, TwistFrameChangeIsAdjoint) {
  using S = TypeParam;
  for (int i = 0; i < 64; ++i) {
    const SE3<S> g = this->motion(3);
    const Twist<S> V = this->twist(2, 1);
    const M6L Ad = to_ld(g.adjoint());
    const LD scale = (1 + max_abs(g.translation())) * (1 + max_abs(V.vector()));
    EXPECT_TRUE(near<S>(g.act(V).vector(), V6L(Ad * to_ld(V.vector())), kOp, scale));
    EXPECT_TRUE(near<S>(g.act_inv(V).vector(), V6L(Ad.inverse() * to_ld(V.vector())), kChain, scale));
    EXPECT_TRUE(near<S>(g.act_inv(V).vector(), g.inverse().act(V).vector(), kChain, scale));
    EXPECT_TRUE(near<S>(g.act_inv(g.act(V)).vector(), V.vector(), kChain, scale));
    EXPECT_TRUE(near<S>(g.act(g.act_inv(V)).vector(), V.vector(), kChain, scale));
    // And as the seed derives it: [xi_a] = g [xi_b] g^-1.
    const M4L G = to_ld(g.matrix());
    EXPECT_TRUE(near<S>(g.act(V).vector(), vee_ld(G * hat_ld(to_ld(V.vector())) * G.inverse()), kChain, scale));
  }
}

TYPED_TEST(TwistWrench, WrenchFrameChangeIsAdjointInverseTranspose) {
  using S = TypeParam;
  for (int i = 0; i < 64; ++i) {
    const SE3<S> g = this->motion(3);
    const Wrench<S> F(this->gauss3(5), this->gauss3(2));
    const M6L Ad = to_ld(g.adjoint());
    const LD scale = (1 + max_abs(g.translation())) * (1 + max_abs(F.vector()));
    // F_a = Ad_g^-T F_b, F_b = Ad_g^T F_a.
    EXPECT_TRUE(near<S>(g.act(F).vector(), V6L(Ad.inverse().transpose() * to_ld(F.vector())), kChain, scale));
    EXPECT_TRUE(near<S>(g.act_inv(F).vector(), V6L(Ad.transpose() * to_ld(F.vector())), kOp, scale));
    EXPECT_TRUE(near<S>(g.act_inv(g.act(F)).vector(), F.vector(), kChain, scale));
    EXPECT_TRUE(near<S>(g.act(g.act_inv(F)).vector(), F.vector(), kChain, scale));
    EXPECT_TRUE(near<S>(g.act_inv(F).vector(), g.inverse().act(F).vector(), kChain, scale));
    // A force f at the origin of b is, in a, the force R f at p with the
    // moment p x R f about a's origin.
    const Wrench<S> pure(F.force(), V3<S>::Zero());
    const V3L Rf = to_ld(g.rotation().matrix()) * to_ld(F.force());
    EXPECT_TRUE(near<S>(g.act(pure).vector(), (V6L() << Rf, to_ld(g.translation()).cross(Rf)).finished(), kOp, scale));
  }
}

TYPED_TEST(TwistWrench, PowerIsFrameIndependent) {
  using S = TypeParam;
  int wrong_transform_breaks_it = 0;
  for (int i = 0; i < 64; ++i) {
    const SE3<S> g = this->motion(3);
    const Twist<S> Vb = this->twist(2, 1);
    const Wrench<S> Fb(this->gauss3(5), this->gauss3(2));
    const Twist<S> Va = g.act(Vb);
    const Wrench<S> Fa = g.act(Fb);
    // The size of the terms summed, for the rounding of the dot products.
    const LD terms = (to_ld(Va.vector()).cwiseAbs().dot(to_ld(Fa.vector()).cwiseAbs())) +
                     (to_ld(Vb.vector()).cwiseAbs().dot(to_ld(Fb.vector()).cwiseAbs()));
    const LD pb = to_ld(Vb.vector()).dot(to_ld(Fb.vector()));
    EXPECT_TRUE(near_scalar<S>(Fa.power(Va), pb, kChain, terms));
    EXPECT_TRUE(near_scalar<S>(chasles::power(Va, Fa), pb, kChain, terms));
    EXPECT_TRUE(near_scalar<S>(chasles::power(Vb, Fb), pb, kOp, terms));
    // The other direction, from a to b.
    EXPECT_TRUE(near_scalar<S>(chasles::power(g.act_inv(Va), g.act_inv(Fa)), pb, kChain, terms));
    // Moving the wrench like a twist (the spatialmath #169 mistake) does not
    // conserve power: the test above can tell the two apart.
    const Wrench<S> wrong(V6<S>(g.adjoint() * Fb.vector()));
    if (std::fabs(LD(chasles::power(Va, wrong)) - pb) > 1e-2 * terms) ++wrong_transform_breaks_it;
  }
  EXPECT_GT(wrong_transform_breaks_it, 48);
}

// ---- wrench screws (Poinsot) -----------------------------------------------------

TYPED_TEST(TwistWrench, WrenchScrewPoinsot) {
  using S = TypeParam;
  // A force 2 along z on the line through (1, 0, 0), plus a couple 3 about z:
  // tau = (1, 0, 0) x (0, 0, 2) + (0, 0, 3) = (0, -2, 3). Pitch f.tau / |f|^2
  // = 6 / 4, line through f x tau / |f|^2 = (4, 0, 0) / 4. All exact.
  const Wrench<S> F(V3<S>(0, 0, 2), V3<S>(0, -2, 3));
  const auto s = F.screw();
  EXPECT_EQ(s.pitch, S(1.5));
  EXPECT_EQ(F.pitch(), S(1.5));
  EXPECT_TRUE(all_equal(s.point, V3<S>(1, 0, 0)));
  EXPECT_TRUE(all_equal(s.direction, V3<S>(0, 0, 1)));
  EXPECT_EQ(s.magnitude, S(2));
  EXPECT_TRUE(all_equal(Wrench<S>::from_screw(s).vector(), F.vector()));

  // A pure couple: infinite pitch, direction tau / |tau|, magnitude |tau|.
  const auto c = Wrench<S>(V3<S>::Zero(), V3<S>(0, 0, -5)).screw();
  EXPECT_TRUE(std::isinf(c.pitch) && c.pitch > 0);
  EXPECT_TRUE(all_equal(c.direction, V3<S>(0, 0, -1)));
  EXPECT_EQ(c.magnitude, S(5));
  EXPECT_TRUE(all_equal(Wrench<S>::from_screw(c).vector(), Wrench<S>(V3<S>::Zero(), V3<S>(0, 0, -5)).vector()));
  // The zero wrench.
  const auto z = Wrench<S>().screw();
  EXPECT_EQ(z.magnitude, S(0));
  EXPECT_EQ(z.pitch, S(0));

  // Random: a force m d on the line through r, plus a couple h m d.
  for (int i = 0; i < 64; ++i) {
    const V3<S> r = this->gauss3(2), d = this->unit3();
    const S m = S(0.5 + 4 * this->u01(this->rng)), h = S(this->n01(this->rng));
    const V3L rl = to_ld(r), dl = to_ld(d), f = LD(m) * dl;
    const V3L tau = rl.cross(f) + LD(h) * LD(m) * dl;
    const Wrench<S> W(f.template cast<S>(), tau.template cast<S>());
    const auto ws = W.screw();
    const LD scale = 1 + max_abs(r) + std::fabs(h);
    EXPECT_TRUE(near_scalar<S>(ws.pitch, h, kChain, scale));
    EXPECT_TRUE(near_scalar<S>(ws.magnitude, m, kOp));
    EXPECT_TRUE(near<S>(ws.direction, dl, kOp));
    EXPECT_TRUE(near<S>(ws.point, V3L(rl - rl.dot(dl) * dl), kChain, scale));
    // About any point q of the line the moment is parallel to f:
    // tau - q x f = pitch f.
    const V3L q = to_ld(ws.point) + LD(0.7) * to_ld(ws.direction);
    EXPECT_TRUE(near<S>(V3L(to_ld(W.torque()) - q.cross(to_ld(W.force()))), V3L(LD(ws.pitch) * to_ld(W.force())),
                        kChain, scale * m));
    EXPECT_TRUE(near<S>(Wrench<S>::from_screw(ws).vector(), W.vector(), kChain, scale * m));
    EXPECT_TRUE(near<S>(Wrench<S>::from_screw(r, V3<S>(S(2) * d), h, m).vector(), W.vector(), kChain, scale * m));
  }
}

// ---- orders, bracket, hat/vee, arithmetic --------------------------------------------

TYPED_TEST(TwistWrench, ModernRoboticsOrder) {
  using S = TypeParam;
  const Twist<S> xi(V3<S>(1, 2, 3), V3<S>(4, 5, 6));
  EXPECT_TRUE(all_equal(xi.vector(), (V6<S>() << 1, 2, 3, 4, 5, 6).finished()));
  EXPECT_TRUE(all_equal(xi.to_modern_robotics(), (V6<S>() << 4, 5, 6, 1, 2, 3).finished()));
  EXPECT_TRUE(
      all_equal(Twist<S>::from_modern_robotics((V6<S>() << 4, 5, 6, 1, 2, 3).finished()).vector(), xi.vector()));
  for (int i = 0; i < 16; ++i) {
    const Twist<S> x = this->twist();
    EXPECT_TRUE(all_equal(Twist<S>::from_modern_robotics(x.to_modern_robotics()).vector(), x.vector()));
    EXPECT_TRUE(all_equal(x.to_modern_robotics().template head<3>().eval(), x.angular().eval()));
    EXPECT_TRUE(all_equal(x.to_modern_robotics().template tail<3>().eval(), x.linear().eval()));
  }
}

TYPED_TEST(TwistWrench, BracketAntisymmetryAndJacobi) {
  using S = TypeParam;
  for (int i = 0; i < 64; ++i) {
    const Twist<S> a = this->twist(2, 1), b = this->twist(2, 1), c = this->twist(2, 1);
    EXPECT_TRUE(all_equal(a.bracket(b).vector(), V6<S>(-b.bracket(a).vector())));
    EXPECT_TRUE(all_equal(a.bracket(a).vector(), V6<S>::Zero().eval()));
    // (w1 x v2 + v1 x w2, w1 x w2) and the matrix commutator, in long double.
    const V6L al = to_ld(a.vector()), bl = to_ld(b.vector());
    const V6L ref = vee_ld(hat_ld(al) * hat_ld(bl) - hat_ld(bl) * hat_ld(al));
    const V6L formula =
        (V6L() << al.tail<3>().cross(bl.head<3>()) + al.head<3>().cross(bl.tail<3>()), al.tail<3>().cross(bl.tail<3>()))
            .finished();
    EXPECT_EQ(max_abs_diff(ref, formula), LD(0));
    const LD sab = (1 + max_abs(al)) * (1 + max_abs(bl));
    EXPECT_TRUE(near<S>(a.bracket(b).vector(), ref, kOp, sab));
    EXPECT_TRUE(near<S>(V6<S>(a.ad() * b.vector()), ref, kOp, sab));
    // Jacobi: [a, [b, c]] + [b, [c, a]] + [c, [a, b]] = 0.
    const Twist<S> j = a.bracket(b.bracket(c)) + b.bracket(c.bracket(a)) + c.bracket(a.bracket(b));
    const LD sabc = sab * (1 + max_abs(c.vector()));
    EXPECT_TRUE(near<S>(j.vector(), V6<S>::Zero().eval(), kChain, sabc));
    // ad is a Lie algebra morphism: ad_[a,b] = [ad_a, ad_b].
    const M6L A = to_ld(a.ad()), B = to_ld(b.ad());
    EXPECT_TRUE(near<S>(a.bracket(b).ad(), M6L(A * B - B * A), kChain, sab));
  }
}

TYPED_TEST(TwistWrench, HatVeeOfSe3) {
  using S = TypeParam;
  for (int i = 0; i < 32; ++i) {
    const Twist<S> xi = this->twist(3, 2);
    const Eigen::Matrix<S, 4, 4> X = xi.hat();
    // [xi] = [[ [w], v ], [0, 0]], entry by entry.
    Eigen::Matrix<S, 4, 4> E;
    const V3<S> v = xi.linear(), w = xi.angular();
    E << 0, -w[2], w[1], v[0],  //
        w[2], 0, -w[0], v[1],   //
        -w[1], w[0], 0, v[2],   //
        0, 0, 0, 0;
    EXPECT_TRUE(all_equal(X, E));
    EXPECT_TRUE(all_equal(SE3<S>::hat(xi.vector()), E));
    EXPECT_TRUE(all_equal(Twist<S>::vee(X).vector(), xi.vector()));
    EXPECT_TRUE(all_equal(SE3<S>::vee(X), xi.vector()));
    // vee ignores the bottom row and the symmetric part of the 3x3 block.
    Eigen::Matrix<S, 4, 4> Y = X;
    Y.template bottomRows<1>() << 7, 8, 9, 10;
    Y(0, 1) += S(0.5);
    Y(1, 0) += S(0.5);
    EXPECT_TRUE(near<S>(Twist<S>::vee(Y).vector(), xi.vector(), kOp, 4));
    // exp of the hat matrix (long double Taylor series) is SE3::exp.
    M4L acc = M4L::Identity(), term = M4L::Identity();
    const M4L Xl = to_ld(X) / 4;  // scaling and squaring: exp(X) = exp(X/4)^4
    for (int k = 1; k < 40; ++k) {
      term = term * Xl / LD(k);
      acc += term;
    }
    const M4L expX = acc * acc * acc * acc;
    EXPECT_TRUE(near<S>(SE3<S>::exp(xi).matrix(), expX, kChain, 1 + max_abs(xi.vector())));
  }
}

TYPED_TEST(TwistWrench, AccessorsAndArithmetic) {
  using S = TypeParam;
  static_assert(Twist<S>::linear_offset == 0 && Twist<S>::angular_offset == 3);
  static_assert(Wrench<S>::force_offset == 0 && Wrench<S>::torque_offset == 3);
  Twist<S> a(V3<S>(1, 2, 3), V3<S>(4, 5, 6));
  const Twist<S> b(V6<S>::Constant(S(0.5)));
  EXPECT_TRUE(all_equal(a.linear().eval(), V3<S>(1, 2, 3)));
  EXPECT_TRUE(all_equal(a.angular().eval(), V3<S>(4, 5, 6)));
  EXPECT_TRUE(all_equal((a + b).vector(), (V6<S>() << 1.5, 2.5, 3.5, 4.5, 5.5, 6.5).finished()));
  EXPECT_TRUE(all_equal((a - b).vector(), (V6<S>() << 0.5, 1.5, 2.5, 3.5, 4.5, 5.5).finished()));
  EXPECT_TRUE(all_equal((-a).vector(), V6<S>(-a.vector())));
  EXPECT_TRUE(all_equal((a * S(2)).vector(), (S(2) * a).vector()));
  EXPECT_TRUE(all_equal((a * S(2)).vector(), (V6<S>() << 2, 4, 6, 8, 10, 12).finished()));
  a.angular() = V3<S>(7, 8, 9);  // views write through
  EXPECT_EQ(a.vector()[3], S(7));
  EXPECT_TRUE(all_equal(Twist<S>().vector(), V6<S>::Zero().eval()));

  Wrench<S> F(V3<S>(1, 2, 3), V3<S>(4, 5, 6));
  EXPECT_TRUE(all_equal(F.force().eval(), V3<S>(1, 2, 3)));
  EXPECT_TRUE(all_equal(F.torque().eval(), V3<S>(4, 5, 6)));
  EXPECT_TRUE(all_equal((F + F).vector(), (S(2) * F).vector()));
  EXPECT_TRUE(all_equal((F - F).vector(), V6<S>::Zero().eval()));
  EXPECT_TRUE(all_equal((-F).vector(), V6<S>(-F.vector())));
  F.torque()[0] = S(-1);
  EXPECT_EQ(F.vector()[3], S(-1));
  // Power: v.f + w.tau = (1, 2, 3).(1, 2, 3) + (7, 8, 9).(-1, 5, 6) = 14 + 87.
  EXPECT_EQ(F.power(a), S(101));
  EXPECT_EQ(chasles::power(a, F), S(101));

  // Casts: widening is exact, narrowing rounds each entry once.
  const Twist<S> t = this->twist();
  EXPECT_TRUE(all_equal(t.template cast<double>().template cast<S>().vector(), t.vector()));
  for (int k = 0; k < 6; ++k) EXPECT_EQ(t.template cast<float>().vector()[k], static_cast<float>(t.vector()[k]));
  const Wrench<S> w(this->gauss3(), this->gauss3());
  EXPECT_TRUE(all_equal(w.template cast<double>().template cast<S>().vector(), w.vector()));

  // is_approx: relative beyond unit scale.
  EXPECT_TRUE(t.is_approx(t, 0));
  EXPECT_TRUE(Twist<S>(V6<S>::Constant(1000)).is_approx(Twist<S>(V6<S>::Constant(S(1000.5))), S(1e-3)));
  EXPECT_FALSE(Twist<S>(V6<S>::Constant(1000)).is_approx(Twist<S>(V6<S>::Constant(S(1000.5))), S(1e-4)));
  EXPECT_FALSE(Wrench<S>(V6<S>::Zero()).is_approx(Wrench<S>(V6<S>::Constant(S(0.5))), S(0.1)));
  EXPECT_TRUE(Wrench<S>(V6<S>::Zero()).is_approx(Wrench<S>(V6<S>::Constant(S(0.5))), S(0.5)));
}

}  // namespace
