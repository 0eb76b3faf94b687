// detail/small_solve.hpp: Gaussian elimination with partial pivoting for the
// fixed-size systems of the means and the splines, against the definition
// (A X = B) in long double, on systems that need the row swaps; the Cholesky
// solve of inverse kinematics' damped normal equations (of n <= MaxN rows),
// against the definition and Eigen's LLT, and a matrix that is not positive
// definite.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Cholesky>
#include <Eigen/Core>

#include <chasles/detail/small_solve.hpp>

#include "support/scalar_types.hpp"

namespace {

using chasles::detail::cholesky_solve;
using chasles::detail::inverse_partial_pivot;
using chasles::detail::solve_partial_pivot;
using chasles_test::ScalarName;
using chasles_test::ScalarTypes;

template <typename S>
class SmallSolve : public ::testing::Test {};
TYPED_TEST_SUITE(SmallSolve, ScalarTypes, ScalarName);

constexpr int N = 9;  // the largest group dimension (SE23)

/// max |A X - B| / (|A| |X| + |B|), in long double.
template <typename S, int M>
long double residual(const Eigen::Matrix<S, N, N>& A, const Eigen::Matrix<S, N, M>& X,
                     const Eigen::Matrix<S, N, M>& B) {
  using LD = long double;
  const Eigen::Matrix<LD, N, N> Al = A.template cast<LD>();
  const Eigen::Matrix<LD, N, M> Xl = X.template cast<LD>(), Bl = B.template cast<LD>();
  const LD scale = Al.cwiseAbs().maxCoeff() * Xl.cwiseAbs().maxCoeff() * N + Bl.cwiseAbs().maxCoeff();
  return (Al * Xl - Bl).cwiseAbs().maxCoeff() / scale;
}

TYPED_TEST(SmallSolve, SolvesRandomSystemsToAFewUlps) {
  using S = TypeParam;
  using Matrix = Eigen::Matrix<S, N, N>;
  using Vector = Eigen::Matrix<S, N, 1>;
  std::mt19937 gen(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto random = [&](auto m) {
    for (int i = 0; i < m.rows(); ++i)
      for (int j = 0; j < m.cols(); ++j) m(i, j) = S(u(gen));
    return m;
  };
  for (int trial = 0; trial < 200; ++trial) {
    const Matrix A = random(Matrix());
    const Vector b = random(Vector());
    const Vector x = solve_partial_pivot<S, N, 1>(A, b);
    // Backward stable: the residual is a few eps of |A| |x| whatever A's condition.
    EXPECT_LT((residual<S, 1>(A, x, b)), 8 * std::numeric_limits<S>::epsilon()) << "trial " << trial;
    const Matrix Ainv = inverse_partial_pivot(A);
    EXPECT_LT((residual<S, N>(A, Ainv, Matrix(Matrix::Identity()))), 8 * std::numeric_limits<S>::epsilon());
  }
}

TYPED_TEST(SmallSolve, SwapsRowsWhereTheDiagonalIsZero) {
  using S = TypeParam;
  using Matrix = Eigen::Matrix<S, N, N>;
  // A cyclic permutation (every diagonal entry 0): elimination without row
  // swaps divides by 0 at the first step.
  Matrix P = Matrix::Zero();
  for (int i = 0; i < N; ++i) P(i, (i + 1) % N) = S(1);
  EXPECT_EQ(inverse_partial_pivot(P), Matrix(P.transpose()));
  // The largest pivot is taken: [[eps, 1], [1, 1]] without a swap loses x.
  Eigen::Matrix<S, 2, 2> A;
  A << S(1e-30f), S(1), S(1), S(1);
  const Eigen::Matrix<S, 2, 1> x = solve_partial_pivot<S, 2, 1>(A, Eigen::Matrix<S, 2, 1>(S(1), S(2)));
  EXPECT_NEAR(double(x[0]), 1.0, 1e-6);
  EXPECT_NEAR(double(x[1]), 1.0, 1e-6);
}

TYPED_TEST(SmallSolve, ASingularSystemGivesNonFiniteValues) {
  using S = TypeParam;
  Eigen::Matrix<S, 3, 3> A;
  A << S(1), S(2), S(3), S(2), S(4), S(6), S(0), S(1), S(1);  // row 2 = 2 * row 1
  const Eigen::Matrix<S, 3, 1> x = solve_partial_pivot<S, 3, 1>(A, Eigen::Matrix<S, 3, 1>(S(1), S(1), S(1)));
  EXPECT_FALSE(x.allFinite());  // mean.hpp falls back on the gradient step on exactly this
}

// The damped normal equations (J^T J + mu I) x = b of inverse_kinematics,
// J 6 x n, n = 1 to 8 in matrices of capacity 8 (as a chain's), mu from
// 1e-6 to 1 of max diag J^T J: the residual is a few eps of |A| |x|
// (Cholesky is backward stable on a positive definite matrix), and x
// agrees with Eigen's LLT to cond(A) eps.
TYPED_TEST(SmallSolve, CholeskySolvesDampedNormalEquations) {
  using S = TypeParam;
  constexpr int Max = 8;
  using Matrix = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, Max, Max>;
  using Vector = Eigen::Matrix<S, Eigen::Dynamic, 1, Eigen::ColMajor, Max, 1>;
  using LD = long double;
  std::mt19937 gen(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    const int n = 1 + trial % Max;
    Eigen::Matrix<S, 6, Eigen::Dynamic, Eigen::ColMajor, 6, Max> J(6, n);
    Vector b(n);
    for (int i = 0; i < 6; ++i)
      for (int j = 0; j < n; ++j) J(i, j) = S(u(gen));
    for (int j = 0; j < n; ++j) b(j) = S(u(gen));
    const Matrix JtJ = J.transpose() * J;
    const S mu = JtJ.diagonal().maxCoeff() * S(std::pow(10.0, -6.0 * (trial % 7) / 6.0));
    const Matrix A = JtJ + mu * Matrix::Identity(n, n);
    const Vector x = cholesky_solve(A, b);
    ASSERT_TRUE(x.allFinite()) << "trial " << trial;
    const Eigen::Matrix<LD, Eigen::Dynamic, Eigen::Dynamic> Al = A.template cast<LD>();
    const Eigen::Matrix<LD, Eigen::Dynamic, 1> xl = x.template cast<LD>(), bl = b.template cast<LD>();
    const LD scale = Al.cwiseAbs().maxCoeff() * xl.cwiseAbs().maxCoeff() * n + bl.cwiseAbs().maxCoeff();
    EXPECT_LT((Al * xl - bl).cwiseAbs().maxCoeff() / scale, 8 * std::numeric_limits<S>::epsilon()) << "trial " << trial;
    const Vector y = A.llt().solve(b);
    const S cond = JtJ.diagonal().maxCoeff() * S(7) / mu;  // >= |A| |A^-1| (|A| <= n max diag + mu)
    EXPECT_LE((x - y).cwiseAbs().maxCoeff(), 16 * cond * std::numeric_limits<S>::epsilon() * y.cwiseAbs().maxCoeff())
        << "trial " << trial;
  }
}

TYPED_TEST(SmallSolve, CholeskyOfAMatrixNotPositiveDefiniteGivesNonFiniteValues) {
  using S = TypeParam;
  using Matrix = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic, Eigen::ColMajor, 4, 4>;
  using Vector = Eigen::Matrix<S, Eigen::Dynamic, 1, Eigen::ColMajor, 4, 1>;
  Matrix A(3, 3);
  A << S(1), S(2), S(0), S(2), S(1), S(0), S(0), S(0), S(1);  // eigenvalues 3, 1, -1
  EXPECT_FALSE(cholesky_solve(A, Vector(Vector::Ones(3))).allFinite());
  Matrix Z = Matrix::Zero(2, 2);  // positive semidefinite only: a zero pivot
  EXPECT_FALSE(cholesky_solve(Z, Vector(Vector::Ones(2))).allFinite());
}

}  // namespace
