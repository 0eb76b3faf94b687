// chasles: SO(3), the group of rotations of R^3.
#pragma once

#include <limits>
#include <optional>
#include <type_traits>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "chasles/constants.hpp"
#include "chasles/detail/approx.hpp"
#include "chasles/detail/arguments.hpp"
#include "chasles/detail/nearest_rotation.hpp"
#include "chasles/detail/rodrigues.hpp"
#include "chasles/detail/series.hpp"
#include "chasles/detail/so3_log.hpp"
#include "chasles/lie_group.hpp"

namespace chasles {

namespace detail {

/// false, for a static_assert in a template that must not be instantiated.
template <typename T>
struct always_false : std::false_type {};

/// A B for 3 x 3 matrices, coefficient by coefficient, not by Eigen's 3 x 3
/// product: a chain's passes multiply rotations that exp has just stored,
/// and Eigen's product reads them back in packets that straddle those
/// stores, a store-forwarding stall per joint (SO3 composition: the mass
/// matrix took 15% longer, a composition alone 10%; SpatialInertia::transform:
/// a tenth of the mass matrix).
template <typename Scalar>
inline Eigen::Matrix<Scalar, 3, 3> product3(const Eigen::Matrix<Scalar, 3, 3>& A,
                                            const Eigen::Matrix<Scalar, 3, 3>& B) noexcept {
  Eigen::Matrix<Scalar, 3, 3> P;
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) P(i, j) = A(i, 0) * B(0, j) + A(i, 1) * B(1, j) + A(i, 2) * B(2, j);
  return P;
}

}  // namespace detail

/// A rotation of R^3: an element of SO(3), stored as its 3x3 matrix.
///
/// `R_ab` maps coordinates in frame b to frame a: `p_a = R_ab * p_b`; its
/// columns are b's axes written in a. Composition follows the frames:
/// `R_ac = R_ab * R_bc`. The tangent space is R^3 (angular velocity / rotation
/// vector w), with `hat(w) p = w x p`.
///
/// Invariant: the matrix is a rotation to working precision, unless built
/// with `from_matrix_unchecked` from data that is not. Every operation is
/// noexcept, allocation-free and of bounded cost.
template <typename Scalar_>
class SO3 {
 public:
  using Scalar = Scalar_;
  using Real = RealOf<Scalar>;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;
  using Quaternion = Eigen::Quaternion<Scalar>;
  using Tangent = Vector3;        ///< the rotation vector w
  using AdjointMatrix = Matrix3;  ///< Ad_R, and the Jacobians
  static constexpr int DoF = 3;

  /// The identity rotation.
  SO3() noexcept : R_(Matrix3::Identity()) {}

  static SO3 identity() noexcept { return SO3(); }

  /// Not a constructor: a 3x3 matrix becomes an SO3 through one of the three
  /// explicit forms, `from_matrix` (checked), `from_matrix_projected` or
  /// `from_matrix_unchecked`. This declaration only turns `SO3 R(M);` and
  /// `SO3 R = M;` into a compile error that says so.
  template <typename Derived,
            std::enable_if_t<Derived::RowsAtCompileTime == 3 && Derived::ColsAtCompileTime == 3, int> = 0>
  SO3(const Eigen::MatrixBase<Derived>& /*M*/) noexcept : R_() {
    static_assert(detail::always_false<Derived>::value,
                  "chasles::SO3 is not constructible from a matrix: use SO3::from_matrix(M) (checked: an "
                  "std::optional, empty when M is not a rotation), SO3::from_matrix_projected(M) (the nearest "
                  "rotation) or SO3::from_matrix_unchecked(M) (for data known to be a rotation)");
  }

  // ---- Lie algebra ------------------------------------------------------

  /// hat(w) = [w] = [[0, -w3, w2], [w3, 0, -w1], [-w2, w1, 0]], so [w] p = w x p.
  static Matrix3 hat(const Vector3& w) noexcept {
    Matrix3 W;
    W << Scalar(0), -w[2], w[1],  //
        w[2], Scalar(0), -w[0],   //
        -w[1], w[0], Scalar(0);
    return W;
  }

