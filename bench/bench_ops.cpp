// chasles C++ benchmarks: each operation on inputs cycled through 1024
// pre-generated elements (nothing constant-folds), results kept alive with
// DoNotOptimize, beside the baselines a C++ user has without chasles
// (Eigen's AngleAxis, Quaternion, Isometry3) and the floors (one sincos, one
// atan2, a 3x3 by 3x3 and a 3x3 by 3 product).
//
//   build/bench/chasles_bench_portable --benchmark_repetitions=5
//     --benchmark_report_aggregates_only=true   (one line)
//
// Names: <group>/<op>/<input>/<scalar>, e.g. SO3/log/near_pi/double. The
// exp and log kernels also report err_eps, their worst error on the very
// inputs they are timed on, in eps of the scalar (add_measured).
#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>
#include <type_traits>
#include <vector>

#include <benchmark/benchmark.h>

#include <Eigen/Geometry>

#include "chasles/bspline.hpp"
#include "chasles/chasles.hpp"
#include "chasles/dynamics.hpp"
#include "chasles/kinematics.hpp"
#include "harness.hpp"
#include "support/arms.hpp"
#include "support/reference.hpp"

namespace {

using chasles_bench::add;
using chasles_bench::kN;
using chasles_bench::run;
constexpr double kPi = 3.14159265358979323846;

/// Rotation vectors of a given kind: generic (angle uniform in (0.1, 3)),
/// tiny (~1e-9) or near pi (pi - 1e-6).
template <typename S>
std::vector<Eigen::Matrix<S, 3, 1>> rotation_vectors(const std::string& kind, std::uint32_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0, 1);
  std::uniform_real_distribution<double> u(0.1, 3.0);
  std::vector<Eigen::Matrix<S, 3, 1>> out;
  for (std::size_t i = 0; i < kN; ++i) {
    Eigen::Vector3d axis(n(rng), n(rng), n(rng));
    axis.normalize();
    const double angle = kind == "tiny" ? 1e-9 * (1 + u(rng)) : kind == "near_pi" ? kPi - 1e-6 : u(rng);
    out.push_back((angle * axis).cast<S>());
  }
  return out;
}

template <typename S>
std::vector<Eigen::Matrix<S, 6, 1>> twists(const std::string& kind, std::uint32_t seed) {
  std::mt19937_64 rng(seed + 7);
  std::normal_distribution<double> n(0, 1);
  std::vector<Eigen::Matrix<S, 6, 1>> out;
  for (const auto& w : rotation_vectors<S>(kind, seed)) {
    Eigen::Matrix<S, 6, 1> xi;
    xi.template head<3>() = Eigen::Vector3d(n(rng), n(rng), n(rng)).cast<S>();
    xi.template tail<3>() = w;
    out.push_back(xi);
  }
  return out;
}

/// As add, with the accuracy of op on exactly the inputs it is timed on:
/// the worst of error(input, op(input)) against the long double reference
/// (tests/cpp/support/reference.hpp), in eps of S, reported as the counter
/// err_eps (bench/report.py prints it beside the time).
template <typename S, typename In, typename Op, typename Error>
void add_measured(const std::string& name, std::vector<In> in, Op op, Error error) {
  long double worst = 0;
  for (const In& x : in) worst = std::max(worst, error(x, op(x)));
  const double err_eps = double(worst / std::numeric_limits<S>::epsilon());
  benchmark::RegisterBenchmark(name.c_str(), [in = std::move(in), op, err_eps](benchmark::State& s) {
    run(s, in, op);
    s.counters["err_eps"] = err_eps;
  });
}

/// The errors of the exp and log kernels, as test_accuracy.cpp defines them:
/// rotations entrywise, rotation vectors absolutely, translations relative
/// to their largest entry; in long double against the reference computed
/// from the kernel's own (rounded) input.
namespace error {
using chasles_ref::ld;
template <typename S>
ld so3_exp(const Eigen::Matrix<S, 3, 1>& w, const chasles::SO3<S>& R) {
  return (R.matrix().template cast<ld>() - chasles_ref::exp3(w.template cast<ld>())).cwiseAbs().maxCoeff();
}
template <typename S>
ld so3_log(const chasles::SO3<S>& R, const Eigen::Matrix<S, 3, 1>& w) {
  return (w.template cast<ld>() - chasles_ref::log3(R.matrix().template cast<ld>())).cwiseAbs().maxCoeff();
}
template <typename S>
ld se3_exp(const Eigen::Matrix<S, 6, 1>& xi, const chasles::SE3<S>& g) {
  const chasles_ref::M4 ref = chasles_ref::exp6(xi.template cast<ld>());
  const chasles_ref::M4 got = g.matrix().template cast<ld>();
  const ld rotation = (got.topLeftCorner<3, 3>() - ref.topLeftCorner<3, 3>()).cwiseAbs().maxCoeff();
  const ld scale = std::max(ref.topRightCorner<3, 1>().cwiseAbs().maxCoeff(), ld(1e-300));
  return std::max(rotation, (got.topRightCorner<3, 1>() - ref.topRightCorner<3, 1>()).cwiseAbs().maxCoeff() / scale);
}
template <typename S>
ld se3_log(const chasles::SE3<S>& g, const Eigen::Matrix<S, 6, 1>& xi) {
  const chasles_ref::V6 ref = chasles_ref::log6(g.matrix().template cast<ld>());
  const chasles_ref::V6 got = xi.template cast<ld>();
  const ld rotation = (got.tail<3>() - ref.tail<3>()).cwiseAbs().maxCoeff();
  const ld scale = std::max(ref.head<3>().cwiseAbs().maxCoeff(), ld(1e-300));
  return std::max(rotation, (got.head<3>() - ref.head<3>()).cwiseAbs().maxCoeff() / scale);
}
}  // namespace error

