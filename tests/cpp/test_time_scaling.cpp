// time_scaling.hpp: the cubic, quintic and trapezoidal time scalings and the
// straight-line joint trajectory (Lynch and Park, "Modern Robotics", ch. 9):
// - the boundary values (s = 0 and 1, rest at both ends, and for the quintic
//   zero acceleration), the symmetry s(T - t) = 1 - s(t), clamping outside
//   [0, T] and NaN for an invalid duration, peak velocity ratio or time
//   (typed: float, double and an autodiff scalar);
// - s_dot and s_ddot against central differences of the long double s and
//   s_dot, and against automatic differentiation in t (and in T and k);
// - the trapezoid's peak velocity v = k / T, its acceleration
//   a = v^2 / (v T - 1) and phase durations, and the triangle at k = 2;
// - numbers of the modern_robotics package (CubicTimeScaling,
//   QuinticTimeScaling, JointTrajectory);
// - joint_trajectory: exact end points, its derivatives, fixed, maximum and
//   dynamic sizes, and no allocation for fixed and maximum sizes.
#define EIGEN_RUNTIME_NO_MALLOC  // Eigen::internal::set_is_malloc_allowed below
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <type_traits>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <chasles/time_scaling.hpp>

namespace {

using chasles::TimeScaling;
using chasles::TimeScalingKind;
using ld = long double;
/// Derivatives with respect to (t, T, k).
using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 3, 1>>;

template <typename S>
double value(const S& x) {
  return static_cast<double>(chasles::detail::real_value(x));
}

/// A time scaling of kind for the trapezoid's ratio k.
template <typename S>
TimeScaling<S> scaling(TimeScalingKind kind, const S& T, const S& t, const S& k) {
  return chasles::time_scaling(kind, T, t, k);
}

constexpr std::array<TimeScalingKind, 3> kKinds = {TimeScalingKind::cubic, TimeScalingKind::quintic,
                                                   TimeScalingKind::trapezoidal};

template <typename S>
class TimeScalingTest : public ::testing::Test {};
using Scalars = ::testing::Types<float, double, AD>;
struct Name {
  template <typename S>
  static std::string GetName(int) {
    return std::is_same<S, float>::value ? "float" : std::is_same<S, double>::value ? "double" : "autodiff";
  }
};
TYPED_TEST_SUITE(TimeScalingTest, Scalars, Name);

/// The machine epsilon of S's real type.
template <typename S>
double eps() {
  return static_cast<double>(std::numeric_limits<chasles::RealOf<S>>::epsilon());
}

TYPED_TEST(TimeScalingTest, BoundaryValues) {
  using S = TypeParam;
  for (double T : {0.5, 2.0, 7.3}) {
    for (double k : {1.1, 1.5, 2.0}) {
      const double alpha = k * k / (k - 1);  // a T^2
      for (TimeScalingKind kind : kKinds) {
        const TimeScaling<S> a = scaling(kind, S(T), S(0), S(k)), b = scaling(kind, S(T), S(T), S(k));
        EXPECT_EQ(value(a.s), 0.0);
        EXPECT_EQ(value(b.s), 1.0);
        EXPECT_EQ(value(a.s_dot), 0.0);
        EXPECT_EQ(value(b.s_dot), 0.0);
        const double sdd = kind == TimeScalingKind::cubic     ? 6 / (T * T)
                           : kind == TimeScalingKind::quintic ? 0.0
                                                              : alpha / (T * T);
        EXPECT_NEAR(value(a.s_ddot), sdd, 8 * eps<S>() * sdd);
        EXPECT_NEAR(value(b.s_ddot), -sdd, 8 * eps<S>() * sdd);
      }
    }
  }
}

TYPED_TEST(TimeScalingTest, SymmetricAboutTheMidpoint) {
  using S = TypeParam;
  const double T = 3.0;
  for (TimeScalingKind kind : kKinds) {
    for (double t : {0.1, 0.4, 0.9, 1.2, 1.5}) {
      const TimeScaling<S> a = scaling(kind, S(T), S(t), S(1.5)), b = scaling(kind, S(T), S(T - t), S(1.5));
      EXPECT_NEAR(value(a.s) + value(b.s), 1.0, 8 * eps<S>());
      EXPECT_NEAR(value(a.s_dot), value(b.s_dot), 16 * eps<S>());
      EXPECT_NEAR(value(a.s_ddot), -value(b.s_ddot), 16 * eps<S>());
    }
  }
}

TYPED_TEST(TimeScalingTest, AtRestOutsideTheMotion) {
  using S = TypeParam;
  const double inf = std::numeric_limits<double>::infinity(), T = 2.5;
  for (TimeScalingKind kind : kKinds) {
    for (double t : {-1e-30, -0.5, -1e30, -inf, T + 1e-5, 2 * T, 1e30, inf}) {
      const TimeScaling<S> f = scaling(kind, S(T), S(t), S(1.5));
      EXPECT_EQ(value(f.s), t < 0 ? 0.0 : 1.0) << t;
      EXPECT_EQ(value(f.s_dot), 0.0) << t;
      EXPECT_EQ(value(f.s_ddot), 0.0) << t;
    }
  }
}

TYPED_TEST(TimeScalingTest, InvalidInputIsNaN) {
  using S = TypeParam;
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const auto all_nan = [](const TimeScaling<S>& f) {
    return std::isnan(value(f.s)) && std::isnan(value(f.s_dot)) && std::isnan(value(f.s_ddot));
  };
  for (TimeScalingKind kind : kKinds) {
    for (double T : {0.0, -0.0, -1.0, nan, inf, -inf}) {
      for (double t : {-1.0, 0.0, 0.5, 2.0}) EXPECT_TRUE(all_nan(scaling(kind, S(T), S(t), S(1.5)))) << T << " " << t;
    }
    EXPECT_TRUE(all_nan(scaling(kind, S(2), S(nan), S(1.5))));
  }
  for (double k : {1.0, 0.5, -2.0, 2.0 + 1e-6, 3.0, nan, inf})
    EXPECT_TRUE(all_nan(chasles::trapezoidal_time_scaling(S(2), S(k), S(0.5)))) << k;
  // The trapezoid from the single entry point without its ratio.
  EXPECT_TRUE(all_nan(chasles::time_scaling(TimeScalingKind::trapezoidal, S(2), S(0.5))));
  EXPECT_FALSE(all_nan(chasles::time_scaling(TimeScalingKind::cubic, S(2), S(0.5))));
  // And through a joint trajectory.
  const Eigen::Matrix<S, 2, 1> q0(S(0), S(1)), q1(S(1), S(3));
  const auto p = chasles::joint_trajectory(q0, q1, chasles::cubic_time_scaling(S(0), S(0.5)));
  EXPECT_TRUE(std::isnan(value(p.q(0))) && std::isnan(value(p.qd(1))) && std::isnan(value(p.qdd(0))));
}

TYPED_TEST(TimeScalingTest, TrapezoidPeakVelocityAndAcceleration) {
  using S = TypeParam;
  for (double T : {0.8, 4.0}) {
    for (double k : {1.05, 1.5, 1.9, 2.0}) {
      const double v = k / T, a = v * v / (v * T - 1), t_a = v / a;  // MR: a = v^2 / (v T - 1)
      const auto at = [&](double t) { return chasles::trapezoidal_time_scaling(S(T), S(k), S(t)); };
      // Accelerating before t_a, cruising at v between, decelerating after T - t_a.
      const double before = 0.999 * t_a, after = 1.001 * t_a;
      EXPECT_NEAR(value(at(before).s_ddot), a, 16 * eps<S>() * a);
      EXPECT_NEAR(value(at(before).s_dot), a * before, 16 * eps<S>() * v);
      EXPECT_NEAR(value(at(T - before).s_ddot), -a, 16 * eps<S>() * a);
      EXPECT_NEAR(value(at(T / 2).s_dot), v, 16 * eps<S>() * v);
      EXPECT_NEAR(value(at(T / 2).s), 0.5, 16 * eps<S>());
      EXPECT_EQ(value(at(T / 2).s_ddot), 0.0);
      if (k < 2) {
        EXPECT_EQ(value(at(after).s_ddot), 0.0);
        EXPECT_NEAR(value(at(after).s_dot), v, 16 * eps<S>() * v);
        EXPECT_NEAR(value(at(after).s), v * after - v * v / (2 * a), 16 * eps<S>());  // MR's cruise phase
      }
      // v is the peak: no sample is faster, none accelerates harder than a.
      double peak = 0, peak_acceleration = 0;
      for (int i = 0; i <= 200; ++i) {
        const TimeScaling<S> f = at(T * i / 200.0);
        peak = std::max(peak, value(f.s_dot));
        peak_acceleration = std::max(peak_acceleration, std::abs(value(f.s_ddot)));
      }
      EXPECT_NEAR(peak, v, 16 * eps<S>() * v);
      EXPECT_NEAR(peak_acceleration, a, 16 * eps<S>() * a);
    }
    // The triangle: v = 2 / T, a = 4 / T^2, switching at T / 2.
    const auto tri = [&](double t) { return chasles::trapezoidal_time_scaling(S(T), S(2), S(t)); };
    EXPECT_NEAR(value(tri(0.499 * T).s_ddot), 4 / (T * T), 16 * eps<S>() * 4 / (T * T));
    EXPECT_NEAR(value(tri(0.501 * T).s_ddot), -4 / (T * T), 16 * eps<S>() * 4 / (T * T));
    EXPECT_NEAR(value(tri(0.5 * T).s_dot), 2 / T, 16 * eps<S>() * 2 / T);
    EXPECT_NEAR(value(tri(0.25 * T).s), 0.125, 16 * eps<S>());
  }
}

/// s, s_dot, s_ddot of kind in long double.
TimeScaling<ld> reference(TimeScalingKind kind, ld T, ld t, ld k) { return chasles::time_scaling(kind, T, t, k); }

TYPED_TEST(TimeScalingTest, DerivativesMatchCentralDifferences) {
  using S = TypeParam;
  for (double T : {0.3, 2.0, 9.0}) {
    for (double k : {1.25, 1.5, 2.0}) {
      const double switches[] = {(k - 1) / k, 1 / k};
      for (TimeScalingKind kind : kKinds) {
        for (double r : {0.02, 0.13, 0.3, 0.45, 0.5, 0.55, 0.71, 0.9, 0.99}) {
          if (kind == TimeScalingKind::trapezoidal &&
              (std::abs(r - switches[0]) < 1e-3 || std::abs(r - switches[1]) < 1e-3))
            continue;  // s_ddot jumps there
          const ld t = ld(r) * ld(T), h = 1e-5L * ld(T);
          const TimeScaling<ld> plus = reference(kind, ld(T), t + h, ld(k)),
                                minus = reference(kind, ld(T), t - h, ld(k));
          const double s_dot = static_cast<double>((plus.s - minus.s) / (2 * h));
          const double s_ddot = static_cast<double>((plus.s_dot - minus.s_dot) / (2 * h));
          const TimeScaling<S> f = scaling(kind, S(T), S(static_cast<double>(t)), S(k));
          // Truncation h^2 |s'''| / 6 ~ 1e-10 relative; rounding of S, relative to 1 / T and 1 / T^2.
          const double tol = 64 * eps<S>() + 1e-8;
          EXPECT_NEAR(value(f.s_dot) * T, s_dot * T, tol * k * k / (k - 1)) << r;
          EXPECT_NEAR(value(f.s_ddot) * T * T, s_ddot * T * T, tol * k * k / (k - 1)) << r;
        }
      }
    }
  }
}

TEST(TimeScaling, DerivativesMatchAutomaticDifferentiation) {
  // Variables (t, T, k): ds/dt = s_dot, d s_dot/dt = s_ddot, ds/dT = -(t / T) s_dot; ds/dk against long double
  // central differences.
  for (TimeScalingKind kind : kKinds) {
    for (double r : {0.05, 0.3, 0.5, 0.62, 0.95}) {
      const double T = 1.7, k = 1.4, t = r * T;
      const TimeScaling<AD> f = scaling(kind, AD(T, 3, 1), AD(t, 3, 0), AD(k, 3, 2));
      EXPECT_NEAR(f.s.derivatives()(0), f.s_dot.value(), 1e-14);
      EXPECT_NEAR(f.s_dot.derivatives()(0), f.s_ddot.value(), 1e-13);
      EXPECT_NEAR(f.s.derivatives()(1), -r * f.s_dot.value(), 1e-14);
      const ld h = 1e-6L;
      const ld ds_dk = (reference(kind, T, t, k + h).s - reference(kind, T, t, k - h).s) / (2 * h);
      EXPECT_NEAR(f.s.derivatives()(2), static_cast<double>(ds_dk), 1e-9);
      if (kind != TimeScalingKind::trapezoidal) {
        EXPECT_EQ(f.s.derivatives()(2), 0.0);
      }
    }
  }
  // At rest outside [0, T]: no derivative.
  const TimeScaling<AD> f = chasles::quintic_time_scaling(AD(2.0, 3, 1), AD(2.5, 3, 0));
  EXPECT_TRUE(f.s.derivatives().isZero(0));
}

TEST(TimeScaling, ModernRoboticsNumbers) {
  // modern_robotics 1.1.1 (pip, build/dev's venv), printed by repr:
  //   mr.CubicTimeScaling(Tf, t) and mr.QuinticTimeScaling(Tf, t) for (Tf, t) below.
  struct Case {
    double Tf, t, cubic, quintic;
  };
  const Case cases[] = {{2, 0.6, 0.21600000000000003, 0.16307999999999995},
                        {3.7, 1.1, 0.21260339960120825, 0.15952278292973676},
                        {1, 0.25, 0.15625, 0.103515625},
                        {5, 4.2, 0.9313920000000002, 0.9682412544000001}};
  for (const Case& c : cases) {
    EXPECT_NEAR(chasles::cubic_time_scaling(c.Tf, c.t).s, c.cubic, 1e-15);
    EXPECT_NEAR(chasles::quintic_time_scaling(c.Tf, c.t).s, c.quintic, 1e-15);
    EXPECT_NEAR(chasles::cubic_time_scaling(float(c.Tf), float(c.t)).s, c.cubic, 4e-7);
    EXPECT_NEAR(chasles::quintic_time_scaling(float(c.Tf), float(c.t)).s, c.quintic, 4e-7);
  }
  // mr.JointTrajectory(thetastart, thetaend, 4, 6, method), MR's docstring example: rows 2 and 3 (t = 1.6, 2.4),
  // method 3 (cubic) and 5 (quintic); rows 0 and 5 are thetastart and thetaend.
  using V8 = Eigen::Matrix<double, 8, 1>;
  const V8 start = (V8() << 1, 0, 0, 1, 1, 0.2, 0, 1).finished();
  const V8 end = (V8() << 1.2, 0.5, 0.6, 1.1, 2, 2, 0.9, 1).finished();
  const std::array<V8, 4> rows = {(V8() << 1.0704, 0.17600000000000005, 0.21120000000000005, 1.0352000000000001, 1.352,
                                   0.8336000000000001, 0.3168000000000001, 1.0)
                                      .finished(),
                                  (V8() << 1.1296, 0.32400000000000007, 0.3888000000000001, 1.0648, 1.6480000000000001,
                                   1.3664000000000003, 0.5832000000000002, 1.0)
                                      .finished(),
                                  (V8() << 1.063488, 0.15872000000000003, 0.19046400000000002, 1.031744, 1.31744,
                                   0.7713920000000001, 0.28569600000000006, 1.0)
                                      .finished(),
                                  (V8() << 1.1365120000000002, 0.34128000000000014, 0.4095360000000002, 1.068256,
                                   1.6825600000000003, 1.4286080000000005, 0.6143040000000003, 1.0)
                                      .finished()};
  const double Tf = 4, gap = Tf / 5;
  for (int m = 0; m < 2; ++m) {
    const TimeScalingKind kind = m == 0 ? TimeScalingKind::cubic : TimeScalingKind::quintic;
    for (int i = 0; i <= 5; ++i) {
      const V8 q = chasles::joint_trajectory(start, end, chasles::time_scaling(kind, Tf, gap * i)).q;
      if (i == 0) {
        EXPECT_EQ(q, start);
      }
      if (i == 5) {
        EXPECT_EQ(q, end);
      }
      if (i == 2 || i == 3) {
        EXPECT_LT((q - rows[size_t(2 * m + i - 2)]).cwiseAbs().maxCoeff(), 1e-15) << m << i;
      }
    }
  }
}

TYPED_TEST(TimeScalingTest, JointTrajectory) {
  using S = TypeParam;
  using V3 = Eigen::Matrix<S, 3, 1>;
  using VMax = Eigen::Matrix<S, Eigen::Dynamic, 1, 0, 8, 1>;
  const V3 start(S(0.1), S(-2.3), S(0.7)), end(S(0.7), S(1.9), S(0.7));
  const V3 d = end - start;
  // The end points exactly (0.1 + (0.7 - 0.1) is not 0.7 in floating point).
  for (TimeScalingKind kind : kKinds) {
    EXPECT_TRUE(chasles::joint_trajectory(start, end, scaling(kind, S(2), S(0), S(1.5))).q == start);
    EXPECT_TRUE(chasles::joint_trajectory(start, end, scaling(kind, S(2), S(2), S(1.5))).q == end);
    EXPECT_TRUE(chasles::joint_trajectory(start, end, scaling(kind, S(2), S(5), S(1.5))).q == end);
  }
  for (double t : {0.3, 1.0, 1.6}) {
    const TimeScaling<S> f = chasles::quintic_time_scaling(S(2), S(t));
    const auto p = chasles::joint_trajectory(start, end, f);
    static_assert(std::is_same<std::decay_t<decltype(p.q)>, V3>::value, "a fixed-size result");
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(value(p.q(i)), value(start(i)) + value(f.s) * value(d(i)), 8 * eps<S>() * 4);
      EXPECT_NEAR(value(p.qd(i)), value(f.s_dot) * value(d(i)), 8 * eps<S>() * 4);
      EXPECT_NEAR(value(p.qdd(i)), value(f.s_ddot) * value(d(i)), 8 * eps<S>() * 4);
    }
    EXPECT_EQ(value(p.q(2)), value(start(2)));  // a joint that does not move stays put
    EXPECT_EQ(value(p.qd(2)), 0.0);
    // The same through maximum-size and dynamic-size vectors, and through expressions.
    const VMax start_max = start, end_max = end;
    const auto p_max = chasles::joint_trajectory(start_max, end_max, f);
    static_assert(std::is_same<std::decay_t<decltype(p_max.q)>, VMax>::value, "a maximum-size result");
    const Eigen::Matrix<S, Eigen::Dynamic, 1> start_dyn = start, end_dyn = end;
    const auto p_dyn = chasles::joint_trajectory(start_dyn, end_dyn.head(3), f);
    const auto p_expr = chasles::joint_trajectory(start_max.head(3), end.transpose().transpose(), f);
    for (int i = 0; i < 3; ++i) {
      EXPECT_EQ(value(p_max.q(i)), value(p.q(i)));
      EXPECT_EQ(value(p_dyn.qd(i)), value(p.qd(i)));
      EXPECT_EQ(value(p_expr.qdd(i)), value(p.qdd(i)));
    }
  }
}

