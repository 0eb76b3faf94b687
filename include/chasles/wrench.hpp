// chasles: wrenches, the elements of se(3)*, dual to twists.
#pragma once

#include <Eigen/Core>

#include "chasles/detail/approx.hpp"
#include "chasles/detail/arguments.hpp"
#include "chasles/screw.hpp"
#include "chasles/twist.hpp"

namespace chasles {

/// A wrench F = (f, tau): force first, torque second, so that the power of
/// a twist V = (v, w) on it is the plain dot product V . F = v.f + w.tau.
///
/// Wrenches change frame by the transpose of the adjoint: F_b = Ad_{g_ab}^T F_a
/// (`SE3::act_inv(Wrench)`), F_a = Ad_{g_ab}^-T F_b (`SE3::act(Wrench)`), which
/// is what keeps the power V . F the same in every frame.
template <typename Scalar_>
class Wrench {
 public:
  using Scalar = Scalar_;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  using Vector6 = Eigen::Matrix<Scalar, 6, 1>;
  static constexpr int force_offset = 0;   ///< where f starts in vector()
  static constexpr int torque_offset = 3;  ///< where tau starts in vector()

  /// The zero wrench.
  Wrench() noexcept : F_(Vector6::Zero()) {}
  /// From the force f and the torque tau.
  Wrench(const Vector3& f, const Vector3& tau) noexcept : F_(detail::stack<Scalar>(f, tau)) {}
  /// From the 6-vector (f, tau).
  explicit Wrench(const Vector6& F) noexcept : F_(F) {}

  const Vector6& vector() const noexcept { return F_; }
  Vector6& vector() noexcept { return F_; }
  auto force() const noexcept { return F_.template segment<3>(force_offset); }
  auto force() noexcept { return F_.template segment<3>(force_offset); }
  auto torque() const noexcept { return F_.template segment<3>(torque_offset); }
  auto torque() noexcept { return F_.template segment<3>(torque_offset); }

  /// The power V . F = v.f + w.tau of a twist on this wrench.
  Scalar power(const Twist<Scalar>& V) const noexcept { return V.vector().dot(F_); }

  /// The screw of the wrench (Poinsot): with f != 0, a force along the line
  /// through f x tau / |f|^2 with direction f / |f|, magnitude |f|, plus a
  /// torque pitch * f about it, pitch = f.tau / |f|^2; with f = 0 (or f so
  /// small that the line is beyond the largest finite distance), a pure
  /// couple: pitch +inf, direction tau / |tau|, magnitude |tau|.
  Screw<Scalar> screw() const noexcept { return detail::screw_of_pair(Vector3(force()), Vector3(torque())); }
  /// f.tau / |f|^2 (+inf for f = 0).
  Scalar pitch() const noexcept { return screw().pitch; }

  /// The wrench of a screw: magnitude * (d, q x d + h d) for the line
  /// through `point` q along `direction` d (normalized here), `pitch` h; with
  /// h = +inf, the couple (0, magnitude * d).
  static Wrench from_screw(const Vector3& point, const Vector3& direction, const Scalar& pitch,
                           const Scalar& magnitude) noexcept {
    Vector3 f, tau;
    detail::pair_of_screw(point, direction, pitch, magnitude, f, tau);
    return Wrench(f, tau);
  }
  static Wrench from_screw(const Screw<Scalar>& s) noexcept {
    return from_screw(s.point, s.direction, s.pitch, s.magnitude);
  }

  template <typename NewScalar>
  Wrench<NewScalar> cast() const noexcept {
    return Wrench<NewScalar>(F_.template cast<NewScalar>());
  }

  Wrench operator+(const Wrench& o) const noexcept { return Wrench(Vector6(F_ + o.F_)); }
  Wrench operator-(const Wrench& o) const noexcept { return Wrench(Vector6(F_ - o.F_)); }
  Wrench operator-() const noexcept { return Wrench(Vector6(-F_)); }
  Wrench operator*(const Scalar& s) const noexcept { return Wrench(Vector6(F_ * s)); }
  /// x * s for s of another arithmetic type (0.1 for a float wrench), converted explicitly.
  template <typename T, detail::EnableIfOtherArithmetic<Scalar, T> = 0>
  Wrench operator*(const T& s) const noexcept {
    return *this * detail::scalar_of<Scalar>(s);
  }

  /// max |F - other| <= tol * max(1, max |F|, max |other|).
  bool is_approx(const Wrench& other, const RealOf<Scalar>& tol) const noexcept {
    return detail::approx_equal(F_, other.F_, tol);
  }

 private:
  Vector6 F_;
};

/// The power V . F of a twist on a wrench (both in the same frame).
template <typename Scalar>
inline Scalar power(const Twist<Scalar>& V, const Wrench<Scalar>& F) noexcept {
  return F.power(V);
}

/// s * x, the same as x * s.
template <typename Scalar>
inline Wrench<Scalar> operator*(const typename Wrench<Scalar>::Scalar& s, const Wrench<Scalar>& x) noexcept {
  return x * s;
}
template <typename Scalar, typename T, detail::EnableIfOtherArithmetic<Scalar, T> = 0>
inline Wrench<Scalar> operator*(const T& s, const Wrench<Scalar>& x) noexcept {
  return x * detail::scalar_of<Scalar>(s);
}

using Wrenchf = Wrench<float>;
using Wrenchd = Wrench<double>;

}  // namespace chasles
