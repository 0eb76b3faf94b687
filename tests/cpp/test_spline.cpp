// spline.hpp: the interpolating C2 spline passes through its keys; its body
// velocity and acceleration match central differences of the evaluated
// elements; velocity and acceleration are continuous at the interior keys;
// natural ends have zero acceleration; two keys give the geodesic; keys on a
// screw motion give that screw motion; the SE3 spline of pure rotations is the
// SO3 spline; the Jacobian coefficients agree on both sides of their series
// cutoff and with long double; autodiff through the evaluation gives the
// velocity; bad inputs are reported.
//
// Every group through the same code: SO2, SE2, Sim3 and SE23 splines pass through
// their keys with the rates of central differences, C2 at the keys (the
// acceleration's term (d/dt Jr) r' by forward differentiation of Jr); two
// keys give the geodesic and keys on a one-parameter subgroup that motion;
// that term equals the closed forms of SO3 and SE3 on both sides of their
// series cutoff; the SO2 spline is the natural cubic spline of the
// unwrapped angles (a long double tridiagonal solve).
#include <algorithm>
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

#include <chasles/spline.hpp>

#include "support/scalar_types.hpp"

namespace {

using chasles::fit_spline;
using chasles::SE2;
using chasles::SE23;
using chasles::SE3;
using chasles::Sim3;
using chasles::SO2;
using chasles::SO3;
using chasles::Spline;
using chasles::SplineEnds;
using chasles::SplineFit;
using chasles::SplineSample;
using chasles::SplineSegment;
using chasles::SplineStatus;
using chasles::SplineWork;

template <typename T>
class SplineTest : public ::testing::Test {};
using chasles_test::ScalarName;
using chasles_test::ScalarTypes;
TYPED_TEST_SUITE(SplineTest, ScalarTypes, ScalarName);

/// A fitted spline that owns its storage (the test's convenience; the library only views).
template <typename Group>
struct Fitted {
  using S = typename Group::Scalar;
  std::vector<S> times;
  std::vector<Group> keys;
  std::vector<SplineSegment<Group>> segments;
  std::vector<SplineWork<Group>> work;
  SplineFit fit{SplineStatus::ok, 0};
  Fitted(std::vector<S> t, std::vector<Group> k, SplineEnds ends = SplineEnds::natural)
      : times(std::move(t)), keys(std::move(k)), segments(keys.size() > 1 ? keys.size() - 1 : 1), work(keys.size()) {
    fit = fit_spline(static_cast<int>(keys.size()), times.data(), keys.data(), segments.data(), work.data(), ends);
  }
  Spline<Group> spline() const {
    return Spline<Group>(static_cast<int>(keys.size()), times.data(), keys.data(), segments.data());
  }
};

template <typename S>
Eigen::Matrix<S, 3, 1> normal3(std::mt19937_64& gen, double scale) {
  std::normal_distribution<double> normal(0, scale);
  return Eigen::Vector3d(normal(gen), normal(gen), normal(gen)).cast<S>();
}

/// Irregular increasing times: steps uniform in [0.3, 1.0].
template <typename S>
std::vector<S> random_times(std::mt19937_64& gen, int n) {
  std::uniform_real_distribution<double> step(0.3, 1.0);
  std::vector<S> t;
  double now = -0.7;
  for (int i = 0; i < n; ++i) {
    t.push_back(S(now));
    now += step(gen);
  }
  return t;
}

/// Keys that walk: each step a random rotation of about 0.6 rad (and 0.5 m).
template <typename Group>
std::vector<Group> random_walk(std::mt19937_64& gen, int n);
template <>
std::vector<SO3<double>> random_walk(std::mt19937_64& gen, int n) {
  std::vector<SO3<double>> out{SO3<double>::exp(normal3<double>(gen, 1.0))};
  for (int i = 1; i < n; ++i) out.push_back(out.back() * SO3<double>::exp(normal3<double>(gen, 0.35)));
  return out;
}
template <>
std::vector<SE3<double>> random_walk(std::mt19937_64& gen, int n) {
  std::vector<SE3<double>> out{SE3<double>(SO3<double>::exp(normal3<double>(gen, 1.0)), normal3<double>(gen, 1.0))};
  for (int i = 1; i < n; ++i) {
    Eigen::Matrix<double, 6, 1> xi;
    xi << normal3<double>(gen, 0.3), normal3<double>(gen, 0.35);
    out.push_back(out.back() * SE3<double>::exp(xi));
  }
  return out;
}
/// The other groups: a start exp(N(0, 1) per coordinate), steps exp(N(0, 0.35^2) per coordinate).
template <typename Group>
std::vector<Group> random_walk(std::mt19937_64& gen, int n) {
  std::normal_distribution<double> start(0, 1.0), step(0, 0.35);
  const auto tangent = [&](std::normal_distribution<double>& d) {
    typename Group::Tangent x;
    for (int k = 0; k < Group::DoF; ++k) x[k] = d(gen);
    return x;
  };
  std::vector<Group> out{Group::exp(tangent(start))};
  for (int i = 1; i < n; ++i) out.push_back(out.back() * Group::exp(tangent(step)));
  return out;
}
template <typename S, template <typename> class G>
std::vector<G<S>> cast_all(const std::vector<G<double>>& in) {
  std::vector<G<S>> out;
  for (const auto& x : in) out.push_back(x.template cast<S>());
  return out;
}

template <typename Group>
double distance(const Group& a, const Group& b) {
  return static_cast<double>((a.inverse() * b).log().norm());
}

template <typename S, template <typename> class G>
void check_keys_and_differences() {
  using Group = G<S>;
  using Tangent = Eigen::Matrix<S, Group::DoF, 1>;
  const bool is_float = std::is_same<S, float>::value;
  const double eps = std::numeric_limits<S>::epsilon();
  std::mt19937_64 gen(20261124);
  for (int trial = 0; trial < 5; ++trial) {
    const int n = 2 + trial * 3;
    const Fitted<Group> f(random_times<S>(gen, n), cast_all<S>(random_walk<G<double>>(gen, n)));
    ASSERT_EQ(f.fit.status, SplineStatus::ok) << "n = " << n;
    const Spline<Group> sp = f.spline();
    // Through the keys, to the rounding of log/exp over one segment.
    for (int i = 0; i < n; ++i) EXPECT_LT(distance(sp(f.times[i]).element, f.keys[i]), 64 * eps) << "key " << i;
    // Central differences of the evaluated elements: y(d) = log(X(t)^-1 X(t + d)) = V d + V' d^2 / 2 + O(d^3), so
    // V ~ (y(d) - y(-d)) / (2 d) and V' ~ (y(d) + y(-d)) / d^2, both with error O(d^2) |derivatives| (of order 10
    // here: rates ~ 1 rad/s over steps ~ 0.6 s) plus rounding eps / d (velocity) and eps / d^2 (acceleration).
    // d balances the two: double d = 1e-4 (velocity error ~ 1e-7, acceleration ~ 1e-7 + 2e-8), float d = 3e-2 for
    // the velocity (~ 1e-2 + 4e-6) and 6e-2 for the acceleration (~ 4e-2 + 3e-5); the bounds are a few times those.
    const double dv = is_float ? 3e-2 : 1e-4, da = is_float ? 6e-2 : 1e-4;
    const double tol_v = is_float ? 5e-2 : 1e-6, tol_a = is_float ? 2e-1 : 1e-5;
    std::uniform_real_distribution<double> u(static_cast<double>(f.times.front()), static_cast<double>(f.times.back()));
    for (int k = 0; k < 20; ++k) {
      const double t = u(gen);
      const SplineSample<Group> x = sp(S(t));
      EXPECT_TRUE(sp.element(S(t)).matrix() == x.element.matrix()) << "element() is sample's element, t = " << t;
      const auto y = [&](double d) -> Eigen::Matrix<double, Group::DoF, 1> {
        return (x.element.inverse() * sp(S(t + d)).element).log().template cast<double>();
      };
      const Eigen::Matrix<double, Group::DoF, 1> v_fd = (y(dv) - y(-dv)) / (2 * dv);
      const Eigen::Matrix<double, Group::DoF, 1> a_fd = (y(da) + y(-da)) / (da * da);
      const double scale_v = 1 + x.velocity.template cast<double>().norm();
      const double scale_a = 1 + x.acceleration.template cast<double>().norm();
      EXPECT_LT((x.velocity.template cast<double>() - v_fd).norm(), tol_v * scale_v) << "t = " << t;
      EXPECT_LT((x.acceleration.template cast<double>() - a_fd).norm(), tol_a * scale_a) << "t = " << t;
    }
    // C2 at the interior keys: the left limit (segment k - 1 at its end) equals the right limit (segment k at 0).
    // The fit stops with a step <= spline_step_tolerance (1 + |w|): the rates are within ~ that of the exact
    // solution, and the acceleration mismatch is ~ 6/h times it: bounds 1e-9 (double) and 1e-3 (float).
    const double tol_c2 = is_float ? 1e-3 : 1e-9;
    for (int k = 1; k + 1 < n; ++k) {
      const SplineSample<Group> left = sp.sample(k - 1, f.times[k] - f.times[k - 1]);
      const SplineSample<Group> right = sp.sample(k, S(0));
      const double scale =
          1 + right.velocity.template cast<double>().norm() + right.acceleration.template cast<double>().norm();
      EXPECT_LT(distance(left.element, f.keys[k]), 64 * eps) << "key " << k;
      EXPECT_LT((left.velocity - right.velocity).template cast<double>().norm(), 64 * eps * scale) << "key " << k;
      EXPECT_LT((left.acceleration - right.acceleration).template cast<double>().norm(), tol_c2 * scale) << "key " << k;
    }
    // Natural ends: no acceleration at the first and the last key.
    const Tangent a0 = sp.sample(0, S(0)).acceleration;
    const Tangent an = sp.sample(n - 2, f.times[n - 1] - f.times[n - 2]).acceleration;
    EXPECT_LT(a0.template cast<double>().norm(), 1e3 * eps);
    EXPECT_LT(an.template cast<double>().norm(),
              tol_c2 * (1 + sp.sample(n - 2, S(0)).velocity.template cast<double>().norm()));
  }
}

TYPED_TEST(SplineTest, SO3ThroughKeysDifferencesC2) { check_keys_and_differences<TypeParam, SO3>(); }
TYPED_TEST(SplineTest, SE3ThroughKeysDifferencesC2) { check_keys_and_differences<TypeParam, SE3>(); }
TYPED_TEST(SplineTest, SO2ThroughKeysDifferencesC2) { check_keys_and_differences<TypeParam, SO2>(); }
TYPED_TEST(SplineTest, SE2ThroughKeysDifferencesC2) { check_keys_and_differences<TypeParam, SE2>(); }
TYPED_TEST(SplineTest, Sim3ThroughKeysDifferencesC2) { check_keys_and_differences<TypeParam, Sim3>(); }
TYPED_TEST(SplineTest, SE23ThroughKeysDifferencesC2) { check_keys_and_differences<TypeParam, SE23>(); }

TYPED_TEST(SplineTest, ChordEndsHaveTheFirstAndLastSegmentsRates) {
  using S = TypeParam;
  std::mt19937_64 gen(7);
  const int n = 6;
  const Fitted<SE3<S>> f(random_times<S>(gen, n), cast_all<S>(random_walk<SE3<double>>(gen, n)), SplineEnds::chord);
  ASSERT_EQ(f.fit.status, SplineStatus::ok);
  const double eps = std::numeric_limits<S>::epsilon();
  const Spline<SE3<S>> sp = f.spline();
  const auto w0 = ((f.keys[0].inverse() * f.keys[1]).log() / (f.times[1] - f.times[0])).eval();
  const auto wn = ((f.keys[n - 2].inverse() * f.keys[n - 1]).log() / (f.times[n - 1] - f.times[n - 2])).eval();
  EXPECT_LT((sp(f.times[0]).velocity - w0).template cast<double>().norm(),
            64 * eps * (1 + w0.template cast<double>().norm()));
  EXPECT_LT((sp(f.times[n - 1]).velocity - wn).template cast<double>().norm(),
            64 * eps * (1 + wn.template cast<double>().norm()));
}

template <typename S, template <typename> class G>
void check_geodesic() {
  using Group = G<S>;
  using Tangent = Eigen::Matrix<S, Group::DoF, 1>;
  const double eps = std::numeric_limits<S>::epsilon();
  std::mt19937_64 gen(11);
  for (int trial = 0; trial < 10; ++trial) {
    const std::vector<Group> keys = cast_all<S>(random_walk<G<double>>(gen, 2));
    for (SplineEnds ends : {SplineEnds::natural, SplineEnds::chord}) {
      const Fitted<Group> f({S(0.25), S(1.75)}, keys, ends);
      ASSERT_EQ(f.fit.status, SplineStatus::ok);
      const Tangent D = (keys[0].inverse() * keys[1]).log();
      const Tangent V = D / S(1.5);
      const double scale = 1 + V.template cast<double>().norm();
      for (double t : {-0.5, 0.25, 0.6, 1.0, 1.75, 2.5}) {
        const SplineSample<Group> x = f.spline()(S(t));
        const Group geodesic = keys[0] * Group::exp(Tangent(S((t - 0.25) / 1.5) * D));
        EXPECT_LT(distance(x.element, geodesic), 64 * eps * scale) << t;
        EXPECT_LT((x.velocity - V).template cast<double>().norm(), 64 * eps * scale) << t;
        EXPECT_LT(x.acceleration.template cast<double>().norm(), 64 * eps * scale) << t;
      }
    }
  }
}
TYPED_TEST(SplineTest, TwoKeysGiveTheGeodesic) {
  check_geodesic<TypeParam, SO3>();
  check_geodesic<TypeParam, SE3>();
  check_geodesic<TypeParam, SO2>();
  check_geodesic<TypeParam, SE2>();
  check_geodesic<TypeParam, Sim3>();
  check_geodesic<TypeParam, SE23>();
}

template <typename S, template <typename> class G>
void check_screw() {
  using Group = G<S>;
  using Tangent = Eigen::Matrix<S, Group::DoF, 1>;
  const double eps = std::numeric_limits<S>::epsilon();
  std::mt19937_64 gen(3);
  for (int trial = 0; trial < 5; ++trial) {
    const Group start = cast_all<S>(random_walk<G<double>>(gen, 1))[0];
    Eigen::Matrix<double, Group::DoF, 1> xd;
    for (int j = 0; j < Group::DoF; ++j) xd[j] = std::normal_distribution<double>(0, 1.0)(gen);
    const Tangent xi = xd.template cast<S>();  // |w| ~ 1.6 rad/s, steps <= 1 s: each step's angle < pi
    const int n = 3 + 2 * trial;
    const std::vector<S> times = random_times<S>(gen, n);
    std::vector<Group> keys;
    for (S t : times) keys.push_back(start * Group::exp(Tangent(t * xi)));
    const Fitted<Group> f(times, keys);
    ASSERT_EQ(f.fit.status, SplineStatus::ok);
    EXPECT_LE(f.fit.iterations, 2);
    const double scale = 1 + xd.norm() * (1 + std::abs(static_cast<double>(times.back())));
    std::uniform_real_distribution<double> u(static_cast<double>(times.front()), static_cast<double>(times.back()));
    for (int k = 0; k < 20; ++k) {
      const double t = u(gen);
      const SplineSample<Group> x = f.spline()(S(t));
      EXPECT_LT(distance(x.element, Group(start * Group::exp(Tangent(S(t) * xi)))), 256 * eps * scale) << t;
      EXPECT_LT((x.velocity - xi).template cast<double>().norm(), 256 * eps * scale) << t;
      EXPECT_LT(x.acceleration.template cast<double>().norm(), 256 * eps * scale) << t;
    }
  }
}
TYPED_TEST(SplineTest, KeysOnAScrewMotionGiveThatScrewMotion) {
  check_screw<TypeParam, SO3>();
  check_screw<TypeParam, SE3>();
  check_screw<TypeParam, SO2>();
  check_screw<TypeParam, SE2>();
  check_screw<TypeParam, Sim3>();
  check_screw<TypeParam, SE23>();
}

// The term of the acceleration by forward differentiation of Jr equals the
// closed forms of SO3 and SE3 (Kolesnikov's coefficients), on both sides of
// their series cutoff (|r| below and above 2).
template <template <typename> class G>
void check_dual_rates_against_closed_forms() {
  using Group = G<double>;
  using T = Eigen::Matrix<double, Group::DoF, 1>;
  std::mt19937_64 gen(17);
  std::normal_distribution<double> normal(0, 1);
  for (const double size : {1e-6, 0.3, 1.5, 2.5, 3.1}) {
    for (int trial = 0; trial < 20; ++trial) {
      T r, r1, r2;
      for (int k = 0; k < Group::DoF; ++k) {
        r[k] = normal(gen);
        r1[k] = normal(gen);
        r2[k] = normal(gen);
      }
      r *= size / r.template tail<3>().norm();  // the rotation angle |w| = size
      T v, a, v_dual, a_dual;
      chasles::detail::spline_rates(static_cast<const Group*>(nullptr), r, r1, r2, v, a);
      chasles::detail::spline_rates_dual<Group>(r, r1, r2, v_dual, a_dual);
      const double scale = 1 + r.norm() * (1 + r1.norm()) * (1 + r1.norm() + r2.norm());
      EXPECT_LT((v - v_dual).norm(), 64 * std::numeric_limits<double>::epsilon() * scale) << size;
      EXPECT_LT((a - a_dual).norm(), 64 * std::numeric_limits<double>::epsilon() * scale) << size;
    }
  }
}
TEST(SplineDualRates, EqualTheClosedFormsOfSO3AndSE3) {
  check_dual_rates_against_closed_forms<SO3>();
  check_dual_rates_against_closed_forms<SE3>();
}

// SO(2) is commutative (Jr = 1): its spline is the classical cubic spline of
// the unwrapped angles theta_0 + sum_j log(X_j^-1 X_{j+1}), natural or with
// the chord slopes at the ends; solved here in long double as a tridiagonal
// system in the slopes m_i (2 h_{k-1}^-1 m_{k-1} + 4 (h_{k-1}^-1 + h_k^-1) m_k
// + 2 h_k^-1 m_{k+1} = 6 (D_{k-1} / h_{k-1}^2 + D_k / h_k^2)).
TEST(SplineSO2, IsTheCubicSplineOfTheUnwrappedAngles) {
  using LD = long double;
  std::mt19937_64 gen(23);
  const int n = 9;
  const std::vector<double> times = random_times<double>(gen, n);
  const std::vector<SO2<double>> keys = random_walk<SO2<double>>(gen, n);
  for (SplineEnds ends : {SplineEnds::natural, SplineEnds::chord}) {
    const Fitted<SO2<double>> f(times, keys, ends);
    ASSERT_EQ(f.fit.status, SplineStatus::ok);
    std::vector<LD> h(n - 1), D(n - 1), theta(n);
    theta[0] = keys[0].angle();
    for (int i = 0; i + 1 < n; ++i) {
      h[i] = LD(times[i + 1]) - LD(times[i]);
      D[i] = (keys[i].inverse() * keys[i + 1]).angle();
      theta[i + 1] = theta[i] + D[i];
    }
    // Rows a_i m_{i-1} + b_i m_i + c_i m_{i+1} = d_i, solved by the Thomas algorithm.
    std::vector<LD> a(n, 0), b(n, 0), c(n, 0), d(n, 0), m(n);
    for (int i = 0; i < n; ++i) {
      const bool first = i == 0, last = i == n - 1;
      if ((first || last) && ends == SplineEnds::chord) {
        b[i] = 1;
        d[i] = first ? D[0] / h[0] : D[n - 2] / h[n - 2];
        continue;
      }
      if (!first) {
        a[i] = 2 / h[i - 1];
        b[i] += 4 / h[i - 1];
        d[i] += 6 * D[i - 1] / (h[i - 1] * h[i - 1]);
      }
      if (!last) {
        c[i] = 2 / h[i];
        b[i] += 4 / h[i];
        d[i] += 6 * D[i] / (h[i] * h[i]);
      }
    }
    for (int i = 1; i < n; ++i) {
      const LD w = a[i] / b[i - 1];
      b[i] -= w * c[i - 1];
      d[i] -= w * d[i - 1];
    }
    m[n - 1] = d[n - 1] / b[n - 1];
    for (int i = n - 2; i >= 0; --i) m[i] = (d[i] - c[i] * m[i + 1]) / b[i];
    // The Hermite cubic of each segment, its value and its first two derivatives.
    std::uniform_real_distribution<double> u(times.front(), times.back());
    for (int k = 0; k < 50; ++k) {
      const double t = u(gen);
      int i = 0;
      while (i + 2 < n && times[i + 1] <= t) ++i;
      const LD s = (LD(t) - LD(times[i])) / h[i], hh = h[i];
      const LD h00 = 2 * s * s * s - 3 * s * s + 1, h10 = s * s * s - 2 * s * s + s, h01 = -2 * s * s * s + 3 * s * s,
               h11 = s * s * s - s * s;
      const LD value = h00 * theta[i] + h10 * hh * m[i] + h01 * theta[i + 1] + h11 * hh * m[i + 1];
      const LD slope = ((6 * s * s - 6 * s) * theta[i] + (3 * s * s - 4 * s + 1) * hh * m[i] +
                        (-6 * s * s + 6 * s) * theta[i + 1] + (3 * s * s - 2 * s) * hh * m[i + 1]) /
                       hh;
      const LD curvature = ((12 * s - 6) * theta[i] + (6 * s - 4) * hh * m[i] + (-12 * s + 6) * theta[i + 1] +
                            (6 * s - 2) * hh * m[i + 1]) /
                           (hh * hh);
      const SplineSample<SO2<double>> x = f.spline()(t);
      const LD err = std::remainder(LD(x.element.angle()) - value, 2 * std::acos(LD(-1)));
      const double eps = std::numeric_limits<double>::epsilon();
      EXPECT_LT(std::fabs(double(err)), 64 * eps * (1 + std::fabs(double(value)))) << t;
      EXPECT_NEAR(x.velocity[0], double(slope), 256 * eps * (1 + std::fabs(double(slope)))) << t;
      EXPECT_NEAR(x.acceleration[0], double(curvature), 1024 * eps * (1 + std::fabs(double(curvature)))) << t;
    }
  }
}

TYPED_TEST(SplineTest, SE3OfPureRotationsIsTheSO3Spline) {
  using S = TypeParam;
  const double eps = std::numeric_limits<S>::epsilon();
  std::mt19937_64 gen(5);
  const int n = 7;
  const std::vector<S> times = random_times<S>(gen, n);
  const std::vector<SO3<S>> rs = cast_all<S>(random_walk<SO3<double>>(gen, n));
  std::vector<SE3<S>> gs;
  for (const auto& r : rs) gs.push_back(SE3<S>(r, Eigen::Matrix<S, 3, 1>::Zero()));
  for (SplineEnds ends : {SplineEnds::natural, SplineEnds::chord}) {
    const Fitted<SO3<S>> fr(times, rs, ends);
    const Fitted<SE3<S>> fg(times, gs, ends);
    ASSERT_EQ(fr.fit.status, SplineStatus::ok);
    ASSERT_EQ(fg.fit.status, SplineStatus::ok);
    for (double t = -0.5; t < static_cast<double>(times.back()) + 0.5; t += 0.37) {
      const SplineSample<SO3<S>> a = fr.spline()(S(t));
      const SplineSample<SE3<S>> b = fg.spline()(S(t));
      const double scale =
          1 + a.velocity.template cast<double>().norm() + a.acceleration.template cast<double>().norm();
      EXPECT_LT(distance(a.element, b.element.rotation()), 64 * eps * scale) << t;
      EXPECT_EQ(b.element.translation().template cast<double>().norm(), 0.0) << t;
      EXPECT_LT((a.velocity - b.velocity.template tail<3>()).template cast<double>().norm(), 64 * eps * scale) << t;
      EXPECT_LT((a.acceleration - b.acceleration.template tail<3>()).template cast<double>().norm(), 256 * eps * scale)
          << t;
      EXPECT_EQ(b.velocity.template head<3>().template cast<double>().norm(), 0.0) << t;
      EXPECT_EQ(b.acceleration.template head<3>().template cast<double>().norm(), 0.0) << t;
    }
  }
}

TYPED_TEST(SplineTest, BadInputsAreReported) {
  using S = TypeParam;
  const std::vector<SO3<S>> keys(3);
  std::vector<SplineSegment<SO3<S>>> seg(2);
  std::vector<SplineWork<SO3<S>>> work(3);
  const S nan = std::numeric_limits<S>::quiet_NaN(), inf = std::numeric_limits<S>::infinity();
  EXPECT_EQ(fit_spline(1, std::vector<S>{S(0)}.data(), keys.data(), seg.data(), work.data()).status,
            SplineStatus::too_few_keys);
  for (const std::vector<S>& t : {std::vector<S>{0, 1, 1}, std::vector<S>{0, 2, 1}, std::vector<S>{0, nan, 2},
                                  std::vector<S>{0, 1, inf}, std::vector<S>{-inf, 1, 2}}) {
    EXPECT_EQ(fit_spline(3, t.data(), keys.data(), seg.data(), work.data()).status, SplineStatus::times_not_increasing);
  }
}

// The Jacobian coefficients a, b and their s-derivatives: series below spline_series_theta2, closed forms above.
// Both sides of the cutoff against long double (series to s^12 in long double, exact there to ~1e-19) and the
// derivatives against long double central differences of a and b.
template <typename T>
std::array<T, 6> coeffs(T s) {
  const auto k = chasles::detail::jacobian_coefficients<T>(s);
  return {k.a, k.b, k.a1, k.b1, k.a2, k.b2};
}
TEST(SplineCoefficients, BothSidesOfTheSeriesCutoffAgreeWithLongDouble) {
  const double cut = chasles::Thresholds<double>::spline_series_theta2;
  for (double s :
       {0.0, 1e-12, 1e-4, 0.5, std::nextafter(cut, 0.0), cut, std::nextafter(cut, 10.0), 5.0, 9.0, 30.0, 100.0}) {
    const std::array<double, 6> d = coeffs<double>(s);
    const std::array<long double, 6> l = coeffs<long double>(s);
    for (int j = 0; j < 6; ++j) {
      const double rel = std::abs(static_cast<double>((static_cast<long double>(d[j]) - l[j]) / l[j]));
      EXPECT_LT(rel, 400 * std::numeric_limits<double>::epsilon()) << "s = " << s << " coefficient " << j;
    }
    const float sf = static_cast<float>(s);
    const std::array<float, 6> f = coeffs<float>(sf);
    const std::array<long double, 6> lf = coeffs<long double>(static_cast<long double>(sf));
    for (int j = 0; j < 6; ++j) {
      const double rel = std::abs(static_cast<double>((static_cast<long double>(f[j]) - lf[j]) / lf[j]));
      EXPECT_LT(rel, 400 * std::numeric_limits<float>::epsilon()) << "s = " << s << " coefficient " << j;
    }
  }
  // The derivatives are those of a and b (long double central differences, step 1e-5: error ~1e-10).
  for (long double s : {0.3L, 2.0L, 4.0L, 7.0L, 40.0L}) {
    const long double d = 1e-5L;
    const auto p = coeffs<long double>(s + d), m = coeffs<long double>(s - d), c = coeffs<long double>(s);
    EXPECT_NEAR(static_cast<double>((p[0] - m[0]) / (2 * d)), static_cast<double>(c[2]), 1e-9) << s;
    EXPECT_NEAR(static_cast<double>((p[1] - m[1]) / (2 * d)), static_cast<double>(c[3]), 1e-9) << s;
    EXPECT_NEAR(static_cast<double>((p[2] - m[2]) / (2 * d)), static_cast<double>(c[4]), 1e-9) << s;
    EXPECT_NEAR(static_cast<double>((p[3] - m[3]) / (2 * d)), static_cast<double>(c[5]), 1e-9) << s;
  }
}

// Autodiff through the fit and the evaluation: dX/dt = X [V] with V the analytic body velocity.
TEST(SplineAutodiff, TimeDerivativeOfTheElementIsTheBodyVelocity) {
  using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 1, 1>>;
  std::mt19937_64 gen(9);
  const int n = 5;
  const std::vector<double> td = random_times<double>(gen, n);
  const std::vector<SE3<double>> kd = random_walk<SE3<double>>(gen, n);
  std::vector<AD> times;
  std::vector<SE3<AD>> keys;
  for (int i = 0; i < n; ++i) {
    times.push_back(AD(td[i]));
    keys.push_back(kd[i].cast<AD>());
  }
  const Fitted<SE3<AD>> f(times, keys);
  ASSERT_EQ(f.fit.status, SplineStatus::ok);
  const Fitted<SE3<double>> fd(td, kd);
  for (double t : {-0.5, 0.1, 0.9, 1.7}) {
    const SplineSample<SE3<AD>> x = f.spline()(AD(t, Eigen::Matrix<double, 1, 1>(1.0)));
    Eigen::Matrix4d M, dM;
    const Eigen::Matrix<AD, 4, 4> Ma = x.element.matrix();
    for (int r = 0; r < 4; ++r)
      for (int c = 0; c < 4; ++c) {
        M(r, c) = Ma(r, c).value();
        dM(r, c) = Ma(r, c).derivatives()(0);
      }
    const SplineSample<SE3<double>> y = fd.spline()(t);
    const Eigen::Matrix4d Vhat = M.inverse() * dM;
    Eigen::Matrix<double, 6, 1> v;
    v << Vhat(0, 3), Vhat(1, 3), Vhat(2, 3), Vhat(2, 1), Vhat(0, 2), Vhat(1, 0);
    EXPECT_LT((v - y.velocity).norm(), 1e-12 * (1 + y.velocity.norm())) << t;
  }
}

}  // namespace

