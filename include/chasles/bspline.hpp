// chasles: the uniform cumulative cubic B-spline on any group (SO(3), SE(3),
// SO(2), SE(2), Sim(3), ...), with its body velocity and body acceleration.
#pragma once

#include <cstddef>
#include <iterator>
#include <type_traits>

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/detail/assert.hpp"
#include "chasles/lie_group.hpp"
#include "chasles/se2.hpp"
#include "chasles/se23.hpp"
#include "chasles/se3.hpp"
#include "chasles/sim3.hpp"
#include "chasles/so2.hpp"
#include "chasles/so3.hpp"
#include "chasles/twist.hpp"

namespace chasles {

// The curve (Kim, Kim and Shin 1995; Lovegrove, Patron-Perez and Sibley
// 2013, eq. 4): on segment i, for u in [0, 1],
//
//   X(u) = X_i * A_1 * A_2 * A_3,   A_j = exp(Bt_j(u) d_j),
//   d_j = log(X_{i+j-1}^-1 X_{i+j}),
//
// with the cumulative basis of the uniform cubic B-spline (Bt_0 = 1):
//
//   Bt_1 = (5 + 3u - 3u^2 + u^3) / 6,  Bt_2 = (1 + 3u + 3u^2 - 2u^3) / 6,
//   Bt_3 = u^3 / 6,                     Bt_1 + Bt_2 + Bt_3 = 1 + u.
//
// The curve is C2, does not pass through the control elements (at u = 0 it
// is X_i exp(5/6 d_1) exp(1/6 d_2)), and reduces to the ordinary cubic
// B-spline on R^n when the group is a vector space.
//
// Its body velocity omega = (X^-1 X')^vee and body acceleration omega' come
// from the recursion of Sommer, Usenko, Schubert, Demmel and Cremers (2020,
// "Efficient derivative computation for cumulative B-splines on Lie
// groups", eqs. 38-39), over the partial products Y_j = A_1 ... A_j:
//
//   omega_j  = Ad_{A_j^-1} omega_{j-1}  + Bt_j' d_j,
//   omega_j' = Ad_{A_j^-1} omega_{j-1}' + Bt_j'' d_j + [omega_j, Bt_j' d_j],
//
// from omega_0 = omega_0' = 0 (A_j^-1 A_j' = Bt_j' d_j since d_j commutes
// with its own exponential; the bracket is the derivative of Ad_{A_j^-1}),
// with time derivatives Bt' = (dBt/du) / dt, Bt'' = (d^2Bt/du^2) / dt^2.
// No difference quotient, no extra exp or log: three log, three exp.
//
// The group enters through exp, log, inverse, *, its adjoint and its ad:
// Ad_{A^-1} x and [a, b] = ad_a b in closed form for SO(3) and SE(3) (below),
// and as A.inverse().adjoint() x and G::ad(a) b for every other group, which
// has its B-splines with no line of its own.

/// The cumulative basis of the uniform cubic B-spline at u, and its first
/// and second derivatives with respect to u: entries j = 0, 1, 2 are
/// Bt_{j+1}, Bt_{j+1}', Bt_{j+1}'' (Bt_0 = 1 is left out).
template <typename Scalar>
struct CubicBSplineBasis {
  Eigen::Matrix<Scalar, 3, 1> value;
  Eigen::Matrix<Scalar, 3, 1> first;
  Eigen::Matrix<Scalar, 3, 1> second;
};

/// The basis at u (meaningful on [0, 1]; a polynomial, so any u evaluates).
template <typename Scalar>
inline CubicBSplineBasis<Scalar> cubic_bspline_basis(const Scalar& u) noexcept {
  const Scalar one(1), two(2), three(3), six(6);
  const Scalar u2 = u * u, u3 = u2 * u;
  CubicBSplineBasis<Scalar> b;
  // Bt = C (1, u, u^2, u^3), C = [[5, 3, -3, 1], [1, 3, 3, -2], [0, 0, 0, 1]] / 6
  b.value << (Scalar(5) + three * u - three * u2 + u3) / six, (one + three * u + three * u2 - two * u3) / six, u3 / six;
  const Scalar v = one - u;
  b.first << v * v / two, (one + two * u - two * u2) / two, u2 / two;
  b.second << u - one, one - two * u, u;
  return b;
}

/// A point of a B-spline: the element X, its body velocity (X^-1 X')^vee and
/// body acceleration (the time derivative of the body velocity), in the
/// tangent coordinates of the group (w for SO3; (v, w), linear part first,
/// for SE3; the group's tangent order for the others), per unit of time.
template <typename Group>
struct BSplinePoint {
  using Tangent = Eigen::Matrix<typename Group::Scalar, Group::DoF, 1>;
  Group value;
  Tangent velocity;
  Tangent acceleration;
};

namespace detail {

/// Ad_{A^-1} x for any group.
template <typename G>
inline typename G::Tangent adjoint_inverse_times(const G& A, const typename G::Tangent& x) noexcept {
  return A.inverse().adjoint() * x;
}
/// The Lie bracket [a, b] = ad_a b for any group.
template <typename G>
inline typename G::Tangent lie_bracket(const G* /*tag*/, const typename G::Tangent& a,
                                       const typename G::Tangent& b) noexcept {
  return G::ad(a) * b;
}

/// Ad_{A^-1} x for a rotation: R^T w.
template <typename S>
inline Eigen::Matrix<S, 3, 1> adjoint_inverse_times(const SO3<S>& A, const Eigen::Matrix<S, 3, 1>& x) noexcept {
  return A.matrix().transpose() * x;
}
/// Ad_{A^-1} x for a rigid motion: (R^T (v - p x w), R^T w).
template <typename S>
inline Eigen::Matrix<S, 6, 1> adjoint_inverse_times(const SE3<S>& A, const Eigen::Matrix<S, 6, 1>& x) noexcept {
  return A.act_inv(Twist<S>(x)).vector();
}
/// The Lie bracket of so(3): a x b.
template <typename S>
inline Eigen::Matrix<S, 3, 1> lie_bracket(const SO3<S>* /*tag*/, const Eigen::Matrix<S, 3, 1>& a,
                                          const Eigen::Matrix<S, 3, 1>& b) noexcept {
  return a.cross(b);
}
/// The Lie bracket of se(3): ad_a b = (w_a x v_b + v_a x w_b, w_a x w_b).
template <typename S>
inline Eigen::Matrix<S, 6, 1> lie_bracket(const SE3<S>* /*tag*/, const Eigen::Matrix<S, 6, 1>& a,
                                          const Eigen::Matrix<S, 6, 1>& b) noexcept {
  return Twist<S>(a).bracket(Twist<S>(b)).vector();
}

}  // namespace detail

/// The cubic B-spline segment over the four control elements first[0..3]
/// at u in [0, 1]: X(u) = X_0 exp(Bt_1 d_1) exp(Bt_2 d_2) exp(Bt_3 d_3),
/// d_j = log(X_{j-1}^-1 X_j). `first` is any random-access iterator (a
/// pointer, a std::vector or std::array iterator) to elements of a group.
template <typename Iterator>
inline auto cubic_bspline_segment(Iterator first,
                                  const typename std::iterator_traits<Iterator>::value_type::Scalar& u) noexcept {
  using Group = typename std::iterator_traits<Iterator>::value_type;
  const CubicBSplineBasis<typename Group::Scalar> b = cubic_bspline_basis(u);
  Group X = first[0];
  for (int j = 0; j < 3; ++j) {
    const auto d = (first[j].inverse() * first[j + 1]).log();
    X *= Group::exp(b.value[j] * d);
  }
  return X;
}

/// A point of a segment and its Jacobians with respect to the segment's four
/// control elements, in the right-local convention of lie_group.hpp:
/// X(u; X_k exp(e)) = X(u) exp(control[k] e + o(e)).
template <typename Group>
struct BSplineSegmentJacobians {
  Group value;
  typename Group::AdjointMatrix control[4];
};

/// The segment at u (as cubic_bspline_segment) and its Jacobians with
/// respect to first[0..3] (Sommer et al. 2020, section 4.3, on the right):
/// with B_j = Bt_j(u), A_j = exp(B_j d_j) and the suffixes S_j = A_{j+1}
/// ... A_3 (S_3 = I), X = X_0 S_0 and
///   dX/dd_j = Ad_{S_j^-1} J_r(B_j d_j) B_j,
/// while d_j = log(X_{j-1}^-1 X_j) moves by J_r(d_j)^-1 with X_j and by
/// -J_l(d_j)^-1 with X_{j-1} (rminus_jacobians), so
///   control[0] = Ad_{S_0^-1} - dX/dd_1 J_l(d_1)^-1,
///   control[k] = dX/dd_k J_r(d_k)^-1 - dX/dd_{k+1} J_l(d_{k+1})^-1,
///   control[3] = dX/dd_3 J_r(d_3)^-1.
/// Six exp/log and their Jacobians, no difference quotient; every group.
template <typename Iterator>
inline auto cubic_bspline_segment_jacobians(
    Iterator first, const typename std::iterator_traits<Iterator>::value_type::Scalar& u) noexcept {
  using Group = typename std::iterator_traits<Iterator>::value_type;
  using Tangent = typename Group::Tangent;
  using Matrix = typename Group::AdjointMatrix;
  const CubicBSplineBasis<typename Group::Scalar> b = cubic_bspline_basis(u);
  Tangent d[3];
  Matrix dX[3];  // dX / dd_j
  for (int j = 0; j < 3; ++j) d[j] = (first[j].inverse() * first[j + 1]).log();
  Group S = Group::identity();  // S_j, built from the right
  for (int j = 2; j >= 0; --j) {
    const Tangent step = b.value[j] * d[j];
    dX[j] = S.inverse().adjoint() * Group::right_jacobian(step) * b.value[j];
    S = Group::exp(step) * S;
  }
  BSplineSegmentJacobians<Group> out;
  out.value = first[0] * S;
  out.control[0] = S.inverse().adjoint();
  for (int j = 0; j < 3; ++j) {
    out.control[j] -= dX[j] * Group::left_jacobian_inverse(d[j]);
    out.control[j + 1] = dX[j] * Group::right_jacobian_inverse(d[j]);
  }
  return out;
}

/// The same segment with its body velocity and body acceleration per unit
/// of time, for knots `spacing` apart (u = (t - t_i) / spacing): the
/// recursion of Sommer et al. (2020) written at the top of this file.
template <typename Iterator>
inline auto cubic_bspline_segment_derivatives(
    Iterator first, const typename std::iterator_traits<Iterator>::value_type::Scalar& u,
    const typename std::iterator_traits<Iterator>::value_type::Scalar& spacing) noexcept {
  using Group = typename std::iterator_traits<Iterator>::value_type;
  using Scalar = typename Group::Scalar;
  using Tangent = typename BSplinePoint<Group>::Tangent;
  const CubicBSplineBasis<Scalar> b = cubic_bspline_basis(u);
  const Scalar rate = Scalar(1) / spacing, rate2 = rate * rate;
  BSplinePoint<Group> out{first[0], Tangent::Zero(), Tangent::Zero()};
  for (int j = 0; j < 3; ++j) {
    const Tangent d = (first[j].inverse() * first[j + 1]).log();
    const Group A = Group::exp(Tangent(b.value[j] * d));
    const Tangent dv = (b.first[j] * rate) * d;  // Bt_j' d_j
    out.value *= A;
    // omega_j = Ad_{A^-1} omega_{j-1} + Bt_j' d_j
    out.velocity = detail::adjoint_inverse_times(A, out.velocity) + dv;
    // omega_j' = Ad_{A^-1} omega_{j-1}' + Bt_j'' d_j + [omega_j, Bt_j' d_j]
    out.acceleration = detail::adjoint_inverse_times(A, out.acceleration) + (b.second[j] * rate2) * d +
                       detail::lie_bracket(static_cast<const Group*>(nullptr), out.velocity, dv);
  }
  return out;
}

/// Where a time falls on a uniform B-spline: the segment (control elements
/// segment .. segment + 3) and u in [0, 1].
template <typename Scalar>
struct BSplineTime {
  std::ptrdiff_t segment;
  Scalar u;
};

/// The segment (in [0, count - 4]) and u in [0, 1] of time t on a uniform
/// cubic B-spline of `count` >= 4 control elements, start time t0 and knot
/// spacing dt > 0, clamped to [t0, t0 + (count - 3) dt] (CubicBSplineView's
/// time convention): O(1), one division. A NaN time gives segment 0 and a
/// NaN u.
template <typename Scalar>
inline BSplineTime<Scalar> cubic_bspline_locate(std::ptrdiff_t count, const Scalar& t0, const Scalar& dt,
                                                const Scalar& t) noexcept {
  using Real = RealOf<Scalar>;
  const std::ptrdiff_t last = count - 4;
  const Scalar s = (t - t0) / dt;  // knot units from the start
  const Real r = detail::real_value(s), n = Real(last + 1);
  if (r > Real(0) && r < n) {
    std::ptrdiff_t i = static_cast<std::ptrdiff_t>(r);  // floor, r > 0
    if (i > last) i = last;
    return {i, s - Scalar(Real(i))};
  }
  if (r >= n) return {last, Scalar(1)};
  if (r <= Real(0)) return {0, Scalar(0)};
  return {0, s};  // NaN
}

/// A uniform cumulative cubic B-spline over the caller's control elements,
/// a view: it stores a pointer to them, their count and the two times, and
/// neither copies nor allocates (the elements must outlive it).
///
/// Time convention: N >= 4 control elements X_0 .. X_{N-1}, start time t0
/// and knot spacing dt > 0. Segment i in [0, N - 4] covers the times
/// [t0 + i dt, t0 + (i + 1) dt] with u = (t - t0) / dt - i and uses X_i ..
/// X_{i+3}; the spline is defined on [t0, t0 + (N - 3) dt] (end_time()).
/// A knot time belongs to the segment that starts there (the last one to
/// the last segment, u = 1); the curve, velocity and acceleration are
/// continuous across knots, so the choice matters only to rounding.
///
/// Outside [t0, end_time()] the time is clamped: the element, velocity and
/// acceleration at the nearest end (the spline is not extrapolated). A NaN
/// time gives NaN numbers. Preconditions (the caller's, asserted with
/// eigen_assert): N >= 4 and dt > 0 finite.
template <typename Group>
class CubicBSplineView {
 public:
  using Scalar = typename Group::Scalar;
  using Real = RealOf<Scalar>;
  using Tangent = typename BSplinePoint<Group>::Tangent;

