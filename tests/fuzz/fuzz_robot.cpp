// Fuzz target: the robot-arm operations that take raw numbers, in float and
// double: inverse kinematics (arbitrary target matrices, seeds and joint
// limits), SpatialInertia built from raw (m, c, I_c), and the dynamics of a
// 7-joint arm at raw (q, qd, qdd, tau, tip wrench).
//
// Input: byte 0: bit 0 set: float; (byte 0 >> 1) % 3 picks the part (0 IK,
// 1 inertia, 2 dynamics). Byte 1: options of the part (below). Then raw T
// values (fuzz_support.hpp: raw IEEE bits, so NaN, inf, subnormals occur).
//
// ---- Part 0, inverse kinematics (inverse_kinematics.hpp) ----
// Byte 1: n = 1 + b % 7 joints of a chain of up to 7 (Chain<T, Dynamic, 7>:
// a prismatic rail along (1, 2, 0) / sqrt(5), then a UR5, the first n
// joints), the limits (b / 7) % 3 (0: none, 1: [-2, 2], 2: raw [lo, hi]
// for every joint), bit 0x40: the target is SE3::from_matrix_projected(G)
// (a rotation; else the unchecked G, any 3x4 numbers), bit 0x80: one random
// restart (the overload with a generator). Values: G (16, row by row), q0
// (7, the first n used), lo, hi.
// Properties, every input:
// - it returns (the sanitizers see every read out of bounds) after at most
//   max_iterations = 100 iterations per attempt, 0 <= iterations <=
//   total_iterations <= 100 attempts, 1 <= attempts <= 2 (1 without the
//   restart, or when the first converged); converged == (status ==
//   converged), status time_budget never (no budget given);
// - the returned error is pose_error at the returned q, bit for bit;
// - converged implies |e_v| <= position_tolerance, |e_w| <=
//   orientation_tolerance (e finite);
// - the cost never increases: |e(q)|^2 <= |e(q0 clamped)|^2 (NaN: the start
//   was NaN; without restart: a step is kept only when the cost decreased);
// - q0 finite and the limits not NaN with lo <= hi: q finite and within
//   [lower, upper].
//
// ---- Part 1, SpatialInertia (spatial_inertia.hpp) ----
// Values: m, c (3), I_c (9, row by row), V (6), xi (6; g = SE3::exp(xi)),
// m2, c2 (3; a second body (m2, c2, I_c)).
// Properties:
// - is_physical() on any numbers (no overflow, no UB): when it holds, m, c
//   and I_c are finite and m > 0; against a long double reference on
//   I_c / max |I_ij| (eigenvalues l1 <= l2 <= l3, trace t, asymmetry a):
//   true when m > 0 finite, c finite, a <= tol / 2, l1 > d t and
//   t / 2 - l3 > d t; false when a > 2 tol, or l1 < -d t, or
//   t / 2 - l3 < -(tol + d) t (tol = inertia_tolerance, d = 64 eps: outside
//   these margins rounding cannot change the answer);
// - bounded size: m, c, I_c, V finite with every entry at most
//   L = max^(1/5) / 16 (2.2e60 in double, 3.4e6 in float), g's rotation
//   finite and |p| <= L: matrix(), momentum(V), kinetic_energy(V),
//   transform(g), transform_inv(g) finite (the largest product formed is
//   m |c|^2 |w|^2 <= 27 L^5: finite), and with m, m2 > 0 and |c2| <= L, the
//   sum of the two bodies; momentum(V) and kinetic_energy(V) equal their
//   long double values to kChain eps of the sum of the magnitudes of their
//   terms (momentum: m|v|, m|c||w|, |I||w|, m|c||v|, m|c|^2|w|; energy:
//   m (|v| + |c||w|)^2 and |I| |w|^2, times the 3 of a 3-term sum).
//
// ---- Part 2, dynamics (dynamics.hpp) ----
// Byte 1: n = 1 + b % 7 joints of a Panda-like 7R arm (a Chain<T, Dynamic,
// 7>, physical box inertias). Values: q (7), qd (7), qdd (7), F_tip (6);
// forward_dynamics takes qdd as its tau (the input stays within 256 bytes).
// Properties: with q finite (any size: revolute joints), |qd_i|, |qdd_i| <=
// Q = sqrt(max) / 2^24 (1.1e12 in float), |F_j| <= max / 2^48:
// inverse_dynamics (with and without F_tip), mass_matrix, gravity_torques,
// coriolis, bias, forward_dynamics (with F_tip; status ok), kinetic_energy and
// potential_energy finite (terms at most ~1e6 Q^2 for this arm, and M(q)^-1
// at most ~1e4: far below max); the kinetic energy from the links' twists
// equals 1/2 qd^T M(q) qd to 64 n eps (sum_j 2.5 |qd_j|)^2 max_i |G_i| (the
// twists' sums and both quadratic forms, rounded; plus n kChain (1 + max_i
// |G_i|) times the smallest subnormal for products that underflow). Outside
// the range every operation still runs (for the sanitizers) with no
// requirement on its value.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>

