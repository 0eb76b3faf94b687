// chasles._core: what the classes of the Lie groups share, written once for
// SO2, SE2, SO3 and SE3 from the traits Lie<G> (after manif's
// python/bindings_lie_group_base.h): the Jacobians of exp as static methods,
// the action on points through the array function, the object protocol
// (==, repr, __array__, copy, pickle), numpy's Generator for random, scipy's
// classes. Each group's class is made and bound in its own file
// (bind_so3.cpp, bind_se3.cpp, bind_planar.cpp), which calls def_lie_group
// with what only it has; the module-level functions of the groups are in
// bind_jacobians.cpp.
#pragma once

#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <utility>

#include <chasles/jacobians.hpp>
#include <chasles/se2.hpp>
#include <chasles/se3.hpp>
#include <chasles/so2.hpp>
#include <chasles/so3.hpp>
#include <chasles/twist.hpp>

#include "bindings.hpp"
#include "convert.hpp"

namespace chasles_py {

template <typename G>
struct Lie;

template <>
struct Lie<chasles::SO3d> : GroupNames<chasles::SO3d> {
  static constexpr int N = 3, D = 3, P = 3;  // the matrix size, the tangent dimension, the point size
  using Tangent = Eigen::Matrix<double, D, 1>;
  using Jacobian = Eigen::Matrix<double, D, D>;
  static constexpr const char* tangent = "w";
  static constexpr const char* act_ufunc = "so3_act";
  static constexpr const char* act_hint = "an SO3 composes only with an SO3";
  static constexpr const char* inverse = "R^-1 = R^T";
  static constexpr const char* matrix = "The rotation matrix R";
  static constexpr const char* example = "[0.3, 0.2, 0.1]";
  static constexpr const char* adjoint = "Ad_R = R (3x3), so that R exp([w]) R^T = exp([R w]).";
  static constexpr const char* between =
      "in between, the rotation about one fixed axis\n(slerp). Values outside [0, 1] extrapolate";
  static constexpr const char* approx = "max |R_a - R_b| <= tol";
  static constexpr const char* tol = "the largest accepted difference of matrix entries (>= 0)";
  static constexpr Jacobian (*jacobians[4])(const Tangent&) = {
      [](const Tangent& w) { return chasles::so3_right_jacobian(w); },
      [](const Tangent& w) { return chasles::so3_left_jacobian(w); },
      [](const Tangent& w) { return chasles::so3_right_jacobian_inverse(w); },
      [](const Tangent& w) { return chasles::so3_left_jacobian_inverse(w); }};
  static constexpr const char* acted = "points or vectors";
  static constexpr const char* action = "p_a = R_ab p_b";
  static constexpr const char* symbol = "R";
  static constexpr const char* moved = "rotated";
  static constexpr const char* act_example = R"doc(
Example:
    >>> R = SO3.exp([0.0, 0.0, np.pi])
    >>> np.round(R.act([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]), 12) + 0.0
    array([[-1.,  0.,  0.],
           [ 0.,  0.,  1.]])
)doc";
  /// The tangent argument of exp: shape (3,), finite.
  static Tangent tangent_arg(py::handle h, const char* what) { return to_finite_eigen<D>(h, what); }
  static constexpr const char* exp_doc = R"doc(The rotation exp([w]) of a rotation vector, by Rodrigues' formula.

R = I + (sin theta / theta) [w] + ((1 - cos theta) / theta^2) [w]^2 with
theta = |w|, exact to a few ulps for every w (Taylor series near 0).

Args:
    w: rotation vector, shape (3,): unit axis times angle in radians.

Returns:
    SO3: exp([w]).

Raises:
    ValueError: w is not of shape (3,), or not finite.
    TypeError: w is not real (complex, object, str, None).

Example:
    >>> R = SO3.exp([0.0, 0.0, np.pi / 2])
    >>> np.round(R.as_matrix(), 12) + 0.0
    array([[ 0., -1.,  0.],
           [ 1.,  0.,  0.],
           [ 0.,  0.,  1.]])
)doc";
  static constexpr const char* log_doc = R"doc(The rotation vector w with exp([w]) = R and |w| in [0, pi].

