// chasles: Gaussians on a group, and how their covariances propagate
// through the group's operations, to first order.
//
// Convention: the right (local) perturbation of the Jacobians
// (lie_group.hpp): a Gaussian with mean M and covariance S (DoF x DoF, in
// the order of the group's tangent) is the distribution of
//   X = M exp(e),  e ~ N(0, S),
// the "concentrated Gaussian" of Barfoot and Furgale ("Associating
// Uncertainty With Three-Dimensional Poses for Use in Estimation
// Problems", IEEE T-RO 2014) written on the right, as Sola, Deray and
// Atchuthan ("A micro Lie theory for state estimation in robotics", 2018,
// section V.B) and manif write it. The left perturbation X = exp(e_l) M
// has e_l = Ad_M e, so S_l = Ad_M S Ad_M^T (left_covariance, from_left).
//
// Each operation f maps the perturbations linearly to first order,
// f(X) = f(M) exp(J e + o(e)), with J the operation's Jacobian
// (lie_group.hpp, jacobians.hpp), so the result is the Gaussian with mean
// f(M) and covariance J S J^T; for two operands, J_a S_a J_a^T +
// J_b S_b J_b^T + J_a C J_b^T + J_b C^T J_a^T, C = E[e_a e_b^T] their
// cross-covariance (zero when they are independent). First order is exact
// for the means' linear parts and accurate while the covariances are small
// against the curvature (angles well below a radian); tests/cpp/test_gaussian
// checks it against Monte Carlo at small and large uncertainty.
//
// Every operation is noexcept, allocation-free and of bounded cost, for
// every group and scalar (float, double, autodiff); sampling for float and
// double.
#pragma once

#include <cmath>

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/euler.hpp"
#include "chasles/jacobians.hpp"
#include "chasles/lie_group.hpp"
#include "chasles/random.hpp"

namespace chasles {

namespace detail {

/// L lower triangular with L L^T = A, for a symmetric positive semidefinite
/// A (its lower triangle is read): the Cholesky factorization, in which a
/// pivot at or below covariance_pivot_tolerance times A's largest diagonal
/// entry (constants.hpp) is a direction of zero variance: its column of L
/// is zero, so that a singular covariance (a coordinate held fixed) still
/// has a factor. A pivot below minus that tolerance (A not positive
/// semidefinite) makes the factor NaN.
template <typename Scalar, int N>
inline Eigen::Matrix<Scalar, N, N> psd_cholesky(const Eigen::Matrix<Scalar, N, N>& A) noexcept {
  using std::sqrt;
  Scalar top(0);
  for (int i = 0; i < N; ++i) top = A(i, i) > top ? A(i, i) : top;
  const Scalar floor = Scalar(ThresholdsOf<Scalar>::covariance_pivot_tolerance) * top;
  Eigen::Matrix<Scalar, N, N> L = Eigen::Matrix<Scalar, N, N>::Zero();
  for (int k = 0; k < N; ++k) {
    Scalar d = A(k, k);
    for (int j = 0; j < k; ++j) d -= L(k, j) * L(k, j);
    if (d < -floor) {
      L(k, k) = detail::quiet_nan<Scalar>();
      continue;
    }
    if (!(d > floor)) continue;  // zero variance: the column stays 0
    const Scalar l = sqrt(d);
    L(k, k) = l;
    for (int i = k + 1; i < N; ++i) {
      Scalar s = A(i, k);
      for (int j = 0; j < k; ++j) s -= L(i, j) * L(k, j);
      L(i, k) = s / l;
    }
  }
  return L;
}

/// J S J^T, symmetric to the last bit (the upper triangle copied from the
/// lower), for a covariance S and any Jacobian J.
template <typename JMatrix, typename SMatrix>
inline Eigen::Matrix<typename SMatrix::Scalar, JMatrix::RowsAtCompileTime, JMatrix::RowsAtCompileTime> congruence(
    const JMatrix& J, const SMatrix& S) noexcept {
  constexpr int R = JMatrix::RowsAtCompileTime;
  const Eigen::Matrix<typename SMatrix::Scalar, R, SMatrix::ColsAtCompileTime> JS = J * S;
  Eigen::Matrix<typename SMatrix::Scalar, R, R> out;
  for (int j = 0; j < R; ++j)
    for (int i = j; i < R; ++i) out(i, j) = out(j, i) = JS.row(i).dot(J.row(j));
  return out;
}

}  // namespace detail

/// A Gaussian on R^n, mean and covariance: what the action of a Gaussian on
/// a point gives (the point's mean and covariance), and its log (the
/// tangent's).
template <typename Scalar, int N>
struct VectorGaussian {
  Eigen::Matrix<Scalar, N, 1> mean;
  Eigen::Matrix<Scalar, N, N> cov;
};

/// A Gaussian on the group G: X = mean exp(e), e ~ N(0, cov), cov in the
/// order of G's tangent ((v, w) for SE(3), (v, w, sigma) for Sim(3), ...).
/// The covariance is not checked (symmetric positive semidefinite is the
/// caller's to keep; the Python package checks it).
template <typename G>
class Gaussian {
  static_assert(detail::IsLieGroup<G>::value, "Gaussian<G>: G must be a group of the library (SO3d, SE3d, ...)");