// ---- hostile input ------------------------------------------------------------------

// The segment search is std::upper_bound's over the interior times (a binary search, O(log n)), for
// pointers and for strided Eigen maps (the binding's view of numpy's memory): at the keys, between,
// before, after and NaN.
TEST(SplineSegmentIndex, IsUpperBoundOverTheInteriorTimes) {
  std::mt19937_64 gen(5);
  for (const int n : {2, 3, 4, 7, 64, 1000}) {
    const std::vector<double> t = random_times<double>(gen, n);
    std::vector<double> strided(2 * static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) strided[2 * static_cast<std::size_t>(i)] = t[static_cast<std::size_t>(i)];
    const Eigen::Map<const Eigen::VectorXd, Eigen::Unaligned, Eigen::InnerStride<2>> map(strided.data(), n);
    std::vector<double> probes{t.front() - 5, t.back() + 5, -1e300, 1e300};
    for (int i = 0; i < n; ++i) {
      probes.push_back(t[static_cast<std::size_t>(i)]);
      probes.push_back(std::nextafter(t[static_cast<std::size_t>(i)], -1e9));
      probes.push_back(t[static_cast<std::size_t>(i)] + 0.1);
    }
    for (const double x : probes) {
      const int want = static_cast<int>(std::upper_bound(t.data() + 1, t.data() + n - 1, x) - t.data()) - 1;
      EXPECT_EQ(chasles::spline_segment_index(n, t.data(), x), want) << n << " " << x;
      EXPECT_EQ(chasles::spline_segment_index(n, map, x), want) << n << " " << x;
    }
    EXPECT_EQ(chasles::spline_segment_index(n, t.data(), std::numeric_limits<double>::quiet_NaN()), n - 2);
  }
}

