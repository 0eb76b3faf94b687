// Jacobians of SO(3) and SE(3) (include/chasles/jacobians.hpp), right
// (local) convention: f(X exp(dx)) = f(X) exp(J dx + o(dx)).
//
// References, independent of the library's formulas:
// - every Jacobian of exp (J_r, J_l) against a central difference on the
//   manifold with one Richardson step, computed in long double from the
//   oracle of support/reference.hpp (matrix exponential by Pade, log by the
//   Mercator series near I): e.g. J_r e_k = d/dh log(exp(x)^-1 exp(x + h e_k)).
//   With h = 1e-3 the truncation error of (4 D(h/2) - D(h)) / 3 is
//   O(h^4) ~ 1e-13 times the fifth derivative, the rounding error
//   eps_ld / h ~ 1e-16; measured, it is below 1e-16 relative (the double
//   SO(3) Jacobians agree with it to 2 eps). The reference is evaluated at
//   the point as rounded to S, so only the library's own error is counted.
//   Tolerance, relative to max(1, |J|): 64 eps of S for J_r, J_l (measured
//   worst: 2 eps float, 28 eps double, the latter for |v| = 100, where Q's
//   products of up to five 3x3 factors of size |v| and theta round);
//   256 eps for the inverses, compared with the LU inverse of the reference,
//   which amplifies either side's error by up to cond(J) (measured worst:
//   3 eps float, 157 eps double, again at |v| = 100).
// - inverses against the long double LU inverse of the reference Jacobian,
//   and J J^-1 = I;
// - the operation Jacobians by the first-order check
//   f(X rplus dx) = f(X) rplus (J dx) + O(|dx|^2);
// - identities J_l(x) = J_r(-x), J_l(x) = Ad(exp(x)) J_r(x);
// - autodiff through exp and the Jacobians at exactly 0 (finite, exact).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <Eigen/LU>
#include <unsupported/Eigen/AutoDiff>

#include <chasles/jacobians.hpp>

#include "support/group_traits.hpp"
#include "support/reference.hpp"
#include "support/samples.hpp"