At exactly pi both axis signs are correct; one of them is returned, never
NaN. Accurate to a few ulps, and to O(d) for a matrix off SO(3) by d.

Returns:
    ndarray: w, shape (3,), float64.

Example:
    >>> SO3.exp([0.1, -0.2, 0.3]).log()
    array([ 0.1, -0.2,  0.3])
)doc";
  static constexpr const char* hat_doc = R"doc(The skew-symmetric matrix [w] of w, so that [w] @ p = w x p.

Args:
    w: vector, shape (3,).

Returns:
    ndarray: [w] = [[0, -w3, w2], [w3, 0, -w1], [-w2, w1, 0]], shape (3, 3).

Example:
    >>> SO3.hat([1.0, 2.0, 3.0])
    array([[ 0., -3.,  2.],
           [ 3.,  0., -1.],
           [-2.,  1.,  0.]])
)doc";
  static constexpr const char* vee_doc = R"doc(The vector w of a skew-symmetric matrix [w]: the inverse of hat.

Reads the antisymmetric part (W - W^T)/2, so a matrix that is not exactly
skew gives the w of its nearest skew matrix.

Args:
    matrix: shape (3, 3).

Returns:
    ndarray: w, shape (3,).

Example:
    >>> SO3.vee(SO3.hat([1.0, 2.0, 3.0]))
    array([1., 2., 3.])
)doc";
  static constexpr const char* from_matrix_doc = R"doc(Checked construction from a rotation matrix.

Accepts M when its rotation defect max(|M^T M - I|_max, |det M - 1|) is at
most tol (default sqrt(eps) = 1.49e-08: data printed with about 9 significant
digits passes). Keeps M as it is (no projection).

Args:
    matrix: shape (3, 3), finite.
    tol: the largest accepted defect.

Returns:
    SO3: the rotation M.

Raises:
    ValueError: M is not a rotation within tol (the message gives the defect
        and det M; use ``SO3.from_matrix_projected`` for the nearest
        rotation), or M is not finite, or not of shape (3, 3).

Example:
    >>> R = SO3.from_matrix([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    >>> np.round(R.log(), 12) + 0.0
    array([0.        , 0.        , 1.57079633])
)doc";
  static constexpr const char* projected_doc = R"doc(The rotation nearest to a matrix in the Frobenius norm.

For det M > 0 this is the orthogonal polar factor; it is defined for every
finite M, reflections and singular matrices included.

Args:
    matrix: shape (3, 3), finite.

Returns:
    SO3: the nearest rotation.

Example:
    >>> M = SO3.exp([0.1, 0.2, 0.3]).as_matrix() + 1e-4
    >>> SO3.from_matrix_projected(M).is_approx(SO3.exp([0.1, 0.2, 0.3]), tol=1e-3)
    True
)doc";
  static constexpr const char* unchecked_doc = R"doc(Construction without a check, for data known to be a rotation.

Only the shape and finiteness are checked. Operations on an SO3 built from a
matrix that is not a rotation give meaningless results.

Args:
    matrix: shape (3, 3), finite.

