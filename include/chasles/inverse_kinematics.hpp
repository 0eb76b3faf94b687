// chasles: inverse kinematics of serial chains by damped least squares
// (Levenberg-Marquardt) on the body error twist.
//
// The error of a configuration q against a target pose T is the body error
//   e(q) = rminus(T, g(q)) = log(g(q)^-1 T)   (6, (v, w); zero at a solution),
// the twist that carries the tool frame g(q) onto T, in the tool frame. Its
// exact Jacobian (not only the manipulator Jacobian): moving the joints by
// dq moves the tool by g exp(J_b dq), so g^-1 T becomes
// exp(-J_b dq) exp(e) = exp(e - J_l(e)^-1 J_b dq + o(dq)) (the left Jacobian
// of SE(3), jacobians.hpp), and
//   de/dq = -J_l(e)^-1 J_b(q).
// Each iteration tries the damped Gauss-Newton (Levenberg-Marquardt) step
//   (J^T J + mu I) dq = -J^T e,
// with the joints at a limit that the step would push past held there (the
// step of the others solved again without them: an active set), projected
// onto the joint limits (q + dq clamped to [lower, upper]), and keeps it if
// the cost |e|^2 / 2 decreased. The damping mu follows Nielsen's
// rule (Madsen, Nielsen and Tingleff, "Methods for non-linear least squares
// problems", 2004, sec. 3.2): it starts at tau max(diag J^T J), shrinks
// after a step by max(1/3, 1 - (2 rho - 1)^3), rho the ratio of the actual
// decrease of the cost to the linear model's, and after a rejected step
// grows by nu = 2, 4, 8, ...: a short gradient-like step far from a
// solution or near a singular configuration, Gauss-Newton (quadratic
// convergence) close to a regular one; mu > 0 keeps the system positive
// definite at a singular configuration. An attempt stops with status
// no_progress at a local minimum of the cost, where a restart from another
// seed is the remedy: when the step falls below rounding (their test 2), or,
// when a restart remains, sooner: when the cost is above ik_stall_ratio
// (0.9) of what it was ik_stall_iterations (8) iterations before
// (constants.hpp: how they were chosen). A slow attempt may still
// converge, so the last attempt, or the only one, is not cut. (Their test
// 1, a gradient J^T e small against |J| |e|, is not used: near a singular
// configuration it holds at points that still converge.)
//
// Converged when |e_v| <= position_tolerance and |e_w| <= orientation_tolerance
// (e_v, e_w the linear and angular parts of e: for a small error, the
// position error in the tool frame, in the chain's length unit, and the
// rotation angle in radians). The cost is bounded: at most max_iterations
// iterations per attempt, each one or two n x n Cholesky factorizations
// (detail::cholesky_solve on the chain's fixed-capacity matrices: no
// allocation) and one body pass that gives the pose and the body Jacobian
// together (Chain::forward_body(q, J_b)); and, when options.max_time is finite, at
// most that many seconds of std::chrono::steady_clock for the whole call,
// restarts included (the clock is read before each iteration, so a call ends
// at most one iteration after its budget). The result says why it stopped
// (IKStatus) and counts the iterations of the attempt it returns, of all
// attempts, and the attempts.
#pragma once

#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>

#include <Eigen/Core>

#include "chasles/constants.hpp"
#include "chasles/detail/small_solve.hpp"
#include "chasles/jacobians.hpp"
#include "chasles/kinematics.hpp"
#include "chasles/se3.hpp"

