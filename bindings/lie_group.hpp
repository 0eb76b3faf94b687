// chasles._core: what the classes of the Lie groups share, written once for
// SO3 and SE3 from the traits Lie<G> (after manif's
// python/bindings_lie_group_base.h): the Jacobians of exp as static methods,
// the action on points through the array function, the object protocol
// (==, repr, __array__, copy, pickle), numpy's Generator for random, scipy's
// classes. Each group's class is made and bound in its own file
// (bind_so3.cpp, bind_se3.cpp), which calls def_lie_group with what only it
// has; the module-level functions of the groups are in bind_jacobians.cpp.
#pragma once

#include <cstdio>
#include <cstring>
#include <memory>
#include <utility>
#include <string>

#include <chasles/jacobians.hpp>
#include <chasles/se3.hpp>
#include <chasles/so3.hpp>

#include "bindings.hpp"
#include "convert.hpp"

namespace chasles_py {

template <typename G>
struct Lie;

template <>
struct Lie<chasles::SO3d> {
  static constexpr int N = 3, D = 3;  // the matrix size, the tangent dimension
  using Tangent = Eigen::Matrix<double, D, 1>;
  using Jacobian = Eigen::Matrix<double, D, D>;
  static constexpr const char* name = "SO3";
  static constexpr const char* tangent = "w";
  static constexpr const char* act_ufunc = "so3_act";
  static constexpr const char* act_hint = "an SO3 composes only with an SO3";
  static constexpr const char* kind = "rotation";
  static constexpr const char* inverse = "R^-1 = R^T";
  static constexpr const char* matrix = "The rotation matrix R";
  static constexpr const char* example = "[0.3, 0.2, 0.1]";
  static constexpr const char* adjoint = "Ad_R = R (3x3), so that R exp([w]) R^T = exp([R w]).";
  static constexpr const char* between = "in between, the rotation about one fixed axis\n(slerp). Values outside [0, 1] extrapolate";
  static constexpr const char* approx = "max |R_a - R_b| <= tol";
  static constexpr const char* tol = "the largest accepted difference of matrix entries (>= 0)";
  static constexpr Jacobian (*jacobians[4])(const Tangent&) = {
      [](const Tangent& w) { return chasles::so3_right_jacobian(w); },
      [](const Tangent& w) { return chasles::so3_left_jacobian(w); },
      [](const Tangent& w) { return chasles::so3_right_jacobian_inverse(w); },
      [](const Tangent& w) { return chasles::so3_left_jacobian_inverse(w); }};
  static constexpr const char* jacobian_doc = R"doc(The %s of SO(3) at the rotation vector w, shape (3, 3).

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
};

template <>
struct Lie<chasles::SE3d> {
  static constexpr int N = 4, D = 6;
  using Tangent = Eigen::Matrix<double, D, 1>;
  using Jacobian = Eigen::Matrix<double, D, D>;
  static constexpr const char* name = "SE3";
  static constexpr const char* tangent = "xi";
  static constexpr const char* act_ufunc = "se3_act";
  static constexpr const char* act_hint =
      "an SE3 composes with an SE3 by @; it acts on a Twist or a Wrench by g.act(x)";
  static constexpr const char* kind = "motion";
  static constexpr const char* inverse = "g^-1 = [[R^T, -R^T p], [0, 1]]";
  static constexpr const char* matrix = "The homogeneous matrix g = [[R, p], [0, 1]]";
  static constexpr const char* example = "[0.1, 0.2, 0.3, 0.4, 0.5, 0.6]";
  static constexpr const char* adjoint = "Ad_g = [[R, [p] R], [0, R]] (6x6, Murray-Li-Sastry order).\n\n"
                                         "g [xi] g^-1 = [Ad_g xi]: twists change frame by xi_a = Ad_g xi_b; wrenches\n"
                                         "by F_b = Ad_g^T F_a.";
  static constexpr const char* between = "and the motion in between is one screw motion";
  static constexpr const char* approx =
      "rotation matrices within tol (absolute), translations within\ntol * max(1, |p|_max) (relative beyond unit scale)";
  static constexpr const char* tol = "the tolerance (>= 0)";
  static constexpr Jacobian (*jacobians[4])(const Tangent&) = {
      [](const Tangent& xi) { return chasles::se3_right_jacobian(xi); },
      [](const Tangent& xi) { return chasles::se3_left_jacobian(xi); },
      [](const Tangent& xi) { return chasles::se3_right_jacobian_inverse(xi); },
      [](const Tangent& xi) { return chasles::se3_left_jacobian_inverse(xi); }};
  static constexpr const char* jacobian_doc = R"doc(The %s of SE(3) at the twist xi = (v, w), shape (6, 6).

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
};

/// g's action on points: the array function so3_act / se3_act with g's
/// matrix (numpy's rules for dtypes, broadcasting and the GIL), or for one
/// point of float64 the same kernel without numpy's dispatch (the same
/// bits). Points of float32 give float32: the matrix is rounded to float32
/// once and the float32 kernel runs, as se3_act on a float32 pose would
/// (without it numpy would promote the points to float64: twice the memory).
template <typename G>
py::object act_points(const G& g, ArrayLike points, const char* what) {
  using L = Lie<G>;
  const auto& api = npy();
  PyObject* o = points.obj.ptr();
  if (!api.PyArray_Check_(o) && is_bound_object(points.obj))
    raise_type_error(std::string(what) + ": expected points of shape (..., 3), got " + type_name(points.obj) + " (" +
                     L::act_hint + ")");
  if (Eigen::Vector3d p; single_element(points.obj, p.data(), 3)) return vec_out<3>(g.act(p));
  py::object M = mat_out<L::N, L::N>(g.matrix());
  if (api.PyArray_Check_(o) && py::detail::array_descriptor_proxy(py::detail::array_proxy(o)->descr)->type_num ==
                                   py::detail::npy_api::NPY_FLOAT_)
    M = M.attr("astype")(py::dtype::of<float>());
  const py::object p = ufunc_operand(points.obj, what);
  static PyObject* const act = array_function(L::act_ufunc);
  return call_ufunc<2>(act, what, {M.ptr(), p.ptr()});
}

/// numpy's Generator of `rng` as the samplers take it: None (a fresh
/// default_rng()), an int seed >= 0, a SeedSequence, a BitGenerator or a
/// Generator (used, and advanced, as is); numpy's TypeError or ValueError
/// re-raised naming `name`.
inline py::object numpy_generator(py::handle rng, const char* name) {
  static PyObject* const default_rng = py::handle(numpy_attr("random")).attr("default_rng").cast<py::object>().release().ptr();
  PyObject* g = PyObject_CallOneArg(default_rng, rng.ptr());
  if (g != nullptr) return py::reinterpret_steal<py::object>(g);
  py::error_already_set e;
  if (!e.matches(PyExc_TypeError) && !e.matches(PyExc_ValueError)) throw e;
  const std::string text = std::string(name) +
                           "(rng): expected None, an int seed >= 0, a SeedSequence, a BitGenerator or a "
                           "numpy.random.Generator, got " +
                           py::repr(rng).cast<std::string>() + " (" + e.what() + ")";
  if (e.matches(PyExc_TypeError)) throw py::type_error(text);
  throw py::value_error(text);
}

/// Three uniforms in [0, 1) drawn from the Generator gen.
inline Eigen::Vector3d uniforms(const py::object& gen, const char* what) {
  return to_eigen<3>(gen.attr("random")(3), what);
}

/// scipy.spatial.transform's class `name`, imported now (scipy is no
/// dependency of the package); ImportError naming `what` when scipy (or a
/// scipy recent enough to have `name`) is missing.
inline py::object scipy_class(const char* name, const char* what) {
  PyObject* mod = PyImport_ImportModule("scipy.spatial.transform");
  if (mod == nullptr) {
    if (!PyErr_ExceptionMatches(PyExc_ImportError)) throw py::error_already_set();
    py::raise_from(PyExc_ImportError, (std::string(what) +
                                       " needs scipy (scipy.spatial.transform), which could not be imported; "
                                       "install it with `pip install scipy`")
                                          .c_str());
    throw py::error_already_set();
  }
  const py::module_ transform = py::reinterpret_steal<py::module_>(mod);
  if (!py::hasattr(transform, name)) {
    const std::string version = py::str(py::module_::import("scipy").attr("__version__"));
    throw py::import_error(std::string(what) + " needs scipy.spatial.transform." + name + " (scipy >= 1.16); scipy " +
                           version + " is installed");
  }
  return transform.attr(name);
}

/// obj as a single instance of scipy's class `kind` (TypeError for another
/// type, ValueError for a stack, with `batch`: the array route for one).
inline void check_single_scipy(py::handle obj, const char* kind, const char* what, const char* batch) {
  if (!py::isinstance(obj, scipy_class(kind, what))) {
    raise_type_error(std::string(what) + ": expected a scipy.spatial.transform." + kind + ", got " + type_name(obj));
  }
  if (!obj.attr("single").cast<bool>()) {
    const std::string shape = py::str(obj.attr("as_matrix")().attr("shape"));
    raise_value_error(std::string(what) + ": expected a single " + kind + ", got a stack (as_matrix() of shape " +
                      shape + "). " + batch);
  }
}

/// `text` with {G} (the class), {kind}, {inverse}, {matrix}, {example},
/// {adjoint}, {between}, {approx}, {tol}, {N} and {D} of the group G.
template <typename G>
std::string group_text(std::string text) {
  using L = Lie<G>;
  const std::pair<const char*, std::string> fields[] = {
      {"{G}", L::name},         {"{kind}", L::kind},         {"{inverse}", L::inverse}, {"{matrix}", L::matrix},
      {"{example}", L::example}, {"{adjoint}", L::adjoint}, {"{between}", L::between}, {"{approx}", L::approx},
      {"{tol}", L::tol},         {"{N}", std::to_string(L::N)}, {"{D}", std::to_string(L::D)}};
  for (const auto& [key, value] : fields)
    for (std::size_t at = text.find(key); at != std::string::npos; at = text.find(key, at + value.size()))
      text.replace(at, std::strlen(key), value);
  return text;
}

/// A docstring of group_text, kept for the process (pybind11 keeps the pointer).
template <typename G>
const char* group_doc(const char* text) {
  return (new std::string(group_text<G>(text)))->c_str();
}

/// What SO3 and SE3 share: the group operations (inverse, @, the action on
/// points, adjoint, as_matrix, normalized, interpolate, is_approx) with one
/// docstring for both, the Jacobians of exp (static methods), the matrix as
/// __array__, and the value protocol over the state of `state(g)`
/// (def_value_protocol), made back by `from_state`.
template <int S, typename G, typename Repr, typename State, typename FromState>
void def_lie_group(Class<G>& cls, Repr repr, State state, FromState from_state) {
  using L = Lie<G>;
  cls.def("inverse", [](Obj<G> g) { return g->inverse(); }, group_doc<G>(R"doc(The inverse {kind} {inverse}.

Returns:
    {G}: the inverse.

Example:
    >>> g = {G}.exp({example})
    >>> (g @ g.inverse()).is_approx({G}.identity())
    True
)doc"));
  cls.def(
      "__matmul__", [](Obj<G> a, Obj<G> b) { return *a * *b; }, py::arg("other"), py::is_operator(),
      group_doc<G>(R"doc(Composition: g_ab @ g_bc = g_ac.

Args:
    other: {G}.

Returns:
    {G}: the composed {kind}.
)doc"));
  cls.def("adjoint", [](Obj<G> g) { return mat_out<L::D, L::D>(g->adjoint()); }, group_doc<G>(R"doc(The adjoint {adjoint}

Returns:
    ndarray: shape ({D}, {D}).
)doc"));
  cls.def("as_matrix", [](Obj<G> g) { return mat_out<L::N, L::N>(g->matrix()); }, group_doc<G>(R"doc({matrix}.

Returns:
    ndarray: shape ({N}, {N}), float64 (a new array).
)doc"));
  cls.def("normalized", [](Obj<G> g) { return g->normalized(); }, group_doc<G>(R"doc(The same {kind} with the nearest rotation.

Removes the drift that accumulates over many compositions.

Returns:
    {G}: the projected {kind}.
)doc"));
  static const std::string interpolate_what = std::string(L::name) + ".interpolate(t)";
  cls.def_static(
      "interpolate",
      [](Obj<G> a, Obj<G> b, RealLike t) {
        return chasles::interpolate(*a, *b, to_finite_real(t.obj, interpolate_what.c_str()));
      },
      py::arg("a"), py::arg("b"), py::arg("t"), group_doc<G>(R"doc(Geodesic interpolation a exp(t log(a^-1 b)).

t = 0 gives a, t = 1 gives b, {between}.

Args:
    a: {G}, the start.
    b: {G}, the end.
    t: the fraction, finite.

Returns:
    {G}: the interpolated {kind}.

Example:
    >>> a, b = {G}(), {G}.exp({example})
    >>> {G}.interpolate(a, b, 0.5).is_approx(a @ {G}.exp(0.5 * np.array({example})))
    True
)doc"));
  static const std::string tol_what = std::string(L::name) + ".is_approx(tol)";
  cls.def(
      "is_approx",
      [](Obj<G> a, Obj<G> b, RealLike tol) { return a->is_approx(*b, to_tolerance(tol.obj, tol_what.c_str())); },
      py::arg("other"), py::arg_v("tol", 1e-9), group_doc<G>(R"doc(Whether two {kind}s are equal within tol: {approx}.

``==`` is the exact comparison (every stored number equal).

Args:
    other: {G}.
    tol: {tol}.

Returns:
    bool.
)doc"));
  static const char* const names[4] = {"right_jacobian", "left_jacobian", "right_jacobian_inverse",
                                       "left_jacobian_inverse"};
  static const char* const titles[4] = {"right Jacobian J_r", "left Jacobian J_l", "inverse right Jacobian J_r^-1",
                                        "inverse left Jacobian J_l^-1"};
  static std::string docs[4];  // pybind11 keeps the pointers
  for (int k = 0; k < 4; ++k) {
    char buf[2048];
    std::snprintf(buf, sizeof buf, L::jacobian_doc, titles[k]);
    docs[k] = buf;
    const std::string what = std::string(L::name) + "." + names[k] + "(" + L::tangent + ")";
    const auto J = L::jacobians[k];
    cls.def_static(
        names[k], [J, what](ArrayLike x) { return mat_out<L::D, L::D>(J(to_finite_eigen<L::D>(x.obj, what.c_str()))); },
        py::arg(L::tangent), docs[k].c_str());
  }
  static const std::string array_doc = std::string("The ") + (L::N == 3 ? "rotation" : "homogeneous") +
                                       " matrix, shape (" + std::to_string(L::N) + ", " + std::to_string(L::N) +
                                       "), for np.asarray (numpy's dtype and copy keywords).";
  def_array(cls, [](const G& g) { return mat_out<L::N, L::N>(g.matrix()); }, array_doc.c_str());
  def_value_protocol<S>(cls, repr, state, from_state);
}

}  // namespace chasles_py
