// The properties the fuzz targets share: what must hold for every valid
// rotation, for the angle of every log, and for checked construction.
#pragma once

#include <cstring>
#include <optional>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <chasles/se3.hpp>
#include <chasles/so3.hpp>

#include "fuzz_support.hpp"

namespace chasles_fuzz {

constexpr LD kDefect = 4;

template <typename DA, typename DB>
bool identical(const Eigen::MatrixBase<DA>& a, const Eigen::MatrixBase<DB>& b) {
  return (a.array() == b.array()).all();
}

/// Bit for bit, NaN included (a copied value must be the same bits).
template <typename T, int R, int C>
bool same_bits(const Eigen::Matrix<T, R, C>& a, const Eigen::Matrix<T, R, C>& b) {
  return std::memcmp(a.data(), b.data(), sizeof(T) * R * C) == 0;
}

/// The angle of a log: in [0, pi], up to rounding (angle_allowance).
template <typename T, typename Describe>
void check_log_angle(const Vec3<T>& w, const char* ty, const Describe& describe) {
  check(finite(w), "log of a finite matrix is finite", ty, describe);
  check_le((norm(w) - kPi) / eps<T>(), angle_allowance<T>() / eps<T>(), "log: (|w| - pi) / eps", ty, describe);
}

/// Every property of a rotation R known to be valid (a rotation to a few
/// eps): log, exp(log R), quaternion both ways, checked construction
/// accepts R itself and refuses a reflection of it and R with a non-finite
/// entry, projection keeps it. `selector` picks the column reflected and
/// the entry made non-finite.
///
/// R itself is off SO(3) by its defect D (a few eps): it lies within
/// (sqrt(3)/2) D + O(D^2) of its nearest rotation, which the round trips
/// return to first order, so they are allowed kDefect D on top of their
/// own tolerance.
template <typename T, typename Describe>
void check_valid_rotation(const chasles::SO3<T>& R, unsigned selector, const char* ty, const Describe& describe) {
  using SO3 = chasles::SO3<T>;
  const Mat3<T>& M = R.matrix();
  const LD defect = rotation_defect(M);

  const Vec3<T> w = R.log();
  check_log_angle<T>(w, ty, describe);
  const LD off = kDefect * defect / eps<T>();
  check_le(error_in_eps<T>(SO3::exp(w).matrix(), M) - off, kExp, "exp(log R) - R - 4 defect, valid R (eps)", ty,
           describe);

  // Quaternion: unit, a largest component that is positive (the documented
  // sign, up to a near tie between two components), and back to R.
  const Eigen::Quaternion<T> q = R.quaternion();
  check(finite(q.coeffs()), "quaternion of a rotation is finite", ty, describe);
  check_le(std::fabs(norm(q.coeffs()) - 1) / eps<T>() - off, kExp, "|quaternion(R)| - 1 - 4 defect (eps)", ty,
           describe);
  check_le((max_abs(q.coeffs()) - LD(q.coeffs().maxCoeff())) / eps<T>(), kExp,
           "largest |q_i| - largest q_i (sign convention, eps)", ty, describe);
  check_le(error_in_eps<T>(SO3::from_quaternion(q).matrix(), M) - off, kExp,
           "from_quaternion(quaternion(R)) - R - 4 defect (eps)", ty, describe);

  // Checked construction: R itself is accepted, unchanged.
  const std::optional<SO3> accepted = SO3::from_matrix(M);
  check(accepted.has_value(), "from_matrix accepts a valid rotation", ty, describe);
  check(identical(accepted->matrix(), M), "from_matrix returns the matrix itself", ty, describe);
  // A reflection (one column negated, exactly; det -1) and -R (det -1) are refused.
  Mat3<T> F = M;
  F.col(selector % 3) = -F.col(selector % 3);
  check(!SO3::from_matrix(F).has_value(), "from_matrix refuses a reflection (column negated)", ty, describe);
  check(!SO3::from_matrix(Mat3<T>(-M)).has_value(), "from_matrix refuses -R (det -1)", ty, describe);
  // One entry inf, -inf or NaN: refused; the projection gives the identity.
  const T bad[3] = {std::numeric_limits<T>::infinity(), -std::numeric_limits<T>::infinity(),
                    std::numeric_limits<T>::quiet_NaN()};
  Mat3<T> N = M;
  N((selector / 3) % 3, selector % 3) = bad[(selector / 9) % 3];
  check(!SO3::from_matrix(N).has_value(), "from_matrix refuses a non-finite entry", ty, describe);
  check(identical(SO3::from_matrix_projected(N).matrix(), Mat3<T>::Identity()),
        "from_matrix_projected of a non-finite matrix is the identity", ty, describe);

  // Projection: R stays R (to its own defect and the projection's accuracy).
  const Mat3<T> P = SO3::from_matrix_projected(M).matrix();
  check_le(error_in_eps<T>(P, M) - off, kProj, "from_matrix_projected(R) - R - 4 defect (eps)", ty, describe);
}

/// from_matrix(M) against the defect of M in long double. The library's
/// M^T M - I and det M are sums of products of at most three entries, each
/// rounded a few times: off by at most kChain eps s^3, s = max(1, max |M_ij|).
/// Within that margin of the tolerance either answer is right; outside it
/// the answer is fixed. Non-finite matrices are refused.
template <typename T, typename Describe>
void check_checked_so3(const Mat3<T>& M, const char* ty, const Describe& describe) {
  using SO3 = chasles::SO3<T>;
  const std::optional<SO3> r = SO3::from_matrix(M);
  if (!finite(M)) {
    check(!r.has_value(), "from_matrix refuses a non-finite matrix", ty, describe);
    return;
  }
  const LD tol = chasles::Thresholds<T>::rotation_tolerance;
  const LD s = std::max(LD(1), max_abs(M));
  const LD margin = kChain * eps<T>() * s * s * s;
  const LD d = rotation_defect(M);
  if (d <= tol - margin) {
    check(r.has_value() && identical(r->matrix(), M), "from_matrix accepts M with defect < tolerance", ty, describe);
  } else if (d > tol + margin) {
    check(!r.has_value(), "from_matrix refuses M with defect > tolerance", ty, describe);
  }
}

/// The same for SE3: the rotation block's defect and the bottom row's
/// deviation from (0, 0, 0, 1) (one rounding each).
template <typename T, typename Describe>
void check_checked_se3(const Mat4<T>& G, const char* ty, const Describe& describe) {
  using SE3 = chasles::SE3<T>;
  const std::optional<SE3> r = SE3::from_matrix(G);
  if (!finite(G)) {
    check(!r.has_value(), "SE3::from_matrix refuses a non-finite matrix", ty, describe);
    return;
  }
  const LD tol = chasles::Thresholds<T>::rotation_tolerance;
  const Mat3<T> B = G.template topLeftCorner<3, 3>();
  const LD s = std::max(LD(1), max_abs(B));
  const LD margin = kChain * eps<T>() * s * s * s;
  LD d = rotation_defect(B);
  for (int j = 0; j < 4; ++j) d = std::max(d, std::fabs(LD(G(3, j)) - (j == 3 ? 1 : 0)));
  if (d <= tol - margin) {
    check(r.has_value() && identical(r->matrix().template topRows<3>(), G.template topRows<3>()) &&
              identical(r->matrix().template bottomRows<1>(), Eigen::Matrix<T, 1, 4>(0, 0, 0, 1)),
          "SE3::from_matrix accepts G with defect < tolerance", ty, describe);
  } else if (d > tol + margin) {
    check(!r.has_value(), "SE3::from_matrix refuses G with defect > tolerance", ty, describe);
  }
}

/// The largest eigenvalue of Horn's N(M), in long double: the largest value
/// of tr(R^T M) over all rotations R (Horn 1987), for checking that the
/// projection is the nearest rotation.
template <typename T>
LD best_trace(const Mat3<T>& M3) {
  const Eigen::Matrix<LD, 3, 3> M = M3.template cast<LD>();
  Eigen::Matrix<LD, 4, 4> N;
  const LD t = M.trace();
  N(0, 0) = t;
  N(0, 1) = N(1, 0) = M(2, 1) - M(1, 2);
  N(0, 2) = N(2, 0) = M(0, 2) - M(2, 0);
  N(0, 3) = N(3, 0) = M(1, 0) - M(0, 1);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) N(1 + i, 1 + j) = M(i, j) + M(j, i) - (i == j ? t : LD(0));
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix<LD, 4, 4>> es(N, Eigen::EigenvaluesOnly);
  return es.eigenvalues()[3];
}

}  // namespace chasles_fuzz
