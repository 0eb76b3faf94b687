// Test support: the fixed-size aliases, machine epsilon and printing shared
// by the C++ suites and the fuzz targets (their reports name the input).
#pragma once

#include <limits>
#include <sstream>
#include <string>
#include <type_traits>

#include <Eigen/Core>

namespace chasles_test {

template <typename T>
using Vec3 = Eigen::Matrix<T, 3, 1>;
template <typename T>
using Vec6 = Eigen::Matrix<T, 6, 1>;
template <typename T>
using Mat3 = Eigen::Matrix<T, 3, 3>;
template <typename T>
using Mat4 = Eigen::Matrix<T, 4, 4>;

/// T's machine epsilon, in long double.
template <typename T>
constexpr long double eps() {
  return static_cast<long double>(std::numeric_limits<T>::epsilon());
}

/// "float" or "double", for reports.
template <typename T>
const char* type_name() {
  return sizeof(T) == sizeof(float) ? "float" : "double";
}

/// The entries of a vector, "(x, y, z)", or of a matrix, row by row,
/// "[a b c; d e f]", with the digits that round-trip their scalar type
/// (21 for the long double references).
template <typename Derived>
std::string str(const Eigen::MatrixBase<Derived>& x) {
  std::ostringstream os;
  os.precision(std::numeric_limits<typename Derived::Scalar>::max_digits10);
  if (x.cols() == 1) {
    os << "(";
    for (Eigen::Index i = 0; i < x.size(); ++i) os << (i ? ", " : "") << x(i);
    os << ")";
    return os.str();
  }
  os << "[";
  for (Eigen::Index i = 0; i < x.rows(); ++i) {
    for (Eigen::Index j = 0; j < x.cols(); ++j) os << (j ? " " : "") << x(i, j);
    if (i + 1 < x.rows()) os << "; ";
  }
  os << "]";
  return os.str();
}

/// A scalar with the digits that round-trip its type.
template <typename T, typename = typename std::enable_if<std::is_floating_point<T>::value>::type>
std::string str(T x) {
  std::ostringstream os;
  os.precision(std::numeric_limits<T>::max_digits10);
  os << x;
  return os.str();
}

}  // namespace chasles_test