namespace {

using chasles_test::eps;
using chasles_test::LD;
using chasles_test::max_abs;
using chasles_test::max_abs_diff;
using chasles_test::near;
using namespace chasles;

using MX = Eigen::Matrix<LD, Eigen::Dynamic, Eigen::Dynamic>;
using VX = Eigen::Matrix<LD, Eigen::Dynamic, 1>;

constexpr LD kStep = 1e-3L;

/// Central difference with one Richardson step, column k of a Jacobian.
VX derivative(const std::function<VX(LD)>& f, LD h) {
  const auto d = [&](LD s) { return VX((f(s) - f(-s)) / (2 * s)); };
  return (4 * d(h / 2) - d(h)) / 3;
}

chasles_ref::M4 inverse4(const chasles_ref::M4& g) {
  chasles_ref::M4 out = chasles_ref::M4::Identity();
  out.topLeftCorner<3, 3>() = g.topLeftCorner<3, 3>().transpose();
  out.topRightCorner<3, 1>() = -(g.topLeftCorner<3, 3>().transpose() * g.topRightCorner<3, 1>());
  return out;
}

/// Reference right (left = false) or left Jacobian of exp at x, long double.
MX reference_exp_jacobian3(const chasles_ref::V3& x, bool right) {
  const chasles_ref::M3 E0t = chasles_ref::exp3(x).transpose();
  MX J(3, 3);
  for (int k = 0; k < 3; ++k) {
    J.col(k) = derivative(
        [&](LD h) {
          const chasles_ref::M3 E = chasles_ref::exp3(chasles_ref::V3(x + h * chasles_ref::V3::Unit(k)));
          return VX(chasles_ref::log3(right ? chasles_ref::M3(E0t * E) : chasles_ref::M3(E * E0t)));
        },
        kStep);
  }
  return J;
}

MX reference_exp_jacobian6(const chasles_ref::V6& x, bool right) {
  const chasles_ref::M4 E0i = inverse4(chasles_ref::exp6(x));
  MX J(6, 6);
  for (int k = 0; k < 6; ++k) {
    J.col(k) = derivative(
        [&](LD h) {
          const chasles_ref::M4 E = chasles_ref::exp6(chasles_ref::V6(x + h * chasles_ref::V6::Unit(k)));
          return VX(chasles_ref::log6(right ? chasles_ref::M4(E0i * E) : chasles_ref::M4(E * E0i)));
        },
        kStep);
  }
  return J;
}

/// Tolerances relative to max(1, |J|): see the header comment.
template <typename S>
LD jac_tol() {
  return 64 * eps<S>();
}
template <typename S>
LD jac_inverse_tol() {
  return 256 * eps<S>();
}

template <typename Derived>
LD rel_err(const Eigen::MatrixBase<Derived>& lib, const MX& ref) {
  const MX l = lib.template cast<LD>();
  if (!l.allFinite()) return std::numeric_limits<LD>::infinity();
  return max_abs_diff(l, ref) / std::max<LD>(1, max_abs(ref));
}

void report(const char* name, LD worst, LD tol) {
  std::printf("[ worst    ] %-44s %.3Le (tol %.1Le)\n", name, worst, tol);
  EXPECT_LE(worst, tol) << name;
}

template <typename S>
class Jacobians : public ::testing::Test {};
using Scalars = ::testing::Types<float, double>;
TYPED_TEST_SUITE(Jacobians, Scalars);

// ---- the Jacobians of exp against central differences ---------------------

TYPED_TEST(Jacobians, So3AgainstCentralDifferences) {
  using S = TypeParam;
  LD worst_r = 0, worst_l = 0, worst_ri = 0, worst_li = 0;
  for (const auto& w : chasles_test::rotation_vectors<S>(24)) {
    const chasles_ref::V3 x = w.template cast<LD>();
    const MX Jr = reference_exp_jacobian3(x, true), Jl = reference_exp_jacobian3(x, false);
    worst_r = std::max(worst_r, rel_err(so3_right_jacobian(w), Jr));
    worst_l = std::max(worst_l, rel_err(so3_left_jacobian(w), Jl));
    worst_ri = std::max(worst_ri, rel_err(so3_right_jacobian_inverse(w), MX(Jr.inverse())));
    worst_li = std::max(worst_li, rel_err(so3_left_jacobian_inverse(w), MX(Jl.inverse())));
  }
  report("so3_right_jacobian", worst_r, jac_tol<S>());
  report("so3_left_jacobian", worst_l, jac_tol<S>());
  report("so3_right_jacobian_inverse", worst_ri, jac_inverse_tol<S>());
  report("so3_left_jacobian_inverse", worst_li, jac_inverse_tol<S>());
}

TYPED_TEST(Jacobians, Se3AgainstCentralDifferences) {
  using S = TypeParam;
  LD worst_r = 0, worst_l = 0, worst_ri = 0, worst_li = 0;
  for (const auto& xi : chasles_test::twists<S>(24)) {
    const chasles_ref::V6 x = xi.template cast<LD>();
    const MX Jr = reference_exp_jacobian6(x, true), Jl = reference_exp_jacobian6(x, false);
    worst_r = std::max(worst_r, rel_err(se3_right_jacobian(xi), Jr));
    worst_l = std::max(worst_l, rel_err(se3_left_jacobian(xi), Jl));
    worst_ri = std::max(worst_ri, rel_err(se3_right_jacobian_inverse(xi), MX(Jr.inverse())));
    worst_li = std::max(worst_li, rel_err(se3_left_jacobian_inverse(xi), MX(Jl.inverse())));
  }
  report("se3_right_jacobian", worst_r, jac_tol<S>());
  report("se3_left_jacobian", worst_l, jac_tol<S>());
  report("se3_right_jacobian_inverse", worst_ri, jac_inverse_tol<S>());
  report("se3_left_jacobian_inverse", worst_li, jac_inverse_tol<S>());
}

// ---- identities -------------------------------------------------------------

TYPED_TEST(Jacobians, So3Identities) {
  using S = TypeParam;
  using M3 = Eigen::Matrix<S, 3, 3>;
  for (const auto& w : chasles_test::rotation_vectors<S>(24)) {
    EXPECT_TRUE(near<S>(so3_left_jacobian(w), so3_right_jacobian(Eigen::Matrix<S, 3, 1>(-w)), 2));
    EXPECT_TRUE(near<S>(so3_left_jacobian_inverse(w), so3_right_jacobian_inverse(Eigen::Matrix<S, 3, 1>(-w)), 2));
    // J_l = Ad(exp(w)) J_r = R J_r.
    EXPECT_TRUE(near<S>(so3_left_jacobian(w), M3(SO3<S>::exp(w).adjoint() * so3_right_jacobian(w)), 16));
    // J J^-1 = I; |J^-1| <= about pi^2 / 4 + 2 at pi, hence 32 eps.
    EXPECT_TRUE(near<S>(M3(so3_right_jacobian(w) * so3_right_jacobian_inverse(w)), M3::Identity(), 32));
    EXPECT_TRUE(near<S>(M3(so3_left_jacobian(w) * so3_left_jacobian_inverse(w)), M3::Identity(), 32));
  }
}

TYPED_TEST(Jacobians, Se3Identities) {
  using S = TypeParam;
  using M6 = Eigen::Matrix<S, 6, 6>;
  using V6 = Eigen::Matrix<S, 6, 1>;
  for (const auto& xi : chasles_test::twists<S>(24)) {
    const LD scale = std::max<LD>(1, max_abs(xi));
    EXPECT_TRUE(near<S>(se3_left_jacobian(xi), se3_right_jacobian(V6(-xi)), 2));
    EXPECT_TRUE(near<S>(M6(SE3<S>::exp(xi).adjoint() * se3_right_jacobian(xi)), se3_left_jacobian(xi), 32, scale));
    EXPECT_TRUE(
        near<S>(M6(se3_right_jacobian(xi) * se3_right_jacobian_inverse(xi)), M6::Identity(), 64, scale * scale));
    EXPECT_TRUE(near<S>(M6(se3_left_jacobian(xi) * se3_left_jacobian_inverse(xi)), M6::Identity(), 64, scale * scale));
  }
}

// ---- plus and minus ---------------------------------------------------------

TYPED_TEST(Jacobians, PlusMinusRoundTrips) {
  using S = TypeParam;
  std::mt19937_64 rng(chasles_test::kSeed + 77);
  const auto ws = chasles_test::rotation_vectors<S>(16);
  const auto xis = chasles_test::twists<S>(16);
  for (std::size_t i = 0; i + 1 < ws.size(); ++i) {
    const SO3<S> g = SO3<S>::exp(ws[i]), h = SO3<S>::exp(ws[i + 1]);
    EXPECT_TRUE(rplus(h, rminus(g, h)).is_approx(g, 32 * std::numeric_limits<S>::epsilon()));
    EXPECT_TRUE(lplus(lminus(g, h), h).is_approx(g, 32 * std::numeric_limits<S>::epsilon()));
  }
  for (std::size_t i = 0; i + 1 < xis.size(); ++i) {
    const SE3<S> g = SE3<S>::exp(xis[i]), h = SE3<S>::exp(xis[i + 1]);
    const LD scale = std::max({LD(1), max_abs(g.translation()), max_abs(h.translation())});
    EXPECT_TRUE(near<S>(rplus(h, rminus(g, h)).matrix(), g.matrix(), 64, scale));
    EXPECT_TRUE(near<S>(lplus(lminus(g, h), h).matrix(), g.matrix(), 64, scale));
  }
  // rminus(rplus(h, x), h) = x for |x| < pi.
  const Eigen::Matrix<S, 3, 1> x(S(0.3), S(-0.2), S(0.5));
  const SO3<S> h = SO3<S>::exp(ws[5]);
  EXPECT_TRUE(near<S>(rminus(rplus(h, x), h), x, 16));
  EXPECT_TRUE(near<S>(lminus(lplus(x, h), h), x, 16));
}

TYPED_TEST(Jacobians, PlusMinusArgumentOrderPinned) {
  using S = TypeParam;
  using V3 = Eigen::Matrix<S, 3, 1>;
  using V6 = Eigen::Matrix<S, 6, 1>;
  // h = Rz(0.5), g = h Rx(0.3): g = h exp(0.3 x), so rminus(g, h) = (0.3, 0, 0)
  // ("g minus h" = log(h^-1 g), as manif's g.rminus(h)); rminus(h, g) = -(0.3, 0, 0).
  const SO3<S> h = SO3<S>::exp(V3(0, 0, S(0.5)));
  const SO3<S> g = h * SO3<S>::exp(V3(S(0.3), 0, 0));
  EXPECT_TRUE(near<S>(rminus(g, h), V3(S(0.3), 0, 0), 8));
  EXPECT_TRUE(near<S>(rminus(h, g), V3(S(-0.3), 0, 0), 8));
  // Left: g2 = Rx(0.3) h = exp(0.3 x) h, so lminus(g2, h) = (0.3, 0, 0).
  const SO3<S> g2 = SO3<S>::exp(V3(S(0.3), 0, 0)) * h;
  EXPECT_TRUE(near<S>(lminus(g2, h), V3(S(0.3), 0, 0), 8));
  // The right difference of g2 and h is not the left one: log(h^-1 g2) = Rz(-0.5) (0.3, 0, 0).
  EXPECT_TRUE(near<S>(rminus(g2, h), V3(S(0.3) * std::cos(S(0.5)), S(-0.3) * std::sin(S(0.5)), 0), 8));
  // SE(3): h = (Rz(pi/2), (1, 0, 0)); g = h exp((0, 2, 0, 0, 0, 0)) moves 2 along h's y axis,
  // which is the world's -x: g's translation is (1 - 2, 0, 0) = (-1, 0, 0).
  V6 y2 = V6::Zero();
  y2[1] = S(2);
  const SE3<S> hs(SO3<S>::exp(V3(0, 0, S(1.5707963267948966))), V3(1, 0, 0));
  const SE3<S> gs = rplus(hs, y2);
  EXPECT_TRUE(near<S>(gs.translation(), V3(-1, 0, 0), 8));
  EXPECT_TRUE(near<S>(rminus(gs, hs), y2, 8));
  // Left: lplus(y2, hs) translates in the world frame: (1, 2, 0).
  EXPECT_TRUE(near<S>(lplus(y2, hs).translation(), V3(1, 2, 0), 8));
  EXPECT_TRUE(near<S>(lminus(lplus(y2, hs), hs), y2, 8));
}

// ---- operation Jacobians: first-order checks --------------------------------
//
// With |dx| = d (1e-4 double, 3e-3 float), f(X rplus dx) rminus (f(X) rplus J dx)
// is O(d^2) for a correct J and O(d) for a wrong one: the bound 8 d^2 s
// (s the size of the translations involved, at least 1) plus 64 eps s
// separates them (a wrong column errs by about d, and 8 d s < 1 here).

template <typename S>
S step() {
  return std::is_same<S, float>::value ? S(3e-3) : S(1e-4);
}

template <typename S, typename Derived>
Eigen::Matrix<S, Derived::RowsAtCompileTime, 1> random_dir(std::mt19937_64& rng, S d) {
  std::normal_distribution<double> n(0.0, 1.0);
  Eigen::Matrix<S, Derived::RowsAtCompileTime, 1> x;
  for (int i = 0; i < x.size(); ++i) x[i] = S(n(rng));
  return Eigen::Matrix<S, Derived::RowsAtCompileTime, 1>(x * (d / x.norm()));
}

template <typename G>
void first_order_checks() {
  using S = typename G::Scalar;
  using T = typename chasles_test::GroupTraits<G>;
  using Tangent = typename T::Tangent;
  using V3 = Eigen::Matrix<S, 3, 1>;
  std::mt19937_64 rng(chasles_test::kSeed + 5);
  const S d = step<S>();
  const auto xs = T::tangents(16);
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const G X = G::exp(xs[i]);
    const G Y = G::exp(xs[(i + 7) % xs.size()]);
    const LD s = std::max({LD(1), T::scale(X), T::scale(Y)});
    const LD bound = 8 * LD(d) * LD(d) * s + 64 * eps<S>() * s;
    const Tangent dx = random_dir<S, Tangent>(rng, d);
    const V3 p(S(0.5), S(-1), S(2)), dp = random_dir<S, V3>(rng, d);
    const std::string at = "at x = " + std::to_string(double(xs[i].norm()));

    // exp: exp(x + dx) vs exp(x) exp(J_r dx).
    // (through rplus: the Jacobian of exp is the right Jacobian by definition)
    // compose, a * b, perturbing a then b.
    const auto cj = compose_jacobians(X, Y);
    EXPECT_LE(LD(max_abs(rminus(G(rplus(X, dx) * Y), rplus(G(X * Y), Tangent(cj.lhs * dx))))), bound) << at;
    EXPECT_LE(LD(max_abs(rminus(G(X * rplus(Y, dx)), rplus(G(X * Y), Tangent(cj.rhs * dx))))), bound) << at;
    // inverse.
    EXPECT_LE(LD(max_abs(rminus(rplus(X, dx).inverse(), rplus(X.inverse(), Tangent(inverse_jacobian(X) * dx))))), bound)
        << at;
    // action on a point.
    const auto aj = act_jacobians(X, p);
    EXPECT_LE(LD(max_abs(V3(rplus(X, dx) * p - (X * p + aj.group * dx)))), bound * 4) << at;
    EXPECT_LE(LD(max_abs(V3(X * V3(p + dp) - (X * p + aj.point * dp)))), 64 * eps<S>() * s * 4) << at;
    // rplus(X, xi) = X exp(xi), perturbing X then xi (xi another sample, up to pi).
    const Tangent xi = xs[(i + 3) % xs.size()];
    const LD sx = std::max(s, T::scale(xi));
    const LD bound_x = 8 * LD(d) * LD(d) * sx + 64 * eps<S>() * sx;
    const auto rpj = rplus_jacobians(X, xi);
    EXPECT_LE(LD(max_abs(rminus(rplus(rplus(X, dx), xi), rplus(rplus(X, xi), Tangent(rpj.lhs * dx))))), bound_x)
        << "rplus_jacobians lhs " << at;
    EXPECT_LE(LD(max_abs(rminus(rplus(X, Tangent(xi + dx)), rplus(rplus(X, xi), Tangent(rpj.rhs * dx))))), bound_x)
        << "rplus_jacobians rhs " << at;
    // lplus(xi, X) = exp(xi) X.
    const auto lpj = lplus_jacobians(xi, X);
    EXPECT_LE(LD(max_abs(rminus(lplus(Tangent(xi + dx), X), rplus(lplus(xi, X), Tangent(lpj.lhs * dx))))), bound_x)
        << "lplus_jacobians lhs " << at;
    EXPECT_LE(LD(max_abs(rminus(lplus(xi, rplus(X, dx)), rplus(lplus(xi, X), Tangent(lpj.rhs * dx))))), bound_x)
        << "lplus_jacobians rhs " << at;
    // between(X, Y) = X^-1 Y.
    const auto bj = between_jacobians(X, Y);
    EXPECT_LE(LD(max_abs(rminus(between(rplus(X, dx), Y), rplus(between(X, Y), Tangent(bj.lhs * dx))))), bound)
        << "between_jacobians lhs " << at;
    EXPECT_LE(LD(max_abs(rminus(between(X, rplus(Y, dx)), rplus(between(X, Y), Tangent(bj.rhs * dx))))), bound)
        << "between_jacobians rhs " << at;
    // rminus(X, Y) = log(Y^-1 X) and lminus(X, Y) = log(X Y^-1): vector-valued,
    // away from angle pi where log jumps between w and -w.
    if (chasles_test::rotation_angle<G>(rminus(X, Y)) < chasles_test::kPi - 1e-2L) {
      const auto rmj = rminus_jacobians(X, Y);
      EXPECT_LE(LD(max_abs(Tangent(rminus(rplus(X, dx), Y) - (rminus(X, Y) + rmj.lhs * dx)))), bound * 4)
          << "rminus_jacobians lhs " << at;
      EXPECT_LE(LD(max_abs(Tangent(rminus(X, rplus(Y, dx)) - (rminus(X, Y) + rmj.rhs * dx)))), bound * 4)
          << "rminus_jacobians rhs " << at;
    }
    if (chasles_test::rotation_angle<G>(lminus(X, Y)) < chasles_test::kPi - 1e-2L) {
      const auto lmj = lminus_jacobians(X, Y);
      EXPECT_LE(LD(max_abs(Tangent(lminus(rplus(X, dx), Y) - (lminus(X, Y) + lmj.lhs * dx)))), bound * 4)
          << "lminus_jacobians lhs " << at;
      EXPECT_LE(LD(max_abs(Tangent(lminus(X, rplus(Y, dx)) - (lminus(X, Y) + lmj.rhs * dx)))), bound * 4)
          << "lminus_jacobians rhs " << at;
    }
    // log: a vector-valued function, away from angle pi where it is discontinuous.
    if (chasles_test::rotation_angle<G>(xs[i]) < chasles_test::kPi - 1e-2L) {
      EXPECT_LE(LD(max_abs(Tangent(rplus(X, dx).log() - (X.log() + log_jacobian(X) * dx)))), bound * 4) << at;
    }
    // interpolate in t: interpolate(a, b, t + dt) vs interpolate(a, b, t) exp(J_t dt).
    if (chasles_test::rotation_angle<G>(rminus(Y, X)) < chasles_test::kPi - 1e-2L) {
      const S t(0.3);
      const Tangent jt = interpolate_jacobian_t(X, Y, t);
      EXPECT_LE(LD(max_abs(rminus(interpolate(X, Y, S(t + d)), rplus(interpolate(X, Y, t), Tangent(d * jt))))), bound)
          << at;
    }
  }
}

