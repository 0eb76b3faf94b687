// chasles: small helpers on fixed-size matrices: the one approximate comparison
// behind every is_approx, the finiteness check, the half difference of vee,
// clamping, and stacking two 3-vectors.
#pragma once

#include <cmath>

#include <Eigen/Core>

#include "chasles/constants.hpp"

namespace chasles {
namespace detail {

/// max |a - b| <= tol * max(1, max |a|, max |b|): absolute near the unit
/// scale (rotation entries), relative beyond it (large translations).
/// NaN compares unequal.
template <typename DerivedA, typename DerivedB>
inline bool approx_equal(const Eigen::MatrixBase<DerivedA>& a, const Eigen::MatrixBase<DerivedB>& b,
                         const RealOf<typename DerivedA::Scalar>& tol) noexcept {
  using Scalar = typename DerivedA::Scalar;
  using std::abs;
  Scalar scale(1);
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (Eigen::Index i = 0; i < a.rows(); ++i) {
      if (abs(a(i, j)) > scale) scale = abs(a(i, j));
      if (abs(b(i, j)) > scale) scale = abs(b(i, j));
    }
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (Eigen::Index i = 0; i < a.rows(); ++i)
      if (!(abs(a(i, j) - b(i, j)) <= tol * scale)) return false;
  return true;
}

/// Whether x is finite: x - x is 0 for finite x and NaN for inf and NaN,
/// so x - x <= 0 holds exactly for finite x (one comparison, no ==).
/// (std::isfinite does not take autodiff scalars.)
template <typename Scalar>
inline bool is_finite(const Scalar& x) noexcept {
  return x - x <= Scalar(0);
}

/// (a - b) / 2, as vee reads the antisymmetric part of a matrix: half the
/// difference, exact for a skew pair b = -a at every magnitude, subnormals
/// included (halving each first, a / 2 - b / 2, rounds half the smallest
/// subnormal to 0: vee(hat(x)) lost an x of 5e-324); each halved first when
/// the difference overflows (|a|, |b| past half the largest number).
template <typename Scalar>
inline Scalar half_difference(const Scalar& a, const Scalar& b) noexcept {
  const Scalar half(0.5), d = a - b;
  return is_finite(d) ? Scalar(half * d) : Scalar(half * a - half * b);
}

/// a == b exactly (NaN equal to nothing), for the places that mean an exact
/// comparison of floating-point numbers: spelled a <= b && b <= a, the same
/// test, so that -Wfloat-equal keeps flagging every accidental ==.
template <typename Scalar>
inline bool exactly_equal(const Scalar& a, const Scalar& b) noexcept {
  return a <= b && b <= a;
}

/// Whether every entry is finite (is_finite). (Eigen's allFinite() calls
/// isfinite, which autodiff scalars lack.)
template <typename Derived>
inline bool all_finite(const Eigen::MatrixBase<Derived>& a) noexcept {
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (Eigen::Index i = 0; i < a.rows(); ++i)
      if (!is_finite(a(i, j))) return false;
  return true;
}

/// x clamped to [-bound, bound], as a select (min/max instructions, no
/// branch). An x equal to a bound is kept as it is (autodiff scalars keep
/// their derivative there).
template <typename Scalar>
inline Scalar clamped(const Scalar& x, const Scalar& bound) noexcept {
  return x > bound ? bound : (x < -bound ? Scalar(-bound) : x);
}

/// M with every entry clamped to [-bound, bound].
template <typename Scalar, int Rows, int Cols>
inline Eigen::Matrix<Scalar, Rows, Cols> clamped(const Eigen::Matrix<Scalar, Rows, Cols>& M,
                                                 const Scalar& bound) noexcept {
  Eigen::Matrix<Scalar, Rows, Cols> out;
  for (int j = 0; j < Cols; ++j)
    for (int i = 0; i < Rows; ++i) out(i, j) = clamped(M(i, j), bound);
  return out;
}

/// (a, b) as one 6-vector, element by element.
// Not Eigen's comma initializer: for a float 6-vector from two 3-vectors it
// trips GCC 12's -Warray-bounds with SSE packets, a false positive that
// -Werror users would inherit.
template <typename Scalar, typename DerivedA, typename DerivedB>
inline Eigen::Matrix<Scalar, 6, 1> stack(const Eigen::MatrixBase<DerivedA>& a,
                                         const Eigen::MatrixBase<DerivedB>& b) noexcept {
  Eigen::Matrix<Scalar, 6, 1> out;
  for (int i = 0; i < 3; ++i) {
    out[i] = a[i];
    out[i + 3] = b[i];
  }
  return out;
}

}  // namespace detail
}  // namespace chasles
