// chasles: time scalings s(t) of a rest-to-rest motion of duration T (cubic,
// quintic, trapezoidal) and the straight-line joint trajectory they time,
// q(t) = q_start + s(t) (q_end - q_start): Lynch and Park, "Modern
// Robotics", ch. 9.2 ("Point-to-Point Trajectories": 9.2.1 straight-line
// paths, 9.2.2 "Polynomial Time Scaling" and "Trapezoidal Motion Profiles").
//
// Every time scaling is s(t) = f(r), r = t / T, with f(0) = 0, f(1) = 1, so
// s_dot = f'(r) / T and s_ddot = f''(r) / T^2. Outside [0, T] the motion is
// at rest: s = 0 before, 1 after, both derivatives 0. A duration that is not
// finite and positive (or a trapezoid's peak velocity ratio outside (1, 2])
// gives s, s_dot, s_ddot all NaN; a NaN t gives NaN.
#pragma once

#include <cmath>
#include <type_traits>

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/detail/assert.hpp"

namespace chasles {

/// The path parameter s in [0, 1] at one time and its first two time
/// derivatives.
template <typename Scalar>
struct TimeScaling {
  Scalar s, s_dot, s_ddot;
};

/// The time scalings of time_scaling.
enum class TimeScalingKind : unsigned char { cubic, quintic, trapezoidal };

namespace detail {
/// f(t / T) and its time derivatives, for profile(r) = (f, f', f'') on
/// [0, 1]; at rest outside [0, T]; NaN unless 0 < T < inf and t is a number.
template <typename Scalar, typename Profile>
inline TimeScaling<Scalar> scale_time(const Scalar& T, const Scalar& t, const Profile& profile) noexcept {
  using std::isfinite;
  using std::isnan;
  using Real = RealOf<Scalar>;
  const Real T_value = real_value(T);
  if (!(T_value > Real(0)) || !isfinite(T_value) || isnan(real_value(t)))
    return {quiet_nan<Scalar>(), quiet_nan<Scalar>(), quiet_nan<Scalar>()};
  if (real_value(t) < Real(0)) return {Scalar(0), Scalar(0), Scalar(0)};
  if (real_value(t) > T_value) return {Scalar(1), Scalar(0), Scalar(0)};
  const TimeScaling<Scalar> f = profile(Scalar(t / T));
  return {f.s, Scalar(f.s_dot / T), Scalar(f.s_ddot / (T * T))};
}
}  // namespace detail

/// The cubic time scaling (MR 9.2.2, third-order polynomial): zero velocity
/// at both ends. s = 3 r^2 - 2 r^3, ds/dr = 6 r (1 - r), d2s/dr2 = 6 (1 - 2 r).
template <typename Scalar>
inline TimeScaling<Scalar> cubic_time_scaling(const Scalar& duration, const Scalar& t) noexcept {
  return detail::scale_time(duration, t, [](const Scalar& r) noexcept -> TimeScaling<Scalar> {
    return {Scalar(r * r * (Scalar(3) - Scalar(2) * r)), Scalar(Scalar(6) * r * (Scalar(1) - r)),
            Scalar(Scalar(6) * (Scalar(1) - Scalar(2) * r))};
  });
}

/// The quintic time scaling (MR 9.2.2, fifth-order polynomial): zero velocity
/// and acceleration at both ends. s = 10 r^3 - 15 r^4 + 6 r^5,
/// ds/dr = 30 r^2 (1 - r)^2, d2s/dr2 = 60 r (1 - r) (1 - 2 r).
template <typename Scalar>
inline TimeScaling<Scalar> quintic_time_scaling(const Scalar& duration, const Scalar& t) noexcept {
  return detail::scale_time(duration, t, [](const Scalar& r) noexcept -> TimeScaling<Scalar> {
    const Scalar u = Scalar(1) - r;
    return {Scalar(r * r * r * (Scalar(10) + r * (Scalar(6) * r - Scalar(15)))), Scalar(Scalar(30) * r * r * u * u),
            Scalar(Scalar(60) * r * u * (Scalar(1) - Scalar(2) * r))};
  });
}

/// The trapezoidal time scaling (MR 9.2.2, "Trapezoidal Motion Profiles",
/// the case of given v and T): constant acceleration a, then the peak
/// velocity v, then constant deceleration -a. The peak velocity is given as
/// k = v T, its ratio to the average velocity 1 / T, in (1, 2]; then
/// a = v^2 / (v T - 1) (MR's formula), and the acceleration lasts
/// v / a = T (k - 1) / k. k = 2 is the triangle profile (no cruise, a = 4 / T^2);
/// k -> 1 the rectangle (infinite a). In r = t / T, with alpha = a T^2 =
/// k^2 / (k - 1):
///   r < 1 - 1/k:       s = alpha r^2 / 2,           ds/dr = alpha r, d2s/dr2 = alpha
///   r > 1/k:           s = 1 - alpha (1 - r)^2 / 2, ds/dr = alpha (1 - r), d2s/dr2 = -alpha
///   otherwise:         s = k r - (k - 1) / 2,       ds/dr = k,       d2s/dr2 = 0
/// (at the switching instants, where the acceleration jumps, s_ddot is 0: the
/// cruise's). k outside (1, 2] or NaN gives NaN.
template <typename Scalar>
inline TimeScaling<Scalar> trapezoidal_time_scaling(const Scalar& duration, const Scalar& peak_velocity_ratio,
                                                    const Scalar& t) noexcept {
  using Real = RealOf<Scalar>;
  const Real k_value = detail::real_value(peak_velocity_ratio);
  if (!(k_value > Real(1) && k_value <= Real(2)))
    return {detail::quiet_nan<Scalar>(), detail::quiet_nan<Scalar>(), detail::quiet_nan<Scalar>()};
  const Scalar& k = peak_velocity_ratio;
  // The acceleration ends at r = 1 - 1/k, the deceleration starts at 1/k.
  const Real accelerating_until = (k_value - Real(1)) / k_value, decelerating_from = Real(1) / k_value;
  return detail::scale_time(duration, t, [&](const Scalar& r) noexcept -> TimeScaling<Scalar> {
    const Scalar alpha = k * k / (k - Scalar(1));
    if (detail::real_value(r) < accelerating_until)
      return {Scalar(alpha * r * r / Scalar(2)), Scalar(alpha * r), alpha};
    if (detail::real_value(r) > decelerating_from) {
      const Scalar u = Scalar(1) - r;
      return {Scalar(Scalar(1) - alpha * u * u / Scalar(2)), Scalar(alpha * u), Scalar(-alpha)};
    }
    return {Scalar(k * r - (k - Scalar(1)) / Scalar(2)), k, Scalar(0)};
  });
}

/// One entry point for the three: peak_velocity_ratio is read by
/// trapezoidal only, which gives NaN without it.
template <typename Scalar>
inline TimeScaling<Scalar> time_scaling(TimeScalingKind kind, const Scalar& duration, const Scalar& t,
                                        const Scalar& peak_velocity_ratio = detail::quiet_nan<Scalar>()) noexcept {
  switch (kind) {
    case TimeScalingKind::cubic: return cubic_time_scaling(duration, t);
    case TimeScalingKind::quintic: return quintic_time_scaling(duration, t);
    case TimeScalingKind::trapezoidal: return trapezoidal_time_scaling(duration, peak_velocity_ratio, t);
  }
  return {detail::quiet_nan<Scalar>(), detail::quiet_nan<Scalar>(), detail::quiet_nan<Scalar>()};
}

/// Joint positions, velocities and accelerations at one time.
template <typename JointVector>
struct JointTrajectoryPoint {
  JointVector q, qd, qdd;
};

/// The straight-line joint trajectory timed by a time scaling (MR 9.2.1):
/// q = q_start + s d, qd = s_dot d, qdd = s_ddot d, d = q_end - q_start.
/// q is q_start + s d for s <= 1/2 and q_end - (1 - s) d above (as
/// std::lerp): exactly q_start at s = 0, q_end at s = 1. Vectors of any
/// fixed, maximum or dynamic size, of one length and one scalar type.
template <typename DerivedStart, typename DerivedEnd>
inline JointTrajectoryPoint<typename DerivedStart::PlainObject> joint_trajectory(
    const Eigen::MatrixBase<DerivedStart>& q_start, const Eigen::MatrixBase<DerivedEnd>& q_end,
    const TimeScaling<typename DerivedStart::Scalar>& scaling) noexcept {
  using Scalar = typename DerivedStart::Scalar;
  using JointVector = typename DerivedStart::PlainObject;
  static_assert(DerivedStart::IsVectorAtCompileTime && DerivedEnd::IsVectorAtCompileTime,
                "chasles: joint_trajectory takes joint vectors");
  static_assert(std::is_same<Scalar, typename DerivedEnd::Scalar>::value,
                "chasles: joint_trajectory's q_start and q_end have one scalar type");
  CHASLES_ASSERT(q_start.size() == q_end.size());
  const JointVector d = q_end - q_start;
  JointTrajectoryPoint<JointVector> point{d, scaling.s_dot * d, scaling.s_ddot * d};
  if (detail::real_value(scaling.s) <= RealOf<Scalar>(0.5)) {
    point.q = q_start + scaling.s * d;
  } else {
    point.q = q_end - (Scalar(1) - scaling.s) * d;
  }
  return point;
}

}  // namespace chasles
