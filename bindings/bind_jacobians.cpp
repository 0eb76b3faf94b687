// chasles._core: the Jacobians of include/chasles/jacobians.hpp as static
// methods of SO3 and SE3 (right_jacobian, left_jacobian and their inverses),
// the module-level rplus, rminus, lplus, lminus for SO3 and SE3, and the
// module-level Jacobians of the group operations (log_jacobian,
// inverse_jacobian, compose_jacobians, act_jacobians, interpolate_jacobian_t,
// rplus_jacobians, rminus_jacobians, lplus_jacobians, lminus_jacobians,
// between_jacobians) and between,
// overloaded for SO3 and SE3, in the right-local convention; and the array
// functions so3_act_jacobian, se3_act_jacobian (generalized ufuncs).
#include <chasles/jacobians.hpp>

#include <cstdio>
#include <string>
#include <tuple>

#include "bindings.hpp"
#include "convert.hpp"
#include "ufunc.hpp"

namespace chasles_py {

namespace {

using chasles::SE3d;
using chasles::SO3d;
using Vector3 = Eigen::Vector3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;

const char* const kSo3Doc = R"doc(The %s of SO(3) at the rotation vector w, shape (3, 3).

Right (local) convention, as manif and Pinocchio:
exp(w + dw) = exp(w) exp(J_r(w) dw + o(dw)) and
exp(w + dw) = exp(J_l(w) dw + o(dw)) exp(w), with
J_r(w) = I - B [w] + C [w]^2, J_l(w) = J_r(-w) = I + B [w] + C [w]^2,
B = (1 - cos theta) / theta^2, C = (theta - sin theta) / theta^3;
J_r^-1 = I + 1/2 [w] + D [w]^2, J_l^-1 = I - 1/2 [w] + D [w]^2,
D = (1 - (theta/2) cot(theta/2)) / theta^2 (finite for |w| < 2 pi).

Args:
    w: rotation vector, shape (3,), finite.

Returns:
    ndarray: shape (3, 3), float64.

Raises:
    ValueError: w is not of shape (3,), or not finite.
    TypeError: w is not real.
)doc";

const char* const kSe3Doc = R"doc(The %s of SE(3) at the twist xi = (v, w), shape (6, 6).

Linear part first. Right (local) convention, as manif and Pinocchio:
exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi), with
J_l(xi) = [[J_l(w), Q(v, w)], [0, J_l(w)]] (Barfoot; Sola et al. 2018,
eq. 180), J_r(xi) = J_l(-xi), and the inverses by the block formula
[[J^-1, -J^-1 Q J^-1], [0, J^-1]].

Args:
    xi: twist (v, w), shape (6,), finite.

Returns:
    ndarray: shape (6, 6), float64.

Raises:
    ValueError: xi is not of shape (6,), or not finite.
    TypeError: xi is not real.
)doc";

using Matrices = std::tuple<py::array_t<double>, py::array_t<double>>;

std::string doc_for(const char* fmt, const char* name) {
  char buf[2048];
  std::snprintf(buf, sizeof buf, fmt, name);
  return buf;
}

}  // namespace