TYPED_TEST(Jacobians, So3OperationsFirstOrder) { first_order_checks<SO3<TypeParam>>(); }
TYPED_TEST(Jacobians, Se3OperationsFirstOrder) { first_order_checks<SE3<TypeParam>>(); }

TYPED_TEST(Jacobians, ExpJacobiansFirstOrder) {
  using S = TypeParam;
  using V3 = Eigen::Matrix<S, 3, 1>;
  using V6 = Eigen::Matrix<S, 6, 1>;
  std::mt19937_64 rng(chasles_test::kSeed + 9);
  const S d = step<S>();
  for (const auto& w : chasles_test::rotation_vectors<S>(16)) {
    const V3 dx = random_dir<S, V3>(rng, d);
    const LD bound = 8 * LD(d) * LD(d) + 64 * eps<S>();
    EXPECT_LE(LD(max_abs(rminus(SO3<S>::exp(V3(w + dx)), rplus(SO3<S>::exp(w), V3(so3_right_jacobian(w) * dx))))),
              bound);
    EXPECT_LE(LD(max_abs(lminus(SO3<S>::exp(V3(w + dx)), lplus(V3(so3_left_jacobian(w) * dx), SO3<S>::exp(w))))),
              bound);
  }
  for (const auto& xi : chasles_test::twists<S>(16)) {
    const V6 dx = random_dir<S, V6>(rng, d);
    const LD s = std::max<LD>(1, max_abs(xi));
    const LD bound = 8 * LD(d) * LD(d) * s + 64 * eps<S>() * s;
    EXPECT_LE(LD(max_abs(rminus(SE3<S>::exp(V6(xi + dx)), rplus(SE3<S>::exp(xi), V6(se3_right_jacobian(xi) * dx))))),
              bound);
    EXPECT_LE(LD(max_abs(lminus(SE3<S>::exp(V6(xi + dx)), lplus(V6(se3_left_jacobian(xi) * dx), SE3<S>::exp(xi))))),
              bound);
  }
}

