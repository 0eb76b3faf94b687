// chasles: Rodrigues' form I + a [u] + b [u]^2, shared by the SO(3)
// exponential (a = sin(theta)/theta, b = (1 - cos(theta))/theta^2) and the
// SO(3) Jacobians and their inverses (other coefficients, detail/series.hpp).
#pragma once

#include <Eigen/Core>

namespace chasles {
namespace detail {

/// I + a [u] + b [u]^2 from its two coefficients
/// (detail/series.hpp). [u]^2 = u u^T - |u|^2 I, so the diagonal is
/// 1 - b (u_j^2 + u_k^2): no 1 - b|u|^2 + b u_i^2 round trip, and exactly 1
/// on the rotation axis of a coordinate-axis rotation.
template <typename Scalar>
inline Eigen::Matrix<Scalar, 3, 3> rodrigues(const Eigen::Matrix<Scalar, 3, 1>& u, const Scalar& a,
                                             const Scalar& b) noexcept {
  const Scalar xx = u[0] * u[0], yy = u[1] * u[1], zz = u[2] * u[2];
  const Scalar bxy = b * u[0] * u[1], bxz = b * u[0] * u[2], byz = b * u[1] * u[2];
  const Scalar ax = a * u[0], ay = a * u[1], az = a * u[2];
  Eigen::Matrix<Scalar, 3, 3> R;
  R << Scalar(1) - b * (yy + zz), bxy - az, bxz + ay,  //
      bxy + az, Scalar(1) - b * (xx + zz), byz - ax,   //
      bxz - ay, byz + ax, Scalar(1) - b * (xx + yy);
  return R;
}

}  // namespace detail
}  // namespace chasles