Returns:
    SO3: the matrix as it is.
)doc";
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
struct Lie<chasles::SE3d> : GroupNames<chasles::SE3d> {
  static constexpr int N = 4, D = 6, P = 3;
  using Tangent = Eigen::Matrix<double, D, 1>;
  using Jacobian = Eigen::Matrix<double, D, D>;
  static constexpr const char* tangent = "xi";
  static constexpr const char* act_ufunc = "se3_act";
  static constexpr const char* act_hint =
      "an SE3 composes with an SE3 by @; it acts on a Twist or a Wrench by g.act(x)";
  static constexpr const char* inverse = "g^-1 = [[R^T, -R^T p], [0, 1]]";
  static constexpr const char* matrix = "The homogeneous matrix g = [[R, p], [0, 1]]";
  static constexpr const char* example = "[0.1, 0.2, 0.3, 0.4, 0.5, 0.6]";
  static constexpr const char* adjoint =
      "Ad_g = [[R, [p] R], [0, R]] (6x6, Murray-Li-Sastry order).\n\n"
      "g [xi] g^-1 = [Ad_g xi]: twists change frame by xi_a = Ad_g xi_b; wrenches\n"
      "by F_b = Ad_g^T F_a.";
  static constexpr const char* between = "and the motion in between is one screw motion";
  static constexpr const char* approx =
      "rotation matrices within tol (absolute), translations within\ntol * max(1, |p|_max) (relative beyond unit "
      "scale)";
  static constexpr const char* tol = "the tolerance (>= 0)";
  static constexpr Jacobian (*jacobians[4])(const Tangent&) = {
      [](const Tangent& xi) { return chasles::se3_right_jacobian(xi); },
      [](const Tangent& xi) { return chasles::se3_left_jacobian(xi); },
      [](const Tangent& xi) { return chasles::se3_right_jacobian_inverse(xi); },
      [](const Tangent& xi) { return chasles::se3_left_jacobian_inverse(xi); }};
  static constexpr const char* acted = "points";
  static constexpr const char* action = "q_a = R q_b + p";
  static constexpr const char* symbol = "g";
  static constexpr const char* moved = "moved";
  static constexpr const char* act_example = R"doc(
Example:
    >>> g = SE3(translation=[1.0, 0.0, 0.0])
    >>> g.act([[0.0, 0.0, 0.0], [1.0, 1.0, 1.0]])
    array([[1., 0., 0.],
           [2., 1., 1.]])
)doc";
  /// The tangent argument of exp: a Twist, or anything array-like of shape (6,), finite.
  static Tangent tangent_arg(py::handle h, const char* what) {
    if (is_native_float64_array(h.ptr())) return to_finite_eigen<D>(h, what);
    py::detail::make_caster<Obj<chasles::Twistd>> twist;
    if (twist.load(h, false)) return static_cast<Obj<chasles::Twistd>&>(twist).ptr->vector();
    return to_finite_eigen<D>(h, what);
  }
  static constexpr const char* exp_doc = R"doc(The screw motion exp([xi]) of a twist xi = (v, w), linear part first.

In closed form, with theta = |w|: R = exp([w]), p = V v,
V = I + ((1 - cos theta) / theta^2) [w] + ((theta - sin theta) / theta^3) [w]^2;
w = 0 (pure translation) and tiny w included, exact to a few ulps.

Args:
    xi: twist coordinates (v, w), shape (6,), finite; or a Twist.

Returns:
    SE3: exp([xi]).

Example:
    >>> g = SE3.exp([1.0, 0.0, 0.0, 0.0, 0.0, np.pi / 2])
    >>> np.round(g.translation, 12) + 0.0
    array([0.63661977, 0.63661977, 0.        ])
)doc";
  static constexpr const char* log_doc = R"doc(The twist xi = (v, w) with exp([xi]) = g, rotation angle |w| in [0, pi].

w = log(R); v = V^-1 p. At a rotation angle of exactly pi either axis sign is
returned, never NaN.

Returns:
    ndarray: xi = (v, w), shape (6,), linear part first.

Example:
    >>> SE3(translation=[1.0, 2.0, 3.0]).log()
    array([1., 2., 3., 0., 0., 0.])
)doc";
  static constexpr const char* hat_doc = R"doc(The 4x4 matrix [xi] = [[ [w], v ], [0, 0]] of a twist xi = (v, w).

Args:
    xi: shape (6,), (v, w).

Returns:
    ndarray: shape (4, 4).

Example:
    >>> SE3.hat([1.0, 2.0, 3.0, 0.0, 0.0, 1.0]) + 0.0
    array([[ 0., -1.,  0.,  1.],
           [ 1.,  0.,  0.,  2.],
           [ 0.,  0.,  0.,  3.],
           [ 0.,  0.,  0.,  0.]])
)doc";
  static constexpr const char* vee_doc = R"doc(The twist (v, w) of a 4x4 matrix [[S, v], [*, *]]: the inverse of hat.

