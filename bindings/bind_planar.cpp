// chasles._core: classes SO2 and SE2 over chasles::SO2d and chasles::SE2d
// (include/chasles/so2.hpp, se2.hpp): their traits Lie<G> (names and the
// texts only they have), then what only they have beside def_lie_group.
#include <chasles/se2.hpp>
#include <chasles/so2.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "lie_group.hpp"
#include "signatures.hpp"

namespace chasles_py {

template <>
struct Lie<chasles::SO2d> : GroupNames<chasles::SO2d> {
  static constexpr int N = 2, D = 1, P = 2;
  using Tangent = Eigen::Matrix<double, 1, 1>;
  using Jacobian = Eigen::Matrix<double, 1, 1>;
  static constexpr const char* tangent = "theta";
  static constexpr const char* act_ufunc = "so2_act";
  static constexpr const char* act_hint = "an SO2 composes only with an SO2";
  static constexpr const char* inverse = "R^-1 = R^T";
  static constexpr const char* matrix = "The rotation matrix R = [[c, -s], [s, c]]";
  static constexpr const char* example = "0.5";
  static constexpr const char* adjoint = "Ad_R = 1 (1x1): the plane's rotations commute.";
  static constexpr const char* between = "in between, the rotation at constant angular velocity";
  static constexpr const char* approx = "the stored (cos, sin) within tol";
  static constexpr const char* tol = "the largest accepted difference (>= 0)";
  static constexpr Jacobian (*jacobians[4])(const Tangent&) = {
      &chasles::SO2d::right_jacobian, &chasles::SO2d::left_jacobian, &chasles::SO2d::right_jacobian_inverse,
      &chasles::SO2d::left_jacobian_inverse};
  static constexpr const char* acted = "points or vectors of the plane";
  static constexpr const char* action = "p_a = R_ab p_b";
  static constexpr const char* symbol = "R";
  static constexpr const char* moved = "rotated";
  static constexpr const char* act_example = R"doc(
Example:
    >>> np.round(SO2.exp(np.pi / 2).act([[1.0, 0.0], [0.0, 2.0]]), 12) + 0.0
    array([[ 0.,  1.],
           [-2.,  0.]])
)doc";
  static Tangent tangent_arg(py::handle h, const char* what) { return to_tangent<1>(h, what, true); }
  static constexpr const char* exp_doc = R"doc(The rotation by theta: exp(theta) = [[cos, -sin], [sin, cos]].

One sincos, exact to the libm's rounding for every theta.

Args:
    theta: the angle in radians, a float (or shape (1,)), finite.

Returns:
    SO2: the rotation.

Raises:
    ValueError: theta is not finite, or of another shape.
    TypeError: theta is not real.

Example:
    >>> np.round(SO2.exp(np.pi / 2).as_matrix(), 12) + 0.0
    array([[ 0., -1.],
           [ 1.,  0.]])
)doc";
  static constexpr const char* log_doc = R"doc(The angle theta = atan2(sin, cos) in [-pi, pi].

Accurate to an ulp over the whole range (no acos).

Returns:
    float: theta.

Example:
    >>> SO2.exp(0.5).log()
    0.5
)doc";
  static constexpr const char* hat_doc = R"doc(The skew-symmetric matrix of an angle: [[0, -theta], [theta, 0]].

Args:
    theta: a float (or shape (1,)).

Returns:
    ndarray: shape (2, 2).
)doc";
  static constexpr const char* vee_doc = R"doc(The angle of a skew-symmetric 2x2 matrix: (W[1, 0] - W[0, 1]) / 2.

Args:
    matrix: shape (2, 2).

Returns:
    float: theta.
)doc";
  static constexpr const char* from_matrix_doc = R"doc(Checked construction from a 2x2 rotation matrix.

Accepts M when max(|M^T M - I|_max, |det M - 1|) is at most tol (default
sqrt(eps) = 1.49e-08).

Args:
    matrix: shape (2, 2), finite.
    tol: the largest accepted defect.

Returns:
    SO2: the rotation ((c, s) = ((M00 + M11) / 2, (M10 - M01) / 2)).

Raises:
    ValueError: M is not a rotation within tol (the message gives the defect
        and det M), or M is not finite, or not of shape (2, 2).

Example:
    >>> SO2.from_matrix([[0.0, -1.0], [1.0, 0.0]]).log() == np.pi / 2
    True
)doc";
  static constexpr const char* projected_doc = R"doc(The rotation nearest to a 2x2 matrix in the Frobenius norm.

(c, s) along (M00 + M11, M10 - M01), made unit; defined for every finite M
(the identity where that vector is 0).

Args:
    matrix: shape (2, 2), finite.

Returns:
    SO2: the nearest rotation.
)doc";
  static constexpr const char* unchecked_doc = R"doc(Construction without a check, for data known to be a rotation.