/// Chain/<op>/<input>/<scalar> over joint vectors uniform in [-pi, pi].
template <typename S, typename C>
void register_chain(const std::string& input, const std::string& sn, int n) {
  using JV = typename C::JointVector;
  const C chain = chasles_test::ur5_chain<C>(n);
  std::mt19937_64 rng(11 + std::uint32_t(n));
  std::uniform_real_distribution<double> u(-kPi, kPi);
  std::vector<JV> th;
  for (std::size_t i = 0; i < kN; ++i) {
    JV t(n);
    for (int j = 0; j < n; ++j) t(j) = S(u(rng));
    th.push_back(t);
  }
  const std::string tail = "/" + input + "/" + sn;
  add("Chain/forward" + tail, th, [chain](const JV& t) { return chain.forward(t); });
  add("Chain/forward_body" + tail, th, [chain](const JV& t) { return chain.forward_body(t); });
  add("Chain/jacobian_space" + tail, th, [chain](const JV& t) { return chain.jacobian_space(t); });
  add("Chain/jacobian_body" + tail, th, [chain](const JV& t) { return chain.jacobian_body(t); });
  // Inverse kinematics of forward(theta) from a seed 0.3 rad away (each
  // joint theta_i + U(-0.3, 0.3)), to the default tolerances.
  std::uniform_real_distribution<double> jitter(-0.3, 0.3);
  std::vector<std::pair<chasles::SE3<S>, JV>> problems;
  for (const JV& t : th) {
    JV seed(n);
    for (int j = 0; j < n; ++j) seed(j) = t(j) + S(jitter(rng));
    problems.emplace_back(chain.forward(t), seed);
  }
  add("Chain/inverse_kinematics_from_0.3rad" + tail, problems,
      [chain](const auto& p) { return chasles::inverse_kinematics(chain, p.first, p.second); });
}

/// Spline/<group>/fit_100_keys and Spline/<group>/evaluate (element, body velocity and acceleration at times
/// cycled through the range) over 100 keys: steps exp(z), z ~ N(0, 0.35^2 I) per component, 0.3 to 1 s apart.
template <typename Group>
void register_spline(const std::string& group, const std::string& sn) {
  using S = typename Group::Scalar;
  using Tangent = Eigen::Matrix<S, Group::DoF, 1>;
  struct Storage {
    std::vector<S> times;
    std::vector<Group> keys;
    std::vector<chasles::SplineSegment<Group>> segments;
    std::vector<chasles::SplineWork<Group>> work;
  };
  const auto st = std::make_shared<Storage>();
  std::mt19937_64 rng(17);
  std::normal_distribution<double> normal(0, 0.35);
  std::uniform_real_distribution<double> step(0.3, 1.0);
  double t = 0;
  Group X = Group::identity();
  for (int i = 0; i < 100; ++i) {
    Tangent z;
    for (int j = 0; j < Group::DoF; ++j) z[j] = S(normal(rng));
    X = X * Group::exp(z);
    st->keys.push_back(X);
    st->times.push_back(S(t));
    t += step(rng);
  }
  st->segments.resize(99);
  st->work.resize(100);
  chasles::fit_spline(100, st->times.data(), st->keys.data(), st->segments.data(), st->work.data());
  benchmark::RegisterBenchmark(("Spline/" + group + "/fit_100_keys/" + sn).c_str(), [st](benchmark::State& state) {
    for (auto _ : state) {
      auto r = chasles::fit_spline(100, st->times.data(), st->keys.data(), st->segments.data(), st->work.data());
      benchmark::DoNotOptimize(r);
      benchmark::ClobberMemory();
    }
  });
  std::uniform_real_distribution<double> u(0, static_cast<double>(st->times.back()));
  std::vector<S> ts;
  for (std::size_t i = 0; i < kN; ++i) ts.push_back(S(u(rng)));
  const chasles::Spline<Group> spline(100, st->times.data(), st->keys.data(), st->segments.data());
  add("Spline/" + group + "/evaluate/100_keys/" + sn, ts, [spline, st](S time) { return spline(time); });
  add("Spline/" + group + "/element/100_keys/" + sn, ts, [spline, st](S time) { return spline.element(time); });
}

/// BSpline/<op>/<group>/<scalar>: a 64-element spline (random steps of up
/// to 0.5 per tangent coordinate) at times uniform over its 61 segments:
/// the element alone, and with body velocity and acceleration.
template <typename G>
void register_bspline_of(const std::string& group, const std::string& sn, std::uint32_t seed) {
  using S = typename G::Scalar;
  using T = Eigen::Matrix<S, G::DoF, 1>;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> step(-0.5, 0.5), time(0.0, 61.0);
  auto control = std::make_shared<std::vector<G>>(1, G());
  for (int k = 1; k < 64; ++k) {
    T x;
    for (int j = 0; j < G::DoF; ++j) x[j] = S(step(rng));
    control->push_back(control->back() * G::exp(x));
  }
  std::vector<S> times;
  for (std::size_t i = 0; i < kN; ++i) times.push_back(S(time(rng)));
  const auto view = [control] { return chasles::CubicBSplineView<G>(control->data(), 64, S(0), S(1)); };
  add("BSpline/value/" + group + "/" + sn, times, [view](S t) { return view()(t); });
  add("BSpline/value_velocity_acceleration/" + group + "/" + sn, times, [view](S t) { return view().evaluate(t); });
}

