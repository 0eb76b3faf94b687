// chasles._core: the Jacobians of include/chasles/jacobians.hpp as static
// methods of SO3 and SE3 (right_jacobian, left_jacobian and their inverses),
// and the module-level rplus, rminus, lplus, lminus for SO3 and SE3.
#include <chasles/jacobians.hpp>

#include <cstdio>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"

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

std::string doc_for(const char* fmt, const char* name) {
  char buf[2048];
  std::snprintf(buf, sizeof buf, fmt, name);
  return buf;
}

}  // namespace

void bind_jacobians(py::module_& m) {
  auto so3 = py::reinterpret_borrow<py::class_<SO3d>>(m.attr("SO3"));
  auto se3 = py::reinterpret_borrow<py::class_<SE3d>>(m.attr("SE3"));

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
    >>> chasles.rplus(g, [0.0, 2.0, 0.0, 0.0, 0.0, 0.0]).translation()
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
}

}  // namespace chasles_py