(c, s) = ((M00 + M11) / 2, (M10 - M01) / 2): a rotation matrix's own numbers.

Args:
    matrix: shape (2, 2), finite.

Returns:
    SO2: the rotation.
)doc";
  static constexpr const char* jacobian_doc = R"doc(The %s of SO(2) at theta: [[1.]] for every theta.

The plane's rotations commute, so exp(theta + d) = exp(theta) exp(d) exactly
and every Jacobian of exp is the identity (shape (1, 1), for the generic
code and for SE2's blocks).

Args:
    theta: a float (or shape (1,)), finite.

Returns:
    ndarray: [[1.]], shape (1, 1), float64.
)doc";
};

template <>
struct Lie<chasles::SE2d> : GroupNames<chasles::SE2d> {
  static constexpr int N = 3, D = 3, P = 2;
  using Tangent = Eigen::Vector3d;
  using Jacobian = Eigen::Matrix3d;
  static constexpr const char* tangent = "xi";
  static constexpr const char* act_ufunc = "se2_act";
  static constexpr const char* act_hint = "an SE2 composes only with an SE2";
  static constexpr const char* inverse = "g^-1 = [[R^T, -R^T t], [0, 1]]";
  static constexpr const char* matrix = "The homogeneous matrix g = [[R, t], [0, 1]] (3x3)";
  static constexpr const char* example = "[0.1, 0.2, 0.3]";
  static constexpr const char* adjoint = "Ad_g = [[R, (t_y, -t_x)], [0, 1]] (3x3), so that g [xi] g^-1 = [Ad_g xi].";
  static constexpr const char* between = "and the motion in between is one rotation about a fixed point";
  static constexpr const char* approx = "rotations within tol (absolute), translations within\ntol * max(1, |t|_max)";
  static constexpr const char* tol = "the tolerance (>= 0)";
  static constexpr Jacobian (*jacobians[4])(const Tangent&) = {
      &chasles::SE2d::right_jacobian, &chasles::SE2d::left_jacobian, &chasles::SE2d::right_jacobian_inverse,
      &chasles::SE2d::left_jacobian_inverse};
  static constexpr const char* acted = "points of the plane";
  static constexpr const char* action = "q_a = R q_b + t";
  static constexpr const char* symbol = "g";
  static constexpr const char* moved = "moved";
  static constexpr const char* act_example = R"doc(
Example:
    >>> SE2(translation=[1.0, 0.0]).act([[0.0, 0.0], [1.0, 1.0]])
    array([[1., 0.],
           [2., 1.]])
)doc";
  static Tangent tangent_arg(py::handle h, const char* what) { return to_finite_eigen<3>(h, what); }
  static constexpr const char* exp_doc =
      R"doc(The motion exp([xi]) of a planar twist xi = (vx, vy, w), linear part first.

R = exp(w), t = V (vx, vy) with V = [[a, -b], [b, a]], a = sin(w) / w,
b = (1 - cos(w)) / w: one sincos, series below the cutoff, exact to a few
ulps for every xi.

Args:
    xi: (vx, vy, w), shape (3,), finite.

Returns:
    SE2: exp([xi]).

Example:
    >>> np.round(SE2.exp([1.0, 0.0, np.pi / 2]).translation, 12) + 0.0
    array([0.63661977, 0.63661977])
)doc";
  static constexpr const char* log_doc = R"doc(The twist xi = (vx, vy, w) with exp([xi]) = g, w in [-pi, pi].

w = atan2(sin, cos); (vx, vy) = V^-1 t with V^-1 = [[e, w/2], [-w/2, e]],
e = (w/2) cot(w/2), without cancellation near 0 or pi.

Returns:
    ndarray: xi = (vx, vy, w), shape (3,).

Example:
    >>> SE2(translation=[1.0, 2.0]).log()
    array([1., 2., 0.])
)doc";
  static constexpr const char* hat_doc = R"doc(The 3x3 matrix [xi] = [[0, -w, vx], [w, 0, vy], [0, 0, 0]].

Args:
    xi: (vx, vy, w), shape (3,).

Returns:
    ndarray: shape (3, 3).
)doc";
  static constexpr const char* vee_doc = R"doc(The twist (vx, vy, w) of a 3x3 matrix: the inverse of hat.

w is read from the antisymmetric part of the top-left block; the bottom row
is ignored.

Args:
    matrix: shape (3, 3).

Returns:
    ndarray: shape (3,).
)doc";
  static constexpr const char* from_matrix_doc =
      R"doc(Checked construction from a 3x3 homogeneous matrix [[R, t], [0, 1]].

Accepts M when the rotation defect of its top-left block and the deviation
of its bottom row from (0, 0, 1) are both at most tol (default sqrt(eps)).