// ---- the coefficients on both sides of the Taylor cutoff ----------------------
//
// D, q3 and q4 (detail/series.hpp) against long double references summed from
// their full series (D: |B_2n| t^(n-1) / (2n)!, Bernoulli numbers; q3:
// sum (-1)^k t^(k-2) / (2k)!; q4: sum (-1)^k (k-1) t^(k-2) / (2k+1)!, k >= 2),
// at the cutoff, one ulp below it and around it. What is promised is the
// accuracy of each term: D multiplies [w]^2 (size t), q3 terms of size t, q4
// terms of size t^2, so |error| * t (t^2 for q4) must be a few eps. The
// closed forms cancel just above the cutoff and reach about 4 eps there.

LD reference_d(LD t) {
  if (t > LD(0.5)) {
    const LD h = std::sqrt(t) / 2;
    return (1 - h * std::cos(h) / std::sin(h)) / t;
  }
  // |B_2n| / (2n)! for n = 1..8.
  const LD c[] = {1.0L / 12,
                  1.0L / 720,
                  1.0L / 30240,
                  1.0L / 1209600,
                  1.0L / 47900160,
                  691.0L / 1307674368000.0L,
                  1.0L / 74724249600.0L,
                  3617.0L / 10670622842880000.0L};
  LD sum = 0, p = 1;
  for (LD ck : c) {
    sum += ck * p;
    p *= t;
  }
  return sum;
}

