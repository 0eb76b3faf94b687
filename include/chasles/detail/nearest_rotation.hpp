// chasles: the rotation nearest to a 3x3 matrix.
#pragma once

#include <cmath>

#include <Eigen/Core>

#include "chasles/constants.hpp"

namespace chasles {
namespace detail {

/// The unit quaternion (w, x, y, z) of the rotation nearest to M in the
/// Frobenius norm. |R - M|^2 = 3 + |M|^2 - 2 tr(R^T M), so the nearest R
/// maximizes tr(R(q)^T M) = q^T N q over unit q (Horn, 1987), with
///   N = [[ tr M,  a^T               ],
///        [ a,     M + M^T - tr(M) I ]],   a = (M21 - M12, M02 - M20, M10 - M01):
/// q is the eigenvector of N's largest eigenvalue. It is found by cyclic
/// Jacobi rotations on the 4x4 symmetric N, which converge quadratically;
/// at most `max_sweeps` sweeps of 6 rotations bound the cost. Unlike the
/// polar decomposition, this is right for every finite M: reflections and
/// singular matrices included. Only +, *, / and sqrt: autodiff scalars work.
template <typename Scalar>
inline Eigen::Matrix<Scalar, 4, 1> nearest_rotation_quaternion(const Eigen::Matrix<Scalar, 3, 3>& M) noexcept {
  using std::abs;
  using std::sqrt;
  constexpr int max_sweeps = 12;
  const Scalar tr = M.trace();
  Eigen::Matrix<Scalar, 4, 4> A;
  A(0, 0) = tr;
  A(1, 0) = A(0, 1) = M(2, 1) - M(1, 2);
  A(2, 0) = A(0, 2) = M(0, 2) - M(2, 0);
  A(3, 0) = A(0, 3) = M(1, 0) - M(0, 1);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) A(i + 1, j + 1) = M(i, j) + M(j, i) - (i == j ? tr : Scalar(0));
  Eigen::Matrix<Scalar, 4, 4> V = Eigen::Matrix<Scalar, 4, 4>::Identity();

  const Scalar eps(ThresholdsOf<Scalar>::epsilon);
  const Scalar total2 = A.squaredNorm();
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    Scalar off2(0);
    for (int p = 0; p < 4; ++p)
      for (int q = p + 1; q < 4; ++q) off2 += A(p, q) * A(p, q);
    if (!(off2 > eps * eps * total2)) break;  // converged (or not finite)
    for (int p = 0; p < 4; ++p) {
      for (int q = p + 1; q < 4; ++q) {
        if (A(p, q) == Scalar(0)) continue;
        // The rotation in the (p, q) plane that zeroes A(p, q):
        // t = tan(phi) is the smaller root of t^2 + 2 zeta t - 1 = 0.
        const Scalar zeta = (A(q, q) - A(p, p)) / (Scalar(2) * A(p, q));
        const Scalar az = abs(zeta);
        // For huge |zeta|, 1 / (2 |zeta|) avoids forming zeta^2.
        Scalar t;
        if (az > Scalar(1) / eps) {
          t = Scalar(0.5) / az;
        } else {
          t = Scalar(1) / (az + sqrt(Scalar(1) + az * az));
        }
        if (zeta < Scalar(0)) t = -t;
        const Scalar c = Scalar(1) / sqrt(Scalar(1) + t * t);
        const Scalar s = t * c;
        for (int k = 0; k < 4; ++k) {  // A <- A J
          const Scalar akp = A(k, p), akq = A(k, q);
          A(k, p) = c * akp - s * akq;
          A(k, q) = s * akp + c * akq;
        }
        for (int k = 0; k < 4; ++k) {  // A <- J^T A
          const Scalar apk = A(p, k), aqk = A(q, k);
          A(p, k) = c * apk - s * aqk;
          A(q, k) = s * apk + c * aqk;
        }
        for (int k = 0; k < 4; ++k) {  // V <- V J
          const Scalar vkp = V(k, p), vkq = V(k, q);
          V(k, p) = c * vkp - s * vkq;
          V(k, q) = s * vkp + c * vkq;
        }
      }
    }
  }
  int best = 0;
  for (int i = 1; i < 4; ++i)
    if (A(i, i) > A(best, best)) best = i;
  return V.col(best);
}

}  // namespace detail
}  // namespace chasles
