// chasles: the rotation nearest to a 3x3 matrix.
#pragma once

#include <cmath>

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/detail/approx.hpp"

namespace chasles {
namespace detail {

/// Four scalars (w, x, y, z).
// Passed by value: kept in registers.
template <typename Scalar>
struct Quaternion4 {
  Scalar w, x, y, z;

  /// Whether all four are finite, with one test: a sum with an inf or a NaN
  /// in it is not finite (a sum that overflows also reads as not finite;
  /// callers then take their slower, clamped path).
  bool finite() const noexcept { return is_finite(Scalar(w + x + y + z)); }
};

/// Horn's symmetric 4x4 matrix of a 3x3 M, shifted: K = N(M) + I, in
/// (w, x, y, z) order. For a rotation with quaternion q, K = 4 q q^T:
///   K_ww = 1 + tr M = 4 w^2,   K_xx = 1 + M00 - M11 - M22 = 4 x^2, ...
///   K_wx = M21 - M12 = 4 w x,  K_xy = M01 + M10 = 4 x y, ...
/// Its diagonal sums to 4 for every M (Horn, Closed-form solution of
/// absolute orientation using unit quaternions, JOSA A 4(4), 1987).
// Held as ten named scalars, not an array: an array indexed at run time
// lives in memory, and vector loads of entries just stored one by one
// stall on store forwarding.
template <typename Scalar>
struct HornMatrix {
  Scalar ww, xx, yy, zz, wx, wy, wz, xy, xz, yz;

  explicit HornMatrix(const Eigen::Matrix<Scalar, 3, 3>& M) noexcept
      : ww(Scalar(1) + M(0, 0) + M(1, 1) + M(2, 2)),
        xx(Scalar(1) + M(0, 0) - M(1, 1) - M(2, 2)),
        yy(Scalar(1) - M(0, 0) + M(1, 1) - M(2, 2)),
        zz(Scalar(1) - M(0, 0) - M(1, 1) + M(2, 2)),
        wx(M(2, 1) - M(1, 2)),
        wy(M(0, 2) - M(2, 0)),
        wz(M(1, 0) - M(0, 1)),
        xy(M(0, 1) + M(1, 0)),
        xz(M(0, 2) + M(2, 0)),
        yz(M(1, 2) + M(2, 1)) {}

  /// The index (0 = w .. 3 = z) of the largest diagonal entry (>= 1, as
  /// the diagonal sums to 4; the first on ties): Shepperd's choice.
  int largest_diagonal() const noexcept {
    int k = 0;
    Scalar best = ww;
    if (xx > best) k = 1, best = xx;
    if (yy > best) k = 2, best = yy;
    if (zz > best) k = 3;
    return k;
  }

  /// The column of the largest diagonal entry (Shepperd's), as (w, x, y, z),
  /// and that entry.
  // Picked by 0/1 weights rather than a branch: which column wins depends
  // on the data, and a mispredicted branch costs more than the 20 multiplies.
  Quaternion4<Scalar> largest_column(Scalar& diagonal) const noexcept {
    const int k = largest_diagonal();
    const Scalar m0(k == 0), m1(k == 1), m2(k == 2), m3(k == 3);
    diagonal = m0 * ww + m1 * xx + m2 * yy + m3 * zz;
    return {m0 * ww + m1 * wx + m2 * wy + m3 * wz,  //
            m0 * wx + m1 * xx + m2 * xy + m3 * xz,  //
            m0 * wy + m1 * xy + m2 * yy + m3 * yz,  //
            m0 * wz + m1 * xz + m2 * yz + m3 * zz};
  }

  /// K v.
  Quaternion4<Scalar> times(const Quaternion4<Scalar>& v) const noexcept {
    return {ww * v.w + wx * v.x + wy * v.y + wz * v.z,  //
            wx * v.w + xx * v.x + xy * v.y + xz * v.z,  //
            wy * v.w + xy * v.x + yy * v.y + yz * v.z,  //
            wz * v.w + xz * v.x + yz * v.y + zz * v.z};
  }

