// Derivatives through Eigen::AutoDiffScalar (fixed-size derivative
// vectors) of SO3 exp, SO3 log, SE3 exp and SE3 log: finite and correct at
// angle 0, 1e-8, on both sides of the Taylor cutoff, near pi and at random
// angles. The reference is a central finite difference, with one Richardson
// step, of the long double oracle (support/reference.hpp): accurate to about
// 1e-14 here, independent of the library. At 0 the derivatives are also
// checked against their exact values: d exp(w)/dw_k = hat(e_k), and
// d log(R)/dR at R = I reads the antisymmetric part, w = vee((R - R^T)/2).
//
// log is differentiated along the group, R(delta) = R0 exp(delta) (dR =
// R0 hat(e_k)), so that the reference is defined by the rotation alone and
// not by how a log extends off SO(3). No branch may form 0/0: every
// derivative must be finite.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <chasles/detail/series.hpp>
#include <chasles/se3.hpp>
#include <chasles/so3.hpp>

#include "support/reference.hpp"
#include "support/samples.hpp"

namespace {

using chasles_ref::kPi;
using chasles_ref::ld;
using chasles_ref::M3;
using chasles_ref::M4;
using chasles_ref::V3;
using chasles_ref::V6;

template <int N>
using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
using Jac = Eigen::Matrix<ld, Eigen::Dynamic, Eigen::Dynamic>;

// Derivatives are O(1) here (translations of size 1): a wrong branch or a
// lost term shows as O(theta) or O(1), a 0/0 as NaN. Relative to max(1, |J|).
constexpr ld kTol = 1e-10L;

template <typename Derived>
std::string str(const Eigen::MatrixBase<Derived>& x) {
  std::ostringstream os;
  os.precision(17);
  os << "(";
  for (Eigen::Index i = 0; i < x.size(); ++i) os << (i ? ", " : "") << double(x(i));
  os << ")";
  return os.str();
}

/// Central difference with one Richardson step: (4 D(h/2) - D(h)) / 3.
/// f maps a step t (along one direction) to a vector of outputs.
inline Eigen::Matrix<ld, Eigen::Dynamic, 1> derivative(const std::function<Eigen::Matrix<ld, Eigen::Dynamic, 1>(ld)>& f,
                                                       ld h) {
  const auto d = [&](ld s) { return Eigen::Matrix<ld, Eigen::Dynamic, 1>((f(s) - f(-s)) / (2 * s)); };
  return (4 * d(h / 2) - d(h)) / 3;
}

template <typename Scalar, int R, int C>
Eigen::Matrix<ld, Eigen::Dynamic, 1> flatten(const Eigen::Matrix<Scalar, R, C>& m) {
  Eigen::Matrix<ld, Eigen::Dynamic, 1> out(R * C);
  for (int i = 0; i < R; ++i)
    for (int j = 0; j < C; ++j) out[i * C + j] = ld(m(i, j));
  return out;
}

/// Jacobian of autodiff outputs (one row per output, one column per variable).
template <int N, int R, int C>
Jac ad_jacobian(const Eigen::Matrix<AD<N>, R, C>& m) {
  Jac J(R * C, N);
  for (int i = 0; i < R; ++i)
    for (int j = 0; j < C; ++j)
      for (int k = 0; k < N; ++k) J(i * C + j, k) = ld(m(i, j).derivatives()[k]);
  return J;
}

struct Worst {
  ld err = 0;
  std::string where;
  void update(ld e, const std::string& at) {
    if (!(e <= err)) {
      err = e;
      where = at;
    }
  }
};

ld jac_error(const Jac& ad, const Jac& ref) {
  if (!ad.allFinite()) return std::numeric_limits<ld>::infinity();
  return (ad - ref).cwiseAbs().maxCoeff() / std::max<ld>(1, ref.cwiseAbs().maxCoeff());
}

void report(const std::string& name, const Worst& w, ld tol) {
  std::printf("[ worst    ] %-36s %.3Le (tol %.1Le) at %s\n", name.c_str(), w.err, tol, w.where.c_str());
  ::testing::Test::RecordProperty(name, std::to_string(double(w.err)));
  EXPECT_LE(w.err, tol) << name << " at " << w.where;
}

/// Rotation vectors: 0, 1e-8, either side of the Taylor cutoff (theta^2 or
/// sin^2 theta = taylor_theta2, within 1e-4 relative), near pi
/// (pi - 1e-3, pi - 1e-4), exactly pi (exp only: log is not differentiable
/// there), random; along fixed and random axes.
std::vector<V3> rotation_vectors(bool include_pi) {
  std::mt19937_64 rng(chasles_test::kSeed + 31);
  std::vector<V3> out;
  out.push_back(V3::Zero());
  const ld cut = std::sqrt(ld(chasles::Thresholds<double>::taylor_theta2));
  std::vector<ld> angles = {1e-8L, cut * (1 - 1e-4L), cut * (1 + 1e-4L), 0.3L, 1, kPi / 2,
                            2.5L,  kPi - 1e-3L,       kPi - 1e-4L};
  if (include_pi) angles.push_back(kPi);
  const std::vector<V3> axes = {V3::UnitX(), V3::UnitZ(), V3(1, 1, 0).normalized(), V3(1, -2, 3).normalized()};
  for (ld a : angles) {
    for (const V3& u : axes) out.push_back(V3(a * u).cast<double>().cast<ld>());
    out.push_back(V3(a * chasles_test::random_unit<double>(rng).cast<ld>()).cast<double>().cast<ld>());
  }
  std::uniform_real_distribution<double> u(0, double(kPi) - 1e-3);
  for (int i = 0; i < 16; ++i)
    out.push_back(V3(ld(u(rng)) * chasles_test::random_unit<double>(rng).cast<ld>()).cast<double>().cast<ld>());
  return out;
}

/// A finite-difference step for log at angle theta: below the distance to
/// the cut locus at pi (the log's Taylor radius there), above rounding.
ld log_step(ld theta) { return std::min(1e-4L, 1e-3L * (kPi - theta)); }

// ---------------------------------------------------------------------------

TEST(Autodiff, SO3ExpAtZeroIsHat) {
  Eigen::Matrix<AD<3>, 3, 1> w;
  for (int k = 0; k < 3; ++k) w[k] = AD<3>(0.0, 3, k);
  const Eigen::Matrix<AD<3>, 3, 3> R = chasles::SO3<AD<3>>::exp(w).matrix();
  for (int k = 0; k < 3; ++k) {
    Eigen::Matrix3d dR;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) dR(i, j) = R(i, j).derivatives()[k];
    EXPECT_TRUE(dR == chasles::SO3d::hat(Eigen::Vector3d::Unit(k))) << "d exp/dw_" << k << " at 0:\n" << dR;
  }
}

