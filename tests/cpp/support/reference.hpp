// A long double reference ("oracle") for exp and log of SO(3) and SE(3),
// written without any of chasles' code paths, for the accuracy suites.
//
// - exp: the matrix exponential of the 3x3 / 4x4 hat matrix by Eigen's
//   unsupported MatrixFunctions (Pade approximants with scaling and
//   squaring), in long double (64-bit mantissa on x86: about 19 digits, so
//   its own error is ~1e-19, four orders below the 1e-15 contract). For
//   SE(3) the translation column v is first scaled by a power of two to
//   |v| <= 1 and the result's translation scaled back (exact, since
//   exp([[W, s v], [0, 0]]) = [[R, s V v], [0, 1]]): otherwise a large v
//   would make the Pade code square up to 2^20 times, and the rotation
//   block would lose 2^20 ulps. `exp_taylor` (plain Taylor sum with scaling
//   and squaring) checks it in test_accuracy.cpp.
// - log: two regimes, neither the library's formulas:
//   * |R - I|_max < 0.05 (theta below about 0.05): the Mercator series of the
//     matrix logarithm, log(I + X) = X - X^2/2 + X^3/3 - ..., summed to 40
//     terms, then vee of its antisymmetric part. X = R - I is formed
//     exactly in long double from a double or float matrix, so tiny
//     rotation vectors (1e-300) come out with full relative accuracy,
//     which a quaternion eigenvector (absolute accuracy only) cannot give.
//   * otherwise: the unit quaternion of the nearest rotation, as the
//     eigenvector of the largest eigenvalue of Horn's symmetric 4x4 matrix
//     N(R) (Eigen's SelfAdjointEigenSolver in long double), then
//     theta = 2 atan2(|q_v|, |q_w|) and w = theta q_v / |q_v| * sign(q_w);
//     here |q_v| >= sin(0.0125), so the division is harmless.
//   SE(3): w as above, then v = V(w)^-1 p with V(w) = sum_k [w]^k / (k+1)!
//   (40 terms) and a partial-pivoting LU solve.
// - Rounded inputs: to test log at a known answer, the tests pick a long
//   double tangent vector, build the long double matrix with `exp3`/`exp6`,
//   round it to double (or float), and take as the reference the oracle log
//   of the ROUNDED matrix evaluated in long double. The rounding of the
//   input is thus not counted as the library's error.
#pragma once

#include <cmath>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <unsupported/Eigen/MatrixFunctions>

#include "support/exp_taylor.hpp"

namespace chasles_ref {

using ld = long double;
using V3 = Eigen::Matrix<ld, 3, 1>;
using V6 = Eigen::Matrix<ld, 6, 1>;
using M3 = Eigen::Matrix<ld, 3, 3>;
using M4 = Eigen::Matrix<ld, 4, 4>;

constexpr ld kPi = 3.141592653589793238462643383279502884L;

inline M3 hat(const V3& w) {
  M3 W;
  W << 0, -w[2], w[1],  //
      w[2], 0, -w[0],   //
      -w[1], w[0], 0;
  return W;
}

/// [xi] for xi = (v, w), linear part first.
inline M4 hat6(const V6& xi) {
  M4 X = M4::Zero();
  X.topLeftCorner<3, 3>() = hat(xi.tail<3>());
  X.topRightCorner<3, 1>() = xi.head<3>();
  return X;
}

/// (W - W^T)/2 read as a vector.
inline V3 vee_antisymmetric(const M3& W) {
  return V3((W(2, 1) - W(1, 2)) / 2, (W(0, 2) - W(2, 0)) / 2, (W(1, 0) - W(0, 1)) / 2);
}

/// exp([w]) by Eigen's MatrixFunctions in long double.
inline M3 exp3(const V3& w) {
  const M3 W = hat(w);
  return W.exp();
}

/// exp([xi]) by Eigen's MatrixFunctions in long double (v scaled by 2^-k).
inline M4 exp6(const V6& xi) {
  const ld vmax = xi.head<3>().cwiseAbs().maxCoeff();
  int k = 0;
  if (vmax > 1) k = std::ilogb(vmax) + 1;
  V6 scaled = xi;
  for (int i = 0; i < 3; ++i) scaled[i] = std::ldexp(xi[i], -k);
  const M4 X = hat6(scaled);
  M4 g = X.exp();
  for (int i = 0; i < 3; ++i) g(i, 3) = std::ldexp(g(i, 3), k);
  g.row(3) << 0, 0, 0, 1;
  return g;
}

/// |x| for a 3-vector without under/overflow of the squares.
inline ld scaled_norm(const V3& x) {
  const ld m = x.cwiseAbs().maxCoeff();
  if (m == 0) return 0;
  return m * (x / m).norm();
}

/// The unit quaternion (w, x, y, z), w >= 0, of the rotation nearest to M:
/// the top eigenvector of Horn's N(M), tr(R(q)^T M) = q^T N q.
inline Eigen::Matrix<ld, 4, 1> nearest_quaternion(const M3& M) {
  M4 N;
  const ld t = M.trace();
  N(0, 0) = t;
  N(0, 1) = N(1, 0) = M(2, 1) - M(1, 2);
  N(0, 2) = N(2, 0) = M(0, 2) - M(2, 0);
  N(0, 3) = N(3, 0) = M(1, 0) - M(0, 1);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) N(1 + i, 1 + j) = M(i, j) + M(j, i) - (i == j ? t : ld(0));
  Eigen::SelfAdjointEigenSolver<M4> es(N);
  Eigen::Matrix<ld, 4, 1> q = es.eigenvectors().col(3);  // eigenvalues ascending
  q /= q.norm();
  if (q[0] < 0) q = -q;
  return q;
}

/// Rotation vector of M (angle in [0, pi]), see the file comment.
inline V3 log3(const M3& M) {
  const M3 X = M - M3::Identity();
  if (X.cwiseAbs().maxCoeff() < 0.05L) {
    M3 sum = M3::Zero(), power = X;
    for (int k = 1; k <= 40; ++k) {
      sum += ((k % 2 == 1) ? ld(1) : ld(-1)) / ld(k) * power;
      power = (power * X).eval();
    }
    return vee_antisymmetric(sum);
  }
  const Eigen::Matrix<ld, 4, 1> q = nearest_quaternion(M);
  const V3 qv = q.tail<3>();
  const ld nv = scaled_norm(qv);
  const ld theta = 2 * std::atan2(nv, std::fabs(q[0]));
  return (theta / nv) * qv;
}

/// V(w) = sum_k [w]^k / (k+1)!.
inline M3 v_matrix(const V3& w) {
  const M3 W = hat(w);
  M3 sum = M3::Identity(), term = M3::Identity();
  for (int k = 1; k <= 40; ++k) {
    term = (term * W) / ld(k + 1);
    sum += term;
  }
  return sum;
}

/// (v, w) with v = V(w)^-1 p, for a given rotation vector w.
inline V6 log6_with_rotation(const V3& w, const V3& p) {
  const V3 v = v_matrix(w).partialPivLu().solve(p);
  V6 xi;
  xi << v, w;
  return xi;
}

/// log of a 4x4 rigid motion (bottom row not read).
inline V6 log6(const M4& g) { return log6_with_rotation(log3(g.topLeftCorner<3, 3>()), g.topRightCorner<3, 1>()); }

}  // namespace chasles_ref