template <typename S>
void register_bspline(const std::string& sn) {
  register_bspline_of<chasles::SO3<S>>("SO3", sn, 31);
  register_bspline_of<chasles::SE3<S>>("SE3", sn, 37);
}

/// Dynamics/<op>/<input>/<scalar>: the same arms, each link a box of
/// 1 to 4 kg placed along the arm (inertias in the base frame at home), over
/// states (q, qd, qdd) uniform in [-pi, pi] x [-2, 2] x [-2, 2].
template <typename S, typename D>
void register_dynamics(const std::string& input, const std::string& sn, int n) {
  using JV = typename D::JointVector;
  using C = chasles::Chain<S, D::Screws::ColsAtCompileTime, D::Screws::MaxColsAtCompileTime>;
  const C chain = chasles_test::ur5_chain<C>(n);
  typename D::Inertias inertias;
  std::mt19937_64 rng(17 + std::uint32_t(n));
  std::uniform_real_distribution<double> u(-kPi, kPi), r(-2, 2), m(1, 4), side(0.05, 0.3);
  for (int i = 0; i < n; ++i) {
    const double mass = m(rng), x = side(rng), y = side(rng), z = side(rng);
    const Eigen::Matrix<S, 3, 1> moments(S(mass * (y * y + z * z) / 12), S(mass * (x * x + z * z) / 12),
                                         S(mass * (x * x + y * y) / 12));
    const Eigen::Matrix<S, 3, 1> com(S(0.1 * i), S(0.05 * i), S(0.1));
    inertias[std::size_t(i)] = chasles::SpatialInertia<S>(S(mass), com, moments.asDiagonal());
  }
  const D dyn(chain.space_screws(), chain.home(), typename D::HomeAsGiven(), inertias,
              Eigen::Matrix<S, 3, 1>(S(0), S(0), S(-9.81)));
  struct State {
    JV q, qd, qdd;
  };
  std::vector<State> states;
  for (std::size_t k = 0; k < kN; ++k) {
    State st{JV(n), JV(n), JV(n)};
    for (int j = 0; j < n; ++j) {
      st.q(j) = S(u(rng));
      st.qd(j) = S(r(rng));
      st.qdd(j) = S(r(rng));
    }
    states.push_back(st);
  }
  const std::string tail = "/" + input + "/" + sn;
  add("Dynamics/inverse_dynamics" + tail, states,
      [dyn](const State& x) { return inverse_dynamics(dyn, x.q, x.qd, x.qdd); });
  add("Dynamics/mass_matrix" + tail, states, [dyn](const State& x) { return mass_matrix(dyn, x.q); });
  add("Dynamics/gravity_torques" + tail, states, [dyn](const State& x) { return gravity_torques(dyn, x.q); });
  add("Dynamics/forward_dynamics" + tail, states,
      [dyn](const State& x) { return forward_dynamics(dyn, x.q, x.qd, x.qdd); });
}

