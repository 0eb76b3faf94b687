// chasles: the rotation, rigid motion or similarity that best aligns one set
// of vectors or points with another (least squares).
//
// - so3_align: Wahba's problem, the rotation R minimizing
//     L(R) = sum_i w_i |a_i - R b_i|^2
//   for vectors a_i seen in frame A and b_i in frame B: scipy's
//   Rotation.align_vectors(a, b, weights, return_sensitivity=True), with its
//   root-sum-squared distance rssd = sqrt(min L) and its sensitivity matrix,
//   and its two special cases: a single pair gives the shortest rotation
//   taking b to a; one infinite weight makes that pair "primary": it is
//   aligned exactly (whatever the lengths), and the others are best fitted
//   by a rotation about it (the limit of a weight growing without bound;
//   the pair's term is left out of rssd).
// - se3_align: the rigid motion g = (R, t) minimizing
//   sum_i w_i |A_i - g B_i|^2 for points (Kabsch: R aligns the centred
//   points, t = mean(A) - R mean(B), the means weighted).
// - sim3_align: the similarity g = (R, t, s), acting as s R p + t,
//   minimizing the same: Umeyama's ("Least-squares estimation of
//   transformation parameters between two point patterns", TPAMI 13(4),
//   1991, eq. 40-42), with weights; Eigen::umeyama(B, A) without them.
//
// Method. With B = sum_i w_i a_i b_i^T (the points centred on their means),
//   L(R) = sum_i w_i (|a_i|^2 + |b_i|^2) - 2 tr(R^T B),
// so R is the rotation nearest to B in the Frobenius norm: the eigenvector of
// the largest eigenvalue of Horn's 4x4 quaternion matrix N(B) (Davenport's
// q-method; detail/nearest_rotation.hpp, the projection behind
// SO3::from_matrix_projected). A unit quaternion is a rotation, so no
// reflection is ever returned and no sign is corrected: the case where
// Kabsch's and Umeyama's SVD need det(U V^T) = -1 flipped is the one where
// N's largest eigenvalue is s1 + s2 - s3. N's four eigenvalues give the
// signed singular values s1 >= s2 >= |s3| of B (HornEigen), from which
//   uniqueness: s2 + s3 > align_tolerance s1 (constants.hpp says why), else
//               AlignStatus::not_determined (parallel vectors, collinear
//               points: the rotation about their line is free);
//   scipy's sensitivity: mean(w) / zeta (kappa I + B B^T),
//               zeta = (s1 + s2)(s2 + s3)(s3 + s1), kappa = s1 s2 + s2 s3 + s3 s1;
//   Umeyama's scale: s = (s1 + s2 + s3) / sum_i w_i |b_i - mean(b)|^2.
// rssd is summed from the residuals in a last pass, sqrt(sum_i w_i
// |a_i - g b_i|^2), to a few ulps; scipy's form, the square root of the
// first line less 2 tr(R^T B), cancels to an absolute error of about
// sqrt(eps) |a| for a close fit.
//
// The primary-vector case (scipy's, for one pair or one infinite weight w_p):
// R1 the shortest rotation taking b_p to a_p (the quaternion of their
// bisector; for an obtuse angle a half turn first, so that the rotation
// takes b_p to a_p to rounding also where they are nearly opposite), then
// R = exp(phi u) R1, u = a_p / |a_p|, c_i = R1 b_i and
//   phi = atan2(sum_i w_i (c_i x a_i) . u, sum_i w_i (c_i . a_i - (c_i . u)(a_i . u))),
// the rotation about u that best fits the others' components orthogonal to u.
//
// Ranges: the vectors or points by forward iterators, a in [a_first,
// a_last) and b from b_first (as std::transform), over any fixed-size Eigen
// 3-vector type of the Scalar (Eigen::Matrix<Scalar, 3, 1>, or a Map of
// one: a caller's N x 3 buffer); the weights by a forward iterator over
// Scalar, or none (all 1). Nothing is allocated; the cost is three passes
// over the range (so3_align: two) and one 4x4 Jacobi eigensolve (at most 12
// sweeps).
//
// What is refused (status, with the identity and NaN numbers): no vectors,
// or fewer than 3 points (too_few); a weight negative or NaN, more than one
// infinite one (so3_align), an infinite one or all 0 (se3_align,
// sim3_align) (weights_not_valid); a coordinate that is not finite, or sums
// that overflow (not_finite); a primary vector of length 0 (zero_primary).
// A rotation that the data do not determine is returned (one of the
// minimizers: scipy's choice for so3_align) with status not_determined.
#pragma once

