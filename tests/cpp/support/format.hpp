// Test support: the fixed-size aliases, machine epsilon and printing shared
// by the accuracy and threshold suites (their reports name the worst input).
#pragma once

#include <limits>
#include <sstream>
#include <string>

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
long double eps() {
  return static_cast<long double>(std::numeric_limits<T>::epsilon());
}

/// "float" or "double", for reports.
template <typename T>
const char* type_name() {
  return sizeof(T) == sizeof(float) ? "float" : "double";
}

/// A vector's entries with 21 significant digits: "(x, y, z)".
template <typename Derived>
std::string str(const Eigen::MatrixBase<Derived>& x) {
  std::ostringstream os;
  os.precision(21);
  os << "(";
  for (Eigen::Index i = 0; i < x.size(); ++i) os << (i ? ", " : "") << static_cast<long double>(x(i));
  os << ")";
  return os.str();
}

}  // namespace chasles_test
