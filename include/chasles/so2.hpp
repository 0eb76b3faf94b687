// chasles: SO(2), the group of rotations of the plane.
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <type_traits>

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/detail/approx.hpp"
#include "chasles/detail/series.hpp"
#include "chasles/lie_group.hpp"

namespace chasles {

namespace detail {

/// (x, y) / |(x, y)| for any finite nonzero (x, y), from 1e-300 to 1e300 as
/// from 1 (a norm whose square would underflow or overflow is first scaled
/// by the larger component); (1, 0) for zero or a non-finite component.
template <typename Scalar>
inline Eigen::Matrix<Scalar, 2, 1> unit_complex(const Scalar& x, const Scalar& y) noexcept {
  using std::abs;
  using std::sqrt;
  Scalar a = x, b = y;
  Scalar n2 = a * a + b * b;
  if (!(n2 > Scalar(ThresholdsOf<Scalar>::tiny_norm2)) || !(n2 < Scalar(ThresholdsOf<Scalar>::huge_norm2))) {
    const Scalar m = abs(a) > abs(b) ? abs(a) : abs(b);
    if (!(m > Scalar(0)) || !is_finite(a) || !is_finite(b)) return Eigen::Matrix<Scalar, 2, 1>(Scalar(1), Scalar(0));
    a /= m;
    b /= m;
    n2 = a * a + b * b;
  }
  const Scalar n = sqrt(n2);
  return Eigen::Matrix<Scalar, 2, 1>(a / n, b / n);
}

/// The angle theta = atan2(s, c) of (c, s), and e = (theta/2) cot(theta/2)
/// (the diagonal of SE(2)'s V^-1, for SE2::log), from the half angle, as so3_log does it
/// (detail/so3_log.hpp): (u_w, u_v) is a positive multiple of
/// (cos(theta/2), sin(theta/2)) without cancellation, (1 + c, s) for c >= 0
/// and (|s|, sign(s) (1 - c)) otherwise; then theta/2 = atan2(u_v, u_w) in
/// [-pi/2, pi/2] by the rational atan of detail/series.hpp (AtanRational: a
/// <= b the smaller and the larger of |u_v| and u_w, atan(a/b) = (a/b) g,
/// g = G / (B Q~) from the homogeneous forms in A = a^2, B = b^2), so that
/// theta = f u_v with
///   |theta| < pi/2: f = 2 G / (u_w B Q~),
///   past it:        f = (pi - 2 u_w G / (|u_v| B Q~)) / |u_v|,
/// and e = (theta/2) u_w / u_v = f u_w / 2: no libm call, two divides, no
/// branch for small angles (g = 1 exactly at 0: autodiff derivatives exact
/// there), e = 0 at pi. Measured against atan2 in long double over 2e6
/// angles (random, near 0, near pi): theta within 4.0 eps in double and in
/// float, worst just past pi/2 (libm's atan2: 0.5 ulp, and SO2::angle keeps
/// it), at 0.7 of SE2::log's cost with atan2. For (c, s) off the unit circle
/// by d, theta errs by O(d). Types without the rational fit (long double)
/// take atan2.
template <typename Scalar>
struct PlanarLog {
  Scalar theta, e;
};
template <typename Scalar>
inline PlanarLog<Scalar> planar_log(const Scalar& c, const Scalar& s) noexcept {
  const bool right = !(c < Scalar(0));  // NaN takes this side, and stays NaN
  const Scalar uw = right ? Scalar(Scalar(1) + c) : Scalar(s < Scalar(0) ? Scalar(-s) : s);
  const Scalar uv = right ? s : Scalar(s < Scalar(0) ? Scalar(c - Scalar(1)) : Scalar(Scalar(1) - c));
  const Scalar n = uv < Scalar(0) ? Scalar(-uv) : uv;
  if constexpr (AtanRational<RealOf<Scalar>>::available) {
    using R = AtanRational<RealOf<Scalar>>;
    constexpr std::size_t np = std::extent<decltype(R::p)>::value;
    const Scalar uv2 = uv * uv, uw2 = uw * uw;
    const bool acute = uv2 < uw2;
    const Scalar A = acute ? uv2 : uw2, B = acute ? uw2 : uv2;
    Scalar p, q;
    if constexpr (std::is_floating_point<Scalar>::value) {
      using Pair = Eigen::Array<Scalar, 2, 1>;  // P and Q side by side
      const Pair pq = homogeneous_estrin<Pair, np>(A, B, [](std::size_t i) { return Pair(R::p[i], R::q[i]); });
      p = pq[0], q = pq[1];
    } else {
      p = homogeneous_estrin<Scalar, np>(A, B, [](std::size_t i) { return Scalar(R::p[i]); });
      q = homogeneous_estrin<Scalar, np>(A, B, [](std::size_t i) { return Scalar(R::q[i]); });
    }
    const Scalar bq = B * q;
    const Scalar g2 = Scalar(2) * (bq - A * p);  // 2 G
    if (acute) {
      const Scalar f = g2 / (uw * bq);  // theta / u_v
      return {f * uv, Scalar(0.5) * f * uw};
    }
    // theta = sign(u_v) (pi - 2 atan(u_w / n)): pi less the small part, not
    // divided by n and multiplied back (two roundings more on pi).
    const Scalar inv = Scalar(1) / (n * bq);
    const Scalar rest = Scalar(3.14159265358979323846) - uw * g2 * inv;
    return {uv < Scalar(0) ? Scalar(-rest) : rest, Scalar(0.5) * rest * uw * bq * inv};
  } else {
    const Scalar half = detail::arctan2<Scalar>(uv, uw);  // in [-pi/2, pi/2]
    const Scalar t = Scalar(4) * half * half;
    if (t < Scalar(ThresholdsOf<Scalar>::taylor_theta2))  // e's series: no 0/0 at 0
      return {Scalar(2) * half, Scalar(1) - t / Scalar(12) * (Scalar(1) + t / Scalar(60))};
    return {Scalar(2) * half, half * uw / uv};
  }
}

}  // namespace detail

/// A rotation of the plane: an element of SO(2), stored as the unit complex
/// number (cos theta, sin theta). Its matrix is R = [[c, -s], [s, c]].
///
/// Stored as two numbers rather than the 2x2 matrix: composition is one
/// complex product (4 multiplications), half the memory traffic of the
/// matrix product, and the matrix is formed only when asked for. The tangent
/// space is R (the angle theta, a 1-vector for the generic code), with
/// hat(theta) = [[0, -theta], [theta, 0]]. R_ab maps frame b to frame a, as
/// for SO3. Every operation is noexcept, allocation-free and of bounded cost.
template <typename Scalar_>
class SO2 {
 public:
  using Scalar = Scalar_;
  using Real = RealOf<Scalar>;
  using Vector2 = Eigen::Matrix<Scalar, 2, 1>;
  using Matrix2 = Eigen::Matrix<Scalar, 2, 2>;
  using Tangent = Eigen::Matrix<Scalar, 1, 1>;        ///< the angle theta
  using AdjointMatrix = Eigen::Matrix<Scalar, 1, 1>;  ///< Ad_R = 1, and the Jacobians
  static constexpr int DoF = 1;