LD reference_q(LD t, bool q4) {
  LD sum = 0, p = 1, fact = q4 ? 120 : 24;  // (2k+1)! or (2k)! at k = 2
  for (int k = 2; k < 30; ++k) {
    sum += (k % 2 ? -1 : 1) * (q4 ? LD(k - 1) : LD(1)) * p / fact;
    p *= t;
    fact *= q4 ? LD(2 * k + 2) * LD(2 * k + 3) : LD(2 * k + 1) * LD(2 * k + 2);
  }
  return sum;
}

TYPED_TEST(Jacobians, CoefficientsAcrossTheCutoff) {
  using S = TypeParam;
  const S cut = chasles::Thresholds<S>::taylor_theta2;
  std::vector<S> ts = {S(0),
                       cut / 4,
                       std::nextafter(cut, S(0)),
                       cut,
                       std::nextafter(cut, S(1)),
                       cut * S(1.01),
                       cut * 4,
                       S(0.1),
                       S(1),
                       S(4),
                       S(9),
                       S(9.8)};
  for (S t : ts) {
    const LD tl = t;
    const LD d = chasles::detail::jacobian_inverse_coefficient(t);
    const auto q = chasles::detail::q_coefficients(t);
    EXPECT_LE(std::fabs(d - reference_d(tl)) * std::max(tl, LD(eps<S>())), 8 * eps<S>()) << "D at t = " << tl;
    EXPECT_LE(std::fabs(LD(q.q3) - reference_q(tl, false)) * std::max(tl, LD(eps<S>())), 8 * eps<S>())
        << "q3 at t = " << tl;
    EXPECT_LE(std::fabs(LD(q.q4) - reference_q(tl, true)) * std::max(tl * tl, LD(eps<S>())), 8 * eps<S>())
        << "q4 at t = " << tl;
  }
}