  /// vee([w]) = w. Reads the antisymmetric part (W - W^T)/2, so a matrix that
  /// is not exactly skew gives the w of its nearest skew matrix.
  static Vector3 vee(const Matrix3& W) noexcept {
    using detail::half_difference;
    return Vector3(half_difference(W(2, 1), W(1, 2)), half_difference(W(0, 2), W(2, 0)),
                   half_difference(W(1, 0), W(0, 1)));
  }

  /// Adjoint of the algebra: ad(w) = [w] (3x3), so ad(a) b = [a, b].
  static Matrix3 ad(const Vector3& w) noexcept { return hat(w); }

  /// The Lie bracket of so(3): [[a], [b]] = [a x b], i.e. the cross product.
  static Vector3 bracket(const Vector3& a, const Vector3& b) noexcept { return a.cross(b); }

  // ---- exp and log ------------------------------------------------------

  /// exp([w]) by Rodrigues' formula, theta = |w|:
  ///   R = I + (sin theta / theta) [w] + ((1 - cos theta) / theta^2) [w]^2.
  /// Exact to a few ulps for every w, Taylor series below the cutoff
  /// (see constants.hpp), never a 0/0 (autodiff derivatives exact at 0).
  static SO3 exp(const Vector3& w) noexcept {
    const Scalar t = w.squaredNorm();
    if (!(t < Scalar(ThresholdsOf<Scalar>::huge_theta2))) {
      const auto r = detail::long_rotation(w);
      return SO3(Unchecked(), detail::rodrigues(r.axis, r.sin_theta, r.one_minus_cos));
    }
    const auto k = detail::exp_coefficients(t);
    return SO3(Unchecked(), detail::rodrigues(w, k.a, k.b));
  }

  /// The rotation vector w with exp([w]) = R and |w| in [0, pi]. At exactly
  /// pi both axis signs are correct; one of them is returned, never NaN.
  /// Accurate to a few ulps, and to O(d) for a matrix off SO(3) by d.
  Vector3 log() const noexcept { return detail::so3_log(R_).omega; }

  /// The rotation angle theta = |log()| in [0, pi], from the halves of the
  /// quaternion u (as log, through Horn's matrix: detail::so3_log):
  ///   theta = 2 atan2(|u_v|, |u_w|),  |u_v| ~ sin(theta/2), |u_w| ~ cos(theta/2)
  /// (Sola, Deray and Atchuthan 2018, the Log of unit quaternions). Unlike acos((tr R - 1) / 2), which loses
  /// half the digits near 0 and near pi, it is accurate to a few ulps over
  /// the whole range, and to O(d) for a matrix off SO(3) by d. Below
  /// tiny_norm2 (constants.hpp) |u_v|^2 is formed from u_v scaled by its
  /// largest component, so that tiny angles do not underflow to 0. Exactly 0
  /// at the identity, without a sqrt of 0 (autodiff derivatives stay finite).
  Scalar angle() const noexcept {
    using std::abs;
    using std::sqrt;
    detail::Quaternion4<Scalar> u = detail::quaternion_power_step(detail::HornMatrix<Scalar>(R_));
    if (!u.finite()) u = detail::clamped_quaternion_power_step(R_);  // cold: far from SO(3)
    const Scalar uv2 = u.x * u.x + u.y * u.y + u.z * u.z;
    if (!(uv2 < Scalar(ThresholdsOf<Scalar>::tiny_norm2)))
      return Scalar(2) * detail::arctan2<Scalar>(sqrt(uv2), abs(u.w));
    // Cold: |u_v|^2 may have underflowed (theta below about 1e-18 in float,
    // 1e-150 in double): |u_v| = m |u_v / m| with m its largest component.
    Scalar m = abs(u.x);
    if (abs(u.y) > m) m = abs(u.y);
    if (abs(u.z) > m) m = abs(u.z);
    if (!(m > Scalar(0))) return Scalar(0);  // the identity: no sqrt of 0
    const Scalar x = u.x / m, y = u.y / m, z = u.z / m;
    return Scalar(2) * detail::arctan2<Scalar>(m * sqrt(x * x + y * y + z * z), abs(u.w));
  }