void bind_jacobians(py::module_& m) {
  auto so3 = py::reinterpret_borrow<py::class_<SO3d, InlineHolder<SO3d>>>(m.attr("SO3"));
  auto se3 = py::reinterpret_borrow<py::class_<SE3d, InlineHolder<SE3d>>>(m.attr("SE3"));

  // The docstrings must outlive the module: pybind11 keeps the pointer.
  static const std::string so3_docs[4] = {doc_for(kSo3Doc, "right Jacobian J_r"), doc_for(kSo3Doc, "left Jacobian J_l"),
                                          doc_for(kSo3Doc, "inverse right Jacobian J_r^-1"),
                                          doc_for(kSo3Doc, "inverse left Jacobian J_l^-1")};
  static const std::string se3_docs[4] = {doc_for(kSe3Doc, "right Jacobian J_r"), doc_for(kSe3Doc, "left Jacobian J_l"),
                                          doc_for(kSe3Doc, "inverse right Jacobian J_r^-1"),
                                          doc_for(kSe3Doc, "inverse left Jacobian J_l^-1")};

  so3.def_static(
      "right_jacobian",
      [](ArrayLike w) { return mat_out<3, 3>(chasles::so3_right_jacobian(to_finite_eigen<3>(w.obj, "SO3.right_jacobian(w)"))); },
      py::arg("w"), so3_docs[0].c_str());
  so3.def_static(
      "left_jacobian",
      [](ArrayLike w) { return mat_out<3, 3>(chasles::so3_left_jacobian(to_finite_eigen<3>(w.obj, "SO3.left_jacobian(w)"))); },
      py::arg("w"), so3_docs[1].c_str());
  so3.def_static(
      "right_jacobian_inverse",
      [](ArrayLike w) {
        return mat_out<3, 3>(
            chasles::so3_right_jacobian_inverse(to_finite_eigen<3>(w.obj, "SO3.right_jacobian_inverse(w)")));
      },
      py::arg("w"), so3_docs[2].c_str());
  so3.def_static(
      "left_jacobian_inverse",
      [](ArrayLike w) {
        return mat_out<3, 3>(
            chasles::so3_left_jacobian_inverse(to_finite_eigen<3>(w.obj, "SO3.left_jacobian_inverse(w)")));
      },
      py::arg("w"), so3_docs[3].c_str());

  se3.def_static(
      "right_jacobian",
      [](ArrayLike xi) {
        return mat_out<6, 6>(chasles::se3_right_jacobian(to_finite_eigen<6>(xi.obj, "SE3.right_jacobian(xi)")));
      },
      py::arg("xi"), se3_docs[0].c_str());
  se3.def_static(
      "left_jacobian",
      [](ArrayLike xi) {
        return mat_out<6, 6>(chasles::se3_left_jacobian(to_finite_eigen<6>(xi.obj, "SE3.left_jacobian(xi)")));
      },
      py::arg("xi"), se3_docs[1].c_str());
  se3.def_static(
      "right_jacobian_inverse",
      [](ArrayLike xi) {
        return mat_out<6, 6>(
            chasles::se3_right_jacobian_inverse(to_finite_eigen<6>(xi.obj, "SE3.right_jacobian_inverse(xi)")));
      },
      py::arg("xi"), se3_docs[2].c_str());
  se3.def_static(
      "left_jacobian_inverse",
      [](ArrayLike xi) {
        return mat_out<6, 6>(
            chasles::se3_left_jacobian_inverse(to_finite_eigen<6>(xi.obj, "SE3.left_jacobian_inverse(xi)")));
      },
      py::arg("xi"), se3_docs[3].c_str());

  // ---- plus and minus -----------------------------------------------------

  m.def(
      "rplus", [](Obj<SO3d> g, ArrayLike xi) { return chasles::rplus(*g, to_finite_eigen<3>(xi.obj, "rplus(g, xi)")); },
      py::arg("g"), py::arg("xi"));
  m.def(
      "rplus", [](Obj<SE3d> g, ArrayLike xi) { return chasles::rplus(*g, to_finite_eigen<6>(xi.obj, "rplus(g, xi)")); },
      py::arg("g"), py::arg("xi"),
      R"doc(g rplus xi = g exp(xi): a perturbation in g's own (local, right) frame.

Args:
    g: SO3 or SE3.
    xi: tangent vector, shape (3,) for SO3 (rotation vector w), (6,) for SE3
        (twist (v, w), linear part first), finite.

Returns:
    SO3 or SE3: g exp(xi).

Raises:
    ValueError: xi has the wrong shape for g, or is not finite.

Example:
    >>> g = chasles.SE3(translation=[1.0, 0.0, 0.0])
    >>> chasles.rplus(g, [0.0, 2.0, 0.0, 0.0, 0.0, 0.0]).translation
    array([1., 2., 0.])
)doc");
  m.def(
      "rminus", [](Obj<SO3d> g, Obj<SO3d> h) { return vec_out<3>(chasles::rminus(*g, *h)); }, py::arg("g"),
      py::arg("h"));
  m.def(
      "rminus", [](Obj<SE3d> g, Obj<SE3d> h) { return vec_out<6>(chasles::rminus(*g, *h)); }, py::arg("g"),
      py::arg("h"),
      R"doc(g rminus h = log(h^-1 g): the xi with rplus(h, xi) == g ("g minus h").

The order is manif's g.rminus(h); jaxlie's rminus(a, b) = log(a^-1 b) takes
the arguments the other way round.

Args:
    g: SO3 or SE3.
    h: of the same group as g.

Returns:
    ndarray: shape (3,) for SO3, (6,) for SE3 ((v, w), linear part first).

Example:
    >>> h = chasles.SO3.exp([0.0, 0.0, 0.5])
    >>> g = h @ chasles.SO3.exp([0.3, 0.0, 0.0])
    >>> np.round(chasles.rminus(g, h), 12) + 0.0
    array([0.3, 0. , 0. ])
)doc");
  m.def(
      "lplus", [](ArrayLike xi, Obj<SO3d> g) { return chasles::lplus(to_finite_eigen<3>(xi.obj, "lplus(xi, g)"), *g); },
      py::arg("xi"), py::arg("g"));
  m.def(
      "lplus", [](ArrayLike xi, Obj<SE3d> g) { return chasles::lplus(to_finite_eigen<6>(xi.obj, "lplus(xi, g)"), *g); },
      py::arg("xi"), py::arg("g"),
      R"doc(xi lplus g = exp(xi) g: a perturbation in the fixed (global, left) frame.

Args:
    xi: tangent vector, shape (3,) for SO3, (6,) for SE3 ((v, w)), finite.
    g: SO3 or SE3.

Returns:
    SO3 or SE3: exp(xi) g.

Raises:
    ValueError: xi has the wrong shape for g, or is not finite.
)doc");
  m.def(
      "lminus", [](Obj<SO3d> g, Obj<SO3d> h) { return vec_out<3>(chasles::lminus(*g, *h)); }, py::arg("g"),
      py::arg("h"));
  m.def(
      "lminus", [](Obj<SE3d> g, Obj<SE3d> h) { return vec_out<6>(chasles::lminus(*g, *h)); }, py::arg("g"),
      py::arg("h"),
      R"doc(g lminus h = log(g h^-1): the xi with lplus(xi, h) == g.

Args:
    g: SO3 or SE3.
    h: of the same group as g.

Returns:
    ndarray: shape (3,) for SO3, (6,) for SE3 ((v, w), linear part first).
)doc");
  // ---- Jacobians of the group operations (right-local convention) --------

  m.def(
      "log_jacobian", [](Obj<SO3d> g) { return mat_out<3, 3>(chasles::log_jacobian(*g)); }, py::arg("g"));
  m.def(
      "log_jacobian", [](Obj<SE3d> g) { return mat_out<6, 6>(chasles::log_jacobian(*g)); }, py::arg("g"),
      R"doc(The Jacobian of g -> log(g), in the right-local convention.

For a map f to the tangent space the right-local Jacobian J is defined by
f(g exp(dx)) = f(g) + J dx + o(dx); here J = J_r(log g)^-1 (Sola et al.
2018, section IV), finite up to the angle pi, where log itself jumps between
w and -w (J is that of the branch log returns).

Args:
    g: SO3 or SE3.

Returns:
    ndarray: shape (3, 3) for SO3, (6, 6) for SE3 (rows and columns (v, w),
    linear part first), float64.

Example:
    >>> g = chasles.SO3.exp([0.0, 0.0, 0.5])
    >>> dx = np.array([1e-7, 0.0, 0.0])
    >>> bool(np.allclose(chasles.rplus(g, dx).log() - g.log(),
    ...                  chasles.log_jacobian(g) @ dx, atol=1e-13))
    True
)doc");

  m.def(
      "inverse_jacobian", [](Obj<SO3d> g) { return mat_out<3, 3>(chasles::inverse_jacobian(*g)); }, py::arg("g"));
  m.def(
      "inverse_jacobian", [](Obj<SE3d> g) { return mat_out<6, 6>(chasles::inverse_jacobian(*g)); }, py::arg("g"),
      R"doc(The Jacobian of g -> g^-1, in the right-local convention: -Ad_g.

Right-local: f(g exp(dx)) = f(g) exp(J dx + o(dx)); here
(g exp(dx))^-1 = g^-1 exp(-Ad_g dx), so J = -Ad_g (Sola et al. 2018,
section IV).

Args:
    g: SO3 or SE3.

Returns:
    ndarray: shape (3, 3) for SO3 (-R), (6, 6) for SE3 (-Ad_g, twists
    (v, w), linear part first), float64.

Example:
    >>> g = chasles.SO3.exp([0.0, 0.0, np.pi / 2])
    >>> np.round(chasles.inverse_jacobian(g), 12) + 0.0
    array([[ 0.,  1.,  0.],
           [-1.,  0.,  0.],
           [ 0.,  0., -1.]])
)doc");

  m.def(
      "compose_jacobians",
      [](Obj<SO3d> a, Obj<SO3d> b) {
        const auto J = chasles::compose_jacobians(*a, *b);
        return Matrices(mat_out<3, 3>(J.lhs), mat_out<3, 3>(J.rhs));
      },
      py::arg("a"), py::arg("b"));
  m.def(
      "compose_jacobians",
      [](Obj<SE3d> a, Obj<SE3d> b) {
        const auto J = chasles::compose_jacobians(*a, *b);
        return Matrices(mat_out<6, 6>(J.lhs), mat_out<6, 6>(J.rhs));
      },
      py::arg("a"), py::arg("b"),
      R"doc(The Jacobians (J_a, J_b) of (a, b) -> a b, in the right-local convention.

Right-local: (a exp(da)) (b exp(db)) = a b exp(J_a da + J_b db + o(da, db)),
with J_a = Ad_{b^-1} and J_b = I (Sola et al. 2018, section IV).

Args:
    a: SO3 or SE3.
    b: of the same group as a.

Returns:
    tuple[ndarray, ndarray]: (J_a, J_b), each of shape (3, 3) for SO3,
    (6, 6) for SE3 (twists (v, w), linear part first), float64.

Raises:
    TypeError: a and b are not of the same group.

Example:
    >>> a, b = chasles.SO3(), chasles.SO3.exp([0.0, 0.0, np.pi / 2])
    >>> J_a, J_b = chasles.compose_jacobians(a, b)
    >>> bool(np.allclose(J_a, b.inverse().as_matrix())), bool(np.array_equal(J_b, np.eye(3)))
    (True, True)
)doc");

  m.def(
      "act_jacobians",
      [](Obj<SO3d> g, ArrayLike p) {
        const auto J = chasles::act_jacobians(*g, to_finite_eigen<3>(p.obj, "act_jacobians(g, p)"));
        return Matrices(mat_out<3, 3>(J.group), mat_out<3, 3>(J.point));
      },
      py::arg("g"), py::arg("p"));
  m.def(
      "act_jacobians",
      [](Obj<SE3d> g, ArrayLike p) {
        const auto J = chasles::act_jacobians(*g, to_finite_eigen<3>(p.obj, "act_jacobians(g, p)"));
        return Matrices(mat_out<3, 6>(J.group), mat_out<3, 3>(J.point));
      },
      py::arg("g"), py::arg("p"),
      R"doc(The Jacobians (J_g, J_p) of (g, p) -> g p (the action on a point).

Right-local in g: (g exp(dx)) (p + dp) = g p + J_g dx + J_p dp + o(dx, dp).
SO3: J_g = -R [p], J_p = R; SE3: J_g = [R, -R [p]] (columns (v, w), linear
part first), J_p = R (Sola et al. 2018, appendices B and D).

Args:
    g: SO3 or SE3.
    p: point, shape (3,), finite.

Returns:
    tuple[ndarray, ndarray]: (J_g, J_p); J_g of shape (3, 3) for SO3,
    (3, 6) for SE3, J_p of shape (3, 3); float64.

Raises:
    ValueError: p is not of shape (3,), or not finite.

Example:
    >>> g = chasles.SE3(translation=[1.0, 0.0, 0.0])
    >>> J_g, J_p = chasles.act_jacobians(g, [0.0, 0.0, 1.0])
    >>> J_g + 0.0
    array([[ 1.,  0.,  0.,  0.,  1.,  0.],
           [ 0.,  1.,  0., -1.,  0.,  0.],
           [ 0.,  0.,  1.,  0.,  0.,  0.]])
)doc");

  // ---- Jacobians of plus, minus and between (right-local convention) ----

  m.def(
      "rplus_jacobians",
      [](Obj<SO3d> g, ArrayLike xi) {
        const auto J = chasles::rplus_jacobians(*g, to_finite_eigen<3>(xi.obj, "rplus_jacobians(g, xi)"));
        return Matrices(mat_out<3, 3>(J.lhs), mat_out<3, 3>(J.rhs));
      },
      py::arg("g"), py::arg("xi"));
  m.def(
      "rplus_jacobians",
      [](Obj<SE3d> g, ArrayLike xi) {
        const auto J = chasles::rplus_jacobians(*g, to_finite_eigen<6>(xi.obj, "rplus_jacobians(g, xi)"));
        return Matrices(mat_out<6, 6>(J.lhs), mat_out<6, 6>(J.rhs));
      },
      py::arg("g"), py::arg("xi"),
      R"doc(The Jacobians (J_g, J_xi) of (g, xi) -> rplus(g, xi) = g exp(xi).

Right-local: rplus(g exp(dg), xi + dxi) = rplus(g, xi) exp(J_g dg + J_xi dxi
+ o), with J_g = Ad_{exp(xi)}^-1 = Ad_{exp(-xi)} and J_xi = J_r(xi) (Sola et
al. 2018, section IV; manif's rplus Jacobians).

Args:
    g: SO3 or SE3.
    xi: tangent vector, shape (3,) for SO3, (6,) for SE3 ((v, w), linear
        part first), finite.

Returns:
    tuple[ndarray, ndarray]: (J_g, J_xi), each of shape (3, 3) for SO3,
    (6, 6) for SE3, float64.

Raises:
    ValueError: xi has the wrong shape for g, or is not finite.

Example:
    >>> J_g, J_xi = chasles.rplus_jacobians(chasles.SO3(), [0.0, 0.0, 0.0])
    >>> bool(np.array_equal(J_g, np.eye(3))), bool(np.array_equal(J_xi, np.eye(3)))
    (True, True)
)doc");

  m.def(
      "rminus_jacobians",
      [](Obj<SO3d> g, Obj<SO3d> h) {
        const auto J = chasles::rminus_jacobians(*g, *h);
        return Matrices(mat_out<3, 3>(J.lhs), mat_out<3, 3>(J.rhs));
      },
      py::arg("g"), py::arg("h"));
  m.def(
      "rminus_jacobians",
      [](Obj<SE3d> g, Obj<SE3d> h) {
        const auto J = chasles::rminus_jacobians(*g, *h);
        return Matrices(mat_out<6, 6>(J.lhs), mat_out<6, 6>(J.rhs));
      },
      py::arg("g"), py::arg("h"),
      R"doc(The Jacobians (J_g, J_h) of (g, h) -> rminus(g, h) = log(h^-1 g).

Right-local: rminus(g exp(dg), h exp(dh)) = rminus(g, h) + J_g dg + J_h dh
+ o, with xi = rminus(g, h), J_g = J_r(xi)^-1 and J_h = -J_l(xi)^-1 (Sola et
al. 2018, section IV; manif's rminus Jacobians). They are those of the branch
log returns: finite up to the angle pi, where log jumps between w and -w.

Args:
    g: SO3 or SE3.
    h: of the same group as g.

Returns:
    tuple[ndarray, ndarray]: (J_g, J_h), each of shape (3, 3) for SO3,
    (6, 6) for SE3 (twists (v, w), linear part first), float64.

Raises:
    TypeError: g and h are not of the same group.

Example:
    >>> J_g, J_h = chasles.rminus_jacobians(chasles.SE3(), chasles.SE3())
    >>> bool(np.array_equal(J_g, np.eye(6))), bool(np.array_equal(J_h, -np.eye(6)))
    (True, True)
)doc");

  m.def(
      "lplus_jacobians",
      [](ArrayLike xi, Obj<SO3d> g) {
        const auto J = chasles::lplus_jacobians(to_finite_eigen<3>(xi.obj, "lplus_jacobians(xi, g)"), *g);
        return Matrices(mat_out<3, 3>(J.lhs), mat_out<3, 3>(J.rhs));
      },
      py::arg("xi"), py::arg("g"));
  m.def(
      "lplus_jacobians",
      [](ArrayLike xi, Obj<SE3d> g) {
        const auto J = chasles::lplus_jacobians(to_finite_eigen<6>(xi.obj, "lplus_jacobians(xi, g)"), *g);
        return Matrices(mat_out<6, 6>(J.lhs), mat_out<6, 6>(J.rhs));
      },
      py::arg("xi"), py::arg("g"),
      R"doc(The Jacobians (J_xi, J_g) of (xi, g) -> lplus(xi, g) = exp(xi) g.

Right-local in the result and in g: lplus(xi + dxi, g exp(dg)) =
lplus(xi, g) exp(J_xi dxi + J_g dg + o), with J_xi = Ad_{g^-1} J_r(xi) and
J_g = I (Sola et al. 2018, sections III and IV).

Args:
    xi: tangent vector, shape (3,) for SO3, (6,) for SE3 ((v, w), linear
        part first), finite.
    g: SO3 or SE3.

Returns:
    tuple[ndarray, ndarray]: (J_xi, J_g), each of shape (3, 3) for SO3,
    (6, 6) for SE3, float64.

Raises:
    ValueError: xi has the wrong shape for g, or is not finite.

Example:
    >>> g = chasles.SO3.exp([0.0, 0.0, np.pi / 2])
    >>> J_xi, J_g = chasles.lplus_jacobians([0.0, 0.0, 0.0], g)
    >>> bool(np.allclose(J_xi, g.inverse().as_matrix())), bool(np.array_equal(J_g, np.eye(3)))
    (True, True)
)doc");

  m.def(
      "lminus_jacobians",
      [](Obj<SO3d> g, Obj<SO3d> h) {
        const auto J = chasles::lminus_jacobians(*g, *h);
        return Matrices(mat_out<3, 3>(J.lhs), mat_out<3, 3>(J.rhs));
      },
      py::arg("g"), py::arg("h"));
  m.def(
      "lminus_jacobians",
      [](Obj<SE3d> g, Obj<SE3d> h) {
        const auto J = chasles::lminus_jacobians(*g, *h);
        return Matrices(mat_out<6, 6>(J.lhs), mat_out<6, 6>(J.rhs));
      },
      py::arg("g"), py::arg("h"),
      R"doc(The Jacobians (J_g, J_h) of (g, h) -> lminus(g, h) = log(g h^-1).

Right-local in the arguments: lminus(g exp(dg), h exp(dh)) = lminus(g, h) +
J_g dg + J_h dh + o, with xi = lminus(g, h), J_g = J_r(xi)^-1 Ad_h and
J_h = -J_g (Sola et al. 2018, section IV). Finite up to the angle pi, where
log jumps between w and -w.

Args:
    g: SO3 or SE3.
    h: of the same group as g.

Returns:
    tuple[ndarray, ndarray]: (J_g, J_h), each of shape (3, 3) for SO3,
    (6, 6) for SE3 (twists (v, w), linear part first), float64.

Raises:
    TypeError: g and h are not of the same group.

Example:
    >>> h = chasles.SO3.exp([0.0, 0.0, np.pi / 2])
    >>> J_g, J_h = chasles.lminus_jacobians(h, h)
    >>> bool(np.allclose(J_g, h.as_matrix())), bool(np.array_equal(J_h, -J_g))
    (True, True)
)doc");

  m.def(
      "between", [](Obj<SO3d> a, Obj<SO3d> b) { return chasles::between(*a, *b); }, py::arg("a"), py::arg("b"));
  m.def(
      "between", [](Obj<SE3d> a, Obj<SE3d> b) { return chasles::between(*a, *b); }, py::arg("a"), py::arg("b"),
      R"doc(between(a, b) = a^-1 b: b seen from a (manif's a.between(b)).

Args:
    a: SO3 or SE3.
    b: of the same group as a.

Returns:
    SO3 or SE3: a^-1 b.

Raises:
    TypeError: a and b are not of the same group.

Example:
    >>> a = chasles.SE3(translation=[1.0, 0.0, 0.0])
    >>> b = chasles.SE3(translation=[1.0, 2.0, 0.0])
    >>> chasles.between(a, b).translation
    array([0., 2., 0.])
)doc");

  m.def(
      "between_jacobians",
      [](Obj<SO3d> a, Obj<SO3d> b) {
        const auto J = chasles::between_jacobians(*a, *b);
        return Matrices(mat_out<3, 3>(J.lhs), mat_out<3, 3>(J.rhs));
      },
      py::arg("a"), py::arg("b"));
  m.def(
      "between_jacobians",
      [](Obj<SE3d> a, Obj<SE3d> b) {
        const auto J = chasles::between_jacobians(*a, *b);
        return Matrices(mat_out<6, 6>(J.lhs), mat_out<6, 6>(J.rhs));
      },
      py::arg("a"), py::arg("b"),
      R"doc(The Jacobians (J_a, J_b) of (a, b) -> between(a, b) = a^-1 b.

Right-local: between(a exp(da), b exp(db)) = between(a, b) exp(J_a da +
J_b db + o), with J_a = -Ad_{b^-1 a} and J_b = I (Sola et al. 2018,
section IV; manif's between Jacobians).

Args:
    a: SO3 or SE3.
    b: of the same group as a.

Returns:
    tuple[ndarray, ndarray]: (J_a, J_b), each of shape (3, 3) for SO3,
    (6, 6) for SE3 (twists (v, w), linear part first), float64.

Raises:
    TypeError: a and b are not of the same group.

Example:
    >>> a = chasles.SO3.exp([0.0, 0.0, np.pi / 2])
    >>> J_a, J_b = chasles.between_jacobians(a, chasles.SO3())
    >>> bool(np.allclose(J_a, -a.as_matrix())), bool(np.array_equal(J_b, np.eye(3)))
    (True, True)
)doc");

  m.def(
      "interpolate_jacobian_t",
      [](Obj<SO3d> a, Obj<SO3d> b, RealLike t) {
        return vec_out<3>(
            chasles::interpolate_jacobian_t(*a, *b, to_finite_real(t.obj, "interpolate_jacobian_t(t)")));
      },
      py::arg("a"), py::arg("b"), py::arg("t"));
  m.def(
      "interpolate_jacobian_t",
      [](Obj<SE3d> a, Obj<SE3d> b, RealLike t) {
        return vec_out<6>(
            chasles::interpolate_jacobian_t(*a, *b, to_finite_real(t.obj, "interpolate_jacobian_t(t)")));
      },
      py::arg("a"), py::arg("b"), py::arg("t"),
      R"doc(The derivative in t of interpolate(a, b, t) = a exp(t log(a^-1 b)).

Right-local: interpolate(a, b, t + dt) = interpolate(a, b, t) exp(J dt + o(dt)),
and J = J_r(t xi) xi = xi = rminus(b, a) = log(a^-1 b), the same for every t
(the geodesic has constant body velocity).

Args:
    a: SO3 or SE3, the start.
    b: of the same group as a, the end.
    t: the fraction, finite.

Returns:
    ndarray: shape (3,) for SO3, (6,) for SE3 ((v, w), linear part first),
    float64.

Raises:
    ValueError: t is not finite.
    TypeError: a and b are not of the same group.

Example:
    >>> a, b = chasles.SE3(), chasles.SE3(translation=[2.0, 0.0, 0.0])
    >>> chasles.interpolate_jacobian_t(a, b, 0.5)
    array([2., 0., 0., 0., 0., 0.])
)doc");

  // ---- the Jacobian of the point action for many points (array functions) ----

  using ufunc::Core;
  using ufunc::def_ufunc;
  def_ufunc<Core<3, 3>(Core<3, 3>, Core<3>)>(m, "so3_act_jacobian", "R, points",
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
                                                return chasles::act_jacobians<T>(
                                                           chasles::SO3<T>::from_matrix_unchecked(R),
                                                           chasles::Vector3Of<T>(p))
                                                    .group;
                                              });
  def_ufunc<Core<3, 6>(Core<4, 4>, Core<3>)>(m, "se3_act_jacobian", "g, points",
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
                                                return chasles::act_jacobians<T>(
                                                           chasles::SE3<T>::from_matrix_unchecked(g),
                                                           chasles::Vector3Of<T>(p))
                                                    .group;
                                              });
}

}  // namespace chasles_py