Args:
    matrix: shape (3, 3), finite.
    tol: the largest accepted defect.

Returns:
    SE2: the motion.

Raises:
    ValueError: M is not a rigid motion within tol (the message gives both
        defects), or M is not finite, or not of shape (3, 3).

Example:
    >>> SE2.from_matrix(np.eye(3)) == SE2()
    True
)doc";
  static constexpr const char* projected_doc =
      R"doc(The nearest rotation to the top-left block, and the translation column.

The bottom row is not read.

Args:
    matrix: shape (3, 3), finite.

Returns:
    SE2: the projected motion.
)doc";
  static constexpr const char* unchecked_doc = R"doc(Construction without a check from [[R, t], [*, *]], for valid data.

Args:
    matrix: shape (3, 3), finite.

Returns:
    SE2: the motion.
)doc";
  static constexpr const char* jacobian_doc = R"doc(The %s of SE(2) at xi = (vx, vy, w), shape (3, 3).

Linear part first. Right (local) convention, as manif:
exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi), with
J_l = [[a, -b, C vx + B vy], [b, a, -B vx + C vy], [0, 0, 1]],
a = sin(w) / w, b = (1 - cos w) / w, B = b / w, C = (w - sin w) / w^2
(Sola et al. 2018, appendix C), J_r(xi) = J_l(-xi), and the inverses by the
block formula [[V^-1, -V^-1 u], [0, 1]] (finite for |w| < 2 pi).

Args:
    xi: (vx, vy, w), shape (3,), finite.

Returns:
    ndarray: shape (3, 3), float64.
)doc";
};

namespace {

using chasles::SE2d;
using chasles::SO2d;
using Vector2 = Eigen::Vector2d;
using Matrix2 = Eigen::Matrix2d;
using Matrix3 = Eigen::Matrix3d;

/// The error of from_matrix and __setstate__: the defects, det and what to call.
template <typename G, int N>
[[noreturn]] void raise_not_in_group(const Eigen::Matrix<double, N, N>& M, double tol, const char* fn,
                                     bool tol_argument) {
  const Matrix2 R = M.template topLeftCorner<2, 2>();
  const double det = R.determinant();
  std::string msg = std::string(fn) + ": not a " + (N == 2 ? "rotation matrix" : "rigid motion") +
                    ": the rotation defect max(|R^T R - I|, |det R - 1|) is " + short_float(SO2d::rotation_defect(R)) +
                    " (det R = " + det_string(det) + ")";
  if constexpr (N == 3) {
    double row = 0.0;
    for (int j = 0; j < 3; ++j) row = std::max(row, std::abs(M(2, j) - (j == 2 ? 1.0 : 0.0)));
    msg += " and the bottom row differs from (0, 0, 1) by " + short_float(row);
  }
  msg += "; tol = " + short_float(tol) + ". ";
  if (det < 0) msg += "A negative determinant is a reflection, not a rotation. ";
  msg += std::string("Use ") + Lie<G>::cls + ".from_matrix_projected(matrix) for the nearest rotation" +
         (tol_argument ? ", or pass a larger tol." : ".");
  raise_value_error(msg);
}

/// The state's (c, s), checked as from_matrix checks a rotation.
SO2d rotation_of_state(double c, double s, const char* what) {
  Matrix2 R;
  R << c, -s, s, c;
  require_finite(R, what);
  if (!SO2d::from_matrix(R, kRotationTolerance)) raise_not_in_group<SO2d, 2>(R, kRotationTolerance, what, false);
  return SO2d::from_complex_unchecked(c, s);
}

const char* const kSO2Doc =
    R"doc(A rotation of the plane: an element of SO(2), stored as (cos theta, sin theta) (float64).

Its matrix is R = [[c, -s], [s, c]]; ``R_ab`` maps frame b to frame a,
``R_ac = R_ab @ R_bc``. The tangent space is R: the angle theta (a float in
Python; a 1-vector for the generic C++ code). The array functions so2_exp,
so2_log, ... take angles of shape (...) and matrices of shape (..., 2, 2).

Example:
    >>> R = SO2.exp(np.pi / 2)
    >>> np.round(R @ [1.0, 0.0], 12) + 0.0
    array([0., 1.])
    >>> (R @ R.inverse()).log()
    0.0
)doc";

const char* const kSE2Doc =
    R"doc(A rigid motion of the plane: an element of SE(2), stored as a rotation R (an SO2) and a translation t.

Its matrix is g = [[R, t], [0, 1]] (3x3); ``g_ab`` maps frame b to frame a,
``q_a = R q_b + t`` (``g @ q``), ``g_ac = g_ab @ g_bc``. The tangent space is
the planar twists xi = (vx, vy, w), linear part first (as SE3, manif and
jaxlie).