TEST(Autodiff, SO3Exp) {
  Worst worst;
  for (const V3& w0 : rotation_vectors(true)) {
    Eigen::Matrix<AD<3>, 3, 1> w;
    for (int k = 0; k < 3; ++k) w[k] = AD<3>(double(w0[k]), 3, k);
    const Jac J = ad_jacobian<3>(Eigen::Matrix<AD<3>, 3, 3>(chasles::SO3<AD<3>>::exp(w).matrix()));
    Jac ref(9, 3);
    for (int k = 0; k < 3; ++k)
      ref.col(k) = derivative([&](ld t) { return flatten(chasles_ref::exp3(V3(w0 + t * V3::Unit(k)))); }, 1e-4L);
    worst.update(jac_error(J, ref), "w = " + str(w0));
  }
  report("SO3 exp Jacobian", worst, kTol);
}

TEST(Autodiff, SO3LogAtIdentityReadsTheAntisymmetricPart) {
  Eigen::Matrix<AD<9>, 3, 3> M;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) M(i, j) = AD<9>(i == j ? 1.0 : 0.0, 9, 3 * i + j);
  const Eigen::Matrix<AD<9>, 3, 1> w = chasles::SO3<AD<9>>::from_matrix_unchecked(M).log();
  // w = vee((M - M^T)/2): w_x = (M21 - M12)/2, w_y = (M02 - M20)/2, w_z = (M10 - M01)/2.
  Eigen::Matrix<double, 3, 9> expected = Eigen::Matrix<double, 3, 9>::Zero();
  expected(0, 3 * 2 + 1) = 0.5;
  expected(0, 3 * 1 + 2) = -0.5;
  expected(1, 3 * 0 + 2) = 0.5;
  expected(1, 3 * 2 + 0) = -0.5;
  expected(2, 3 * 1 + 0) = 0.5;
  expected(2, 3 * 0 + 1) = -0.5;
  for (int r = 0; r < 3; ++r) {
    EXPECT_EQ(w[r].value(), 0.0);
    for (int c = 0; c < 9; ++c) EXPECT_EQ(w[r].derivatives()[c], expected(r, c)) << "dw_" << r << "/dM entry " << c;
  }
}

