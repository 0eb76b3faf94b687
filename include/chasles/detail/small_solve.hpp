// chasles: the small square systems of the means and the splines (N = DoF of a
// group, at most 9), solved by Gaussian elimination with partial pivoting
// (Golub & Van Loan, Matrix Computations, 4th ed., Algorithm 3.4.1), and the
// symmetric positive definite ones of inverse kinematics (n joints).
//
// Eigen's PartialPivLU would do the same arithmetic, but it is written for
// large matrices (a blocked factorization over dynamic-size blocks, with a
// matrix product kernel), and each group and scalar instantiates all of it:
// in test_mean.cpp it was 13.7 s of the 17.4 s of template instantiation
// (clang -ftime-trace), and a cost paid again by every user's file that
// calls geodesic_mean or fit_spline. These loops over fixed sizes
// instantiate in a fraction of that. A zero pivot gives inf or NaN, as
// Eigen's does; the callers check the result (mean.hpp) or cannot reach one
// (spline.hpp: its matrices are strictly diagonally dominant).
#pragma once

#include <cmath>

#include <Eigen/Core>

namespace chasles {
namespace detail {

/// X with A X = B, for a square A of fixed size N and B of N rows.
template <typename Scalar, int N, int M>
inline Eigen::Matrix<Scalar, N, M> solve_partial_pivot(Eigen::Matrix<Scalar, N, N> A,
                                                       Eigen::Matrix<Scalar, N, M> B) noexcept {
  static_assert(N > 0 && M > 0, "fixed sizes only");
  using std::abs;
  for (int k = 0; k < N; ++k) {
    int p = k;  // the row of the largest |A(i, k)|, i >= k
    for (int i = k + 1; i < N; ++i)
      if (abs(A(i, k)) > abs(A(p, k))) p = i;
    if (p != k) {
      A.row(k).swap(A.row(p));
      B.row(k).swap(B.row(p));
    }
    for (int i = k + 1; i < N; ++i) {
      const Scalar f = A(i, k) / A(k, k);
      for (int j = k + 1; j < N; ++j) A(i, j) -= f * A(k, j);
      for (int j = 0; j < M; ++j) B(i, j) -= f * B(k, j);
    }
  }
  for (int k = N - 1; k >= 0; --k) {  // back substitution on the upper triangle
    for (int j = 0; j < M; ++j) {
      Scalar x = B(k, j);
      for (int i = k + 1; i < N; ++i) x -= A(k, i) * B(i, j);
      B(k, j) = x / A(k, k);
    }
  }
  return B;
}

/// x with A x = b for a symmetric positive definite A of n <= MaxN rows
/// (the damped normal equations of inverse_kinematics): the Cholesky
/// factorization A = L L^T (Golub & Van Loan, Algorithm 4.2.1) on the copy
/// A, then L y = b and L^T x = y, in scalar loops. Eigen's LLT runs its
/// blocked code's bookkeeping on these dynamic-size matrices at every
/// column, and its triangular solves their panel logic: the iteration of
/// inverse_kinematics measured 5-15% slower with it (7 joints). A pivot
/// <= 0 (A not positive definite, or NaN) gives inf or NaN, as Eigen's does.
template <typename Matrix, typename Vector>
inline Vector cholesky_solve(Matrix A, Vector b) noexcept {
  using std::sqrt;
  using Scalar = typename Matrix::Scalar;
  const Eigen::Index n = A.rows();
  for (Eigen::Index j = 0; j < n; ++j) {
    Scalar d = A(j, j);
    for (Eigen::Index k = 0; k < j; ++k) d -= A(j, k) * A(j, k);
    d = sqrt(d);
    A(j, j) = d;
    for (Eigen::Index i = j + 1; i < n; ++i) {
      Scalar x = A(i, j);
      for (Eigen::Index k = 0; k < j; ++k) x -= A(i, k) * A(j, k);
      A(i, j) = x / d;
    }
  }
  for (Eigen::Index i = 0; i < n; ++i) {  // L y = b
    Scalar x = b(i);
    for (Eigen::Index k = 0; k < i; ++k) x -= A(i, k) * b(k);
    b(i) = x / A(i, i);
  }
  for (Eigen::Index i = n - 1; i >= 0; --i) {  // L^T x = y
    Scalar x = b(i);
    for (Eigen::Index k = i + 1; k < n; ++k) x -= A(k, i) * b(k);
    b(i) = x / A(i, i);
  }
  return b;
}

/// A^-1 for a square A of fixed size N.
template <typename Scalar, int N>
inline Eigen::Matrix<Scalar, N, N> inverse_partial_pivot(const Eigen::Matrix<Scalar, N, N>& A) noexcept {
  return solve_partial_pivot<Scalar, N, N>(A, Eigen::Matrix<Scalar, N, N>::Identity());
}

}  // namespace detail
}  // namespace chasles
