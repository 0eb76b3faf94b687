// bspline.hpp: the uniform cumulative cubic B-spline on SO(3) and SE(3),
// and through the same code on SO(2), SE(2) and Sim(3) (every typed test
// below runs on the five groups; their oracle exp is the long double Taylor
// exponential of the hat matrix, their oracle log the group's own log in
// long double, itself tested against 50-digit references in test_groups and
// test_sim3).
//
// - X(t) against an independent long double evaluation of the explicit
//   formula X_i prod_j exp(Bt_j log(X_{j-1}^-1 X_j)), written here from the
//   ordinary B-spline basis b_l(u) (Qin 2000's blending matrix) summed into
//   the cumulative one, with the oracle exp and log of support/reference.hpp;
// - the body velocity and acceleration against central differences of the
//   evaluated elements (typed, float and double) and against automatic
//   differentiation through Eigen::AutoDiffScalar (time as the variable);
// - the Jacobians of a segment's element with respect to its four control
//   elements against central differences (long double);
// - C2 at the knots, constant control, one-parameter subgroups (SO3 and
//   SE3 screw motions), SE3 of pure rotations equal to SO3, and the time
//   convention of the view (knots, clamping, NaN).
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <chasles/bspline.hpp>

#include "support/reference.hpp"

namespace {

using chasles::BSplinePoint;
using chasles::CubicBSplineView;
using chasles::SE2;
using chasles::SE23;
using chasles::SE3;
using chasles::Sim3;
using chasles::SO2;
using chasles::SO3;
using ld = long double;

// ---- groups under test ---------------------------------------------------------

template <typename G>
struct GroupOf;
template <typename S>
struct GroupOf<SO3<S>> {
  static constexpr int dof = 3;
  static Eigen::Matrix<S, 3, 3> matrix(const SO3<S>& R) { return R.matrix(); }
  static Eigen::Matrix<ld, 3, 3> ref_exp(const Eigen::Matrix<ld, 3, 1>& w) { return chasles_ref::exp3(w); }
  static Eigen::Matrix<ld, 3, 1> ref_log(const Eigen::Matrix<ld, 3, 3>& R) { return chasles_ref::log3(R); }
  static const char* name() { return "SO3"; }
};
template <typename S>
struct GroupOf<SE3<S>> {
  static constexpr int dof = 6;
  static Eigen::Matrix<S, 4, 4> matrix(const SE3<S>& g) { return g.matrix(); }
  static Eigen::Matrix<ld, 4, 4> ref_exp(const Eigen::Matrix<ld, 6, 1>& xi) { return chasles_ref::exp6(xi); }
  static Eigen::Matrix<ld, 6, 1> ref_log(const Eigen::Matrix<ld, 4, 4>& g) { return chasles_ref::log6(g); }
  static const char* name() { return "SE3"; }
};

/// The groups written only over the generic interface: the oracle exp is
/// exp_taylor of the hat matrix (long double), the oracle log the group's
/// log in long double.
template <template <typename> class Group, typename S>
struct GenericGroupOf {
  using G = Group<S>;
  using GL = Group<ld>;
  static constexpr int dof = G::DoF;
  static auto matrix(const G& g) { return g.matrix(); }
  template <typename T>
  static auto ref_exp(const T& x) {
    const auto X = GL::hat(typename GL::Tangent(x));
    return chasles_ref::exp_taylor<decltype(X)::RowsAtCompileTime>(X);
  }
  template <typename M>
  static typename GL::Tangent ref_log(const M& m) {
    return GL::from_matrix_unchecked(m).log();
  }
};
template <typename S>
struct GroupOf<SO2<S>> : GenericGroupOf<SO2, S> {
  static const char* name() { return "SO2"; }
};
template <typename S>
struct GroupOf<SE2<S>> : GenericGroupOf<SE2, S> {
  static const char* name() { return "SE2"; }
};
template <typename S>
struct GroupOf<Sim3<S>> : GenericGroupOf<Sim3, S> {
  static const char* name() { return "Sim3"; }
};
template <typename S>
struct GroupOf<SE23<S>> : GenericGroupOf<SE23, S> {
  static const char* name() { return "SE23"; }
};

template <typename G>
class BSpline : public ::testing::Test {};
struct GroupName {
  template <typename G>
  static std::string GetName(int) {
    using S = typename G::Scalar;
    return std::string(GroupOf<G>::name()) + (std::is_same<S, float>::value ? "f" : "d");
  }
};
using Groups = ::testing::Types<SO3<float>, SO3<double>, SE3<float>, SE3<double>, SO2<float>, SO2<double>, SE2<float>,
                                SE2<double>, Sim3<float>, Sim3<double>, SE23<float>, SE23<double>>;
TYPED_TEST_SUITE(BSpline, Groups, GroupName);

template <typename G>
using TangentOf = Eigen::Matrix<typename G::Scalar, G::DoF, 1>;

/// n control elements, each a random step (entries uniform in +-step) from
/// the one before: random enough to exercise every term, with steps well
/// below pi so that the logs are far from their cut.
template <typename G>
std::vector<G> random_control(int n, double step, unsigned seed) {
  using S = typename G::Scalar;
  std::mt19937_64 gen(seed);
  std::uniform_real_distribution<double> uni(-1, 1);
  Eigen::Matrix<double, G::DoF, 1> x0;
  for (int k = 0; k < G::DoF; ++k) x0[k] = 2 * uni(gen);
  std::vector<G> out{G::exp(TangentOf<G>(x0.template cast<S>()))};
  for (int i = 1; i < n; ++i) {
    Eigen::Matrix<double, G::DoF, 1> x;
    for (int k = 0; k < G::DoF; ++k) x[k] = step * uni(gen);
    out.push_back(out.back() * G::exp(TangentOf<G>(x.template cast<S>())));
  }
  return out;
}

template <typename S>
constexpr ld eps() {
  return static_cast<ld>(std::numeric_limits<S>::epsilon());
}

template <typename DA, typename DB>
ld max_diff(const Eigen::MatrixBase<DA>& a, const Eigen::MatrixBase<DB>& b) {
  ld m = 0;
  for (Eigen::Index i = 0; i < a.size(); ++i) {
    const ld d = std::fabs(static_cast<ld>(a(i)) - static_cast<ld>(b(i)));
    if (!(d <= m)) m = d;
  }
  return m;
}

/// The reference element of segment `first` at u, in long double: the
/// ordinary uniform cubic basis b_l(u) = [1 u u^2 u^3] M_l with Qin's
/// blending matrix M = [[1, 4, 1, 0], [-3, 0, 3, 0], [3, -6, 3, 0],
/// [-1, 3, -3, 1]] / 6, the cumulative Bt_j = sum_{l >= j} b_l, and
/// X = X_0 prod_j exp(Bt_j log(X_{j-1}^-1 X_j)) with the oracle's exp and log.
template <typename G>
auto reference_segment(const G* first, ld u) {
  using Tr = GroupOf<G>;
  const ld M[4][4] = {{1, 4, 1, 0}, {-3, 0, 3, 0}, {3, -6, 3, 0}, {-1, 3, -3, 1}};
  const ld powers[4] = {1, u, u * u, u * u * u};
  ld b[4] = {0, 0, 0, 0};
  for (int l = 0; l < 4; ++l)
    for (int k = 0; k < 4; ++k) b[l] += powers[k] * M[k][l] / 6;
  auto X = Tr::matrix(first[0]).template cast<ld>().eval();
  for (int j = 1; j <= 3; ++j) {
    ld cumulative = 0;
    for (int l = j; l < 4; ++l) cumulative += b[l];
    const auto A = Tr::matrix(first[j - 1]).template cast<ld>().eval();
    const auto B = Tr::matrix(first[j]).template cast<ld>().eval();
    const auto d = Tr::ref_log((A.inverse() * B).eval());
    X = (X * Tr::ref_exp((cumulative * d).eval())).eval();
  }
  return X;
}

// ---- the basis -------------------------------------------------------------------

TEST(BSplineBasis, SumsToOnePlusUWithDerivativesOneAndZero) {
  for (double u = 0; u <= 1.0; u += 0.125) {
    const auto b = chasles::cubic_bspline_basis(u);
    EXPECT_NEAR(b.value.sum(), 1 + u, 1e-15);
    EXPECT_NEAR(b.first.sum(), 1.0, 1e-15);
    EXPECT_NEAR(b.second.sum(), 0.0, 1e-15);
  }
  // The ends: (5/6, 1/6, 0) at u = 0 and (1, 5/6, 1/6) at u = 1, so that
  // segment i at u = 1 is segment i + 1 at u = 0.
  const auto b0 = chasles::cubic_bspline_basis(0.0), b1 = chasles::cubic_bspline_basis(1.0);
  EXPECT_EQ(b0.value, Eigen::Vector3d(5.0 / 6, 1.0 / 6, 0));
  EXPECT_EQ(b1.value, Eigen::Vector3d(1, 5.0 / 6, 1.0 / 6));
}

TEST(BSplineBasis, DerivativesAreThoseOfTheValues) {
  // Exact for cubics: the central difference of a cubic has error h^2 b''' / 6
  // (b''' is constant, at most 2 in magnitude), so h = 1e-4 gives 3e-9, and
  // the rounding adds eps / h ~ 2e-12.
  const double h = 1e-4;
  for (double u = 0.05; u < 1.0; u += 0.1) {
    const auto b = chasles::cubic_bspline_basis(u), p = chasles::cubic_bspline_basis(u + h),
               m = chasles::cubic_bspline_basis(u - h);
    for (int j = 0; j < 3; ++j) {
      EXPECT_NEAR(b.first[j], (p.value[j] - m.value[j]) / (2 * h), 1e-8);
      EXPECT_NEAR(b.second[j], (p.first[j] - m.first[j]) / (2 * h), 1e-8);
    }
  }
}

// ---- the element -----------------------------------------------------------------

TYPED_TEST(BSpline, ElementMatchesTheExplicitFormulaInLongDouble) {
  using G = TypeParam;
  using S = typename G::Scalar;
  const auto X = random_control<G>(9, 1.2, 7);
  ld worst = 0;
  for (int i = 0; i + 4 <= 9; ++i)
    for (const double u : {0.0, 1e-9, 0.3, 0.5, 0.77, 1.0 - 1e-9, 1.0}) {
      const auto ref = reference_segment(X.data() + i, ld(u));
      const auto got = GroupOf<G>::matrix(chasles::cubic_bspline_segment(X.data() + i, S(u)));
      worst = std::max(worst, max_diff(got, ref) / std::max<ld>(1, ref.cwiseAbs().maxCoeff()));
      // The derivative form computes the same element.
      const auto both = chasles::cubic_bspline_segment_derivatives(X.data() + i, S(u), S(0.5));
      EXPECT_EQ(GroupOf<G>::matrix(both.value), got);
    }
  // Three log, three exp and five products of order-1 matrices: a few tens
  // of eps (the control elements themselves carry their rounding: the
  // reference starts from the same rounded matrices).
  EXPECT_LE(worst, 64 * eps<S>()) << worst / eps<S>() << " eps";
}

/// The Jacobians of a segment's element with respect to its four control
/// elements, against central differences of rminus(X(u; X_k exp(e)), X(u))
/// on the long double group (step 1e-6: truncation and rounding near
/// 1e-12), at u = 0, 0.37 and 1 of steps d_j about 1 rad.
TYPED_TEST(BSpline, SegmentJacobiansMatchCentralDifferences) {
  using G = TypeParam;
  using S = typename G::Scalar;
  using GL = typename chasles::detail::WithScalar<G, ld>::type;
  using TL = typename GL::Tangent;
  const auto X = random_control<G>(4, 1.0, 11);
  std::vector<GL> XL;
  for (const G& x : X) XL.push_back(x.template cast<ld>());
  // 1e-9 in double (the differences' error is near 1e-12), 1e3 eps in float.
  const ld tol = std::is_same<S, float>::value ? 1e3 * eps<S>() : 1e-9L;
  for (const double u : {0.0, 0.37, 1.0}) {
    const auto J = chasles::cubic_bspline_segment_jacobians(X.data(), S(u));
    const auto value = GroupOf<G>::matrix(chasles::cubic_bspline_segment(X.data(), S(u)));
    EXPECT_LE(max_diff(GroupOf<G>::matrix(J.value), value),
              16 * eps<S>() * std::max<ld>(1, value.cwiseAbs().maxCoeff()));
    const GL center = chasles::cubic_bspline_segment(XL.data(), ld(u));
    for (int k = 0; k < 4; ++k) {
      for (int i = 0; i < G::DoF; ++i) {
        const ld h = 1e-6L;
        TL e = TL::Zero();
        e[i] = h;
        std::vector<GL> plus = XL, minus = XL;
        plus[k] = plus[k] * GL::exp(e);
        minus[k] = minus[k] * GL::exp(TL(-e));
        const TL fd = (chasles::rminus(chasles::cubic_bspline_segment(plus.data(), ld(u)), center) -
                       chasles::rminus(chasles::cubic_bspline_segment(minus.data(), ld(u)), center)) /
                      (2 * h);
        EXPECT_LE(max_diff(J.control[k].col(i), fd), tol * std::max<ld>(1, fd.cwiseAbs().maxCoeff()))
            << "u " << u << ", control " << k << ", axis " << i;
      }
    }
  }
}

TYPED_TEST(BSpline, ConstantControlGivesAConstantWithZeroRates) {
  using G = TypeParam;
  using S = typename G::Scalar;
  const G X = random_control<G>(1, 0, 3)[0];
  const std::vector<G> control(6, X);
  const CubicBSplineView<G> spline(control.data(), 6, S(-1), S(0.25));
  for (const double t : {-1.0, -0.9, -0.5, -0.27, 0.0, 0.5}) {
    const BSplinePoint<G> p = spline.evaluate(S(t));
    // X^-1 X is the identity to rounding, so the logs are a few eps, scaled
    // by the rates 1 / dt = 4 and 1 / dt^2 = 16.
    EXPECT_LE(max_diff(GroupOf<G>::matrix(p.value), GroupOf<G>::matrix(X)), 16 * eps<S>() * 4);
    EXPECT_LE(max_diff(p.velocity, TangentOf<G>::Zero()), 16 * eps<S>() * 4 * 4);
    EXPECT_LE(max_diff(p.acceleration, TangentOf<G>::Zero()), 16 * eps<S>() * 4 * 16);
  }
}

/// X_k = X_0 exp(k dt xi): X(t) = X_0 exp((t - t0 + dt) xi) (the cumulative
/// basis sums to u + 1), body velocity xi, acceleration 0.
template <typename G>
void check_one_parameter_subgroup(const TangentOf<G>& xi) {
  using S = typename G::Scalar;
  const S dt(0.4), t0(2);
  const G X0 = random_control<G>(1, 0, 5)[0];
  std::vector<G> control;
  for (int k = 0; k < 7; ++k) control.push_back(X0 * G::exp(TangentOf<G>(S(k) * dt * xi)));
  const CubicBSplineView<G> spline(control.data(), 7, t0, dt);
  ld worst_x = 0, worst_v = 0, worst_a = 0;
  for (double t = 2; t <= 3.6; t += 0.05) {
    const BSplinePoint<G> p = spline.evaluate(S(t));
    const auto ref = (GroupOf<G>::matrix(X0).template cast<ld>() *
                      GroupOf<G>::ref_exp(((ld(t) - ld(t0) + ld(dt)) * xi.template cast<ld>()).eval()))
                         .eval();
    worst_x =
        std::max(worst_x, max_diff(GroupOf<G>::matrix(p.value), ref) / std::max<ld>(1, ref.cwiseAbs().maxCoeff()));
    worst_v = std::max(worst_v, max_diff(p.velocity, xi));
    worst_a = std::max(worst_a, max_diff(p.acceleration, TangentOf<G>::Zero()));
  }
  // The steps d_j equal dt xi to rounding (a few eps of |dt xi| ~ 1); the
  // velocity divides them by dt, the acceleration by dt^2.
  EXPECT_LE(worst_x, 64 * eps<S>()) << worst_x / eps<S>() << " eps";
  EXPECT_LE(worst_v, 64 * eps<S>() / ld(dt)) << worst_v / eps<S>() << " eps";
  EXPECT_LE(worst_a, 64 * eps<S>() / ld(dt * dt)) << worst_a / eps<S>() << " eps";
}

TYPED_TEST(BSpline, OneParameterSubgroupIsThatMotionAtConstantVelocity) {
  using G = TypeParam;
  using S = typename G::Scalar;
  if constexpr (G::DoF == 1) {
    check_one_parameter_subgroup<G>(TangentOf<G>(S(1.7)));
  } else if constexpr (G::DoF == 7) {
    TangentOf<G> x;
    x << S(0.4), S(-1), S(0.3), S(0.8), S(-1.1), S(0.5), S(0.6);  // with a steady scaling
    check_one_parameter_subgroup<G>(x);
  } else if constexpr (G::DoF == 3) {
    check_one_parameter_subgroup<G>(TangentOf<G>(S(0.8), S(-1.1), S(0.5)));
  } else if constexpr (G::DoF == 9) {
    TangentOf<G> x;  // (rho, nu, w): position and velocity parts beside the rotation
    x << S(0.4), S(-1), S(0.3), S(1.5), S(0.2), S(-0.7), S(0.8), S(-1.1), S(0.5);
    check_one_parameter_subgroup<G>(x);
  } else {
    // A screw motion of pitch 0.37 about an axis off the origin, and a pure translation.
    check_one_parameter_subgroup<G>(
        SE3<S>::exp(chasles::Twist<S>::from_screw(Eigen::Matrix<S, 3, 1>(S(1), S(-2), S(0.5)),
                                                  Eigen::Matrix<S, 3, 1>(S(0.3), S(0.4), S(-1)), S(0.37), S(1.3))
                        .vector())
            .log());
    TangentOf<G> v;
    v << S(1.5), S(-0.5), S(2), S(0), S(0), S(0);
    check_one_parameter_subgroup<G>(v);
  }
}

// ---- velocity and acceleration ---------------------------------------------------

TYPED_TEST(BSpline, RatesMatchCentralDifferencesOfTheElements) {
  using G = TypeParam;
  using S = typename G::Scalar;
  const auto X = random_control<G>(8, 1.0, 11);
  const S dt(0.5), t0(-0.3);
  const CubicBSplineView<G> spline(X.data(), 8, t0, dt);
  // Body velocity: (log(X(t)^-1 X(t+h)) - log(X(t)^-1 X(t-h))) / 2h, and
  // the acceleration as the central difference of the analytic velocity.
  // Errors: truncation h^2 |f'''| / 6 (f''' is omega'' for the velocity,
  // omega''' for the acceleration) and rounding eps |f| / h. Here
  // |omega''| <~ |d| / dt^3 ~ 16 and |omega'''| <~ |d| / dt^4 ~ 32 (steps
  // |d| <= 2, dt = 0.5), so h = 1e-4 (double) leaves 5e-8 and 2e-11;
  // h = 1e-2 (float) leaves 5e-4 and 1e-4 (times the operation count).
  // The tolerances are 4x and 20x above those bounds: a missing term of the
  // recursion (a bracket, an adjoint) is O(1). The times keep 0.05 dt > h
  // away from the knots, where the third derivative jumps (the curve is C2,
  // not C3) and a difference straddling a knot is only first-order accurate.
  const bool is_float = std::is_same<S, float>::value;
  const S h = is_float ? S(1e-2) : S(1e-4);
  const ld tol = is_float ? 1e-2L : 2e-7L;
  std::mt19937_64 gen(3);
  std::uniform_real_distribution<double> uni(0.05, 0.95);
  ld worst_v = 0, worst_a = 0;
  for (int k = 0; k < 40; ++k) {
    const S t = t0 + dt * S(double(k % 5) + uni(gen));
    const BSplinePoint<G> p = spline.evaluate(t);
    const G plus = spline(S(t + h)), minus = spline(S(t - h));
    const TangentOf<G> v = ((p.value.inverse() * plus).log() - (p.value.inverse() * minus).log()) / (S(2) * h);
    const TangentOf<G> a = (spline.evaluate(S(t + h)).velocity - spline.evaluate(S(t - h)).velocity) / (S(2) * h);
    worst_v = std::max(worst_v, max_diff(p.velocity, v) / std::max<ld>(1, max_diff(v, TangentOf<G>::Zero())));
    worst_a = std::max(worst_a, max_diff(p.acceleration, a) / std::max<ld>(1, max_diff(a, TangentOf<G>::Zero())));
  }
  EXPECT_LE(worst_v, tol);
  EXPECT_LE(worst_a, tol);
}

TYPED_TEST(BSpline, ContinuousToSecondOrderAtTheKnots) {
  using G = TypeParam;
  using S = typename G::Scalar;
  const auto X = random_control<G>(8, 1.5, 13);
  const S dt(0.2);
  // Segment i at u = 1 against segment i + 1 at u = 0, evaluated apart: the
  // same products in another order, so a few tens of eps of the largest
  // entry (Sim(3)'s reach 36 in double and 75 in float here: the scale
  // multiplies the rotation and the translations grow with it), times the
  // rates 1/dt = 5 and 1/dt^2 = 25. A basis that is not C2 fails by O(1).
  for (int i = 0; i + 5 <= 8; ++i) {
    const auto left = chasles::cubic_bspline_segment_derivatives(X.data() + i, S(1), dt);
    const auto right = chasles::cubic_bspline_segment_derivatives(X.data() + i + 1, S(0), dt);
    const auto value = GroupOf<G>::matrix(right.value);
    EXPECT_LE(max_diff(GroupOf<G>::matrix(left.value), value),
              64 * eps<S>() * std::max<ld>(1, value.cwiseAbs().maxCoeff()))
        << i;
    EXPECT_LE(max_diff(left.velocity, right.velocity), 64 * eps<S>() * 5 * 4) << i;
    EXPECT_LE(max_diff(left.acceleration, right.acceleration), 64 * eps<S>() * 25 * 4) << i;
  }
}

TYPED_TEST(BSpline, ThePoseSplineOfPureRotationsIsTheRotationSpline) {
  using G = TypeParam;
  using S = typename G::Scalar;
  if constexpr (G::DoF == 6) {
    const auto R = random_control<SO3<S>>(6, 1.3, 17);
    std::vector<SE3<S>> g;
    for (const auto& r : R) g.push_back(SE3<S>(r, Eigen::Matrix<S, 3, 1>::Zero()));
    const CubicBSplineView<SO3<S>> rs(R.data(), 6, S(1), S(0.3));
    const CubicBSplineView<SE3<S>> gs(g.data(), 6, S(1), S(0.3));
    for (double t = 1; t <= 1.9; t += 0.07) {
      const auto a = rs.evaluate(S(t));
      const auto b = gs.evaluate(S(t));
      EXPECT_LE(max_diff(b.value.rotation().matrix(), a.value.matrix()), 8 * eps<S>());
      EXPECT_LE(max_diff(b.value.translation(), Eigen::Matrix<S, 3, 1>::Zero()), 8 * eps<S>());
      EXPECT_LE(max_diff(b.velocity.template tail<3>(), a.velocity), 8 * eps<S>() / ld(0.3));
      EXPECT_LE(max_diff(b.acceleration.template tail<3>(), a.acceleration), 8 * eps<S>() / ld(0.09));
      // The linear parts: a rotation-only log has v = 0 exactly (V^-1 0), so they stay 0.
      EXPECT_LE(max_diff(b.velocity.template head<3>(), Eigen::Matrix<S, 3, 1>::Zero()), 8 * eps<S>());
      EXPECT_LE(max_diff(b.acceleration.template head<3>(), Eigen::Matrix<S, 3, 1>::Zero()), 8 * eps<S>());
    }
  }
}

// ---- the time convention ---------------------------------------------------------

TYPED_TEST(BSpline, TimesMapToSegmentsAndClampOutside) {
  using G = TypeParam;
  using S = typename G::Scalar;
  const auto X = random_control<G>(6, 1.0, 19);
  const CubicBSplineView<G> spline(X.data(), 6, S(1), S(0.5));
  EXPECT_EQ(spline.size(), 6);
  EXPECT_EQ(spline.segments(), 3);
  EXPECT_EQ(spline.end_time(), S(2.5));
  // A knot starts its segment; the last time ends the last segment.
  for (int k = 0; k < 3; ++k) {
    const auto at = spline.locate(S(1) + S(0.5) * S(k));
    EXPECT_EQ(at.segment, k);
    EXPECT_EQ(at.u, S(0));
  }
  const auto mid = spline.locate(S(1.875));
  EXPECT_EQ(mid.segment, 1);
  EXPECT_EQ(mid.u, S(0.75));
  const auto end = spline.locate(S(2.5));
  EXPECT_EQ(end.segment, 2);
  EXPECT_EQ(end.u, S(1));
  // Outside: clamped to the ends, rates included.
  const auto first = spline.evaluate(S(1)), last = spline.evaluate(S(2.5));
  for (const double t : {0.99, -1e30, -std::numeric_limits<double>::infinity()}) {
    const auto p = spline.evaluate(S(t));
    EXPECT_EQ(GroupOf<G>::matrix(p.value), GroupOf<G>::matrix(first.value));
    EXPECT_EQ(p.velocity, first.velocity);
    EXPECT_EQ(p.acceleration, first.acceleration);
  }
  for (const double t : {2.51, 1e30, std::numeric_limits<double>::infinity()}) {
    const auto p = spline.evaluate(S(t));
    EXPECT_EQ(GroupOf<G>::matrix(p.value), GroupOf<G>::matrix(last.value));
    EXPECT_EQ(p.acceleration, last.acceleration);
  }
  // NaN: NaN numbers, no out-of-range read.
  const auto p = spline.evaluate(std::numeric_limits<S>::quiet_NaN());
  EXPECT_TRUE(GroupOf<G>::matrix(p.value).array().isNaN().any());
  EXPECT_TRUE(p.velocity.array().isNaN().all());
  EXPECT_TRUE(GroupOf<G>::matrix(spline(std::numeric_limits<S>::quiet_NaN())).array().isNaN().any());
}

// ---- automatic differentiation ---------------------------------------------------

using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;

/// d/dt through the spline of AD control elements (the double ones cast):
/// the element's derivative gives the body velocity (X^-1 dX/dt)^vee, and
/// the derivative of the analytic velocity the acceleration.
template <typename G>
void check_against_autodiff(unsigned seed) {
  using GA = decltype(std::declval<G>().template cast<AD>());
  const auto X = random_control<G>(7, 1.4, seed);
  std::vector<GA> XA;
  for (const auto& x : X) XA.push_back(x.template cast<AD>());
  const CubicBSplineView<G> spline(X.data(), 7, 0.25, 0.35);
  const CubicBSplineView<GA> spline_ad(XA.data(), 7, AD(0.25), AD(0.35));
  double worst_v = 0, worst_a = 0;
  for (double t = 0.26; t < 0.25 + 4 * 0.35; t += 0.0437) {
    const AD ta(t, 1, 0);  // the variable t
    const auto p = spline.evaluate(t);
    const auto pa = spline_ad.evaluate(ta);
    const auto M = GroupOf<GA>::matrix(pa.value);
    Eigen::Matrix<double, M.RowsAtCompileTime, M.ColsAtCompileTime> value, derivative;
    for (int i = 0; i < M.rows(); ++i)
      for (int j = 0; j < M.cols(); ++j) {
        value(i, j) = M(i, j).value();
        derivative(i, j) = M(i, j).derivatives()[0];
      }
    Eigen::Matrix<double, G::DoF, 1> v;
    if constexpr (std::is_same<G, SO3<double>>::value)
      v = SO3<double>::vee(value.transpose() * derivative);
    else
      v = G::vee(value.inverse() * derivative);
    Eigen::Matrix<double, G::DoF, 1> a, v_ad;
    for (int k = 0; k < G::DoF; ++k) {
      a[k] = pa.velocity[k].derivatives()[0];
      v_ad[k] = pa.velocity[k].value();
    }
    // The same arithmetic on the values (Eigen vectorizes double, not AD: rounding differs).
    EXPECT_LE((v_ad - p.velocity).cwiseAbs().maxCoeff(), 1e-14 * std::max(1.0, p.velocity.cwiseAbs().maxCoeff()));
    // Both sides are exact derivatives of the same computation in double:
    // they differ by rounding (tens of eps of the rates, which are ~10).
    worst_v = std::max(worst_v, (p.velocity - v).cwiseAbs().maxCoeff());
    worst_a = std::max(worst_a, (p.acceleration - a).cwiseAbs().maxCoeff());
  }
  EXPECT_LE(worst_v, 1e-12);
  EXPECT_LE(worst_a, 1e-11);
}

TEST(BSplineAutodiff, SO3RatesAreTheDerivativesInTime) {
  check_against_autodiff<SO3<double>>(23);
  check_against_autodiff<SO3<double>>(29);
}

TEST(BSplineAutodiff, SE3RatesAreTheDerivativesInTime) {
  check_against_autodiff<SE3<double>>(31);
  check_against_autodiff<SE3<double>>(37);
}

TEST(BSplineAutodiff, SO2SE2Sim3AndSE23RatesAreTheDerivativesInTime) {
  check_against_autodiff<SO2<double>>(41);
  check_against_autodiff<SE2<double>>(43);
  check_against_autodiff<SE2<double>>(47);
  check_against_autodiff<Sim3<double>>(53);
  check_against_autodiff<Sim3<double>>(59);
  check_against_autodiff<SE23<double>>(61);
}

}  // namespace