Example:
    >>> g = SE2(SO2.exp(np.pi / 2), [1.0, 2.0])
    >>> np.round(g @ [1.0, 0.0], 12) + 0.0
    array([1., 3.])
    >>> SE2.exp(g.log()).is_approx(g)
    True
)doc";

}  // namespace

void bind_so2(Class<SO2d>& cls) {
  cls.attr("__doc__") = kSO2Doc;
  hold_inline(cls);
  def_lie_group<2>(
      cls, [](const SO2d& R) { return "SO2(theta=" + float_repr(R.angle()) + ")"; },
      [](const SO2d& R) { return R.complex(); },
      [](const double* v) { return rotation_of_state(v[0], v[1], "SO2.__setstate__"); }, raise_not_in_group<SO2d, 2>);
  cls.attr("__array_ufunc__") = py::none();
  cls.def(py::init<>(), "The identity rotation.");
  def_refusal(cls, [](const py::args& args, const py::kwargs& kwargs) {
    return "SO2(" + describe_arguments(args, kwargs) +
           "): SO2() takes no arguments, it is the identity. An angle is SO2.exp(theta); a 2x2 matrix "
           "SO2.from_matrix(matrix) (checked), SO2.from_matrix_projected(matrix) or SO2.from_matrix_unchecked(matrix).";
  });
  cls.def_static("identity", &SO2d::identity, "The identity rotation.");
  cls.def_static(
      "rotation_defect",
      [](ArrayLike M) { return SO2d::rotation_defect(to_eigen<2, 2>(M.obj, "SO2.rotation_defect(matrix)")); },
      py::arg("matrix"), R"doc(How far a 2x2 matrix is from a rotation: max(|M^T M - I|_max, |det M - 1|).

Args:
    matrix: shape (2, 2).

Returns:
    float: the defect (inf when an entry is not finite).
)doc");
}

void bind_se2(Class<SE2d>& cls) {
  cls.attr("__doc__") = kSE2Doc;
  hold_inline(cls);
  def_lie_group<4>(
      cls,
      [](const SE2d& g) {
        return "SE2(rotation=SO2(theta=" + float_repr(g.rotation().angle()) +
               "), translation=" + array_repr(vec_out<2>(g.translation())) + ")";
      },
      [](const SE2d& g) {
        Eigen::Vector4d v;
        v << g.rotation().complex(), g.translation();
        return v;
      },
      [](const double* v) {
        const Vector2 t(v[2], v[3]);
        require_finite(t, "SE2.__setstate__");
        return SE2d(rotation_of_state(v[0], v[1], "SE2.__setstate__"), t);
      },
      raise_not_in_group<SE2d, 3>);
  cls.attr("__array_ufunc__") = py::none();
  cls.def(py::init([](Obj<SO2d> rotation, ArrayLike translation) {
            return SE2d(*rotation, to_finite_eigen<2>(translation.obj, "SE2(translation)"));
          }),
          py::arg_v("rotation", SO2d(), "SO2()"), py::arg_v("translation", py::make_tuple(0.0, 0.0), "(0.0, 0.0)"),
          R"doc(The rigid motion g = [[R, t], [0, 1]] of a rotation and a translation.

Args:
    rotation: SO2, R (default: the identity).
    translation: shape (2,), t, finite (default: 0).
)doc");
  def_refusal(cls, [](const py::args& args, const py::kwargs& kwargs) {
    return "SE2(" + describe_arguments(args, kwargs) +
           "): SE2(rotation, translation) takes an SO2 and a translation of shape (2,). A twist (vx, vy, w) is "
           "SE2.exp(xi); a 3x3 matrix SE2.from_matrix(matrix) (checked), SE2.from_matrix_projected(matrix) or "
           "SE2.from_matrix_unchecked(matrix).";
  });
  cls.def_static("identity", &SE2d::identity, "The identity motion.");
  cls.def_property_readonly(
      "rotation", [](Obj<SE2d> g) { return g->rotation(); }, "SO2: the rotation R of g = [[R, t], [0, 1]].");
  cls.def_property_readonly(
      "translation", [](Obj<SE2d> g) { return vec_out<2>(g->translation()); },
      "ndarray: the translation t of g = [[R, t], [0, 1]], shape (2,) (a new array).");
  cls.def_static(
      "transform_defect",
      [](ArrayLike M) { return SE2d::transform_defect(to_eigen<3, 3>(M.obj, "SE2.transform_defect(matrix)")); },
      py::arg("matrix"), R"doc(How far a 3x3 matrix is from a rigid motion of the plane.

The rotation defect of its top-left block or the deviation of its bottom
row from (0, 0, 1), whichever is larger.

Args:
    matrix: shape (3, 3).

Returns:
    float: the defect.
)doc");
}

}  // namespace chasles_py