template <typename S>
void register_all(const std::string& sn) {
  using namespace chasles;
  using V3 = Eigen::Matrix<S, 3, 1>;
  using M3 = Eigen::Matrix<S, 3, 3>;
  using Q = Eigen::Quaternion<S>;
  using Iso = Eigen::Transform<S, 3, Eigen::Isometry>;

  // ---- SO3
  for (const std::string kind : {"generic", "tiny", "near_pi"}) {
    const auto ws = rotation_vectors<S>(kind, 1);
    add_measured<S>("SO3/exp/" + kind + "/" + sn, ws, [](const V3& w) { return SO3<S>::exp(w); }, error::so3_exp<S>);
    std::vector<SO3<S>> Rs;
    for (const auto& w : ws) Rs.push_back(SO3<S>::exp(w));
    add_measured<S>("SO3/log/" + kind + "/" + sn, Rs, [](const SO3<S>& R) { return R.log(); }, error::so3_log<S>);
    // The speed issue's peers on every kind of input: Eigen's exp to a
    // quaternion (4 numbers out, no matrix) and its log from a stored
    // quaternion.
    add("Eigen/quaternion_exp/" + kind + "/" + sn, ws, [](const V3& w) {
      const S a = w.norm();
      return Q(Eigen::AngleAxis<S>(a, w / a));
    });
    std::vector<Q> qs;
    for (const auto& R : Rs) qs.push_back(R.quaternion());
    add("Eigen/AngleAxis_from_quaternion/" + kind + "/" + sn, qs, [](const Q& q) {
      const Eigen::AngleAxis<S> aa(q);
      return V3(aa.angle() * aa.axis());
    });
    if (kind == "generic") {
      add("Eigen/AngleAxis_to_matrix/" + kind + "/" + sn, ws, [](const V3& w) {
        const S a = w.norm();
        return Eigen::AngleAxis<S>(a, w / a).toRotationMatrix();
      });
      add("Eigen/quaternion_exp_to_matrix/" + kind + "/" + sn, ws, [](const V3& w) {
        const S a = w.norm();
        return Q(Eigen::AngleAxis<S>(a, w / a)).toRotationMatrix();
      });
    }
    std::vector<M3> Ms;
    for (const auto& R : Rs) Ms.push_back(R.matrix());
    add("Eigen/AngleAxis_from_matrix/" + kind + "/" + sn, Ms, [](const M3& M) {
      const Eigen::AngleAxis<S> aa(M);
      return V3(aa.angle() * aa.axis());
    });
  }
  const auto ws = rotation_vectors<S>("generic", 2);
  std::vector<SO3<S>> Rs;
  std::vector<std::pair<SO3<S>, SO3<S>>> Rpairs;
  std::vector<std::pair<SO3<S>, V3>> Rpoints;
  std::vector<std::pair<Q, Q>> Qpairs;
  std::vector<std::pair<Q, V3>> Qpoints;
  std::vector<Q> Qs;
  for (std::size_t i = 0; i < kN; ++i) {
    Rs.push_back(SO3<S>::exp(ws[i]));
    Qs.push_back(Rs.back().quaternion());
  }
  for (std::size_t i = 0; i < kN; ++i) {
    Rpairs.emplace_back(Rs[i], Rs[(i + 1) & (kN - 1)]);
    Rpoints.emplace_back(Rs[i], ws[(i + 3) & (kN - 1)]);
    Qpairs.emplace_back(Qs[i], Qs[(i + 1) & (kN - 1)]);
    Qpoints.emplace_back(Qs[i], ws[(i + 3) & (kN - 1)]);
  }
  add("SO3/compose/generic/" + sn, Rpairs, [](const auto& p) { return p.first * p.second; });
  add("SO3/inverse/generic/" + sn, Rs, [](const SO3<S>& R) { return R.inverse(); });
  add("SO3/act/generic/" + sn, Rpoints, [](const auto& p) { return V3(p.first * p.second); });
  add("SO3/as_quaternion/generic/" + sn, Rs, [](const SO3<S>& R) { return R.quaternion(); });
  add("SO3/from_quaternion/generic/" + sn, Qs, [](const Q& q) { return SO3<S>::from_quaternion(q); });
  add("SO3/interpolate/generic/" + sn, Rpairs, [](const auto& p) { return interpolate(p.first, p.second, S(0.3)); });
  add("SO3/normalized/generic/" + sn, Rs, [](const SO3<S>& R) { return R.normalized(); });
  // Euler angles: intrinsic ZYX (= extrinsic xyz, RPY) and ZXZ beside Eigen's
  // AngleAxis product and eulerAngles (the same sequences, Eigen's ranges).
  std::vector<V3> eul;
  for (const auto& R : Rs) eul.push_back(as_euler<EulerSequence::ZYX>(R).angles);
  add("SO3/from_euler_ZYX/generic/" + sn, eul, [](const V3& t) { return from_euler<EulerSequence::ZYX>(t); });
  add("Eigen/AngleAxis_product_ZYX/generic/" + sn, eul, [](const V3& t) {
    return M3((Eigen::AngleAxis<S>(t[0], V3::UnitZ()) * Eigen::AngleAxis<S>(t[1], V3::UnitY()) *
               Eigen::AngleAxis<S>(t[2], V3::UnitX()))
                  .toRotationMatrix());
  });
  add("SO3/as_euler_ZYX/generic/" + sn, Rs, [](const SO3<S>& R) { return as_euler<EulerSequence::ZYX>(R).angles; });
  add("SO3/as_euler_ZXZ/generic/" + sn, Rs, [](const SO3<S>& R) { return as_euler<EulerSequence::ZXZ>(R).angles; });
  add("Eigen/eulerAngles_ZYX/generic/" + sn, Rs, [](const SO3<S>& R) { return V3(R.matrix().eulerAngles(2, 1, 0)); });
  add("Eigen/eulerAngles_ZXZ/generic/" + sn, Rs, [](const SO3<S>& R) { return V3(R.matrix().eulerAngles(2, 0, 2)); });
  add("Eigen/quaternion_compose/generic/" + sn, Qpairs, [](const auto& p) { return Q(p.first * p.second); });
  add("Eigen/quaternion_act/generic/" + sn, Qpoints, [](const auto& p) { return V3(p.first * p.second); });
  add("Eigen/quaternion_to_matrix/generic/" + sn, Qs, [](const Q& q) { return q.toRotationMatrix(); });
  add("Eigen/matrix_to_quaternion/generic/" + sn, Rs, [](const SO3<S>& R) { return Q(R.matrix()); });
  add("Eigen/quaternion_slerp/generic/" + sn, Qpairs, [](const auto& p) { return p.first.slerp(S(0.3), p.second); });

  // ---- SE3
  for (const std::string kind : {"generic", "tiny", "near_pi"}) {
    const auto xs = twists<S>(kind, 3);
    add_measured<S>(
        "SE3/exp/" + kind + "/" + sn, xs, [](const Eigen::Matrix<S, 6, 1>& xi) { return SE3<S>::exp(xi); },
        error::se3_exp<S>);
    std::vector<SE3<S>> gs;
    for (const auto& xi : xs) gs.push_back(SE3<S>::exp(xi));
    add_measured<S>("SE3/log/" + kind + "/" + sn, gs, [](const SE3<S>& g) { return g.log(); }, error::se3_log<S>);
  }
  const auto xs = twists<S>("generic", 4);
  std::vector<SE3<S>> gs;
  std::vector<Iso> isos;
  for (const auto& xi : xs) {
    gs.push_back(SE3<S>::exp(xi));
    Iso T = Iso::Identity();
    T.linear() = gs.back().rotation().matrix();
    T.translation() = gs.back().translation();
    isos.push_back(T);
  }
  std::vector<std::pair<SE3<S>, SE3<S>>> gpairs;
  std::vector<std::pair<SE3<S>, V3>> gpoints;
  std::vector<std::pair<SE3<S>, Twist<S>>> gtwists;
  std::vector<std::pair<SE3<S>, Wrench<S>>> gwrenches;
  std::vector<std::pair<Iso, Iso>> isopairs;
  std::vector<std::pair<Iso, V3>> isopoints;
  for (std::size_t i = 0; i < kN; ++i) {
    const std::size_t j = (i + 1) & (kN - 1), k = (i + 5) & (kN - 1);
    gpairs.emplace_back(gs[i], gs[j]);
    gpoints.emplace_back(gs[i], xs[k].template head<3>());
    gtwists.emplace_back(gs[i], Twist<S>(xs[k]));
    gwrenches.emplace_back(gs[i], Wrench<S>(xs[k]));
    isopairs.emplace_back(isos[i], isos[j]);
    isopoints.emplace_back(isos[i], xs[k].template head<3>());
  }
  add("SE3/compose/generic/" + sn, gpairs, [](const auto& p) { return p.first * p.second; });
  add("SE3/inverse/generic/" + sn, gs, [](const SE3<S>& g) { return g.inverse(); });
  add("SE3/act/generic/" + sn, gpoints, [](const auto& p) { return V3(p.first * p.second); });
  add("SE3/adjoint/generic/" + sn, gs, [](const SE3<S>& g) { return g.adjoint(); });
  add("SE3/act_twist/generic/" + sn, gtwists, [](const auto& p) { return p.first.act(p.second); });
  add("SE3/act_wrench/generic/" + sn, gwrenches, [](const auto& p) { return p.first.act_inv(p.second); });
  add("SE3/interpolate/generic/" + sn, gpairs, [](const auto& p) { return interpolate(p.first, p.second, S(0.3)); });
  add("Eigen/Isometry3_compose/generic/" + sn, isopairs, [](const auto& p) { return Iso(p.first * p.second); });
  add("Eigen/Isometry3_inverse/generic/" + sn, isos, [](const Iso& T) { return Iso(T.inverse(Eigen::Isometry)); });
  add("Eigen/Isometry3_act/generic/" + sn, isopoints, [](const auto& p) { return V3(p.first * p.second); });

  // ---- Chain (product of exponentials): a UR5 (Modern Robotics, example
  // 4.5) and the same arm on a linear rail (7 joints); fixed-size chains and
  // a dynamic chain with a bound of 8 joints.
  register_chain<S, Chain<S, 6>>("6dof", sn, 6);
  register_chain<S, Chain<S, 7>>("7dof", sn, 7);
  register_chain<S, Chain<S, Eigen::Dynamic, 8>>("6dof_dynamic_max8", sn, 6);
  register_chain<S, Chain<S, Eigen::Dynamic, 8>>("7dof_dynamic_max8", sn, 7);
  register_spline<SO3<S>>("SO3", sn);
  register_spline<SE3<S>>("SE3", sn);
  register_bspline<S>(sn);
  register_dynamics<S, chasles::Chain<S, 6>>("6dof", sn, 6);
  register_dynamics<S, chasles::Chain<S, 7>>("7dof", sn, 7);
  register_dynamics<S, chasles::Chain<S, Eigen::Dynamic, 8>>("7dof_dynamic_max8", sn, 7);

  // ---- floors
  std::vector<S> angles;
  for (const auto& w : ws) angles.push_back(w.norm());
  add("floor/sincos/generic/" + sn, angles, [](S a) {
    using std::cos;
    using std::sin;
    return std::make_pair(sin(a), cos(a));
  });
  add("floor/atan2/generic/" + sn, ws, [](const V3& w) {
    using std::atan2;
    return atan2(w[0], w[1]);
  });
  std::vector<std::pair<M3, M3>> mpairs;
  for (const auto& p : Rpairs) mpairs.emplace_back(p.first.matrix(), p.second.matrix());
  add("floor/matmul_3x3_3x3/generic/" + sn, mpairs, [](const auto& p) { return M3(p.first * p.second); });
  std::vector<std::pair<M3, V3>> mpoints;
  for (const auto& p : Rpoints) mpoints.emplace_back(p.first.matrix(), p.second);
  add("floor/matmul_3x3_3/generic/" + sn, mpoints, [](const auto& p) { return V3(p.first * p.second); });
}