namespace chasles {

/// Tolerances and bounds of inverse_kinematics. The defaults per scalar
/// type come from constants.hpp (ik_tolerance, ik_max_iterations).
template <typename Scalar>
struct IKOptions {
  /// |e_v| at a solution (the chain's length unit).
  Scalar position_tolerance = Scalar(ThresholdsOf<Scalar>::ik_tolerance);
  /// |e_w| at a solution (radians).
  Scalar orientation_tolerance = Scalar(ThresholdsOf<Scalar>::ik_tolerance);
  /// The bound on iterations per attempt (each one body pass: the pose and the body Jacobian).
  int max_iterations = ThresholdsOf<Scalar>::ik_max_iterations;
  /// The damping at the start, relative to the largest diagonal entry of
  /// J^T J (Madsen, Nielsen and Tingleff's tau). 1e-2: on TRAC-IK's
  /// protocol (bench/ik_protocols.py), from the middle of the limits (the
  /// UR5's is singular), 86% of the UR5's first attempts converge, against
  /// 59% with their 1e-3 (and 54% with 1e-4, 85% with 1e-1); the median
  /// solve takes 12 iterations, against 18.
  Scalar initial_damping = Scalar(1e-2);
  /// The time budget of the whole call, restarts included, in seconds of
  /// std::chrono::steady_clock. Infinite (the default), NaN or beyond
  /// max_time_unbounded: no budget, and the clock is never read.
  double max_time = std::numeric_limits<double>::infinity();
};

/// A budget of at least this many seconds (a year) is no budget: the
/// deadline now + max_time would overflow the clock's 64-bit nanoseconds
/// beyond 292 years.
constexpr double max_time_unbounded = 3.15e7;

/// Why inverse_kinematics stopped.
enum class IKStatus : int {
  converged = 0,        ///< |e_v| and |e_w| within their tolerances
  iteration_bound = 1,  ///< max_iterations iterations without converging
  time_budget = 2,      ///< options.max_time elapsed before a solution
  no_progress = 3,      ///< stalled at a local minimum of the cost, where a restart is the remedy
};

/// The outcome of inverse_kinematics.
template <typename ChainT>
struct IKResult {
  typename ChainT::JointVector q;  ///< the configuration returned (within the limits)
  IKStatus status;                 ///< why it stopped (see inverse_kinematics)
  bool converged;                  ///< status == IKStatus::converged
  int iterations;                  ///< iterations of the attempt that gave q (0: its seed, clamped, converged)
  int total_iterations;            ///< iterations of every attempt
  int attempts;                    ///< attempts made: 1 + the restarts taken
  Eigen::Matrix<typename ChainT::Scalar, 6, 1> error;  ///< e(q) = log(g(q)^-1 T), (v, w)
};

namespace detail {

/// de/dq = -J_l(e)^-1 J_b(q) (6 x n) at q, with e = pose_error and J_b(q)
/// already known: the formula of pose_error_jacobian, shared with the
/// iteration of inverse_kinematics (which has both at hand).
template <typename Jacobian, typename Scalar>
inline Jacobian pose_error_jacobian_at(const Eigen::Matrix<Scalar, 6, 1>& e, const Jacobian& jacobian_body) noexcept {
  return -(se3_left_jacobian_inverse(e) * jacobian_body);
}

template <typename Scalar>
inline bool ik_converged(const Eigen::Matrix<Scalar, 6, 1>& e, const IKOptions<Scalar>& o) noexcept {
  return e.template head<3>().squaredNorm() <= o.position_tolerance * o.position_tolerance &&
         e.template tail<3>().squaredNorm() <= o.orientation_tolerance * o.orientation_tolerance;
}

/// The end of a time budget: none (the clock never read) or a point of
/// std::chrono::steady_clock.
struct IKDeadline {
  using Clock = std::chrono::steady_clock;
  bool timed;
  Clock::time_point at;

