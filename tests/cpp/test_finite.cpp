// No NaN and no inf from any finite input, in any operation: exp of huge
// vectors (up to 1e300 and past the overflow of |w|^2), log of arbitrary
// finite matrices (zero, huge and tiny entries, reflections, singular),
// quaternions of arbitrary matrices, from_quaternion of zero, tiny and
// huge quaternions, projections, and screws of zero (and large) twists;
// and vee(hat(x)) == x exactly, for every group and scalar, at the smallest
// subnormal and at the largest finite numbers.
// Only inputs whose true result is representable are used (for SE3 exp,
// |V v| <= |v|, so v is kept at or below 1e300).
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <chasles/chasles.hpp>

#include "support/format.hpp"
#include "support/samples.hpp"

namespace {

using chasles_test::Mat3;
using chasles_test::Mat4;
using chasles_test::str;
using chasles_test::type_name;
using chasles_test::Vec3;
using chasles_test::Vec6;

/// Counts the inputs of one operation whose output is not finite, and
/// keeps the first of them.
struct Failures {
  int count = 0, total = 0;
  std::string first;
  template <typename In, typename Out>
  void check(bool finite, const In& input, const Out& output) {
    ++total;
    if (finite) return;
    if (count++ == 0) first = "input " + str(input) + " gives " + str(output);
  }
};

void expect_none(const Failures& f, const std::string& what) {
  std::printf("[ info     ] %-48s %d non-finite of %d inputs\n", what.c_str(), f.count, f.total);
  EXPECT_EQ(f.count, 0) << what << ": " << f.count << " of " << f.total
                        << " inputs give NaN or inf; first: " << f.first;
}

/// sign * 10^x, x uniform in [lo, hi] (then rounded to T: may be 0 or
/// subnormal at the low end, never inf).
template <typename T>
T log_uniform(std::mt19937_64& rng, double lo, double hi) {
  std::uniform_real_distribution<double> ex(lo, hi), sg(-1, 1);
  const long double v = std::pow(10.0L, (long double)ex(rng));
  const long double m = std::numeric_limits<T>::max();
  return T((sg(rng) < 0 ? -1 : 1) * (v > m ? m : v));
}

template <typename T>
double max_exp10() {
  return std::log10(double(std::numeric_limits<T>::max()));
}
template <typename T>
double min_exp10() {
  return std::log10(double(std::numeric_limits<T>::denorm_min()));
}

/// Vectors of every magnitude, entry by entry and as a whole, with zeros,
/// subnormals, the extremes, and (e.g.) one huge entry beside tiny ones.
template <typename T, int N>
std::vector<Eigen::Matrix<T, N, 1>> wild_vectors(double hi, int n_random = 3000) {
  using V = Eigen::Matrix<T, N, 1>;
  std::mt19937_64 rng(chasles_test::kSeed + 11);
  const T big = std::numeric_limits<T>::max(), tiny = std::numeric_limits<T>::denorm_min();
  const T top = T(std::min<long double>(std::pow(10.0L, hi), big));
  std::vector<V> out;
  out.push_back(V::Zero());
  for (T s : {tiny, std::numeric_limits<T>::min(), T(1), top, -top})
    for (int i = 0; i < N; ++i) {
      out.push_back(V::Constant(s));
      V e = V::Zero();
      e[i] = s;
      out.push_back(e);
    }
  std::uniform_real_distribution<double> u(0, 1);
  for (int k = 0; k < n_random; ++k) {
    V v;
    if (k % 2 == 0) {
      for (int i = 0; i < N; ++i) v[i] = u(rng) < 0.1 ? T(0) : log_uniform<T>(rng, min_exp10<T>(), hi);
    } else {
      const double e = min_exp10<T>() + (hi - min_exp10<T>()) * u(rng);
      std::normal_distribution<double> nd(0, 1);
      for (int i = 0; i < N; ++i) v[i] = T(std::pow(10.0L, e) * nd(rng));
      for (int i = 0; i < N; ++i)
        if (!std::isfinite(v[i])) v[i] = v[i] > 0 ? top : -top;
    }
    out.push_back(v);
  }
  for (const V& v : out) EXPECT_TRUE(v.allFinite()) << "test bug: input " << str(v);
  return out;
}

/// Arbitrary finite 3x3 matrices: zero, identity, reflections, singular,
/// rank one, random of every scale up to the largest finite value, and
/// rotations times huge or tiny factors.
template <typename T>
std::vector<Mat3<T>> wild_matrices(int n_random = 3000) {
  using M = Mat3<T>;
  std::mt19937_64 rng(chasles_test::kSeed + 12);
  const T big = std::numeric_limits<T>::max();
  std::vector<M> out;
  out.push_back(M::Zero());
  out.push_back(M::Identity());
  out.push_back(-M::Identity());
  out.push_back(Vec3<T>(1, 1, -1).asDiagonal());
  out.push_back(Vec3<T>(-1, 1, 1).asDiagonal());
  out.push_back(Vec3<T>(1, -1, -1).asDiagonal());
  out.push_back(M::Ones());
  out.push_back(M::Constant(big));
  out.push_back(M::Identity() * big);
  out.push_back(-M::Identity() * big);
  out.push_back(M::Identity() * std::numeric_limits<T>::denorm_min());
  M alternating;
  alternating << big, -big, big, -big, big, -big, big, -big, big;
  out.push_back(alternating);
  const T h = sizeof(T) == sizeof(float) ? T(1e36) : T(1e300);  // huge but well inside the range
  M mixed;  // large antisymmetric and symmetric parts of opposite signs
  mixed << h, h, -h, 0, -h, 0, 0, h, -h;
  out.insert(out.begin(), mixed);
  M skew_huge = M::Identity();  // |vee(R - R^T)/2|^2 overflows, trace fine
  skew_huge(1, 0) = sizeof(T) == sizeof(float) ? T(1e20) : T(1e155);
  skew_huge(0, 1) = -skew_huge(1, 0);
  out.insert(out.begin(), skew_huge);
  for (const auto& w : chasles_test::rotation_vectors<T>(16)) {
    const M R = chasles::SO3<T>::exp(w).matrix();
    out.push_back(R);
    out.push_back(R * Vec3<T>(1, 1, -1).asDiagonal());  // reflection
    out.push_back(T(1e-3) * R);
    out.push_back(h * R);
    out.push_back(std::numeric_limits<T>::min() * R);
    out.push_back((big / 2) * R);
  }
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> nd(0, 1);
  for (int k = 0; k < n_random; ++k) {
    M m;
    if (k % 3 == 0) {
      for (int i = 0; i < 9; ++i) m(i) = u(rng) < 0.1 ? T(0) : log_uniform<T>(rng, min_exp10<T>(), max_exp10<T>());
    } else if (k % 3 == 1) {
      const double e = min_exp10<T>() + (max_exp10<T>() - min_exp10<T>()) * u(rng);
      for (int i = 0; i < 9; ++i) {
        const long double x = std::pow(10.0L, e) * nd(rng);
        m(i) = std::fabs(x) > big ? (x > 0 ? big : -big) : T(x);
      }
    } else {  // rank one
      Vec3<T> a, b;
      for (int i = 0; i < 3; ++i) {
        a[i] = log_uniform<T>(rng, -10, 10);
        b[i] = log_uniform<T>(rng, -10, 10);
      }
      m = a * b.transpose();
    }
    out.push_back(m);
  }
  for (const M& m : out) EXPECT_TRUE(m.allFinite()) << "test bug: input " << str(m);
  return out;
}

template <typename T>
Mat4<T> with_translation(const Mat3<T>& R, const Vec3<T>& p) {
  Mat4<T> g = Mat4<T>::Identity();
  g.template topLeftCorner<3, 3>() = R;
  g.template topRightCorner<3, 1>() = p;
  return g;
}

template <typename T>
double translation_limit() {
  return sizeof(T) == sizeof(float) ? 30.0 : 300.0;  // 1e300 in double, as far in float
}

// ---------------------------------------------------------------------------

template <typename T>
void so3_exp_finite() {
  Failures f;
  for (const Vec3<T>& w : wild_vectors<T, 3>(max_exp10<T>())) {
    const Mat3<T> R = chasles::SO3<T>::exp(w).matrix();
    f.check(R.allFinite(), w, R);
  }
  expect_none(f, std::string("SO3::exp ") + type_name<T>());
}
/// vee(hat(x)) == x bit for bit with entries of +-the smallest subnormal,
/// +-the largest finite number, 1 and 0, at every position.
template <typename G>
void vee_of_hat_is_exact() {
  using S = typename G::Scalar;
  using T = typename G::Tangent;
  const S values[] = {std::numeric_limits<S>::denorm_min(),
                      -std::numeric_limits<S>::denorm_min(),
                      std::numeric_limits<S>::max(),
                      -std::numeric_limits<S>::max(),
                      S(1),
                      S(0)};
  for (int i = 0; i < G::DoF; ++i)
    for (const S v : values) {
      T x = T::Constant(S(0.5));
      x[i] = v;
      const T back = G::vee(G::hat(x));
      for (int k = 0; k < G::DoF; ++k)
        EXPECT_TRUE(back[k] <= x[k] && back[k] >= x[k]) << type_name<S>() << " entry " << i << " = " << v;
    }
}

TEST(Finite, VeeOfHatIsExact) {
  vee_of_hat_is_exact<chasles::SO2<double>>();
  vee_of_hat_is_exact<chasles::SE2<double>>();
  vee_of_hat_is_exact<chasles::SO3<double>>();
  vee_of_hat_is_exact<chasles::SE3<double>>();
  vee_of_hat_is_exact<chasles::Sim3<double>>();
  vee_of_hat_is_exact<chasles::SE23<double>>();
  vee_of_hat_is_exact<chasles::SO3<float>>();
  vee_of_hat_is_exact<chasles::SE23<float>>();
}

TEST(Finite, SO3ExpDouble) { so3_exp_finite<double>(); }
TEST(Finite, SO3ExpFloat) { so3_exp_finite<float>(); }

/// w of every size, v up to 1e300 (so that V v, of norm <= |v|, is finite).
template <typename T>
void se3_exp_finite() {
  Failures f;
  {
    // Smallest case: a moderate rotation (|w|^2 far below huge_theta2) and a
    // translation of 1e300 (double; 1e30 float): w x v overflows.
    Vec6<T> xi = Vec6<T>::Zero();
    xi[1] = sizeof(T) == sizeof(float) ? T(1e30) : T(1e300);
    xi[3] = T(1e10);
    const Mat4<T> g = chasles::SE3<T>::exp(xi).matrix();
    f.check(g.allFinite(), xi, g);
  }
  const auto ws = wild_vectors<T, 3>(max_exp10<T>(), 1500);
  const auto vs = wild_vectors<T, 3>(translation_limit<T>(), 1500);
  for (std::size_t i = 0; i < ws.size(); ++i) {
    for (std::size_t j : {i, ws.size() - 1 - i, (i * 7919) % vs.size()}) {
      Vec6<T> xi;
      for (int k = 0; k < 3; ++k) {
        xi[k] = vs[j % vs.size()][k];
        xi[k + 3] = ws[i][k];
      }
      const Mat4<T> g = chasles::SE3<T>::exp(xi).matrix();
      f.check(g.allFinite(), xi, g);
    }
  }
  expect_none(f, std::string("SE3::exp ") + type_name<T>());
}
TEST(Finite, SE3ExpDouble) { se3_exp_finite<double>(); }
TEST(Finite, SE3ExpFloat) { se3_exp_finite<float>(); }

template <typename T>
void so3_log_finite() {
  Failures f;
  for (const Mat3<T>& M : wild_matrices<T>()) {
    const Vec3<T> w = chasles::SO3<T>::from_matrix_unchecked(M).log();
    f.check(w.allFinite(), M, w);
  }
  expect_none(f, std::string("SO3::log ") + type_name<T>());
}
TEST(Finite, SO3LogDouble) { so3_log_finite<double>(); }
TEST(Finite, SO3LogFloat) { so3_log_finite<float>(); }

template <typename T>
void se3_log_finite() {
  Failures f;
  const auto ps = wild_vectors<T, 3>(translation_limit<T>(), 200);
  const auto Ms = wild_matrices<T>();
  for (std::size_t i = 0; i < Ms.size(); ++i) {
    for (const Vec3<T>& p : {Vec3<T>(Vec3<T>::Zero()), Vec3<T>(Vec3<T>::Ones()), ps[i % ps.size()]}) {
      const Mat4<T> g = with_translation<T>(Ms[i], p);
      const Vec6<T> xi = chasles::SE3<T>::from_matrix_unchecked(g).log();
      f.check(xi.allFinite(), g, xi);
    }
  }
  expect_none(f, std::string("SE3::log ") + type_name<T>());
}
TEST(Finite, SE3LogDouble) { se3_log_finite<double>(); }
TEST(Finite, SE3LogFloat) { se3_log_finite<float>(); }

template <typename T>
void quaternion_finite() {
  Failures f;
  {
    // Smallest case: a large multiple of the identity (1e300 I; 1e36 I in float).
    const Mat3<T> M = (sizeof(T) == sizeof(float) ? T(1e36) : T(1e300)) * Mat3<T>::Identity();
    const Eigen::Quaternion<T> q = chasles::SO3<T>::from_matrix_unchecked(M).quaternion();
    f.check(q.coeffs().allFinite(), M, q.coeffs());
  }
  for (const Mat3<T>& M : wild_matrices<T>()) {
    const Eigen::Quaternion<T> q = chasles::SO3<T>::from_matrix_unchecked(M).quaternion();
    f.check(q.coeffs().allFinite(), M, q.coeffs());
  }
  expect_none(f, std::string("SO3::quaternion ") + type_name<T>());
}
TEST(Finite, QuaternionDouble) { quaternion_finite<double>(); }
TEST(Finite, QuaternionFloat) { quaternion_finite<float>(); }

template <typename T>
void from_quaternion_finite() {
  Failures f;
  {
    // Smallest case: a tiny nonzero quaternion, |q|^2 subnormal (double) or 0.
    const T tiny = sizeof(T) == sizeof(float) ? T(1e-20) : T(1e-160);
    const Mat3<T> R = chasles::SO3<T>::from_quaternion(Eigen::Quaternion<T>(tiny, 0, 0, 0)).matrix();
    f.check(R.allFinite(), Eigen::Matrix<T, 4, 1>(tiny, 0, 0, 0), R);
  }
  for (const Eigen::Matrix<T, 4, 1>& c : wild_vectors<T, 4>(max_exp10<T>())) {
    const Eigen::Quaternion<T> q(c[0], c[1], c[2], c[3]);
    const Mat3<T> R = chasles::SO3<T>::from_quaternion(q).matrix();
    f.check(R.allFinite(), c, R);
  }
  expect_none(f, std::string("SO3::from_quaternion ") + type_name<T>());
}
TEST(Finite, FromQuaternionDouble) { from_quaternion_finite<double>(); }
TEST(Finite, FromQuaternionFloat) { from_quaternion_finite<float>(); }

TEST(Finite, FromQuaternionZeroIsIdentity) {
  EXPECT_TRUE(chasles::SO3d::from_quaternion(Eigen::Quaterniond(0, 0, 0, 0)).matrix() == Eigen::Matrix3d::Identity());
  EXPECT_TRUE(chasles::SO3f::from_quaternion(Eigen::Quaternionf(0, 0, 0, 0)).matrix() == Eigen::Matrix3f::Identity());
}

template <typename T>
void projections_finite() {
  Failures so3, se3, normalized, checked;
  for (const Mat3<T>& M : wild_matrices<T>()) {
    const Mat3<T> R = chasles::SO3<T>::from_matrix_projected(M).matrix();
    so3.check(R.allFinite(), M, R);
    const Mat3<T> N = chasles::SO3<T>::from_matrix_unchecked(M).normalized().matrix();
    normalized.check(N.allFinite(), M, N);
    const Mat4<T> g = with_translation<T>(M, Vec3<T>(1, -2, 3));
    const Mat4<T> G = chasles::SE3<T>::from_matrix_projected(g).matrix();
    se3.check(G.allFinite(), g, G);
    const auto c = chasles::SO3<T>::from_matrix(M);
    checked.check(!c || c->matrix().allFinite(), M, c ? c->matrix() : Mat3<T>(Mat3<T>::Zero()));
  }
  expect_none(so3, std::string("SO3::from_matrix_projected ") + type_name<T>());
  expect_none(normalized, std::string("SO3::normalized ") + type_name<T>());
  expect_none(se3, std::string("SE3::from_matrix_projected ") + type_name<T>());
  expect_none(checked, std::string("SO3::from_matrix (checked) ") + type_name<T>());
}
TEST(Finite, ProjectionsDouble) { projections_finite<double>(); }
TEST(Finite, ProjectionsFloat) { projections_finite<float>(); }

// ---------------------------------------------------------------------------
// Screws.

template <typename T>
bool screw_finite(const chasles::Screw<T>& s, bool infinite_pitch_allowed) {
  const bool pitch_ok =
      std::isfinite(s.pitch) || (infinite_pitch_allowed && s.pitch == std::numeric_limits<T>::infinity());
  return s.point.allFinite() && s.direction.allFinite() && std::isfinite(s.magnitude) && pitch_ok;
}

/// (pitch, magnitude, |direction|, |point|).
template <typename T>
Eigen::Matrix<T, 4, 1> screw_summary(const chasles::Screw<T>& s) {
  return Eigen::Matrix<T, 4, 1>(s.pitch, s.magnitude, s.direction.norm(), s.point.norm());
}

template <typename T>
void screws_of_zero() {
  using V3 = Vec3<T>;
  const chasles::Screw<T> st = chasles::Twist<T>().screw();
  EXPECT_TRUE(screw_finite(st, false)) << str(screw_summary(st));
  EXPECT_EQ(st.magnitude, T(0));
  EXPECT_EQ(st.pitch, T(0));
  EXPECT_TRUE(std::isfinite(chasles::Twist<T>().pitch()));
  const chasles::Screw<T> sw = chasles::Wrench<T>().screw();
  EXPECT_TRUE(screw_finite(sw, false)) << str(screw_summary(sw));
  // A pure translation: pitch +inf by design, everything else finite.
  const chasles::Screw<T> sp = chasles::Twist<T>(V3(1, 2, 3), V3::Zero()).screw();
  EXPECT_TRUE(screw_finite(sp, true)) << str(screw_summary(sp));
  // Back from screws with a zero direction, zero magnitude, infinite pitch.
  const chasles::Twist<T> t0 = chasles::Twist<T>::from_screw(V3(1, 2, 3), V3::Zero(), T(0.5), T(2));
  EXPECT_TRUE(t0.vector().allFinite()) << str(t0.vector());
  const chasles::Twist<T> t1 = chasles::Twist<T>::from_screw(st);
  EXPECT_TRUE(t1.vector().allFinite()) << str(t1.vector());
  const chasles::Twist<T> t2 =
      chasles::Twist<T>::from_screw(V3::Zero(), V3(0, 0, 1), std::numeric_limits<T>::infinity(), T(2));
  EXPECT_TRUE(t2.vector().allFinite()) << str(t2.vector());
  const chasles::Wrench<T> f0 = chasles::Wrench<T>::from_screw(sw);
  EXPECT_TRUE(f0.vector().allFinite()) << str(f0.vector());
  const Mat4<T> g0 = chasles::SE3<T>::from_screw(V3(1, 2, 3), V3::Zero(), T(0.5), T(2)).matrix();
  EXPECT_TRUE(g0.allFinite()) << str(g0);
  const Mat4<T> g1 = chasles::SE3<T>::from_screw(V3(1, 2, 3), V3(0, 0, 1), T(0.5), T(0)).matrix();
  EXPECT_TRUE(g1.allFinite()) << str(g1);
}
TEST(Finite, ScrewsOfZeroDouble) { screws_of_zero<double>(); }
TEST(Finite, ScrewsOfZeroFloat) { screws_of_zero<float>(); }

/// Twists and wrenches of every size whose screw is representable: |l|
/// and |m| within a factor 1e8 of each other (so that the pitch l.m/|l|^2
/// and the point l x m / |l|^2 are of order 1), |l| from sqrt(min normal)
/// (well below it, the pitch and point of order |m| / |l|^2 would overflow
/// for |m| of order |l|) up to a tenth of the largest finite value.
template <typename T>
void screws_of_all_sizes() {
  Failures twists, wrenches;
  {
    // Smallest case: w = (1e200, 0, 0) (1e20 in float), v = (1, 0, 0):
    // magnitude 1e200, pitch 1e-200, all representable; |w|^2 overflows.
    const Vec3<T> w(sizeof(T) == sizeof(float) ? T(1e20) : T(1e200), 0, 0), v(1, 0, 0);
    const chasles::Twist<T> tw(v, w);
    twists.check(screw_finite(tw.screw(), false), tw.vector(), screw_summary(tw.screw()));
  }
  std::mt19937_64 rng(chasles_test::kSeed + 13);
  std::uniform_real_distribution<double> u(std::log10(double(std::numeric_limits<T>::min())) / 2 + 1,
                                           max_exp10<T>() - 1);
  std::normal_distribution<double> nd(0, 1);
  for (int k = 0; k < 3000; ++k) {
    const long double s = std::pow(10.0L, u(rng)),
                      r = std::pow(10.0L, std::uniform_real_distribution<double>(-8, 0)(rng));
    Vec3<T> l, m;
    for (int i = 0; i < 3; ++i) {
      l[i] = T(s * nd(rng) / 3);
      m[i] = T(s * r * nd(rng) / 3);
    }
    const chasles::Twist<T> tw(m, l);
    const chasles::Screw<T> st = tw.screw();
    twists.check(screw_finite(st, false), tw.vector(), screw_summary(st));
    const chasles::Wrench<T> wr(l, m);
    const chasles::Screw<T> sw = wr.screw();
    wrenches.check(screw_finite(sw, false), wr.vector(), screw_summary(sw));
  }
  expect_none(twists, std::string("Twist::screw ") + type_name<T>());
  expect_none(wrenches, std::string("Wrench::screw ") + type_name<T>());
}
TEST(Finite, ScrewsOfAllSizesDouble) { screws_of_all_sizes<double>(); }
TEST(Finite, ScrewsOfAllSizesFloat) { screws_of_all_sizes<float>(); }

}  // namespace
