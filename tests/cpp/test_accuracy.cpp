// Accuracy of exp and log against an independent long double reference
// (support/reference.hpp), over the whole domain: angle 0, tiny angles,
// generic angles, near pi and exactly pi, translations from 0 to 1e6, and
// rotation matrices a little off SO(3).
//
// The contract (double; float to the same number of ulps, i.e. every
// threshold scaled by FLT_EPSILON / DBL_EPSILON):
//   SO3 exp   entrywise |R - R_ref| <= 1e-15, angles 0 .. pi;
//   SO3 log   |w - w_ref|_max <= 1e-15, angles 1e-300 .. pi - 1e-12, sign
//             strict; at pi a valid answer with either sign; angle in
//             [0, pi]; tiny angles (1e-300 .. 1e-4): |w - w_ref|_max <=
//             4 eps |w_ref|_max;
//   SE3 exp   rotation block entrywise <= 2e-15, translation
//             |p - p_ref|_max / |p_ref|_max <= 2e-15;
//   SE3 log   w: |w - w_ref|_max <= 2e-15, v: |v - v_ref|_max / |v_ref|_max
//             <= 2e-15 (a zero reference must be matched exactly);
//   off SO(3) log of (rotation + E), |E_ij| <= d, d in 1e-12 .. 1e-9 (not
//             re-orthonormalized): |w - w_true|_max <= 2 d.
// Each case prints its worst error (and the input where it occurs) on
// stdout and as a test property, so that the figures can be quoted.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <chasles/se3.hpp>
#include <chasles/so3.hpp>

#include "support/format.hpp"
#include "support/reference.hpp"
#include "support/samples.hpp"

