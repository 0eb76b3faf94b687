// Fuzz target: SE(3) exp and log, screws (twist -> screw, screw -> twist and
// motion), wrench screws and interpolation, in float and double.
//
// Input: byte 0 picks the scalar type (bit 0 set: float); then raw T values:
// xi = (v, w) (6), q (4, as w x y z) and p (3) of a second motion g = (R(q), p),
// a screw: point (3), direction (3), pitch, magnitude; then t (1).
//
// Properties (every input; tolerances and domains in fuzz_support.hpp):
// - exp(xi), xi finite, |v_i| <= translation_limit(): finite; the rotation
//   that of SO3::exp(w) to kOp eps and a rotation (defect_bound of the exp
//   contract); for angles up to pi, p = V v keeps the component along the
//   axis (n.p = n.v) and |p| <= |v| (|V| <= 1), to kExp eps |v|;
// - log of exp(xi) and of g: finite, angle in [0, pi], exp(log g) = g to kExp
//   eps max(1, |p|); below pi - kPiMargin eps, log(exp(xi)) = xi;
// - Twist(v, w).screw(), |v_i|, |w_i| <= max / 2 (so |v|, |w| are finite):
//   finite fields, pitch +inf only for w = 0 or an axis that is truly beyond
//   the largest finite distance (pitch or point past max / 2 in long
//   double), unit direction (zero for the zero twist), magnitude |w| (|v| at
//   infinite pitch), and from_screw gives the twist back (kChain eps) when
//   the point and the pitch are below max / 4;
// - from_screw(point, direction, pitch, magnitude) for any nonzero finite
//   direction, finite or +inf pitch, and sizes within [1/S, S] (S = 2^(e/4),
//   e the largest binary exponent, so that no product overflows or
//   underflows): the twist magnitude (-d x q + h d, d) (d = direction / |d|),
//   and its screw gives back |magnitude|, sign(magnitude) d, the pitch and
//   the point of the line nearest the origin; SE3::from_screw is its exp;
// - Wrench(f, tau).screw(): the same finiteness;
// - interpolate(g, exp(xi), t), |t| <= 1024, translations below
//   max / 2^22: finite, accepted by SE3::from_matrix (its defect is
//   reported); exactly g at t = 0, exp(xi) to kChain eps max(1, |p_g| + |p|)
//   at t = 1 (b's translation is formed from g's).
#include <cstddef>
#include <cstdint>

#include <chasles/se3.hpp>
#include <chasles/twist.hpp>
#include <chasles/wrench.hpp>

#include "fuzz_support.hpp"
#include "properties.hpp"

