// chasles: what every Lie group of the library shares, written once over its
// interface: interpolation, the plus and minus operators, between, and the
// Jacobians of the group operations (right convention).
//
// A group G (SO2, SE2, SO3, SE3) provides: Scalar, DoF, Tangent (a DoF-vector)
// and AdjointMatrix (DoF x DoF); exp(Tangent), log(), inverse(), operator*,
// adjoint(); the static Jacobians of exp right_jacobian, left_jacobian,
// right_jacobian_inverse and left_jacobian_inverse. What follows is written
// in those terms only, so that a new group gets it by defining them.
//
// Convention: right (local) perturbations, as manif and Pinocchio. For
// f: G -> H the Jacobian J is defined by
//   f(X exp(dx)) = f(X) exp(J dx + o(dx)),
// (Sola, Deray and Atchuthan, "A micro Lie theory for state estimation in
// robotics", 2018, arXiv:1812.01537: "Sola" below, sections III and IV).
//
// Argument order: rplus(g, xi) = g exp(xi) and rminus(g, h) = log(h^-1 g),
// so that rplus(h, rminus(g, h)) == g: "g minus h", as manif's
// g.rminus(h) = log(h^-1 g). (jaxlie's rminus(a, b) = log(a^-1 b) takes the
// other order.) The left versions: lplus(xi, g) = exp(xi) g and
// lminus(g, h) = log(g h^-1), so that lplus(lminus(g, h), h) == g.
//
// Beside a vector of the group's own Tangent type, the tangent vector of
// rplus and lplus may be any Eigen vector expression of the right size
// (0.1 * dx, a Map, a segment), of any scalar type that converts to the
// group's; it is converted explicitly (detail/arguments.hpp).
#pragma once

#include <type_traits>

#include <Eigen/Core>

#include "chasles/detail/arguments.hpp"