/// The everyday tools: distances, sampling, means of 50 elements (a cloud of
/// 0.87 rad rms about a random element, as bench_python.py's) and the
/// Jacobians of rminus, between and the point action.
template <typename S>
void register_statistics(const std::string& sn) {
  using namespace chasles;
  using V3 = Eigen::Matrix<S, 3, 1>;
  const auto ws = rotation_vectors<S>("generic", 21);
  const auto xs = twists<S>("generic", 22);
  std::vector<std::pair<SO3<S>, SO3<S>>> Rpairs;
  std::vector<std::pair<SE3<S>, SE3<S>>> gpairs;
  std::vector<std::pair<SE3<S>, V3>> gpoints;
  for (std::size_t i = 0; i < kN; ++i) {
    const std::size_t j = (i + 1) & (kN - 1);
    Rpairs.emplace_back(SO3<S>::exp(ws[i]), SO3<S>::exp(ws[j]));
    gpairs.emplace_back(SE3<S>::exp(xs[i]), SE3<S>::exp(xs[j]));
    gpoints.emplace_back(gpairs.back().first, xs[j].template head<3>());
  }
  add("SO3/distance/generic/" + sn, Rpairs, [](const auto& p) { return distance(p.first, p.second); });
  add("SE3/distance/generic/" + sn, gpairs, [](const auto& p) { return distance(p.first, p.second); });
  add("SO3/rminus_jacobians/generic/" + sn, Rpairs, [](const auto& p) { return rminus_jacobians(p.first, p.second); });
  add("SE3/rminus_jacobians/generic/" + sn, gpairs, [](const auto& p) { return rminus_jacobians(p.first, p.second); });
  add("SE3/between_jacobians/generic/" + sn, gpairs,
      [](const auto& p) { return between_jacobians(p.first, p.second); });
  add("SE3/act_jacobians/generic/" + sn, gpoints, [](const auto& p) { return act_jacobians(p.first, p.second); });
  // Gaussians (gaussian.hpp): compose, between and the fourth-order compose
  // of two uncertain poses, beside compose's arithmetic written plainly with
  // Eigen (Ad_{b^-1} S_a Ad_{b^-1}^T + S_b from the adjoint).
  using M6 = Eigen::Matrix<S, 6, 6>;
  std::vector<std::pair<Gaussian<SE3<S>>, Gaussian<SE3<S>>>> gaussians;
  for (const auto& p : gpairs) {
    const M6 A = M6::Random() * S(0.1);
    gaussians.emplace_back(Gaussian<SE3<S>>(p.first, M6(A * A.transpose())),
                           Gaussian<SE3<S>>(p.second, M6(A.transpose() * A)));
  }
  add("SE3/gaussian_compose/generic/" + sn, gaussians, [](const auto& p) { return p.first * p.second; });
  add("SE3/gaussian_between/generic/" + sn, gaussians, [](const auto& p) { return p.first.between(p.second); });
  add("SE3/gaussian_compose_fourth_order/generic/" + sn, gaussians,
      [](const auto& p) { return compose_fourth_order(p.first, p.second); });
  add("Eigen/gaussian_compose_plain/generic/" + sn, gaussians, [](const auto& p) {
    const M6 A = p.second.mean().inverse().adjoint();
    return std::make_pair(SE3<S>(p.first.mean() * p.second.mean()),
                          M6(A * p.first.cov() * A.transpose() + p.second.cov()));
  });

  // Sampling: one draw per iteration from a generator kept across iterations.
  benchmark::RegisterBenchmark(("SO3/random/uniform/" + sn).c_str(), [](benchmark::State& st) {
    std::mt19937_64 gen(5);
    for (auto _ : st) benchmark::DoNotOptimize(random_rotation<S>(gen));
  });
  benchmark::RegisterBenchmark(("SE3/random_gaussian/generic/" + sn).c_str(), [](benchmark::State& st) {
    std::mt19937_64 gen(6);
    const SE3<S> mean = SE3<S>::exp(Eigen::Matrix<S, 6, 1>::Constant(S(0.3)));
    const Eigen::Matrix<S, 6, 6> L = S(0.1) * Eigen::Matrix<S, 6, 6>::Identity();
    for (auto _ : st) benchmark::DoNotOptimize(random_gaussian(gen, mean, L));
  });

  // Means of 50 elements: chordal (closed form) and geodesic (Newton).
  constexpr std::size_t kCloud = 50;
  std::mt19937_64 gen(23);
  std::normal_distribution<double> normal(0, 0.5);
  const SE3<S> centre = SE3<S>::exp(xs[0]);
  std::vector<std::vector<SO3<S>>> Rclouds;
  std::vector<std::vector<SE3<S>>> gclouds;
  for (int c = 0; c < 8; ++c) {
    std::vector<SO3<S>> Rc;
    std::vector<SE3<S>> gc;
    for (std::size_t i = 0; i < kCloud; ++i) {
      Eigen::Matrix<S, 6, 1> e;
      for (int k = 0; k < 6; ++k) e[k] = S(normal(gen));
      Rc.push_back(centre.rotation() * SO3<S>::exp(V3(e.template tail<3>())));
      gc.push_back(centre * SE3<S>::exp(e));
    }
    Rclouds.push_back(std::move(Rc));
    gclouds.push_back(std::move(gc));
  }
  for (int c = 8; c < int(kN); ++c) {  // cycle the 8 clouds through the 1024 inputs
    Rclouds.push_back(Rclouds[std::size_t(c % 8)]);
    gclouds.push_back(gclouds[std::size_t(c % 8)]);
  }
  add("SO3/mean_chordal/cloud50/" + sn, Rclouds, [](const auto& v) { return chordal_mean(v.begin(), v.end()); });
  add("SO3/mean_geodesic/cloud50/" + sn, Rclouds, [](const auto& v) { return geodesic_mean(v.begin(), v.end()); });
  add("SE3/mean_chordal/cloud50/" + sn, gclouds, [](const auto& v) { return chordal_mean(v.begin(), v.end()); });
  add("SE3/mean_geodesic/cloud50/" + sn, gclouds, [](const auto& v) { return geodesic_mean(v.begin(), v.end()); });

  // Alignment of 50 points (a 3 x 2 x 1 box moved by a random similarity,
  // noise 0.01), beside Eigen::umeyama on the same points as 3 x 50 matrices.
  using Points = Eigen::Matrix<S, 3, 50>;
  struct PointSet {
    std::vector<V3> a, b;
    Points A, B;
  };
  std::vector<PointSet> sets;
  std::uniform_real_distribution<double> box(-1, 1);
  for (int c = 0; c < 8; ++c) {
    PointSet p;
    const Sim3<S> g(centre.rotation() * SO3<S>::exp(V3(ws[std::size_t(c)])), xs[std::size_t(c)].template head<3>(),
                    S(1.5));
    for (int i = 0; i < 50; ++i) {
      const V3 q = Eigen::Vector3d(3 * box(gen), 2 * box(gen), box(gen)).cast<S>();
      p.b.push_back(q);
      p.a.push_back(g * q + Eigen::Vector3d(0.01 * normal(gen), 0.01 * normal(gen), 0.01 * normal(gen)).cast<S>());
      p.A.col(i) = p.a.back();
      p.B.col(i) = q;
    }
    sets.push_back(std::move(p));
  }
  for (int c = 8; c < int(kN); ++c) sets.push_back(sets[std::size_t(c % 8)]);
  add("SO3/align/vectors50/" + sn, sets,
      [](const PointSet& p) { return so3_align(p.a.begin(), p.a.end(), p.b.begin()); });
  add("SE3/align/points50/" + sn, sets,
      [](const PointSet& p) { return se3_align(p.a.begin(), p.a.end(), p.b.begin()); });
  add("Sim3/align/points50/" + sn, sets,
      [](const PointSet& p) { return sim3_align(p.a.begin(), p.a.end(), p.b.begin()); });
  if constexpr (std::is_same<S, double>::value) {  // (float: GCC 12 -O3 warns inside Eigen's Umeyama.h)
    add("Eigen/umeyama_rigid/points50/" + sn, sets,
        [](const PointSet& p) { return Eigen::Matrix<S, 4, 4>(Eigen::umeyama(p.B, p.A, false)); });
    add("Eigen/umeyama/points50/" + sn, sets,
        [](const PointSet& p) { return Eigen::Matrix<S, 4, 4>(Eigen::umeyama(p.B, p.A, true)); });
  }
}

}  // namespace