// ---- special points -----------------------------------------------------------

TEST(JacobiansSpecial, ExactValuesAtZeroAndNearPi) {
  using V3 = Eigen::Vector3d;
  using M3 = Eigen::Matrix3d;
  EXPECT_EQ(so3_right_jacobian(V3(V3::Zero())), M3::Identity());
  EXPECT_EQ(so3_left_jacobian_inverse(V3(V3::Zero())), M3::Identity());
  EXPECT_EQ(se3_right_jacobian(Eigen::Matrix<double, 6, 1>(Eigen::Matrix<double, 6, 1>::Zero())),
            (Eigen::Matrix<double, 6, 6>::Identity()));
  // Near and at pi the inverses are finite: J_r^-1(pi n) = I + pi/2 [n] + [n]^2 (D = 1/pi^2).
  for (double a : {chasles_test::kPi - 1e-6L, chasles_test::kPi}) {
    const V3 w = a * V3(1, 2, -2) / 3;
    const M3 Ji = so3_right_jacobian_inverse(w);
    ASSERT_TRUE(Ji.allFinite());
    const M3 N = SO3d::hat(V3(1, 2, -2) / 3);
    const M3 expected = M3::Identity() + (a / 2) * N + (1 - (a / 2) * std::cos(a / 2) / std::sin(a / 2)) * N * N;
    EXPECT_TRUE(near<double>(Ji, expected, 8));
  }
}

// ---- autodiff -------------------------------------------------------------------

template <int N>
using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;

TEST(JacobiansAutodiff, ExpThroughRightJacobianAtZeroAndBeyond) {
  // d/dd exp(w0 + d)|_0 = exp(w0) [J_r(w0) e_k]: at w0 = 0, 1e-8 and random,
  // the autodiff derivative of exp equals the closed-form right Jacobian.
  using A = AD<3>;
  for (const Eigen::Vector3d& w0 : {Eigen::Vector3d(0, 0, 0), Eigen::Vector3d(1e-8, 0, 0),
                                    Eigen::Vector3d(0.3, -1.2, 0.7), Eigen::Vector3d(0, 0, 3.1415916)}) {
    Eigen::Matrix<A, 3, 1> w;
    for (int i = 0; i < 3; ++i) w[i] = A(w0[i], 3, i);
    const auto R = SO3<A>::exp(w).matrix();
    const Eigen::Matrix3d R0 = SO3d::exp(w0).matrix();
    const Eigen::Matrix3d Jr = so3_right_jacobian(w0);
    for (int k = 0; k < 3; ++k) {
      Eigen::Matrix3d dR;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) dR(i, j) = R(i, j).derivatives()[k];
      ASSERT_TRUE(dR.allFinite());
      EXPECT_TRUE(near<double>(Eigen::Vector3d(SO3d::vee(R0.transpose() * dR)), Eigen::Vector3d(Jr.col(k)), 16));
    }
  }
}

