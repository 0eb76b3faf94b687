// chasles: SO(3), the group of rotations of R^3.
#pragma once

#include <limits>
#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "chasles/constants.hpp"
#include "chasles/detail/approx.hpp"
#include "chasles/detail/nearest_rotation.hpp"
#include "chasles/detail/series.hpp"

namespace chasles {

template <typename Scalar_>
class SO3;

namespace detail {

/// What the so(3) log knows besides w, for the se(3) log to reuse.
template <typename Scalar>
struct So3Log {
  Eigen::Matrix<Scalar, 3, 1> omega;  ///< the rotation vector, angle in [0, pi]
  Scalar theta2;                      ///< |omega|^2
  Scalar sin_theta;                   ///< sin(theta); only set when !near_identity
  Scalar one_minus_cos;               ///< 1 - cos(theta), without cancellation
  bool near_identity;                 ///< the Taylor branch was taken
};

/// The log of a rotation matrix, robust over the whole of SO(3) and for
/// matrices a little off it.
///
/// With s = vee((R - R^T)/2) = sin(theta) n and c = (tr R - 1)/2 = cos(theta):
/// - near the identity (c > 0 and |s|^2 below the Taylor cutoff):
///   w = (theta / sin theta) s, the factor a series in |s|^2: no sqrt, no 0/0;
/// - theta <= pi/2: theta = atan2(|s|, c), w = (theta / |s|) s;
/// - theta > pi/2: the axis from the symmetric part,
///   (R + R^T)/2 - c I = (1 - c) n n^T, read from its largest diagonal
///   entry's column (>= (1 - c)/3 >= 1/3: no small divisor), its sign from s,
///   and sin(theta) = n . s, so theta = atan2(n . s, c) stays in [0, pi] and
///   the error of a matrix off by d stays of order d, where dividing by
///   sin(theta) would amplify it by 1/sin(theta).
/// Finite for every finite input: c is clamped to [-1, 1], halves are taken
/// before sums, and a degenerate column falls back to a unit axis.
template <typename Scalar>
inline So3Log<Scalar> so3_log(const Eigen::Matrix<Scalar, 3, 3>& R) noexcept {
  using std::atan2;
  using std::sqrt;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  const Scalar half(0.5);
  const Vector3 s(half * R(2, 1) - half * R(1, 2), half * R(0, 2) - half * R(2, 0),
                  half * R(1, 0) - half * R(0, 1));
  Scalar c = half * R(0, 0) + half * R(1, 1) + half * R(2, 2) - half;
  if (c > Scalar(1)) c = Scalar(1);
  if (c < Scalar(-1)) c = Scalar(-1);
  const Scalar s2 = s.squaredNorm();

  So3Log<Scalar> out;
  if (!(c < Scalar(0))) {
    out.one_minus_cos = s2 / (Scalar(1) + c);  // 1 - c = sin^2 / (1 + c), no cancellation
    if (s2 < ThresholdsOf<Scalar>::taylor_theta2) {
      const Scalar f = theta_over_sin_series(s2);
      out.omega = f * s;
      out.theta2 = s2 * f * f;
      out.near_identity = true;
    } else {
      const Scalar sin_theta = sqrt(s2);
      const Scalar theta = atan2(sin_theta, c);
      out.omega = (theta / sin_theta) * s;
      out.theta2 = theta * theta;
      out.sin_theta = sin_theta;
      out.near_identity = false;
    }
    return out;
  }

  int i = 0;
  if (R(1, 1) > R(i, i)) i = 1;
  if (R(2, 2) > R(i, i)) i = 2;
  const Scalar one_minus_c = Scalar(1) - c;
  Vector3 n;
  for (int j = 0; j < 3; ++j) n[j] = half * R(j, i) + half * R(i, j);
  n[i] = R(i, i) - c;
  const Scalar den2 = n[i] * one_minus_c;
  if (den2 > Scalar(0)) {
    n /= sqrt(den2);
  } else {
    n = Vector3::Unit(i);  // not a rotation: any unit axis keeps the result finite
  }
  Scalar sin_theta = n.dot(s);
  if (sin_theta < Scalar(0)) {
    n = -n;
    sin_theta = -sin_theta;
  }
  const Scalar theta = atan2(sin_theta, c);
  out.omega = theta * n;
  out.theta2 = theta * theta;
  out.sin_theta = sin_theta;
  out.one_minus_cos = one_minus_c;
  out.near_identity = false;
  return out;
}

/// I + a [u] + b [u]^2, expanding [u]^2 = u u^T - |u|^2 I, with u2 = |u|^2:
/// Rodrigues' formula from its coefficients (detail/series.hpp).
template <typename Scalar>
inline Eigen::Matrix<Scalar, 3, 3> rodrigues(const Eigen::Matrix<Scalar, 3, 1>& u, const Scalar& a,
                                             const Scalar& b, const Scalar& u2) noexcept {
  const Scalar c = Scalar(1) - b * u2;  // cos(theta)
  const Scalar bxy = b * u[0] * u[1], bxz = b * u[0] * u[2], byz = b * u[1] * u[2];
  const Scalar ax = a * u[0], ay = a * u[1], az = a * u[2];
  Eigen::Matrix<Scalar, 3, 3> R;
  R << c + b * u[0] * u[0], bxy - az, bxz + ay,  //
      bxy + az, c + b * u[1] * u[1], byz - ax,   //
      bxz - ay, byz + ax, c + b * u[2] * u[2];
  return R;
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
  static constexpr int DoF = 3;

  /// The identity rotation.
  SO3() noexcept : R_(Matrix3::Identity()) {}

  static SO3 identity() noexcept { return SO3(); }

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
    const Scalar half(0.5);
    return Vector3(half * W(2, 1) - half * W(1, 2), half * W(0, 2) - half * W(2, 0),
                   half * W(1, 0) - half * W(0, 1));
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
      return SO3(detail::rodrigues(r.axis, r.sin_theta, r.one_minus_cos, Scalar(1)));
    }
    const auto k = detail::exp_coefficients(t);
    return SO3(detail::rodrigues(w, k.a, k.b, t));
  }

