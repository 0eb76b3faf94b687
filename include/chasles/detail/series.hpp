// chasles: the coefficient functions of exp and log, each written once.
//
// With theta = |w| and t = theta^2, the exponentials of so(3) and se(3) are
//   exp([w])   = I + A [w] + B [w]^2                               (Rodrigues)
//   V(w)       = I + B [w] + C [w]^2,   exp([xi]) = [exp([w]), V v; 0, 1]
// and the inverse of V, used by the se(3) log, is
//   V(w)^-1    = I - 1/2 [w] + D [w]^2
// with
//   A = sin(theta) / theta              = 1 - t/6 + t^2/120 - ...
//   B = (1 - cos(theta)) / theta^2      = 1/2 - t/24 + t^2/720 - ...
//   C = (theta - sin(theta)) / theta^3  = 1/6 - t/120 + t^2/5040 - ...
//   D = (1 - (theta/2) cot(theta/2)) / theta^2 = 1/12 + t/720 + t^2/30240 + ...
// (Murray, Li and Sastry, A Mathematical Introduction to Robotic Manipulation,
// 1994, eqs. 2.14 and 2.36; Sola, Deray and Atchuthan, A micro Lie theory for
// state estimation in robotics, 2018, eqs. 143 and 174.)
//
// Below Thresholds::taylor_theta2 the series are used: they form no 0/0, so
// values and autodiff derivatives are exact at theta = 0. Above it the closed
// forms are used, written without cancellation where the coefficient is
// multiplied by something of order 1 (B via the half angle). C and D do
// cancel near 0, but each only ever multiplies [w]^2, of size t, so the
// absolute error it adds is a few eps: the results stay exact to a few ulps.
#pragma once

#include <cmath>
#include <cstddef>
#include <type_traits>
#include <utility>

#include <Eigen/Core>

#include "chasles/constants.hpp"