namespace chasles {
namespace detail {

/// Whether G is a Lie group of the library (has Tangent, AdjointMatrix and DoF).
template <typename G, typename = void>
struct IsLieGroup : std::false_type {};
template <typename G>
struct IsLieGroup<G, std::void_t<typename G::Tangent, typename G::AdjointMatrix, decltype(G::DoF)>> : std::true_type {};
template <typename G>
using EnableIfLieGroup = std::enable_if_t<IsLieGroup<G>::value, int>;

/// The group G over another scalar: SE2<double> -> SE2<T> (the splines'
/// dual numbers, the Python bindings' float32 kernels).
template <typename G, typename T>
struct WithScalar;
template <template <typename> class G, typename S, typename T>
struct WithScalar<G<S>, T> {
  using type = G<T>;
};

}  // namespace detail

/// Geodesic interpolation: a exp(t log(a^-1 b)); t = 0 gives a, t = 1 gives b
/// (slerp for rotations, one screw motion for rigid motions).
template <typename G, detail::EnableIfLieGroup<G> = 0>
inline G interpolate(const G& a, const G& b, const typename G::Scalar& t) noexcept {
  return a * G::exp(typename G::Tangent(t * (a.inverse() * b).log()));
}
/// The same with t of another arithmetic type, converted to the Scalar
/// (interpolate(a, b, 0.5) for float groups).
template <typename G, typename T, detail::EnableIfLieGroup<G> = 0,
          detail::EnableIfOtherArithmetic<typename G::Scalar, T> = 0>
inline G interpolate(const G& a, const G& b, const T& t) noexcept {
  return interpolate(a, b, detail::scalar_of<typename G::Scalar>(t));
}

// ---- plus and minus -------------------------------------------------------

/// g rplus xi = g exp(xi).
template <typename G, detail::EnableIfLieGroup<G> = 0>
inline G rplus(const G& g, const typename G::Tangent& xi) noexcept {
  return g * G::exp(xi);
}
template <typename G, typename Derived, detail::EnableIfLieGroup<G> = 0>
inline G rplus(const G& g, const Eigen::MatrixBase<Derived>& xi) noexcept {
  return rplus(g, detail::tangent_of<typename G::Scalar, G::DoF>(xi));
}

/// g rminus h = log(h^-1 g): the xi with h exp(xi) = g.
template <typename G, detail::EnableIfLieGroup<G> = 0>
inline typename G::Tangent rminus(const G& g, const G& h) noexcept {
  return (h.inverse() * g).log();
}

/// xi lplus g = exp(xi) g.
template <typename G, detail::EnableIfLieGroup<G> = 0>
inline G lplus(const typename G::Tangent& xi, const G& g) noexcept {
  return G::exp(xi) * g;
}
template <typename Derived, typename G, detail::EnableIfLieGroup<G> = 0>
inline G lplus(const Eigen::MatrixBase<Derived>& xi, const G& g) noexcept {
  return lplus(detail::tangent_of<typename G::Scalar, G::DoF>(xi), g);
}

/// g lminus h = log(g h^-1): the xi with exp(xi) h = g.
template <typename G, detail::EnableIfLieGroup<G> = 0>
inline typename G::Tangent lminus(const G& g, const G& h) noexcept {
  return (g * h.inverse()).log();
}

/// between(a, b) = a^-1 b, the motion from a to b.
template <typename G, detail::EnableIfLieGroup<G> = 0>
inline G between(const G& a, const G& b) noexcept {
  return a.inverse() * b;
}

// ---- Jacobians of the group operations (right convention) ----------------

/// d log(g) / dg = J_r(log g)^-1   (Sola section IV).
template <typename G, detail::EnableIfLieGroup<G> = 0>
inline typename G::AdjointMatrix log_jacobian(const G& g) noexcept {
  return G::right_jacobian_inverse(g.log());
}

/// d(g^-1) / dg = -Ad_g   (Sola section IV).
template <typename G, detail::EnableIfLieGroup<G> = 0>
inline typename G::AdjointMatrix inverse_jacobian(const G& g) noexcept {
  return -g.adjoint();
}

/// The two Jacobians of a composition a * b.
template <typename Matrix>
struct ComposeJacobians {
  Matrix lhs;  ///< d(a b) / da = Ad_{b^-1}
  Matrix rhs;  ///< d(a b) / db = I
};

template <typename G, detail::EnableIfLieGroup<G> = 0>
inline ComposeJacobians<typename G::AdjointMatrix> compose_jacobians(const G& /*a*/, const G& b) noexcept {
  return {b.inverse().adjoint(), G::AdjointMatrix::Identity()};
}

/// The two Jacobians of a function of two arguments f(x, y), right-local in
/// both: f(x (+) dx, y (+) dy) = f(x, y) (+) (J_x dx + J_y dy + o(dx, dy)),
/// where (+) is rplus on a group and + on a tangent vector.
template <typename Matrix>
struct BinaryJacobians {
  Matrix lhs;  ///< d f / d(first argument)
  Matrix rhs;  ///< d f / d(second argument)
};

/// rplus(g, xi) = g exp(xi):  J_g = Ad_{exp(xi)}^-1 = Ad_{exp(-xi)},  J_xi = J_r(xi)
/// (Sola section IV: g exp(dg) exp(xi) = g exp(xi) exp(Ad_{exp(-xi)} dg)).
template <typename G, detail::EnableIfLieGroup<G> = 0>
inline BinaryJacobians<typename G::AdjointMatrix> rplus_jacobians(const G& /*g*/,
                                                                  const typename G::Tangent& xi) noexcept {
  return {G::exp(xi).inverse().adjoint(), G::right_jacobian(xi)};
}

/// rminus(g, h) = log(h^-1 g) = xi:  J_g = J_r(xi)^-1,  J_h = -J_l(xi)^-1
/// (Sola section IV; the Jacobians of the branch log returns).
template <typename G, detail::EnableIfLieGroup<G> = 0>
inline BinaryJacobians<typename G::AdjointMatrix> rminus_jacobians(const G& g, const G& h) noexcept {
  using Matrix = typename G::AdjointMatrix;
  const typename G::Tangent xi = rminus(g, h);
  return {G::right_jacobian_inverse(xi), Matrix(-G::left_jacobian_inverse(xi))};
}

/// lplus(xi, g) = exp(xi) g:  J_xi = Ad_{g^-1} J_r(xi),  J_g = I.
/// exp(xi + dxi) g = exp(J_l dxi) exp(xi) g = exp(xi) g exp(Ad_{(exp(xi) g)^-1} J_l dxi),
/// and Ad_{g^-1} Ad_{exp(-xi)} J_l(xi) = Ad_{g^-1} J_r(xi) (J_r = Ad_{exp(-xi)} J_l, Sola section III).
template <typename G, detail::EnableIfLieGroup<G> = 0>
inline BinaryJacobians<typename G::AdjointMatrix> lplus_jacobians(const typename G::Tangent& xi, const G& g) noexcept {
  using Matrix = typename G::AdjointMatrix;
  return {Matrix(g.inverse().adjoint() * G::right_jacobian(xi)), Matrix::Identity()};
}

/// lminus(g, h) = log(g h^-1) = xi:  J_g = J_r(xi)^-1 Ad_h,  J_h = -J_r(xi)^-1 Ad_h.
/// g exp(dg) h^-1 = exp(xi) exp(Ad_h dg), so d xi = J_r(xi)^-1 Ad_h dg; and
/// g (h exp(dh))^-1 = exp(xi) exp(-Ad_h dh)   (Sola section IV).
template <typename G, detail::EnableIfLieGroup<G> = 0>
inline BinaryJacobians<typename G::AdjointMatrix> lminus_jacobians(const G& g, const G& h) noexcept {
  using Matrix = typename G::AdjointMatrix;
  const Matrix J = G::right_jacobian_inverse(lminus(g, h)) * h.adjoint();
  return {J, Matrix(-J)};
}

/// between(a, b) = a^-1 b:  J_a = -Ad_{b^-1 a},  J_b = I
/// ((a exp(da))^-1 b = exp(-da) a^-1 b = a^-1 b exp(-Ad_{b^-1 a} da); Sola section IV, manif's between).
template <typename G, detail::EnableIfLieGroup<G> = 0>
inline BinaryJacobians<typename G::AdjointMatrix> between_jacobians(const G& a, const G& b) noexcept {
  using Matrix = typename G::AdjointMatrix;
  return {Matrix(-(b.inverse() * a).adjoint()), Matrix::Identity()};
}

/// d interpolate(a, b, t) / dt in the right-local convention:
///   a exp((t + dt) xi) = a exp(t xi) exp(J_r(t xi) xi dt),  xi = log(a^-1 b) = b rminus a,
/// and J_r(t xi) xi = xi exactly (ad_xi xi = 0: every power of ad_{t xi}
/// annihilates xi), so the rate is the constant tangent xi (t of any
/// arithmetic type).
template <typename G, typename T, detail::EnableIfLieGroup<G> = 0>
inline typename G::Tangent interpolate_jacobian_t(const G& a, const G& b, const T& /*t*/) noexcept {
  return rminus(b, a);
}

}  // namespace chasles
