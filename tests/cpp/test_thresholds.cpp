// Both sides of every cutoff (constants.hpp), in float and double: inputs
// whose theta^2 (exp) or sin^2(theta) = |vee(R - R^T)/2|^2 (log) lies one
// ulp below and one ulp above Thresholds<T>::taylor_theta2, the two sides
// of the log's branch at theta = pi/2 (cos(theta) = (tr R - 1)/2 >= 0 or
// < 0), and of huge_theta2 for exp. Each side is compared with the long
// double reference (support/reference.hpp) and the two sides with each
// other: they agree to a few ulps, here 4 (of 1 for rotation entries, of
// the result's size for rotation vectors and translations).
// Round-trip tests cannot see a threshold bug; these can.
//
// Also: the constants are what their comments claim.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <type_traits>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <chasles/constants.hpp>
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

constexpr ld kUlps = 4;  // "a few ulps"

ld max_abs(const M3& a) { return a.cwiseAbs().maxCoeff(); }

/// |a - b|_max in ulps of max(1, |b|_max) (T's ulps).
template <typename T, typename A, typename B>
ld ulps(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  return (a - b).cwiseAbs().maxCoeff() / (eps<T>() * std::max<ld>(1, b.cwiseAbs().maxCoeff()));
}

/// |a - b|_max in ulps of |b|_max (relative; a zero b must be matched exactly).
template <typename T, typename A, typename B>
ld rel_ulps(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  const ld scale = std::max(b.cwiseAbs().maxCoeff(), ld(std::numeric_limits<ld>::min()));
  return (a - b).cwiseAbs().maxCoeff() / (eps<T>() * scale);
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

template <typename T>
void report(const std::string& name, const Worst& w, ld tol_ulps = kUlps) {
  std::printf("[ worst    ] %-58s %6.2Lf ulps (tol %.2Lf) at %s\n", (name + " " + type_name<T>()).c_str(), w.err,
              tol_ulps, w.where.c_str());
  ::testing::Test::RecordProperty(name + " " + type_name<T>(), std::to_string(double(w.err)));
  EXPECT_LE(w.err, tol_ulps) << name << " " << type_name<T>() << " at " << w.where;
}

template <typename T>
std::vector<Vec3<T>> axes() {
  std::vector<Vec3<T>> ax = {Vec3<T>::UnitX(), Vec3<T>::UnitZ(), Vec3<T>(1, 1, 0).normalized(),
                             Vec3<T>(1, -2, 3).normalized(), Vec3<T>(1, 1, 1).normalized()};
  std::mt19937_64 rng(chasles_test::kSeed + 21);
  for (int i = 0; i < 11; ++i) ax.push_back(chasles_test::random_unit<T>(rng));
  return ax;
}

/// Adjacent scalars lo < hi (one ulp apart) with |lo u|^2 < cutoff <= |hi u|^2,
/// the squared norm evaluated as the library evaluates it.
template <typename T>
std::pair<T, T> straddle(const Vec3<T>& u, T cutoff) {
  const auto t = [&](T s) { return Vec3<T>(s * u).squaredNorm(); };
  T s = T(std::sqrt(ld(cutoff) / ld(u.squaredNorm())));
  for (int k = 0; k < 64 && !(t(s) < cutoff); ++k) s = std::nextafter(s, T(0));
  for (int k = 0; k < 64 && t(std::nextafter(s, T(1e300))) < cutoff; ++k) s = std::nextafter(s, T(1e300));
  const T hi = std::nextafter(s, std::numeric_limits<T>::infinity());
  EXPECT_LT(t(s), cutoff);
  EXPECT_GE(t(hi), cutoff);
  return {s, hi};
}

// ---------------------------------------------------------------------------
// The constants.

template <typename T>
void constants_as_documented() {
  using Th = chasles::Thresholds<T>;
  EXPECT_EQ(Th::epsilon, std::numeric_limits<T>::epsilon());
  const T cbrt_eps = T(std::cbrt(ld(std::numeric_limits<T>::epsilon())));
  const T sqrt_eps = T(std::sqrt(ld(std::numeric_limits<T>::epsilon())));
  EXPECT_GE(Th::taylor_theta2, std::nextafter(cbrt_eps, T(0)));
  EXPECT_LE(Th::taylor_theta2, std::nextafter(cbrt_eps, T(1)));
  EXPECT_GE(Th::rotation_tolerance, std::nextafter(sqrt_eps, T(0)));
  EXPECT_LE(Th::rotation_tolerance, std::nextafter(sqrt_eps, T(1)));
  std::printf(
      "[ info     ] %-11s taylor_theta2 %.10Lg (cbrt eps %.10Lg), rotation_tolerance %.10Lg (sqrt eps %.10Lg)\n",
      sizeof(T) == sizeof(float) ? "float" : (sizeof(T) == sizeof(double) ? "double" : "long double"),
      ld(Th::taylor_theta2), std::cbrt(ld(std::numeric_limits<T>::epsilon())), ld(Th::rotation_tolerance),
      std::sqrt(ld(std::numeric_limits<T>::epsilon())));
}

/// "3900 times a rotation's (|u|^2 <= 256) and 226 times below float's
/// overflow (2.26e8)", and above the clamped path's 3.5e4 (log_quaternion_norm2).
template <typename T>
void log_quaternion_norm2_as_documented() {
  const ld c = chasles::Thresholds<T>::log_quaternion_norm2;
  EXPECT_GE(c, 256 * 3900.0L);
  EXPECT_GE(c, 3.5e4L);
  EXPECT_LE(c, 2.26e8L / 226);
}

TEST(Constants, FloatAsDocumented) {
  constants_as_documented<float>();
  log_quaternion_norm2_as_documented<float>();
  // "Chosen a factor 1e8 below the largest finite value".
  EXPECT_LE(chasles::Thresholds<float>::huge_theta2, std::numeric_limits<float>::max() / 1e8f);
  EXPECT_GE(chasles::Thresholds<float>::huge_theta2, std::numeric_limits<float>::max() / 1e9f);
  EXPECT_LE(chasles::Thresholds<float>::huge_norm2, std::numeric_limits<float>::max() / 1e8f);
  EXPECT_GE(chasles::Thresholds<float>::huge_norm2, std::numeric_limits<float>::max() / 1e9f);
  EXPECT_EQ(chasles::Thresholds<float>::tiny_norm2, 1 / chasles::Thresholds<float>::huge_norm2);
}
TEST(Constants, DoubleAsDocumented) {
  constants_as_documented<double>();
  log_quaternion_norm2_as_documented<double>();
  EXPECT_LE(chasles::Thresholds<double>::huge_theta2, std::numeric_limits<double>::max() / 1e8);
  EXPECT_GE(chasles::Thresholds<double>::huge_theta2, std::numeric_limits<double>::max() / 1e9);
  EXPECT_LE(chasles::Thresholds<double>::huge_norm2, std::numeric_limits<double>::max() / 1e8);
  EXPECT_GE(chasles::Thresholds<double>::huge_norm2, std::numeric_limits<double>::max() / 1e9);
  EXPECT_EQ(chasles::Thresholds<double>::tiny_norm2, 1 / chasles::Thresholds<double>::huge_norm2);
}
TEST(Constants, LongDoubleAsDocumented) {
  constants_as_documented<long double>();
  // "as double: safe for both long double formats" (long double may be double).
  EXPECT_LE(chasles::Thresholds<long double>::huge_theta2, (long double)(std::numeric_limits<double>::max() / 1e8));
  EXPECT_LE(chasles::Thresholds<long double>::huge_norm2, (long double)(std::numeric_limits<double>::max() / 1e8));
}
TEST(Constants, AutodiffUsesItsRealType) {
  using AD = Eigen::AutoDiffScalar<Eigen::Matrix<double, 3, 1>>;
  static_assert(std::is_same<chasles::RealOf<AD>, double>::value, "RealOf<autodiff over double> is double");
  EXPECT_EQ(chasles::ThresholdsOf<AD>::taylor_theta2, chasles::Thresholds<double>::taylor_theta2);
}

// ---------------------------------------------------------------------------
// exp: theta^2 one ulp either side of taylor_theta2.

template <typename T>
void exp_across_taylor_cutoff() {
  using SO3 = chasles::SO3<T>;
  using SE3 = chasles::SE3<T>;
  const T cutoff = chasles::Thresholds<T>::taylor_theta2;
  std::mt19937_64 rng(chasles_test::kSeed + 22);
  Worst so3_ref, so3_jump, se3_rot_ref, se3_trans_ref, se3_trans_jump;
  for (const Vec3<T>& u : axes<T>()) {
    const auto [lo, hi] = straddle<T>(u, cutoff);
    const Vec3<T> w_lo = lo * u, w_hi = hi * u;
    const std::string at = "w = " + str(w_lo) + " / " + str(w_hi);
    const M3 R_lo = SO3::exp(w_lo).matrix().template cast<ld>(), R_hi = SO3::exp(w_hi).matrix().template cast<ld>();
    const M3 ref_lo = chasles_ref::exp3(w_lo.template cast<ld>()), ref_hi = chasles_ref::exp3(w_hi.template cast<ld>());
    so3_ref.update(std::max(ulps<T>(R_lo, ref_lo), ulps<T>(R_hi, ref_hi)), at);
    so3_jump.update(ulps<T>(M3(R_hi - R_lo), M3(ref_hi - ref_lo)), at);
    // SE3: translations along, across and at random to the axis, size 1 and 1e3.
    for (int k = 0; k < 6; ++k) {
      Vec3<T> v = chasles_test::random_unit<T>(rng);
      if (k % 3 == 0) v = u;
      if (k % 3 == 1) v = u.cross(v).normalized();
      if (k >= 3) v *= T(1000);
      Vec6<T> xi_lo, xi_hi;
      for (int i = 0; i < 3; ++i) {
        xi_lo[i] = xi_hi[i] = v[i];
        xi_lo[i + 3] = w_lo[i];
        xi_hi[i + 3] = w_hi[i];
      }
      const M4 g_lo = SE3::exp(xi_lo).matrix().template cast<ld>(), g_hi = SE3::exp(xi_hi).matrix().template cast<ld>();
      const M4 rg_lo = chasles_ref::exp6(xi_lo.template cast<ld>()),
               rg_hi = chasles_ref::exp6(xi_hi.template cast<ld>());
      const std::string at6 = "xi = " + str(xi_lo) + " / " + str(xi_hi);
      se3_rot_ref.update(std::max(ulps<T>(M3(g_lo.topLeftCorner<3, 3>()), M3(rg_lo.topLeftCorner<3, 3>())),
                                  ulps<T>(M3(g_hi.topLeftCorner<3, 3>()), M3(rg_hi.topLeftCorner<3, 3>()))),
                         at6);
      const V3 p_lo = g_lo.topRightCorner<3, 1>(), p_hi = g_hi.topRightCorner<3, 1>();
      const V3 rp_lo = rg_lo.topRightCorner<3, 1>(), rp_hi = rg_hi.topRightCorner<3, 1>();
      se3_trans_ref.update(std::max(rel_ulps<T>(p_lo, rp_lo), rel_ulps<T>(p_hi, rp_hi)), at6);
      // The jump, in ulps of |p|: (p_hi - p_lo) against (ref_hi - ref_lo).
      se3_trans_jump.update(
          (V3(p_hi - p_lo) - V3(rp_hi - rp_lo)).cwiseAbs().maxCoeff() / (eps<T>() * rp_lo.cwiseAbs().maxCoeff()), at6);
    }
  }
  report<T>("SO3 exp at taylor_theta2, each side vs reference", so3_ref);
  report<T>("SO3 exp at taylor_theta2, jump between sides", so3_jump);
  report<T>("SE3 exp at taylor_theta2, rotation vs reference", se3_rot_ref);
  report<T>("SE3 exp at taylor_theta2, translation vs reference", se3_trans_ref);
  report<T>("SE3 exp at taylor_theta2, translation jump", se3_trans_jump);
}

TEST(TaylorCutoff, ExpDouble) { exp_across_taylor_cutoff<double>(); }
TEST(TaylorCutoff, ExpFloat) { exp_across_taylor_cutoff<float>(); }

// ---------------------------------------------------------------------------
// log: sin^2(theta) one step either side of taylor_theta2, and the
// switch of Shepperd's column from w to an axis component.

/// Rotation matrices in T on both sides of a branch of the log: along the
/// axis u, angles theta0 (1 + k eps) for k = -kmax .. kmax, rounded to T;
/// returns the first adjacent pair (in k) where `side` changes.
template <typename T, typename Side>
bool find_branch_pair(const Vec3<T>& u, ld theta0, Side side, Mat3<T>& below, Mat3<T>& above, V3& w_below,
                      V3& w_above) {
  const V3 ul = u.template cast<ld>();
  const int kmax = 400;
  Mat3<T> prev = Mat3<T>::Zero();
  V3 prev_w = V3::Zero();
  bool have_prev = false;
  for (int k = -kmax; k <= kmax; ++k) {
    const V3 w = theta0 * (1 + ld(k) * eps<T>()) * ul;
    const Mat3<T> R = chasles_ref::exp3(w).template cast<T>();
    if (have_prev && side(prev) != side(R)) {
      if (side(prev)) {
        below = prev, above = R, w_below = prev_w, w_above = w;
      } else {
        below = R, above = prev, w_below = w, w_above = prev_w;
      }
      return true;
    }
    prev = R;
    prev_w = w;
    have_prev = true;
  }
  return false;
}

template <typename T>
void log_across_branch(const char* name, ld (*theta0_of_axis)(const V3&), bool (*side)(const Mat3<T>&)) {
  using SO3 = chasles::SO3<T>;
  using SE3 = chasles::SE3<T>;
  std::mt19937_64 rng(chasles_test::kSeed + 23);
  Worst so3_ref, so3_jump, se3_rot_ref, se3_trans_ref, se3_trans_jump;
  int pairs = 0;
  for (const Vec3<T>& u : axes<T>()) {
    Mat3<T> A = Mat3<T>::Zero(), B = Mat3<T>::Zero();  // A on the `side` = true side
    V3 wa = V3::Zero(), wb = V3::Zero();
    const ld theta0 = theta0_of_axis(u.template cast<ld>());
    if (!find_branch_pair<T>(u, theta0, side, A, B, wa, wb)) continue;
    ++pairs;
    const std::string at = "w = " + str(wa) + " / " + str(wb);
    const V3 got_a = SO3::from_matrix_unchecked(A).log().template cast<ld>();
    const V3 got_b = SO3::from_matrix_unchecked(B).log().template cast<ld>();
    const V3 ref_a = chasles_ref::log3(A.template cast<ld>()), ref_b = chasles_ref::log3(B.template cast<ld>());
    so3_ref.update(std::max(rel_ulps<T>(got_a, ref_a), rel_ulps<T>(got_b, ref_b)), at);
    so3_jump.update(
        (V3(got_b - got_a) - V3(ref_b - ref_a)).cwiseAbs().maxCoeff() / (eps<T>() * ref_a.cwiseAbs().maxCoeff()), at);
    for (int k = 0; k < 6; ++k) {
      Vec3<T> p = chasles_test::random_unit<T>(rng);
      if (k % 3 == 0) p = u;
      if (k % 3 == 1) p = u.cross(p).normalized();
      if (k >= 3) p *= T(1000);
      Mat4<T> ga = Mat4<T>::Identity(), gb = Mat4<T>::Identity();
      ga.template topLeftCorner<3, 3>() = A;
      gb.template topLeftCorner<3, 3>() = B;
      ga.template topRightCorner<3, 1>() = gb.template topRightCorner<3, 1>() = p;
      const V6 xa = SE3::from_matrix_unchecked(ga).log().template cast<ld>();
      const V6 xb = SE3::from_matrix_unchecked(gb).log().template cast<ld>();
      const V6 ra = chasles_ref::log6(ga.template cast<ld>()), rb = chasles_ref::log6(gb.template cast<ld>());
      const std::string at6 = at + ", p = " + str(p);
      se3_rot_ref.update(std::max(rel_ulps<T>(xa.tail<3>(), ra.tail<3>()), rel_ulps<T>(xb.tail<3>(), rb.tail<3>())),
                         at6);
      se3_trans_ref.update(std::max(rel_ulps<T>(xa.head<3>(), ra.head<3>()), rel_ulps<T>(xb.head<3>(), rb.head<3>())),
                           at6);
      se3_trans_jump.update((V3(xb.head<3>() - xa.head<3>()) - V3(rb.head<3>() - ra.head<3>())).cwiseAbs().maxCoeff() /
                                (eps<T>() * ra.head<3>().cwiseAbs().maxCoeff()),
                            at6);
    }
  }
  std::printf("[ info     ] %s %s: %d pairs of matrices straddling the branch\n", name, type_name<T>(), pairs);
  EXPECT_GE(pairs, 10) << "the inputs must straddle the branch";
  report<T>(std::string(name) + ", SO3 log each side vs reference", so3_ref);
  report<T>(std::string(name) + ", SO3 log jump", so3_jump);
  report<T>(std::string(name) + ", SE3 log w vs reference", se3_rot_ref);
  report<T>(std::string(name) + ", SE3 log v vs reference", se3_trans_ref);
  report<T>(std::string(name) + ", SE3 log v jump", se3_trans_jump);
}

/// The library's own choice of branch (detail::so3_log reports it).
template <typename T>
bool log_series_branch(const Mat3<T>& R) {
  return chasles::detail::so3_log<T>(R).near_identity;
}

/// The column of Horn's K the log starts from (detail/nearest_rotation.hpp)
/// is w's (true) or an axis component's (false).
template <typename T>
bool log_w_column(const Mat3<T>& R) {
  return chasles::detail::HornMatrix<T>(R).largest_diagonal() == 0;
}

/// sin^2(theta) = taylor_theta2: a rotation's log takes the series on
/// |vee(R - R^T) / 2|^2 = sin^2(theta) (detail::so3_log).
template <typename T>
ld series_cutoff_angle(const V3&) {
  return std::asin(std::sqrt(ld(chasles::Thresholds<T>::taylor_theta2)));
}

/// w^2 = max_i (n_i sin(theta/2))^2: theta = 2 atan(1 / max |n_i|).
ld column_switch_angle(const V3& n) { return 2 * std::atan(1 / n.cwiseAbs().maxCoeff()); }

/// theta < pi/2 (|u_v|^2 < u_w^2 in so3_log's quaternion u), where the
/// rational atan (detail/series.hpp) switches from atan(|u_v| / u_w) to
/// pi/2 - atan(u_w / |u_v|).
template <typename T>
bool log_acute(const Mat3<T>& R) {
  const auto u = chasles::detail::quaternion_power_step(chasles::detail::HornMatrix<T>(R));
  return u.x * u.x + u.y * u.y + u.z * u.z < u.w * u.w;
}

ld half_turn_angle(const V3&) { return kPi / 2; }

TEST(TaylorCutoff, LogDouble) {
  log_across_branch<double>("log at taylor_theta2", series_cutoff_angle<double>, log_series_branch<double>);
}
TEST(TaylorCutoff, LogFloat) {
  log_across_branch<float>("log at taylor_theta2", series_cutoff_angle<float>, log_series_branch<float>);
}
TEST(ShepperdColumnSwitch, LogDouble) {
  log_across_branch<double>("log at the column switch", column_switch_angle, log_w_column<double>);
}
TEST(ShepperdColumnSwitch, LogFloat) {
  log_across_branch<float>("log at the column switch", column_switch_angle, log_w_column<float>);
}

TEST(LogAcuteSwitch, Double) { log_across_branch<double>("log at theta = pi/2", half_turn_angle, log_acute<double>); }
TEST(LogAcuteSwitch, Float) { log_across_branch<float>("log at theta = pi/2", half_turn_angle, log_acute<float>); }

// ---------------------------------------------------------------------------
// log at log_quaternion_norm2: past it so3_log normalizes its quaternion u
// before the rational atan. M = c R for c > 0 scales u smoothly (as c^2 in
// the power step's dominant terms), so the c either side of the threshold
// give logs that must agree to a few ulps, each side computed its own way.
// Far past it, and past overflow, the log stays finite and of angle <= pi.

template <typename T>
void log_across_quaternion_norm_cutoff() {
  using SO3 = chasles::SO3<T>;
  const T cutoff = chasles::Thresholds<T>::log_quaternion_norm2;
  const auto u2_of = [](const Mat3<T>& M) {
    const auto u = chasles::detail::quaternion_power_step(chasles::detail::HornMatrix<T>(M));
    return u.w * u.w + u.x * u.x + u.y * u.y + u.z * u.z;
  };
  std::mt19937_64 rng(chasles_test::kSeed + 24);
  Worst jump;
  int pairs = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const Vec3<T> w = (chasles_test::random_unit<T>(rng) * T(0.1 + 3.0 * trial / 40)).eval();
    const Mat3<T> R = chasles_ref::exp3(w.template cast<ld>()).template cast<T>();
    // Bisect c (in T) for u2(c R) <= cutoff < u2(next c R).
    T lo = T(1), hi = T(1e6);
    if (!(u2_of(lo * R) <= cutoff) || !(u2_of(hi * R) > cutoff)) continue;
    while (std::nextafter(lo, hi) != hi) {
      const T mid = lo + (hi - lo) / 2;
      if (mid == lo || mid == hi) break;
      (u2_of(mid * R) <= cutoff ? lo : hi) = mid;
    }
    const Mat3<T> below = lo * R, above = hi * R;
    if (!(u2_of(below) <= cutoff && u2_of(above) > cutoff)) continue;
    ++pairs;
    const Vec3<T> wb = SO3::from_matrix_unchecked(below).log(), wa = SO3::from_matrix_unchecked(above).log();
    jump.update(ulps<T>(wa.template cast<ld>(), wb.template cast<ld>()), "w = " + str(w.template cast<ld>()));
    // Far past the threshold and past overflow: finite, angle <= pi.
    for (T c : {T(1e8), T(1e20), std::numeric_limits<T>::max() / T(4)}) {
      const Vec3<T> wc = SO3::from_matrix_unchecked(Mat3<T>(c * R)).log();
      EXPECT_TRUE(wc.allFinite()) << "c = " << c;
      EXPECT_LE(ld(wc.norm()), kPi * (1 + 4 * eps<T>())) << "c = " << c;
    }
  }
  std::printf("[ info     ] log at log_quaternion_norm2 %s: %d pairs of matrices straddling it\n", type_name<T>(),
              pairs);
  EXPECT_GE(pairs, 30);
  report<T>("log at log_quaternion_norm2, jump between sides", jump);
}