TEST(JacobiansAutodiff, JacobiansAtExactlyZeroAreFiniteAndExact) {
  // At 0: J_r = I - 1/2 [w] + O(|w|^2), so d J_r / dw_k = -1/2 [e_k]; J_l: +1/2;
  // J_r^-1: +1/2, J_l^-1: -1/2. SE(3): d J_r / dxi_k = -1/2 ad(e_k).
  using A3 = AD<3>;
  Eigen::Matrix<A3, 3, 1> w;
  for (int i = 0; i < 3; ++i) w[i] = A3(0.0, 3, i);
  const auto check3 = [](const Eigen::Matrix<A3, 3, 3>& J, double sign, const char* name) {
    for (int k = 0; k < 3; ++k) {
      Eigen::Matrix3d dJ, val;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
          dJ(i, j) = J(i, j).derivatives()[k];
          val(i, j) = J(i, j).value();
        }
      ASSERT_TRUE(dJ.allFinite()) << name;
      EXPECT_EQ(val, Eigen::Matrix3d::Identity()) << name;
      EXPECT_TRUE(near<double>(dJ, Eigen::Matrix3d(sign * 0.5 * SO3d::hat(Eigen::Vector3d::Unit(k))), 2)) << name;
    }
  };
  check3(so3_right_jacobian(w), -1, "so3_right_jacobian");
  check3(so3_left_jacobian(w), +1, "so3_left_jacobian");
  check3(so3_right_jacobian_inverse(w), +1, "so3_right_jacobian_inverse");
  check3(so3_left_jacobian_inverse(w), -1, "so3_left_jacobian_inverse");

  using A6 = AD<6>;
  Eigen::Matrix<A6, 6, 1> xi;
  for (int i = 0; i < 6; ++i) xi[i] = A6(0.0, 6, i);
  const Eigen::Matrix<A6, 6, 6> Jr = se3_right_jacobian(xi), Jri = se3_right_jacobian_inverse(xi);
  for (int k = 0; k < 6; ++k) {
    Eigen::Matrix<double, 6, 6> dJ, dJi;
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < 6; ++j) {
        dJ(i, j) = Jr(i, j).derivatives()[k];
        dJi(i, j) = Jri(i, j).derivatives()[k];
      }
    ASSERT_TRUE(dJ.allFinite() && dJi.allFinite());
    const Eigen::Matrix<double, 6, 6> adk = SE3d::ad(Eigen::Matrix<double, 6, 1>::Unit(k));
    EXPECT_TRUE(near<double>(dJ, Eigen::Matrix<double, 6, 6>(-0.5 * adk), 2));
    EXPECT_TRUE(near<double>(dJi, Eigen::Matrix<double, 6, 6>(0.5 * adk), 2));
  }
}

// ---- the Jacobians of rplus, rminus, lplus, lminus, between by autodiff ------
//
// The derivative of the implementation itself, exact up to rounding, at
// d = 0 of f(X exp(d), Y) rminus f(X, Y) (or f(X exp(d), Y) - f(X, Y) for the
// vector-valued rminus, lminus), and likewise in the second argument, compared
// with the closed forms, at identity, 1e-8, near pi and random elements.
// Tolerance 256 eps (double) relative to max(1, |J|): Ad_g, J_r and their
// inverses are products of a few 3x3 and 6x6 matrices with entries up to
// |p| ~ 100, each rounding to a few eps of the largest entry (measured
// worst: 4 eps SO(3), 64 eps SE(3)); a wrong term errs by order 1.

template <typename G, int N>
struct AdGroup {
  using A = Eigen::AutoDiffScalar<Eigen::Matrix<double, N, 1>>;
  using GA = decltype(std::declval<G>().template cast<A>());
  using VA = Eigen::Matrix<A, N, 1>;
  using M = Eigen::Matrix<double, N, N>;
  static VA seed() {
    VA d;
    for (int i = 0; i < N; ++i) d[i] = A(0.0, N, i);
    return d;
  }
  static M jacobian(const VA& y) {
    M J;
    for (int i = 0; i < N; ++i) J.row(i) = y[i].derivatives().transpose();
    return J;
  }
};