// A view over fewer than two keys has no segment: the constructor asserts (eigen_assert; the tests
// keep assertions on) instead of reading segment 0 of an empty array.
TEST(SplineDeathTest, ViewOverFewerThanTwoKeysAsserts) {
  const std::vector<double> t{0.0};
  const std::vector<SO3<double>> k(1);
  const SplineSegment<SO3<double>>* none = nullptr;
  EXPECT_DEATH((void)Spline<SO3<double>>(1, t.data(), k.data(), none).element(0.5), "");
  EXPECT_DEATH((void)Spline<SO3<double>>(0, nullptr, nullptr, none)(0.5), "");
  std::vector<SplineSegment<SO3<double>>> seg(1);
  std::vector<SplineWork<SO3<double>>> work(1);
  EXPECT_EQ(fit_spline(1, t.data(), k.data(), seg.data(), work.data()).status, SplineStatus::too_few_keys);
  EXPECT_EQ(fit_spline(0, t.data(), k.data(), seg.data(), work.data()).status, SplineStatus::too_few_keys);
}

// Steps whose cubic coefficients (~D/h^3) or accelerations (~D/h^2) leave the floating-point range are
// reported as such (step_out_of_range), after an unsorted time anywhere; the steps at the bounds of
// constants.hpp are fitted and pass through the keys, with the velocity of the geodesic between two.
template <typename S, template <typename> class G>
void check_step_range() {
  using Group = G<S>;
  using T = chasles::Thresholds<S>;
  std::mt19937_64 gen(8);
  const std::vector<Group> keys = cast_all<S>(random_walk<G<double>>(gen, 4));
  const S lo = T::spline_min_step, hi = T::spline_max_step;
  for (const S h : {S(lo / 10), S(hi * 10), std::numeric_limits<S>::denorm_min(), std::numeric_limits<S>::max() / 4}) {
    const Fitted<Group> f({S(0), h, S(2) * h, S(3) * h}, keys);
    EXPECT_EQ(f.fit.status, SplineStatus::step_out_of_range) << h;
  }
  const Fitted<Group> unsorted({S(0), lo / 10, S(-1), S(1)}, keys);  // a tiny step, then a step back
  EXPECT_EQ(unsorted.fit.status, SplineStatus::times_not_increasing);
  for (const S h : {S(lo * S(1.5)), S(hi / S(1.5))}) {  // within the bounds after the rounding of 2 h, 3 h
    const Fitted<Group> f({S(0), h, S(2) * h, S(3) * h}, keys);
    ASSERT_EQ(f.fit.status, SplineStatus::ok) << h;
    const Spline<Group> s = f.spline();
    const double tol = 64 * std::numeric_limits<S>::epsilon();
    for (int i = 0; i < 4; ++i)
      EXPECT_LT(distance(s.element(f.times[static_cast<std::size_t>(i)]), keys[static_cast<std::size_t>(i)]), tol) << h;
    for (int i = 0; i < 3; ++i) {
      const SplineSample<Group> x = s(f.times[static_cast<std::size_t>(i)] + h / S(2));
      ASSERT_TRUE(x.element.matrix().allFinite() && x.velocity.allFinite() && x.acceleration.allFinite()) << h;
      // rates of order |D| / h and |D| / h^2: the step's log over h, to the fit's accuracy
      const auto D = (keys[static_cast<std::size_t>(i)].inverse() * keys[static_cast<std::size_t>(i) + 1]).log();
      EXPECT_LT(static_cast<double>((x.velocity * h).norm()), 10 * static_cast<double>(D.norm()) + 1) << h;
    }
  }
  const Fitted<Group> two({S(0), lo}, {keys[0], keys[1]});
  ASSERT_EQ(two.fit.status, SplineStatus::ok);
  const auto D = (keys[0].inverse() * keys[1]).log();
  const SplineSample<Group> mid = two.spline()(lo / S(2));
  EXPECT_LT(static_cast<double>((mid.velocity * lo - D).norm()),
            1e3 * std::numeric_limits<S>::epsilon() * (1 + static_cast<double>(D.norm())));
}
TYPED_TEST(SplineTest, TimeStepsOutsideTheRangeAreReported) {
  check_step_range<TypeParam, SO3>();
  check_step_range<TypeParam, SE3>();
}

