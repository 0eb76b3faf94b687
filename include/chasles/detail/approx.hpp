// chasles: the one approximate comparison behind every is_approx.
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

}  // namespace detail
}  // namespace chasles