  static IKDeadline after(double seconds) noexcept {
    if (!(seconds < max_time_unbounded)) return {false, {}};  // infinite, NaN, or beyond the clock's range
    const auto budget = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
    return {true, Clock::now() + budget};
  }
  bool passed() const noexcept { return timed && Clock::now() >= at; }
};

template <typename ChainT>
inline IKResult<ChainT> ik_result(const typename ChainT::JointVector& q, IKStatus status, int iterations,
                                  const Eigen::Matrix<typename ChainT::Scalar, 6, 1>& e) noexcept {
  return {q, status, status == IKStatus::converged, iterations, iterations, 1, e};
}

/// One attempt from q0 (the method at the top of this header), until the
/// deadline; cut short when it stalls if restart_remains.
template <typename ChainT, typename Derived>
inline IKResult<ChainT> ik_attempt(const ChainT& chain, const SE3<typename ChainT::Scalar>& target,
                                   const Eigen::MatrixBase<Derived>& q0, const typename ChainT::JointVector& lower,
                                   const typename ChainT::JointVector& upper,
                                   const IKOptions<typename ChainT::Scalar>& options, const IKDeadline& deadline,
                                   bool restart_remains) noexcept {
  using Scalar = typename ChainT::Scalar;
  using JointVector = typename ChainT::JointVector;
  using Vector6 = Eigen::Matrix<Scalar, 6, 1>;
  constexpr int N = ChainT::JointsAtCompileTime, MaxN = ChainT::MaxJointsAtCompileTime;
  using Normal = Eigen::Matrix<Scalar, N, N, Eigen::ColMajor, MaxN, MaxN>;
  const Eigen::Index n = chain.n_joints();
  CHASLES_ASSERT(q0.size() == n && lower.size() == n && upper.size() == n);

  const auto half_squared = [](const Vector6& e) -> Scalar { return e.squaredNorm() / Scalar(2); };

  using Jacobian = typename ChainT::Jacobian;
  JointVector q = q0.template cast<Scalar>().cwiseMax(lower).cwiseMin(upper);
  Jacobian J_b(6, n), J_b_trial(6, n);  // the body Jacobians at q and at the trial
  Vector6 e = rminus(target, chain.forward_body(q, J_b));
  Scalar cost = half_squared(e);
  Normal JtJ(n, n);
  JointVector gradient(n);  // J^T e, the gradient of cost = |e|^2 / 2
  const auto linearize = [&] {
    // J = de/dq = -J_l(e)^-1 J_b(q) (pose_error_jacobian, with e and J_b known).
    const Jacobian J = pose_error_jacobian_at(e, J_b);
    JtJ.noalias() = J.transpose() * J;
    gradient.noalias() = J.transpose() * e;
  };
  linearize();
  Scalar mu = options.initial_damping * JtJ.diagonal().maxCoeff();
  Scalar nu(2);
  const Scalar eps(ThresholdsOf<Scalar>::epsilon);
  // The costs of the last ik_stall_iterations iterations, a ring.
  constexpr int stall_iterations = ThresholdsOf<Scalar>::ik_stall_iterations;
  const Scalar stall_ratio(ThresholdsOf<Scalar>::ik_stall_ratio);
  Scalar recent_cost[static_cast<std::size_t>(stall_iterations)] = {};
  for (int k = 1; k <= options.max_iterations; ++k) {
    if (ik_converged(e, options)) return ik_result<ChainT>(q, IKStatus::converged, k - 1, e);
    if (deadline.passed()) return ik_result<ChainT>(q, IKStatus::time_budget, k - 1, e);
    Scalar& cost_before = recent_cost[k % stall_iterations];  // the cost stall_iterations iterations ago
    if (restart_remains && k > stall_iterations && cost > stall_ratio * cost_before)
      return ik_result<ChainT>(q, IKStatus::no_progress, k - 1, e);
    cost_before = cost;
    // The damped Gauss-Newton step (J^T J + mu I) dq = -J^T e. A joint at a
    // limit that the step would push past is held there (removed from the
    // system: an active set), and the step of the others solved again, so
    // that the joints left free make the descent; then projected onto the limits.
    Normal A = JtJ + mu * Normal::Identity(n, n);
    JointVector dq = -cholesky_solve(A, gradient);
    JointVector reduced_gradient = gradient;
    bool held = false;
    for (Eigen::Index i = 0; i < n; ++i) {
      if ((q(i) <= lower(i) && dq(i) < Scalar(0)) || (q(i) >= upper(i) && dq(i) > Scalar(0))) {
        A.row(i).setZero();
        A.col(i).setZero();
        A(i, i) = Scalar(1);
        reduced_gradient(i) = Scalar(0);
        held = true;
      }
    }
    if (held) {
      dq = -cholesky_solve(A, reduced_gradient);
    }
    const JointVector trial = (q + dq).cwiseMax(lower).cwiseMin(upper);
    const JointVector step = trial - q;
    if (!(step.squaredNorm() > eps * eps * (q.squaredNorm() + eps)))
      return ik_result<ChainT>(q, IKStatus::no_progress, k, e);
    const Vector6 e_trial = rminus(target, chain.forward_body(trial, J_b_trial));
    const Scalar cost_trial = half_squared(e_trial);
    // Gain ratio: the actual decrease of the cost over the linear model's.
    const Scalar predicted = -(step.dot(gradient) + step.dot(JtJ * step) / Scalar(2));
    const Scalar rho = (cost - cost_trial) / predicted;
    if (predicted > Scalar(0) && rho > Scalar(0)) {  // false for NaN: a non-finite trial is rejected
      q = trial;
      e = e_trial;
      cost = cost_trial;
      J_b = J_b_trial;
      linearize();
      const Scalar r = Scalar(2) * rho - Scalar(1);
      const Scalar shrink = Scalar(1) - r * r * r;
      mu *= shrink > Scalar(1) / Scalar(3) ? shrink : Scalar(1) / Scalar(3);
      nu = Scalar(2);
    } else {
      mu *= nu;
      nu *= Scalar(2);
    }
  }
  return ik_result<ChainT>(q, ik_converged(e, options) ? IKStatus::converged : IKStatus::iteration_bound,
                           options.max_iterations, e);
}

}  // namespace detail

/// The body error e(q) = rminus(T, g(q)) = log(g(q)^-1 T), (v, w): the
/// twist that carries the tool frame at q onto the target T, in the tool
/// frame; zero at a solution. g(q) by the body pass (Chain::forward_body(q,
/// J_b) without the Jacobian), the pose inverse_kinematics works with.
template <typename ChainT, typename Derived>
inline Eigen::Matrix<typename ChainT::Scalar, 6, 1> pose_error(const ChainT& chain,
                                                               const SE3<typename ChainT::Scalar>& target,
                                                               const Eigen::MatrixBase<Derived>& q) noexcept {
  return rminus(target, detail::body_pass(chain, q, nullptr));
}

/// de/dq = -J_l(e)^-1 J_b(q) (6 x n), the exact Jacobian of pose_error.
template <typename ChainT, typename Derived>
inline typename ChainT::Jacobian pose_error_jacobian(const ChainT& chain, const SE3<typename ChainT::Scalar>& target,
                                                     const Eigen::MatrixBase<Derived>& q) noexcept {
  typename ChainT::Jacobian J_b;
  const SE3<typename ChainT::Scalar> g = chain.forward_body(q, J_b);
  return detail::pose_error_jacobian_at(Eigen::Matrix<typename ChainT::Scalar, 6, 1>(rminus(target, g)), J_b);
}

/// Inverse kinematics of `chain` for the tool pose `target`, from the
/// configuration q0, within the joint limits [lower, upper] (entries may be
/// -inf / +inf for unlimited joints; q0 is first clamped into them): one
/// attempt (see the top of this header for the method). Its status:
/// converged, iteration_bound, no_progress, or time_budget when
/// options.max_time ran out first. noexcept, allocation-free; at most
/// options.max_iterations iterations.
template <typename ChainT, typename Derived>
inline IKResult<ChainT> inverse_kinematics(const ChainT& chain, const SE3<typename ChainT::Scalar>& target,
                                           const Eigen::MatrixBase<Derived>& q0,
                                           const typename ChainT::JointVector& lower,
                                           const typename ChainT::JointVector& upper,
                                           const IKOptions<typename ChainT::Scalar>& options = {}) noexcept {
  return detail::ik_attempt(chain, target, q0, lower, upper, options, detail::IKDeadline::after(options.max_time),
                            false);
}

/// inverse_kinematics from q0, then, while not converged, from up to
/// `restarts` random seeds drawn from gen, each uniform within the limits
/// ([-pi, pi] for a joint whose limit is infinite on either side), all within
/// one budget of options.max_time seconds: the seeds, and so the result
/// when no budget cuts the call short, depend on gen's state only. Returns
/// the first converged attempt, or else the attempt with the smallest
/// error, with status time_budget when the budget ended the call and that
/// attempt's own status (iteration_bound or no_progress) when the restarts
/// ran out. Every attempt but the last ends as soon as it stalls (see the
/// top of this header). noexcept, allocation-free; at most (restarts + 1)
/// options.max_iterations iterations.
template <typename ChainT, typename Derived, typename Generator>
inline IKResult<ChainT> inverse_kinematics(const ChainT& chain, const SE3<typename ChainT::Scalar>& target,
                                           const Eigen::MatrixBase<Derived>& q0,
                                           const typename ChainT::JointVector& lower,
                                           const typename ChainT::JointVector& upper,
                                           const IKOptions<typename ChainT::Scalar>& options, Generator& gen,
                                           int restarts) noexcept {
  using Scalar = typename ChainT::Scalar;
  using Real = RealOf<Scalar>;
  const detail::IKDeadline deadline = detail::IKDeadline::after(options.max_time);
  IKResult<ChainT> best = detail::ik_attempt(chain, target, q0, lower, upper, options, deadline, restarts > 0);
  int total = best.iterations, attempts = 1;
  bool out_of_time = best.status == IKStatus::time_budget;
  typename ChainT::JointVector seed(chain.n_joints());
  std::uniform_real_distribution<Real> uniform(Real(0), Real(1));
  const Scalar pi(static_cast<Real>(3.14159265358979323846)), inf(std::numeric_limits<Real>::infinity());
  for (int r = 0; r < restarts && !best.converged && !out_of_time; ++r) {
    if (deadline.passed()) {
      out_of_time = true;
      break;
    }
    for (Eigen::Index i = 0; i < seed.size(); ++i) {
      const bool bounded = lower(i) > -inf && upper(i) < inf;
      const Scalar a = bounded ? lower(i) : -pi, b = bounded ? upper(i) : pi;
      seed(i) = a + (b - a) * Scalar(uniform(gen));
    }
    const IKResult<ChainT> attempt =
        detail::ik_attempt(chain, target, seed, lower, upper, options, deadline, r + 1 < restarts);
    total += attempt.iterations;
    ++attempts;
    out_of_time = attempt.status == IKStatus::time_budget;
    if (attempt.converged || attempt.error.squaredNorm() < best.error.squaredNorm()) best = attempt;
  }
  if (out_of_time && !best.converged) best.status = IKStatus::time_budget;
  best.total_iterations = total;
  best.attempts = attempts;
  return best;
}

/// inverse_kinematics with no joint limits.
template <typename ChainT, typename Derived>
inline IKResult<ChainT> inverse_kinematics(const ChainT& chain, const SE3<typename ChainT::Scalar>& target,
                                           const Eigen::MatrixBase<Derived>& q0,
                                           const IKOptions<typename ChainT::Scalar>& options = {}) noexcept {
  using JointVector = typename ChainT::JointVector;
  using Scalar = typename ChainT::Scalar;
  const Eigen::Index n = chain.n_joints();
  const Scalar inf = std::numeric_limits<RealOf<Scalar>>::infinity();
  return inverse_kinematics(chain, target, q0, JointVector(JointVector::Constant(n, -inf)),
                            JointVector(JointVector::Constant(n, inf)), options);
}

}  // namespace chasles