// Outside the keys the end segment's cubic continues to spline_max_extrapolation segment lengths from
// the end key, then holds: for every finite t the element is a group element and the rates are finite
// (the cubic at t = 1e110 overflowed: NaN).
template <typename S, template <typename> class G>
void check_extrapolation() {
  using Group = G<S>;
  std::mt19937_64 gen(9);
  const Fitted<Group> f(random_times<S>(gen, 5), cast_all<S>(random_walk<G<double>>(gen, 5)));
  ASSERT_EQ(f.fit.status, SplineStatus::ok);
  const Spline<Group> s = f.spline();
  const S K = chasles::Thresholds<S>::spline_max_extrapolation;
  const S t0 = f.times.front(), t1 = f.times[1], tl = f.times.back(), tp = f.times[3];
  // within the range of the cubic: the cubic itself (sample at the raw offset)
  for (const S x : {S(tl + (tl - tp)), S(tl + S(10) * (tl - tp))}) {
    const SplineSample<Group> a = s(x), b = s.sample(3, x - tp);
    EXPECT_EQ(a.element.matrix(), b.element.matrix()) << x;
    EXPECT_EQ(a.velocity, b.velocity) << x;
  }
  const SplineSample<Group> last = s.sample(3, (K + S(1)) * (tl - tp)), first = s.sample(0, -K * (t1 - t0));
  ASSERT_TRUE(last.element.matrix().allFinite() && last.velocity.allFinite() && last.acceleration.allFinite());
  ASSERT_TRUE(first.element.matrix().allFinite() && first.velocity.allFinite() && first.acceleration.allFinite());
  const S big = std::numeric_limits<S>::max();
  for (const S x : {S(1e30), S(big / 2), big, S(tl + S(2) * K * (tl - tp))}) {
    const SplineSample<Group> a = s(x);
    EXPECT_EQ(a.element.matrix(), last.element.matrix()) << x;
    EXPECT_EQ(a.velocity, last.velocity) << x;
    EXPECT_EQ(a.acceleration, last.acceleration) << x;
    EXPECT_EQ(s.element(x).matrix(), last.element.matrix()) << x;
    const SplineSample<Group> b = s(-x);
    EXPECT_EQ(b.element.matrix(), first.element.matrix()) << x;
    EXPECT_EQ(b.acceleration, first.acceleration) << x;
  }
  const Eigen::Matrix<S, 3, 3> R = last.element.matrix().template topLeftCorner<3, 3>();
  EXPECT_LT(static_cast<double>((R.transpose() * R - Eigen::Matrix<S, 3, 3>::Identity()).norm()),
            1e3 * std::numeric_limits<S>::epsilon());
  const SplineSample<Group> nan = s(std::numeric_limits<S>::quiet_NaN());
  EXPECT_TRUE(nan.velocity.hasNaN());
}
TYPED_TEST(SplineTest, ExtrapolationHoldsPastItsBoundForEveryFiniteTime) {
  check_extrapolation<TypeParam, SO3>();
  check_extrapolation<TypeParam, SE3>();
}
TEST(SplineExtrapolation, DoubleAtTheTimesOfTheReport) {
  std::mt19937_64 gen(10);
  const Fitted<SE3<double>> f(random_times<double>(gen, 3), random_walk<SE3<double>>(gen, 3));
  const Spline<SE3<double>> s = f.spline();
  for (const double x : {1e110, -1e110, 1e200, 1e308}) {
    const SplineSample<SE3<double>> a = s(x);
    EXPECT_TRUE(a.element.matrix().allFinite() && a.velocity.allFinite() && a.acceleration.allFinite()) << x;
  }
}
