// Jacobians against central finite differences of their defining
// identities, taken on the long double group: the one check of the
// operations' Jacobians for every group of the typed suites (test_groups,
// test_sim3).
#pragma once

#include <string>
#include <type_traits>

#include <gtest/gtest.h>
#include <Eigen/Core>

#include <chasles/chasles.hpp>

#include "support/group_traits.hpp"

namespace chasles_test {

/// Central differences of d -> f(d) (a vector of `rows` entries), d along
/// each of the D tangent axes, step 1e-6: truncation about 1e-12 and
/// rounding about 1e-13 on a long double group.
template <int D, typename F>
Eigen::Matrix<LD, Eigen::Dynamic, Eigen::Dynamic> central_differences(int rows, F f) {
  using TL = Eigen::Matrix<LD, D, 1>;
  const LD h = 1e-6L;
  Eigen::Matrix<LD, Eigen::Dynamic, Eigen::Dynamic> J(rows, D);
  for (int i = 0; i < D; ++i) {
    TL d = TL::Zero();
    d[i] = h;
    J.col(i) = (f(d) - f(TL(-d))) / (2 * h);
  }
  return J;
}

/// The tolerance of a Jacobian against central differences, in eps of S
/// (group_traits.hpp's `near`): 1e-9 absolute in double, a thousand times
/// the differences' own error; 1e3 eps in float.
template <typename S>
LD fd_tolerance() {
  return std::is_same<S, float>::value ? LD(1e3) : LD(1e-9) / eps<S>();
}

/// The Jacobians of log, inverse, compose, rplus, rminus, lplus, lminus,
/// between and the action (on a point of kPoint entries) at a, b and the
/// tangent y, each against the differences of its defining identity; and
/// interpolate's derivative in t, rminus(b, a), exactly. `at` names the
/// inputs in a failure's message.
template <typename G, int kPoint>
void expect_operation_jacobians(const G& a, const G& b, const typename G::Tangent& y, const std::string& at) {
  using S = typename G::Scalar;
  using GL = decltype(a.template cast<LD>());
  using TL = typename GL::Tangent;
  constexpr int D = G::DoF;
  const GL al = a.template cast<LD>(), bl = b.template cast<LD>();
  const TL yl = y.template cast<LD>();
  const LD k = fd_tolerance<S>();
  auto same = [&](const auto& J, const auto& ref, const char* what) {
    EXPECT_TRUE(near<S>(J, ref, k)) << what << " " << at;
  };
  auto fd = [](auto f) { return central_differences<D>(D, f); };
  same(log_jacobian(a), fd([&](const TL& d) { return TL(rplus(al, d).log() - al.log()); }), "log");
  same(inverse_jacobian(a), fd([&](const TL& d) { return TL(rminus(rplus(al, d).inverse(), al.inverse())); }),
       "inverse");
  const auto cj = compose_jacobians(a, b);
  same(cj.lhs, fd([&](const TL& d) { return TL(rminus(rplus(al, d) * bl, al * bl)); }), "compose a");
  same(cj.rhs, fd([&](const TL& d) { return TL(rminus(al * rplus(bl, d), al * bl)); }), "compose b");
  const auto rp = rplus_jacobians(a, y);
  same(rp.lhs, fd([&](const TL& d) { return TL(rminus(rplus(rplus(al, d), yl), rplus(al, yl))); }), "rplus g");
  same(rp.rhs, fd([&](const TL& d) { return TL(rminus(rplus(al, TL(yl + d)), rplus(al, yl))); }), "rplus xi");
  const auto rm = rminus_jacobians(a, b);
  same(rm.lhs, fd([&](const TL& d) { return TL(rminus(rplus(al, d), bl) - rminus(al, bl)); }), "rminus g");
  same(rm.rhs, fd([&](const TL& d) { return TL(rminus(al, rplus(bl, d)) - rminus(al, bl)); }), "rminus h");
  const auto lp = lplus_jacobians(y, a);
  same(lp.lhs, fd([&](const TL& d) { return TL(rminus(lplus(TL(yl + d), al), lplus(yl, al))); }), "lplus xi");
  same(lp.rhs, fd([&](const TL& d) { return TL(rminus(lplus(yl, rplus(al, d)), lplus(yl, al))); }), "lplus g");
  const auto lm = lminus_jacobians(a, b);
  same(lm.lhs, fd([&](const TL& d) { return TL(lminus(rplus(al, d), bl) - lminus(al, bl)); }), "lminus g");
  same(lm.rhs, fd([&](const TL& d) { return TL(lminus(al, rplus(bl, d)) - lminus(al, bl)); }), "lminus h");
  const auto bj = between_jacobians(a, b);
  same(bj.lhs, fd([&](const TL& d) { return TL(rminus(between(rplus(al, d), bl), between(al, bl))); }), "between a");
  same(bj.rhs, fd([&](const TL& d) { return TL(rminus(between(al, rplus(bl, d)), between(al, bl))); }), "between b");
  const Eigen::Matrix<LD, kPoint, 1> p = Eigen::Matrix<LD, kPoint, 1>::LinSpaced(0.3L, -1.7L);
  const auto aj = act_jacobians(a, Eigen::Matrix<S, kPoint, 1>(p.template cast<S>()));
  same(aj.group,
       central_differences<D>(kPoint, [&](const TL& d) { return Eigen::Matrix<LD, kPoint, 1>(rplus(al, d).act(p)); }),
       "act g");
  same(aj.point, to_ld(a.matrix().template topLeftCorner<kPoint, kPoint>()), "act p");
  EXPECT_TRUE(near<S>(interpolate_jacobian_t(a, b, S(0.3)), rminus(b, a), 0)) << at;
}

}  // namespace chasles_test
