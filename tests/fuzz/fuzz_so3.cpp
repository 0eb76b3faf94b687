// Fuzz target: SO(3) exp, log, quaternion conversion both ways, checked and
// projecting construction of valid rotations, and interpolation, in float
// and double.
//
// Input: byte 0 picks the scalar type (bit 0 set: float) and a selector (the
// other bits: which column is reflected, which entry made non-finite); then
// raw T values: w (3), q (4, as w x y z), t (1).
//
// Properties (every input; tolerances and domains in fuzz_support.hpp):
// - exp(w), w finite: finite, a rotation (defect_bound of the exp
//   contract); below pi - kPiMargin
//   eps, log(exp(w)) = w; up to pi, its quaternion is +-(cos(theta/2),
//   sin(theta/2) w/theta) in long double;
// - from_quaternion(q): the identity for q = 0 or a non-finite q;
//   otherwise the long double rotation of q / |q|, and the quaternion of the
//   result is +-q / |q|;
// - every valid rotation above (and the interpolated one) passes
//   check_valid_rotation (log's angle in [0, pi], exp(log R) = R, quaternion
//   round trip, checked construction accepts it and refuses its reflections
//   and non-finite versions, projection keeps it);
// - interpolate(a, b, t), t finite, |t| <= max / 4 (so |t log(a^-1 b)| is
//   finite): a valid rotation as above (its defect is reported); exactly a
//   at t = 0; b to kChain eps at t = 1.
#include <cstddef>
#include <cstdint>

#include <chasles/so3.hpp>

#include "fuzz_support.hpp"
#include "properties.hpp"

namespace {

using namespace chasles_fuzz;

template <typename T>
void fuzz(Bytes& in, unsigned selector) {
  using SO3 = chasles::SO3<T>;
  const char* ty = type_name<T>();
  const Vec3<T> w = in.vector<T, 3>();
  const Vec4<T> qc = in.vector<T, 4>();
  const T t = in.scalar<T>();
  const auto input = [&] {
    return "w = " + str(w) + ", q (w x y z) = " + str(qc) + ", t = " + str(t) + ", selector " +
           std::to_string(selector);
  };

  // ---- exp ----
  const SO3 E = SO3::exp(w);
  const bool w_ok = finite(w);
  if (w_ok) {
    check(finite(E.matrix()), "exp of a finite w is finite", ty, input);
    check_le(rotation_defect(E.matrix()) / eps<T>(), defect_bound(exp_contract<T>()) / eps<T>(),
             "exp(w): rotation defect (eps)", ty, input);
    const LD theta = norm(w);
    if (theta < kPi - kPiMargin * eps<T>()) {
      const LD scale = std::max(LD(1), max_abs(w));
      check_le(max_abs_diff(E.log(), w) / (eps<T>() * scale), kExp, "log(exp(w)) - w, |w| < pi (eps)", ty, input);
    }
    if (theta <= kPi) {
      // exp(theta n) has the quaternion +-(cos(theta/2), sin(theta/2) n).
      Vec4<LD> ref(std::cos(theta / 2), 0, 0, 0);
      if (theta > 0) ref.template tail<3>() = (std::sin(theta / 2) / theta) * w.template cast<LD>();
      const Eigen::Quaternion<T> q = E.quaternion();
      const Vec4<LD> got(q.w(), q.x(), q.y(), q.z());
      check_le(std::min(max_abs_diff(got, ref), max_abs_diff(got, Vec4<LD>(-ref))) / eps<T>(), kExp,
               "quaternion(exp(w)) vs (cos, sin n), |w| <= pi (eps)", ty, input);
    }
    check_valid_rotation<T>(E, selector, ty, input);
  }

  // ---- from_quaternion ----
  const Eigen::Quaternion<T> q(qc[0], qc[1], qc[2], qc[3]);
  const SO3 Q = SO3::from_quaternion(q);
  const bool q_ok = finite(qc) && max_abs(qc) > 0;
  if (!q_ok) {
    check(identical(Q.matrix(), Mat3<T>::Identity()), "from_quaternion of zero or non-finite q is the identity", ty,
          input);
  } else {
    check(finite(Q.matrix()), "from_quaternion of a finite q is finite", ty, input);
    const Eigen::Matrix<LD, 3, 3> ref = rotation_of_quaternion(qc[0], qc[1], qc[2], qc[3]);
    check_le(error_in_eps<T>(Q.matrix(), ref), kExp, "from_quaternion(q) vs long double (eps)", ty, input);
    const Eigen::Quaternion<T> back = Q.quaternion();
    const LD n = norm(qc);
    const Vec4<LD> unit = qc.template cast<LD>() / n;
    const Vec4<LD> got(back.w(), back.x(), back.y(), back.z());
    check_le(std::min(max_abs_diff(got, unit), max_abs_diff(got, Vec4<LD>(-unit))) / eps<T>(), kExp,
             "quaternion(from_quaternion(q)) vs +-q/|q| (eps)", ty, input);
    check_valid_rotation<T>(Q, selector / 3, ty, input);
  }

  // ---- interpolation ----
  const SO3 a = q_ok ? Q : SO3::identity();
  const SO3 b = w_ok ? E : SO3::identity();
  const SO3 I = chasles::interpolate(a, b, t);
  if (std::isfinite(t) && std::fabs(LD(t)) <= LD(std::numeric_limits<T>::max()) / 4) {
    check(finite(I.matrix()), "interpolate with finite t is finite", ty, input);
    // A rotation: check_valid_rotation below has from_matrix accept it.
    Worst::instance().update("interpolate: rotation defect (eps)", ty, rotation_defect(I.matrix()) / eps<T>());
    if (t == T(0)) check(identical(I.matrix(), a.matrix()), "interpolate(a, b, 0) = a exactly", ty, input);
    if (t == T(1))
      check_le(error_in_eps<T>(I.matrix(), b.matrix()), kChain, "interpolate(a, b, 1) - b (eps)", ty, input);
    check_valid_rotation<T>(I, selector / 9, ty, input);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  const unsigned head = in.byte();
  if (head & 1u) {
    fuzz<float>(in, head >> 1);
  } else {
    fuzz<double>(in, head >> 1);
  }
  return 0;
}
