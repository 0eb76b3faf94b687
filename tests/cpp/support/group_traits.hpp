// A small traits layer so that one typed GoogleTest suite runs over
// {SO3, SE3} x {float, double}, and the comparison helpers every suite uses:
// tolerances are k * eps of the scalar under test, with k a small number
// stated where it is used, and the error is reported in units of eps.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <sstream>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>
#include <Eigen/LU>

#include <chasles/chasles.hpp>

#include "support/samples.hpp"

namespace chasles_test {

using LD = long double;

/// Machine epsilon of the scalar under test, as a long double.
template <typename S>
constexpr LD eps() {
  return static_cast<LD>(std::numeric_limits<S>::epsilon());
}

/// Any fixed-size Eigen object, entry by entry in long double: the reference
/// computations of the tests run in long double so that the error measured is
/// the library's, not the reference's.
template <typename Derived>
Eigen::Matrix<LD, Derived::RowsAtCompileTime, Derived::ColsAtCompileTime> to_ld(const Eigen::MatrixBase<Derived>& a) {
  return a.template cast<LD>();
}

// The helpers below read every coefficient: each evaluates an expression
// argument once (eval() is a reference for a plain matrix), since a
// coefficient of an unevaluated product expression computes the whole
// product again.

/// max |a_ij| (0 for an empty object), in long double.
template <typename Derived>
LD max_abs(const Eigen::MatrixBase<Derived>& expr) {
  const auto& a = expr.eval();
  LD m = 0;
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (Eigen::Index i = 0; i < a.rows(); ++i) m = std::max(m, std::fabs(static_cast<LD>(a(i, j))));
  return m;
}

/// max |a_ij - b_ij| in long double; NaN if either holds a NaN.
template <typename DA, typename DB>
LD max_abs_diff(const Eigen::MatrixBase<DA>& a_expr, const Eigen::MatrixBase<DB>& b_expr) {
  const auto& a = a_expr.eval();
  const auto& b = b_expr.eval();
  LD m = 0;
  for (Eigen::Index j = 0; j < a.cols(); ++j)
    for (Eigen::Index i = 0; i < a.rows(); ++i) {
      const LD d = std::fabs(static_cast<LD>(a(i, j)) - static_cast<LD>(b(i, j)));
      if (!(d <= m)) m = d;  // NaN wins
    }
  return m;
}

/// Passes when max |a - b| <= k * eps<S> * scale, scale = max(1, max |a|,
/// max |b|, extra_scale): absolute at unit scale (rotation entries), relative
/// beyond it. `extra_scale` is the size of the intermediate quantities when a
/// result is formed by cancellation (g g^-1 = I with |p| = 100: the error is
/// of order eps * 100 although the result is of order 1). On failure the
/// message gives the error in units of eps * scale, and both operands.
template <typename S, typename DA, typename DB>
::testing::AssertionResult near(const Eigen::MatrixBase<DA>& a_expr, const Eigen::MatrixBase<DB>& b_expr, LD k,
                                LD extra_scale = 1) {
  const auto& a = a_expr.eval();
  const auto& b = b_expr.eval();
  const LD scale = std::max({LD(1), max_abs(a), max_abs(b), extra_scale});
  const LD err = max_abs_diff(a, b);
  if (err <= k * eps<S>() * scale) return ::testing::AssertionSuccess();
  Eigen::IOFormat fmt(Eigen::FullPrecision, 0, ", ", "\n", "[", "]");
  std::ostringstream os;
  os.precision(21);
  os << "max |a - b| = " << static_cast<double>(err) << " = " << static_cast<double>(err / (eps<S>() * scale))
     << " eps * scale (allowed " << static_cast<double>(k) << "), scale " << static_cast<double>(scale) << "\na =\n"
     << to_ld(a).format(fmt) << "\nb =\n"
     << to_ld(b).format(fmt);
  return ::testing::AssertionFailure() << os.str();
}

/// The same for two scalars.
template <typename S>
::testing::AssertionResult near_scalar(LD a, LD b, LD k, LD extra_scale = 1) {
  const LD scale = std::max({LD(1), std::fabs(a), std::fabs(b), extra_scale});
  const LD err = std::fabs(a - b);
  if (err <= k * eps<S>() * scale) return ::testing::AssertionSuccess();
  std::ostringstream os;
  os.precision(21);
  os << "|a - b| = " << static_cast<double>(err) << " = " << static_cast<double>(err / (eps<S>() * scale))
     << " eps * scale (allowed " << static_cast<double>(k) << "); a = " << a << ", b = " << b;
  return ::testing::AssertionFailure() << os.str();
}

/// (3x3 block, long double) max(|M^T M - I|_max, |det M - 1|): the rotation
/// defect recomputed independently of the library.
template <typename Derived>
LD reference_rotation_defect(const Eigen::MatrixBase<Derived>& M3) {
  const Eigen::Matrix<LD, 3, 3> M = to_ld(M3);
  const LD e = max_abs_diff(M.transpose() * M, Eigen::Matrix<LD, 3, 3>::Identity());
  return std::max(e, std::fabs(M.determinant() - LD(1)));
}

template <typename G>
struct GroupTraits;

/// SO(3): tangent R^3, 3x3 matrices acting on points of R^3.
template <typename S>
struct GroupTraits<chasles::SO3<S>> {
  using Group = chasles::SO3<S>;
  using Scalar = S;
  static constexpr int kDoF = 3;
  static constexpr int kDim = 3;  ///< size of matrix()
  using Tangent = Eigen::Matrix<S, 3, 1>;
  using Matrix = Eigen::Matrix<S, 3, 3>;
  using AdjointMatrix = Eigen::Matrix<S, 3, 3>;
  using Point = Eigen::Matrix<S, 3, 1>;
  using Homogeneous = Eigen::Matrix<LD, 3, 1>;

