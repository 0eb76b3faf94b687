// The matrix exponential as a plain Taylor sum in long double, with scaling
// and squaring: the oracle of exp for every group (the hat matrix's
// exponential), of phi(ad) (test_sim3), and the check of reference.hpp's
// Pade exponential (test_accuracy). Light: Eigen/Core only.
#pragma once

#include <cmath>
#include <limits>

#include <Eigen/Core>

namespace chasles_ref {

/// sum_k (A/2^s)^k / k!, squared s times, with |A/2^s|_1 <= 1/2, summed
/// until a term is below a sixteenth of long double's epsilon times the
/// sum's largest entry (the terms after it add less than that again: they
/// shrink by at least half each), at most 40 terms.
template <int N>
Eigen::Matrix<long double, N, N> exp_taylor(const Eigen::Matrix<long double, N, N>& A) {
  using MN = Eigen::Matrix<long double, N, N>;
  const long double norm1 = A.cwiseAbs().colwise().sum().maxCoeff();
  int s = 0;
  while (std::ldexp(norm1, -s) > 0.5L) ++s;
  const MN B = A * std::ldexp(1.0L, -s);
  MN sum = MN::Identity(), term = MN::Identity();
  const long double tiny = std::numeric_limits<long double>::epsilon() / 16;
  for (int k = 1; k <= 40; ++k) {
    term = (term * B) / static_cast<long double>(k);
    sum += term;
    if (term.cwiseAbs().maxCoeff() <= tiny * sum.cwiseAbs().maxCoeff()) break;
  }
  for (int i = 0; i < s; ++i) sum = (sum * sum).eval();
  return sum;
}

}  // namespace chasles_ref