TEST(TimeScaling, JointTrajectoryDoesNotAllocate) {
  using VMax = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, 7, 1>;
  const Eigen::Matrix<double, 6, 1> a = Eigen::Matrix<double, 6, 1>::LinSpaced(0, 1);
  const Eigen::Matrix<double, 6, 1> b = Eigen::Matrix<double, 6, 1>::LinSpaced(2, -1);
  const VMax c = a, e = b;
  const Eigen::Matrix<AD, 6, 1> a_ad = a.cast<AD>(), b_ad = b.cast<AD>();
  double sum = 0;
  Eigen::internal::set_is_malloc_allowed(false);
  for (TimeScalingKind kind : kKinds) {
    sum += chasles::joint_trajectory(a, b, chasles::time_scaling(kind, 2.0, 0.7, 1.5)).qdd.sum();
    sum += chasles::joint_trajectory(c, e, chasles::time_scaling(kind, 2.0, 0.7, 1.5)).qd.sum();
    sum +=
        chasles::joint_trajectory(a_ad, b_ad, chasles::time_scaling(kind, AD(2.0), AD(0.7), AD(1.5))).q.sum().value();
  }
  Eigen::internal::set_is_malloc_allowed(true);
  EXPECT_TRUE(std::isfinite(sum));
}

}  // namespace