#include <cmath>
#include <type_traits>
#include <utility>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "chasles/constants.hpp"
#include "chasles/detail/approx.hpp"
#include "chasles/detail/nearest_rotation.hpp"
#include "chasles/detail/series.hpp"
#include "chasles/detail/weights.hpp"
#include "chasles/se3.hpp"
#include "chasles/sim3.hpp"
#include "chasles/so3.hpp"

namespace chasles {

/// How an alignment ended.
enum class AlignStatus : unsigned char {
  ok,
  /// The data do not determine the rotation to half the digits of the type
  /// (constants.hpp, align_tolerance): vectors all parallel (or fewer than two
  /// of weight > 0 that are not), collinear points (or fewer than 3 of weight
  /// > 0); with a primary vector, others all parallel to it. The result is
  /// one of the minimizers (for so3_align, scipy's), rssd its distance.
  not_determined,
  too_few,            ///< so3_align: no vectors; se3_align, sim3_align: fewer than 3 points
  weights_not_valid,  ///< a weight negative or NaN; so3_align: more than one infinite; else: one infinite, or all 0
  not_finite,         ///< a coordinate is not finite, or the sums overflowed
  zero_primary,       ///< so3_align: the primary vector (the single pair, or of the infinite weight) has length 0
};

/// The outcome of so3_align, se3_align or sim3_align.
template <typename Group>
struct AlignResult {
  using Scalar = typename Group::Scalar;
  /// The minimizer, g with a_i ~ g b_i (identity when status is one of the refusals).
  Group transform;
  /// sqrt(sum_i w_i |a_i - g b_i|^2), the primary vector's term left out (NaN for a refusal).
  Scalar rssd;
  /// s1 >= s2 >= |s3|, the signed singular values of the (centred) cross-covariance
  /// sum_i w_i a_i b_i^T, s3 < 0 when the best orthogonal fit is a reflection
  /// (NaN with a primary vector, and for a refusal).
  Eigen::Matrix<Scalar, 3, 1> singular_values;
  /// so3_align: scipy's sensitivity matrix (see the file comment), where
  /// has_sensitivity; NaN elsewhere.
  Eigen::Matrix<Scalar, 3, 3> sensitivity;
  /// so3_align without a primary vector, status ok (as scipy, which gives no
  /// sensitivity for one pair or an infinite weight); false for se3_align and sim3_align.
  bool has_sensitivity;
  AlignStatus status;
  explicit operator bool() const noexcept { return status == AlignStatus::ok; }
};

namespace detail {

/// The Scalar of the 3-vectors an iterator points to.
template <typename Iterator>
using VectorScalarOf = typename std::decay_t<decltype(*std::declval<Iterator&>())>::Scalar;

/// A result with the identity and NaN numbers: a refusal.
template <typename Group>
inline AlignResult<Group> align_refused(AlignStatus status) noexcept {
  using Scalar = typename Group::Scalar;
  const Scalar nan = quiet_nan<Scalar>();
  return {Group(), nan,   Eigen::Matrix<Scalar, 3, 1>::Constant(nan), Eigen::Matrix<Scalar, 3, 3>::Constant(nan),
          false,   status};
}

/// v / |v|, |v| taken of v scaled to a largest |component| of 1 (so that its
/// square neither overflows nor underflows); 0 for v = 0.
template <typename Scalar>
inline Eigen::Matrix<Scalar, 3, 1> unit_vector(const Eigen::Matrix<Scalar, 3, 1>& v) noexcept {
  using std::abs;
  using std::sqrt;
  Scalar m(0);
  for (int k = 0; k < 3; ++k)
    if (abs(v[k]) > m) m = abs(v[k]);
  if (!(m > Scalar(0))) return Eigen::Matrix<Scalar, 3, 1>::Zero();
  const Eigen::Matrix<Scalar, 3, 1> u = v / m;
  return u / sqrt(u.squaredNorm());
}

/// The rotation nearest to B, the signed singular values of B and whether
/// the rotation is determined (the file comment).
template <typename Scalar>
struct RotationFit {
  SO3<Scalar> rotation;
  Eigen::Matrix<Scalar, 3, 1> s;
  bool determined;
};

template <typename Scalar>
inline RotationFit<Scalar> rotation_fit(const Eigen::Matrix<Scalar, 3, 3>& B) noexcept {
  const HornEigen<Scalar> e = horn_eigen(B);
  const Scalar half(0.5);
  // eigenvalues l1 >= l2 >= l3 >= l4 of N(B): s1 + s2 + s3, s1 - s2 - s3, -s1 + s2 - s3, -s1 - s2 + s3
  const Eigen::Matrix<Scalar, 3, 1> s(half * (e.values[0] + e.values[1]), half * (e.values[0] + e.values[2]),
                                      half * (e.values[0] + e.values[3]));
  const Scalar gap = half * (e.values[0] - e.values[1]);  // s2 + s3
  const bool determined = gap > Scalar(ThresholdsOf<Scalar>::align_tolerance) * s[0];
  const SO3<Scalar> R = SO3<Scalar>::from_quaternion(Eigen::Quaternion<Scalar>(e.q[0], e.q[1], e.q[2], e.q[3]));
  return {R, s, determined};
}

/// The rotation by the quaternion (v . h, v x h), h = (u + v) / |u + v|
/// their bisector (cos and sin of half the angle, about v x u): the
/// shortest taking the unit vector v to the unit vector u, for u . v >= 0
/// (then |u + v| >= sqrt(2), so h is known to rounding).
template <typename Scalar>
inline SO3<Scalar> bisector_rotation(const Eigen::Matrix<Scalar, 3, 1>& u,
                                     const Eigen::Matrix<Scalar, 3, 1>& v) noexcept {
  const Eigen::Matrix<Scalar, 3, 1> h = unit_vector(Eigen::Matrix<Scalar, 3, 1>(u + v));
  const Eigen::Matrix<Scalar, 3, 1> n = v.cross(h);
  return SO3<Scalar>::from_quaternion(Eigen::Quaternion<Scalar>(v.dot(h), n[0], n[1], n[2]));
}

/// The shortest rotation taking the unit vector v to the unit vector u.
/// Acute angles: bisector_rotation. Obtuse ones: a half turn about m, v x u
/// made orthogonal to v, which takes v to -v (to rounding: m is orthogonal
/// to v by construction), then bisector_rotation from -v to u (acute). For
/// nearly opposite vectors v x u is rounding and the axis of the shortest
/// rotation is not known (a change of the data by eps turns it by eps / |v x u|),
/// but the rotation still takes v to u to rounding. (The bisector alone, or
/// the axis v x u, as scipy 1.17 takes it near pi, would not: its
/// align_vectors(a, -2.5 a), where v x u is rounding, takes -2.5 a to a
/// direction off a's by more than 1e-8 for 73% of 1000 normal a, by up to
/// 1.97.) Exactly opposite (v x u = 0): m = e_k x u, k the index of u's
/// smallest |component| (the first on ties), scipy's axis there.
template <typename Scalar>
inline SO3<Scalar> shortest_rotation(const Eigen::Matrix<Scalar, 3, 1>& u,
                                     const Eigen::Matrix<Scalar, 3, 1>& v) noexcept {
  using std::abs;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  if (u.dot(v) >= Scalar(0)) return bisector_rotation(u, v);
  Vector3 m = v.cross(u);
  if (!(m.squaredNorm() > Scalar(0))) {
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (abs(u[i]) < abs(u[k])) k = i;
    m = Vector3::Unit(k).cross(u);
  }
  m = unit_vector(Vector3(m - m.dot(v) * v));
  const SO3<Scalar> half_turn = SO3<Scalar>::from_quaternion(Eigen::Quaternion<Scalar>(Scalar(0), m[0], m[1], m[2]));
  return bisector_rotation(u, Vector3(half_turn * v)) * half_turn;
}

/// sqrt(sum_i w_i |a_i - g b_i|^2) over the finite weights (the primary
/// vector's infinite weight is left out).
template <typename Group, typename AIterator, typename BIterator, typename WeightIterator>
inline typename Group::Scalar root_sum_squared(const Group& g, AIterator a, AIterator a_last, BIterator b,
                                               WeightIterator w) noexcept {
  using std::sqrt;
  using Scalar = typename Group::Scalar;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  Scalar sum(0);
  for (; a != a_last; ++a, ++b, ++w) {
    const Scalar wi = *w;
    if (!is_finite(wi)) continue;
    const Vector3 ai = *a, bi = *b;
    sum += wi * (ai - g * bi).squaredNorm();
  }
  return sqrt(sum);
}

/// se3_align and sim3_align (the file comment).
template <typename Group, typename AIterator, typename BIterator, typename WeightIterator>
inline AlignResult<Group> point_align(AIterator a_first, AIterator a_last, BIterator b_first,
                                      WeightIterator w_first) noexcept {
  using Scalar = typename Group::Scalar;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;
  constexpr bool with_scale = std::is_same<Group, Sim3<Scalar>>::value;
  // pass 1: the weighted means (a coordinate that is not finite makes its
  // sum inf or NaN, 0 * inf included: the sums are checked, not each point)
  long n = 0;
  bool weights_valid = true;
  Scalar total(0);
  Vector3 sa = Vector3::Zero(), sb = Vector3::Zero();
  {
    BIterator b = b_first;
    WeightIterator w = w_first;
    for (AIterator a = a_first; a != a_last; ++a, ++b, ++w, ++n) {
      const Vector3 ai = *a, bi = *b;
      const Scalar wi = *w;
      if (!(wi >= Scalar(0)) || !is_finite(wi)) {  // NaN fails >= 0
        weights_valid = false;
        continue;
      }
      sa += wi * ai;
      sb += wi * bi;
      total += wi;
    }
  }
  if (n < 3) return align_refused<Group>(AlignStatus::too_few);
  if (!weights_valid || !(total > Scalar(0))) return align_refused<Group>(AlignStatus::weights_not_valid);
  if (!is_finite(total) || !all_finite(sa) || !all_finite(sb)) return align_refused<Group>(AlignStatus::not_finite);
  const Vector3 ma = sa / total, mb = sb / total;
  // pass 2: the cross-covariance of the centred points (two passes: no
  // cancellation for points far from the origin) and the spread of the b's
  Matrix3 H = Matrix3::Zero();
  Scalar vb(0);
  {
    BIterator b = b_first;
    WeightIterator w = w_first;
    for (AIterator a = a_first; a != a_last; ++a, ++b, ++w) {
      const Scalar wi = *w;
      const Vector3 da = Vector3(*a) - ma, db = Vector3(*b) - mb;
      H += (wi * da) * db.transpose();
      vb += wi * db.squaredNorm();
    }
  }
  if (!all_finite(H) || !is_finite(vb)) return align_refused<Group>(AlignStatus::not_finite);
  const RotationFit<Scalar> fit = rotation_fit(H);
  AlignResult<Group> r = align_refused<Group>(fit.determined ? AlignStatus::ok : AlignStatus::not_determined);
  r.singular_values = fit.s;
  if constexpr (with_scale) {
    // s = tr(R^T H) / sum_i w_i |b_i - mean b|^2 (Umeyama's eq. 42); vb = 0
    // only for coincident b's (not determined: H = 0), whose scale is 1
    const Scalar s = vb > Scalar(0) ? Scalar(fit.s.sum() / vb) : Scalar(1);
    r.transform = Group(fit.rotation, Vector3(ma - s * (fit.rotation * mb)), s);
  } else {
    r.transform = Group(fit.rotation, Vector3(ma - fit.rotation * mb));
  }
  // pass 3
  r.rssd = root_sum_squared(r.transform, a_first, a_last, b_first, w_first);
  return r;
}

}  // namespace detail

/// The rotation R minimizing sum_i w_i |a_i - R b_i|^2 (Wahba's problem),
/// as scipy's Rotation.align_vectors(a, b, weights, return_sensitivity=True)
/// (see the file comment): vectors a_i in [a_first, a_last), b_i from
/// b_first, weights w_i from w_first (>= 0; one may be +inf: the primary
/// vector).
template <typename AIterator, typename BIterator, typename WeightIterator>
inline AlignResult<SO3<detail::VectorScalarOf<AIterator>>> so3_align(AIterator a_first, AIterator a_last,
                                                                     BIterator b_first,
                                                                     WeightIterator w_first) noexcept {
  using std::sqrt;
  using Scalar = detail::VectorScalarOf<AIterator>;
  using Group = SO3<Scalar>;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;
  // pass 1: B = sum_i w_i a_i b_i^T over the finite weights, and the primary
  // vector (a coordinate that is not finite makes a column or a row of B inf
  // or NaN, 0 * inf included: B is checked, not each vector; the primary
  // vectors, left out of B, on their own)
  long n = 0, infinite = 0;
  bool weights_valid = true;
  Matrix3 B = Matrix3::Zero();
  Scalar total(0);
  AIterator a_primary = a_first;
  BIterator b_primary = b_first;
  {
    BIterator b = b_first;
    WeightIterator w = w_first;
    for (AIterator a = a_first; a != a_last; ++a, ++b, ++w, ++n) {
      const Scalar wi = *w;
      if (!(wi >= Scalar(0))) {  // negative or NaN
        weights_valid = false;
      } else if (!detail::is_finite(wi)) {  // +inf: the primary vector
        ++infinite;
        a_primary = a;
        b_primary = b;
      } else {
        const Vector3 ai = *a, bi = *b;
        B += (wi * ai) * bi.transpose();
        total += wi;
      }
    }
  }
  if (n == 0) return detail::align_refused<Group>(AlignStatus::too_few);
  if (!weights_valid || infinite > 1) return detail::align_refused<Group>(AlignStatus::weights_not_valid);

  if (n == 1 || infinite == 1) {
    // the primary vector aligned exactly, the others fitted about it
    const Vector3 ap = *a_primary, bp = *b_primary;
    if (!detail::all_finite(ap) || !detail::all_finite(bp))
      return detail::align_refused<Group>(AlignStatus::not_finite);
    const Vector3 u = detail::unit_vector(ap), v = detail::unit_vector(bp);
    if (!(u.squaredNorm() > Scalar(0)) || !(v.squaredNorm() > Scalar(0)))
      return detail::align_refused<Group>(AlignStatus::zero_primary);
    const Group R1 = detail::shortest_rotation(u, v);
    AlignResult<Group> r = detail::align_refused<Group>(AlignStatus::ok);
    r.transform = R1;
    if (n > 1) {
      Scalar S(0), C(0), scale(0);
      BIterator b = b_first;
      WeightIterator w = w_first;
      for (AIterator a = a_first; a != a_last; ++a, ++b, ++w) {
        const Scalar wi = *w;
        if (!detail::is_finite(wi)) continue;  // the primary vector
        const Vector3 ai = *a, ci = R1 * Vector3(*b);
        S += wi * ci.cross(ai).dot(u);
        C += wi * (ci.dot(ai) - ci.dot(u) * ai.dot(u));
        scale += wi * sqrt(ai.squaredNorm() * ci.squaredNorm());
      }
      if (!detail::is_finite(S) || !detail::is_finite(C) || !detail::is_finite(scale))
        return detail::align_refused<Group>(AlignStatus::not_finite);
      r.transform = Group::exp(Vector3(u * Scalar(detail::arctan2<Scalar>(S, C)))) * R1;
      if (!(sqrt(S * S + C * C) > Scalar(ThresholdsOf<Scalar>::align_tolerance) * scale))
        r.status = AlignStatus::not_determined;
    }
    r.rssd = detail::root_sum_squared(r.transform, a_first, a_last, b_first, w_first);
    return r;
  }

  if (!detail::all_finite(B) || !detail::is_finite(total)) return detail::align_refused<Group>(AlignStatus::not_finite);
  const detail::RotationFit<Scalar> fit = detail::rotation_fit(B);
  AlignResult<Group> r = detail::align_refused<Group>(fit.determined ? AlignStatus::ok : AlignStatus::not_determined);
  r.transform = fit.rotation;
  r.singular_values = fit.s;
  if (fit.determined) {
    // scipy's sensitivity: mean(w) / zeta (kappa I + B B^T), with s and B
    // divided by s1 first (the products of three singular values overflow for
    // weights or vectors past the cube root of the largest Scalar)
    const Scalar c = Scalar(1) / fit.s[0];
    const Scalar s1(1), s2 = fit.s[1] * c, s3 = fit.s[2] * c;
    const Matrix3 Bc = B * c;
    const Scalar zeta = (s1 + s2) * (s2 + s3) * (s3 + s1);
    const Scalar kappa = s1 * s2 + s2 * s3 + s3 * s1;
    const Scalar mean_weight = total / Scalar(static_cast<RealOf<Scalar>>(n));
    r.sensitivity = (mean_weight * c / zeta) * (kappa * Matrix3::Identity() + Bc * Bc.transpose());
    r.has_sensitivity = true;
  }
  // pass 2
  r.rssd = detail::root_sum_squared(r.transform, a_first, a_last, b_first, w_first);
  return r;
}

/// so3_align with all weights 1.
template <typename AIterator, typename BIterator>
inline AlignResult<SO3<detail::VectorScalarOf<AIterator>>> so3_align(AIterator a_first, AIterator a_last,
                                                                     BIterator b_first) noexcept {
  return so3_align(a_first, a_last, b_first, detail::UnitWeights<detail::VectorScalarOf<AIterator>>());
}

/// The rigid motion g minimizing sum_i w_i |A_i - g B_i|^2 (Kabsch with
/// centroids; see the file comment): points A_i in [a_first, a_last), B_i
/// from b_first, weights w_i from w_first (finite, >= 0, not all 0).
template <typename AIterator, typename BIterator, typename WeightIterator>
inline AlignResult<SE3<detail::VectorScalarOf<AIterator>>> se3_align(AIterator a_first, AIterator a_last,
                                                                     BIterator b_first,
                                                                     WeightIterator w_first) noexcept {
  return detail::point_align<SE3<detail::VectorScalarOf<AIterator>>>(a_first, a_last, b_first, w_first);
}

/// se3_align with all weights 1.
template <typename AIterator, typename BIterator>
inline AlignResult<SE3<detail::VectorScalarOf<AIterator>>> se3_align(AIterator a_first, AIterator a_last,
                                                                     BIterator b_first) noexcept {
  return se3_align(a_first, a_last, b_first, detail::UnitWeights<detail::VectorScalarOf<AIterator>>());
}

/// The similarity g (s R p + t) minimizing sum_i w_i |A_i - g B_i|^2
/// (Umeyama, with weights; see the file comment): points A_i in [a_first,
/// a_last), B_i from b_first, weights w_i from w_first (finite, >= 0, not
/// all 0).
template <typename AIterator, typename BIterator, typename WeightIterator>
inline AlignResult<Sim3<detail::VectorScalarOf<AIterator>>> sim3_align(AIterator a_first, AIterator a_last,
                                                                       BIterator b_first,
                                                                       WeightIterator w_first) noexcept {
  return detail::point_align<Sim3<detail::VectorScalarOf<AIterator>>>(a_first, a_last, b_first, w_first);
}

/// sim3_align with all weights 1.
template <typename AIterator, typename BIterator>
inline AlignResult<Sim3<detail::VectorScalarOf<AIterator>>> sim3_align(AIterator a_first, AIterator a_last,
                                                                       BIterator b_first) noexcept {
  return sim3_align(a_first, a_last, b_first, detail::UnitWeights<detail::VectorScalarOf<AIterator>>());
}

}  // namespace chasles
