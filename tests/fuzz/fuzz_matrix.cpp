// Fuzz target: arbitrary 3x3 and 4x4 matrices given to the three
// from-matrix forms (unchecked, checked, projected) of SO3 and SE3, and to
// log and quaternion through the unchecked form, in float and double.
//
// Input: byte 0 picks the scalar type (bit 0 set: float); then 16 raw T
// values, row by row: the 4x4 G, whose top-left block is the 3x3 M.
//
// Properties (every input; tolerances and domains in fuzz_support.hpp):
// - SO3::from_matrix(M) accepts M (returning it unchanged) when its long
//   double defect is below sqrt(eps), refuses it when above, beyond the
//   rounding margin of check_checked_so3, and refuses non-finite M; the same
//   for SE3::from_matrix(G) with the bottom row;
// - from_matrix_projected(M), M finite: finite, a rotation to kProj eps, and
//   the nearest one: tr(P^T M) reaches the largest eigenvalue of Horn's N(M)
//   (long double) to kProj eps sum |M_ij|; M not finite: the identity;
//   SE3::from_matrix_projected(G): that rotation and G's translation column,
//   bit for bit, whatever the bottom row;
// - log and quaternion of the unchecked M, M finite: finite, log's angle in
//   [0, pi], and the theta^2 the SO3 log hands to the SE3 log is |w|^2;
//   SE3 log of the unchecked G (its bottom row is not read), M and
//   p finite with |p_i| <= translation_limit(): finite, angle in [0, pi].
#include <cstddef>
#include <cstdint>

#include <chasles/se3.hpp>
#include <chasles/so3.hpp>

#include "fuzz_support.hpp"
#include "properties.hpp"

namespace {

using namespace chasles_fuzz;

template <typename T>
void fuzz(Bytes& in) {
  using SO3 = chasles::SO3<T>;
  using SE3 = chasles::SE3<T>;
  const char* ty = type_name<T>();
  const Mat4<T> G = in.matrix<T, 4>();
  const Mat3<T> M = G.template topLeftCorner<3, 3>();
  const Vec3<T> p = G.template topRightCorner<3, 1>();
  const auto input = [&] { return "G = " + str(G); };

  check_checked_so3<T>(M, ty, input);
  check_checked_se3<T>(G, ty, input);

  // Projection.
  const Mat3<T> P = SO3::from_matrix_projected(M).matrix();
  if (finite(M)) {
    check(finite(P), "from_matrix_projected of a finite M is finite", ty, input);
    check_le(rotation_defect(P) / eps<T>(), kProj, "from_matrix_projected: rotation defect (eps)", ty, input);
    const LD trace = (P.template cast<LD>().transpose() * M.template cast<LD>()).trace();
    const LD sum = M.template cast<LD>().cwiseAbs().sum();
    if (sum > 0)
      check_le((best_trace(M) - trace) / (eps<T>() * sum), kProj,
               "projection: max tr(R^T M) - tr(P^T M) (eps sum |M_ij|)", ty, input);
  } else {
    check(identical(P, Mat3<T>::Identity()), "from_matrix_projected of a non-finite M is the identity", ty, input);
  }
  const SE3 Gp = SE3::from_matrix_projected(G);
  check(same_bits<T, 3, 3>(Gp.rotation().matrix(), P) && same_bits<T, 3, 1>(Gp.translation(), p),
        "SE3::from_matrix_projected: projected block and the translation column as given", ty, input);

  // log and quaternion of whatever the unchecked form holds.
  const SO3 U = SO3::from_matrix_unchecked(M);
  const Vec3<T> w = U.log();
  const Eigen::Quaternion<T> q = U.quaternion();
  if (finite(M)) {
    check_log_angle<T>(w, ty, input);
    check(finite(q.coeffs()), "quaternion of a finite matrix is finite", ty, input);
    // What the SE3 log reuses from the SO3 log: theta^2 = |w|^2 (So3Log).
    // Both come from the same theta/2 = h: theta^2 = fl(4h h) (one rounding,
    // u = eps/2), w = fl(fl(2h / n) u_v) (two per component: 4u on |w|^2)
    // with n = fl(sqrt(fl(|u_v|^2))) (|u_v|^2 / n^2 within 5u): they differ
    // by at most 10u = 5 eps relative, to first order (the series branch,
    // theta^2 = f f |u_v|^2 against |f u_v|^2, by 7u). 6 eps covers the
    // second-order terms.
    const auto r = chasles::detail::so3_log<T>(M);
    const LD w2 = r.omega.template cast<LD>().squaredNorm();
    check_le(std::fabs(LD(r.theta2) - w2) / (eps<T>() * std::max(LD(1), w2)), 6,
             "so3 log: theta^2 - |w|^2 (eps max(1, |w|^2))", ty, input);
  }
  const Vec6<T> xi = SE3::from_matrix_unchecked(G).log();
  if (finite(Mat3<T>(M)) && finite(p) && max_abs(p) <= LD(translation_limit<T>())) {
    check(finite(xi), "SE3 log of a finite matrix (translation within the limit) is finite", ty, input);
    check_log_angle<T>(Vec3<T>(xi.template tail<3>()), ty, input);
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