w is read from the antisymmetric part of S; the bottom row is ignored.

Args:
    matrix: shape (4, 4).

Returns:
    ndarray: xi = (v, w), shape (6,).
)doc";
  static constexpr const char* from_matrix_doc =
      R"doc(Checked construction from a 4x4 homogeneous matrix [[R, p], [0, 1]].

Accepts M when the rotation defect of its top-left block,
max(|R^T R - I|_max, |det R - 1|), and the deviation of its bottom row from
(0, 0, 0, 1) are both at most tol (default sqrt(eps) = 1.49e-08).

Args:
    matrix: shape (4, 4), finite.
    tol: the largest accepted defect.

Returns:
    SE3: the motion.

Raises:
    ValueError: M is not a rigid motion within tol (the message gives both
        defects; use ``SE3.from_matrix_projected`` for the nearest rotation),
        or M is not finite, or not of shape (4, 4).

Example:
    >>> SE3.from_matrix(np.eye(4)).is_approx(SE3())
    True
)doc";
  static constexpr const char* projected_doc =
      R"doc(The nearest rotation to the top-left block, and the translation column.

The bottom row is not read.

Args:
    matrix: shape (4, 4), finite.

Returns:
    SE3: the projected motion.
)doc";
  static constexpr const char* unchecked_doc = R"doc(Construction without a check from [[R, p], [*, *]], for valid data.

Only the shape and finiteness are checked; the bottom row is not read.

Args:
    matrix: shape (4, 4), finite.

Returns:
    SE3: the motion.
)doc";
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