  static std::vector<Tangent> tangents(int n_random = 32, std::uint32_t seed = kSeed) {
    return rotation_vectors<S>(n_random, seed);
  }
  static Group exp(const Tangent& x) { return Group::exp(x); }
  static Matrix hat(const Tangent& x) { return Group::hat(x); }
  static Tangent vee(const Matrix& X) { return Group::vee(X); }
  static AdjointMatrix ad(const Tangent& x) { return Group::ad(x); }
  static Tangent bracket(const Tangent& a, const Tangent& b) { return Group::bracket(a, b); }
  static Eigen::Matrix<S, 3, 1> rotation_part(const Tangent& x) { return x; }
  /// The size of the translation of g (none here): the scale of its errors.
  static LD scale(const Group&) { return 1; }
  static LD scale(const Tangent&) { return 1; }
  /// A point as the vector the matrix acts on.
  static Homogeneous homogeneous(const Point& p) { return to_ld(p); }
  static Eigen::Matrix<LD, 3, 1> dehomogenize(const Homogeneous& h) { return h; }
  static Eigen::Matrix<S, 3, 3> rotation_block(const Matrix& M) { return M; }
  static Matrix with_rotation_block(const Matrix&, const Eigen::Matrix<S, 3, 3>& R) { return R; }
  static S defect(const Matrix& M) { return Group::rotation_defect(M); }
  static std::optional<Group> from_matrix(const Matrix& M) { return Group::from_matrix(M); }
  static std::optional<Group> from_matrix(const Matrix& M, S tol) { return Group::from_matrix(M, tol); }
  static Group from_matrix_projected(const Matrix& M) { return Group::from_matrix_projected(M); }
  static Group from_matrix_unchecked(const Matrix& M) { return Group::from_matrix_unchecked(M); }
};

/// SE(3): tangent (v, w) in R^6, 4x4 homogeneous matrices acting on (p, 1).
template <typename S>
struct GroupTraits<chasles::SE3<S>> {
  using Group = chasles::SE3<S>;
  using Scalar = S;
  static constexpr int kDoF = 6;
  static constexpr int kDim = 4;
  using Tangent = Eigen::Matrix<S, 6, 1>;
  using Matrix = Eigen::Matrix<S, 4, 4>;
  using AdjointMatrix = Eigen::Matrix<S, 6, 6>;
  using Point = Eigen::Matrix<S, 3, 1>;
  using Homogeneous = Eigen::Matrix<LD, 4, 1>;

  static std::vector<Tangent> tangents(int n_random = 32, std::uint32_t seed = kSeed) {
    return twists<S>(n_random, seed);
  }
  static Group exp(const Tangent& x) { return Group::exp(x); }
  static Matrix hat(const Tangent& x) { return Group::hat(x); }
  static Tangent vee(const Matrix& X) { return Group::vee(X); }
  static AdjointMatrix ad(const Tangent& x) { return Group::ad(x); }
  static Tangent bracket(const Tangent& a, const Tangent& b) {
    return chasles::Twist<S>(a).bracket(chasles::Twist<S>(b)).vector();
  }
  static Eigen::Matrix<S, 3, 1> rotation_part(const Tangent& x) { return x.template tail<3>(); }
  static LD scale(const Group& g) { return std::max(LD(1), max_abs(g.translation())); }
  static LD scale(const Tangent& x) { return std::max(LD(1), max_abs(x)); }
  static Homogeneous homogeneous(const Point& p) {
    Homogeneous h;
    h << to_ld(p), LD(1);
    return h;
  }
  static Eigen::Matrix<LD, 3, 1> dehomogenize(const Homogeneous& h) { return h.template head<3>(); }
  static Eigen::Matrix<S, 3, 3> rotation_block(const Matrix& M) { return M.template topLeftCorner<3, 3>(); }
  static Matrix with_rotation_block(const Matrix& M, const Eigen::Matrix<S, 3, 3>& R) {
    Matrix out = M;
    out.template topLeftCorner<3, 3>() = R;
    return out;
  }
  static S defect(const Matrix& M) { return Group::transform_defect(M); }
  static std::optional<Group> from_matrix(const Matrix& M) { return Group::from_matrix(M); }
  static std::optional<Group> from_matrix(const Matrix& M, S tol) { return Group::from_matrix(M, tol); }
  static Group from_matrix_projected(const Matrix& M) { return Group::from_matrix_projected(M); }
  static Group from_matrix_unchecked(const Matrix& M) { return Group::from_matrix_unchecked(M); }
};

/// The rotation angle |w| of a tangent, in long double.
template <typename G>
LD rotation_angle(const typename GroupTraits<G>::Tangent& x) {
  return to_ld(GroupTraits<G>::rotation_part(x)).norm();
}

/// Group elements exp(x) of every tangent sample: identity, tiny angles,
/// near pi, exactly pi, random (fixed seed).
template <typename G>
std::vector<G> elements(int n_random = 32, std::uint32_t seed = kSeed) {
  std::vector<G> out;
  for (const auto& x : GroupTraits<G>::tangents(n_random, seed)) out.push_back(GroupTraits<G>::exp(x));
  return out;
}

}  // namespace chasles_test
