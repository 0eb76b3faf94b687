// chasles: Euler angles, the 12 axis sequences, extrinsic and intrinsic, with
// scipy's meaning (scipy.spatial.transform.Rotation.from_euler / as_euler).
#pragma once

#include <cmath>
#include <utility>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "chasles/constants.hpp"
#include "chasles/detail/series.hpp"
#include "chasles/so3.hpp"

namespace chasles {

/// An Euler axis sequence, a value the compiler sees (a template argument).
///
/// Lowercase: extrinsic (fixed axes). `xyz` with angles (a, b, c) is
/// R = Rz(c) Ry(b) Rx(a): first about the fixed x, then the fixed y, then the
/// fixed z. Uppercase: intrinsic (moving axes). `XYZ` with angles (a, b, c)
/// is R = Rx(a) Ry(b) Rz(c): about x, then about the new y, then the newer z.
/// Extrinsic `ijk` with (a, b, c) is intrinsic `KJI` with (c, b, a).
/// Tait-Bryan sequences (three distinct axes) have the middle angle in
/// [-pi/2, pi/2], proper Euler sequences (first axis = last) in [0, pi]; the
/// other two angles are in [-pi, pi]. As scipy.
enum class EulerSequence {
  xyz,
  xzy,
  yxz,
  yzx,
  zxy,
  zyx,
  xyx,
  xzx,
  yxy,
  yzy,
  zxz,
  zyz,  // extrinsic
  XYZ,
  XZY,
  YXZ,
  YZX,
  ZXY,
  ZYX,
  XYX,
  XZX,
  YXY,
  YZY,
  ZXZ,
  ZYZ,  // intrinsic
};

/// Euler angles of a rotation, and whether the gimbal lock was hit.
template <typename Scalar>
struct EulerAngles {
  /// The three angles in radians, in the order of the sequence's letters.
  Eigen::Matrix<Scalar, 3, 1> angles;
  /// The first and third axes coincide to working precision (middle angle
  /// +-pi/2 for Tait-Bryan, 0 or pi for proper Euler): only their sum or
  /// difference is defined, and the third angle is set to zero, as scipy.
  bool gimbal_lock;
};

namespace detail {

/// The axes of a sequence: first, second and third letter (0, 1, 2 for x,
/// y, z) and whether it is extrinsic.
struct EulerAxes {
  int a0, a1, a2;
  bool extrinsic;
};

constexpr EulerAxes euler_axes(EulerSequence seq) noexcept {
  constexpr int table[12][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0},
                                {0, 1, 0}, {0, 2, 0}, {1, 0, 1}, {1, 2, 1}, {2, 0, 2}, {2, 1, 2}};
  const int n = static_cast<int>(seq);
  const int r = n % 12;
  return EulerAxes{table[r][0], table[r][1], table[r][2], n < 12};
}

/// M <- R_axis(t) M, R_axis the rotation by t about coordinate axis
/// `Axis`: with (Axis, p, q) cyclic, R e_p = c e_p + s e_q and
/// R e_q = -s e_p + c e_q, so rows p and q of M mix (12 multiplications).
/// Entries that are zero in both rows stay exactly zero: a product built at
/// the gimbal lock has its lock pair exactly cos(fl(pi/2)) times the rest.
template <int Axis, typename Scalar>
inline void rotate_rows(Eigen::Matrix<Scalar, 3, 3>& M, const Scalar& t) noexcept {
  using std::cos;
  using std::sin;
  constexpr int p = (Axis + 1) % 3, q = (Axis + 2) % 3;
  const Scalar c = cos(t), s = sin(t);
  for (int j = 0; j < 3; ++j) {
    const Scalar mp = M(p, j), mq = M(q, j);
    M(p, j) = c * mp - s * mq;
    M(q, j) = s * mp + c * mq;
  }
}

/// Intrinsic Euler angles (t1, t2, t3) of R = R_I(t1) R_J(t2) R_C(t3), with
/// C = I (proper Euler) or C = K = 3 - I - J (Tait-Bryan).
///
/// Robust everywhere, the gimbal lock included (after Shoemake, "Euler
/// angle conversion", Graphics Gems IV, and Day, "Converting a rotation
/// matrix to Euler angles and back", 2014): one outer angle from the atan2
/// of a pair of entries whose norm is |cos t2| (Tait-Bryan) or |sin t2|
/// (proper), the other outer angle from the atan2 of a pair combined with
/// the first angle's (cos, sin), so that R_I(t1) R_J(t2) R_C(t3) reproduces
/// R to rounding however ill-determined t1 and t3 are separately; the middle
/// angle from the atan2 of the pair's norm and one entry (never asin or acos
/// of one entry). With s = +1 if (I, J, K) is cyclic, else -1, the rows and
/// columns used are (derived from R_J(t) e_K = cos t e_K + s sin t e_I and
/// its cyclic shifts):
///   Tait-Bryan: R(I,:) = (c2 c3, -s c2 s3, s s2),  R(:,K) = (s s2, -s s1 c2, c1 c2);
///   proper:     R(I,:) = (c2, s2 s3, s s2 c3),     R(:,I) = (c2, s1 s2, -s c1 s2)
/// (indexed I, J, K). ZeroFirst picks which outer angle is read directly
/// and set to zero at the lock: the third (intrinsic, as scipy) or the first
/// (the third of the extrinsic sequence, read reversed). The lock is a pair
/// of norm at most eps (constants.hpp, euler_lock2).
template <int I, int J, bool Proper, bool ZeroFirst, typename Scalar>
inline EulerAngles<Scalar> intrinsic_euler(const Eigen::Matrix<Scalar, 3, 3>& R) noexcept {
  using std::sqrt;
  constexpr int K = 3 - I - J;
  const Scalar s((J - I + 3) % 3 == 1 ? 1 : -1);
  // The pair read directly, (cos, sin) of the outer angle times a norm h.
  Scalar a, b;
  if constexpr (Proper) {
    if constexpr (ZeroFirst) {
      a = -s * R(K, I), b = R(J, I);
    } else {
      a = s * R(I, K), b = R(I, J);
    }
  } else {
    if constexpr (ZeroFirst) {
      a = R(K, K), b = -s * R(J, K);
    } else {
      a = R(I, I), b = -s * R(I, J);
    }
  }
  const Scalar h2 = a * a + b * b;
  EulerAngles<Scalar> out;
  out.gimbal_lock = h2 <= Scalar(ThresholdsOf<Scalar>::euler_lock2);
  Scalar direct(0), c(1), sn(0), h(0);
  if (!out.gimbal_lock) {
    h = sqrt(h2);
    direct = detail::arctan2<Scalar>(b, a);
    c = a / h;  // (cos, sin) of the angle read directly: no sin/cos call
    sn = b / h;
  } else if (h2 > Scalar(0)) {
    h = sqrt(h2);  // only for the middle angle's last ulp; never sqrt(0)
  }
  // The other outer angle, from R with the direct one removed.
  Scalar other;
  if constexpr (Proper) {
    if constexpr (ZeroFirst) {  // row J of R_I(t1)^T R = (., c3, -s s3)
      other = detail::arctan2<Scalar>(-s * c * R(J, K) - sn * R(K, K), c * R(J, J) + s * sn * R(K, J));
    } else {  // column J of R R_I(t3)^T = (., c1, s s1)
      other = detail::arctan2<Scalar>(s * c * R(K, J) - sn * R(K, K), c * R(J, J) - s * sn * R(J, K));
    }
    out.angles[1] = detail::arctan2<Scalar>(h, R(I, I));
  } else {
    if constexpr (ZeroFirst) {  // row J of R_I(t1)^T R = row J of R_K(t3) = (s s3, c3, .)
      other = detail::arctan2<Scalar>(s * c * R(J, I) + sn * R(K, I), c * R(J, J) + s * sn * R(K, J));
    } else {  // column J of R R_K(t3)^T = column J of R_I(t1) = (., c1, s s1)
      other = detail::arctan2<Scalar>(s * c * R(K, J) + sn * R(K, I), c * R(J, J) + s * sn * R(J, I));
    }
    out.angles[1] = detail::arctan2<Scalar>(s * R(I, K), h);
  }
  out.angles[0] = ZeroFirst ? direct : other;
  out.angles[2] = ZeroFirst ? other : direct;
  return out;
}

}  // namespace detail