/// g's action on points: the array function so3_act, se3_act, ... with g's
/// matrix (numpy's rules for dtypes, broadcasting and the GIL), or for one
/// point of float64 the same kernel without numpy's dispatch (the same
/// bits; for Sim3 within an ulp or two: the array function reads s and R
/// back from the matrix s R). Points of float32 give float32: the matrix is rounded to float32
/// once and the float32 kernel runs, as se3_act on a float32 pose would
/// (without it numpy would promote the points to float64: twice the memory).
template <typename G>
py::object act_points(const G& g, ArrayLike points, const char* what) {
  using L = Lie<G>;
  const auto& api = npy();
  PyObject* o = points.obj.ptr();
  if (!api.PyArray_Check_(o) && is_bound_object(points.obj))
    raise_type_error(std::string(what) + ": expected points of shape (..., " + std::to_string(L::P) + "), got " +
                     type_name(points.obj) + " (" + L::act_hint + ")");
  if (Eigen::Matrix<double, L::P, 1> p; single_element(points.obj, p.data(), L::P)) return vec_out<L::P>(g.act(p));
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
  static PyObject* const default_rng =
      py::handle(numpy_attr("random")).attr("default_rng").cast<py::object>().release().ptr();
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
    py::raise_from(PyExc_ImportError,
                   (std::string(what) + " needs scipy (scipy.spatial.transform), which could not be imported; "
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

/// A tangent result: SO2's angle as a float, others as an array of shape (D,).
template <int D>
auto tangent_out(const Eigen::Matrix<double, D, 1>& x) {
  if constexpr (D == 1) {
    return x[0];
  } else {
    return vec_out<D>(x);
  }
}

/// `text` with {G} (the class), {kind}, {inverse}, {matrix}, {example},
/// {adjoint}, {between}, {approx}, {tol}, {N}, {D}, {t} (the tangent's name), {acted},
/// {action}, {g} (the element's symbol), {moved}, {act} (the array function) and {P} (the point size) of the
/// group G.
template <typename G>
std::string group_text(std::string text) {
  using L = Lie<G>;
  const std::pair<const char*, std::string> fields[] = {{"{G}", L::cls},
                                                        {"{kind}", L::kind},
                                                        {"{inverse}", L::inverse},
                                                        {"{matrix}", L::matrix},
                                                        {"{example}", L::example},
                                                        {"{adjoint}", L::adjoint},
                                                        {"{between}", L::between},
                                                        {"{approx}", L::approx},
                                                        {"{tol}", L::tol},
                                                        {"{N}", std::to_string(L::N)},
                                                        {"{D}", std::to_string(L::D)},
                                                        {"{t}", L::tangent},
                                                        {"{acted}", L::acted},
                                                        {"{action}", L::action},
                                                        {"{g}", L::symbol},
                                                        {"{moved}", L::moved},
                                                        {"{act}", L::act_ufunc},
                                                        {"{P}", std::to_string(L::P)}};
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

/// What the groups share: the group operations (inverse, @, the action on
/// points, adjoint, as_matrix, normalized, interpolate, is_approx) with one
/// docstring for both, the Jacobians of exp (static methods), the matrix as
/// __array__, exp, log, hat, vee, the three constructions from a matrix
/// (from_matrix refuses with `invalid(M, tol, fn, tol_argument)`), and the
/// value protocol over the state of `state(g)` (def_value_protocol), made
/// back by `from_state`.
template <int S, typename G, typename Repr, typename State, typename FromState>
void def_lie_group(Class<G>& cls, Repr repr, State state, FromState from_state,
                   void (*invalid)(const Eigen::Matrix<double, Lie<G>::N, Lie<G>::N>&, double, const char*, bool)) {
  using L = Lie<G>;
  using Matrix = Eigen::Matrix<double, L::N, L::N>;
  static const char* const exp_what = group_doc<G>("{G}.exp({t})");
  cls.def_static(
      "exp", [](ArrayLike x) { return G::exp(L::tangent_arg(x.obj, exp_what)); }, py::arg(L::tangent), L::exp_doc);
  cls.def("log", [](Obj<G> g) { return tangent_out<L::D>(g->log()); }, L::log_doc);
  static const char* const hat_what = group_doc<G>("{G}.hat({t})");
  cls.def_static(
      "hat", [](ArrayLike x) { return mat_out<L::N, L::N>(G::hat(to_tangent<L::D>(x.obj, hat_what, false))); },
      py::arg(L::tangent), L::hat_doc);
  static const char* const vee_what = group_doc<G>("{G}.vee(matrix)");
  cls.def_static(
      "vee", [](ArrayLike X) { return tangent_out<L::D>(G::vee(to_eigen<L::N, L::N>(X.obj, vee_what))); },
      py::arg("matrix"), L::vee_doc);
  static const char* const matrix_what = group_doc<G>("{G}.from_matrix(matrix)");
  static const char* const tol_arg_what = group_doc<G>("{G}.from_matrix(tol)");
  static const char* const fn_what = group_doc<G>("{G}.from_matrix");
  static auto* const refuse = invalid;
  cls.def_static(
      "from_matrix",
      [](ArrayLike matrix, RealLike tol) {
        const Matrix M = to_finite_eigen<L::N, L::N>(matrix.obj, matrix_what);
        const double t = to_tolerance(tol.obj, tol_arg_what);
        const auto g = G::from_matrix(M, t);
        if (!g) refuse(M, t, fn_what, true);
        return *g;
      },
      py::arg("matrix"), py::arg_v("tol", chasles::Thresholds<double>::rotation_tolerance), L::from_matrix_doc);
  static const char* const projected_what = group_doc<G>("{G}.from_matrix_projected(matrix)");
  cls.def_static(
      "from_matrix_projected",
      [](ArrayLike matrix) {
        return G::from_matrix_projected(to_finite_eigen<L::N, L::N>(matrix.obj, projected_what));
      },
      py::arg("matrix"), L::projected_doc);
  static const char* const unchecked_what = group_doc<G>("{G}.from_matrix_unchecked(matrix)");
  cls.def_static(
      "from_matrix_unchecked",
      [](ArrayLike matrix) {
        return G::from_matrix_unchecked(to_finite_eigen<L::N, L::N>(matrix.obj, unchecked_what));
      },
      py::arg("matrix"), L::unchecked_doc);
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
  static const std::string act_doc = group_text<G>(R"doc(

The array function {act} with this {kind}: numpy's rules for dtypes and
broadcasting.

Args:
    points: array_like of shape (..., {P}).

Returns:
    ndarray: the {moved} points, shape (..., {P}).
)doc");
  static const std::string matmul_doc = group_text<G>("Action on {acted}: {action}.") + act_doc;
  static const char* const matmul_what = group_doc<G>("{G} @ points");
  cls.def(
      "__matmul__", [](Obj<G> g, ArrayLike p) { return act_points(*g, p, matmul_what); }, py::arg("points"),
      matmul_doc.c_str());
  static const std::string act_full_doc =
      group_text<G>("Action on {acted}: {action} (the same as ``{g} @ points``).") + act_doc + L::act_example;
  static const char* const act_what = group_doc<G>("{G}.act(points)");
  cls.def(
      "act", [](Obj<G> g, ArrayLike p) { return act_points(*g, p, act_what); }, py::arg("points"),
      act_full_doc.c_str());
  cls.def(
      "adjoint", [](Obj<G> g) { return mat_out<L::D, L::D>(g->adjoint()); }, group_doc<G>(R"doc(The adjoint {adjoint}

Returns:
    ndarray: shape ({D}, {D}).
)doc"));
  cls.def("as_matrix", [](Obj<G> g) { return mat_out<L::N, L::N>(g->matrix()); }, group_doc<G>(R"doc({matrix}.

Returns:
    ndarray: shape ({N}, {N}), float64 (a new array).
)doc"));
  cls.def(
      "normalized", [](Obj<G> g) { return g->normalized(); },
      group_doc<G>(R"doc(The same {kind} with the nearest rotation.

Removes the drift that accumulates over many compositions.

Returns:
    {G}: the projected {kind}.
)doc"));
  static const std::string interpolate_what = std::string(L::cls) + ".interpolate(t)";
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
  static const std::string pow_what = std::string(L::cls) + " ** t";
  cls.def(
      "__pow__",
      [](Obj<G> g, RealLike t) {
        return chasles::interpolate(G::identity(), *g, to_finite_real(t.obj, pow_what.c_str()));
      },
      py::arg("t"), py::is_operator(), group_doc<G>(R"doc(The power exp(t log g): t = 0 gives the identity, t = 1
this {kind}, t = -1 its inverse, t = 0.5 the {kind} half way along its
geodesic from the identity (the one whose square it is, for angles below pi),
as scipy's ``Rotation.__pow__``.

Args:
    t: the exponent, finite (not only an integer).

Returns:
    {G}: the power.

Example:
    >>> g = {G}.exp({example})
    >>> ((g ** 0.5) @ (g ** 0.5)).is_approx(g) and (g ** -1).is_approx(g.inverse())
    True
)doc"));
  static const std::string tol_what = std::string(L::cls) + ".is_approx(tol)";
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
    const std::string what = std::string(L::cls) + "." + names[k] + "(" + L::tangent + ")";
    const auto J = L::jacobians[k];
    cls.def_static(
        names[k],
        [J, what](ArrayLike x) { return mat_out<L::D, L::D>(J(to_tangent<L::D>(x.obj, what.c_str(), true))); },
        py::arg(L::tangent), docs[k].c_str());
  }
  static const std::string array_doc =
      std::string("The ") + (std::string(L::kind) == "rotation" ? "rotation" : "homogeneous") + " matrix, shape (" +
      std::to_string(L::N) + ", " + std::to_string(L::N) + "), for np.asarray (numpy's dtype and copy keywords).";
  def_array(cls, [](const G& g) { return mat_out<L::N, L::N>(g.matrix()); }, array_doc.c_str());
  def_value_protocol<S>(cls, repr, state, from_state);
}

}  // namespace chasles_py