 public:
  using Group = G;
  using Scalar = typename G::Scalar;
  using Tangent = typename G::Tangent;
  using Covariance = typename G::AdjointMatrix;
  static constexpr int DoF = G::DoF;

  /// The identity with zero covariance.
  Gaussian() noexcept : mean_(), cov_(Covariance::Zero()) {}
  Gaussian(const G& mean, const Covariance& cov) noexcept : mean_(mean), cov_(cov) {}
  /// From the covariance of the left perturbation X = exp(e_l) mean.
  static Gaussian from_left(const G& mean, const Covariance& left_cov) noexcept {
    const Covariance Ad_inv = mean.inverse().adjoint();
    return Gaussian(mean, detail::congruence(Ad_inv, left_cov));
  }

  const G& mean() const noexcept { return mean_; }
  const Covariance& cov() const noexcept { return cov_; }
  /// The covariance of the left perturbation: Ad_mean cov Ad_mean^T.
  Covariance left_covariance() const noexcept { return detail::congruence(mean_.adjoint(), cov_); }

  /// X^-1 = exp(-e) mean^-1 = mean^-1 exp(-Ad_mean e): mean^-1, Ad cov Ad^T.
  Gaussian inverse() const noexcept { return Gaussian(mean_.inverse(), left_covariance()); }

  /// X_a X_b for independent X_a (this) and X_b: mean_a mean_b, and
  /// Ad_{b^-1} cov_a Ad_{b^-1}^T + cov_b (compose_jacobians: J_b = I).
  Gaussian compose(const Gaussian& b) const noexcept {
    const auto J = compose_jacobians(mean_, b.mean_);
    return Gaussian(mean_ * b.mean_, Covariance(detail::congruence(J.lhs, cov_) + b.cov_));
  }
  /// The same with the cross-covariance cross = E[e_a e_b^T]: adds
  /// J_a cross + (J_a cross)^T.
  Gaussian compose(const Gaussian& b, const Covariance& cross) const noexcept {
    const auto J = compose_jacobians(mean_, b.mean_);
    return Gaussian(mean_ * b.mean_, with_cross(J.lhs, b, cross));
  }
  Gaussian operator*(const Gaussian& b) const noexcept { return compose(b); }

  /// X_a^-1 X_b (the relative motion from X_a, this, to X_b), independent:
  /// J_a = -Ad_{b^-1 a}, J_b = I (between_jacobians).
  Gaussian between(const Gaussian& b) const noexcept {
    const auto J = between_jacobians(mean_, b.mean_);
    return Gaussian(chasles::between(mean_, b.mean_), Covariance(detail::congruence(J.lhs, cov_) + b.cov_));
  }
  /// The same with the cross-covariance cross = E[e_a e_b^T].
  Gaussian between(const Gaussian& b, const Covariance& cross) const noexcept {
    const auto J = between_jacobians(mean_, b.mean_);
    return Gaussian(chasles::between(mean_, b.mean_), with_cross(J.lhs, b, cross));
  }