  /// The rotation vector w with exp([w]) = R and |w| in [0, pi]. At exactly
  /// pi both axis signs are correct; one of them is returned, never NaN.
  /// Accurate to a few ulps, and to O(d) for a matrix off SO(3) by d.
  Vector3 log() const noexcept { return detail::so3_log(R_).omega; }

  // ---- group operations -------------------------------------------------

  SO3 inverse() const noexcept { return SO3(R_.transpose()); }

  /// Composition: (R_ab * R_bc) = R_ac.
  SO3 operator*(const SO3& other) const noexcept { return SO3(R_ * other.R_); }
  SO3& operator*=(const SO3& other) noexcept {
    R_ = R_ * other.R_;
    return *this;
  }

  /// Action on a point or vector: p_a = R_ab p_b.
  Vector3 act(const Vector3& p) const noexcept { return R_ * p; }
  Vector3 operator*(const Vector3& p) const noexcept { return R_ * p; }

  /// Adjoint of the group: Ad_R = R, so R exp([w]) R^T = exp([R w]).
  Matrix3 adjoint() const noexcept { return R_; }

  // ---- conversions ------------------------------------------------------

  const Matrix3& matrix() const noexcept { return R_; }

  /// Unit quaternion by Shepperd's method: the largest of 4w^2, 4x^2, 4y^2,
  /// 4z^2 (they sum to 4, so it is >= 1) gives one component, the others are
  /// divided by it: no small divisor for any input. The sign is the one that
  /// makes that largest component positive. Unit to rounding for a
  /// rotation (the class invariant); for a matrix off SO(3) by d (from
  /// from_matrix_unchecked) the norm is off by O(d^2).
  Quaternion quaternion() const noexcept {
    using std::sqrt;
    const Matrix3& R = R_;
    const Scalar kw = Scalar(1) + R(0, 0) + R(1, 1) + R(2, 2);  // 4 w^2
    const Scalar kx = Scalar(1) + R(0, 0) - R(1, 1) - R(2, 2);  // 4 x^2
    const Scalar ky = Scalar(1) - R(0, 0) + R(1, 1) - R(2, 2);  // 4 y^2
    const Scalar kz = Scalar(1) - R(0, 0) - R(1, 1) + R(2, 2);  // 4 z^2
    Scalar w, x, y, z;
    // r = 2 |q_i| >= 1 for the largest; f = 1 / (2 r) scales the pair sums.
    if (!(kw < kx) && !(kw < ky) && !(kw < kz)) {
      const Scalar r = sqrt(kw), f = Scalar(0.5) / r;
      w = Scalar(0.5) * r;
      x = f * (R(2, 1) - R(1, 2));
      y = f * (R(0, 2) - R(2, 0));
      z = f * (R(1, 0) - R(0, 1));
    } else if (!(kx < ky) && !(kx < kz)) {
      const Scalar r = sqrt(kx), f = Scalar(0.5) / r;
      x = Scalar(0.5) * r;
      w = f * (R(2, 1) - R(1, 2));
      y = f * (R(0, 1) + R(1, 0));
      z = f * (R(0, 2) + R(2, 0));
    } else if (!(ky < kz)) {
      const Scalar r = sqrt(ky), f = Scalar(0.5) / r;
      y = Scalar(0.5) * r;
      w = f * (R(0, 2) - R(2, 0));
      x = f * (R(0, 1) + R(1, 0));
      z = f * (R(1, 2) + R(2, 1));
    } else {
      const Scalar r = sqrt(kz), f = Scalar(0.5) / r;
      z = Scalar(0.5) * r;
      w = f * (R(1, 0) - R(0, 1));
      x = f * (R(0, 2) + R(2, 0));
      y = f * (R(1, 2) + R(2, 1));
    }
    // For a rotation |q|^2 = 1 + delta with delta of order eps: one Newton
    // step for 1/sqrt, (3 - |q|^2) / 2, normalizes it to rounding with
    // multiplies only (a sqrt and a divide here would triple the cost).
    // Scaled as scalars, before the quaternion is built: scaling its stored
    // coefficients stalls on store forwarding.
    const Scalar n = Scalar(0.5) * (Scalar(3) - (w * w + x * x + y * y + z * z));
    return Quaternion(n * w, n * x, n * y, n * z);
  }