  // ---- Jacobians of exp (Sola app. B; B, C, D in detail/series.hpp) -------

  /// Right Jacobian: exp(w + dw) = exp(w) exp(J_r(w) dw + o(dw)),
  ///   J_r(w) = I - B [w] + C [w]^2.
  static Matrix3 right_jacobian(const Vector3& w) noexcept {
    const auto k = detail::exp_coefficients(Scalar(w.squaredNorm()));
    return detail::rodrigues<Scalar>(w, Scalar(-k.b), k.c);
  }
  /// Left Jacobian: exp(w + dw) = exp(J_l(w) dw + o(dw)) exp(w),
  ///   J_l(w) = I + B [w] + C [w]^2 = J_r(-w) = V(w).
  static Matrix3 left_jacobian(const Vector3& w) noexcept {
    const auto k = detail::exp_coefficients(Scalar(w.squaredNorm()));
    return detail::rodrigues<Scalar>(w, k.b, k.c);
  }
  /// J_r(w)^-1 = I + 1/2 [w] + D [w]^2,  D = (1 - (theta/2) cot(theta/2)) / theta^2;
  /// finite for |w| < 2 pi, in particular at and near pi.
  static Matrix3 right_jacobian_inverse(const Vector3& w) noexcept {
    return detail::rodrigues<Scalar>(w, Scalar(0.5), detail::jacobian_inverse_coefficient(Scalar(w.squaredNorm())));
  }
  /// J_l(w)^-1 = I - 1/2 [w] + D [w]^2 = V(w)^-1.
  static Matrix3 left_jacobian_inverse(const Vector3& w) noexcept {
    return detail::rodrigues<Scalar>(w, Scalar(-0.5), detail::jacobian_inverse_coefficient(Scalar(w.squaredNorm())));
  }

  // ---- group operations -------------------------------------------------

  SO3 inverse() const noexcept { return SO3(Unchecked(), R_.transpose()); }

  /// Composition: (R_ab * R_bc) = R_ac (detail::product3: coefficient by coefficient).
  SO3 operator*(const SO3& other) const noexcept { return SO3(Unchecked(), detail::product3(R_, other.R_)); }
  SO3& operator*=(const SO3& other) noexcept {
    R_ = detail::product3(R_, other.R_);
    return *this;
  }

  /// Action on a point or vector: p_a = R_ab p_b.
  Vector3 act(const Vector3& p) const noexcept { return R_ * p; }
  Vector3 operator*(const Vector3& p) const noexcept { return R_ * p; }

  /// Adjoint of the group: Ad_R = R, so R exp([w]) R^T = exp([R w]).
  Matrix3 adjoint() const noexcept { return R_; }

  // ---- conversions ------------------------------------------------------

  const Matrix3& matrix() const noexcept { return R_; }

  /// Unit quaternion by Shepperd's method: of the columns of Horn's
  /// K = 4 q q^T (detail/nearest_rotation.hpp), the one with the largest
  /// diagonal entry 4 q_k^2 (the diagonal sums to 4, so it is >= 1) is
  /// scaled by 1 / (2 |q_k|): no small divisor for any input. The sign is the
  /// one that makes that largest component positive. Unit to rounding for a
  /// rotation (the class invariant); for a matrix off SO(3) by d (from
  /// from_matrix_unchecked) the norm is off by O(d^2). Finite for every
  /// finite matrix (one far from SO(3) is clamped to [-2, 2] first).
  Quaternion quaternion() const noexcept {
    const detail::Quaternion4<Scalar> q = detail::shepperd_quaternion(R_);
    if (q.finite()) {
      return Quaternion(q.w, q.x, q.y, q.z);
    }
    const detail::Quaternion4<Scalar> qc = detail::clamped_shepperd_quaternion(R_);  // cold: far from SO(3)
    return Quaternion(qc.w, qc.x, qc.y, qc.z);
  }