  /// The identity rotation.
  SO2() noexcept : cs_(Scalar(1), Scalar(0)) {}
  static SO2 identity() noexcept { return SO2(); }

  // ---- Lie algebra ------------------------------------------------------

  /// hat(theta) = [[0, -theta], [theta, 0]].
  static Matrix2 hat(const Tangent& theta) noexcept {
    Matrix2 W;
    W << Scalar(0), -theta[0], theta[0], Scalar(0);
    return W;
  }
  /// vee reads the antisymmetric part: (W(1, 0) - W(0, 1)) / 2.
  static Tangent vee(const Matrix2& W) noexcept { return Tangent(detail::half_difference(W(1, 0), W(0, 1))); }
  /// ad(theta) = 0: SO(2) is commutative.
  static AdjointMatrix ad(const Tangent& /*theta*/) noexcept { return AdjointMatrix::Zero(); }

  // ---- exp and log ------------------------------------------------------

  /// exp(theta) = (cos theta, sin theta): one sincos, exact to the libm's
  /// rounding for every theta.
  static SO2 exp(const Scalar& theta) noexcept {
    using std::cos;
    using std::sin;
    return SO2(Unchecked(), cos(theta), sin(theta));
  }
  static SO2 exp(const Tangent& theta) noexcept { return exp(theta[0]); }

  /// The angle theta = atan2(s, c) in [-pi, pi]: libm's atan2, within an ulp
  /// over the whole range, and for (c, s) off the unit circle by d too (atan2
  /// reads only the direction). (SE2::log takes the angle with its e from
  /// detail::planar_log instead: no libm call, a few ulps.)
  Scalar angle() const noexcept { return detail::arctan2<Scalar>(cs_[1], cs_[0]); }
  Tangent log() const noexcept { return Tangent(angle()); }

  // ---- Jacobians of exp: all the identity (the group is commutative) ------

  static AdjointMatrix right_jacobian(const Tangent&) noexcept { return AdjointMatrix::Identity(); }
  static AdjointMatrix left_jacobian(const Tangent&) noexcept { return AdjointMatrix::Identity(); }
  static AdjointMatrix right_jacobian_inverse(const Tangent&) noexcept { return AdjointMatrix::Identity(); }
  static AdjointMatrix left_jacobian_inverse(const Tangent&) noexcept { return AdjointMatrix::Identity(); }

  // ---- group operations -------------------------------------------------

  /// R^-1 = R^T: the conjugate (c, -s).
  SO2 inverse() const noexcept { return SO2(Unchecked(), cs_[0], -cs_[1]); }