/// The rotation of Euler angles in sequence Seq (radians): for intrinsic
/// `ABC`, R = R_A(angles[0]) R_B(angles[1]) R_C(angles[2]); for extrinsic
/// `abc`, R = R_c(angles[2]) R_b(angles[1]) R_a(angles[0]). Any finite
/// angles (no range restriction). The product of the three elementary
/// rotations, as row operations (36 multiplications, 3 sin/cos pairs),
/// each entry to a few ulps; at the lock (middle angle fl(pi/2), 0 or
/// fl(pi)) the entries that as_euler reads for the lock are those of the
/// exact product, cos(fl(pi/2)) = 6e-17 or sin(fl(pi)) = 1.2e-16 times the
/// rest, so that as_euler reports the lock of angles given at the lock.
template <EulerSequence Seq, typename Scalar>
inline SO3<Scalar> from_euler(const Eigen::Matrix<Scalar, 3, 1>& angles) noexcept {
  constexpr detail::EulerAxes ax = detail::euler_axes(Seq);
  Eigen::Matrix<Scalar, 3, 3> R = Eigen::Matrix<Scalar, 3, 3>::Identity();
  if constexpr (ax.extrinsic) {  // R_c(t3) (R_b(t2) (R_a(t1) I))
    detail::rotate_rows<ax.a0>(R, angles[0]);
    detail::rotate_rows<ax.a1>(R, angles[1]);
    detail::rotate_rows<ax.a2>(R, angles[2]);
  } else {  // R_A(t1) (R_B(t2) (R_C(t3) I))
    detail::rotate_rows<ax.a2>(R, angles[2]);
    detail::rotate_rows<ax.a1>(R, angles[1]);
    detail::rotate_rows<ax.a0>(R, angles[0]);
  }
  return SO3<Scalar>::from_matrix_unchecked(R);
}