/// d/d delta log(R0 exp(delta)) at delta = 0, by autodiff on R0 with
/// derivatives R0 hat(e_k).
TEST(Autodiff, SO3Log) {
  Worst worst, worst_analytic;
  for (const V3& w0 : rotation_vectors(false)) {
    const M3 R0l = chasles_ref::exp3(w0);
    const Eigen::Matrix3d R0 = R0l.cast<double>();
    Eigen::Matrix<AD<3>, 3, 3> M;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        M(i, j) = AD<3>(R0(i, j));
        for (int k = 0; k < 3; ++k)
          M(i, j).derivatives()[k] = (R0 * chasles::SO3d::hat(Eigen::Vector3d::Unit(k)))(i, j);
      }
    const Jac J = ad_jacobian<3>(Eigen::Matrix<AD<3>, 3, 1>(chasles::SO3<AD<3>>::from_matrix_unchecked(M).log()));
    Jac ref(3, 3);
    const ld h = log_step(w0.norm());
    for (int k = 0; k < 3; ++k)
      ref.col(k) = derivative(
          [&](ld t) {
            return Eigen::Matrix<ld, Eigen::Dynamic, 1>(chasles_ref::log3(R0l * chasles_ref::exp3(t * V3::Unit(k))));
          },
          h);
    if (w0.norm() == 0) {
      EXPECT_LE((J - Jac::Identity(3, 3)).cwiseAbs().maxCoeff(), 1e-15L) << "at identity:\n" << J;
    }
    worst.update(jac_error(J, ref), "w = " + str(w0));
    // Analytic: the inverse of the right Jacobian J_r(w) = V(-w) = sum_k (-[w])^k / (k+1)!.
    const Jac analytic = chasles_ref::v_matrix(V3(-w0)).inverse();
    worst_analytic.update(jac_error(J, analytic), "w = " + str(w0));
  }
  report("SO3 log Jacobian (right-trivialized)", worst, kTol);
  report("SO3 log Jacobian vs J_r^-1 (analytic)", worst_analytic, kTol);
}

/// Twists: each rotation vector with a unit translation (random, or along
/// or across the axis), and pure translations.
std::vector<V6> twists(bool include_pi) {
  std::mt19937_64 rng(chasles_test::kSeed + 32);
  std::vector<V6> out;
  out.push_back(V6::Zero());
  int k = 0;
  for (const V3& w : rotation_vectors(include_pi)) {
    V3 v = chasles_test::random_unit<double>(rng).cast<ld>();
    if (k % 3 == 1 && w.norm() > 0) v = w.normalized().cast<double>().cast<ld>();
    if (k % 3 == 2 && w.norm() > 0) v = w.cross(v).normalized().cast<double>().cast<ld>();
    ++k;
    V6 xi;
    xi << v, w;
    out.push_back(xi);
  }
  V6 xi;
  xi << V3(0.6L, -0.8L, 0), V3::Zero();
  out.push_back(xi);
  return out;
}

