// chasles: the groups in Ceres Solver (http://ceres-solver.org, 2.1 or
// later). Optional: chasles.hpp does not include it, and it needs Ceres's
// headers (Debian/Ubuntu: apt-get install libceres-dev; CMake:
// find_package(Ceres), link Ceres::ceres).
//
// Two things:
//   - every group over `ceres::Jet` scalars, so that an autodiff cost
//     functor can work in chasles types (exp, log, compose, act, rminus and
//     the rest, with exact derivatives at angle 0 too). Include this header
//     before any use of a group over Jet: it tells the groups the real type
//     under a Jet, whose Eigen::NumTraits name the Jet itself;
//   - `CeresManifold<G>`, a `ceres::Manifold` for each group G (over
//     double), with analytic Jacobians, in the parameter layout of
//     `Parameters<G>` below;
//   - `BetweenCost<G>`, the residual of a relative measurement (a pose
//     graph's edge), and `CubicBSplineCost<G>`, the residual of a pose
//     measured on a B-spline (bspline.hpp: continuous-time estimation, the
//     fit of a trajectory to timestamped poses), with analytic Jacobians.
//
// The parameter layout (`Parameters<G>::size` numbers per element, the
// rotation first, then the rest in the order of the group's tangent):
//   SO2   (c, s)                       the unit complex number, 2
//   SE2   (c, s, x, y)                 rotation, translation, 4
//   SO3   (qx, qy, qz, qw)             the unit quaternion (Eigen's order), 4
//   SE3   (qx, qy, qz, qw, x, y, z)    quaternion, translation, 7 (Sophus's)
//   Sim3  (qx, qy, qz, qw, x, y, z, s) quaternion, translation, scale, 8
//   SE23  (qx, qy, qz, qw, px, py, pz, vx, vy, vz)
//                                      quaternion, position, velocity, 10
// The manifold's tangent is the group's (right perturbation, lie_group.hpp):
//   Plus(x, delta) = x exp(delta),   Minus(y, x) = log(x^-1 y) = rminus(y, x).
// Plus writes the quaternion (q or -q, the same rotation) nearer to x's, so
// that an update moves the parameters continuously; Plus(x, Minus(y, x))
// is y itself when y's quaternion is the nearer one (x . y >= 0).
#pragma once

#include <ceres/jet.h>
#include <ceres/manifold.h>
#include <ceres/sized_cost_function.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "chasles/constants.hpp"

namespace chasles {

/// The real type under a Jet (its NumTraits' Literal is the Jet itself).
template <typename T, int N>
struct RealType<::ceres::Jet<T, N>> {
  using type = RealOf<T>;
  static type value(const ::ceres::Jet<T, N>& x) noexcept { return detail::real_value(x.a); }
};

}  // namespace chasles

#include "chasles/bspline.hpp"
#include "chasles/lie_group.hpp"
#include "chasles/se2.hpp"
#include "chasles/se23.hpp"
#include "chasles/se3.hpp"
#include "chasles/sim3.hpp"
#include "chasles/so2.hpp"
#include "chasles/so3.hpp"