/// SO2 and SE2: exp and log on generic, tiny (~1e-9) and near-pi angles with
/// their worst error against a long double reference (the closed forms with
/// sinl, cosl and atan2l, 1 - cos as 2 sin^2(theta/2): no cancellation),
/// compose, inverse and the action; the floor is one sincos (floor/sincos).
template <typename S>
void register_planar(const std::string& sn) {
  using namespace chasles;
  using ld = long double;
  using V2 = Eigen::Matrix<S, 2, 1>;
  using V3 = Eigen::Matrix<S, 3, 1>;
  std::mt19937_64 rng(31);
  std::normal_distribution<double> n(0, 1);
  std::uniform_real_distribution<double> u(0.1, 3.0), sign(-1, 1);
  for (const std::string kind : {"generic", "tiny", "near_pi"}) {
    std::vector<S> thetas;
    std::vector<V3> xs;
    for (std::size_t i = 0; i < kN; ++i) {
      const double a = kind == "tiny" ? 1e-9 * (1 + u(rng)) : kind == "near_pi" ? kPi - 1e-6 : u(rng);
      thetas.push_back(S(sign(rng) < 0 ? -a : a));
      xs.push_back(V3(S(n(rng)), S(n(rng)), thetas.back()));
    }
    add_measured<S>(
        "SO2/exp/" + kind + "/" + sn, thetas, [](S t) { return SO2<S>::exp(t); },
        [](S t, const SO2<S>& R) {
          return std::max(std::fabs(ld(R.complex()[0]) - std::cos(ld(t))),
                          std::fabs(ld(R.complex()[1]) - std::sin(ld(t))));
        });
    std::vector<SO2<S>> Rs;
    for (S t : thetas) Rs.push_back(SO2<S>::exp(t));
    add_measured<S>(
        "SO2/log/" + kind + "/" + sn, Rs, [](const SO2<S>& R) { return R.angle(); },
        [](const SO2<S>& R, S t) { return std::fabs(ld(t) - std::atan2(ld(R.complex()[1]), ld(R.complex()[0]))); });
    add_measured<S>(
        "SE2/exp/" + kind + "/" + sn, xs, [](const V3& xi) { return SE2<S>::exp(xi); },
        [](const V3& xi, const SE2<S>& g) {
          const ld w = xi[2], a = std::sin(w) / w, h = std::sin(w / 2), b = 2 * h * h / w;
          const ld tx = a * xi[0] - b * xi[1], ty = b * xi[0] + a * xi[1];
          const ld rot = std::max(std::fabs(ld(g.rotation().complex()[0]) - std::cos(w)),
                                  std::fabs(ld(g.rotation().complex()[1]) - std::sin(w)));
          const ld scale = std::max({std::fabs(tx), std::fabs(ty), ld(1e-300)});
          return std::max(rot,
                          std::max(std::fabs(g.translation()[0] - tx), std::fabs(g.translation()[1] - ty)) / scale);
        });
    std::vector<SE2<S>> gs;
    for (const V3& xi : xs) gs.push_back(SE2<S>::exp(xi));
    add_measured<S>(
        "SE2/log/" + kind + "/" + sn, gs, [](const SE2<S>& g) { return g.log(); },
        [](const SE2<S>& g, const V3& xi) {
          const ld c = g.rotation().complex()[0], s = g.rotation().complex()[1];
          const ld w = std::atan2(s, c), e = w / 2 * std::cos(w / 2) / std::sin(w / 2);
          const ld tx = g.translation()[0], ty = g.translation()[1];
          const ld vx = e * tx + w / 2 * ty, vy = e * ty - w / 2 * tx;
          const ld scale = std::max({std::fabs(vx), std::fabs(vy), ld(1e-300)});
          return std::max(std::fabs(xi[2] - w), std::max(std::fabs(xi[0] - vx), std::fabs(xi[1] - vy)) / scale);
        });
  }
  std::vector<SO2<S>> Rs;
  std::vector<SE2<S>> gs;
  for (std::size_t i = 0; i < kN; ++i) {
    Rs.push_back(SO2<S>::exp(S(u(rng))));
    gs.push_back(SE2<S>::exp(V3(S(n(rng)), S(n(rng)), S(u(rng)))));
  }
  std::vector<std::pair<SO2<S>, SO2<S>>> Rpairs;
  std::vector<std::pair<SE2<S>, SE2<S>>> gpairs;
  std::vector<std::pair<SE2<S>, V2>> gpoints;
  for (std::size_t i = 0; i < kN; ++i) {
    const std::size_t j = (i + 1) & (kN - 1);
    Rpairs.emplace_back(Rs[i], Rs[j]);
    gpairs.emplace_back(gs[i], gs[j]);
    gpoints.emplace_back(gs[i], gs[j].translation());
  }
  add("SO2/compose/generic/" + sn, Rpairs, [](const auto& p) { return p.first * p.second; });
  add("SE2/compose/generic/" + sn, gpairs, [](const auto& p) { return p.first * p.second; });
  add("SE2/inverse/generic/" + sn, gs, [](const SE2<S>& g) { return g.inverse(); });
  add("SE2/act/generic/" + sn, gpoints, [](const auto& p) { return V2(p.first * p.second); });
}