  /// Composition R_ab R_bc = R_ac: the complex product.
  SO2 operator*(const SO2& o) const noexcept {
    return SO2(Unchecked(), cs_[0] * o.cs_[0] - cs_[1] * o.cs_[1], cs_[0] * o.cs_[1] + cs_[1] * o.cs_[0]);
  }
  SO2& operator*=(const SO2& o) noexcept { return *this = *this * o; }

  /// Action on a point or vector: p_a = R_ab p_b.
  Vector2 act(const Vector2& p) const noexcept {
    return Vector2(cs_[0] * p[0] - cs_[1] * p[1], cs_[1] * p[0] + cs_[0] * p[1]);
  }
  Vector2 operator*(const Vector2& p) const noexcept { return act(p); }

  /// Ad_R = 1 (1x1): R exp(theta) R^-1 = exp(theta).
  AdjointMatrix adjoint() const noexcept { return AdjointMatrix::Identity(); }

  // ---- access and conversions -------------------------------------------

  /// (cos theta, sin theta).
  const Vector2& complex() const noexcept { return cs_; }

  /// R = [[c, -s], [s, c]].
  Matrix2 matrix() const noexcept {
    Matrix2 R;
    R << cs_[0], -cs_[1], cs_[1], cs_[0];
    return R;
  }

  /// How far M is from a rotation: max(|M^T M - I|_max, |det M - 1|); +inf
  /// when an entry is not finite (as SO3::rotation_defect).
  static Scalar rotation_defect(const Matrix2& M) noexcept {
    using std::abs;
    if (!detail::all_finite(M)) return Scalar(std::numeric_limits<Real>::infinity());
    Scalar d = abs(M.determinant() - Scalar(1));
    const Matrix2 E = M.transpose() * M - Matrix2::Identity();
    for (int j = 0; j < 2; ++j)
      for (int i = 0; i < 2; ++i)
        if (abs(E(i, j)) > d) d = abs(E(i, j));
    return d;
  }

  /// Checked construction: the rotation of M if `rotation_defect(M) <=
  /// tolerance` (default sqrt(eps), constants.hpp), otherwise nothing.
  static std::optional<SO2> from_matrix(
      const Matrix2& M, const Scalar& tolerance = Scalar(ThresholdsOf<Scalar>::rotation_tolerance)) noexcept {
    if (rotation_defect(M) <= tolerance) return from_matrix_unchecked(M);
    return std::nullopt;
  }

  /// Unchecked construction, for data known to be a rotation: (c, s) =
  /// ((M00 + M11) / 2, (M10 - M01) / 2), the rotation part of M, which
  /// gives back a rotation matrix's own numbers exactly.
  static SO2 from_matrix_unchecked(const Matrix2& M) noexcept {
    const Scalar half(0.5);
    return SO2(Unchecked(), half * M(0, 0) + half * M(1, 1), half * M(1, 0) - half * M(0, 1));
  }

  /// The rotation nearest to M in the Frobenius norm: the one maximizing
  /// tr(R^T M) = c (M00 + M11) + s (M10 - M01), i.e. that vector made unit,
  /// for every finite M (a reflection's rotation part may be 0: then the
  /// identity, one of the nearest). A non-finite M gives the identity.
  static SO2 from_matrix_projected(const Matrix2& M) noexcept {
    const Vector2 u = detail::unit_complex<Scalar>(M(0, 0) + M(1, 1), M(1, 0) - M(0, 1));
    return SO2(Unchecked(), u[0], u[1]);
  }

  /// From a complex number (c, s) of any nonzero finite norm, normalized;
  /// zero or non-finite gives the identity.
  static SO2 from_complex(const Scalar& c, const Scalar& s) noexcept {
    const Vector2 u = detail::unit_complex<Scalar>(c, s);
    return SO2(Unchecked(), u[0], u[1]);
  }

  /// From (c, s) known to be unit (cos and sin of an angle). No cost.
  static SO2 from_complex_unchecked(const Scalar& c, const Scalar& s) noexcept { return SO2(Unchecked(), c, s); }

  /// The same rotation with (c, s) made unit (removes drift).
  SO2 normalized() const noexcept { return from_complex(cs_[0], cs_[1]); }

  template <typename NewScalar>
  SO2<NewScalar> cast() const noexcept {
    return SO2<NewScalar>::from_matrix_unchecked(matrix().template cast<NewScalar>());
  }

  /// max |R_this - R_other| <= tol (entries of the matrices). No `==`.
  bool is_approx(const SO2& other, const Real& tol) const noexcept { return detail::approx_equal(cs_, other.cs_, tol); }

 private:
  struct Unchecked {};
  SO2(Unchecked, const Scalar& c, const Scalar& s) noexcept : cs_(c, s) {}

  Vector2 cs_;
};

using SO2f = SO2<float>;
using SO2d = SO2<double>;

}  // namespace chasles