namespace chasles {

/// A group element as a Ceres parameter block (the layouts above): `size`,
/// `read(x)` (the quaternion or complex part normalized, as the groups'
/// from_quaternion and from_complex do), `write(g, x, near)` (near: the
/// block whose quaternion's sign to keep, or null), and, over double, the
/// Jacobians of Plus and Minus at x (plus_jacobian: size x DoF,
/// minus_jacobian: DoF x size). Scalar may be a Jet: read and write serve
/// autodiff cost functors.
template <typename G>
struct Parameters;

namespace detail {

template <typename Scalar>
using QuaternionMap = Eigen::Map<const Eigen::Quaternion<Scalar>>;

/// The unit quaternion of R written to x[0..3], its sign the one nearer to
/// `near`'s (when given).
template <typename Scalar>
inline void write_quaternion(const SO3<Scalar>& R, Scalar* x, const Scalar* near) noexcept {
  Eigen::Map<Eigen::Matrix<Scalar, 4, 1>> q(x);
  q = R.quaternion().coeffs();
  if (near != nullptr && q.dot(Eigen::Map<const Eigen::Matrix<Scalar, 4, 1>>(near)) < Scalar(0)) q = -q;
}

/// d q(R exp(w)) / dw at w = 0 for the unit quaternion q = (v, c) of R
/// (Eigen's order): q (x) (w / 2, 1) to first order, so
///   [c I + [v]x ; -v^T] / 2   (4 x 3).
inline Eigen::Matrix<double, 4, 3> quaternion_plus_jacobian(const double* x) noexcept {
  const Eigen::Vector4d q = Eigen::Map<const Eigen::Vector4d>(x).normalized();
  const Eigen::Vector3d v = q.head<3>();
  Eigen::Matrix<double, 4, 3> J;
  J.topRows<3>() = 0.5 * (q[3] * Eigen::Matrix3d::Identity() + SO3<double>::hat(v));
  J.row(3) = -0.5 * v.transpose();
  return J;
}

/// d log(R^-1 R(q + dq)) / dq at dq = 0: 2 (q* (x) dq)'s vector part,
///   2 [c I - [v]x, -v]   (3 x 4), a left inverse of the plus Jacobian
/// (their product is (c^2 + |v|^2) I = I).
inline Eigen::Matrix<double, 3, 4> quaternion_minus_jacobian(const double* x) noexcept {
  const Eigen::Vector4d q = Eigen::Map<const Eigen::Vector4d>(x).normalized();
  const Eigen::Vector3d v = q.head<3>();
  Eigen::Matrix<double, 3, 4> J;
  J.leftCols<3>() = 2.0 * (q[3] * Eigen::Matrix3d::Identity() - SO3<double>::hat(v));
  J.col(3) = -2.0 * v;
  return J;
}

/// The rotation matrix of the quaternion x[0..3] (normalized).
inline Eigen::Matrix3d quaternion_rotation(const double* x) noexcept {
  return SO3<double>::from_quaternion(Eigen::Quaterniond(QuaternionMap<double>(x))).matrix();
}

/// d (c, s)(R exp(theta)) / dtheta at 0 for the unit (c, s): (-s, c); and
/// d theta / d(c, s), its transpose (a left inverse: c^2 + s^2 = 1).
inline Eigen::Vector2d complex_tangent(const double* x) noexcept {
  const Eigen::Vector2d u = Eigen::Map<const Eigen::Vector2d>(x).normalized();
  return Eigen::Vector2d(-u[1], u[0]);
}

}  // namespace detail

template <typename Scalar>
struct Parameters<SO2<Scalar>> {
  static constexpr int size = 2;
  static SO2<Scalar> read(const Scalar* x) noexcept { return SO2<Scalar>::from_complex(x[0], x[1]); }
  static void write(const SO2<Scalar>& g, Scalar* x, const Scalar* /*near*/ = nullptr) noexcept {
    Eigen::Map<Eigen::Matrix<Scalar, 2, 1>>{x} = g.complex();
  }
  static Eigen::Matrix<double, 2, 1> plus_jacobian(const double* x) noexcept { return detail::complex_tangent(x); }
  static Eigen::Matrix<double, 1, 2> minus_jacobian(const double* x) noexcept {
    return detail::complex_tangent(x).transpose();
  }
};

template <typename Scalar>
struct Parameters<SE2<Scalar>> {
  static constexpr int size = 4;
  static SE2<Scalar> read(const Scalar* x) noexcept {
    return SE2<Scalar>(SO2<Scalar>::from_complex(x[0], x[1]), Eigen::Matrix<Scalar, 2, 1>(x[2], x[3]));
  }
  static void write(const SE2<Scalar>& g, Scalar* x, const Scalar* /*near*/ = nullptr) noexcept {
    Eigen::Map<Eigen::Matrix<Scalar, 2, 1>>{x} = g.rotation().complex();
    Eigen::Map<Eigen::Matrix<Scalar, 2, 1>>{x + 2} = g.translation();
  }
  /// x exp((v, w)) = (R exp(w), t + R v) to first order.
  static Eigen::Matrix<double, 4, 3> plus_jacobian(const double* x) noexcept {
    const Eigen::Vector2d u = detail::complex_tangent(x);
    Eigen::Matrix<double, 4, 3> J = Eigen::Matrix<double, 4, 3>::Zero();
    J.block<2, 1>(0, 2) = u;
    J.block<2, 1>(2, 0) = Eigen::Vector2d(u[1], -u[0]);  // R's columns: (c, s) and (-s, c)
    J.block<2, 1>(2, 1) = u;
    return J;
  }
  static Eigen::Matrix<double, 3, 4> minus_jacobian(const double* x) noexcept {
    return plus_jacobian(x).transpose();  // R^T R = I, |(-s, c)| = 1: the transpose is the left inverse
  }
};

template <typename Scalar>
struct Parameters<SO3<Scalar>> {
  static constexpr int size = 4;
  static SO3<Scalar> read(const Scalar* x) noexcept {
    return SO3<Scalar>::from_quaternion(Eigen::Quaternion<Scalar>(detail::QuaternionMap<Scalar>(x)));
  }
  static void write(const SO3<Scalar>& g, Scalar* x, const Scalar* near = nullptr) noexcept {
    detail::write_quaternion(g, x, near);
  }
  static Eigen::Matrix<double, 4, 3> plus_jacobian(const double* x) noexcept {
    return detail::quaternion_plus_jacobian(x);
  }
  static Eigen::Matrix<double, 3, 4> minus_jacobian(const double* x) noexcept {
    return detail::quaternion_minus_jacobian(x);
  }
};

template <typename Scalar>
struct Parameters<SE3<Scalar>> {
  static constexpr int size = 7;
  static SE3<Scalar> read(const Scalar* x) noexcept {
    return SE3<Scalar>(Parameters<SO3<Scalar>>::read(x), Eigen::Map<const Eigen::Matrix<Scalar, 3, 1>>(x + 4));
  }
  static void write(const SE3<Scalar>& g, Scalar* x, const Scalar* near = nullptr) noexcept {
    detail::write_quaternion(g.rotation(), x, near);
    Eigen::Map<Eigen::Matrix<Scalar, 3, 1>>{x + 4} = g.translation();
  }
  /// x exp((v, w)) = (R exp(w), p + R v) to first order.
  static Eigen::Matrix<double, 7, 6> plus_jacobian(const double* x) noexcept {
    Eigen::Matrix<double, 7, 6> J = Eigen::Matrix<double, 7, 6>::Zero();
    J.block<4, 3>(0, 3) = detail::quaternion_plus_jacobian(x);
    J.block<3, 3>(4, 0) = detail::quaternion_rotation(x);
    return J;
  }
  static Eigen::Matrix<double, 6, 7> minus_jacobian(const double* x) noexcept {
    Eigen::Matrix<double, 6, 7> J = Eigen::Matrix<double, 6, 7>::Zero();
    J.block<3, 4>(3, 0) = detail::quaternion_minus_jacobian(x);
    J.block<3, 3>(0, 4) = detail::quaternion_rotation(x).transpose();
    return J;
  }
};

template <typename Scalar>
struct Parameters<Sim3<Scalar>> {
  static constexpr int size = 8;
  static Sim3<Scalar> read(const Scalar* x) noexcept {
    return Sim3<Scalar>(Parameters<SO3<Scalar>>::read(x), Eigen::Map<const Eigen::Matrix<Scalar, 3, 1>>(x + 4), x[7]);
  }
  static void write(const Sim3<Scalar>& g, Scalar* x, const Scalar* near = nullptr) noexcept {
    detail::write_quaternion(g.rotation(), x, near);
    Eigen::Map<Eigen::Matrix<Scalar, 3, 1>>{x + 4} = g.translation();
    x[7] = g.scale();
  }
  /// x exp((v, w, sigma)) = (R exp(w), t + s R v, s e^sigma) to first order.
  static Eigen::Matrix<double, 8, 7> plus_jacobian(const double* x) noexcept {
    Eigen::Matrix<double, 8, 7> J = Eigen::Matrix<double, 8, 7>::Zero();
    J.block<4, 3>(0, 3) = detail::quaternion_plus_jacobian(x);
    J.block<3, 3>(4, 0) = x[7] * detail::quaternion_rotation(x);
    J(7, 6) = x[7];
    return J;
  }
  static Eigen::Matrix<double, 7, 8> minus_jacobian(const double* x) noexcept {
    Eigen::Matrix<double, 7, 8> J = Eigen::Matrix<double, 7, 8>::Zero();
    J.block<3, 4>(3, 0) = detail::quaternion_minus_jacobian(x);
    J.block<3, 3>(0, 4) = detail::quaternion_rotation(x).transpose() / x[7];
    J(6, 7) = 1.0 / x[7];
    return J;
  }
};

template <typename Scalar>
struct Parameters<SE23<Scalar>> {
  static constexpr int size = 10;
  static SE23<Scalar> read(const Scalar* x) noexcept {
    using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
    return SE23<Scalar>(Parameters<SO3<Scalar>>::read(x), Eigen::Map<const Vector3>(x + 4),
                        Eigen::Map<const Vector3>(x + 7));
  }
  static void write(const SE23<Scalar>& g, Scalar* x, const Scalar* near = nullptr) noexcept {
    detail::write_quaternion(g.rotation(), x, near);
    Eigen::Map<Eigen::Matrix<Scalar, 3, 1>>{x + 4} = g.translation();
    Eigen::Map<Eigen::Matrix<Scalar, 3, 1>>{x + 7} = g.velocity();
  }
  /// x exp((rho, nu, w)) = (R exp(w), p + R rho, v + R nu) to first order.
  static Eigen::Matrix<double, 10, 9> plus_jacobian(const double* x) noexcept {
    const Eigen::Matrix3d R = detail::quaternion_rotation(x);
    Eigen::Matrix<double, 10, 9> J = Eigen::Matrix<double, 10, 9>::Zero();
    J.block<4, 3>(0, 6) = detail::quaternion_plus_jacobian(x);
    J.block<3, 3>(4, 0) = R;
    J.block<3, 3>(7, 3) = R;
    return J;
  }
  static Eigen::Matrix<double, 9, 10> minus_jacobian(const double* x) noexcept {
    const Eigen::Matrix3d Rt = detail::quaternion_rotation(x).transpose();
    Eigen::Matrix<double, 9, 10> J = Eigen::Matrix<double, 9, 10>::Zero();
    J.block<3, 4>(6, 0) = detail::quaternion_minus_jacobian(x);
    J.block<3, 3>(0, 4) = Rt;
    J.block<3, 3>(3, 7) = Rt;
    return J;
  }
};

/// A group G over double as a ceres::Manifold, in Parameters<G>'s layout:
///   problem.AddParameterBlock(x, Parameters<SE3d>::size, new CeresManifold<SE3d>);
/// Plus(x, delta) = x exp(delta) and Minus(y, x) = rminus(y, x), with their
/// analytic Jacobians (row-major, as Ceres stores them).
template <typename G>
class CeresManifold final : public ::ceres::Manifold {
 public:
  static_assert(std::is_same<typename G::Scalar, double>::value,
                "ceres::Manifold works in double: CeresManifold<SE3d>");
  using Layout = Parameters<G>;
  static constexpr int kAmbient = Layout::size;
  static constexpr int kTangent = G::DoF;