#include <Eigen/Eigenvalues>

#include <chasles/dynamics.hpp>
#include <chasles/inverse_kinematics.hpp>
#include <chasles/kinematics.hpp>
#include <chasles/spatial_inertia.hpp>

#include "fuzz_support.hpp"
#include "properties.hpp"
#include "support/arms.hpp"

namespace {

using namespace chasles_fuzz;

constexpr int kJoints = 7;

// ---------------------------------------------------------------------------
// Inverse kinematics.

template <typename T>
using IKChain = chasles::Chain<T, Eigen::Dynamic, kJoints>;

/// The first n joints of the UR5 of Modern Robotics on its prismatic rail
/// (tests/cpp/support/arms.hpp).
template <typename T>
IKChain<T> rail_ur5(int n) {
  const typename IKChain<T>::Screws screws = chasles_test::railed_ur5_screws<T>().leftCols(n);
  return IKChain<T>(screws, chasles_test::ur5_home<T>());
}

template <typename T>
void fuzz_ik(Bytes& in) {
  using SE3 = chasles::SE3<T>;
  using C = IKChain<T>;
  using J = typename C::JointVector;
  const char* ty = type_name<T>();
  const unsigned options = in.byte();
  const int n = 1 + int(options % 7);
  const int limits = int((options / 7) % 3);
  const bool projected = (options & 0x40u) != 0, restart = (options & 0x80u) != 0;
  const Mat4<T> G = in.matrix<T, 4>();
  const Eigen::Matrix<T, 7, 1> q_all = in.vector<T, 7>();
  const T a = in.scalar<T>(), b = in.scalar<T>();
  const auto input = [&] {
    return "n = " + std::to_string(n) + ", limits " + std::to_string(limits) + (projected ? ", projected" : "") +
           (restart ? ", restart" : "") + ", G = " + str(G) + ", q0 = " + str(q_all) + ", lo, hi = " + str(a) + ", " +
           str(b);
  };

  const C chain = rail_ur5<T>(n);
  const SE3 target = projected ? SE3::from_matrix_projected(G) : SE3::from_matrix_unchecked(G);
  const J q0 = q_all.head(n);
  const T inf = std::numeric_limits<T>::infinity();
  J lower = J::Constant(n, -inf), upper = J::Constant(n, inf);
  if (limits == 1) lower.setConstant(T(-2)), upper.setConstant(T(2));
  if (limits == 2) lower.setConstant(a), upper.setConstant(b);
  const chasles::IKOptions<T> opt;
  std::minstd_rand gen(options);
  const chasles::IKResult<C> r = restart ? chasles::inverse_kinematics(chain, target, q0, lower, upper, opt, gen, 1)
                                         : chasles::inverse_kinematics(chain, target, q0, lower, upper, opt);

  check(r.attempts >= 1 && r.attempts <= (restart ? 2 : 1), "IK: 1 <= attempts <= 1 + restarts", ty, input);
  check(r.iterations >= 0 && r.iterations <= opt.max_iterations && r.total_iterations >= r.iterations &&
            r.total_iterations <= r.attempts * opt.max_iterations,
        "IK: 0 <= iterations <= total_iterations <= attempts * the bound", ty, input);
  check(r.converged == (r.status == chasles::IKStatus::converged) && r.status != chasles::IKStatus::time_budget,
        "IK: converged == (status == converged); no time_budget without a budget", ty, input);
  check(r.status != chasles::IKStatus::iteration_bound || r.iterations == opt.max_iterations,
        "IK: status iteration_bound after max_iterations iterations", ty, input);
  const Vec6<T> e = chasles::pose_error(chain, target, r.q);
  check(same_bits<T, 6, 1>(r.error, e), "IK: error is pose_error at the returned q, bit for bit", ty, input);
  if (r.converged) {
    check(finite(r.error), "IK: converged, finite error", ty, input);
    check(r.error.template head<3>().squaredNorm() <= opt.position_tolerance * opt.position_tolerance &&
              r.error.template tail<3>().squaredNorm() <= opt.orientation_tolerance * opt.orientation_tolerance,
          "IK: converged, |e_v| and |e_w| within the tolerances", ty, input);
  }
  const J q0c = q0.cwiseMax(lower).cwiseMin(upper);
  const T cost0 = chasles::pose_error(chain, target, q0c).squaredNorm();
  if (!restart && cost0 == cost0)
    check(!(r.error.squaredNorm() > cost0), "IK: |e|^2 at the result <= |e|^2 at the clamped seed", ty, input);
  // Limits with a finite number between them (lo = hi = inf clamps q0 to inf).
  const bool limits_ok = limits != 2 || (a <= b && a < inf && b > -inf);
  if (finite(q0) && limits_ok) {
    check(finite(r.q), "IK: finite seed and limits in order: finite q", ty, input);
    check((r.q.array() >= lower.array()).all() && (r.q.array() <= upper.array()).all(), "IK: q within the limits", ty,
          input);
  }
  Worst::instance().update("IK: iterations (no restart)", ty, restart ? LD(0) : LD(r.iterations));
}

// ---------------------------------------------------------------------------
// SpatialInertia.

/// L = max^(1/5) / 16: see the top of this file.
template <typename T>
LD inertia_limit() {
  return std::pow(LD(std::numeric_limits<T>::max()), LD(0.2)) / 16;
}

template <typename T>
void fuzz_inertia(Bytes& in) {
  using SI = chasles::SpatialInertia<T>;
  using LD3 = Eigen::Matrix<LD, 3, 3>;
  const char* ty = type_name<T>();
  static_cast<void>(in.byte());
  const T m = in.scalar<T>();
  const Vec3<T> c = in.vector<T, 3>();
  const Mat3<T> I = in.matrix<T, 3>();
  const Vec6<T> Vv = in.vector<T, 6>(), xi = in.vector<T, 6>();
  const T m2 = in.scalar<T>();
  const Vec3<T> c2 = in.vector<T, 3>();
  const auto input = [&] {
    return "m = " + str(m) + ", c = " + str(c) + ", I = " + str(I) + ", V = " + str(Vv) + ", xi = " + str(xi) +
           ", m2 = " + str(m2) + ", c2 = " + str(c2);
  };
  const SI body(m, c, I);
  const chasles::Twist<T> V(Vv);
  const chasles::SE3<T> g = chasles::SE3<T>::exp(xi);

  // is_physical against the long double reference, outside its margins.
  const bool physical = body.is_physical();
  const bool numbers_finite = std::isfinite(m) && finite(c) && finite(I);
  if (physical) check(numbers_finite && m > 0, "is_physical: m > 0, c and I_c finite", ty, input);
  if (numbers_finite && m > 0 && max_abs(I) > 0) {
    const LD tol = LD(chasles::ThresholdsOf<T>::inertia_tolerance), d = 64 * LD(eps<T>());
    const LD3 In = I.template cast<LD>() / max_abs(I);
    const LD asym = max_abs(LD3(In - In.transpose()));
    const Eigen::SelfAdjointEigenSolver<LD3> es(LD3((In + In.transpose()) / 2), Eigen::EigenvaluesOnly);
    const Eigen::Matrix<LD, 3, 1> l = es.eigenvalues();  // increasing
    const LD t = l.sum();
    const auto detail = [&] {
      std::ostringstream os;
      os << "eigenvalues of I_c / max |I_ij|: " << double(l[0]) << ", " << double(l[1]) << ", " << double(l[2])
         << ", asymmetry " << double(asym) << "; " << input();
      return os.str();
    };
    if (asym <= tol / 2 && l[0] > d * t && t / 2 - l[2] > d * t)
      check(physical, "is_physical: true for a clearly physical body", ty, detail);
    if (asym > 2 * tol || l[0] < -d * t || t / 2 - l[2] < -(tol + d) * t)
      check(!physical, "is_physical: false for a clearly unphysical body", ty, detail);
  }

  // Finite results for bounded finite inputs; momentum and energy against
  // long double.
  const auto matrix = body.matrix();
  const chasles::Wrench<T> h = body.momentum(V);
  const T ke = body.kinetic_energy(V);
  const SI moved = body.transform(g), back = body.transform_inv(g);
  const SI joined = body + SI(m2, c2, I);
  const LD L = inertia_limit<T>();
  const bool bounded =
      numbers_finite && finite(Vv) && std::fabs(LD(m)) <= L && max_abs(c) <= L && max_abs(I) <= L && max_abs(Vv) <= L;
  const bool g_ok = finite(g.rotation().matrix()) && finite(g.translation()) && max_abs(g.translation()) <= L;
  if (bounded) {
    check(finite(matrix), "inertia: matrix() finite (bounded inputs)", ty, input);
    check(finite(h.vector()) && std::isfinite(ke), "inertia: momentum and kinetic energy finite (bounded inputs)", ty,
          input);
    using LD3v = Eigen::Matrix<LD, 3, 1>;
    const LD ml = m;
    const LD3v cl = c.template cast<LD>(), v = Vv.template head<3>().template cast<LD>(),
               w = Vv.template tail<3>().template cast<LD>();
    const LD3 Il = I.template cast<LD>();
    const LD3v vc = v - cl.cross(w), f = ml * vc, tau = Il * w + cl.cross(f);
    const LD ke_ref = (ml * vc.squaredNorm() + w.dot(Il * w)) / 2;
    const LD am = std::fabs(ml), ac = max_abs(c), aI = max_abs(I), av = max_abs(v), aw = max_abs(w);
    const LD h_scale = 3 * std::max({am * av, am * ac * aw, aI * aw, am * ac * av, am * ac * ac * aw});
    const LD ke_scale = 3 * (am * (av + 2 * ac * aw) * (av + 2 * ac * aw) + 3 * aI * aw * aw);
    Eigen::Matrix<LD, 6, 1> h_ref;
    h_ref << f, tau;
    // An intermediate rounded to a multiple of the smallest subnormal carries
    // that absolute error into the products after it: at most the factors
    // m, |c|, |w|, m |c|, m (|v| + 2 |c| |w|) and |I| that follow.
    const LD tiny = subnormal_allowance<T>() * (1 + am + ac + aw + aI + am * ac + am * (av + 2 * ac * aw));
    check_le((max_abs_diff(h.vector(), h_ref) - tiny) / (eps<T>() * std::max(h_scale, LD(1e-300))), kChain,
             "inertia: momentum - long double (eps of its terms)", ty, input);
    check_le(
        (std::fabs(LD(ke) - ke_ref) - tiny * (1 + av + 2 * ac * aw + aw)) / (eps<T>() * std::max(ke_scale, LD(1e-300))),
        kChain, "inertia: kinetic energy - long double (eps of its terms)", ty, input);
    if (g_ok) {
      check(std::isfinite(moved.mass()) && finite(moved.com()) && finite(moved.inertia()) && finite(back.com()) &&
                finite(back.inertia()),
            "inertia: transform(g), transform_inv(g) finite (bounded inputs)", ty, input);
    }
    if (m > 0 && m2 > 0 && std::isfinite(m2) && LD(m2) <= L && finite(c2) && max_abs(c2) <= L)
      check(std::isfinite(joined.mass()) && finite(joined.com()) && finite(joined.inertia()),
            "inertia: the sum of two bodies of positive mass finite (bounded inputs)", ty, input);
  }
}

// ---------------------------------------------------------------------------
// Dynamics.

template <typename T>
using Dyn = chasles::Chain<T, Eigen::Dynamic, kJoints>;

/// The first n joints of the Panda-like arm (tests/cpp/support/arms.hpp).
template <typename T>
Dyn<T> panda_like(int n) {
  const chasles_test::PandaLike<T> panda;
  const typename Dyn<T>::Screws S = panda.screws.leftCols(n);
  return Dyn<T>(S, panda.home, typename Dyn<T>::HomeAsGiven(), panda.inertias, Vec3<T>(T(0), T(0), T(-9.81)));
}

template <typename T>
void fuzz_dynamics(Bytes& in) {
  using D = Dyn<T>;
  using J = typename D::JointVector;
  const char* ty = type_name<T>();
  const int n = 1 + int(in.byte() % 7);
  const Eigen::Matrix<T, 7, 1> q_all = in.vector<T, 7>(), qd_all = in.vector<T, 7>(), qdd_all = in.vector<T, 7>();
  const Vec6<T> Fv = in.vector<T, 6>();
  const auto input = [&] {
    return "n = " + std::to_string(n) + ", q = " + str(q_all) + ", qd = " + str(qd_all) + ", qdd = " + str(qdd_all) +
           ", F_tip = " + str(Fv);
  };
  const D d = panda_like<T>(n);
  const J q = q_all.head(n), qd = qd_all.head(n), qdd = qdd_all.head(n), tau = qdd;
  const chasles::Wrench<T> F(Fv);
  const J id = inverse_dynamics(d, q, qd, qdd), id_tip = inverse_dynamics(d, q, qd, qdd, F);
  const typename D::MassMatrix Mq = mass_matrix(d, q);
  const J grav = gravity_torques(d, q), cor = coriolis(d, q, qd), bias = chasles::bias(d, q, qd);
  const auto forward = forward_dynamics(d, q, qd, tau, F);
  const J fd = forward.qdd;
  const T ke = kinetic_energy(d, q, qd), pe = potential_energy(d, q);

  const LD max = LD(std::numeric_limits<T>::max());
  const LD Q = std::sqrt(max) / LD(16777216), B = max / std::pow(LD(2), 48);
  if (!(finite(q) && finite(qd) && finite(qdd) && finite(Fv) && max_abs(qd) <= Q && max_abs(qdd) <= Q &&
        max_abs(Fv) <= B))
    return;
  check(finite(id) && finite(id_tip), "dynamics: inverse_dynamics finite (in range)", ty, input);
  check(finite(Mq) && finite(grav) && finite(cor) && finite(bias),
        "dynamics: mass_matrix, gravity_torques, coriolis, bias finite (in range)", ty, input);
  check(bool(forward) && finite(fd), "dynamics: forward_dynamics ok and finite (in range)", ty, input);
  check(std::isfinite(ke) && std::isfinite(pe), "dynamics: kinetic and potential energy finite (in range)", ty, input);
  const Eigen::Matrix<LD, Eigen::Dynamic, 1> qdl = qd.template cast<LD>();
  const LD quad = qdl.dot(Mq.template cast<LD>() * qdl) / 2;
  LD G = 0;
  for (int i = 0; i < n; ++i) G = std::max(G, max_abs(d.link_inertias()[std::size_t(i)].matrix()));
  const LD s = 2.5L * qdl.cwiseAbs().sum();
  const LD scale = 64 * n * s * s * G;
  // Products that underflow (qd of subnormal size) are off by a few of the
  // smallest subnormal each, times the inertias.
  const LD tiny = subnormal_allowance<T>() * n * (1 + G);
  if (scale > 0)
    check_le((std::fabs(LD(ke) - quad) - tiny) / (eps<T>() * scale), 1,
             "dynamics: kinetic energy - 1/2 qd^T M qd (64 n eps (2.5 sum |qd|)^2 max |G|)", ty, input);
}

template <typename T>
void fuzz(Bytes& in, unsigned part) {
  if (part == 0) fuzz_ik<T>(in);
  if (part == 1) fuzz_inertia<T>(in);
  if (part == 2) fuzz_dynamics<T>(in);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  Bytes in(data, size);
  const unsigned head = in.byte();
  if (head & 1u) {
    fuzz<float>(in, (head >> 1) % 3);
  } else {
    fuzz<double>(in, (head >> 1) % 3);
  }
  return 0;
}
