// chasles: screws, the geometry shared by twists (Chasles) and wrenches (Poinsot).
#pragma once

#include <limits>

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/detail/approx.hpp"

namespace chasles {

/// A screw: a directed line in space (through `point`, along the unit
/// `direction`), a `pitch` and a `magnitude`.
///
/// For a twist it is Chasles' screw motion: rotate by `magnitude` about the
/// line while translating `pitch * magnitude` along it; pitch = +inf is a
/// pure translation of length `magnitude` along `direction`. For a wrench it
/// is Poinsot's wrench: a force of size `magnitude` along the line plus a
/// torque `pitch * magnitude` about it; pitch = +inf is a pure couple.
/// `point` is the point of the line nearest the origin (0 for infinite pitch).
/// The zero twist or wrench has magnitude 0, pitch 0, direction 0.
template <typename Scalar>
struct Screw {
  Eigen::Matrix<Scalar, 3, 1> point;
  Eigen::Matrix<Scalar, 3, 1> direction;
  Scalar pitch;
  Scalar magnitude;
};

namespace detail {

/// |x| and x / |x| without forming |x|^2 (which overflows past 1e154 in
/// double and underflows below 1e-154): x is first scaled to a largest entry
/// of 1. Returns false, leaving the outputs unset, for x = 0.
template <typename Scalar>
inline bool norm_and_direction(const Eigen::Matrix<Scalar, 3, 1>& x, Scalar& norm,
                               Eigen::Matrix<Scalar, 3, 1>& direction) noexcept {
  using std::abs;
  using std::sqrt;
  Scalar a = abs(x[0]);
  if (abs(x[1]) > a) a = abs(x[1]);
  if (abs(x[2]) > a) a = abs(x[2]);
  if (!(a > Scalar(0))) return false;
  const Eigen::Matrix<Scalar, 3, 1> u = x / a;
  const Scalar nu = sqrt(u.squaredNorm());  // in [1, sqrt(3)]
  direction = u / nu;
  norm = a * nu;
  return true;
}

/// The screw of a pair (l, m) with l the line vector and m the moment:
/// (w, v) for a twist, (f, tau) for a wrench. With l != 0:
///   direction = l / |l|, magnitude = |l|,
///   pitch = l.m / |l|^2 = (direction . m) / |l|,
///   point = l x m / |l|^2 = (direction x m) / |l|;
/// with l = 0: pitch = inf, direction = m / |m|, magnitude = |m|. No |l|^2
/// is formed, so every pair whose screw is representable gets it; an l so
/// small against m that the pitch or the point overflows (the axis is
/// beyond the largest finite distance) is taken as l = 0, its limit.
template <typename Scalar>
inline Screw<Scalar> screw_of_pair(const Eigen::Matrix<Scalar, 3, 1>& l,
                                   const Eigen::Matrix<Scalar, 3, 1>& m) noexcept {
  Screw<Scalar> s;
  if (norm_and_direction(l, s.magnitude, s.direction)) {
    s.pitch = s.direction.dot(m) / s.magnitude;
    s.point = s.direction.cross(m) / s.magnitude;
    // Each finite (not their sum, which can overflow when none does).
    if (is_finite(s.pitch) && all_finite(s.point)) return s;
  }
  s.point.setZero();
  if (norm_and_direction(m, s.magnitude, s.direction)) {
    s.pitch = Scalar(std::numeric_limits<RealOf<Scalar>>::infinity());
  } else {
    s.magnitude = Scalar(0);
    s.direction.setZero();
    s.pitch = Scalar(0);
  }
  return s;
}

/// The inverse: the pair (l, m) = magnitude * (d, q x d + pitch d) of the
/// screw through q along d (normalized here, whatever its size: a d whose
/// |d|^2 would underflow or overflow is scaled first; a zero d gives the
/// zero pair), and (0, magnitude d) for an infinite pitch.
template <typename Scalar>
inline void pair_of_screw(const Eigen::Matrix<Scalar, 3, 1>& q, const Eigen::Matrix<Scalar, 3, 1>& d,
                          const Scalar& pitch, const Scalar& magnitude, Eigen::Matrix<Scalar, 3, 1>& l,
                          Eigen::Matrix<Scalar, 3, 1>& m) noexcept {
  // (Initialized although norm_and_direction sets both whenever it returns
  // true: GCC's -Wmaybe-uninitialized cannot see that at -O3.)
  Scalar norm(0);
  Eigen::Matrix<Scalar, 3, 1> u = Eigen::Matrix<Scalar, 3, 1>::Zero();
  if (!norm_and_direction(d, norm, u)) {
    l.setZero();
    m.setZero();
    return;
  }
  if (exactly_equal(pitch, Scalar(std::numeric_limits<RealOf<Scalar>>::infinity()))) {
    l.setZero();
    m = magnitude * u;
    return;
  }
  l = magnitude * u;
  m = magnitude * (q.cross(u) + pitch * u);
}

}  // namespace detail
}  // namespace chasles