  /// The point X p for a point p known exactly: mean p, and J cov J^T with
  /// J = d(X p)/dX (act_jacobians).
  template <typename Point>
  auto act(const Eigen::MatrixBase<Point>& p) const noexcept {
    constexpr int N = Point::RowsAtCompileTime;
    const Eigen::Matrix<Scalar, N, 1> q = p;
    const auto J = act_jacobians(mean_, q);
    return VectorGaussian<Scalar, N>{Eigen::Matrix<Scalar, N, 1>(mean_.act(q)), detail::congruence(J.group, cov_)};
  }
  /// The same for an uncertain point (independent of X): adds R_p cov_p R_p^T,
  /// R_p = d(X p)/dp.
  template <typename Point, typename PointCov>
  auto act(const Eigen::MatrixBase<Point>& p, const Eigen::MatrixBase<PointCov>& point_cov) const noexcept {
    constexpr int N = Point::RowsAtCompileTime;
    const Eigen::Matrix<Scalar, N, 1> q = p;
    const Eigen::Matrix<Scalar, N, N> Sp = point_cov;
    const auto J = act_jacobians(mean_, q);
    return VectorGaussian<Scalar, N>{
        Eigen::Matrix<Scalar, N, 1>(mean_.act(q)),
        Eigen::Matrix<Scalar, N, N>(detail::congruence(J.group, cov_) + detail::congruence(J.point, Sp))};
  }

  /// log(X) = log(mean exp(e)) = log(mean) + J_r(log mean)^-1 e + o(e):
  /// the tangent Gaussian (log_jacobian).
  VectorGaussian<Scalar, DoF> log() const noexcept {
    return {mean_.log(), detail::congruence(log_jacobian(mean_), cov_)};
  }

  /// interpolate(X_a, X_b, t) = X_a exp(t log(X_a^-1 X_b)) for independent
  /// X_a (this) and X_b: with xi = rminus(b, a) and (J_g, J_x) the Jacobians
  /// of rplus(a, t xi), J_a = J_g + t J_x d(xi)/da and J_b = t J_x d(xi)/db
  /// (rplus_jacobians, rminus_jacobians).
  Gaussian interpolate(const Gaussian& b, const Scalar& t) const noexcept {
    const Tangent xi = rminus(b.mean_, mean_);
    const auto Jm = rminus_jacobians(b.mean_, mean_);
    const auto Jp = rplus_jacobians(mean_, Tangent(t * xi));
    const Covariance Ja = Jp.lhs + t * (Jp.rhs * Jm.rhs);
    const Covariance Jb = t * (Jp.rhs * Jm.lhs);
    return Gaussian(rplus(mean_, Tangent(t * xi)),
                    Covariance(detail::congruence(Ja, cov_) + detail::congruence(Jb, b.cov_)));
  }

  /// The squared Mahalanobis distance of X from the mean,
  /// e^T cov^-1 e with e = rminus(X, mean), through the Cholesky factor
  /// (psd_cholesky). It needs a positive definite covariance: NaN for a
  /// singular one (along a direction of zero variance no distance is
  /// defined: the rounding of rminus alone would put the mean itself at
  /// infinity) and for one that is not positive semidefinite.
  Scalar mahalanobis(const G& X) const noexcept {
    const Tangent e = rminus(X, mean_);
    const Covariance L = factor();
    Tangent y;
    Scalar d2(0);
    for (int k = 0; k < DoF; ++k) {
      if (!(L(k, k) > Scalar(0))) return detail::quiet_nan<Scalar>();  // zero or NaN
      Scalar s = e[k];
      for (int j = 0; j < k; ++j) s -= L(k, j) * y[j];
      y[k] = s / L(k, k);
      d2 += y[k] * y[k];
    }
    return d2;
  }

  /// L with L L^T = cov, lower triangular (detail::psd_cholesky).
  Covariance factor() const noexcept { return detail::psd_cholesky(cov_); }

  /// One sample mean exp(L z), z ~ N(0, I) drawn from gen (random_gaussian).
  /// It factors the covariance on each call: for many samples, take
  /// factor() once and call random_gaussian(gen, mean(), L).
  template <typename Generator>
  G sample(Generator& gen) const noexcept {
    return random_gaussian(gen, mean_, factor());
  }

 private:
  /// J_a cov_a J_a^T + cov_b + K + K^T, K = J_a cross: a composition's or
  /// a between's covariance (J_b = I) with correlated operands.
  Covariance with_cross(const Covariance& Ja, const Gaussian& b, const Covariance& cross) const noexcept {
    const Covariance K = Ja * cross;
    return Covariance(detail::congruence(Ja, cov_) + b.cov_ + K + K.transpose());
  }

