// chasles: the spatial inertia of a rigid body, the map from its twist to
// its momentum wrench (Murray, Li and Sastry, ch. 4.2; Lynch and Park,
// "Modern Robotics", ch. 8.2; Featherstone, "Rigid Body Dynamics
// Algorithms", ch. 2.13), in chasles' order: twists (v, w), wrenches (f, tau).
#pragma once

#include <algorithm>
#include <cmath>
#include <type_traits>

#include <Eigen/Cholesky>
#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/se3.hpp"
#include "chasles/so3.hpp"
#include "chasles/twist.hpp"
#include "chasles/wrench.hpp"

namespace chasles {

/// The inertia of a rigid body described in some frame: its mass m, the
/// position c of its center of mass and its rotational inertia I_c about the
/// center of mass (3x3 symmetric), both in that frame.
///
/// Its 6x6 matrix in the twist order (v, w), so that the momentum of the body
/// moving with the twist V = (v, w) of that frame is the wrench
/// h = G V = (f, tau) (linear momentum first, angular momentum about the
/// frame's origin second) and its kinetic energy is T = 1/2 V^T G V:
///
///   G = [[ m 1,     -m [c]           ],
///        [ m [c],    I_c - m [c]^2   ]]
///
/// (the center of mass moves with v_c = v + w x c = v - [c] w, so
/// f = m v_c and tau = I_c w + c x f = m [c] v + (I_c - m [c][c]) w; note
/// -[c]^2 = [c]^T [c], the parallel-axis term). Featherstone writes the same
/// matrix in the order (w, v) (RBDA eq. 2.63).
///
/// The same body described in frame a, given in frame b and g = g_ab:
/// c_a = R c_b + p, I_a = R I_b R^T, and G_a = Ad_g^-T G_b Ad_g^-1, so that
/// the kinetic energy 1/2 V^T G V is the same in both frames.
///
/// No invariant is enforced by construction (C++ cannot throw): a body is
/// physical when `is_physical()` holds. Inertias that are not are accepted
/// here, by Chain, the dynamics and the URDF loaders (real descriptions have
/// them: 56 of the 1,985 <inertia> elements of the example-robot-data
/// package's URDF files break the triangle inequality);
/// forward_dynamics reports a mass matrix they leave not positive
/// definite (DynamicsStatus).
template <typename Scalar_>
class SpatialInertia {
 public:
  using Scalar = Scalar_;
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  using Matrix3 = Eigen::Matrix<Scalar, 3, 3>;
  using Vector6 = Eigen::Matrix<Scalar, 6, 1>;
  using Matrix6 = Eigen::Matrix<Scalar, 6, 6>;

  /// The body of zero mass and inertia (the neutral element of `+`).
  SpatialInertia() noexcept : m_(0), c_(Vector3::Zero()), I_(Matrix3::Zero()) {}
  /// From the mass m, the center of mass c and the rotational inertia I_c
  /// about the center of mass (taken as given: see `is_physical`).
  SpatialInertia(const Scalar& mass, const Vector3& com, const Matrix3& inertia) noexcept
      : m_(mass), c_(com), I_(inertia) {}

  const Scalar& mass() const noexcept { return m_; }
  const Vector3& com() const noexcept { return c_; }
  /// I_c, the rotational inertia about the center of mass.
  const Matrix3& inertia() const noexcept { return I_; }

  /// G (6x6, order (v, w)): see the class comment.
  Matrix6 matrix() const noexcept {
    Matrix6 G;
    const Matrix3 C = SO3<Scalar>::hat(c_);
    G.template topLeftCorner<3, 3>() = m_ * Matrix3::Identity();
    G.template topRightCorner<3, 3>() = -m_ * C;
    G.template bottomLeftCorner<3, 3>() = m_ * C;
    // I_c - m [c]^2 = I_c + m (|c|^2 1 - c c^T): the parallel-axis form,
    // exactly symmetric when I_c is (c_i c_j = c_j c_i; [c]^2 by a matrix
    // product need not be, once the compiler fuses or reorders its sums).
    G.template bottomRightCorner<3, 3>() = I_ + m_ * (c_.squaredNorm() * Matrix3::Identity() - c_ * c_.transpose());
    return G;
  }