/// Euler angles of R in sequence Seq, in radians, with scipy's ranges
/// (middle angle in [-pi/2, pi/2] for Tait-Bryan, [0, pi] for proper Euler,
/// the others in [-pi, pi]) and scipy's choice at the gimbal lock: the third
/// angle zero. from_euler<Seq>(as_euler<Seq>(R)) reproduces R to a few ulps
/// for every rotation, at and next to the lock too (detail::intrinsic_euler).
template <EulerSequence Seq, typename Scalar>
inline EulerAngles<Scalar> as_euler(const SO3<Scalar>& R) noexcept {
  constexpr detail::EulerAxes ax = detail::euler_axes(Seq);
  constexpr bool proper = ax.a0 == ax.a2;
  if constexpr (ax.extrinsic) {
    // Extrinsic abc with (t1, t2, t3) is intrinsic CBA with (t3, t2, t1);
    // scipy's zero goes on t3, the first intrinsic angle.
    EulerAngles<Scalar> e = detail::intrinsic_euler<ax.a2, ax.a1, proper, true>(R.matrix());
    const Scalar first = e.angles[0];
    e.angles[0] = e.angles[2];
    e.angles[2] = first;
    return e;
  } else {
    return detail::intrinsic_euler<ax.a0, ax.a1, proper, false>(R.matrix());
  }
}

namespace detail {

/// The 24 instances of from_euler and as_euler, in the order of EulerSequence.
template <typename Scalar>
struct EulerTable {
  SO3<Scalar> (*from[24])(const Eigen::Matrix<Scalar, 3, 1>&) noexcept;
  EulerAngles<Scalar> (*as[24])(const SO3<Scalar>&) noexcept;
};

template <typename Scalar, int... N>
constexpr EulerTable<Scalar> euler_table(std::integer_sequence<int, N...>) noexcept {
  return {{&from_euler<static_cast<EulerSequence>(N), Scalar>...},
          {&as_euler<static_cast<EulerSequence>(N), Scalar>...}};
}

template <typename Scalar>
inline constexpr EulerTable<Scalar> kEulerTable = euler_table<Scalar>(std::make_integer_sequence<int, 24>());

}  // namespace detail

/// from_euler with the sequence known at run time (read from a file, or
/// scipy's string): one indirect call to the instance of `seq`.
template <typename Scalar>
inline SO3<Scalar> from_euler(EulerSequence seq, const Eigen::Matrix<Scalar, 3, 1>& angles) noexcept {
  return detail::kEulerTable<Scalar>.from[static_cast<int>(seq)](angles);
}

/// as_euler with the sequence known at run time.
template <typename Scalar>
inline EulerAngles<Scalar> as_euler(EulerSequence seq, const SO3<Scalar>& R) noexcept {
  return detail::kEulerTable<Scalar>.as[static_cast<int>(seq)](R);
}

/// Roll, pitch, yaw (URDF's `rpy`, ROS tf's getRPY / setRPY): about the fixed
/// x, y and z axes in that order, R = Rz(yaw) Ry(pitch) Rx(roll), i.e.
/// from_euler<EulerSequence::xyz>((roll, pitch, yaw)).
template <typename Scalar>
inline SO3<Scalar> from_rpy(const Scalar& roll, const Scalar& pitch, const Scalar& yaw) noexcept {
  return from_euler<EulerSequence::xyz>(Eigen::Matrix<Scalar, 3, 1>(roll, pitch, yaw));
}

/// (roll, pitch, yaw) of R: as_euler<EulerSequence::xyz>(R); pitch in
/// [-pi/2, pi/2], at the lock (pitch +-pi/2) yaw is zero.
template <typename Scalar>
inline EulerAngles<Scalar> as_rpy(const SO3<Scalar>& R) noexcept {
  return as_euler<EulerSequence::xyz>(R);
}

}  // namespace chasles