TEST(Autodiff, SE3ExpAtZeroIsHat) {
  Eigen::Matrix<AD<6>, 6, 1> xi;
  for (int k = 0; k < 6; ++k) xi[k] = AD<6>(0.0, 6, k);
  const Eigen::Matrix<AD<6>, 4, 4> g = chasles::SE3<AD<6>>::exp(xi).matrix();
  for (int k = 0; k < 6; ++k) {
    Eigen::Matrix4d dg;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) dg(i, j) = g(i, j).derivatives()[k];
    EXPECT_TRUE(dg == chasles::SE3d::hat(Eigen::Matrix<double, 6, 1>::Unit(k))) << "d exp/dxi_" << k << " at 0:\n"
                                                                                << dg;
  }
}

TEST(Autodiff, SE3Exp) {
  Worst worst;
  for (const V6& xi0 : twists(true)) {
    Eigen::Matrix<AD<6>, 6, 1> xi;
    for (int k = 0; k < 6; ++k) xi[k] = AD<6>(double(xi0[k]), 6, k);
    const Eigen::Matrix<AD<6>, 4, 4> g = chasles::SE3<AD<6>>::exp(xi).matrix();
    const Jac J = ad_jacobian<6>(Eigen::Matrix<AD<6>, 3, 4>(g.topRows<3>()));
    Jac ref(12, 6);
    for (int k = 0; k < 6; ++k)
      ref.col(k) = derivative(
          [&](ld t) {
            return flatten(Eigen::Matrix<ld, 3, 4>(chasles_ref::exp6(V6(xi0 + t * V6::Unit(k))).topRows<3>()));
          },
          1e-4L);
    worst.update(jac_error(J, ref), "xi = " + str(xi0));
  }
  report("SE3 exp Jacobian", worst, kTol);
}

TEST(Autodiff, SE3LogAtIdentity) {
  // 12 variables: the 9 entries of R (row-major), then p.
  Eigen::Matrix<AD<12>, 4, 4> g;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) g(i, j) = AD<12>(i == j ? 1.0 : 0.0);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) g(i, j).derivatives()[3 * i + j] = 1;
    g(i, 3).derivatives()[9 + i] = 1;
  }
  const Eigen::Matrix<AD<12>, 6, 1> xi = chasles::SE3<AD<12>>::from_matrix_unchecked(g).log();
  Eigen::Matrix<double, 6, 12> expected = Eigen::Matrix<double, 6, 12>::Zero();
  expected.block<3, 3>(0, 9).setIdentity();  // v = p at the identity
  expected(3, 3 * 2 + 1) = 0.5;
  expected(3, 3 * 1 + 2) = -0.5;
  expected(4, 3 * 0 + 2) = 0.5;
  expected(4, 3 * 2 + 0) = -0.5;
  expected(5, 3 * 1 + 0) = 0.5;
  expected(5, 3 * 0 + 1) = -0.5;
  for (int r = 0; r < 6; ++r)
    for (int c = 0; c < 12; ++c) EXPECT_EQ(xi[r].derivatives()[c], expected(r, c)) << "dxi_" << r << "/dg entry " << c;
}