  /// N = K - I as a 4x4 matrix.
  Eigen::Matrix<Scalar, 4, 4> n_matrix() const noexcept {
    Eigen::Matrix<Scalar, 4, 4> N;
    N << ww - Scalar(1), wx, wy, wz,  //
        wx, xx - Scalar(1), xy, xz,   //
        wy, xy, yy - Scalar(1), yz,   //
        wz, xz, yz, zz - Scalar(1);
    return N;
  }
};

/// u = K (K e_k), k = K's largest diagonal: a multiple of the quaternion
/// (w, x, y, z) of the rotation nearest to M, to O(d^2) for M off SO(3) by
/// d (one power step from Shepperd's column; see so3_log), unnormalized.
template <typename Scalar>
inline Quaternion4<Scalar> quaternion_power_step(const HornMatrix<Scalar>& K) noexcept {
  Scalar diagonal;
  return K.times(K.largest_column(diagonal));
}

/// The unit quaternion of a rotation matrix by Shepperd's method: K's
/// column of the largest diagonal entry is K e_k = 4 q_k q with
/// 4 q_k^2 = K_kk >= 1, so q = K e_k / (2 sqrt(K_kk)): no small divisor for
/// any input; the sign makes q_k positive. For a rotation |q|^2 = 1 + delta
/// with delta of order eps, and one Newton step for 1/sqrt, (3 - |q|^2) / 2,
/// normalizes it to rounding with multiplies only (a sqrt and a divide would
/// cost more than the rest). Off SO(3) by d, the norm is off by O(d^2).
template <typename Scalar>
inline Quaternion4<Scalar> shepperd_quaternion(const Eigen::Matrix<Scalar, 3, 3>& M) noexcept {
  using std::sqrt;
  const HornMatrix<Scalar> K(M);
  Scalar w, x, y, z;
  switch (K.largest_diagonal()) {
    case 0: {
      const Scalar f = Scalar(0.5) / sqrt(K.ww);
      w = f * K.ww, x = f * K.wx, y = f * K.wy, z = f * K.wz;
      break;
    }
    case 1: {
      const Scalar f = Scalar(0.5) / sqrt(K.xx);
      w = f * K.wx, x = f * K.xx, y = f * K.xy, z = f * K.xz;
      break;
    }
    case 2: {
      const Scalar f = Scalar(0.5) / sqrt(K.yy);
      w = f * K.wy, x = f * K.xy, y = f * K.yy, z = f * K.yz;
      break;
    }
    default: {
      const Scalar f = Scalar(0.5) / sqrt(K.zz);
      w = f * K.wz, x = f * K.xz, y = f * K.yz, z = f * K.zz;
      break;
    }
  }
  const Scalar n = Scalar(0.5) * (Scalar(3) - (w * w + x * x + y * y + z * z));
  return {n * w, n * x, n * y, n * z};
}

/// Shepperd's quaternion of M clamped to [-2, 2] (a rotation's entries lie
/// in [-1, 1]): finite for every finite M. The cold path of SO3::quaternion.
template <typename Scalar>
EIGEN_DONT_INLINE Quaternion4<Scalar> clamped_shepperd_quaternion(const Eigen::Matrix<Scalar, 3, 3>& M) noexcept {
  return shepperd_quaternion(clamped(M, Scalar(2)));
}

/// The same for M clamped to [-2, 2] (a rotation's entries lie in [-1, 1]):
/// finite for every finite M. The cold path of so3_log (kept out of line).
template <typename Scalar>
EIGEN_DONT_INLINE Quaternion4<Scalar> clamped_quaternion_power_step(const Eigen::Matrix<Scalar, 3, 3>& M) noexcept {
  return quaternion_power_step(HornMatrix<Scalar>(clamped(M, Scalar(2))));
}

/// The eigenvector of Horn's N(M) of the largest eigenvalue, and all four
/// eigenvalues.
template <typename Scalar>
struct HornEigen {
  Eigen::Matrix<Scalar, 4, 1> q;  ///< the unit eigenvector (w, x, y, z) of the largest eigenvalue
  /// The eigenvalues of N(M), largest first. With M = U S V^T (an SVD) and
  /// the signed singular values s1 >= s2 >= |s3| (s3 = det(U V^T) times the
  /// smallest: negative when the nearest orthogonal matrix is a reflection),
  /// they are s1 + s2 + s3, s1 - s2 - s3, -s1 + s2 - s3, -s1 - s2 + s3
  /// (Horn, 1987): the largest is tr(R^T M) for the nearest rotation R, and
  /// the gap to the next, 2 (s2 + s3), is 0 where that rotation is not
  /// unique. Each within about eps |M| (Jacobi's stopping rule).
  Eigen::Matrix<Scalar, 4, 1> values;
};

/// The unit quaternion (w, x, y, z) of the rotation nearest to M in the
/// Frobenius norm, and the eigenvalues of N(M) (HornEigen). |R - M|^2 = 3 + |M|^2 - 2 tr(R^T M), so the nearest R
/// maximizes tr(R(q)^T M) = q^T N q over unit q (Horn, 1987), with
///   N = [[ tr M,  a^T               ],
///        [ a,     M + M^T - tr(M) I ]],   a = (M21 - M12, M02 - M20, M10 - M01)
/// (N = K - I, HornMatrix): q is the eigenvector of N's largest eigenvalue. It is found by cyclic
/// Jacobi rotations on the 4x4 symmetric N, which converge quadratically;
/// at most `max_sweeps` sweeps of 6 rotations bound the cost. Unlike the
/// polar decomposition, this is right for every finite M: reflections and
/// singular matrices included. Only +, *, / and sqrt: autodiff scalars work.
/// The nearest rotation to s M is that of M for every s > 0, so M is first
/// scaled to a largest entry of 1: no product in N or in the sweeps can
/// overflow or underflow, from entries of 1e-300 to 1e300.
/// A non-finite M gives the identity (1, 0, 0, 0) and eigenvalues 0: a NaN in N would stop the
/// sweeps at once and leave the choice of the largest diagonal entry to
/// comparisons with NaN, an arbitrary axis.
template <typename Scalar>
inline HornEigen<Scalar> horn_eigen(const Eigen::Matrix<Scalar, 3, 3>& M_in) noexcept {
  using std::abs;
  using std::sqrt;
  constexpr int max_sweeps = 12;
  if (!all_finite(M_in))
    return {Eigen::Matrix<Scalar, 4, 1>(Scalar(1), Scalar(0), Scalar(0), Scalar(0)),
            Eigen::Matrix<Scalar, 4, 1>::Zero()};
  Scalar m(0);
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      if (abs(M_in(i, j)) > m) m = abs(M_in(i, j));
  const Eigen::Matrix<Scalar, 3, 3> M = m > Scalar(0) ? Eigen::Matrix<Scalar, 3, 3>(M_in / m) : M_in;
  Eigen::Matrix<Scalar, 4, 4> A = HornMatrix<Scalar>(M).n_matrix();
  Eigen::Matrix<Scalar, 4, 4> V = Eigen::Matrix<Scalar, 4, 4>::Identity();

  const Scalar eps(ThresholdsOf<Scalar>::epsilon);
  const Scalar total2 = A.squaredNorm();
  for (int sweep = 0; sweep < max_sweeps; ++sweep) {
    Scalar off2(0);
    for (int p = 0; p < 4; ++p)
      for (int q = p + 1; q < 4; ++q) off2 += A(p, q) * A(p, q);
    if (!(off2 > eps * eps * total2)) break;  // converged (or not finite)
    bool rotated = false;
    for (int p = 0; p < 4; ++p) {
      for (int q = p + 1; q < 4; ++q) {
        // An entry below the rounding of its diagonal entries is left alone:
        // with equal diagonal entries even a 1e-111 would call for a rotation
        // by 45 degrees, which (repeated in every sweep, in both pairs of a
        // matrix with two double eigenvalues: near rank-one M) mixes back the
        // entries just zeroed and slows Jacobi to halving them per sweep.
        if (!(abs(A(p, q)) > eps * (abs(A(p, p)) + abs(A(q, q))))) continue;
        rotated = true;
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
    if (!rotated) break;  // every entry negligible
  }
  int best = 0;
  for (int i = 1; i < 4; ++i)
    if (A(i, i) > A(best, best)) best = i;
  // the eigenvalues of N(M) (N(M / m) m: N is linear in M), sorted by insertion
  Eigen::Matrix<Scalar, 4, 1> values;
  for (int i = 0; i < 4; ++i) {
    const Scalar v = m > Scalar(0) ? Scalar(A(i, i) * m) : A(i, i);
    int k = i;
    for (; k > 0 && values[k - 1] < v; --k) values[k] = values[k - 1];
    values[k] = v;
  }
  return {V.col(best), values};
}

/// The unit quaternion (w, x, y, z) of the rotation nearest to M in the
/// Frobenius norm (horn_eigen, which says how).
template <typename Scalar>
inline Eigen::Matrix<Scalar, 4, 1> nearest_rotation_quaternion(const Eigen::Matrix<Scalar, 3, 3>& M) noexcept {
  return horn_eigen(M).q;
}

/// The nearest rotation to R, a rotation up to rounding (defect d <= sqrt(eps),
/// as SE3::from_matrix accepts): two steps of Bjorck and Bowie's iteration
/// for the orthogonal polar factor, R <- R + R (I - R^T R) / 2 (Bjorck and
/// Bowie, "An iterative algorithm for computing the best estimate of an
/// orthogonal matrix", SIAM J. Numer. Anal. 8(2), 1971; the defect goes from
/// d to about 3 d^2 / 4 per step). An R with R^T R == I in floating point
/// (a permutation, the identity) is returned unchanged, bit for bit. The
/// projection of a matrix near a rotation; nearest_rotation_quaternion above
/// is the one of any matrix.
template <typename Scalar>
Eigen::Matrix<Scalar, 3, 3> orthonormalized(Eigen::Matrix<Scalar, 3, 3> R) noexcept {
  using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;
  for (int step = 0; step < 2; ++step) {
    const Matrix3 E = Matrix3::Identity() - R.transpose() * R;
    R += R * (E * Scalar(0.5));
  }
  return R;
}

}  // namespace detail
}  // namespace chasles