  int AmbientSize() const noexcept override { return kAmbient; }
  int TangentSize() const noexcept override { return kTangent; }

  bool Plus(const double* x, const double* delta, double* x_plus_delta) const noexcept override {
    Layout::write(rplus(Layout::read(x), Eigen::Map<const Eigen::Matrix<double, kTangent, 1>>(delta)), x_plus_delta, x);
    return true;
  }
  bool PlusJacobian(const double* x, double* jacobian) const noexcept override {
    Eigen::Map<RowMajor<kAmbient, kTangent>>{jacobian} = Layout::plus_jacobian(x);
    return true;
  }
  bool Minus(const double* y, const double* x, double* y_minus_x) const noexcept override {
    Eigen::Map<Eigen::Matrix<double, kTangent, 1>>{y_minus_x} = rminus(Layout::read(y), Layout::read(x));
    return true;
  }
  bool MinusJacobian(const double* x, double* jacobian) const noexcept override {
    Eigen::Map<RowMajor<kTangent, kAmbient>>{jacobian} = Layout::minus_jacobian(x);
    return true;
  }

 private:
  // Ceres's row-major storage (a single column or row is stored alike
  // either way, and Eigen requires a column vector to be column-major).
  template <int Rows, int Cols>
  using RowMajor = Eigen::Matrix<double, Rows, Cols, (Cols == 1 ? Eigen::ColMajor : Eigen::RowMajor)>;
};

/// The residual of a relative measurement Z of a^-1 b (a pose graph's edge,
/// GTSAM's BetweenFactor, g2o's EDGE_SE3:QUAT), weighted by a square root
/// L of its information matrix (L^T L = Omega):
///   r = L e,  e = log(Z^-1 a^-1 b) = rminus(between(a, b), Z),
/// so that |r|^2 = e^T Omega e. Parameter blocks a and b in
/// Parameters<G>'s layout (with CeresManifold<G>). Analytic Jacobians: with
/// E = Z^-1 a^-1 b,
///   de/db = J_r(e)^-1,  de/da = -J_r(e)^-1 Ad_{b^-1 a}
/// (b exp(d) gives E exp(d); a exp(d) gives Z^-1 exp(-d) Z E =
/// E exp(-Ad_{(Z E)^-1} d), Z E = a^-1 b), then by the chain rule through
/// the manifold's Minus Jacobian into the blocks' coordinates (Ceres
/// multiplies them by the Plus Jacobian: J_r^-1 .. Minus' Plus' = J_r^-1 ..).
template <typename G>
class BetweenCost final : public ::ceres::SizedCostFunction<G::DoF, Parameters<G>::size, Parameters<G>::size> {
 public:
  static constexpr int kDoF = G::DoF;
  static constexpr int kSize = Parameters<G>::size;
  using Matrix = typename G::AdjointMatrix;