/// Sim3: exp and log on generic (angle in (0.1, 3), sigma in (-2, 2)), tiny
/// (angle and sigma ~1e-9: the double series) and near-pi angles, compose and
/// the action. (Accuracy: tests/cpp/test_sim3.cpp, against the long double
/// matrix exponential.)
template <typename S>
void register_sim3(const std::string& sn) {
  using namespace chasles;
  using V3 = Eigen::Matrix<S, 3, 1>;
  using V7 = Eigen::Matrix<S, 7, 1>;
  std::mt19937_64 rng(41);
  std::normal_distribution<double> n(0, 1);
  std::uniform_real_distribution<double> u(-2, 2);
  for (const std::string kind : {"generic", "tiny", "near_pi"}) {
    std::vector<V7> xs;
    for (const auto& w : rotation_vectors<S>(kind, 43)) {
      V7 xi;
      xi << S(n(rng)), S(n(rng)), S(n(rng)), w, S(kind == "tiny" ? 1e-9 * u(rng) : u(rng));
      xs.push_back(xi);
    }
    add("Sim3/exp/" + kind + "/" + sn, xs, [](const V7& xi) { return Sim3<S>::exp(xi); });
    std::vector<Sim3<S>> gs;
    for (const V7& xi : xs) gs.push_back(Sim3<S>::exp(xi));
    add("Sim3/log/" + kind + "/" + sn, gs, [](const Sim3<S>& g) { return g.log(); });
  }
  std::vector<Sim3<S>> gs;
  for (const auto& w : rotation_vectors<S>("generic", 44)) {
    V7 xi;
    xi << S(n(rng)), S(n(rng)), S(n(rng)), w, S(u(rng));
    gs.push_back(Sim3<S>::exp(xi));
  }
  std::vector<std::pair<Sim3<S>, Sim3<S>>> pairs;
  std::vector<std::pair<Sim3<S>, V3>> points;
  for (std::size_t i = 0; i < kN; ++i) {
    pairs.emplace_back(gs[i], gs[(i + 1) & (kN - 1)]);
    points.emplace_back(gs[i], gs[(i + 5) & (kN - 1)].translation());
  }
  add("Sim3/compose/generic/" + sn, pairs, [](const auto& p) { return p.first * p.second; });
  add("Sim3/act/generic/" + sn, points, [](const auto& p) { return V3(p.first * p.second); });
}