/// d/d delta log(g0 exp(delta)) at delta = 0, by autodiff on g0 with
/// derivatives g0 hat(e_k).
TEST(Autodiff, SE3Log) {
  Worst worst;
  for (const V6& xi0 : twists(false)) {
    const M4 g0l = chasles_ref::exp6(xi0);
    const Eigen::Matrix4d g0 = g0l.cast<double>();
    Eigen::Matrix<AD<6>, 4, 4> g;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) {
        g(i, j) = AD<6>(g0(i, j));
        for (int k = 0; k < 6; ++k)
          g(i, j).derivatives()[k] = (g0 * chasles::SE3d::hat(Eigen::Matrix<double, 6, 1>::Unit(k)))(i, j);
      }
    const Jac J = ad_jacobian<6>(Eigen::Matrix<AD<6>, 6, 1>(chasles::SE3<AD<6>>::from_matrix_unchecked(g).log()));
    Jac ref(6, 6);
    const ld h = log_step(xi0.tail<3>().norm());
    for (int k = 0; k < 6; ++k)
      ref.col(k) = derivative(
          [&](ld t) {
            return Eigen::Matrix<ld, Eigen::Dynamic, 1>(
                chasles_ref::log6(M4(g0l * chasles_ref::exp6(t * V6::Unit(k)))));
          },
          h);
    if (xi0.norm() == 0) {
      EXPECT_LE((J - Jac::Identity(6, 6)).cwiseAbs().maxCoeff(), 1e-15L) << "at identity:\n" << J;
    }
    worst.update(jac_error(J, ref), "xi = " + str(xi0));
  }
  report("SE3 log Jacobian (right-trivialized)", worst, kTol);
}

}  // namespace

// detail::arctan2 (SO3::angle, SO2, the Euler angles, so3_align): the
// derivatives of atan2(y, x), -y/r^2 along x and x/r^2 along y, in every
// quadrant and on the branch cut's sides, in the scalar's own fixed-size
// derivative type (Eigen's atan2 of AutoDiffScalars returns a dynamic-size
// one: a heap allocation), and for a nested autodiff scalar (the splines'
// dual numbers over autodiff), against the closed form and std::atan2.
TEST(Autodiff, Arctan2DerivativesInEveryQuadrant) {
  using AD2 = Eigen::AutoDiffScalar<Eigen::Vector2d>;
  static_assert(std::is_same<decltype(chasles::detail::arctan2<AD2>(AD2(), AD2())), AD2>::value,
                "arctan2 keeps the derivative type");
  for (const double angle : {0.3, 1.9, 3.0, -0.4, -2.5, 3.14159, -3.14159}) {
    for (const double r : {1e-3, 1.0, 7.5}) {
      const double x0 = r * std::cos(angle), y0 = r * std::sin(angle);
      const AD2 x(x0, 2, 0), y(y0, 2, 1);  // d/dx, d/dy
      const AD2 a = chasles::detail::arctan2<AD2>(y, x);
      EXPECT_EQ(a.value(), std::atan2(y0, x0));
      const double r2 = x0 * x0 + y0 * y0;
      EXPECT_NEAR(a.derivatives()[0], -y0 / r2, 1e-15 / r2);
      EXPECT_NEAR(a.derivatives()[1], x0 / r2, 1e-15 / r2);
      // Nested: the value and the first derivative along t of atan2(y0 + t, x0).
      using Inner = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;
      using Nested = Eigen::AutoDiffScalar<Eigen::Matrix<Inner, 1, 1>>;
      const Inner yi(y0, 1, 0);
      const Nested yn(yi, Eigen::Matrix<Inner, 1, 1>(Inner(1.0))),
          xn(Inner(x0), Eigen::Matrix<Inner, 1, 1>(Inner(0.0)));
      const Nested an = chasles::detail::arctan2<Nested>(yn, xn);
      EXPECT_EQ(an.value().value(), std::atan2(y0, x0));
      EXPECT_NEAR(an.derivatives()[0].value(), x0 / r2, 1e-15 / r2);
      // d/dy of d/dt: d(x / (x^2 + y^2))/dy = -2 x y / r^4
      EXPECT_NEAR(an.derivatives()[0].derivatives()[0], -2 * x0 * y0 / (r2 * r2), 1e-14 / (r2 * r2));
    }
  }
}