template <typename G, int N>
void autodiff_operation_jacobians() {
  using Ad = AdGroup<G, N>;
  using A = typename Ad::A;
  using VA = typename Ad::VA;
  using M = typename Ad::M;
  using Tangent = Eigen::Matrix<double, N, 1>;
  using T = chasles_test::GroupTraits<G>;
  const auto xs = T::tangents(12);
  const VA d = Ad::seed();
  const LD tol = 256 * eps<double>();
  LD worst = 0;
  const auto check = [&](const M& ad, const M& closed, const std::string& what) {
    const LD err = rel_err(closed, MX(ad.template cast<LD>()));
    worst = std::max(worst, err);
    EXPECT_LE(err, tol) << what;
  };
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const G X = G::exp(xs[i]), Y = G::exp(xs[(i + 5) % xs.size()]);
    const Tangent xi = xs[(i + 3) % xs.size()];
    const auto XA = X.template cast<A>();
    const auto YA = Y.template cast<A>();
    const VA xiA = xi.template cast<A>();
    const std::string at = " at sample " + std::to_string(i);
    const auto rpj = rplus_jacobians(X, xi);
    const auto rp0 = rplus(X, xi).template cast<A>();
    check(Ad::jacobian(rminus(rplus(rplus(XA, d), xiA), rp0)), rpj.lhs, "rplus lhs" + at);
    check(Ad::jacobian(rminus(rplus(XA, VA(xiA + d)), rp0)), rpj.rhs, "rplus rhs" + at);
    const auto lpj = lplus_jacobians(xi, X);
    const auto lp0 = lplus(xi, X).template cast<A>();
    check(Ad::jacobian(rminus(lplus(VA(xiA + d), XA), lp0)), lpj.lhs, "lplus lhs" + at);
    check(Ad::jacobian(rminus(lplus(xiA, rplus(XA, d)), lp0)), lpj.rhs, "lplus rhs" + at);
    const auto bj = between_jacobians(X, Y);
    const auto b0 = between(X, Y).template cast<A>();
    check(Ad::jacobian(rminus(between(rplus(XA, d), YA), b0)), bj.lhs, "between lhs" + at);
    check(Ad::jacobian(rminus(between(XA, rplus(YA, d)), b0)), bj.rhs, "between rhs" + at);
    // rminus and lminus are differentiable where log is: below the angle pi.
    if (chasles_test::rotation_angle<G>(rminus(X, Y)) < chasles_test::kPi - 1e-6L) {
      const auto rmj = rminus_jacobians(X, Y);
      check(Ad::jacobian(rminus(rplus(XA, d), YA)), rmj.lhs, "rminus lhs" + at);
      check(Ad::jacobian(rminus(XA, rplus(YA, d))), rmj.rhs, "rminus rhs" + at);
    }
    if (chasles_test::rotation_angle<G>(lminus(X, Y)) < chasles_test::kPi - 1e-6L) {
      const auto lmj = lminus_jacobians(X, Y);
      check(Ad::jacobian(lminus(rplus(XA, d), YA)), lmj.lhs, "lminus lhs" + at);
      check(Ad::jacobian(lminus(XA, rplus(YA, d))), lmj.rhs, "lminus rhs" + at);
    }
  }
  report(N == 3 ? "SO3 rplus/rminus/lplus/lminus/between autodiff" : "SE3 rplus/rminus/lplus/lminus/between autodiff",
         worst, tol);
}

TEST(JacobiansAutodiff, So3PlusMinusBetweenJacobians) { autodiff_operation_jacobians<SO3d, 3>(); }
TEST(JacobiansAutodiff, Se3PlusMinusBetweenJacobians) { autodiff_operation_jacobians<SE3d, 6>(); }

TEST(JacobiansAutodiff, PlusMinusJacobiansAtIdentityAndPinned) {
  // At X = Y = identity and xi = 0 every Jacobian is +-I; and the SO(3) values
  // at a quarter turn: rplus's J_g = Ad_{exp(-xi)} = R^T, between's J_a = -R_b^T R_a.
  const SO3d I;
  const Eigen::Vector3d z = Eigen::Vector3d::Zero();
  const Eigen::Matrix3d E = Eigen::Matrix3d::Identity();
  EXPECT_EQ(rplus_jacobians(I, z).lhs, E);
  EXPECT_EQ(rplus_jacobians(I, z).rhs, E);
  EXPECT_EQ(lplus_jacobians(z, I).lhs, E);
  EXPECT_EQ(rminus_jacobians(I, I).lhs, E);
  EXPECT_EQ(rminus_jacobians(I, I).rhs, Eigen::Matrix3d(-E));
  EXPECT_EQ(lminus_jacobians(I, I).rhs, Eigen::Matrix3d(-E));
  EXPECT_EQ(between_jacobians(I, I).lhs, Eigen::Matrix3d(-E));
  const Eigen::Vector3d q(0, 0, 1.5707963267948966);
  const Eigen::Matrix3d Rz = SO3d::exp(q).matrix();
  EXPECT_TRUE(near<double>(rplus_jacobians(I, q).lhs, Eigen::Matrix3d(Rz.transpose()), 4));
  EXPECT_TRUE(near<double>(between_jacobians(SO3d::exp(q), I).lhs, Eigen::Matrix3d(-Rz), 4));
  const SE3d gI;
  const Eigen::Matrix<double, 6, 1> z6 = Eigen::Matrix<double, 6, 1>::Zero();
  using M6 = Eigen::Matrix<double, 6, 6>;
  const M6 E6 = M6::Identity();
  EXPECT_EQ(rplus_jacobians(gI, z6).rhs, E6);
  EXPECT_EQ(rminus_jacobians(gI, gI).rhs, M6(-E6));
  EXPECT_EQ(lplus_jacobians(z6, gI).lhs, E6);
}

}  // namespace