/// SE_2(3): exp and log at the three kinds of angles, compose and act.
template <typename S>
void register_se23(const std::string& sn) {
  using namespace chasles;
  using V3 = Eigen::Matrix<S, 3, 1>;
  using V9 = Eigen::Matrix<S, 9, 1>;
  std::mt19937_64 rng(51);
  std::normal_distribution<double> n(0, 1);
  const auto tangent = [&](const V3& w) {
    V9 xi;  // entry by entry (GCC 12's -Warray-bounds on comma initializers from 3-vectors)
    for (int i = 0; i < 6; ++i) xi[i] = S(n(rng));
    for (int i = 0; i < 3; ++i) xi[6 + i] = w[i];
    return xi;
  };
  for (const std::string kind : {"generic", "tiny", "near_pi"}) {
    std::vector<V9> xs;
    for (const auto& w : rotation_vectors<S>(kind, 53)) xs.push_back(tangent(w));
    add("SE23/exp/" + kind + "/" + sn, xs, [](const V9& xi) { return SE23<S>::exp(xi); });
    std::vector<SE23<S>> gs;
    for (const V9& xi : xs) gs.push_back(SE23<S>::exp(xi));
    add("SE23/log/" + kind + "/" + sn, gs, [](const SE23<S>& g) { return g.log(); });
  }
  std::vector<SE23<S>> gs;
  for (const auto& w : rotation_vectors<S>("generic", 54)) gs.push_back(SE23<S>::exp(tangent(w)));
  std::vector<std::pair<SE23<S>, SE23<S>>> pairs;
  std::vector<std::pair<SE23<S>, V3>> points;
  for (std::size_t i = 0; i < kN; ++i) {
    pairs.emplace_back(gs[i], gs[(i + 1) & (kN - 1)]);
    points.emplace_back(gs[i], gs[(i + 5) & (kN - 1)].translation());
  }
  add("SE23/compose/generic/" + sn, pairs, [](const auto& p) { return p.first * p.second; });
  add("SE23/act/generic/" + sn, points, [](const auto& p) { return V3(p.first * p.second); });
}

int main(int argc, char** argv) {
  register_all<double>("double");
  register_all<float>("float");
  register_statistics<double>("double");
  register_statistics<float>("float");
  register_planar<double>("double");
  register_planar<float>("float");
  register_sim3<double>("double");
  register_sim3<float>("float");
  register_se23<double>("double");
  register_se23<float>("float");
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
