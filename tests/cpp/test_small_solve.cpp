// detail/small_solve.hpp: Gaussian elimination with partial pivoting for the
// fixed-size systems of the means and the splines, against the definition
// (A X = B) in long double, on systems that need the row swaps.
#include <limits>
#include <random>

#include <gtest/gtest.h>
#include <Eigen/Core>

#include <chasles/detail/small_solve.hpp>

#include "support/scalar_types.hpp"

namespace {

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

}  // namespace
