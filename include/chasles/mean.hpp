// chasles: weighted means of the elements of a Lie group.
//
// - chordal_mean: the closed form, part by part (group_parts.hpp): the
//   rotation nearest (Frobenius) to the weighted sum of the rotation
//   matrices, and the weighted average of the Euclidean part.
//   SO(3): the minimizer of sum_i w_i |R - R_i|_F^2; it equals the
//   quaternion eigenvector mean of Markley, Cheng, Crassidis and Oshman
//   ("Averaging quaternions", JGCD 2007), which is scipy's Rotation.mean.
//   SO(2): the weighted average of the unit complex numbers (cos, sin),
//   normalized (the same minimizer). SE(2), SE(3) (and every matrix
//   semidirect product [[R, c], [0, I]], SE_2(3)): that rotation and the
//   weighted average of the columns c, the minimizer of
//   sum_i w_i |M - M_i|_F^2 over the group's matrices. Sim(3): the chordal
//   mean of the rotations, the weighted geometric mean of the scales and
//   the weighted average of the translations (its parts (R, t, log s)):
//   not the Frobenius-nearest similarity, whose scale is tr(R^T sum w_i s_i R_i)
//   / (3 sum w_i) and weighs each rotation by its scale (it vanishes for
//   rotations spread about their sum's null space), but a similarity for
//   every valid input, and for pure scalings the geodesic mean itself.
//   All are left-invariant (mean(g X_i) = g mean(X_i)); only the rotation
//   groups' are right-invariant too.
// - geodesic_mean: the Karcher (exponential barycenter) mean M with
//   sum_i w_i log(M^-1 X_i) = 0, by Newton's method from the chordal mean,
//   at most max_iterations steps, reporting whether it converged. On SE(3)
//   this is the bi-invariant mean of Pennec and Arsigny ("Exponential
//   barycenters of the canonical Cartan connection", 2012), as manif's
//   average: the same equation in the twists; it is invariant under both
//   g X_i and X_i g (SE(3) has no bi-invariant metric, but this barycenter
//   is bi-invariant), which the per-part mean (rotation mean and
//   translation average) is not under X_i g. The same holds for every group
//   (log(M^-1 X_i) is unchanged by X_i -> g X_i, M -> g M, and conjugated
//   by Ad_g^-1 under X_i -> X_i g, M -> M g), written once over the group's
//   exp, log, inverse and left Jacobian (lie_group.hpp): a new group has it
//   with no line of its own.
//
// Ranges are given by forward iterators over elements of one group
// (arrays, std::array, std::vector: any container the caller owns), and
// weights by a forward iterator over Scalar, or none (all 1). Nothing is
// allocated; the cost is bounded by max_iterations passes over the range,
// and two more.
//
// Scale: both means are invariant to the scale of the weights, over the
// whole range of Scalar. The weights are divided by the largest one
// (u_i = w_i / w_max in [0, 1], to an ulp), so that neither
// weights near the largest finite Scalar (whose sum overflows) nor
// subnormal ones (whose products with the matrices underflow) change the
// mean: both give the mean of the same weights scaled to 1. The Euclidean
// parts (translations) are averaged per coordinate k as
// c_k sum_i u_i (p_ik / c_k) / sum_i u_i with c_k = max_i |p_ik| where the
// plain sum could overflow (N c_k above the largest finite Scalar): each
// term is at most u_i, so the sum cannot overflow however large the
// translations (two poses at x = 1e308 average to 1e308).
//
// Weights: finite and >= 0, not all 0 (mean_weights_valid). Others (a
// negative, NaN or infinite weight, all weights 0, an empty range) give the
// identity, and geodesic_mean reports them (weights_valid = false).
#pragma once

#include <iterator>
#include <limits>
#include <type_traits>

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/detail/small_solve.hpp"
#include "chasles/detail/weights.hpp"
#include "chasles/group_parts.hpp"
#include "chasles/lie_group.hpp"