  G mean_;
  Covariance cov_;
};

namespace detail {

/// <<A>> = -tr(A) I + A, for 3x3 A (Barfoot and Furgale 2014, eq. 46).
template <typename Scalar>
inline Eigen::Matrix<Scalar, 3, 3> bracket(const Eigen::Matrix<Scalar, 3, 3>& A) noexcept {
  return Eigen::Matrix<Scalar, 3, 3>(A - A.trace() * Eigen::Matrix<Scalar, 3, 3>::Identity());
}
/// <<A, B>> = <<A>> <<B>> + <<B A>>.
template <typename Scalar>
inline Eigen::Matrix<Scalar, 3, 3> bracket(const Eigen::Matrix<Scalar, 3, 3>& A,
                                           const Eigen::Matrix<Scalar, 3, 3>& B) noexcept {
  return Eigen::Matrix<Scalar, 3, 3>(bracket(A) * bracket(B) + bracket(Eigen::Matrix<Scalar, 3, 3>(B * A)));
}
/// <<S>> for a 6x6 covariance S = [[S_rr, S_rp], [S_rp^T, S_pp]] (translation
/// rows first): [[<<S_pp>>, <<S_rp + S_rp^T>>], [0, <<S_pp>>]].
template <typename Scalar>
inline Eigen::Matrix<Scalar, 6, 6> bracket6(const Eigen::Matrix<Scalar, 6, 6>& S) noexcept {
  using M3 = Eigen::Matrix<Scalar, 3, 3>;
  const M3 pp = bracket(M3(S.template bottomRightCorner<3, 3>()));
  const M3 rp = S.template topRightCorner<3, 3>();
  Eigen::Matrix<Scalar, 6, 6> A = Eigen::Matrix<Scalar, 6, 6>::Zero();
  A.template topLeftCorner<3, 3>() = pp;
  A.template topRightCorner<3, 3>() = bracket(M3(rp + rp.transpose()));
  A.template bottomRightCorner<3, 3>() = pp;
  return A;
}

}  // namespace detail

/// X_a X_b for independent Gaussians on SE(3), with the covariance to fourth
/// order in the perturbations: Barfoot and Furgale 2014, section III.C
/// (eqs. 53-55), written in the left perturbation, where with
/// S_1 = Ad_a S_a Ad_a^T and S_2 = Ad_ab S_b Ad_ab^T (the two left
/// covariances, S_b carried through a) the product's left covariance is
///   S_1 + S_2 + (A_1 S_2 + S_2 A_1^T + A_2 S_1 + S_1 A_2^T) / 12 + B / 4,
///   A_i = <<S_i>>,  B = [[B_rr, B_rp], [B_rp^T, B_pp]],
///   B_rr = <<S1_pp, S2_rr>> + <<S1_rp^T, S2_rp>> + <<S1_rp, S2_rp^T>> + <<S1_rr, S2_pp>>,
///   B_rp = <<S1_pp, S2_rp^T>> + <<S1_rp^T, S2_pp>>,  B_pp = <<S1_pp, S2_pp>>
/// (r: translation, p: rotation, chasles' (v, w) order), taken back to the
/// right perturbation. The first two terms are compose()'s first order;
/// the rest matters once the rotations' standard deviations reach a tenth
/// of a radian (test_gaussian: FourthOrderCompoundingOfLargeUncertainty).
template <typename Scalar>
inline Gaussian<SE3<Scalar>> compose_fourth_order(const Gaussian<SE3<Scalar>>& a,
                                                  const Gaussian<SE3<Scalar>>& b) noexcept {
  using M3 = Eigen::Matrix<Scalar, 3, 3>;
  using M6 = Eigen::Matrix<Scalar, 6, 6>;
  const SE3<Scalar> ab = a.mean() * b.mean();
  const M6 S1 = a.left_covariance();
  const M6 S2 = detail::congruence(ab.adjoint(), b.cov());
  const M6 A1 = detail::bracket6(S1), A2 = detail::bracket6(S2);
  const M3 S1rr = S1.template topLeftCorner<3, 3>(), S1rp = S1.template topRightCorner<3, 3>(),
           S1pp = S1.template bottomRightCorner<3, 3>();
  const M3 S2rr = S2.template topLeftCorner<3, 3>(), S2rp = S2.template topRightCorner<3, 3>(),
           S2pp = S2.template bottomRightCorner<3, 3>();
  const M3 Brr = detail::bracket(S1pp, S2rr) + detail::bracket(M3(S1rp.transpose()), S2rp) +
                 detail::bracket(S1rp, M3(S2rp.transpose())) + detail::bracket(S1rr, S2pp);
  const M3 Brp = detail::bracket(S1pp, M3(S2rp.transpose())) + detail::bracket(M3(S1rp.transpose()), S2pp);
  const M3 Bpp = detail::bracket(S1pp, S2pp);
  M6 B;
  B << Brr, Brp, Brp.transpose(), Bpp;
  const M6 K = A1 * S2 + A2 * S1;
  const M6 left = S1 + S2 + (K + K.transpose()) / Scalar(12) + B / Scalar(4);
  // B's blocks are symmetric only to the order kept: its symmetric part.
  return Gaussian<SE3<Scalar>>::from_left(ab, M6(Scalar(0.5) * (left + left.transpose())));
}

namespace detail {

/// J with (dp, d rpy) = J e to first order, for X = g exp(e) on SE(3):
/// dp = R v (the position's change in the fixed frame) and
/// d rpy = E^-1 R w, E the matrix of the fixed-axis roll, pitch, yaw rates
/// to the angular velocity in the fixed frame (R = Rz(y) Ry(p) Rx(r)):
///   E = [Rz(y) Ry(p) e_x, Rz(y) e_y, e_z]
///     = [[cy cp, -sy, 0], [sy cp, cy, 0], [-sp, 0, 1]],  det E = cp,
///   E^-1 = [[cy, sy, 0], [-sy cp, cy cp, 0], [cy sp, sy sp, cp]] / cp.
/// `inverse`: J^-1 = [[R^T, 0], [0, R^T E]] instead. NaN at the gimbal lock
/// (pitch +-pi/2), where the angles' rates are not defined (J only).
template <typename Scalar>
inline Eigen::Matrix<Scalar, 6, 6> ros_jacobian(const SE3<Scalar>& g, bool inverse) noexcept {
  using std::cos;
  using std::sin;
  using M3 = Eigen::Matrix<Scalar, 3, 3>;
  const EulerAngles<Scalar> rpy = as_rpy(g.rotation());
  const Scalar cp = cos(rpy.angles[1]), sp = sin(rpy.angles[1]), cy = cos(rpy.angles[2]), sy = sin(rpy.angles[2]);
  const M3 R = g.rotation().matrix();
  Eigen::Matrix<Scalar, 6, 6> J = Eigen::Matrix<Scalar, 6, 6>::Zero();
  if (inverse) {
    M3 E;
    E << cy * cp, -sy, Scalar(0), sy * cp, cy, Scalar(0), -sp, Scalar(0), Scalar(1);
    J.template topLeftCorner<3, 3>() = R.transpose();
    J.template bottomRightCorner<3, 3>() = R.transpose() * E;
    return J;
  }
  if (rpy.gimbal_lock) return Eigen::Matrix<Scalar, 6, 6>::Constant(detail::quiet_nan<Scalar>());
  M3 E_inv;
  E_inv << cy, sy, Scalar(0), -sy * cp, cy * cp, Scalar(0), cy * sp, sy * sp, cp;
  J.template topLeftCorner<3, 3>() = R;
  J.template bottomRightCorner<3, 3>() = (E_inv / cp) * R;
  return J;
}

}  // namespace detail

/// The covariance of ROS's geometry_msgs/PoseWithCovariance for a Gaussian
/// on SE(3): that of (x, y, z, roll, pitch, yaw), the position in the fixed
/// frame and the roll, pitch and yaw about the fixed axes (R = Rz(yaw)
/// Ry(pitch) Rx(roll), as_rpy), to first order (detail::ros_jacobian); the
/// message holds it row-major, 36 numbers. NaN at the gimbal lock (pitch
/// +-pi/2), where roll and yaw are not separate angles.
template <typename Scalar>
inline Eigen::Matrix<Scalar, 6, 6> to_ros_covariance(const Gaussian<SE3<Scalar>>& x) noexcept {
  return detail::congruence(detail::ros_jacobian(x.mean(), false), x.cov());
}

/// The Gaussian on SE(3) of a ROS pose with covariance: mean and the
/// covariance of (x, y, z, roll, pitch, yaw) (to_ros_covariance's inverse).
template <typename Scalar>
inline Gaussian<SE3<Scalar>> from_ros_covariance(const SE3<Scalar>& mean,
                                                 const Eigen::Matrix<Scalar, 6, 6>& ros_cov) noexcept {
  return Gaussian<SE3<Scalar>>(mean, detail::congruence(detail::ros_jacobian(mean, true), ros_cov));
}

}  // namespace chasles