  /// From a quaternion of any nonzero norm (it is normalized; the zero
  /// quaternion, and one with a non-finite norm, give the identity).
  static SO3 from_quaternion(const Quaternion& q) noexcept {
    const Scalar n2 = q.coeffs().squaredNorm();
    if (!(n2 > Scalar(0)) || !(n2 < Scalar(ThresholdsOf<Scalar>::huge_theta2))) return SO3();
    const Scalar s = Scalar(2) / n2;
    const Scalar w = q.w(), x = q.x(), y = q.y(), z = q.z();
    Matrix3 R;
    R << Scalar(1) - s * (y * y + z * z), s * (x * y - z * w), s * (x * z + y * w),  //
        s * (x * y + z * w), Scalar(1) - s * (x * x + z * z), s * (y * z - x * w),  //
        s * (x * z - y * w), s * (y * z + x * w), Scalar(1) - s * (x * x + y * y);
    return SO3(R);
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
    if (rotation_defect(M) <= tolerance) return SO3(M);
    return std::nullopt;
  }

  /// Unchecked construction: for data known to be a rotation. No cost.
  static SO3 from_matrix_unchecked(const Matrix3& M) noexcept { return SO3(M); }

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
  bool is_approx(const SO3& other, const Real& tol) const noexcept {
    return detail::approx_equal(R_, other.R_, tol);
  }

 private:
  explicit SO3(const Matrix3& R) noexcept : R_(R) {}

  Matrix3 R_;
};

/// Geodesic interpolation: a exp(t log(a^-1 b)); t = 0 gives a, t = 1 gives b.
template <typename Scalar>
inline SO3<Scalar> interpolate(const SO3<Scalar>& a, const SO3<Scalar>& b, const Scalar& t) noexcept {
  return a * SO3<Scalar>::exp(t * (a.inverse() * b).log());
}

using SO3f = SO3<float>;
using SO3d = SO3<double>;

}  // namespace chasles