namespace chasles {

/// A mean and how it was reached.
template <typename Group>
struct MeanResult {
  Group mean;
  int iterations;      ///< Newton steps taken (0 for the chordal mean)
  bool converged;      ///< the last step was within the tolerance (always true for the chordal mean)
  bool weights_valid;  ///< the weights were valid (mean_weights_valid); if not, mean is the identity
};

namespace detail {

template <typename Iterator>
using GroupOf = std::decay_t<typename std::iterator_traits<Iterator>::value_type>;

/// The rotation matrix of g's rotation part.
template <typename Group>
inline MatrixTypeOf<typename GroupParts<Group>::Rotation> rotation_matrix_of(const Group& g) noexcept {
  return GroupParts<Group>::rotation(g).matrix();
}

/// The element of the weighted sum of the rotation matrices (projected to
/// the nearest rotation) and the mean of the Euclidean parts.
template <typename Group, typename Sum, typename Vector>
inline Group chordal_of(const Sum& sum, const Vector& mean) noexcept {
  using Parts = GroupParts<Group>;
  return Parts::make(Parts::Rotation::from_matrix_projected(sum), mean);
}

/// What the means divide by (see the file comment): the largest weight
/// (0 when the weights are not valid: a negative, NaN or infinite one, all
/// 0, or no element) and its inverse when that is a normal number (the
/// weights are then multiplied by it, within an ulp of the quotient;
/// otherwise, for the largest weights and for subnormal ones, 0: they are
/// divided); and per Euclidean coordinate c_k, the largest |p_k|, when the
/// sum of the coordinates could overflow (n max_i |p_ik| above the largest
/// finite Scalar), else 1 (and always for the rotation groups), so that
/// coordinates of common size are averaged as sum_i u_i p_i / sum_i u_i,
/// without a division per element. K: the number of coordinates.
template <typename Scalar, int K>
struct MeanScales {
  Scalar weight;
  Scalar inverse_weight;
  Eigen::Matrix<Scalar, K, 1> translation;
  bool scales_translations;
};

template <typename Iterator>
using MeanScalesOf = MeanScales<typename GroupOf<Iterator>::Scalar, GroupParts<GroupOf<Iterator>>::K>;

/// w / s.weight: the weight u in [0, 1] (the largest 1), to an ulp.
template <typename Scalar, int K>
inline Scalar scaled_weight(const Scalar& w, const MeanScales<Scalar, K>& s) noexcept {
  return s.inverse_weight > Scalar(0) ? Scalar(w * s.inverse_weight) : Scalar(w / s.weight);
}

template <typename Iterator, typename WeightIterator>
inline MeanScalesOf<Iterator> mean_scales(Iterator first, Iterator last, WeightIterator w) noexcept {
  using std::abs;
  using Group = GroupOf<Iterator>;
  using Parts = GroupParts<Group>;
  using Scalar = typename Group::Scalar;
  constexpr int K = Parts::K;
  using Vector = Eigen::Matrix<Scalar, K, 1>;
  MeanScales<Scalar, K> s{Scalar(0), Scalar(0), Vector::Ones(), false};
  Vector c = Vector::Zero();
  Scalar n(0);
  for (; first != last; ++first, ++w) {
    const Scalar wi = *w;
    if (!(wi >= Scalar(0)) || !is_finite(wi)) {  // not valid (NaN fails >= 0)
      s.weight = Scalar(0);
      return s;
    }
    if (wi > s.weight) s.weight = wi;
    n += Scalar(1);
    if constexpr (K > 0) {
      const Vector p = Parts::vector(*first);
      for (int k = 0; k < K; ++k)
        if (abs(p[k]) > c[k]) c[k] = abs(p[k]);
    }
  }
  if (!(s.weight > Scalar(0))) return s;
  using Real = RealOf<Scalar>;
  const Scalar inverse = Scalar(1) / s.weight;
  // a normal inverse is within an ulp; a subnormal or infinite one is not
  if (inverse >= Scalar(std::numeric_limits<Real>::min()) && is_finite(inverse)) s.inverse_weight = inverse;
  const Scalar safe = Scalar(Eigen::NumTraits<Real>::highest()) / n;  // |sum_i u_i p_ik| <= n max_i |p_ik|
  for (int k = 0; k < K; ++k)
    if (c[k] > safe) s.scales_translations = true;
  if (s.scales_translations)
    for (int k = 0; k < K; ++k) s.translation[k] = c[k] > Scalar(0) ? c[k] : Scalar(1);
  return s;
}

/// The chordal mean with the weights u_i = w_i / s.weight (see the file
/// comment); s from mean_scales, valid.
template <typename Iterator, typename WeightIterator>
inline GroupOf<Iterator> chordal_scaled(Iterator first, Iterator last, WeightIterator w,
                                        const MeanScalesOf<Iterator>& s) noexcept {
  using Group = GroupOf<Iterator>;
  using Parts = GroupParts<Group>;
  using Scalar = typename Group::Scalar;
  using Sum = MatrixTypeOf<typename Parts::Rotation>;
  using Vector = typename Parts::Vector;
  Sum sum = Sum::Zero();
  Vector p = Vector::Zero();
  Scalar total(0);
  for (; first != last; ++first, ++w) {
    const Scalar ui = scaled_weight(Scalar(*w), s);  // in [0, 1]
    sum += ui * rotation_matrix_of(*first);
    if constexpr (Parts::K > 0) {
      if (s.scales_translations) {
        p += ui * Parts::vector(*first).cwiseQuotient(s.translation);  // each |.| <= ui
      } else {
        p += ui * Parts::vector(*first);
      }
    }
    total += ui;  // at least about 1: the largest weight gives 1
  }
  // mean p_k = c_k sum_i u_i (p_ik / c_k) / sum_i u_i, with |sum_i u_i (p_ik / c_k)| <= sum_i u_i
  const Vector mean_p = (p / total).cwiseProduct(s.translation);
  return chordal_of<Group>(sum, mean_p);
}

}  // namespace detail

/// Whether the weights of [first, last) are valid for a mean: each finite
/// and >= 0, at least one > 0 (so the range is not empty).
template <typename Iterator, typename WeightIterator>
inline bool mean_weights_valid(Iterator first, Iterator last, WeightIterator w) noexcept {
  using Scalar = typename detail::GroupOf<Iterator>::Scalar;
  return detail::mean_scales(first, last, w).weight > Scalar(0);
}

/// The chordal mean of [first, last) with weights w (see the file comment),
/// unchanged by a scale of the weights. Weights that are not valid
/// (mean_weights_valid) give the identity.
template <typename Iterator, typename WeightIterator>
inline detail::GroupOf<Iterator> chordal_mean(Iterator first, Iterator last, WeightIterator w) noexcept {
  using std::sqrt;
  using Group = detail::GroupOf<Iterator>;
  using Scalar = typename Group::Scalar;
  using Real = RealOf<Scalar>;
  // One pass with the weights as given, which is the mean when its sums
  // neither overflowed nor became NaN (they are then finite) nor lost digits
  // to underflow (the largest weight is at least sqrt of the smallest normal
  // Scalar: what the products lose below that is far under an ulp of the
  // sum of the weights); otherwise (or for a NaN or infinite weight, all
  // weights 0, no element) a second pass with the weights and translations
  // scaled, after mean_scales has checked the weights.
  using Parts = GroupParts<Group>;
  using Sum = detail::MatrixTypeOf<typename Parts::Rotation>;
  using Vector = typename Parts::Vector;
  Sum sum = Sum::Zero();
  Vector p = Vector::Zero();
  Scalar total(0), largest(0), smallest(0);
  WeightIterator wk = w;
  for (Iterator it = first; it != last; ++it, ++wk) {
    const Scalar wi = *wk;
    largest = wi > largest ? wi : largest;  // selects, not branches (a NaN is neither)
    smallest = wi < smallest ? wi : smallest;
    sum += wi * detail::rotation_matrix_of(*it);
    if constexpr (Parts::K > 0) p += wi * Parts::vector(*it);
    total += wi;  // not finite once a weight is NaN or infinite
  }
  if (!(smallest >= Scalar(0))) return Group();  // a negative weight
  if (largest >= sqrt(Scalar(std::numeric_limits<Real>::min())) && detail::is_finite(total) &&
      detail::all_finite(sum) && detail::all_finite(p))
    return detail::chordal_of<Group>(sum, Vector(p / total));
  const detail::MeanScalesOf<Iterator> s = detail::mean_scales(first, last, w);
  if (!(s.weight > Scalar(0))) return Group();
  return detail::chordal_scaled(first, last, w, s);
}

/// The chordal mean with all weights 1.
template <typename Iterator>
inline detail::GroupOf<Iterator> chordal_mean(Iterator first, Iterator last) noexcept {
  using Scalar = typename detail::GroupOf<Iterator>::Scalar;
  return chordal_mean(first, last, detail::UnitWeights<Scalar>());
}

/// The geodesic (Karcher) mean of [first, last) with weights w: M with
///   F(M) = sum_i w_i e_i = 0,  e_i = log(M^-1 X_i),
/// by Newton's method from the chordal mean. Moving M to M exp(delta)
/// changes e_i to log(exp(-delta) exp(e_i)) = e_i - J_l(e_i)^-1 delta + o(delta)
/// (J_l the left Jacobian of the group), so the Newton step is
///   delta = (sum_i w_i J_l(e_i)^-1)^-1 sum_i w_i e_i,
/// which converges quadratically: at a 1 rad spread (N = 1000) 3 steps
/// bring the residual below 1e-14 in double, where plain gradient steps
/// (delta = the weighted mean of the e_i, as other libraries iterate, capped
/// at 20) converge linearly and take 10 from the chordal mean, 13 from the
/// identity (tests/cpp/test_mean.cpp, tests/python/test_mean.py). Stops when
/// |delta| <= mean_step_tolerance (1 + rms of |e_i|) (constants.hpp), after
/// applying that step, or after max_iterations steps (converged = false).
/// A singular Newton system (spread near pi) falls back to the gradient
/// step. The weights enter as w_i / max_j w_j (see the file comment), so
/// the mean is unchanged by their scale. Weights that are not valid
/// (mean_weights_valid) give {identity, 0, false, false}.
template <typename Iterator, typename WeightIterator>
inline MeanResult<detail::GroupOf<Iterator>> geodesic_mean(
    Iterator first, Iterator last, WeightIterator w,
    int max_iterations = Thresholds<double>::mean_max_iterations) noexcept {
  using std::sqrt;
  using Group = detail::GroupOf<Iterator>;
  using Scalar = typename Group::Scalar;
  constexpr int n = Group::DoF;
  using Tangent = Eigen::Matrix<Scalar, n, 1>;
  using Jacobian = Eigen::Matrix<Scalar, n, n>;
  const detail::MeanScalesOf<Iterator> s = detail::mean_scales(first, last, w);
  if (!(s.weight > Scalar(0))) return {Group(), 0, false, false};
  Group M = detail::chordal_scaled(first, last, w, s);
  for (int k = 1; k <= max_iterations; ++k) {
    Tangent g = Tangent::Zero();
    Jacobian A = Jacobian::Zero();
    Scalar total(0), r2(0);
    WeightIterator wk = w;
    const Group Minv = M.inverse();
    for (Iterator it = first; it != last; ++it, ++wk) {
      const Scalar ui = detail::scaled_weight(Scalar(*wk), s);  // in [0, 1]
      const Tangent e = (Minv * (*it)).log();
      g += ui * e;
      A += ui * Group::left_jacobian_inverse(e);
      r2 += ui * e.squaredNorm();
      total += ui;  // at least about 1
    }
    Tangent delta = detail::solve_partial_pivot<Scalar, n, 1>(A, g);
    if (!detail::all_finite(delta)) delta = g / total;  // singular system: the gradient step
    M = M * Group::exp(delta);
    const Scalar tol = Scalar(ThresholdsOf<Scalar>::mean_step_tolerance) * (Scalar(1) + sqrt(r2 / total));
    if (delta.squaredNorm() <= tol * tol) return {M, k, true, true};
  }
  return {M, max_iterations, false, true};
}

/// The geodesic mean with all weights 1.
template <typename Iterator>
inline MeanResult<detail::GroupOf<Iterator>> geodesic_mean(
    Iterator first, Iterator last, int max_iterations = Thresholds<double>::mean_max_iterations) noexcept {
  using Scalar = typename detail::GroupOf<Iterator>::Scalar;
  return geodesic_mean(first, last, detail::UnitWeights<Scalar>(), max_iterations);
}

}  // namespace chasles
