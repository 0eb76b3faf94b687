// chasles._core: the module-level functions of the Lie groups, each written
// once and overloaded for SO2, SE2, SO3, Sim3, SE23 and SE3 (include/chasles/lie_group.hpp): rplus,
// rminus, lplus, lminus, between, interpolate, and the Jacobians of the group
// operations in the right-local convention (log_jacobian, inverse_jacobian,
// compose_jacobians, act_jacobians, rplus_jacobians, rminus_jacobians,
// lplus_jacobians, lminus_jacobians, between_jacobians,
// interpolate_jacobian_t); and the array functions so3_act_jacobian,
// se3_act_jacobian and, for every group, <g>_compose_jacobians,
// <g>_between_jacobians and <g>_rminus_jacobians. The classes' own
// Jacobians are in lie_group.hpp.
#include <chasles/jacobians.hpp>

#include <string>
#include <tuple>
#include <type_traits>

#include "bindings.hpp"
#include "convert.hpp"
#include "lie_group.hpp"
#include "ufunc.hpp"

namespace chasles_py {

namespace {

using chasles::SE23d;
using chasles::SE2d;
using chasles::SE3d;
using chasles::Sim3d;
using chasles::SO2d;
using chasles::SO3d;
using Matrices = std::tuple<py::array_t<double>, py::array_t<double>>;

/// The (lhs, rhs) Jacobians of a binary function as two arrays.
template <typename J>
Matrices pair(const J& j) {
  return Matrices(mat_out(j.lhs), mat_out(j.rhs));
}

/// Defines rplus, ..., interpolate_jacobian_t for the group G: called for
/// SO2, SE2, SO3, Sim3, SE23, then SE3, which makes each function an overload set in that
/// order. pybind11 shows the signatures of the overloads, each followed by
/// its docstring: the text common to the groups is given once, with the SE3
/// overload; SO3's own text, if any, with its overload.
template <typename G>
void def_group_functions(py::module_& m) {
  constexpr int D = G::DoF;
  constexpr int P = point_size<G>();
  constexpr bool kSE3 = std::is_same_v<G, SE3d>, kSO3 = std::is_same_v<G, SO3d>;
  const auto shared = [](const char* doc) { return kSE3 ? doc : nullptr; };
  // The text of the Jacobians of a function of two elements x and y of the group.
  const auto pair_doc = [](const std::string& x, const std::string& y, const char* head, const char* example) {
    return std::string(head) + "\n\nArgs:\n    " + x + ": SO2, SE2, SO3, SE3, Sim3 or SE23.\n    " + y +
           ": of the same group as " + x + ".\n\nReturns:\n    tuple[ndarray, ndarray]: (J_" + x + ", J_" + y +
           "), each of shape (D, D): (1, 1) for SO2,\n    (3, 3) for SE2 and SO3, (6, 6) for SE3 (twists (v, w)), (7, "
           "7) "
           "for Sim3, (9, 9) for SE23, float64.\n\n"
           "Raises:\n    TypeError: " +
           x + " and " + y + " are not of the same group.\n\nExample:\n" + example;
  };
  m.def(
      "rplus", [](Obj<G> x, ArrayLike xi) { return chasles::rplus(*x, to_tangent<D>(xi.obj, "rplus(g, xi)", true)); },
      py::arg("g"), py::arg("xi"), shared(R"doc(g rplus xi = g exp(xi): a perturbation in g's own (local, right) frame.

Args:
    g: SO2, SE2, SO3, SE3, Sim3 or SE23.
    xi: tangent vector of g's group, finite: SO2's angle theta (a float),
        shape (3,) for SE2 ((vx, vy, w)) and SO3 (rotation vector w), (6,)
        for SE3 (twist (v, w)), (7,) for Sim3 ((v, w, sigma)),
        (9,) for SE23 ((rho, nu, w)).

Returns:
    SO2, SE2, SO3, SE3, Sim3 or SE23: g exp(xi).

Raises:
    ValueError: xi has the wrong shape for g, or is not finite.

Example:
    >>> g = chasles.SE3(translation=[1.0, 0.0, 0.0])
    >>> chasles.rplus(g, [0.0, 2.0, 0.0, 0.0, 0.0, 0.0]).translation
    array([1., 2., 0.])
)doc"));
  m.def(
      "rminus", [](Obj<G> x, Obj<G> h) { return tangent_out<D>(chasles::rminus(*x, *h)); }, py::arg("g"), py::arg("h"),
      shared(R"doc(g rminus h = log(h^-1 g): the xi with rplus(h, xi) == g ("g minus h").

The order is manif's g.rminus(h); jaxlie's rminus(a, b) = log(a^-1 b) takes
the arguments the other way round.

Args:
    g: SO2, SE2, SO3, SE3, Sim3 or SE23.
    h: of the same group as g.

Returns:
    float or ndarray: SO2's angle, shape (3,) for SE2 ((vx, vy, w)) and
    SO3, (6,) for SE3 ((v, w)), (7,) for Sim3, (9,) for SE23.

Example:
    >>> h = chasles.SO3.exp([0.0, 0.0, 0.5])
    >>> g = h @ chasles.SO3.exp([0.3, 0.0, 0.0])
    >>> np.round(chasles.rminus(g, h), 12) + 0.0
    array([0.3, 0. , 0. ])
)doc"));
  m.def(
      "lplus", [](ArrayLike xi, Obj<G> x) { return chasles::lplus(to_tangent<D>(xi.obj, "lplus(xi, g)", true), *x); },
      py::arg("xi"), py::arg("g"),
      shared(R"doc(xi lplus g = exp(xi) g: a perturbation in the fixed (global, left) frame.

Args:
    xi: tangent vector of g's group, finite (as for rplus).
    g: SO2, SE2, SO3, SE3, Sim3 or SE23.

Returns:
    SO2, SE2, SO3, SE3, Sim3 or SE23: exp(xi) g.

Raises:
    ValueError: xi has the wrong shape for g, or is not finite.
)doc"));
  m.def(
      "lminus", [](Obj<G> x, Obj<G> h) { return tangent_out<D>(chasles::lminus(*x, *h)); }, py::arg("g"), py::arg("h"),
      shared(R"doc(g lminus h = log(g h^-1): the xi with lplus(xi, h) == g.

Args:
    g: SO2, SE2, SO3, SE3, Sim3 or SE23.
    h: of the same group as g.

Returns:
    float or ndarray: SO2's angle, shape (3,) for SE2 ((vx, vy, w)) and
    SO3, (6,) for SE3 ((v, w)), (7,) for Sim3, (9,) for SE23.
)doc"));
  m.def(
      "between", [](Obj<G> a, Obj<G> b) { return chasles::between(*a, *b); }, py::arg("a"), py::arg("b"),
      shared(R"doc(between(a, b) = a^-1 b: b seen from a (manif's a.between(b)).

Args:
    a: SO2, SE2, SO3, SE3, Sim3 or SE23.
    b: of the same group as a.

Returns:
    SO2, SE2, SO3, SE3, Sim3 or SE23: a^-1 b.

Raises:
    TypeError: a and b are not of the same group.

Example:
    >>> a = chasles.SE3(translation=[1.0, 0.0, 0.0])
    >>> b = chasles.SE3(translation=[1.0, 2.0, 0.0])
    >>> chasles.between(a, b).translation
    array([0., 2., 0.])
)doc"));
  m.def(
      "interpolate",
      [](Obj<G> a, Obj<G> b, RealLike t) {
        return chasles::interpolate(*a, *b, to_finite_real(t.obj, "interpolate(t)"));
      },
      py::arg("a"), py::arg("b"), py::arg("t"),
      kSE3   ? R"doc(Screw interpolation of rigid motions a exp(t log(a^-1 b)) (as SE3.interpolate).

Args:
    a: SE3, the start (t = 0).
    b: SE3, the end (t = 1).
    t: the fraction, finite.

Returns:
    SE3: the interpolated motion.

Example:
    >>> m = chasles.interpolate(SE3(), SE3(translation=[0.0, 0.0, 4.0]), 0.25)
    >>> m.translation
    array([0., 0., 1.])
)doc"
      : kSO3 ? R"doc(Geodesic interpolation of rotations a exp(t log(a^-1 b)) (as SO3.interpolate).

Args:
    a: SO3, the start (t = 0).
    b: SO3, the end (t = 1).
    t: the fraction, finite.

Returns:
    SO3: the interpolated rotation.
)doc"
             : nullptr);
  m.def(
      "log_jacobian", [](Obj<G> x) { return mat_out(chasles::log_jacobian(*x)); }, py::arg("g"),
      shared(R"doc(The Jacobian of g -> log(g), in the right-local convention.

For a map f to the tangent space the right-local Jacobian J is defined by
f(g exp(dx)) = f(g) + J dx + o(dx); here J = J_r(log g)^-1 (Sola et al.
2018, section IV), finite up to the angle pi, where log itself jumps between
w and -w (J is that of the branch log returns).

Args:
    g: SO2, SE2, SO3, SE3, Sim3 or SE23.

Returns:
    ndarray: shape (D, D), D the tangent size: (1, 1) for SO2, (3, 3) for
    SE2 and SO3, (6, 6) for SE3 (rows and columns (v, w)), (7, 7) for Sim3,
    (9, 9) for SE23,
    float64.

Example:
    >>> g = chasles.SO3.exp([0.0, 0.0, 0.5])
    >>> dx = np.array([1e-7, 0.0, 0.0])
    >>> bool(np.allclose(chasles.rplus(g, dx).log() - g.log(),
    ...                  chasles.log_jacobian(g) @ dx, atol=1e-13))
    True
)doc"));
  m.def(
      "inverse_jacobian", [](Obj<G> x) { return mat_out(chasles::inverse_jacobian(*x)); }, py::arg("g"),
      shared(R"doc(The Jacobian of g -> g^-1, in the right-local convention: -Ad_g.

Right-local: f(g exp(dx)) = f(g) exp(J dx + o(dx)); here
(g exp(dx))^-1 = g^-1 exp(-Ad_g dx), so J = -Ad_g (Sola et al. 2018,
section IV).

Args:
    g: SO2, SE2, SO3, SE3, Sim3 or SE23.

Returns:
    ndarray: shape (D, D): (1, 1) for SO2 (-1), (3, 3) for SE2 and SO3
    (-R), (6, 6) for SE3 (-Ad_g, twists (v, w)), (7, 7) for Sim3,
    (9, 9) for SE23,
    float64.

Example:
    >>> g = chasles.SO3.exp([0.0, 0.0, np.pi / 2])
    >>> np.round(chasles.inverse_jacobian(g), 12) + 0.0
    array([[ 0.,  1.,  0.],
           [-1.,  0.,  0.],
           [ 0.,  0., -1.]])
)doc"));
  m.def(
      "compose_jacobians", [](Obj<G> a, Obj<G> b) { return pair(chasles::compose_jacobians(*a, *b)); }, py::arg("a"),
      py::arg("b"),
      shared(pair_doc("a", "b", R"doc(The Jacobians (J_a, J_b) of (a, b) -> a b, in the right-local convention.

Right-local: (a exp(da)) (b exp(db)) = a b exp(J_a da + J_b db + o(da, db)),
with J_a = Ad_{b^-1} and J_b = I (Sola et al. 2018, section IV).)doc",
                      R"doc(    >>> a, b = chasles.SO3(), chasles.SO3.exp([0.0, 0.0, np.pi / 2])
    >>> J_a, J_b = chasles.compose_jacobians(a, b)
    >>> bool(np.allclose(J_a, b.inverse().as_matrix())), bool(np.array_equal(J_b, np.eye(3)))
    (True, True)
)doc")
                 .c_str()));
  m.def(
      "act_jacobians",
      [](Obj<G> x, ArrayLike p) {
        const auto J = chasles::act_jacobians(*x, to_finite_eigen<P>(p.obj, "act_jacobians(g, p)"));
        return Matrices(mat_out(J.group), mat_out(J.point));
      },
      py::arg("g"), py::arg("p"), shared(R"doc(The Jacobians (J_g, J_p) of (g, p) -> g p (the action on a point).

Right-local in g: (g exp(dx)) (p + dp) = g p + J_g dx + J_p dp + o(dx, dp).
SO3: J_g = -R [p], J_p = R; SE3: J_g = [R, -R [p]] (columns (v, w), linear
part first), J_p = R (Sola et al. 2018, appendices B and D). SO2:
J_g = R (-p_y, p_x); SE2: J_g = [R, R (-p_y, p_x)] (columns (vx, vy, w)).
Sim3: J_g = [s R, -s R [p], s R p] (columns (v, w, sigma)), J_p = s R.
SE23: J_g = [R, 0, -R [p]] (columns (rho, nu, w)), J_p = R.

Args:
    g: SO2, SE2, SO3, SE3, Sim3 or SE23.
    p: point, shape (2,) for SO2 and SE2, (3,) for SO3 and SE3, finite.

Returns:
    tuple[ndarray, ndarray]: (J_g, J_p); J_g of shape (2, 1) for SO2, (2, 3)
    for SE2, (3, 3) for SO3, (3, 6) for SE3, (3, 7) for Sim3, (3, 9) for
    SE23; J_p = R (s R for Sim3), shape (2, 2) or (3, 3); float64.

Raises:
    ValueError: p is not of g's point shape, or not finite.

Example:
    >>> g = chasles.SE3(translation=[1.0, 0.0, 0.0])
    >>> J_g, J_p = chasles.act_jacobians(g, [0.0, 0.0, 1.0])
    >>> J_g + 0.0
    array([[ 1.,  0.,  0.,  0.,  1.,  0.],
           [ 0.,  1.,  0., -1.,  0.,  0.],
           [ 0.,  0.,  1.,  0.,  0.,  0.]])
)doc"));
  m.def(
      "rplus_jacobians",
      [](Obj<G> x, ArrayLike xi) {
        return pair(chasles::rplus_jacobians(*x, to_tangent<D>(xi.obj, "rplus_jacobians(g, xi)", true)));
      },
      py::arg("g"), py::arg("xi"), shared(R"doc(The Jacobians (J_g, J_xi) of (g, xi) -> rplus(g, xi) = g exp(xi).

Right-local: rplus(g exp(dg), xi + dxi) = rplus(g, xi) exp(J_g dg + J_xi dxi
+ o), with J_g = Ad_{exp(xi)}^-1 = Ad_{exp(-xi)} and J_xi = J_r(xi) (Sola et
al. 2018, section IV; manif's rplus Jacobians).

Args:
    g: SO2, SE2, SO3, SE3, Sim3 or SE23.
    xi: tangent vector of g's group, finite (as for rplus).

Returns:
    tuple[ndarray, ndarray]: (J_g, J_xi), each of shape (D, D): (1, 1) for SO2,
    (3, 3) for SE2 and SO3, (6, 6) for SE3, (7, 7) for Sim3,
    (9, 9) for SE23,
    float64.

Raises:
    ValueError: xi has the wrong shape for g, or is not finite.

Example:
    >>> J_g, J_xi = chasles.rplus_jacobians(chasles.SO3(), [0.0, 0.0, 0.0])
    >>> bool(np.array_equal(J_g, np.eye(3))), bool(np.array_equal(J_xi, np.eye(3)))
    (True, True)
)doc"));
  m.def(
      "rminus_jacobians", [](Obj<G> x, Obj<G> h) { return pair(chasles::rminus_jacobians(*x, *h)); }, py::arg("g"),
      py::arg("h"),
      shared(pair_doc("g", "h", R"doc(The Jacobians (J_g, J_h) of (g, h) -> rminus(g, h) = log(h^-1 g).

Right-local: rminus(g exp(dg), h exp(dh)) = rminus(g, h) + J_g dg + J_h dh
+ o, with xi = rminus(g, h), J_g = J_r(xi)^-1 and J_h = -J_l(xi)^-1 (Sola et
al. 2018, section IV; manif's rminus Jacobians). They are those of the branch
log returns: finite up to the angle pi, where log jumps between w and -w.)doc",
                      R"doc(    >>> J_g, J_h = chasles.rminus_jacobians(chasles.SE3(), chasles.SE3())
    >>> bool(np.array_equal(J_g, np.eye(6))), bool(np.array_equal(J_h, -np.eye(6)))
    (True, True)
)doc")
                 .c_str()));
  m.def(
      "lplus_jacobians",
      [](ArrayLike xi, Obj<G> x) {
        return pair(chasles::lplus_jacobians(to_tangent<D>(xi.obj, "lplus_jacobians(xi, g)", true), *x));
      },
      py::arg("xi"), py::arg("g"), shared(R"doc(The Jacobians (J_xi, J_g) of (xi, g) -> lplus(xi, g) = exp(xi) g.

Right-local in the result and in g: lplus(xi + dxi, g exp(dg)) =
lplus(xi, g) exp(J_xi dxi + J_g dg + o), with J_xi = Ad_{g^-1} J_r(xi) and
J_g = I (Sola et al. 2018, sections III and IV).

Args:
    xi: tangent vector of g's group, finite (as for rplus).
    g: SO2, SE2, SO3, SE3, Sim3 or SE23.

Returns:
    tuple[ndarray, ndarray]: (J_xi, J_g), each of shape (D, D): (1, 1) for SO2,
    (3, 3) for SE2 and SO3, (6, 6) for SE3, (7, 7) for Sim3,
    (9, 9) for SE23,
    float64.

Raises:
    ValueError: xi has the wrong shape for g, or is not finite.

Example:
    >>> g = chasles.SO3.exp([0.0, 0.0, np.pi / 2])
    >>> J_xi, J_g = chasles.lplus_jacobians([0.0, 0.0, 0.0], g)
    >>> bool(np.allclose(J_xi, g.inverse().as_matrix())), bool(np.array_equal(J_g, np.eye(3)))
    (True, True)
)doc"));
  m.def(
      "lminus_jacobians", [](Obj<G> x, Obj<G> h) { return pair(chasles::lminus_jacobians(*x, *h)); }, py::arg("g"),
      py::arg("h"),
      shared(pair_doc("g", "h", R"doc(The Jacobians (J_g, J_h) of (g, h) -> lminus(g, h) = log(g h^-1).

Right-local in the arguments: lminus(g exp(dg), h exp(dh)) = lminus(g, h) +
J_g dg + J_h dh + o, with xi = lminus(g, h), J_g = J_r(xi)^-1 Ad_h and
J_h = -J_g (Sola et al. 2018, section IV). Finite up to the angle pi, where
log jumps between w and -w.)doc",
                      R"doc(    >>> h = chasles.SO3.exp([0.0, 0.0, np.pi / 2])
    >>> J_g, J_h = chasles.lminus_jacobians(h, h)
    >>> bool(np.allclose(J_g, h.as_matrix())), bool(np.array_equal(J_h, -J_g))
    (True, True)
)doc")
                 .c_str()));
  m.def(
      "between_jacobians", [](Obj<G> a, Obj<G> b) { return pair(chasles::between_jacobians(*a, *b)); }, py::arg("a"),
      py::arg("b"),
      shared(pair_doc("a", "b", R"doc(The Jacobians (J_a, J_b) of (a, b) -> between(a, b) = a^-1 b.

Right-local: between(a exp(da), b exp(db)) = between(a, b) exp(J_a da +
J_b db + o), with J_a = -Ad_{b^-1 a} and J_b = I (Sola et al. 2018,
section IV; manif's between Jacobians).)doc",
                      R"doc(    >>> a = chasles.SO3.exp([0.0, 0.0, np.pi / 2])
    >>> J_a, J_b = chasles.between_jacobians(a, chasles.SO3())
    >>> bool(np.allclose(J_a, -a.as_matrix())), bool(np.array_equal(J_b, np.eye(3)))
    (True, True)
)doc")
                 .c_str()));
  m.def(
      "interpolate_jacobian_t",
      [](Obj<G> a, Obj<G> b, RealLike t) {
        return tangent_out<D>(
            chasles::interpolate_jacobian_t(*a, *b, to_finite_real(t.obj, "interpolate_jacobian_t(t)")));
      },
      py::arg("a"), py::arg("b"), py::arg("t"),
      shared(R"doc(The derivative in t of interpolate(a, b, t) = a exp(t log(a^-1 b)).

Right-local: interpolate(a, b, t + dt) = interpolate(a, b, t) exp(J dt + o(dt)),
and J = J_r(t xi) xi = xi = rminus(b, a) = log(a^-1 b), the same for every t
(the geodesic has constant body velocity).

Args:
    a: SO2, SE2, SO3, SE3, Sim3 or SE23, the start.
    b: of the same group as a, the end.
    t: the fraction, finite.

Returns:
    float or ndarray: SO2's angle, shape (3,) for SE2 and SO3, (6,) for
    SE3 ((v, w), linear part first), (7,) for Sim3, (9,) for SE23.

Raises:
    ValueError: t is not finite.
    TypeError: a and b are not of the same group.

Example:
    >>> a, b = chasles.SE3(), chasles.SE3(translation=[2.0, 0.0, 0.0])
    >>> chasles.interpolate_jacobian_t(a, b, 0.5)
    array([2., 0., 0., 0., 0., 0.])
)doc"));
}

/// The functions of two elements whose Jacobians are array functions.
enum class Pair { compose, between, rminus };

/// The Jacobians of a function of two elements over batches, as two arrays:
/// <g>_compose_jacobians, <g>_between_jacobians, <g>_rminus_jacobians (what
/// a solver needs per edge of a pose graph, in one call for all of them).
template <typename Group, Pair F>
void def_pair_jacobians(py::module_& m, const char* what, const char* params, const std::string& head) {
  constexpr int N = chasles::detail::matrix_size<Group>, D = Group::DoF;
  using ufunc::Core;
  static const std::string name = std::string(GroupNames<Group>::prefix) + "_" + what;
  const std::string n = std::to_string(N), d = std::to_string(D), x(params, 1), y(params + 3, 1);
  const std::string doc = head + ", for each pair of the batch (as " + what + " for one).\n\nArgs:\n    " + x +
                          ": array_like of shape (..., " + n + ", " + n + "): " + matrices_words<Group>() + ".\n    " +
                          y + ": array_like of shape (..., " + n + ", " + n + "): of the same group.\n\n" +
                          "Returns:\n    tuple (J_" + x + ", J_" + y + "): numpy.ndarray of shape (..., " + d + ", " +
                          d + ") each, in the right-local convention, the batch shape being the broadcast of " + x +
                          "'s and " + y + "'s.";
  ufunc::def_ufunc<std::tuple<Core<D, D>, Core<D, D>>(Core<N, N>, Core<N, N>)>(
      m, name.c_str(), params, ufunc::array_doc(doc.c_str()), ufunc::strided([](const auto& a, const auto& b) noexcept {
        using G = Rebind<Group, ufunc::ScalarOf<decltype(a)>>;
        const G ga = G::from_matrix_unchecked(a), gb = G::from_matrix_unchecked(b);
        const auto j = [&] {
          if constexpr (F == Pair::compose)
            return chasles::compose_jacobians(ga, gb);
          else if constexpr (F == Pair::between)
            return chasles::between_jacobians(ga, gb);
          else
            return chasles::rminus_jacobians(ga, gb);
        }();
        return std::make_tuple(j.lhs, j.rhs);
      }));
}

template <typename Group>
void def_jacobian_arrays(py::module_& m) {
  def_pair_jacobians<Group, Pair::compose>(m, "compose_jacobians", "a, b",
                                           "The Jacobians of a b with respect to a and b");
  def_pair_jacobians<Group, Pair::between>(m, "between_jacobians", "a, b",
                                           "The Jacobians of a^-1 b with respect to a and b");
  def_pair_jacobians<Group, Pair::rminus>(m, "rminus_jacobians", "g, h",
                                          "The Jacobians of log(h^-1 g) with respect to g and h");
}

}  // namespace

void bind_jacobians(py::module_& m) {
  def_group_functions<SO2d>(m);
  def_group_functions<SE2d>(m);
  def_group_functions<SO3d>(m);
  def_group_functions<Sim3d>(m);
  def_group_functions<SE23d>(m);
  def_group_functions<SE3d>(m);
  def_jacobian_arrays<SO2d>(m);
  def_jacobian_arrays<SE2d>(m);
  def_jacobian_arrays<SO3d>(m);
  def_jacobian_arrays<SE3d>(m);
  def_jacobian_arrays<Sim3d>(m);
  def_jacobian_arrays<SE23d>(m);

  // ---- the Jacobian of the point action for many points (array functions) ----

  using ufunc::Core;
  using ufunc::def_ufunc;
  def_ufunc<Core<3, 3>(Core<3, 3>, Core<3>)>(
      m, "so3_act_jacobian", "R, points",
      ufunc::array_doc(R"(Jacobians d(R p)/dR = -R [p] of rotated points, right-local in R.

(R exp(dw)) p = R p - R [p] dw + o(dw) (Sola et al. 2018, appendix B), as
act_jacobians(R, p)[0] for one rotation. The Jacobian with respect to the
point, d(R p)/dp, is R itself: no array is made for it.

Broadcasts: one rotation of shape (3, 3) with points of shape (N, 3) gives
(N, 3, 3), N rotations with N points, ...

Args:
    R: array_like of shape (..., 3, 3): rotation matrices.
    points: array_like of shape (..., 3): points or vectors.

Returns:
    numpy.ndarray of shape (..., 3, 3): the Jacobians (columns: the rotation
    vector dw).)"),
      [](const auto& R, const auto& p) {
        using T = typename std::decay_t<decltype(R)>::Scalar;
        return chasles::act_jacobians<T>(chasles::SO3<T>::from_matrix_unchecked(R), chasles::Vector3Of<T>(p)).group;
      });
  def_ufunc<Core<3, 6>(Core<4, 4>, Core<3>)>(
      m, "se3_act_jacobian", "g, points",
      ufunc::array_doc(R"(Jacobians d(g p)/dg = [R, -R [p]] of transformed points, right-local in g.

(g exp(dxi)) p = g p + [R, -R [p]] dxi + o(dxi), dxi = (v, w) linear part
first (Sola et al. 2018, appendix D), as act_jacobians(g, p)[0] for one
motion. The Jacobian with respect to the point, d(g p)/dp, is the rotation
block R = g[..., :3, :3]: no array is made for it.

Broadcasts: one pose of shape (4, 4) with points of shape (N, 3) gives
(N, 3, 6), N poses with N points, ...

Args:
    g: array_like of shape (..., 4, 4): homogeneous matrices.
    points: array_like of shape (..., 3): points.

Returns:
    numpy.ndarray of shape (..., 3, 6): the Jacobians (columns: the twist
    (v, w)).)"),
      [](const auto& g, const auto& p) {
        using T = typename std::decay_t<decltype(g)>::Scalar;
        return chasles::act_jacobians<T>(chasles::SE3<T>::from_matrix_unchecked(g), chasles::Vector3Of<T>(p)).group;
      });
}

}  // namespace chasles_py