  /// Allocates (Ceres's base stores the block sizes in a std::vector).
  BetweenCost(const G& measurement, const Matrix& sqrt_information)
      : inverse_measurement_(measurement.inverse()), sqrt_information_(sqrt_information) {}

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const noexcept override {
    using Layout = Parameters<G>;
    const G a = Layout::read(parameters[0]);
    const G b = Layout::read(parameters[1]);
    const G a_inverse_b = a.inverse() * b;
    const typename G::Tangent e = (inverse_measurement_ * a_inverse_b).log();
    Eigen::Map<Eigen::Matrix<double, kDoF, 1>>{residuals} = sqrt_information_ * e;
    if (jacobians == nullptr) return true;
    const Matrix LJ = sqrt_information_ * G::right_jacobian_inverse(e);
    if (jacobians[0] != nullptr) {
      Eigen::Map<Eigen::Matrix<double, kDoF, kSize, Eigen::RowMajor>>{jacobians[0]} =
          -(LJ * a_inverse_b.inverse().adjoint()) * Layout::minus_jacobian(parameters[0]);
    }
    if (jacobians[1] != nullptr) {
      Eigen::Map<Eigen::Matrix<double, kDoF, kSize, Eigen::RowMajor>>{jacobians[1]} =
          LJ * Layout::minus_jacobian(parameters[1]);
    }
    return true;
  }