  CubicBSplineView(const Group* control, std::ptrdiff_t count, const Scalar& start_time, const Scalar& spacing) noexcept
      : control_(control), count_(count), t0_(start_time), dt_(spacing) {
    CHASLES_ASSERT(control != nullptr && count >= 4);
    CHASLES_ASSERT(detail::real_value(spacing) > Real(0) &&
                   detail::real_value(spacing) <= Eigen::NumTraits<Real>::highest());
  }

  /// The element at time t: X(t).
  Group operator()(const Scalar& t) const noexcept {
    const BSplineTime<Scalar> at = locate(t);
    return cubic_bspline_segment(control_ + at.segment, at.u);
  }
  /// The element, body velocity and body acceleration at time t.
  BSplinePoint<Group> evaluate(const Scalar& t) const noexcept {
    const BSplineTime<Scalar> at = locate(t);
    return cubic_bspline_segment_derivatives(control_ + at.segment, at.u, dt_);
  }

  /// The segment and u of time t, clamped to [start_time(), end_time()].
  BSplineTime<Scalar> locate(const Scalar& t) const noexcept { return cubic_bspline_locate(count_, t0_, dt_, t); }

  const Group* control() const noexcept { return control_; }
  std::ptrdiff_t size() const noexcept { return count_; }
  std::ptrdiff_t segments() const noexcept { return count_ - 3; }
  const Scalar& start_time() const noexcept { return t0_; }
  const Scalar& spacing() const noexcept { return dt_; }
  /// t0 + (N - 3) dt, the last valid time.
  Scalar end_time() const noexcept { return t0_ + Scalar(Real(count_ - 3)) * dt_; }

 private:
  const Group* control_;
  std::ptrdiff_t count_;
  Scalar t0_;
  Scalar dt_;
};

template <typename Scalar>
using SO3BSplineView = CubicBSplineView<SO3<Scalar>>;
template <typename Scalar>
using SE3BSplineView = CubicBSplineView<SE3<Scalar>>;
template <typename Scalar>
using SO2BSplineView = CubicBSplineView<SO2<Scalar>>;
template <typename Scalar>
using SE2BSplineView = CubicBSplineView<SE2<Scalar>>;
template <typename Scalar>
using Sim3BSplineView = CubicBSplineView<Sim3<Scalar>>;
template <typename Scalar>
using SE23BSplineView = CubicBSplineView<SE23<Scalar>>;

}  // namespace chasles