namespace {

using chasles_ref::kPi;
using chasles_ref::ld;
using chasles_ref::M3;
using chasles_ref::M4;
using chasles_ref::V3;
using chasles_ref::V6;

using chasles_test::eps;
using chasles_test::Mat3;
using chasles_test::Mat4;
using chasles_test::str;
using chasles_test::type_name;
using chasles_test::Vec3;
using chasles_test::Vec6;

/// A double threshold carried to T: the same number of ulps.
template <typename T>
ld tolerance(ld double_tol) {
  return double_tol * ld(std::numeric_limits<T>::epsilon()) / ld(std::numeric_limits<double>::epsilon());
}

/// The worst error of a case and where it occurred. NaN counts as worst.
struct Worst {
  ld err = 0;
  std::string where;
  int count = 0;
  void update(ld e, const std::string& at) {
    ++count;
    if (!(e <= err)) {
      err = e;
      where = at;
    }
  }
};

template <typename T>
void report_t(const std::string& name, const Worst& w, ld tol) {
  std::printf("[ worst    ] %-44s %.3Le (tol %.3Le = %.2Lf eps_%s) over %d inputs, at %s\n",
              (name + " " + type_name<T>()).c_str(), w.err, tol, w.err / eps<T>(), type_name<T>(), w.count,
              w.where.c_str());
  std::ostringstream os;
  os.precision(4);
  os << double(w.err);
  ::testing::Test::RecordProperty(name + "_" + type_name<T>(), os.str());
}

ld max_abs(const M3& a) { return a.cwiseAbs().maxCoeff(); }

/// Smallest gap to pi for which the axis sign is still determined at T's
/// precision: 1e-12 in double, the same number of ulps in float.
template <typename T>
ld strict_pi_gap() {
  return tolerance<T>(1e-12L);
}

/// Angles of the contract, representable in T, from 0 to pi.
template <typename T>
std::vector<ld> contract_angles() {
  std::vector<ld> a;
  const ld tiny = sizeof(T) == sizeof(float) ? 1e-36L : 1e-300L;
  a.push_back(0);
  a.push_back(ld(T(tiny)));
  for (int k = (sizeof(T) == sizeof(float) ? 35 : 299); k >= 1; k -= (k > 20 ? 10 : 1))
    a.push_back(ld(T(std::pow(10.0L, -k))));
  for (ld x : {0.03L, 0.1L, 0.3L, 0.5L, 1.0L, 1.5L, kPi / 2, 2.0L, 2.5L, 3.0L}) a.push_back(ld(T(x)));
  for (ld gap = 1e-1L; gap >= strict_pi_gap<T>() * 0.99L; gap /= 10) a.push_back(ld(T(kPi - gap)));
  a.push_back(ld(T(kPi - strict_pi_gap<T>())));
  a.push_back(ld(T(kPi)));
  return a;
}

/// Axes: coordinate axes, diagonals, and a few random ones (all rounded to T).
template <typename T>
std::vector<Vec3<T>> contract_axes(int n_random = 6) {
  std::vector<Vec3<T>> ax = {Vec3<T>::UnitX(),
                             Vec3<T>::UnitY(),
                             Vec3<T>::UnitZ(),
                             Vec3<T>(1, 1, 0).normalized(),
                             Vec3<T>(1, -2, 3).normalized(),
                             Vec3<T>(1, 1, 1).normalized()};
  std::mt19937_64 rng(chasles_test::kSeed + 7);
  for (int i = 0; i < n_random; ++i) ax.push_back(chasles_test::random_unit<T>(rng));
  return ax;
}

/// Every rotation vector of the SO3 cases: the shared samples plus the
/// contract angles along the contract axes.
template <typename T>
std::vector<Vec3<T>> so3_cases() {
  std::vector<Vec3<T>> out = chasles_test::rotation_vectors<T>(256);
  for (ld a : contract_angles<T>())
    for (const Vec3<T>& u : contract_axes<T>()) out.push_back((T(a) * u).eval());
  return out;
}

/// Angle of a T vector in long double.
template <typename T>
ld angle_of(const Vec3<T>& w) {
  return chasles_ref::scaled_norm(w.template cast<ld>());
}

// ---------------------------------------------------------------------------
// The oracle itself.

TEST(Oracle, MatrixExponentialAgreesWithTaylorSum) {
  std::mt19937_64 rng(chasles_test::kSeed);
  ld worst3 = 0, worst4 = 0;
  std::vector<V3> ws = {V3::Zero(),
                        V3(1e-300L, 0, 0),
                        V3(1e-8L, -2e-8L, 3e-8L),
                        V3(0.3L, -0.2L, 0.1L),
                        V3(1, 0, 0),
                        kPi * V3(1, 1, 0).normalized(),
                        (kPi - 1e-12L) * V3(1, -2, 3).normalized()};
  for (int i = 0; i < 20; ++i) {
    std::uniform_real_distribution<double> u(0, double(kPi));
    ws.push_back(ld(u(rng)) * chasles_test::random_unit<double>(rng).cast<ld>());
  }
  for (const V3& w : ws) {
    worst3 = std::max(worst3, max_abs(chasles_ref::exp3(w) - chasles_ref::exp_taylor<3>(chasles_ref::hat(w))));
    // |v| <= 1: exp6 scales larger v down by a power of two first (exact by
    // linearity of V v in v), so this covers its Pade evaluation; an
    // unscaled Taylor sum at |v| = 1e6 would itself lose 2^20 ulps squaring.
    for (ld size : {0.0L, 1e-3L, 1.0L}) {
      V6 xi;
      xi << size * chasles_test::random_unit<double>(rng).cast<ld>(), w;
      const M4 a = chasles_ref::exp6(xi), b = chasles_ref::exp_taylor<4>(chasles_ref::hat6(xi));
      const ld rot = (a - b).topLeftCorner<3, 3>().cwiseAbs().maxCoeff();
      const ld tr = (a - b).topRightCorner<3, 1>().cwiseAbs().maxCoeff() / std::max<ld>(1, size);
      worst4 = std::max({worst4, rot, tr});
    }
  }
  std::printf("[ oracle   ] exp3 vs Taylor %.3Le, exp6 vs Taylor (translation relative) %.3Le\n", worst3, worst4);
  EXPECT_LE(worst3, 1e-17L);
  EXPECT_LE(worst4, 1e-17L);
}

TEST(Oracle, LogInvertsExpInBothRegimes) {
  std::mt19937_64 rng(chasles_test::kSeed + 1);
  ld worst_abs = 0, worst_rel_tiny = 0, worst6 = 0;
  for (ld a : {1e-300L, 1e-20L, 1e-8L, 0.01L, 0.04L, 0.049L, 0.051L, 0.06L, 0.5L, 1.0L, 2.0L, 3.0L, kPi - 1e-6L,
               kPi - 1e-12L}) {
    for (int i = 0; i < 8; ++i) {
      const V3 w = a * chasles_test::random_unit<double>(rng).cast<ld>();
      const V3 back = chasles_ref::log3(chasles_ref::exp3(w));
      worst_abs = std::max(worst_abs, (back - w).cwiseAbs().maxCoeff());
      if (a < 1e-4L)
        worst_rel_tiny = std::max(worst_rel_tiny, (back - w).cwiseAbs().maxCoeff() / w.cwiseAbs().maxCoeff());
      V6 xi;
      xi << 1e3L * chasles_test::random_unit<double>(rng).cast<ld>(), w;
      const V6 back6 = chasles_ref::log6(chasles_ref::exp6(xi));
      worst6 = std::max(worst6, (back6 - xi).cwiseAbs().maxCoeff() / 1e3L);
    }
  }
  std::printf("[ oracle   ] log3(exp3(w)) - w: %.3Le abs, %.3Le relative (tiny); log6(exp6) %.3Le relative\n",
              worst_abs, worst_rel_tiny, worst6);
  EXPECT_LE(worst_abs, 1e-17L);
  EXPECT_LE(worst_rel_tiny, 1e-17L);
  EXPECT_LE(worst6, 1e-17L);
}

// ---------------------------------------------------------------------------
// SO3 exp.

template <typename T>
void so3_exp_contract() {
  using SO3 = chasles::SO3<T>;
  const ld tol = tolerance<T>(1e-15L);
  Worst worst;
  for (const Vec3<T>& w : so3_cases<T>()) {
    if (angle_of(w) > kPi) continue;  // the contract stops at pi (float pi rounds up)
    const M3 R = SO3::exp(w).matrix().template cast<ld>();
    const M3 ref = chasles_ref::exp3(w.template cast<ld>());
    worst.update(max_abs(R - ref), str(w));
  }
  report_t<T>("SO3 exp entrywise", worst, tol);
  EXPECT_LE(worst.err, tol) << type_name<T>() << " at w = " << worst.where;
}

TEST(SO3Exp, Double) { so3_exp_contract<double>(); }
TEST(SO3Exp, Float) { so3_exp_contract<float>(); }

// ---------------------------------------------------------------------------
// SO3 log.

/// The rotation of the long double vector w, rounded to T.
template <typename T>
Mat3<T> rounded_rotation(const V3& w) {
  return chasles_ref::exp3(w).template cast<T>();
}

template <typename T>
void so3_log_contract() {
  using SO3 = chasles::SO3<T>;
  const ld tol = tolerance<T>(1e-15L);
  Worst strict, at_pi, valid_at_pi, angle_excess;
  for (const Vec3<T>& wt : so3_cases<T>()) {
    const V3 w = wt.template cast<ld>();
    const ld theta = angle_of(wt);
    if (theta == 0) continue;
    const Mat3<T> R = rounded_rotation<T>(w);
    const V3 ref = chasles_ref::log3(R.template cast<ld>());
    const V3 got = SO3::from_matrix_unchecked(R).log().template cast<ld>();
    angle_excess.update(std::max<ld>(0, chasles_ref::scaled_norm(got) - kPi), str(wt));
    if (kPi - theta >= 0.5L * strict_pi_gap<T>()) {
      strict.update((got - ref).cwiseAbs().maxCoeff(), str(wt));
    } else {
      // Within rounding of pi: either sign, and exp of the answer must give R back.
      at_pi.update(std::min((got - ref).cwiseAbs().maxCoeff(), (got + ref).cwiseAbs().maxCoeff()), str(wt));
      valid_at_pi.update(max_abs(chasles_ref::exp3(got) - R.template cast<ld>()), str(wt));
    }
  }
  report_t<T>("SO3 log abs, angle < pi (sign strict)", strict, tol);
  report_t<T>("SO3 log abs, angle ~ pi (either sign)", at_pi, tol);
  report_t<T>("SO3 log at pi: |exp(log R) - R|", valid_at_pi, tol);
  report_t<T>("SO3 log: |w| - pi", angle_excess, 4 * eps<T>());
  EXPECT_LE(strict.err, tol) << type_name<T>() << " at w = " << strict.where;
  EXPECT_LE(at_pi.err, tol) << type_name<T>() << " at w = " << at_pi.where;
  EXPECT_LE(valid_at_pi.err, tol) << type_name<T>() << " at w = " << valid_at_pi.where;
  EXPECT_LE(angle_excess.err, 4 * eps<T>()) << type_name<T>() << " at w = " << angle_excess.where;
}

TEST(SO3Log, Double) { so3_log_contract<double>(); }
TEST(SO3Log, Float) { so3_log_contract<float>(); }

/// Exact pi rotations: diag(1,-1,-1) and friends, the pi rotation about
/// (1,1,0)/sqrt 2 (exactly [[0,1,0],[1,0,0],[0,0,-1]]), and about
/// (1,1,1)/sqrt 3 (rounded): |w| = pi, w = +-pi n, exp(w) = R.
template <typename T>
void so3_log_exactly_pi() {
  using SO3 = chasles::SO3<T>;
  const ld tol = tolerance<T>(1e-15L);
  struct Case {
    Mat3<T> R;
    V3 n;
    const char* name;
  };
  std::vector<Case> cases;
  cases.push_back({Vec3<T>(1, -1, -1).asDiagonal(), V3(1, 0, 0), "diag(1,-1,-1)"});
  cases.push_back({Vec3<T>(-1, 1, -1).asDiagonal(), V3(0, 1, 0), "diag(-1,1,-1)"});
  cases.push_back({Vec3<T>(-1, -1, 1).asDiagonal(), V3(0, 0, 1), "diag(-1,-1,1)"});
  Mat3<T> R110;
  R110 << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  cases.push_back({R110, V3(1, 1, 0).normalized(), "pi about (1,1,0)/sqrt2"});
  Mat3<T> R011;
  R011 << -1, 0, 0, 0, 0, 1, 0, 1, 0;
  cases.push_back({R011, V3(0, 1, 1).normalized(), "pi about (0,1,1)/sqrt2"});
  Mat3<T> R1m10;
  R1m10 << 0, -1, 0, -1, 0, 0, 0, 0, -1;
  cases.push_back({R1m10, V3(1, -1, 0).normalized(), "pi about (1,-1,0)/sqrt2"});
  const V3 n111 = V3(1, 1, 1).normalized();
  cases.push_back({(2 * n111 * n111.transpose() - M3::Identity()).template cast<T>(), n111, "pi about (1,1,1)/sqrt3"});
  Worst worst;
  for (const Case& c : cases) {
    const V3 got = SO3::from_matrix_unchecked(c.R).log().template cast<ld>();
    ASSERT_TRUE(got.allFinite()) << c.name;
    const ld err_axis = std::min((got - kPi * c.n).cwiseAbs().maxCoeff(), (got + kPi * c.n).cwiseAbs().maxCoeff());
    const ld err_exp = max_abs(chasles_ref::exp3(got) - c.R.template cast<ld>());
    const ld err_angle = std::fabs(chasles_ref::scaled_norm(got) - kPi);
    worst.update(std::max({err_axis, err_exp, err_angle}), c.name);
    EXPECT_LE(err_axis, tol) << c.name << ": w = " << str(got);
    EXPECT_LE(err_exp, tol) << c.name << ": w = " << str(got);
    EXPECT_LE(err_angle, tol) << c.name << ": w = " << str(got);
  }
  report_t<T>("SO3 log of exact pi rotations", worst, tol);
}

TEST(SO3LogAtPi, Double) { so3_log_exactly_pi<double>(); }
TEST(SO3LogAtPi, Float) { so3_log_exactly_pi<float>(); }

/// Short of pi the axis keeps its sign: w . n > 0 for angles pi - gap, gap
/// from 1e-1 down to 1e-12 (double), along many axes; and |w| <= pi.
template <typename T>
void so3_log_no_flip_short_of_pi() {
  using SO3 = chasles::SO3<T>;
  std::mt19937_64 rng(chasles_test::kSeed + 3);
  int flips = 0, n = 0;
  std::string first;
  for (int i = 0; i < 200; ++i) {
    const V3 axis = chasles_test::random_unit<T>(rng).template cast<ld>();
    for (ld gap = 1e-1L; gap >= strict_pi_gap<T>() * 0.99L; gap /= 3) {
      const V3 w = (kPi - gap) * axis;
      const Vec3<T> got = SO3::from_matrix_unchecked(rounded_rotation<T>(w)).log();
      ++n;
      if (!(got.template cast<ld>().dot(axis) > 0)) {
        if (flips++ == 0) first = "w = " + str(w) + " gives " + str(got);
      }
    }
  }
  std::printf("[ info     ] SO3 log %s: %d sign flips short of pi over %d inputs\n", type_name<T>(), flips, n);
  EXPECT_EQ(flips, 0) << first;
}

TEST(SO3LogNoFlip, Double) { so3_log_no_flip_short_of_pi<double>(); }
TEST(SO3LogNoFlip, Float) { so3_log_no_flip_short_of_pi<float>(); }

/// Tiny angles, relative accuracy: |w - w_ref|_max <= 4 eps |w_ref|_max.
template <typename T>
void so3_log_tiny_relative() {
  using SO3 = chasles::SO3<T>;
  const ld tol = 4 * eps<T>();
  const ld smallest = sizeof(T) == sizeof(float) ? 1e-36L : 1e-300L;
  std::mt19937_64 rng(chasles_test::kSeed + 4);
  Worst worst;
  std::vector<Vec3<T>> axes = contract_axes<T>(10);
  for (ld a = smallest; a <= 1.0001e-4L; a *= 3.1L) {
    for (const Vec3<T>& u : axes) {
      const Vec3<T> wt = (T(a) * u).eval();
      const Mat3<T> R = rounded_rotation<T>(wt.template cast<ld>());
      const V3 ref = chasles_ref::log3(R.template cast<ld>());
      const V3 got = SO3::from_matrix_unchecked(R).log().template cast<ld>();
      worst.update((got - ref).cwiseAbs().maxCoeff() / ref.cwiseAbs().maxCoeff(), str(wt));
    }
  }
  report_t<T>("SO3 log relative, tiny angles", worst, tol);
  EXPECT_LE(worst.err, tol) << type_name<T>() << " at w = " << worst.where;
}

TEST(SO3LogTiny, Double) { so3_log_tiny_relative<double>(); }
TEST(SO3LogTiny, Float) { so3_log_tiny_relative<float>(); }

// ---------------------------------------------------------------------------
// SE3 exp and log.

template <typename T>
std::vector<Vec6<T>> se3_cases() {
  std::vector<Vec6<T>> out = chasles_test::twists<T>(64);
  std::mt19937_64 rng(chasles_test::kSeed + 5);
  const ld sizes[] = {0, 1e-6L, 1, 100, 1e6L};
  int k = 0;
  for (ld a : contract_angles<T>()) {
    for (const Vec3<T>& u : contract_axes<T>(2)) {
      for (ld s : sizes) {
        Vec6<T> xi;
        // Alternate between a random direction and one orthogonal to w (the
        // case where the (1/2)[w] v term of V is largest).
        Vec3<T> d = chasles_test::random_unit<T>(rng);
        if (k++ % 2 == 0 && a > 0) d = u.cross(d).normalized();
        // (element by element: GCC 12 warns, falsely, on the float comma initializer)
        for (int i = 0; i < 3; ++i) {
          xi[i] = T(s) * d[i];
          xi[i + 3] = T(a) * u[i];
        }
        out.push_back(xi);
      }
    }
  }
  return out;
}

template <typename T>
ld relative_error(const V3& got, const V3& ref) {
  const ld scale = std::max(ref.cwiseAbs().maxCoeff(), ld(std::numeric_limits<ld>::min()));
  return (got - ref).cwiseAbs().maxCoeff() / scale;
}

template <typename T>
void se3_exp_contract() {
  using SE3 = chasles::SE3<T>;
  const ld tol = tolerance<T>(2e-15L);
  Worst rot, trans;
  for (const Vec6<T>& xi : se3_cases<T>()) {
    if (angle_of(Vec3<T>(xi.template tail<3>())) > kPi) continue;
    const M4 g = SE3::exp(xi).matrix().template cast<ld>();
    const M4 ref = chasles_ref::exp6(xi.template cast<ld>());
    rot.update(max_abs(M3(g.topLeftCorner<3, 3>() - ref.topLeftCorner<3, 3>())), str(xi));
    trans.update(relative_error<T>(g.topRightCorner<3, 1>(), ref.topRightCorner<3, 1>()), str(xi));
  }
  report_t<T>("SE3 exp rotation entrywise", rot, tol);
  report_t<T>("SE3 exp translation relative", trans, tol);
  EXPECT_LE(rot.err, tol) << type_name<T>() << " at xi = " << rot.where;
  EXPECT_LE(trans.err, tol) << type_name<T>() << " at xi = " << trans.where;
}

TEST(SE3Exp, Double) { se3_exp_contract<double>(); }
TEST(SE3Exp, Float) { se3_exp_contract<float>(); }

template <typename T>
void se3_log_contract() {
  using SE3 = chasles::SE3<T>;
  const ld tol = tolerance<T>(2e-15L);
  Worst rot, trans;
  for (const Vec6<T>& xi_t : se3_cases<T>()) {
    const ld theta = angle_of(Vec3<T>(xi_t.template tail<3>()));
    if (theta > kPi) continue;
    const Mat4<T> g = chasles_ref::exp6(xi_t.template cast<ld>()).template cast<T>();
    const M4 gl = g.template cast<ld>();
    V6 ref = chasles_ref::log6(gl);
    const V6 got = SE3::from_matrix_unchecked(g).log().template cast<ld>();
    const bool near_pi = kPi - theta < 0.5L * strict_pi_gap<T>();
    if (near_pi && got.tail<3>().dot(ref.tail<3>()) < 0) {
      // The other valid answer at pi: -w, and the v that goes with it.
      ref = chasles_ref::log6_with_rotation(-ref.tail<3>(), gl.topRightCorner<3, 1>());
    }
    rot.update((got.tail<3>() - ref.tail<3>()).cwiseAbs().maxCoeff(), str(xi_t));
    trans.update(relative_error<T>(got.head<3>(), ref.head<3>()), str(xi_t));
  }
  report_t<T>("SE3 log rotation abs", rot, tol);
  report_t<T>("SE3 log translation relative", trans, tol);
  EXPECT_LE(rot.err, tol) << type_name<T>() << " at xi = " << rot.where;
  EXPECT_LE(trans.err, tol) << type_name<T>() << " at xi = " << trans.where;
}

TEST(SE3Log, Double) { se3_log_contract<double>(); }
TEST(SE3Log, Float) { se3_log_contract<float>(); }

// ---------------------------------------------------------------------------
// Off the manifold: log of (rotation + E), |E_ij| <= d, not re-orthonormalized.
//
// The contract: the error is at most 2 d, "as good as projecting first".
// "As good as projecting first" is asserted for two readings of "entries
// off by d": every entry off by a uniform random amount in [-d, d], and
// every entry off by exactly d (random signs, the corners of the box, where
// the worst cases live). It compares, angle by angle and on the same inputs,
// the worst error of log(M) with that of log(from_matrix_projected(M)),
// allowing 1% (a log that ignores the normal part of the perturbation, as
// the projection does, matches it to O(d^2) and rounding).
// The 2 d figure is asserted as the contract states it: double, d from
// 1e-12 to 1e-9, entries off by random amounts (uniform). It is printed for
// the other cases but not asserted there, because no log meets it: it is
// not a worst-case bound even for projecting first, whose error is
// J_r^-1(w) vee(skew(R^T E)), up to about (pi/2) sqrt(3) d; on these seeded
// samples projecting first reaches 2.8 d with every entry off by exactly d
// and 2.04 d in float (printed below).
enum class Perturbation { exactly_d, uniform };

template <typename T>
void log_off_manifold(Perturbation model, const std::vector<ld>& ds, bool assert_two_d) {
  using SO3 = chasles::SO3<T>;
  const char* model_name = model == Perturbation::exactly_d ? "entries off by +-d" : "entries off by U[-d,d]";
  const std::vector<ld> angles = {0, 1e-8L, 1e-4L, 0.1L,        1,           kPi / 2 - 0.01L, kPi / 2, kPi / 2 + 0.01L,
                                  2, 2.5L,  3,     kPi - 1e-3L, kPi - 1e-6L, kPi - 1e-9L,     kPi};
  std::mt19937_64 rng(chasles_test::kSeed + 6);
  std::uniform_real_distribution<double> uni(-1.0, 1.0);
  Worst direct, projected;
  std::vector<Worst> direct_by_angle(angles.size()), projected_by_angle(angles.size());
  for (std::size_t ia = 0; ia < angles.size(); ++ia) {
    const ld a = angles[ia];
    for (int axis = 0; axis < 12; ++axis) {
      const V3 n = axis < 3 ? V3(V3::Unit(axis)) : chasles_test::random_unit<double>(rng).cast<ld>();
      const V3 w_true = a * n;
      const M3 R = chasles_ref::exp3(w_true);
      for (ld d : ds) {
        for (int trial = 0; trial < 12; ++trial) {
          M3 E;
          for (int i = 0; i < 9; ++i) {
            const double r = uni(rng);
            E(i) = model == Perturbation::exactly_d ? (r < 0 ? -d : d) : d * ld(r);
          }
          const Mat3<T> M = (R + E).template cast<T>();
          const auto err = [&](const Vec3<T>& got_t) {
            const V3 got = got_t.template cast<ld>();
            ld e = (got - w_true).cwiseAbs().maxCoeff();
            // w - 2 pi w/|w| is the same rotation (the nearer one past pi).
            if (a > 0) e = std::min(e, (got - w_true * (1 - 2 * kPi / a)).cwiseAbs().maxCoeff());
            return e / d;  // in units of d
          };
          std::ostringstream at;
          at.precision(3);
          at << "w = " << str(w_true) << ", d = " << double(d) << ", trial " << trial;
          const ld e1 = err(SO3::from_matrix_unchecked(M).log());
          const ld e2 = err(SO3::from_matrix_projected(M).log());
          direct.update(e1, at.str());
          projected.update(e2, at.str());
          direct_by_angle[ia].update(e1, at.str());
          projected_by_angle[ia].update(e2, at.str());
        }
      }
    }
  }
  std::string worse_than_projection;
  for (std::size_t ia = 0; ia < angles.size(); ++ia) {
    const bool worse = !(direct_by_angle[ia].err <= 1.01L * projected_by_angle[ia].err);
    std::printf("[ info     ] off-SO(3) log %s, %s, angle %-22.19Lg: log %.3Lf d, projected first %.3Lf d%s\n",
                type_name<T>(), model_name, angles[ia], direct_by_angle[ia].err, projected_by_angle[ia].err,
                worse ? "  <- worse than projecting first" : "");
    if (worse) {
      std::ostringstream os;
      os.precision(4);
      os << "\n  angle " << double(angles[ia]) << ": log " << double(direct_by_angle[ia].err) << " d vs projected "
         << double(projected_by_angle[ia].err) << " d, at " << direct_by_angle[ia].where;
      worse_than_projection += os.str();
    }
  }
  std::printf("[ worst    ] off-SO(3) log %s, %s: log %.3Lf d (contract 2 d%s) at %s\n", type_name<T>(), model_name,
              direct.err, assert_two_d ? "" : ", not asserted here", direct.where.c_str());
  std::printf("[ worst    ] off-SO(3) log %s, %s: projected first %.3Lf d at %s\n", type_name<T>(), model_name,
              projected.err, projected.where.c_str());
  const std::string key = std::string(type_name<T>()) + (model == Perturbation::exactly_d ? "_exact_d" : "_uniform_d");
  ::testing::Test::RecordProperty("off_manifold_log_over_d_" + key, std::to_string(double(direct.err)));
  ::testing::Test::RecordProperty("off_manifold_projected_over_d_" + key, std::to_string(double(projected.err)));
  if (assert_two_d) {
    EXPECT_LE(direct.err, 2) << type_name<T>() << ", " << model_name << ", at " << direct.where
                             << " (projecting first: worst " << double(projected.err) << " d)";
  }
  EXPECT_TRUE(worse_than_projection.empty())
      << type_name<T>() << ", " << model_name << ": log worse than projecting first:" << worse_than_projection;
}

const std::vector<ld> kDoubleDefects = {1e-12L, 1e-11L, 1e-10L, 1e-9L};
// Float: d as far above float's rounding as 1e-12 is above double's
// (rounding adds < 2e-4 d) and small enough for first order (d^2 < 3e-3 d).
const std::vector<ld> kFloatDefects = {3e-4L, 1e-3L, 3e-3L};

TEST(LogOffManifold, DoubleEntriesOffByUniformD) {
  log_off_manifold<double>(Perturbation::uniform, kDoubleDefects, /*assert_two_d=*/true);
}
TEST(LogOffManifold, DoubleEntriesOffByExactlyD) {
  log_off_manifold<double>(Perturbation::exactly_d, kDoubleDefects, /*assert_two_d=*/false);
}
TEST(LogOffManifold, FloatEntriesOffByUniformD) {
  log_off_manifold<float>(Perturbation::uniform, kFloatDefects, /*assert_two_d=*/false);
}
TEST(LogOffManifold, FloatEntriesOffByExactlyD) {
  log_off_manifold<float>(Perturbation::exactly_d, kFloatDefects, /*assert_two_d=*/false);
}

// ---------------------------------------------------------------------------
// Scale: the nearest rotation to s R is R, and the rotation of the
// quaternion s q is that of q, for every finite nonzero s (documented:
// "for every finite M", "a quaternion of any nonzero norm").

template <typename T>
void scale_invariance() {
  using SO3 = chasles::SO3<T>;
  const ld tol = tolerance<T>(1e-15L);
  const V3 w(0.3L, -1.2L, 2.0L);
  const Mat3<T> R = chasles_ref::exp3(w).template cast<T>();
  const Eigen::Quaternion<T> q = Eigen::Quaternion<T>(chasles_ref::exp3(w).template cast<T>()).normalized();
  const M3 Rq = SO3::from_quaternion(q).matrix().template cast<ld>();
  Worst proj, quat;
  const int max_exp = std::numeric_limits<T>::max_exponent10 - 2;
  for (int e = -max_exp; e <= max_exp; e += (sizeof(T) == sizeof(float) ? 4 : 20)) {
    const T s = T(std::pow(10.0L, e));
    const M3 P = SO3::from_matrix_projected(Mat3<T>(s * R)).matrix().template cast<ld>();
    proj.update(max_abs(P - R.template cast<ld>()), "s = 1e" + std::to_string(e));
    const Eigen::Quaternion<T> qs(s * q.w(), s * q.x(), s * q.y(), s * q.z());
    const M3 Q = SO3::from_quaternion(qs).matrix().template cast<ld>();
    quat.update(max_abs(Q - Rq), "s = 1e" + std::to_string(e));
  }
  // The projection's own accuracy at s = 1 is a few eps; allow 4x the SO3 tolerance.
  report_t<T>("from_matrix_projected(s R) vs R", proj, 4 * tol);
  report_t<T>("from_quaternion(s q) vs from_quaternion(q)", quat, 4 * tol);
  EXPECT_LE(proj.err, 4 * tol) << type_name<T>() << " at " << proj.where;
  EXPECT_LE(quat.err, 4 * tol) << type_name<T>() << " at " << quat.where;
}

TEST(ScaleInvariance, Double) { scale_invariance<double>(); }
TEST(ScaleInvariance, Float) { scale_invariance<float>(); }

// ---------------------------------------------------------------------------
// At the scalars adjacent to pi: the two representable angles below T(pi),
// T(pi) itself and the two above it (float pi = 3.14159274 lies above pi,
// double pi below it), along the contract axes. The cases above stop at pi
// and sample float only down to a gap of 5e-4, so these angles, where a
// log built on acos or sqrt(1 - c^2) returns NaN, are checked here:
// SO3 and SE3 exp against the oracle (their formulas have no branch at pi,
// so the contract holds just past it), log of the rounded rotation a valid
// answer with either axis sign (exp3(log R) = R to the contract, |w| at
// most 4 eps past pi, as above), and SE3 log of the rounded motion to its
// contract.
template <typename T>
void adjacent_to_pi() {
  using SO3 = chasles::SO3<T>;
  using SE3 = chasles::SE3<T>;
  const ld tol = tolerance<T>(1e-15L), tol6 = tolerance<T>(2e-15L);
  std::vector<T> angles = {T(kPi)};
  for (int k = 0; k < 2; ++k) {
    angles.insert(angles.begin(), std::nextafter(angles.front(), T(0)));
    angles.push_back(std::nextafter(angles.back(), T(4)));
  }
  std::mt19937_64 rng(chasles_test::kSeed + 8);
  Worst exp3_err, log_valid, angle_excess, exp6_rot, exp6_trans, log6_rot, log6_trans;
  for (const T a : angles) {
    for (const Vec3<T>& u : contract_axes<T>()) {
      const Vec3<T> w = (a * u).eval();
      const std::string at = str(w);
      // exp, against the oracle.
      exp3_err.update(max_abs(SO3::exp(w).matrix().template cast<ld>() - chasles_ref::exp3(w.template cast<ld>())), at);
      // log of the rotation rounded to T: either sign, never NaN.
      const Mat3<T> R = rounded_rotation<T>(w.template cast<ld>());
      const Vec3<T> got = SO3::from_matrix_unchecked(R).log();
      log_valid.update(max_abs(chasles_ref::exp3(got.template cast<ld>()) - R.template cast<ld>()), at);
      angle_excess.update(std::max<ld>(0, angle_of(got) - kPi), at);
      // SE3, with a translation of size 1e3 across the axis (largest (1/2)[w] v).
      const Vec3<T> v = (T(1000) * u.cross(chasles_test::random_unit<T>(rng)).normalized()).eval();
      Vec6<T> xi;
      for (int i = 0; i < 3; ++i) {
        xi[i] = v[i];
        xi[i + 3] = w[i];
      }
      const M4 g = SE3::exp(xi).matrix().template cast<ld>();
      const M4 ref = chasles_ref::exp6(xi.template cast<ld>());
      exp6_rot.update(max_abs(M3(g.topLeftCorner<3, 3>() - ref.topLeftCorner<3, 3>())), str(xi));
      exp6_trans.update(relative_error<T>(g.topRightCorner<3, 1>(), ref.topRightCorner<3, 1>()), str(xi));
      const Mat4<T> gt = ref.template cast<T>();
      const M4 gl = gt.template cast<ld>();
      const V6 x = SE3::from_matrix_unchecked(gt).log().template cast<ld>();
      V6 r = chasles_ref::log6(gl);
      if (x.tail<3>().dot(r.tail<3>()) < 0)
        r = chasles_ref::log6_with_rotation(-r.tail<3>(), gl.topRightCorner<3, 1>());
      log6_rot.update((x.tail<3>() - r.tail<3>()).cwiseAbs().maxCoeff(), str(xi));
      log6_trans.update(relative_error<T>(x.head<3>(), r.head<3>()), str(xi));
    }
  }
  report_t<T>("SO3 exp entrywise, angles adjacent to pi", exp3_err, tol);
  report_t<T>("SO3 log valid, |exp(log R) - R|, adjacent to pi", log_valid, tol);
  report_t<T>("SO3 log: |w| - pi, adjacent to pi", angle_excess, 4 * eps<T>());
  report_t<T>("SE3 exp rotation, adjacent to pi", exp6_rot, tol6);
  report_t<T>("SE3 exp translation relative, adjacent to pi", exp6_trans, tol6);
  report_t<T>("SE3 log rotation (either sign), adjacent to pi", log6_rot, tol6);
  report_t<T>("SE3 log translation relative, adjacent to pi", log6_trans, tol6);
  EXPECT_LE(exp3_err.err, tol) << type_name<T>() << " at w = " << exp3_err.where;
  EXPECT_LE(log_valid.err, tol) << type_name<T>() << " at w = " << log_valid.where;
  EXPECT_LE(angle_excess.err, 4 * eps<T>()) << type_name<T>() << " at w = " << angle_excess.where;
  EXPECT_LE(exp6_rot.err, tol6) << type_name<T>() << " at xi = " << exp6_rot.where;
  EXPECT_LE(exp6_trans.err, tol6) << type_name<T>() << " at xi = " << exp6_trans.where;
  EXPECT_LE(log6_rot.err, tol6) << type_name<T>() << " at xi = " << log6_rot.where;
  EXPECT_LE(log6_trans.err, tol6) << type_name<T>() << " at xi = " << log6_trans.where;
}

TEST(AdjacentToPi, Double) { adjacent_to_pi<double>(); }
TEST(AdjacentToPi, Float) { adjacent_to_pi<float>(); }

}  // namespace
