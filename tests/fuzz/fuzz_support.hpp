// Shared by the fuzz targets (tests/fuzz/fuzz_*.cpp): how the fuzzer's bytes
// become scalars, the long double references the properties are checked
// against, the tolerances, the input domains, and the check that aborts.
//
// Tolerances are those of the C++ test suite (tests/cpp/test_group_laws.cpp),
// k * eps of the scalar under test times max(1, size of the data):
//   kOp    = 4:  one product, determinant or action (sums of at most three
//                products, each rounded once);
//   kChain = 16: a few such operations in a row;
//   kExp   = 16: exp or log alone, or an exp/log round trip ("a few ulps");
//   kProj  = 16: the nearest rotation.
// The one new allowance is the angle of log, just above pi by rounding only:
// see angle_allowance().
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <sstream>
#include <string>
#include <type_traits>

#include <Eigen/Core>
#include <Eigen/LU>

#include <chasles/constants.hpp>

#include "support/format.hpp"  // tests/cpp/support: aliases, eps, str

namespace chasles_fuzz {

using LD = long double;

constexpr LD kOp = 4;
constexpr LD kChain = 16;
constexpr LD kExp = 16;
constexpr LD kProj = 16;
/// log(exp(w)) = w is required only for angles below pi - kPiMargin eps
/// (test_group_laws.cpp): closer to pi, a rounded exp(w) may be the rotation
/// of angle pi + tiny, whose log is the other axis sign.
constexpr LD kPiMargin = 16;
constexpr LD kPi = 3.141592653589793238462643383279502884L;

using chasles_test::eps;  // eps, the fixed-size aliases and str: tests/cpp/support/format.hpp
using chasles_test::Mat3;
using chasles_test::Mat4;
using chasles_test::str;
using chasles_test::Vec3;
using chasles_test::Vec6;
template <typename T>
using Vec4 = Eigen::Matrix<T, 4, 1>;

template <typename T>
const char* type_name() {
  return sizeof(T) == sizeof(float) ? "float" : "double";
}

/// The SO3 exp contract (docs/numerics.md, "Measured errors"): every entry within 1e-15 of
/// the exact rotation in double, the same number of ulps in float.
template <typename T>
constexpr LD exp_contract() {
  return LD(1e-15) * eps<T>() / eps<double>();
}

/// The largest rotation defect max(|M^T M - I|, |det M - 1|) of a matrix
/// whose entries are within e of a rotation Q, M = Q + E: (Q^T E)_ij is at
/// most sqrt(3) e (a column of Q is a unit vector), so
/// |M^T M - I| <= 2 sqrt(3) e + 3 e^2, and det M - 1 = tr(Q^T E) + O(e^2)
/// with |tr(Q^T E)| <= 3 sqrt(3) e. The defects checked on fuzzed inputs
/// are bounded this way from an entrywise contract, not from what a few
/// samples happen to show.
inline LD defect_bound(LD e) { return 3 * std::sqrt(LD(3)) * e + 9 * e * e; }

// ---------------------------------------------------------------------------
// Input domains.

/// How far above pi the angle |log(R)| may come out, from rounding alone, for
/// every finite 3x3 matrix. Past pi/2 the library forms
///   |w| = |(2 (fl(pi/2) - a) / n) u_v|,  n = fl(sqrt(fl(|u_v|^2))),
/// with a = atan(...) >= 0: fl(pi/2) rounds once (u = eps/2), the
/// subtraction once, the division by n once, each product with a component
/// of u_v once, and |u_v| / n <= 1 + 2.5u (gamma_3 / 2 for the sum of three
/// squares, u for the sqrt). So |w| <= pi (1 + u)^4 (1 + 2.5u) < pi (1 + 7u)
/// = pi + 3.5 pi eps. (Below pi/2 and on the series branch |w| is far below pi.)
template <typename T>
LD angle_allowance() {
  return LD(3.5) * kPi * eps<T>();
}

/// The largest translation entry for which SE3 exp and log must give finite
/// results: the largest finite value / 64. SE3 exp forms intermediates up to
/// (1 + 0.73 + 1.2) |v|_2 (se3.hpp: |B w| <= 0.73, |C w| |w| <= 1.2), at most
/// 5.1 |v|_max; SE3 log forms w.p and w x p with |w| <= pi, at most
/// pi sqrt(3) |p|_max < 5.5 |p|_max; the true results are at most sqrt(3) |v|_max
/// (|V| <= 1) and (pi/2) sqrt(3) |p|_max (|V^-1| <= pi/2). A factor 64 keeps all
/// of them finite: inputs beyond it are run (for the sanitizers) but their
/// results are not required to be finite.
template <typename T>
T translation_limit() {
  return std::numeric_limits<T>::max() / T(64);
}

/// Results of subnormal size are rounded to a multiple of the smallest
/// subnormal, not to a relative eps: relative checks of quantities that may
/// be that small allow a few of it on top (sums of a few such roundings).
template <typename T>
LD subnormal_allowance() {
  return kChain * LD(std::numeric_limits<T>::denorm_min());
}

template <typename Derived>
bool finite(const Eigen::MatrixBase<Derived>& a) {
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (Eigen::Index i = 0; i < a.rows(); ++i)
      if (!std::isfinite(a(i, j))) return false;
  return true;
}

template <typename Derived>
LD max_abs(const Eigen::MatrixBase<Derived>& a) {
  LD m = 0;
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (Eigen::Index i = 0; i < a.rows(); ++i) m = std::max(m, std::fabs(static_cast<LD>(a(i, j))));
  return m;
}

/// max |a - b| in long double; NaN if either holds a NaN.
template <typename DA, typename DB>
LD max_abs_diff(const Eigen::MatrixBase<DA>& a, const Eigen::MatrixBase<DB>& b) {
  LD m = 0;
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (Eigen::Index i = 0; i < a.rows(); ++i) {
      const LD d = std::fabs(static_cast<LD>(a(i, j)) - static_cast<LD>(b(i, j)));
      if (!(d <= m)) m = d;
    }
  return m;
}

/// max |a - b| / (eps * max(1, max |a|, max |b|, extra_scale)): the error in
/// the units of the tolerances above; `extra_scale` is the size of
/// intermediates a result is formed from by cancellation (as in
/// test_group_laws.cpp). NaN if either holds a NaN.
template <typename T, typename DA, typename DB>
LD error_in_eps(const Eigen::MatrixBase<DA>& a, const Eigen::MatrixBase<DB>& b, LD extra_scale = 1) {
  const LD scale = std::max({LD(1), max_abs(a), max_abs(b), extra_scale});
  return max_abs_diff(a, b) / (eps<T>() * scale);
}

/// |x| of a 3-vector in long double, without overflow.
template <typename Derived>
LD norm(const Eigen::MatrixBase<Derived>& x) {
  const LD m = max_abs(x);
  if (m == 0 || !std::isfinite(m)) return m;
  LD s = 0;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const LD r = static_cast<LD>(x[i]) / m;
    s += r * r;
  }
  return m * std::sqrt(s);
}