namespace {

using namespace chasles_fuzz;

template <typename T>
LD motion_error(const chasles::SE3<T>& a, const chasles::SE3<T>& b, LD extra_scale = 1) {
  return error_in_eps<T>(a.matrix(), b.matrix(), extra_scale);
}

/// log, its angle, and exp(log g) = g for a valid motion g.
template <typename T, typename Describe>
void check_valid_motion(const chasles::SE3<T>& g, const char* ty, const Describe& describe) {
  using SE3 = chasles::SE3<T>;
  const Vec6<T> xi = g.log();
  check(finite(xi), "SE3 log of a valid motion is finite", ty, describe);
  check_log_angle<T>(Vec3<T>(xi.template tail<3>()), ty, describe);
  const LD off = kDefect * rotation_defect(g.rotation().matrix()) / eps<T>();
  check_le(motion_error<T>(SE3::exp(xi), g) - off, kExp, "SE3 exp(log g) - g - 4 defect (eps max(1,|p|))", ty,
           describe);
  const auto accepted = SE3::from_matrix(g.matrix());
  check(accepted.has_value() && identical(accepted->matrix(), g.matrix()), "SE3::from_matrix accepts a valid motion",
        ty, describe);
}

bool within(const LD x, const LD lo, const LD hi) { return std::fabs(x) >= lo && std::fabs(x) <= hi; }

template <typename T, typename Describe>
void check_twist_screw(const Vec3<T>& v, const Vec3<T>& w, const char* ty, const Describe& describe) {
  using Twist = chasles::Twist<T>;
  const LD half_max = LD(std::numeric_limits<T>::max()) / 2;
  const chasles::Screw<T> s = Twist(v, w).screw();
  if (!(finite(v) && finite(w) && max_abs(v) <= half_max && max_abs(w) <= half_max)) return;
  const auto where = [&] {
    return describe() + "; screw: point " + str(s.point) + ", direction " + str(s.direction) + ", pitch " +
           str(s.pitch) + ", magnitude " + str(s.magnitude);
  };
  check(finite(s.point) && finite(s.direction) && std::isfinite(s.magnitude) &&
            (std::isfinite(s.pitch) || s.pitch == std::numeric_limits<T>::infinity()),
        "screw of a twist: finite fields (pitch finite or +inf)", ty, where);
  const LD nw = norm(w), nv = norm(v);
  if (std::isfinite(s.pitch)) {
    if (nw == 0) {
      check(nv == 0 && s.magnitude == 0 && s.pitch == 0 && max_abs(s.direction) == 0,
            "screw of the zero twist: magnitude 0, pitch 0, direction 0", ty, where);
      return;
    }
    check_le(std::fabs(norm(s.direction) - 1) / eps<T>(), kOp, "screw: |direction| - 1 (eps)", ty, where);
    check_le((std::fabs(LD(s.magnitude) - nw) - subnormal_allowance<T>()) / (eps<T>() * nw), kOp,
             "screw: magnitude - |w| (eps |w|)", ty, where);
    // Back to the twist, where from_screw's q x d + h d cannot overflow
    // (point and pitch below max / 4; the screws of test_finite.cpp keep
    // them near 1e8): closer to the largest finite value it may, although
    // the twist, magnitude times it, is representable.
    if (std::max(max_abs(s.point), std::fabs(LD(s.pitch))) > half_max / 2) return;
    const Twist back = Twist::from_screw(s);
    const LD scale = std::max({LD(1), max_abs(v), max_abs(w)});
    const LD err = std::max(max_abs_diff(back.linear(), v), max_abs_diff(back.angular(), w)) / (eps<T>() * scale);
    check_le(err, kChain, "from_screw(screw(xi)) - xi (eps max(1,|xi|))", ty, where);
  } else {
    // Infinite pitch: w = 0, or the axis is beyond the largest finite
    // distance (its true pitch or point, in long double, past max / 2). (For
    // a subnormal w, |w| and so the pitch are only known to the spacing of
    // subnormals: not checked there.)
    if (max_abs(w) >= LD(std::numeric_limits<T>::min())) {  // |w| itself is then exact to an ulp
      const Vec3<LD> wl = w.template cast<LD>() / nw, vl = v.template cast<LD>() / nw;
      const LD pitch = std::fabs(wl.dot(vl)), point = max_abs(Vec3<LD>(wl.cross(vl)));
      check(std::max(pitch, point) > half_max,
            "screw: infinite pitch only for w = 0 or an axis beyond the largest finite distance", ty, where);
    }
    check(max_abs(s.point) == 0, "screw at infinite pitch: point 0", ty, where);
    check_le((std::fabs(LD(s.magnitude) - nv) - subnormal_allowance<T>()) / (eps<T>() * nv), kOp,
             "screw at infinite pitch: magnitude - |v| (eps |v|)", ty, where);
  }
}

template <typename T, typename Describe>
void check_screw_twist(const Vec3<T>& point, const Vec3<T>& direction, T pitch, T magnitude, const char* ty,
                       const Describe& describe) {
  using Twist = chasles::Twist<T>;
  using SE3 = chasles::SE3<T>;
  const Twist xi = Twist::from_screw(point, direction, pitch, magnitude);
  const SE3 g = SE3::from_screw(point, direction, pitch, magnitude);
  // Sizes: magnitude in [1/S, S], point and pitch at most S; the direction
  // any finite nonzero vector ("normalized here").
  const LD S = std::ldexp(LD(1), std::numeric_limits<T>::max_exponent / 4);
  const LD nd = norm(direction);
  const bool infinite_pitch = pitch == std::numeric_limits<T>::infinity();
  if (!(finite(point) && finite(direction) && (std::isfinite(pitch) || infinite_pitch) && within(magnitude, 1 / S, S) &&
        max_abs(point) <= S && (infinite_pitch || std::fabs(LD(pitch)) <= S) && nd > 0))
    return;
  const auto where = [&] { return describe() + "; twist " + str(xi.vector()); };
  check(finite(xi.vector()), "from_screw: finite twist", ty, where);
  check(finite(g.matrix()), "SE3::from_screw: finite motion", ty, where);
  check_le(motion_error<T>(g, SE3::exp(xi)), 0, "SE3::from_screw = exp(Twist::from_screw) exactly", ty, where);
  // The expected twist, in long double.
  const Vec3<LD> d = direction.template cast<LD>() / nd, q = point.template cast<LD>();
  const LD m = magnitude;
  Vec3<LD> w_ref = m * d, v_ref;
  if (infinite_pitch) {
    v_ref = w_ref;
    w_ref.setZero();
  } else {
    v_ref = m * (-d.cross(q) + LD(pitch) * d);
  }
  const LD size = std::max({LD(1), max_abs(point), infinite_pitch ? LD(0) : std::fabs(LD(pitch))});
  const LD scale = std::fabs(m) * size;
  check_le(std::max(max_abs_diff(xi.angular(), w_ref), max_abs_diff(xi.linear(), v_ref)) / (eps<T>() * scale), kChain,
           "from_screw vs long double (eps |magnitude| max(1,|q|,|h|))", ty, where);
  // And back: the screw of that twist.
  const chasles::Screw<T> s = xi.screw();
  const auto where2 = [&] {
    return where() + "; its screw: point " + str(s.point) + ", direction " + str(s.direction) + ", pitch " +
           str(s.pitch) + ", magnitude " + str(s.magnitude);
  };
  const LD sign = m < 0 ? -1 : 1;
  check_le(std::fabs(LD(s.magnitude) - std::fabs(m)) / (eps<T>() * std::fabs(m)), kOp,
           "screw(from_screw): magnitude (eps |magnitude|)", ty, where2);
  check_le(max_abs_diff(s.direction, Vec3<LD>(sign * d)) / eps<T>(), kOp, "screw(from_screw): direction (eps)", ty,
           where2);
  if (infinite_pitch) {
    check(s.pitch == std::numeric_limits<T>::infinity(), "screw(from_screw): infinite pitch kept", ty, where2);
  } else {
    const Vec3<LD> nearest = q - d.dot(q) * d;  // the point of the line nearest the origin
    check_le(std::fabs(LD(s.pitch) - LD(pitch)) / (eps<T>() * size), kChain,
             "screw(from_screw): pitch (eps max(1,|q|,|h|))", ty, where2);
    check_le(max_abs_diff(s.point, nearest) / (eps<T>() * size), kChain,
             "screw(from_screw): point (eps max(1,|q|,|h|))", ty, where2);
  }
}

template <typename T>
void fuzz(Bytes& in) {
  using SO3 = chasles::SO3<T>;
  using SE3 = chasles::SE3<T>;
  const char* ty = type_name<T>();
  const Vec6<T> xi = in.vector<T, 6>();
  const Vec4<T> qc = in.vector<T, 4>();
  const Vec3<T> p = in.vector<T, 3>();
  const Vec3<T> point = in.vector<T, 3>();
  const Vec3<T> direction = in.vector<T, 3>();
  const T pitch = in.scalar<T>();
  const T magnitude = in.scalar<T>();
  const T t = in.scalar<T>();
  const auto input = [&] {
    return "xi = " + str(xi) + ", q (w x y z) = " + str(qc) + ", p = " + str(p) + ", screw point " + str(point) +
           ", direction " + str(direction) + ", pitch " + str(pitch) + ", magnitude " + str(magnitude) +
           ", t = " + str(t);
  };
  const Vec3<T> v = xi.template head<3>(), w = xi.template tail<3>();
  const T limit = translation_limit<T>();

  // ---- exp and log ----
  const SE3 E = SE3::exp(xi);
  const bool xi_ok = finite(xi) && max_abs(v) <= LD(limit);
  if (xi_ok) {
    check(finite(E.matrix()), "SE3 exp of a finite twist (v within the limit) is finite", ty, input);
    check_le(error_in_eps<T>(E.rotation().matrix(), SO3::exp(w).matrix()), kOp, "SE3 exp rotation vs SO3 exp (eps)", ty,
             input);
    check_le(rotation_defect(E.rotation().matrix()) / eps<T>(), defect_bound(exp_contract<T>()) / eps<T>(),
             "SE3 exp: rotation defect (eps)", ty, input);
    const LD nv = norm(v), nw = norm(w);
    const Vec3<LD> pl = E.translation().template cast<LD>();
    // The translation's accuracy is promised for angles up to pi (docs/numerics.md,
    // "Measured errors"); past it, C w . v (of size |v| / |w|) may underflow while
    // |v| does not.
    if (nv > 0 && nw <= kPi) {
      check_le((norm(E.translation()) - nv - subnormal_allowance<T>()) / (eps<T>() * nv), kExp,
               "SE3 exp: (|p| - |v|) (eps |v|)", ty, input);
      if (nw > 0) {
        const Vec3<LD> n = w.template cast<LD>() / nw;
        check_le((std::fabs(n.dot(pl) - n.dot(v.template cast<LD>())) - subnormal_allowance<T>()) / (eps<T>() * nv),
                 kExp, "SE3 exp: n.p - n.v (eps |v|)", ty, input);
      }
    }
    if (nw < kPi - kPiMargin * eps<T>()) {
      const LD scale = std::max(LD(1), max_abs(xi));
      check_le(max_abs_diff(E.log(), xi) / (eps<T>() * scale), kExp, "SE3 log(exp(xi)) - xi, |w| < pi (eps)", ty,
               input);
    }
    check_valid_motion<T>(E, ty, input);
  }
  const bool g_ok = finite(qc) && max_abs(qc) > 0 && finite(p) && max_abs(p) <= LD(limit);
  const SE3 g(SO3::from_quaternion(Eigen::Quaternion<T>(qc[0], qc[1], qc[2], qc[3])), p);
  if (g_ok) check_valid_motion<T>(g, ty, input);

  // ---- screws ----
  check_twist_screw<T>(v, w, ty, input);
  check_screw_twist<T>(point, direction, pitch, magnitude, ty, input);
  {
    const chasles::Screw<T> s = chasles::Wrench<T>(v, w).screw();  // force v, torque w
    const LD half_max = LD(std::numeric_limits<T>::max()) / 2;
    if (finite(v) && finite(w) && max_abs(v) <= half_max && max_abs(w) <= half_max)
      check(finite(s.point) && finite(s.direction) && std::isfinite(s.magnitude) &&
                (std::isfinite(s.pitch) || s.pitch == std::numeric_limits<T>::infinity()),
            "screw of a wrench: finite fields (pitch finite or +inf)", ty, input);
  }

  // ---- interpolation ----
  const SE3 a = g_ok ? g : SE3::identity();
  const SE3 b = xi_ok ? E : SE3::identity();
  const SE3 I = chasles::interpolate(a, b, t);
  const LD small = std::ldexp(LD(std::numeric_limits<T>::max()), -22);
  if (std::isfinite(t) && std::fabs(LD(t)) <= 1024 && max_abs(a.translation()) <= small &&
      max_abs(b.translation()) <= small) {
    check(finite(I.matrix()), "SE3 interpolate (t, translations within the limits) is finite", ty, input);
    // A rigid motion: checked construction accepts it.
    Worst::instance().update("SE3 interpolate: rotation defect (eps)", ty,
                             rotation_defect(I.rotation().matrix()) / eps<T>());
    check(chasles::SE3<T>::from_matrix(I.matrix()).has_value(), "SE3 interpolate: from_matrix accepts the result", ty,
          input);
    if (t == T(0)) check(identical(I.matrix(), a.matrix()), "SE3 interpolate(a, b, 0) = a exactly", ty, input);
    // a^-1 b and a exp(...) form b's translation from a's: the scale of both
    // (test_group_laws.cpp).
    const LD scale = max_abs(a.translation()) + max_abs(b.translation());
    if (t == T(1))
      check_le(motion_error<T>(I, b, scale), kChain, "SE3 interpolate(a, b, 1) - b (eps max(1,|p_a|+|p_b|))", ty,
               input);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  if (in.byte() & 1u) {
    fuzz<float>(in);
  } else {
    fuzz<double>(in);
  }
  return 0;
}