// ---- hostile input ------------------------------------------------------------------

// cubic_bspline_locate, the view's locate as a free function (the Python binding reads its four
// control elements where numpy holds them): O(1), the same segment and u as the view; times far
// outside, up to the largest finite ones, clamp to the ends (t - t0 may overflow to +-inf).
TYPED_TEST(BSpline, LocateIsTheViewsAndClampsEveryFiniteTime) {
  using G = TypeParam;
  using S = typename G::Scalar;
  const std::vector<G> control = random_control<G>(9, 0.8, 41);
  const S t0 = S(-3), dt = S(0.25);
  const CubicBSplineView<G> view(control.data(), 9, t0, dt);
  const S big = std::numeric_limits<S>::max();
  for (const S t : {S(-3), S(-2.9), S(-2), S(-1.5), S(-1.4), big, -big, S(1e30), S(-1e30)}) {
    const chasles::BSplineTime<S> a = chasles::cubic_bspline_locate<S>(9, t0, dt, t), b = view.locate(t);
    EXPECT_EQ(a.segment, b.segment) << t;
    EXPECT_EQ(a.u, b.u) << t;
    const BSplinePoint<G> p = view.evaluate(t);
    EXPECT_TRUE(GroupOf<G>::matrix(p.value).allFinite() && p.velocity.allFinite() && p.acceleration.allFinite()) << t;
  }
  const CubicBSplineView<G> far(control.data(), 9, -big, S(1));
  EXPECT_EQ(far.locate(big).segment, 5);  // t - t0 = inf: the last segment, u = 1
  EXPECT_EQ(far.locate(big).u, S(1));
  EXPECT_EQ(view.locate(big).segment, 5);
  EXPECT_EQ(view.locate(-big).segment, 0);
  EXPECT_EQ(view.locate(-big).u, S(0));
}