// ---------------------------------------------------------------------------
// References in long double, sharing no code with the library.

/// max(|M^T M - I|_max, |det M - 1|) of a 3x3 matrix.
template <typename Derived>
LD rotation_defect(const Eigen::MatrixBase<Derived>& M3) {
  const Eigen::Matrix<LD, 3, 3> M = M3.template cast<LD>();
  const LD e = max_abs_diff(M.transpose() * M, Eigen::Matrix<LD, 3, 3>::Identity());
  return std::max(e, std::fabs(M.determinant() - LD(1)));
}

/// The rotation matrix of the unit quaternion q / |q|, (w, x, y, z) order.
inline Eigen::Matrix<LD, 3, 3> rotation_of_quaternion(LD w, LD x, LD y, LD z) {
  const LD m = std::max({std::fabs(w), std::fabs(x), std::fabs(y), std::fabs(z)});
  w /= m, x /= m, y /= m, z /= m;
  const LD n = std::sqrt(w * w + x * x + y * y + z * z);
  w /= n, x /= n, y /= n, z /= n;
  Eigen::Matrix<LD, 3, 3> R;
  R << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),  //
      2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),   //
      2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return R;
}

// ---------------------------------------------------------------------------
// Reading the input.

/// The fuzzer's bytes as scalars: raw IEEE bit patterns, sizeof(T) bytes
/// each, so that NaN, inf, subnormals and -0 all occur; 0 past the end.
class Bytes {
 public:
  Bytes(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  std::uint8_t byte() { return pos_ < size_ ? data_[pos_++] : 0; }

  template <typename T>
  T scalar() {
    unsigned char buf[sizeof(T)] = {};
    for (std::size_t i = 0; i < sizeof(T); ++i) buf[i] = byte();
    T x;
    std::memcpy(&x, buf, sizeof(T));
    return x;
  }

  template <typename T, int N>
  Eigen::Matrix<T, N, 1> vector() {
    Eigen::Matrix<T, N, 1> v;
    for (int i = 0; i < N; ++i) v[i] = scalar<T>();
    return v;
  }

  template <typename T, int N>
  Eigen::Matrix<T, N, N> matrix() {  // row by row
    Eigen::Matrix<T, N, N> M;
    for (int i = 0; i < N; ++i)
      for (int j = 0; j < N; ++j) M(i, j) = scalar<T>();
    return M;
  }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

// ---------------------------------------------------------------------------
// Checks and the figures they report.

/// Aborts with the property and the input when `ok` is false; `describe`
/// (called only then) names the input.
template <typename Describe>
void check(bool ok, const char* property, const char* type, const Describe& describe) {
  if (ok) return;
  const std::string what = describe();
  std::fprintf(stderr, "\nchasles fuzz: property violated (%s): %s\n  %s\n", type, property, what.c_str());
  std::abort();
}

/// The worst value of each measured error (in eps, or a margin) seen during
/// a run, printed when the process exits: the figures of a fuzzing session.
class Worst {
 public:
  static Worst& instance() {
    static Worst w;
    return w;
  }
  void update(const char* name, const char* type, LD value) {
    for (int i = 0; i < count_; ++i)
      if (names_[i] == name && types_[i] == type) {
        if (value > values_[i]) values_[i] = value;
        return;
      }
    if (count_ < kMax) {
      names_[count_] = name;
      types_[count_] = type;
      values_[count_++] = value;
    }
  }
  ~Worst() {
    for (int i = 0; i < count_; ++i)
      std::fprintf(stderr, "[ worst ] %-6s %-64s %.3Lg\n", types_[i], names_[i], values_[i]);
  }

 private:
  static constexpr int kMax = 128;
  const char* names_[kMax] = {};
  const char* types_[kMax] = {};
  LD values_[kMax] = {};
  int count_ = 0;
};

/// Records `err` under `name` and checks err <= limit (NaN fails).
template <typename Describe>
void check_le(LD err, LD limit, const char* name, const char* type, const Describe& describe) {
  if (err == err) Worst::instance().update(name, type, err);
  check(err <= limit, name, type, [&] {
    std::ostringstream os;
    os << "measured " << static_cast<double>(err) << ", allowed " << static_cast<double>(limit) << "; " << describe();
    return os.str();
  });
}

}  // namespace chasles_fuzz