 private:
  G inverse_measurement_;
  Matrix sqrt_information_;
};

/// The residual of a pose Z measured at a time of a uniform cubic B-spline
/// (bspline.hpp), weighted by a square root L of its information matrix
/// (L^T L = Omega):
///   r = L e,  e = log(Z^-1 X(u)) = rminus(X(u), Z),
/// X(u) the segment over the four control elements of the time's segment
/// (parameter blocks X_i .. X_{i+3} in Parameters<G>'s layout) and u the
/// time's place in it (cubic_bspline_locate gives both). Analytic
/// Jacobians: de/dX_k = J_r(e)^-1 dX/dX_k, dX/dX_k from
/// cubic_bspline_segment_jacobians, then through the Minus Jacobian into
/// the blocks' coordinates (as BetweenCost).
template <typename G>
class CubicBSplineCost final : public ::ceres::SizedCostFunction<G::DoF, Parameters<G>::size, Parameters<G>::size,
                                                                 Parameters<G>::size, Parameters<G>::size> {
 public:
  static constexpr int kDoF = G::DoF;
  static constexpr int kSize = Parameters<G>::size;
  using Matrix = typename G::AdjointMatrix;

  /// Allocates (Ceres's base stores the block sizes in a std::vector).
  CubicBSplineCost(double u, const G& measurement, const Matrix& sqrt_information)
      : u_(u), inverse_measurement_(measurement.inverse()), sqrt_information_(sqrt_information) {}

  bool Evaluate(double const* const* parameters, double* residuals, double** jacobians) const noexcept override {
    using Layout = Parameters<G>;
    const G four[4] = {Layout::read(parameters[0]), Layout::read(parameters[1]), Layout::read(parameters[2]),
                       Layout::read(parameters[3])};
    const BSplineSegmentJacobians<G> X = cubic_bspline_segment_jacobians(four, u_);
    const typename G::Tangent e = (inverse_measurement_ * X.value).log();
    Eigen::Map<Eigen::Matrix<double, kDoF, 1>>{residuals} = sqrt_information_ * e;
    if (jacobians == nullptr) return true;
    const Matrix LJ = sqrt_information_ * G::right_jacobian_inverse(e);
    for (int k = 0; k < 4; ++k) {
      if (jacobians[k] != nullptr) {
        Eigen::Map<Eigen::Matrix<double, kDoF, kSize, Eigen::RowMajor>>{jacobians[k]} =
            LJ * X.control[k] * Layout::minus_jacobian(parameters[k]);
      }
    }
    return true;
  }

 private:
  double u_;
  G inverse_measurement_;
  Matrix sqrt_information_;
};

}  // namespace chasles