TEST(LogQuaternionNormCutoff, Double) { log_across_quaternion_norm_cutoff<double>(); }
TEST(LogQuaternionNormCutoff, Float) { log_across_quaternion_norm_cutoff<float>(); }

// ---------------------------------------------------------------------------
// exp at huge_theta2: past it the angle is not known to within a turn, so
// both sides are checked for what carries information: R is a rotation
// about the input's axis, and p = V v keeps n . p = n . v and |p| <= |v|.
// No reference exists there (theta mod 2 pi would need theta to 1e-150
// relative), so the bounds are those the exp contracts imply: entries
// within e = 1e-15 (SO3) of a rotation give |R^T R - I| <= 2 sqrt(3) e and
// |R n - n| <= sqrt(3) e; a translation within 2e-15 |p| relative gives
// |n.p - n.v| and (|p| - |v|)+ <= sqrt(3) 2e-15 |v|.

template <typename T>
void exp_across_huge_cutoff() {
  using SO3 = chasles::SO3<T>;
  using SE3 = chasles::SE3<T>;
  const T cutoff = chasles::Thresholds<T>::huge_theta2;
  std::mt19937_64 rng(chasles_test::kSeed + 24);
  Worst orthonormal, axis, along, bound;
  for (const Vec3<T>& u0 : axes<T>()) {
    const auto [lo, hi] = straddle<T>(u0, cutoff);
    for (T s : {lo, hi}) {
      const Vec3<T> w = s * u0;
      const V3 n = w.template cast<ld>() / chasles_ref::scaled_norm(w.template cast<ld>());
      const M3 R = SO3::exp(w).matrix().template cast<ld>();
      const std::string at = "w = " + str(w);
      orthonormal.update(max_abs(R.transpose() * R - M3::Identity()) / eps<T>(), at);
      axis.update((R * n - n).cwiseAbs().maxCoeff() / eps<T>(), at);
      const Vec3<T> v = chasles_test::random_unit<T>(rng) * T(100);
      Vec6<T> xi;
      for (int i = 0; i < 3; ++i) {
        xi[i] = v[i];
        xi[i + 3] = w[i];
      }
      const V3 p = SE3::exp(xi).translation().template cast<ld>();
      const V3 vl = v.template cast<ld>();
      along.update(std::fabs(n.dot(p) - n.dot(vl)) / (eps<T>() * vl.norm()), "xi = " + str(xi));
      bound.update(std::max<ld>(0, p.norm() - vl.norm()) / (eps<T>() * vl.norm()), "xi = " + str(xi));
    }
  }
  const ld e = 1e-15L / ld(std::numeric_limits<double>::epsilon());  // the SO3 exp contract, in ulps
  report<T>("exp at huge_theta2: |R^T R - I|", orthonormal, 2 * std::sqrt(3.0L) * e);
  report<T>("exp at huge_theta2: |R n - n|", axis, std::sqrt(3.0L) * e);
  report<T>("exp at huge_theta2: |n.p - n.v| / |v|", along, std::sqrt(3.0L) * 2 * e);
  report<T>("exp at huge_theta2: (|p| - |v|)+ / |v|", bound, std::sqrt(3.0L) * 2 * e);
}

TEST(HugeCutoff, ExpDouble) { exp_across_huge_cutoff<double>(); }
TEST(HugeCutoff, ExpFloat) { exp_across_huge_cutoff<float>(); }

}  // namespace