  /// The inverse of `matrix()` on matrices of that form: m = G(0, 0),
  /// c from the antisymmetric part of the lower-left block m [c], and
  /// I_c = G_ww + m [c]^2 (symmetrized). Taken as given, like the unchecked
  /// constructors of the groups. A massless body (m = 0: G = [[0, 0], [0,
  /// I_c]], whatever c) gets c = 0, so that the zero matrix gives back
  /// SpatialInertia(), not a NaN center of mass.
  static SpatialInertia from_matrix_unchecked(const Matrix6& G) noexcept {
    const Scalar m = G(0, 0);
    const Matrix3 mC = G.template bottomLeftCorner<3, 3>();
    const bool massless = !(m > Scalar(0) || m < Scalar(0));  // m == 0 (-Wfloat-equal)
    const Vector3 c = massless ? Vector3(Vector3::Zero()) : Vector3(SO3<Scalar>::vee(mC) / m);
    const Matrix3 C = SO3<Scalar>::hat(c);
    const Matrix3 Iww = G.template bottomRightCorner<3, 3>();
    const Matrix3 I = Iww + m * (C * C);
    return SpatialInertia(m, c, Matrix3((I + I.transpose()) / Scalar(2)));
  }

  /// The momentum wrench h = G V = (m (v - c x w), I_c w' + c x m (v - c x w))
  /// with w' = w (the angular momentum about the origin), computed without
  /// forming G.
  Wrench<Scalar> momentum(const Twist<Scalar>& V) const noexcept {
    const Vector3 f = m_ * (V.linear() - c_.cross(V.angular()));  // m v_c
    return Wrench<Scalar>(f, Vector3(I_ * V.angular() + c_.cross(f)));
  }

  /// T = 1/2 V . (G V) = 1/2 (m |v_c|^2 + w . I_c w).
  Scalar kinetic_energy(const Twist<Scalar>& V) const noexcept {
    const Vector3 vc = V.linear() - c_.cross(V.angular());
    return (m_ * vc.squaredNorm() + V.angular().dot(I_ * V.angular())) / Scalar(2);
  }

  /// The same body described in frame a, this one describing it in frame
  /// b, g = g_ab: (m, R c + p, R I_c R^T); its matrix is Ad_g^-T G Ad_g^-1.
  SpatialInertia transform(const SE3<Scalar>& g) const noexcept {
    const Matrix3& R = g.rotation().matrix();
    // Coefficient by coefficient: R is often a product just stored (the
    // chain's pass; detail::product3). R I_c R^T is formed as the upper
    // triangle of (R I_c) R^T, mirrored: exactly symmetric, 45 products.
    const Matrix3 A = detail::product3(R, I_);
    Matrix3 I;
    for (int i = 0; i < 3; ++i)
      for (int j = i; j < 3; ++j) I(j, i) = I(i, j) = A(i, 0) * R(j, 0) + A(i, 1) * R(j, 1) + A(i, 2) * R(j, 2);
    Vector3 c;
    for (int i = 0; i < 3; ++i) c(i) = R(i, 0) * c_(0) + R(i, 1) * c_(1) + R(i, 2) * c_(2) + g.translation()(i);
    return SpatialInertia(m_, c, I);
  }
  /// The same body described in frame b, this one describing it in frame
  /// a, g = g_ab: (m, R^T (c - p), R^T I_c R); transform(g.inverse()).
  SpatialInertia transform_inv(const SE3<Scalar>& g) const noexcept {
    const Matrix3& R = g.rotation().matrix();
    return SpatialInertia(m_, Vector3(R.transpose() * (c_ - g.translation())), Matrix3(R.transpose() * I_ * R));
  }

  /// The inertia of the two bodies rigidly joined (both described in the
  /// same frame): masses add, the center of mass is the weighted mean, and
  /// the rotational inertias about it add with their parallel-axis terms
  /// (the matrices G add).
  SpatialInertia operator+(const SpatialInertia& o) const noexcept {
    const Scalar m = m_ + o.m_;
    const Vector3 c = (m_ * c_ + o.m_ * o.c_) / m;
    const Vector3 d1 = c_ - c, d2 = o.c_ - c;
    const Matrix3 D1 = SO3<Scalar>::hat(d1), D2 = SO3<Scalar>::hat(d2);
    return SpatialInertia(m, c, Matrix3(I_ + o.I_ - m_ * (D1 * D1) - o.m_ * (D2 * D2)));
  }

