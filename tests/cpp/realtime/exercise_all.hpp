// Calls every public operation of chasles once, for the real-time tests:
// test_no_allocation.cpp runs it with allocation forbidden, strict_compile.cpp
// runs it for the three scalars. Both link its one compile, exercise_*.cpp
// (the instantiations declared extern at the end of this file), built with
// -fno-exceptions -fno-rtti -Wpedantic -Werror (tests/cpp/CMakeLists.txt).
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <random>
#include <type_traits>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include <chasles/chasles.hpp>

namespace chasles_test {

/// Every operation a group has (its class, and lie_group.hpp's generic
/// functions) for the elements exp(x) and exp(y), and the series branch at
/// exp(x * 1e-9); returns a checksum.
template <typename G>
typename G::Scalar exercise_group(const typename G::Tangent& x, const typename G::Tangent& y) noexcept {
  using namespace chasles;
  using S = typename G::Scalar;
  using T = typename G::Tangent;
  const G g = G::exp(x), h = G::exp(y), e = G::identity(), tiny = G::exp(T(x * S(1e-9)));
  S sum = g.log().sum() + tiny.log().sum() + G::hat(x).sum() + G::vee(G::hat(x)).sum() + G::ad(x).sum();
  sum += (g * h).matrix().sum() + g.inverse().matrix().sum() + g.adjoint().sum() + e.matrix().sum();
  G m = g;
  m *= h;
  sum += m.matrix().sum() + G().matrix().sum();
  const auto checked = G::from_matrix(g.matrix());
  sum += checked ? checked->matrix().sum() : S(0);
  sum += G::from_matrix_unchecked(g.matrix()).matrix().sum();
  sum += G::from_matrix_projected(g.matrix() * S(1.01)).matrix().sum();
  sum += g.normalized().matrix().sum() + g.template cast<S>().matrix().sum();
  sum += S(g.is_approx(h, RealOf<S>(1e-6)) ? 1 : 0);
  sum += G::right_jacobian(x).sum() + G::left_jacobian(x).sum() + G::right_jacobian(T::Zero()).sum();
  sum += G::right_jacobian_inverse(x).sum() + G::left_jacobian_inverse(x).sum();
  sum += G::left_jacobian_inverse(T::Zero()).sum();
  sum += rplus(g, y).matrix().sum() + rminus(g, h).sum() + lplus(y, g).matrix().sum() + lminus(g, h).sum();
  sum += rplus(g, T(y * S(0.5))).matrix().sum() + between(g, h).matrix().sum();
  sum += interpolate(g, h, S(0.3)).matrix().sum() + interpolate(g, h, 0.25).matrix().sum();
  sum += interpolate_jacobian_t(g, h, S(0.3)).sum() + log_jacobian(g).sum() + inverse_jacobian(g).sum();
  const auto c = compose_jacobians(g, h);
  const auto rp = rplus_jacobians(g, y), rm = rminus_jacobians(g, h);
  const auto lp = lplus_jacobians(y, g), lm = lminus_jacobians(g, h), bt = between_jacobians(g, h);
  sum += c.lhs.sum() + c.rhs.sum() + rp.lhs.sum() + rp.rhs.sum() + rm.lhs.sum() + rm.rhs.sum();
  sum += lp.lhs.sum() + lp.rhs.sum() + lm.lhs.sum() + lm.rhs.sum() + bt.lhs.sum() + bt.rhs.sum();
  return sum;
}

/// What is written once over the groups (mean.hpp, distance.hpp,
/// random.hpp, spline.hpp, bspline.hpp) for the group G and the elements
/// exp(x), exp(y); returns a checksum.
template <typename G>
typename G::Scalar exercise_families(const typename G::Tangent& x, const typename G::Tangent& y) noexcept {
  using namespace chasles;
  using S = typename G::Scalar;
  using T = typename G::Tangent;
  using M = typename G::AdjointMatrix;
  const G g = G::exp(x), h = G::exp(y), e = G::identity();
  const std::array<G, 3> X{g, h, G::exp(T(x * S(0.2)))};
  const std::array<S, 3> ws{S(1), S(2), S(0.5)};
  const MeanResult<G> m = geodesic_mean(X.begin(), X.end(), ws.begin());
  const MeanResult<G> m1 = geodesic_mean(X.begin(), X.end(), 1);
  S sum = m.mean.matrix().sum() + S(m.iterations) + S(m.converged ? 1 : 0) + m1.mean.matrix().sum();
  sum += chordal_mean(X.begin(), X.end()).matrix().sum() + chordal_mean(X.begin(), X.end(), ws.begin()).matrix().sum();
  sum += S(mean_weights_valid(X.begin(), X.end(), ws.begin()) ? 1 : 0);
  const auto d = distance(g, h);  // a Scalar (rotation groups) or the parts' vector
  if constexpr (std::is_same<std::decay_t<decltype(d)>, S>::value) {
    sum += d;
  } else {
    sum += d.sum();
  }
  sum += gaussian_from_normals(g, M(M::Identity()), y).matrix().sum();
  using Parts = GroupParts<G>;
  using Rotation = typename Parts::Rotation;
  const typename Parts::Vector low = Parts::Vector::Constant(S(-1)), high = Parts::Vector::Constant(S(2));
  sum += element_from_uniforms<G>(Eigen::Matrix<S, UniformRotation<Rotation>::U, 1>::Constant(S(0.3)),
                                  Parts::Vector::Constant(S(0.6)), low, high)
             .matrix()
             .sum();
  // Gaussians (gaussian.hpp).
  const M cov = M::Identity() * S(0.01);
  const Gaussian<G> ga(g, cov), gb = Gaussian<G>::from_left(h, cov);
  sum += ga.inverse().cov().sum() + (ga * gb).cov().sum() + ga.compose(gb, cov).cov().sum() +
         ga.between(gb).cov().sum() + ga.between(gb, cov).cov().sum() + ga.left_covariance().sum() +
         ga.log().cov.sum() + ga.interpolate(gb, S(0.3)).cov().sum() + ga.mahalanobis(h) + ga.factor().sum();
  constexpr int P = GroupParts<G>::Rotation::DoF == 1 ? 2 : 3;  // the points of the plane or of space
  const Eigen::Matrix<S, P, 1> pt = Eigen::Matrix<S, P, 1>::Constant(S(0.5));
  sum += ga.act(pt).cov.sum() + ga.act(pt, Eigen::Matrix<S, P, P>::Identity()).cov.sum();
  if constexpr (std::is_floating_point<S>::value) {  // the standard distributions: real scalars only
    std::minstd_rand gen(11);
    sum += random_uniform<Rotation>(gen).matrix().sum() + random_gaussian(gen, g, M(M::Identity())).matrix().sum();
    sum += ga.sample(gen).matrix().sum();
    if constexpr (Parts::K > 0) sum += random_pose<G>(gen, low, high).matrix().sum();
  }
  // Splines over caller storage.
  const std::array<S, 3> ts{S(0), S(0.5), S(1.25)};
  std::array<SplineSegment<G>, 2> segments;
  std::array<SplineWork<G>, 3> work;
  const SplineFit natural = fit_spline(3, ts.data(), X.data(), segments.data(), work.data());
  const SplineFit chord = fit_spline(3, ts.data(), X.data(), segments.data(), work.data(), SplineEnds::chord);
  sum += S(natural.iterations + chord.iterations);
  const Spline<G> spline(3, ts.data(), X.data(), segments.data());
  const SplineSample<G> at = spline(S(0.7));
  sum += at.element.matrix().sum() + at.velocity.sum() + at.acceleration.sum() + spline.element(S(2)).matrix().sum();
  T rate, acceleration;
  spline_body_rates<G>(x, T(y * S(0.5)), T(x * S(-1)), rate, acceleration);
  sum += rate.sum() + acceleration.sum();
  // B-splines.
  const std::array<G, 5> control{g, h, e, g.inverse(), h};
  const CubicBSplineView<G> bspline(control.data(), 5, S(1), S(0.5));
  for (const S& t : {S(1.2), S(0), S(9)}) {
    const BSplinePoint<G> p = bspline.evaluate(t);
    sum += bspline(t).matrix().sum() + p.value.matrix().sum() + p.velocity.sum() + p.acceleration.sum();
  }
  sum += cubic_bspline_segment(control.begin(), S(0.4)).matrix().sum();
  return sum;
}

/// Every public operation of every class for one Scalar; returns a checksum
/// so that nothing is optimized away.
template <typename S>
S exercise_all() noexcept {
  using namespace chasles;
  using V3 = Eigen::Matrix<S, 3, 1>;
  using V6 = Eigen::Matrix<S, 6, 1>;
  using M3 = Eigen::Matrix<S, 3, 3>;
  S sum(0);
  const V3 w(S(0.3), S(-0.2), S(0.1)), p(S(1), S(2), S(3));
  const V6 xi = Twist<S>(p, w).vector();

  // SO3
  const SO3<S> R = SO3<S>::exp(w), I = SO3<S>::identity(), R0;
  sum += R.log().sum() + SO3<S>::exp(V3(S(3.14159), S(0), S(0))).log().sum();  // near pi branch
  sum += SO3<S>::exp(V3(S(1e-9), S(0), S(0))).log().sum();                   // series branch
  sum += SO3<S>::hat(w).sum() + SO3<S>::vee(SO3<S>::hat(w)).sum() + SO3<S>::ad(w).sum();
  sum += SO3<S>::bracket(w, p).sum();
  sum += (R * R.inverse()).matrix().sum() + (R * p).sum() + R.act(p).sum() + R.adjoint().sum();
  SO3<S> Rm = R;
  Rm *= R;
  sum += Rm.matrix().sum();
  sum += SO3<S>::from_quaternion(R.quaternion()).matrix().sum();
  sum += SO3<S>::rotation_defect(R.matrix());
  const auto checked = SO3<S>::from_matrix(R.matrix());
  sum += checked ? checked->matrix().sum() : S(0);
  sum += SO3<S>::from_matrix_unchecked(R.matrix()).matrix().sum();
  sum += SO3<S>::from_matrix_projected(M3(R.matrix() * S(1.01))).matrix().sum();
  sum += R.normalized().matrix().sum() + R.template cast<S>().matrix().sum();
  sum += S(R.is_approx(I, RealOf<S>(1e-3)) ? 1 : 0) + S(R0.is_approx(I, RealOf<S>(0)) ? 1 : 0);
  sum += interpolate(R, I, S(0.3)).matrix().sum();
  sum += R.angle() + I.angle() + distance(R, I);

  // Euler angles: one sequence of each kind, the lock branch and RPY
  sum += as_euler<EulerSequence::xyz>(R).angles.sum() + as_euler<EulerSequence::ZXZ>(R).angles.sum();
  sum += as_euler<EulerSequence::zyz>(I).angles.sum() + S(as_euler<EulerSequence::XYZ>(I).gimbal_lock ? 1 : 0);
  sum += from_euler<EulerSequence::yxy>(w).matrix().sum() + from_euler<EulerSequence::ZYX>(w).matrix().sum();
  sum += from_rpy(w[0], w[1], w[2]).matrix().sum() + as_rpy(R).angles.sum();

  // SE3
  const SE3<S> g = SE3<S>::exp(xi), h(R, p), e = SE3<S>::identity();
  sum += g.log().sum() + SE3<S>::exp(Twist<S>(xi)).translation().sum();
  sum += SE3<S>::hat(xi).sum() + SE3<S>::vee(SE3<S>::hat(xi)).sum() + SE3<S>::ad(xi).sum();
  sum += (g * h.inverse()).matrix().sum() + (g * p).sum() + g.act(p).sum() + g.adjoint().sum();
  SE3<S> gm = g;
  gm *= h;
  sum += gm.matrix().sum() + g.rotation().matrix().sum() + g.translation().sum();
  const Twist<S> tw(xi), tw2(p, w);
  const Wrench<S> F(xi), F2(p, w);
  sum += g.act(tw).vector().sum() + g.act_inv(tw).vector().sum();
  sum += g.act(F).vector().sum() + g.act_inv(F).vector().sum();
  sum += SE3<S>::transform_defect(g.matrix());
  const auto gc = SE3<S>::from_matrix(g.matrix());
  sum += gc ? gc->translation().sum() : S(0);
  sum += SE3<S>::from_matrix_unchecked(g.matrix()).translation().sum();
  sum += SE3<S>::from_matrix_projected(g.matrix()).translation().sum();
  sum += SE3<S>::from_screw(p, w, S(0.1), S(0.5)).translation().sum();
  sum += g.normalized().translation().sum() + g.template cast<S>().translation().sum();
  sum += S(g.is_approx(e, RealOf<S>(1e-3)) ? 1 : 0) + interpolate(g, h, S(0.7)).translation().sum();
  const SE3Distance<S> dgh = distance(g, h);
  sum += dgh.angle + dgh.translation;
  sum += so3_from_uniforms(V3(S(0.2), S(0.5), S(0.7))).matrix().sum() +
         so3_gaussian_from_normals(R, M3(M3::Identity()), w).matrix().sum();
  sum +=
      se3_gaussian_from_normals(g, Eigen::Matrix<S, 6, 6>(Eigen::Matrix<S, 6, 6>::Identity()), xi).translation().sum();
  {
    const Gaussian<SE3<S>> gg(g, Eigen::Matrix<S, 6, 6>::Identity() * S(0.01));
    sum += compose_fourth_order(gg, gg).cov().sum();
    sum += from_ros_covariance(g, to_ros_covariance(gg)).cov().sum();
  }
  {
    const std::array<SO3<S>, 3> Rs{R, I, SO3<S>::exp(p * S(0.1))};
    const std::array<SE3<S>, 3> gs{g, h, e};
    const std::array<S, 3> ws{S(1), S(2), S(0.5)};
    const MeanResult<SO3<S>> mr = geodesic_mean(Rs.begin(), Rs.end(), ws.begin());
    const MeanResult<SE3<S>> mg = geodesic_mean(gs.begin(), gs.end(), 5);
    sum += mr.mean.matrix().sum() + S(mr.iterations) + mg.mean.translation().sum() + S(mg.converged ? 1 : 0);
    sum += chordal_mean(Rs.begin(), Rs.end()).matrix().sum() +
           chordal_mean(gs.begin(), gs.end(), ws.begin()).translation().sum();
  }
  {  // alignment: Wahba (weights and none), the primary vector, one pair (acute, obtuse, opposite), points
    const std::array<V3, 4> b{p, w, V3(S(0), S(1), S(0)), V3(S(-1), S(0.5), S(2))};
    std::array<V3, 4> a;
    for (std::size_t i = 0; i < a.size(); ++i) a[i] = g * b[i];
    const std::array<S, 4> wa{S(1), S(2), S(0.5), S(1)};
    const std::array<S, 4> primary{S(1), S(std::numeric_limits<RealOf<S>>::infinity()), S(0.5), S(1)};
    const AlignResult<SO3<S>> r = so3_align(a.begin(), a.end(), b.begin(), wa.begin());
    const AlignResult<SO3<S>> rp = so3_align(a.begin(), a.end(), b.begin(), primary.begin());
    sum += r.transform.matrix().sum() + r.rssd + r.sensitivity.sum() + r.singular_values.sum();
    sum += rp.transform.matrix().sum() + rp.rssd + S(rp.has_sensitivity ? 1 : 0) + S(r ? 1 : 0);
    sum += so3_align(a.begin(), a.end(), b.begin()).transform.matrix().sum();
    const V3 minus_p = -p, nearly = V3(-p + V3(S(0), S(1e-3), S(0)));
    sum += so3_align(&w, &w + 1, &p).transform.matrix().sum() + so3_align(&p, &p + 1, &minus_p).rssd;
    sum += so3_align(&p, &p + 1, &nearly).transform.matrix().sum();
    const AlignResult<SE3<S>> rg = se3_align(a.begin(), a.end(), b.begin(), wa.begin());
    const AlignResult<Sim3<S>> rs = sim3_align(a.begin(), a.end(), b.begin());
    sum += rg.transform.matrix().sum() + rg.rssd + se3_align(a.begin(), a.end(), b.begin()).rssd;
    sum += rs.transform.matrix().sum() + rs.rssd + sim3_align(a.begin(), a.end(), b.begin(), wa.begin()).rssd;
    sum += S(se3_align(a.begin(), a.begin() + 2, b.begin()).status == AlignStatus::too_few ? 1 : 0);
  }
  if constexpr (std::is_floating_point<S>::value) {  // the standard distributions: real scalars only
    std::minstd_rand gen(7);
    sum += random_rotation<S>(gen).matrix().sum() + random_pose<S>(gen, -p, p).translation().sum();
    sum += random_gaussian(gen, R, M3(M3::Identity())).matrix().sum();
    sum += random_gaussian(gen, g, Eigen::Matrix<S, 6, 6>(Eigen::Matrix<S, 6, 6>::Identity())).translation().sum();
  }

  // Twist
  sum += tw.vector().sum() + tw.linear().sum() + tw.angular().sum() + tw2.to_modern_robotics().sum();
  sum += Twist<S>::from_modern_robotics(xi).vector().sum() + tw.hat().sum() + Twist<S>::vee(tw.hat()).vector().sum();
  sum += tw.ad().sum() + tw.bracket(tw2).vector().sum() + tw.pitch();
  const Screw<S> sc = tw.screw();
  sum += sc.point.sum() + sc.direction.sum() + sc.magnitude;
  sum += Twist<S>::from_screw(sc).vector().sum() + Twist<S>::from_screw(p, w, S(0), S(1)).vector().sum();
  sum += Twist<S>(V6(V6::Zero())).screw().magnitude + Twist<S>(p, V3::Zero()).screw().magnitude;
  sum += Twist<S>::spatial(g, g.matrix()).vector().sum() + Twist<S>::body(g, g.matrix()).vector().sum();
  sum += (tw + tw2 - tw * S(2) + S(3) * (-tw)).vector().sum() + tw.template cast<S>().vector().sum();
  sum += S(tw.is_approx(tw2, RealOf<S>(1e-6)) ? 1 : 0);

  // Wrench
  sum += F.vector().sum() + F.force().sum() + F.torque().sum() + F.power(tw) + power(tw2, F2) + F.pitch();
  const Screw<S> fs = F.screw();
  sum += Wrench<S>::from_screw(fs).vector().sum() + Wrench<S>::from_screw(p, w, S(0.2), S(2)).vector().sum();
  sum += (F + F2 - F * S(2) + S(3) * (-F)).vector().sum() + F.template cast<S>().vector().sum();
  sum += S(F.is_approx(F2, RealOf<S>(1e-6)) ? 1 : 0);

  // SO(2) and SE(2): the generic operations, and what only they have.
  using V2 = Eigen::Matrix<S, 2, 1>;
  using T1 = Eigen::Matrix<S, 1, 1>;
  sum += exercise_group<SO2<S>>(T1(S(0.7)), T1(S(-3.1))) + exercise_group<SE2<S>>(p, w);
  sum += exercise_families<SO2<S>>(T1(S(0.7)), T1(S(-3.1))) + exercise_families<SE2<S>>(p, w);
  const SO2<S> r2 = SO2<S>::exp(S(0.4));
  const SE2<S> g2 = SE2<S>::exp(w);
  sum += r2.angle() + r2.complex().sum() + r2.act(V2(p.template head<2>())).sum() + (r2 * V2(S(1), S(2))).sum();
  sum += SO2<S>::from_complex(S(3), S(4)).angle() + SO2<S>::from_complex_unchecked(S(1), S(0)).angle();
  sum += g2.act(V2(S(1), S(2))).sum() + (g2 * V2(S(1), S(2))).sum() + g2.rotation().angle();
  sum += g2.translation().sum() + SE2<S>(r2, V2(S(1), S(2))).matrix().sum() + SO2<S>::rotation_defect(r2.matrix());
  sum += SE2<S>::transform_defect(g2.matrix());
  const auto a1 = act_jacobians(r2, V2(S(1), S(2)));
  const auto a2 = act_jacobians(g2, V2(S(1), S(2)));
  sum += a1.group.sum() + a1.point.sum() + a2.group.sum() + a2.point.sum();

  // Sim(3): the generic operations, and what only it has.
  using V7 = Eigen::Matrix<S, 7, 1>;
  V7 x7, y7;  // entry by entry: a comma initializer from 3-vectors trips GCC 12's -Warray-bounds
  for (int i = 0; i < 3; ++i) {
    x7[i] = p[i], x7[3 + i] = w[i];
    y7[i] = w[i], y7[3 + i] = S(0.1) * p[i];
  }
  x7[6] = S(0.3), y7[6] = S(-0.2);
  sum += exercise_group<Sim3<S>>(x7, y7) + exercise_families<Sim3<S>>(x7, y7);
  const Sim3<S> s3 = Sim3<S>::exp(x7), s3h(R, p, S(2));
  sum += s3.act(p).sum() + (s3 * p).sum() + s3.rotation().matrix().sum() + s3.translation().sum() + s3.scale();
  sum += s3h.matrix().sum() + Sim3<S>::transform_defect(s3.matrix()) + Sim3<S>::matrix_scale(s3.matrix());
  sum += Sim3<S>::exp(V7(V7::Zero())).log().sum() + Sim3<S>::exp(V7(x7 * S(1e-3))).log().sum();

  // SE_2(3): the generic operations, and what only it has.
  using V9 = Eigen::Matrix<S, 9, 1>;
  V9 x9, y9;  // entry by entry, as x7
  for (int i = 0; i < 3; ++i) {
    x9[i] = p[i], x9[3 + i] = S(0.5) * w[i], x9[6 + i] = w[i];
    y9[i] = w[i], y9[3 + i] = S(-2) * p[i], y9[6 + i] = S(0.1) * p[i];
  }
  sum += exercise_group<SE23<S>>(x9, y9) + exercise_families<SE23<S>>(x9, y9);
  const SE23<S> x23 = SE23<S>::exp(x9), x23h(R, p, w);
  sum += x23.act(p).sum() + (x23 * p).sum() + x23.rotation().matrix().sum() + x23.translation().sum();
  sum += x23.velocity().sum() + x23h.matrix().sum() + SE23<S>::transform_defect(x23.matrix());
  const auto a23 = act_jacobians(x23, p);
  sum += a23.group.sum() + a23.point.sum();

  // Jacobians and plus / minus (jacobians.hpp), including the series branches.
  const V3 w0 = V3::Zero(), wpi(S(3.14159), S(0), S(0));
  const V6 xi0 = V6::Zero();
  sum += so3_right_jacobian(w).sum() + so3_left_jacobian(w).sum() + so3_right_jacobian(w0).sum();
  sum += so3_right_jacobian_inverse(w).sum() + so3_left_jacobian_inverse(w).sum();
  sum += so3_right_jacobian_inverse(wpi).sum() + so3_left_jacobian_inverse(w0).sum();
  sum += se3_right_jacobian(xi).sum() + se3_left_jacobian(xi).sum() + se3_left_jacobian(xi0).sum();
  sum += se3_right_jacobian_inverse(xi).sum() + se3_left_jacobian_inverse(xi).sum();
  sum += se3_right_jacobian_inverse(xi0).sum();
  sum += rplus(R, w).matrix().sum() + rminus(R, I).sum() + lplus(w, R).matrix().sum() + lminus(R, I).sum();
  sum += rplus(g, xi).translation().sum() + rminus(g, h).sum() + lplus(xi, g).translation().sum();
  sum += lminus(g, h).sum();
  sum += log_jacobian(R).sum() + log_jacobian(g).sum() + inverse_jacobian(R).sum() + inverse_jacobian(g).sum();
  const auto cr = compose_jacobians(R, I);
  const auto cg = compose_jacobians(g, h);
  sum += cr.lhs.sum() + cr.rhs.sum() + cg.lhs.sum() + cg.rhs.sum();
  const auto ar = act_jacobians(R, p);
  const auto ag = act_jacobians(g, p);
  sum += ar.group.sum() + ar.point.sum() + ag.group.sum() + ag.point.sum();
  sum += interpolate_jacobian_t(R, I, S(0.3)).sum() + interpolate_jacobian_t(g, h, S(0.3)).sum();
  const auto rpr = rplus_jacobians(R, w), rmr = rminus_jacobians(R, I), lpr = lplus_jacobians(w, R);
  const auto lmr = lminus_jacobians(R, I), btr = between_jacobians(R, I);
  sum += rpr.lhs.sum() + rpr.rhs.sum() + rmr.lhs.sum() + rmr.rhs.sum() + lpr.lhs.sum() + lpr.rhs.sum();
  sum += lmr.lhs.sum() + lmr.rhs.sum() + btr.lhs.sum() + btr.rhs.sum() + between(R, I).matrix().sum();
  const auto rpg = rplus_jacobians(g, xi), rmg = rminus_jacobians(g, h), lpg = lplus_jacobians(xi, g);
  const auto lmg = lminus_jacobians(g, h), btg = between_jacobians(g, h);
  sum += rpg.lhs.sum() + rpg.rhs.sum() + rmg.lhs.sum() + rmg.rhs.sum() + lpg.lhs.sum() + lpg.rhs.sum();
  sum += lmg.lhs.sum() + lmg.rhs.sum() + btg.lhs.sum() + btg.rhs.sum() + between(g, h).translation().sum();

  // Arguments in other types (detail/arguments.hpp): vector expressions, a
  // double vector, a Twist, t and factors as double and int literals.
  sum += rplus(R, w * S(0.5)).matrix().sum() + lplus(w * S(0.5), R).matrix().sum();
  sum += rplus(R, Eigen::Vector3d(0.1, 0.2, 0.3)).matrix().sum() + rplus(g, xi.template head<6>()).translation().sum();
  sum += rplus(g, tw).translation().sum() + lplus(tw, g).translation().sum() + lplus(xi * S(2), g).translation().sum();
  sum += interpolate(R, I, 0.25).matrix().sum() + interpolate(g, h, 1).translation().sum();
  sum += interpolate_jacobian_t(R, I, 0.5).sum() + interpolate_jacobian_t(g, h, 0.5).sum();
  sum += (tw * 2).vector().sum() + (0.5 * tw).vector().sum() + (F * 2).vector().sum() + (0.5 * F).vector().sum();

  // Chain (kinematics.hpp): fixed size, and dynamic with a compile-time bound.
  using C6 = Chain<S, 6>;
  using CD = Chain<S, Eigen::Dynamic, 8>;
  typename C6::Screws S6;
  for (int i = 0; i < 6; ++i)
    S6.col(i) = i % 3 == 2 ? C6::prismatic_screw(V3(w + V3::Constant(S(i))))
                           : C6::revolute_screw(V3(p * S(i)), V3(w + V3::Constant(S(i))));
  const C6 c6(S6, g);
  typename C6::JointVector th6;
  for (int i = 0; i < 6; ++i) th6(i) = S(0.1) * S(i + 1);
  sum += c6.forward(th6).translation().sum() + c6.forward_body(th6).translation().sum();
  sum += c6.jacobian_space(th6).sum() + c6.jacobian_body(th6).sum();
  sum += S(RealOf<S>(c6.n_joints())) + c6.space_screws().sum() + c6.body_screws().sum() + c6.home().translation().sum();
  typename CD::Screws SD(6, 7);
  SD.template leftCols<6>() = S6;
  SD.col(6) = CD::revolute_screw(p, w);
  const CD cd(SD, h);
  typename CD::JointVector thd(7);
  for (int i = 0; i < 7; ++i) thd(i) = S(-0.2) * S(i + 1);
  sum += cd.forward(thd).translation().sum() + cd.forward_body(thd).translation().sum();
  sum += cd.jacobian_space(thd).sum() + cd.jacobian_body(thd).sum();
  sum += S(RealOf<S>(cd.n_joints())) + cd.space_screws().sum() + cd.body_screws().sum() + cd.home().translation().sum();

  // Inverse kinematics (inverse_kinematics.hpp): with and without limits.
  const SE3<S> target = c6.forward(typename C6::JointVector(th6 * S(1.1)));
  const auto ik6 = inverse_kinematics(c6, target, th6);
  typename CD::JointVector ik_lo(7), ik_hi(7);
  ik_lo.setConstant(S(-2));
  ik_hi.setConstant(S(2));
  IKOptions<S> ik_options;
  ik_options.max_iterations = 5;
  const auto ikd =
      inverse_kinematics(cd, cd.forward(typename CD::JointVector(thd * S(0.9))), thd, ik_lo, ik_hi, ik_options);
  std::minstd_rand ik_gen(3);
  const auto ikr = inverse_kinematics(cd, target, thd, ik_lo, ik_hi, ik_options, ik_gen, 2);
  sum += ik6.q.sum() + ik6.error.sum() + S(ik6.iterations) + S(ikd.converged ? 1 : 0) + ikd.q.sum() + ikr.q.sum();
  sum += pose_error(c6, target, th6).sum() + pose_error_jacobian(cd, target, thd).sum();
  {
    // Fixed size with limits, seeded at a limit the step pushes past (the
    // active set holds it), an unreachable target (to the stall or the
    // bound), the restarts overload on the fixed chain, non-finite targets.
    typename C6::JointVector lo6 = C6::JointVector::Constant(S(-0.5)), hi6 = C6::JointVector::Constant(S(0.5));
    const SE3<S> beyond = c6.forward(typename C6::JointVector(C6::JointVector::Constant(S(-1))));
    const auto held =
        inverse_kinematics(c6, beyond, typename C6::JointVector(C6::JointVector::Constant(S(-0.5))), lo6, hi6);
    const SE3<S> far(R, V3(p * S(100)));
    const auto unreachable = inverse_kinematics(c6, far, th6, lo6, hi6);
    std::minstd_rand gen6(5);
    const auto restarted = inverse_kinematics(c6, far, th6, lo6, hi6, IKOptions<S>(), gen6, 1);
    const SE3<S> nan_target = SE3<S>::from_matrix_unchecked(Eigen::Matrix<S, 4, 4>::Constant(S(RealOf<S>(NAN))));
    const auto not_finite = inverse_kinematics(cd, nan_target, thd);
    sum += held.q.sum() + S(held.iterations) + unreachable.error.sum() + S(unreachable.iterations);
    // A time budget over unbounded restarts (the clock read, no allocation).
    IKOptions<S> timed;
    timed.max_time = 1e-4;
    timed.max_iterations = 3;
    const auto budget = inverse_kinematics(c6, far, th6, lo6, hi6, timed, gen6, 1 << 30);
    sum += restarted.q.sum() + S(restarted.converged ? 1 : 0) + S(not_finite.iterations);
    sum += budget.q.sum() + S(budget.total_iterations + budget.attempts + static_cast<int>(budget.status));
  }

  // Splines (spline.hpp) over caller storage, both groups and both end conditions.
  {
    const std::array<S, 3> ts{S(0), S(0.5), S(1.25)};
    const std::array<SO3<S>, 3> Rs{R, I, SO3<S>::exp(p * S(0.1))};
    const std::array<SE3<S>, 3> gs{g, h, e};
    std::array<SplineSegment<SO3<S>>, 2> sr;
    std::array<SplineSegment<SE3<S>>, 2> sg;
    std::array<SplineWork<SO3<S>>, 3> wr;
    std::array<SplineWork<SE3<S>>, 3> wg;
    const SplineFit fr = fit_spline(3, ts.data(), Rs.data(), sr.data(), wr.data());
    const SplineFit fg = fit_spline(3, ts.data(), gs.data(), sg.data(), wg.data(), SplineEnds::chord);
    sum += S(fr.iterations + fg.iterations) + S(fr.status == SplineStatus::ok ? 1 : 0);
    const SO3Spline<S> spr(3, ts.data(), Rs.data(), sr.data());
    const SE3Spline<S> spg(3, ts.data(), gs.data(), sg.data());
    const SplineSample<SO3<S>> a = spr(S(0.7));
    const SplineSample<SE3<S>> b = spg(S(-0.1));
    sum += a.element.matrix().sum() + a.velocity.sum() + a.acceleration.sum() + S(spr.size() + spr.segment(S(0.6)));
    sum += spr.element(S(0.3)).matrix().sum() + spg.element(S(2)).translation().sum();
    sum +=
        b.element.translation().sum() + b.velocity.sum() + b.acceleration.sum() + spg.sample(1, S(0.75)).velocity.sum();
    // The other end conditions, and the fits that refuse their input.
    const SplineFit fr2 = fit_spline(3, ts.data(), Rs.data(), sr.data(), wr.data(), SplineEnds::chord);
    const SplineFit fg2 = fit_spline(3, ts.data(), gs.data(), sg.data(), wg.data(), SplineEnds::natural);
    const std::array<S, 3> bad_ts{S(0), S(1), S(1)};
    const SplineFit few = fit_spline(1, ts.data(), Rs.data(), sr.data(), wr.data());
    const SplineFit unordered = fit_spline(3, bad_ts.data(), gs.data(), sg.data(), wg.data());
    sum += S(fr2.iterations + fg2.iterations + few.iterations + unordered.iterations);
    sum += S(int(few.status) + int(unordered.status));
    V3 rate_r, acc_r;
    V6 rate_g, acc_g;
    spline_body_rates<SO3<S>>(w, p, V3(w * S(2)), rate_r, acc_r);
    spline_body_rates<SE3<S>>(xi, V6(xi * S(0.5)), V6(xi * S(-1)), rate_g, acc_g);
    sum += rate_r.sum() + acc_r.sum() + rate_g.sum() + acc_g.sum();
  }

  // Time scalings and the joint trajectories they time (time_scaling.hpp):
  // each kind, inside the motion, at rest after it, and refused (NaN).
  {
    const TimeScaling<S> cubic = cubic_time_scaling(S(2), S(0.5)), quintic = quintic_time_scaling(S(2), S(1.5));
    const TimeScaling<S> ramp = trapezoidal_time_scaling(S(2), S(1.5), S(0.2));
    const TimeScaling<S> cruise = time_scaling(TimeScalingKind::trapezoidal, S(2), S(1), S(1.5));
    const TimeScaling<S> rest = time_scaling(TimeScalingKind::quintic, S(2), S(3));
    const TimeScaling<S> refused = time_scaling(TimeScalingKind::trapezoidal, S(2), S(1));  // no ratio: NaN
    for (const TimeScaling<S>& x : {cubic, quintic, ramp, cruise, rest}) sum += x.s + x.s_dot + x.s_ddot;
    sum += S(std::isnan(RealType<S>::value(refused.s)) ? 1 : 0);
    const JointTrajectoryPoint<typename C6::JointVector> p6 =
        joint_trajectory(th6, typename C6::JointVector(th6 * S(2)), quintic);
    const JointTrajectoryPoint<typename CD::JointVector> pd =
        joint_trajectory(thd, typename CD::JointVector(-thd), ramp);
    sum += p6.q.sum() + p6.qd.sum() + p6.qdd.sum() + pd.q.sum() + pd.qd.sum() + pd.qdd.sum();
  }

  // Cubic B-splines (bspline.hpp): the segment evaluators, the view, and a
  // time inside, before the start, after the end.
  {
    const std::array<SO3<S>, 5> Rs{R, I, SO3<S>::exp(p * S(0.1)), R.inverse(), R};
    const std::array<SE3<S>, 5> gs{g, h, e, g.inverse(), h};
    const auto bb = cubic_bspline_basis(S(0.3));
    sum += bb.value.sum() + bb.first.sum() + bb.second.sum();
    sum += cubic_bspline_segment(Rs.begin(), S(0.4)).matrix().sum() +
           cubic_bspline_segment(gs.data(), S(0.4)).translation().sum();
    const BSplinePoint<SE3<S>> pg = cubic_bspline_segment_derivatives(gs.begin() + 1, S(0.6), S(0.5));
    sum += pg.value.translation().sum() + pg.velocity.sum() + pg.acceleration.sum();
    const BSplinePoint<SO3<S>> pr0 = cubic_bspline_segment_derivatives(Rs.data(), S(0), S(2));
    sum += pr0.value.matrix().sum() + pr0.velocity.sum() + pr0.acceleration.sum();
    const SO3BSplineView<S> rs(Rs.data(), 5, S(1), S(0.5));
    const SE3BSplineView<S> ss(gs.data(), 5, S(1), S(0.5));
    for (const S& t : {S(1.2), S(1.7), S(0), S(9)}) {
      const BSplinePoint<SO3<S>> pr = rs.evaluate(t);
      sum += rs(t).matrix().sum() + pr.value.matrix().sum() + pr.velocity.sum() + pr.acceleration.sum();
      sum += ss(t).translation().sum() + ss.evaluate(t).acceleration.sum() + rs.locate(t).u;
    }
    sum += rs.start_time() + rs.spacing() + rs.end_time() + S(RealOf<S>(rs.size() + rs.segments()));
    sum += ss.control()->translation().sum();
  }

  // The robot model: types, limits, base, tool, gravity, validate().
  typename CD::JointTypes types{};
  types.fill(chasles::JointType::revolute);
  types[2] = chasles::JointType::prismatic;
  types[5] = chasles::JointType::continuous;
  typename CD::JointVector lo = CD::JointVector::Constant(7, S(-2)), hi = CD::JointVector::Constant(7, S(2));
  const CD model(SD, h, types, lo, hi, CD::JointVector::Constant(7, S(3)), CD::JointVector::Constant(7, S(50)), g, h,
                 CD::default_gravity());
  const chasles::ChainCheck check = model.validate();
  sum += S(RealOf<S>(int(check.status) + int(check.joint))) + S(RealOf<S>(int(model.joint_type(2))));
  sum += model.lower().sum() + model.upper().sum() + model.velocity_limits().sum() + model.effort_limits().sum();
  sum += model.base().translation().sum() + model.tool().translation().sum() + model.gravity().sum();
  sum += model.forward(thd).translation().sum() + model.jacobian_body(thd).sum();
  const CD again(model.space_screws(), model.home(), typename CD::HomeAsGiven());
  sum += again.body_screws().sum() + S(RealOf<S>(int(model.joint_types()[5])));
  {
    // The fixed-size model (valid: unit axes, zero pitch), and validate()
    // reaching each of its refusals.
    typename C6::Screws U6;
    for (int i = 0; i < 6; ++i)
      U6.col(i) = i == 2 ? C6::prismatic_screw(V3::UnitX()) : C6::revolute_screw(V3(p * S(0.1 * i)), V3::Unit(i % 3));
    typename C6::JointTypes types6{};
    types6.fill(JointType::revolute);
    types6[2] = JointType::prismatic;
    const typename C6::JointVector lo6 = C6::JointVector::Constant(S(-1)), hi6 = C6::JointVector::Constant(S(1)),
                                   big6 = C6::JointVector::Constant(S(10));
    const C6 model6(U6, g, types6, lo6, hi6, big6, big6, h, e, V3(V3::UnitZ()));
    const ChainCheck ok6 = model6.validate();
    sum += S(RealOf<S>(int(ok6.status) + int(ok6.joint) + (ok6 ? 1 : 0))) + model6.forward(th6).translation().sum();
    sum += model6.jacobian_space(th6).sum() + model6.lower().sum() + model6.gravity().sum();
    sum += model6.base().translation().sum() + model6.tool().translation().sum();
    typename C6::JointTypes rotating = types6, continuous = types6;
    rotating[0] = JointType::prismatic;  // joint 0 rotates
    continuous[1] = JointType::continuous;  // with finite limits
    typename C6::Screws long_axis = U6, pitched = U6, long_slide = U6;
    long_axis.col(0).template tail<3>() *= S(2);
    pitched.col(0).template head<3>() += long_axis.col(0).template tail<3>();
    long_slide.col(2) *= S(2);
    const ChainCheck refusals[] = {
        C6(long_axis, g, types6, lo6, hi6, big6, big6).validate(),
        C6(pitched, g, types6, lo6, hi6, big6, big6).validate(),
        C6(U6, g, rotating, lo6, hi6, big6, big6).validate(),
        C6(long_slide, g, types6, lo6, hi6, big6, big6).validate(),
        C6(U6, g, types6, hi6, lo6, big6, big6).validate(),
        C6(U6, g, continuous, lo6, hi6, big6, big6).validate(),
        C6(U6, g, types6, lo6, hi6, typename C6::JointVector(-big6), big6).validate(),
        C6(U6, g, types6, lo6, hi6, big6, big6, e, e, V3(V3::Constant(S(RealOf<S>(INFINITY))))).validate(),
    };
    for (const ChainCheck& r : refusals) sum += S(RealOf<S>(int(r.status) + int(r.joint)));
  }

  // SpatialInertia (spatial_inertia.hpp).
  M3 Ic;
  Ic << S(2), S(0.1), S(0), S(0.1), S(3), S(0.2), S(0), S(0.2), S(4);
  const SpatialInertia<S> si(S(1.5), p, Ic), si0;
  sum += si.mass() + si.com().sum() + si.inertia().sum() + si.matrix().sum() + si0.mass();
  sum += SpatialInertia<S>::from_matrix_unchecked(si.matrix()).inertia().sum();
  sum += si.momentum(tw).vector().sum() + si.kinetic_energy(tw) + si.symmetry_defect();
  sum += si.transform(g).com().sum() + si.transform_inv(g).com().sum() + (si + si.transform(g)).inertia().sum();
  sum += S(si.is_physical() ? 1 : 0) + S(si.is_physical(RealOf<S>(0)) ? 1 : 0) + si.template cast<S>().mass();
  sum += S(si.is_approx(si0, RealOf<S>(1e-3)) ? 1 : 0);
  {
    // is_physical's refusals: mass, a non-finite centre, asymmetry, an
    // indefinite I_c, the triangle inequality, I_c = 0.
    M3 asym = Ic, flat = Ic, tri = M3::Zero();
    asym(0, 1) = S(1);
    flat(2, 2) = S(-4);
    tri.diagonal() << S(1), S(1), S(3);
    const SpatialInertia<S> bodies[] = {
        SpatialInertia<S>(S(-1), p, Ic),  SpatialInertia<S>(S(1), V3(V3::Constant(S(RealOf<S>(NAN)))), Ic),
        SpatialInertia<S>(S(1), p, asym), SpatialInertia<S>(S(1), p, flat),
        SpatialInertia<S>(S(1), p, tri),  SpatialInertia<S>(S(1), p, M3(M3::Zero()))};
    for (const SpatialInertia<S>& b : bodies) sum += S(b.is_physical() ? 1 : 0) + b.symmetry_defect();
  }

  // Dynamics (dynamics.hpp, free functions of a Chain): fixed size, and dynamic with a compile-time bound.
  using D6 = Chain<S, 6>;
  using DD = Chain<S, Eigen::Dynamic, 8>;
  typename D6::Inertias I6;
  typename DD::Inertias ID;
  for (std::size_t i = 0; i < 8; ++i) {
    if (i < 6) I6[i] = si.transform(SE3<S>::exp(V6(xi * S(RealOf<S>(i) * RealOf<S>(0.1)))));
    ID[i] = si.transform(SE3<S>::exp(V6(xi * S(RealOf<S>(i) * RealOf<S>(-0.1)))));
  }
  const V3 gravity(S(0), S(0), S(-9.81));
  const Wrench<S> tip(p, w);
  D6 d6(S6, g, typename D6::HomeAsGiven(), I6, gravity);
  const typename D6::JointVector qd6 = th6 * S(2), qdd6 = th6 * S(-3);
  sum += inverse_dynamics(d6, th6, qd6, qdd6).sum() + inverse_dynamics(d6, th6, qd6, qdd6, tip).sum();
  sum += mass_matrix(d6, th6).sum() + gravity_torques(d6, th6).sum() + coriolis(d6, th6, qd6).sum();
  sum += bias(d6, th6, qd6).sum() + forward_dynamics(d6, th6, qd6, qdd6).qdd.sum() +
         forward_dynamics(d6, th6, qd6, qdd6, tip).qdd.sum();
  sum += kinetic_energy(d6, th6, qd6) + potential_energy(d6, th6);
  sum += S(RealOf<S>(d6.n_joints())) + d6.space_screws().sum() + d6.home().translation().sum() +
         d6.link_inertias()[0].mass() + d6.gravity().sum();
  const DD dd(SD, h, ID, gravity);
  const typename DD::JointVector qdd = thd * S(2), qddd = thd * S(-3);
  sum += inverse_dynamics(dd, thd, qdd, qddd, tip).sum() + mass_matrix(dd, thd).sum() + gravity_torques(dd, thd).sum();
  sum += coriolis(dd, thd, qdd).sum() + bias(dd, thd, qdd).sum() + forward_dynamics(dd, thd, qdd, qddd, tip).qdd.sum();
  sum += kinetic_energy(dd, thd, qdd) + potential_energy(dd, thd);
  // Their derivatives and M(q)^-1 (dynamics_derivatives.hpp), both sizes.
  {
    const auto id6 = inverse_dynamics_derivatives(d6, th6, qd6, qdd6, tip);
    const auto fd6 = forward_dynamics_derivatives(d6, th6, qd6, qdd6, tip);
    const auto mi6 = mass_matrix_inverse(d6, th6);
    sum += id6.dtau_dq.sum() + id6.dtau_dqd.sum() + fd6.dqdd_dq.sum() + fd6.dqdd_dqd.sum() + fd6.dqdd_dtau.sum();
    sum += mi6.inverse.sum() + S(RealOf<S>(int(fd6.status) + int(fd6.joint) + (fd6 ? 1 : 0) + (mi6 ? 1 : 0)));
    const auto idd = inverse_dynamics_derivatives(dd, thd, qdd, qddd);
    const auto fdd = forward_dynamics_derivatives(dd, thd, qdd, qddd);
    sum += idd.dtau_dq.sum() + idd.dtau_dqd.sum() + fdd.dqdd_dq.sum() + mass_matrix_inverse(dd, thd).inverse.sum();
    sum += forward_dynamics_articulated(d6, th6, qd6, qdd6, tip).qdd.sum() +
           forward_dynamics_articulated(dd, thd, qdd, qddd).qdd.sum();
    sum += forward_dynamics_composite(d6, th6, qd6, qdd6, tip).qdd.sum() +
           forward_dynamics_composite(dd, thd, qdd, qddd).qdd.sum();
    sum += d6.jacobian_space_dot(th6, qd6).sum() + d6.jacobian_body_dot(th6, qd6).sum();
    sum += dd.jacobian_space_dot(thd, qdd).sum() + dd.jacobian_body_dot(thd, qdd).sum();
  }
  // A helical joint, and validate() with screws of any norm.
  {
    typename C6::Screws H6 = S6;
    H6.col(1).template head<3>() += S(0.1) * H6.col(1).template tail<3>();
    H6.col(3) *= S(2);
    const C6 helical(H6, g);
    sum += S(RealOf<S>(int(helical.joint_type(1)) + int(helical.validate(chasles::ScrewNorms::any).status)));
    sum += helical.forward(th6).translation().sum() + helical.jacobian_body(th6).sum();
  }
  // A Chain carrying its link inertias (moved by its base frame), and its Dynamics.
  const CD heavy(SD, h, types, lo, hi, CD::JointVector::Constant(7, S(3)), CD::JointVector::Constant(7, S(50)), g, h,
                 CD::default_gravity(), ID);
  sum += heavy.link_inertias()[3].com().sum() + model.link_inertias()[0].mass();
  sum += S(RealOf<S>(int(heavy.validate().status)));
  const DD from_chain(heavy);
  sum += inverse_dynamics(from_chain, thd, qdd, qddd, tip).sum() + mass_matrix(from_chain, thd).sum();
  return sum;
}

/// The autodiff scalar of the exercise.
using AutoDiff = Eigen::AutoDiffScalar<Eigen::Matrix<double, 6, 1>>;

/// The value of an exercise's checksum, as a double.
inline double real_value(double x) noexcept { return x; }
inline double real_value(const AutoDiff& x) noexcept { return x.value(); }

// Instantiated once, in exercise_float.cpp, exercise_double.cpp and
// exercise_autodiff.cpp: the files that include this one
// do not compile the exercise again.
extern template float exercise_all<float>() noexcept;
extern template double exercise_all<double>() noexcept;
extern template AutoDiff exercise_all<AutoDiff>() noexcept;

}  // namespace chasles_test