  /// From a quaternion of any nonzero finite norm: it is normalized, from
  /// 1e-300 to 1e300 as from 1 (a norm whose square would underflow or
  /// overflow is first scaled by the largest component). The zero
  /// quaternion, and one with a non-finite component, give the identity.
  static SO3 from_quaternion(const Quaternion& q) noexcept {
    using std::abs;
    Eigen::Matrix<Scalar, 4, 1> c = q.coeffs();
    Scalar n2 = c.squaredNorm();
    if (!(n2 > Scalar(ThresholdsOf<Scalar>::tiny_norm2)) || !(n2 < Scalar(ThresholdsOf<Scalar>::huge_norm2))) {
      Scalar m(0);
      for (int i = 0; i < 4; ++i)
        if (abs(c[i]) > m) m = abs(c[i]);
      if (!(m > Scalar(0)) || !detail::all_finite(c)) return SO3();  // zero, or not finite (a NaN never wins m)
      c /= m;
      n2 = c.squaredNorm();
    }
    const Scalar s = Scalar(2) / n2;
    const Scalar x = c[0], y = c[1], z = c[2], w = c[3];  // Eigen stores (x, y, z, w)
    Matrix3 R;
    R << Scalar(1) - s * (y * y + z * z), s * (x * y - z * w), s * (x * z + y * w),  //
        s * (x * y + z * w), Scalar(1) - s * (x * x + z * z), s * (y * z - x * w),  //
        s * (x * z - y * w), s * (y * z + x * w), Scalar(1) - s * (x * x + y * y);
    return SO3(Unchecked(), R);
  }

  /// How far M is from a rotation: max(|M^T M - I|_max, |det M - 1|).
  /// 0 for a rotation, about 2d for a rotation whose entries are off by d,
  /// 2 for a reflection, +inf when an entry of M is not finite.
  static Scalar rotation_defect(const Matrix3& M) noexcept {
    using std::abs;
    if (!detail::all_finite(M)) return Scalar(std::numeric_limits<Real>::infinity());
    Scalar d = abs(M.determinant() - Scalar(1));
    const Matrix3 E = M.transpose() * M - Matrix3::Identity();
    for (int j = 0; j < 3; ++j)
      for (int i = 0; i < 3; ++i)
        if (abs(E(i, j)) > d) d = abs(E(i, j));
    return d;
  }

  /// Checked construction: M itself if `rotation_defect(M) <= tolerance`,
  /// otherwise nothing. The default tolerance is sqrt(eps) (constants.hpp).
  static std::optional<SO3> from_matrix(
      const Matrix3& M, const Scalar& tolerance = Scalar(ThresholdsOf<Scalar>::rotation_tolerance)) noexcept {
    if (rotation_defect(M) <= tolerance) return SO3(Unchecked(), M);
    return std::nullopt;
  }

  /// Unchecked construction: for data known to be a rotation. No cost.
  static SO3 from_matrix_unchecked(const Matrix3& M) noexcept { return SO3(Unchecked(), M); }

  /// Projecting construction: the rotation nearest to M in the Frobenius
  /// norm (for det M > 0, the orthogonal polar factor), for every finite M,
  /// reflections and singular matrices included (detail/nearest_rotation.hpp).
  /// A non-finite M gives the identity.
  static SO3 from_matrix_projected(const Matrix3& M) noexcept {
    const Eigen::Matrix<Scalar, 4, 1> q = detail::nearest_rotation_quaternion(M);
    return from_quaternion(Quaternion(q[0], q[1], q[2], q[3]));
  }

  /// The nearest rotation to the stored matrix (removes drift after many
  /// compositions).
  SO3 normalized() const noexcept { return from_matrix_projected(R_); }

  template <typename NewScalar>
  SO3<NewScalar> cast() const noexcept {
    return SO3<NewScalar>::from_matrix_unchecked(R_.template cast<NewScalar>());
  }

  /// max |R_this - R_other| <= tol. `==` is deliberately not defined.
  bool is_approx(const SO3& other, const Real& tol) const noexcept { return detail::approx_equal(R_, other.R_, tol); }

 private:
  struct Unchecked {};
  SO3(Unchecked, const Matrix3& R) noexcept : R_(R) {}

  Matrix3 R_;
};

using SO3f = SO3<float>;
using SO3d = SO3<double>;

}  // namespace chasles