  /// |I_c - I_c^T|_max, the asymmetry of the rotational inertia.
  Scalar symmetry_defect() const noexcept { return (I_ - I_.transpose()).cwiseAbs().maxCoeff(); }

  /// Whether the numbers describe a rigid body: m > 0 and finite, c finite,
  /// I_c symmetric (asymmetry at most `tolerance` times its largest entry),
  /// positive definite, and its principal moments satisfying the triangle
  /// inequality I_1 + I_2 >= I_3 (to `tolerance` times the trace).
  ///
  /// The triangle inequality is checked on the second moment of the mass
  /// distribution Sigma = 1/2 tr(I_c) 1 - I_c = integral of rho r r^T, whose
  /// eigenvalues are (I_j + I_k - I_i) / 2: it holds if and only if Sigma is
  /// positive semidefinite (Traversaro, Brossette, Escande and Nori,
  /// "Identification of fully physical consistent inertial parameters", 2016,
  /// sec. III). Both definiteness checks are Cholesky factorizations (3x3,
  /// no allocation).
  bool is_physical(const RealOf<Scalar>& tolerance = ThresholdsOf<Scalar>::inertia_tolerance) const noexcept {
    using std::isfinite;
    const RealOf<Scalar> m = detail::real_value(m_);
    if (!(m > 0) || !isfinite(m)) return false;
    Eigen::Matrix<RealOf<Scalar>, 3, 3> I;
    for (int i = 0; i < 3; ++i) {
      if (!isfinite(detail::real_value(c_[i]))) return false;
      for (int j = 0; j < 3; ++j) {
        I(i, j) = detail::real_value(I_(i, j));
        if (!isfinite(I(i, j))) return false;
      }
    }
    // Every condition is invariant under scaling: I / max |I_ij| has entries
    // of magnitude <= 1, so no sum below overflows (I near the largest
    // finite value) and none underflows to 0 before the comparisons.
    const RealOf<Scalar> scale = I.cwiseAbs().maxCoeff();
    if (!(scale > 0)) return false;
    I /= scale;
    if (!((I - I.transpose()).cwiseAbs().maxCoeff() <= tolerance)) return false;
    const Eigen::Matrix<RealOf<Scalar>, 3, 3> Is = (I + I.transpose()) / RealOf<Scalar>(2);
    if (Eigen::LLT<Eigen::Matrix<RealOf<Scalar>, 3, 3>>(Is).info() != Eigen::Success) return false;
    const RealOf<Scalar> trace = Is.trace();
    const Eigen::Matrix<RealOf<Scalar>, 3, 3> Sigma =
        (trace / 2 + tolerance * trace) * Eigen::Matrix<RealOf<Scalar>, 3, 3>::Identity() - Is;
    return Eigen::LLT<Eigen::Matrix<RealOf<Scalar>, 3, 3>>(Sigma).info() == Eigen::Success;
  }

  template <typename NewScalar>
  SpatialInertia<NewScalar> cast() const noexcept {
    return SpatialInertia<NewScalar>(NewScalar(m_), c_.template cast<NewScalar>(), I_.template cast<NewScalar>());
  }

  /// max of |differences| of m, c and I_c <= tol * max(1, their largest magnitude).
  bool is_approx(const SpatialInertia& other, const RealOf<Scalar>& tol) const noexcept {
    using std::abs;
    using std::max;
    const RealOf<Scalar> scale =
        max({RealOf<Scalar>(1), detail::real_value(abs(m_)), detail::real_value(abs(other.m_)),
             detail::real_value(c_.cwiseAbs().maxCoeff()), detail::real_value(other.c_.cwiseAbs().maxCoeff()),
             detail::real_value(I_.cwiseAbs().maxCoeff()), detail::real_value(other.I_.cwiseAbs().maxCoeff())});
    const RealOf<Scalar> diff =
        max({detail::real_value(abs(m_ - other.m_)), detail::real_value((c_ - other.c_).cwiseAbs().maxCoeff()),
             detail::real_value((I_ - other.I_).cwiseAbs().maxCoeff())});
    return diff <= tol * scale;
  }

 private:
  Scalar m_;
  Vector3 c_;
  Matrix3 I_;
};

using SpatialInertiaf = SpatialInertia<float>;
using SpatialInertiad = SpatialInertia<double>;

}  // namespace chasles