namespace chasles {
namespace detail {

/// A, B and C of the exponential at t = theta^2.
template <typename Scalar>
struct ExpCoefficients {
  Scalar a;  ///< sin(theta) / theta
  Scalar b;  ///< (1 - cos(theta)) / theta^2
  Scalar c;  ///< (theta - sin(theta)) / theta^3
};

/// sum_i coef(i) x^i, i < N, by Estrin's scheme: the pairs
/// coef(2i) + coef(2i+1) x, then pairs of those with x^2, then x^4, ...: a
/// chain of about 2 log2(N) dependent operations instead of Horner's
/// 2 (N - 1). V is the scalar type, or an Eigen array of K scalars that
/// evaluates K polynomials of the same degree side by side (one vector
/// operation each: exp's A and B).
/// The loops are unrolled by pragma (GCC's and Clang's): their bounds are
/// constants, but GCC left them rolled under -march=native, a loop counter
/// and stores of v per step that made SE(3)'s exp and every pass over a
/// chain 5-10% slower than the portable build.
template <typename V, std::size_t N, typename X, typename Coef>
inline V estrin(const X& x0, const Coef& coef) noexcept {
  V v[N];
#pragma GCC unroll 16
  for (std::size_t i = 0; i < N; ++i) v[i] = coef(i);
  X x = x0;
#pragma GCC unroll 8
  for (std::size_t n = N; n > 1; n = (n + 1) / 2) {
#pragma GCC unroll 8
    for (std::size_t i = 0; 2 * i + 1 < n; ++i) v[i] = v[2 * i] + v[2 * i + 1] * x;
    if (n % 2 == 1) v[n / 2] = v[n - 1];
    if (n > 2) x = x * x;
  }
  return v[0];
}

/// The same on homogeneous forms: with x = X / Y, returns
/// Y^(N' - 1) sum_i coef(i) x^i (N' = N rounded up to a power of two) from
/// X and Y, never forming x: the pairs coef(2i) Y + coef(2i+1) X, then
/// pairs of those with Y^2 and X^2, ...; an odd one out at a level is
/// multiplied by that level's power of Y, as if paired with a zero. Two
/// forms of the same N have the same factor Y^(N' - 1): their ratio is the
/// ratio of the polynomials at x, for one division and no other.
template <typename V, std::size_t N, typename X, typename Coef>
inline V homogeneous_estrin(const X& x0, const X& y0, const Coef& coef) noexcept {
  V v[N];
#pragma GCC unroll 16
  for (std::size_t i = 0; i < N; ++i) v[i] = coef(i);
  X x = x0, y = y0;
#pragma GCC unroll 8
  for (std::size_t n = N; n > 1; n = (n + 1) / 2) {
#pragma GCC unroll 8
    for (std::size_t i = 0; 2 * i + 1 < n; ++i) v[i] = v[2 * i] * y + v[2 * i + 1] * x;
    if (n % 2 == 1) v[n / 2] = v[n - 1] * y;
    if (n > 2) x = x * x, y = y * y;
  }
  return v[0];
}

/// Polynomials for A, B and C in u = t - exp_polynomial_center, t =
/// theta^2, on t in [0, exp_polynomial_theta2] (constants.hpp: 7, and 10,
/// past pi^2), in place of sqrt, sincos and a divide: the near-minimax
/// (Chebyshev) fits computed in 50-digit arithmetic and rounded to the type.
/// tests/tools/fit_exp_polynomials.py makes them and measures them:
/// evaluated as below, in the type, against 40-digit values at 6200 points
/// of [0, 10] (uniform, random, and geometric down to 1e-12), the worst
/// absolute errors, and the same times theta for A (which multiplies [w]) and
/// times t for B and C (which multiply [w]^2), i.e. as they reach a matrix:
///   double: A degree 10 1.46 eps (1.93 times theta), B 10 0.51 (2.68 times t),
///           C 9 0.27 (1.27 times t);
///   float:  A degree 6 1.43 eps (1.66), B 6 0.59 (3.43), C 5 0.22 (1.07);
/// each degree the lowest at which the fit's own error is far below that
/// rounding (B takes A's, one more than it needs: they are evaluated side by
/// side, `ab` holding their coefficients in pairs). Centered: in powers of t itself (f(0) + t g(t), exact at 0)
/// the terms of B at t = pi^2 are 0.5, -0.41, 0.14, ... for a value of 0.2,
/// and that cancellation reached the matrix as 6.1 eps (the closed form:
/// 4.1): SO3 exp erred by 5.6 eps near pi, past test_accuracy's 4.5. The
/// centered fits reach 2.7, and SO3 exp's worst entrywise error near pi
/// (2000 random axes, theta in [2.5, pi]) is 3.8 eps against the closed
/// form's 5.8. They do not give f(0) exactly, so below taylor_theta2 the
/// series is used as before (exact at 0, autodiff derivatives exact there).
/// The closed forms err by a few eps too. Only float and double have the
/// polynomials; other real types take the series and the closed forms.
template <typename Real>
struct ExpPolynomials {
  static constexpr bool available = false;
};

template <>
struct ExpPolynomials<double> {
  static constexpr bool available = true;
  alignas(2 * sizeof(double)) static constexpr double ab[][2] = {
      {0.17982485208003604, 0.2685098191583184},       {-0.07567097044201891, -0.02551391330261434},
      {0.004896445903072807, 0.0009423100988728012},   {-0.0001324877834490328, -1.8033683099142838e-05},
      {1.988217267223815e-06, 2.103871668592042e-07},  {-1.9042606768955807e-08, -1.6522057338245808e-09},
      {1.2674937763121227e-10, 9.331690901748137e-12}, {-6.21000254748272e-13, -3.973770716349296e-14},
      {2.3346040986261543e-15, 1.321705996211109e-16}, {-6.94479565159577e-18, -3.5269488640657977e-19},
      {1.755264802987073e-20, 8.051663747841043e-22}};
  static constexpr double c[] = {0.11716787827428056,     -0.005928129690323091,  0.00014738339817861249,
                                 -2.1279449613694143e-06, 1.9961099163359695e-08, -1.3121319906013034e-10,
                                 6.376888363585834e-13,   -2.38408481750134e-15,  7.065156482087271e-18,
                                 -1.7728724485362963e-20};
};

template <>
struct ExpPolynomials<float> {
  static constexpr bool available = true;
  alignas(2 * sizeof(float)) static constexpr float ab[][2] = {
      {0.1798248589038849f, 0.26850980520248413f},        {-0.07567097246646881f, -0.025513913482427597f},
      {0.004896446131169796f, 0.0009423101437278092f},    {-0.00013248820323497057f, -1.8033710148301907e-05f},
      {1.9881156276824186e-06f, 2.1038069064616138e-07f}, {-1.901587332042709e-08f, -1.6505081745776806e-09f},
      {1.3581735736067913e-10f, 9.909129072838141e-12f}};
  static constexpr float c[] = {0.1171678751707077f,     -0.005928129889070988f, 0.0001473836018703878f,
                                -2.127852212652215e-06f, 1.994574461150478e-08f, -1.3916268137847965e-10f};
};

/// A, B, C from theta^2 alone: the series below the cutoff; above it, for
/// float and double (and autodiff scalars over them) up to
/// exp_polynomial_theta2 the polynomials above (no libm call), and beyond
/// it, or for other real types, one sincos of theta/2. The compiler drops
/// `c` where a caller does not read it.
template <typename Scalar>
inline ExpCoefficients<Scalar> exp_coefficients(const Scalar& theta2) noexcept {
  using std::cos;
  using std::sin;
  using std::sqrt;
  ExpCoefficients<Scalar> k;
  using P = ExpPolynomials<RealOf<Scalar>>;
  if (theta2 < ThresholdsOf<Scalar>::taylor_theta2) {
    const Scalar& t = theta2;
    k.a = Scalar(1) - t * (Scalar(1) / Scalar(6) - t * (Scalar(1) / Scalar(120)));
    k.b = Scalar(0.5) - t * (Scalar(1) / Scalar(24) - t * (Scalar(1) / Scalar(720)));
    k.c = Scalar(1) / Scalar(6) - t * (Scalar(1) / Scalar(120) - t * (Scalar(1) / Scalar(5040)));
    return k;
  }
  if constexpr (P::available) {
    if (theta2 <= ThresholdsOf<Scalar>::exp_polynomial_theta2) {
      constexpr std::size_t nab = std::extent<decltype(P::ab)>::value, nc = std::extent<decltype(P::c)>::value;
      static_assert(nc <= nab, "C is evaluated beside A and B, padded to their degree");
      const Scalar u = theta2 - Scalar(ThresholdsOf<Scalar>::exp_polynomial_center);
      if constexpr (std::is_same<Scalar, float>::value) {
        // A, B and C in three lanes of one 4-float vector (C padded with
        // zero coefficients, which add exactly 0): one SSE operation per
        // step for all three.
        using Quad = Eigen::Array<float, 4, 1>;
        const Quad abc = estrin<Quad, nab>(
            u, [](std::size_t i) { return Quad(P::ab[i][0], P::ab[i][1], i < nc ? P::c[i] : 0.0f, 0.0f); });
        k.a = abc[0];
        k.b = abc[1];
        k.c = abc[2];
        return k;
      } else if constexpr (std::is_floating_point<Scalar>::value) {
        // A and B in the two lanes of one vector: half the operations.
        using Pair = Eigen::Array<Scalar, 2, 1>;
        const Pair ab = estrin<Pair, nab>(u, [](std::size_t i) { return Pair(P::ab[i][0], P::ab[i][1]); });
        k.a = ab[0];
        k.b = ab[1];
      } else {
        k.a = estrin<Scalar, nab>(u, [](std::size_t i) { return Scalar(P::ab[i][0]); });
        k.b = estrin<Scalar, nab>(u, [](std::size_t i) { return Scalar(P::ab[i][1]); });
      }
      k.c = estrin<Scalar, nc>(u, [](std::size_t i) { return Scalar(P::c[i]); });
      return k;
    }
  }
  const Scalar theta = sqrt(theta2);
  const Scalar sh = sin(Scalar(0.5) * theta);
  const Scalar ch = cos(Scalar(0.5) * theta);
  // sin(theta) = 2 sin(theta/2) cos(theta/2); 1 - cos(theta) = 2 sin^2(theta/2):
  // no cancellation at small theta.
  const Scalar inv = Scalar(1) / theta;  // one divide for all three
  k.a = Scalar(2) * sh * ch * inv;
  k.b = Scalar(2) * sh * sh * inv * inv;
  k.c = (Scalar(1) - k.a) * inv * inv;
  return k;
}

/// Whether Scalar is Eigen's AutoDiffScalar (a value and its derivatives()).
template <typename Scalar, typename = void>
struct IsEigenAutoDiff : std::false_type {};
template <typename Scalar>
struct IsEigenAutoDiff<Scalar, std::void_t<decltype(std::declval<const Scalar&>().derivatives())>> : std::true_type {};

/// atan2(y, x): std::atan2 for the real types. For an autodiff scalar (a
/// value and derivatives: Eigen's AutoDiffScalar, nested or not), the
/// atan2 of the values and the derivatives (y' x - y x') / (x^2 + y^2), in
/// the scalar's own derivative type: Eigen's atan2 of two AutoDiffScalars
/// returns a dynamic-size derivative vector, a heap allocation on every
/// call (tests/cpp/realtime/test_no_allocation.cpp found it in
/// SO3::angle). Call it as arctan2<Scalar>(y, x): the arguments may be
/// expressions of autodiff scalars. Another scalar type (ceres::Jet) uses
/// its own atan2, found by argument-dependent lookup.
template <typename Scalar>
inline Scalar arctan2(const Scalar& y, const Scalar& x) noexcept {
  if constexpr (std::is_floating_point<Scalar>::value) {
    return std::atan2(y, x);
  } else if constexpr (!IsEigenAutoDiff<Scalar>::value) {
    return atan2(y, x);
  } else {
    using Value = std::decay_t<decltype(y.value())>;
    const Value& yv = y.value();
    const Value& xv = x.value();
    const Value r2 = xv * xv + yv * yv;
    return Scalar(arctan2<Value>(yv, xv), (y.derivatives() * xv - x.derivatives() * yv) / r2);
  }
}

/// atan(x): std::atan for the real types; atan2(x, 1) for scalar types
/// whose library has atan2 but no atan (Eigen's AutoDiffScalar).
template <typename Scalar>
inline Scalar arctan(const Scalar& x) noexcept {
  if constexpr (std::is_floating_point<Scalar>::value) {
    return std::atan(x);
  } else {
    return arctan2<Scalar>(x, Scalar(1));
  }
}

/// asin(x) / x as a series in x2 = x^2, for the so(3) log near the
/// identity (x = sin(theta)): 1 + x^2/6 + 3 x^4/40 + 5 x^6/112 + ...
template <typename Scalar>
inline Scalar asin_over_x_series(const Scalar& x2) noexcept {
  return Scalar(1) + x2 * (Scalar(1) / Scalar(6) + x2 * (Scalar(3) / Scalar(40)));
}

/// atan(x) / x = 1 - z h(z), z = x^2 in [0, 1], h = P / Q: the
/// near-minimax rational fit of h (h(0) = 1/3, h(1) = 1 - pi/4) in
/// relative error, computed in 50-digit arithmetic (a rational Remez
/// exchange) and rounded to the type, for the so(3) log in place of a libm
/// atan, a square root's divide and a second divide. Fitting h rather than
/// atan(x)/x itself: z h is at most 0.215 of the 1 it is subtracted from, so
/// the rounding of P and Q reaches the result damped fourfold (the direct
/// fit, evaluated the same way, erred by 2.7 eps). Each N is the least
/// whose fit error, so damped, is under 1% of an ulp.
/// tests/tools/fit_atan_rational.py makes them and measures them, as
/// so3_log evaluates them (homogeneous_estrin on the squares of the two
/// sides of the half angle).
template <typename Real>
struct AtanRational {
  static constexpr bool available = false;
};

template <>
struct AtanRational<double> {
  static constexpr bool available = true;
  static constexpr double p[] = {0.33333333333333331,   0.81965905456958787,  0.72807838388838253,
                                 0.28277567649728369,   0.045711446627230853, 0.0022768134950878097,
                                 2.5189379962458495e-06};
  static constexpr double q[] = {1.0,
                                 3.0589771637087613,
                                 3.5910500213191527,
                                 2.0253001625931484,
                                 0.56022478166087497,
                                 0.068498929980146187,
                                 0.0026511682928634971};
};

template <>
struct AtanRational<float> {
  static constexpr bool available = true;
  static constexpr float p[] = {0.333333343f, 0.352800846f, 0.0766717046f, 0.000502140261f};
  static constexpr float q[] = {1.0f, 1.65840244f, 0.79648757f, 0.101966873f};
};

/// atan(x) / x as a series in x2 = x^2, for the so(3) log near the
/// identity (x = tan(theta/2)): 1 - x^2/3 + x^4/5 - x^6/7 + ...
template <typename Scalar>
inline Scalar atan_over_x_series(const Scalar& x2) noexcept {
  return Scalar(1) - x2 * (Scalar(1) / Scalar(3) - x2 * (Scalar(1) / Scalar(5)));
}

/// E and D of V^-1 = E I - 1/2 [w] + D w w^T, the inverse of V used by the
/// se(3) log (expanding [w]^2 = w w^T - theta^2 I in I - 1/2 [w] + D [w]^2):
///   E = 1 - D theta^2 = (theta/2) cot(theta/2) = 1 - t/12 - t^2/720 - ...
///   D = (1 - E) / theta^2                       = 1/12 + t/720 + t^2/30240 + ...
/// E in closed form comes from the so(3) log (`half_theta_cot`, from the
/// quaternion: no subtraction, 0 at pi). D cancels near the cutoff but
/// multiplies w w^T (of size t). `near_identity` is the so(3) log's choice
/// of branch.
template <typename Scalar>
struct VInverseCoefficients {
  Scalar e;
  Scalar d;
};

template <typename Scalar>
inline VInverseCoefficients<Scalar> v_inverse_coefficients(const Scalar& theta2, const Scalar& half_theta_cot,
                                                           bool near_identity) noexcept {
  VInverseCoefficients<Scalar> k;
  if (near_identity) {
    const Scalar& t = theta2;
    k.d = Scalar(1) / Scalar(12) + t * (Scalar(1) / Scalar(720) + t * (Scalar(1) / Scalar(30240)));
    k.e = Scalar(1) - t * k.d;
  } else {
    k.e = half_theta_cot;
    k.d = (Scalar(1) - k.e) / theta2;
  }
  return k;
}

/// D = (1 - (theta/2) cot(theta/2)) / theta^2 from theta^2 alone, for the
/// inverses of the SO(3) Jacobians (I -/+ 1/2 [w] + D [w]^2):
///   series below Thresholds::taylor_theta2:  1/12 + t/720 + t^2/30240;
///   above it, E = (theta/2) cos(theta/2) / sin(theta/2) from the half angle,
///   then (1 - E) / theta^2. Finite up to and beyond pi (sin(theta/2) >= 1/sqrt(2)
///   on [0, 3pi/2]); it diverges only at theta = 2 pi, where the inverse
///   Jacobian does not exist. 1 - E cancels near the cutoff, but D only ever
///   multiplies [w]^2 (of size t), so the absolute error it adds is a few eps.
///   No 0/0 on either branch: autodiff derivatives are exact at 0.
template <typename Scalar>
inline Scalar jacobian_inverse_coefficient(const Scalar& theta2) noexcept {
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (theta2 < ThresholdsOf<Scalar>::taylor_theta2) {
    const Scalar& t = theta2;
    return Scalar(1) / Scalar(12) + t * (Scalar(1) / Scalar(720) + t * (Scalar(1) / Scalar(30240)));
  }
  const Scalar half = Scalar(0.5) * sqrt(theta2);
  const Scalar e = half * cos(half) / sin(half);
  return (Scalar(1) - e) / theta2;
}

/// The two coefficients of Q(v, w) (the upper-right block of the SE(3) left
/// Jacobian) beyond A, B, C: with t = theta^2,
///   q3 = (theta^2 + 2 cos(theta) - 2) / (2 theta^4)          = (1/2 - B) / t
///      = 1/24 - t/720 + t^2/40320 - ...
///   q4 = (2 theta - 3 sin(theta) + theta cos(theta)) / (2 theta^5) = (3 C - B) / (2 t)
///      = 1/120 - t/2520 + t^2/120960 - ...
/// (Barfoot, State Estimation for Robotics, 2017, eq. 7.86; Sola et al. 2018,
/// eq. 180). Below the cutoff the series; above it the forms in B and C,
/// which cancel near the cutoff: q3 multiplies terms of size t |v| and q4
/// terms of size t^2 |v|, so the absolute error they add is a few eps |v|.
template <typename Scalar>
struct QCoefficients {
  Scalar b;   ///< (1 - cos(theta)) / theta^2
  Scalar c;   ///< (theta - sin(theta)) / theta^3
  Scalar q3;  ///< (1/2 - B) / theta^2
  Scalar q4;  ///< (3 C - B) / (2 theta^2)
};

template <typename Scalar>
inline QCoefficients<Scalar> q_coefficients(const Scalar& theta2) noexcept {
  const ExpCoefficients<Scalar> k = exp_coefficients(theta2);
  QCoefficients<Scalar> q;
  q.b = k.b;
  q.c = k.c;
  if (theta2 < ThresholdsOf<Scalar>::taylor_theta2) {
    const Scalar& t = theta2;
    q.q3 = Scalar(1) / Scalar(24) - t * (Scalar(1) / Scalar(720) - t * (Scalar(1) / Scalar(40320)));
    q.q4 = Scalar(1) / Scalar(120) - t * (Scalar(1) / Scalar(2520) - t * (Scalar(1) / Scalar(120960)));
  } else {
    const Scalar inv = Scalar(1) / theta2;
    q.q3 = (Scalar(0.5) - k.b) * inv;
    q.q4 = Scalar(0.5) * (Scalar(3) * k.c - k.b) * inv;
  }
  return q;
}

/// A rotation vector w too long for |w|^2 to be formed (|w|^2 at or above
/// Thresholds::huge_theta2, or overflowing): its unit axis and the
/// coefficients of exp in unit-axis form,
///   exp([w]) = I + sin(theta) [n] + (1 - cos(theta)) [n]^2,
///   V(w) v   = A v + (B theta) (n x v) + (1 - A) (n . v) n,
/// from theta/2, which is finite for every finite w. The cold path of exp.
template <typename Scalar>
struct LongRotation {
  Eigen::Matrix<Scalar, 3, 1> axis;  ///< n = w / |w|
  Scalar sin_theta;                  ///< sin(theta)
  Scalar one_minus_cos;              ///< 1 - cos(theta)
  Scalar a;                          ///< sin(theta) / theta
  Scalar b_theta;                    ///< (1 - cos(theta)) / theta
};

template <typename Scalar>
inline LongRotation<Scalar> long_rotation(const Eigen::Matrix<Scalar, 3, 1>& w) noexcept {
  using std::abs;
  using std::cos;
  using std::sin;
  using std::sqrt;
  Scalar m = abs(w[0]);
  if (abs(w[1]) > m) m = abs(w[1]);
  if (abs(w[2]) > m) m = abs(w[2]);
  const Eigen::Matrix<Scalar, 3, 1> u = w / m;  // max |u_i| = 1
  const Scalar nu = sqrt(u.squaredNorm());      // in [1, sqrt(3)]
  const Scalar half = (Scalar(0.5) * m) * nu;   // theta / 2, finite
  const Scalar sh = sin(half);
  const Scalar ch = cos(half);
  LongRotation<Scalar> r;
  r.axis = u / nu;
  r.sin_theta = Scalar(2) * sh * ch;
  r.one_minus_cos = Scalar(2) * sh * sh;
  r.a = sh * ch / half;
  r.b_theta = sh * sh / half;
  return r;
}

}  // namespace detail
}  // namespace chasles
