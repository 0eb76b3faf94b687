// chasles: arguments taken in any type that converts to the Scalar of a
// group: a parameter t as any arithmetic type (interpolate(a, b, 0.5) on a
// float group), a tangent vector as any Eigen expression (rplus(g, 0.1 * dx)).
// The conversion is explicit, here, so that a caller's -Wconversion stays
// quiet, as for Eigen's own `0.1 * v` of a float vector.
#pragma once

#include <type_traits>

#include <Eigen/Core>

#include "chasles/constants.hpp"

namespace chasles {
namespace detail {

/// Enables an overload for an arithmetic type T other than the Scalar (the
/// Scalar itself takes the plain overload).
template <typename Scalar, typename T>
using EnableIfOtherArithmetic = std::enable_if_t<std::is_arithmetic<T>::value && !std::is_same<T, Scalar>::value, int>;

/// An arithmetic t as a Scalar, converted explicitly (through the real type,
/// for autodiff scalars).
template <typename Scalar, typename T>
inline Scalar scalar_of(const T& t) noexcept {
  return Scalar(static_cast<RealOf<Scalar>>(t));
}

/// An Eigen vector expression of N entries as a fixed-size vector of Scalar
/// (converted entry by entry when its scalar type differs; no copy beyond
/// the result's). Any other size does not compile.
template <typename Scalar, int N, typename Derived>
inline Eigen::Matrix<Scalar, N, 1> tangent_of(const Eigen::MatrixBase<Derived>& x) noexcept {
  static_assert(Derived::IsVectorAtCompileTime && Derived::SizeAtCompileTime == N,
                "chasles: this tangent vector has the wrong size (3 for SO3: w; 6 for SE3: (v, w))");
  return x.template cast<Scalar>();
}

}  // namespace detail
}  // namespace chasles
