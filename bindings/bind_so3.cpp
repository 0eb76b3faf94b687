// chasles._core: class SO3 over chasles::SO3d (include/chasles/so3.hpp).
#include <chasles/so3.hpp>

#include <string>

#include "bindings.hpp"
#include "conventions.hpp"
#include "convert.hpp"
#include "signatures.hpp"

namespace chasles_py {

namespace {

using chasles::SO3d;
using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;

constexpr double kRotationTolerance = chasles::Thresholds<double>::rotation_tolerance;

const char* const kClassDoc = R"doc(A rotation of R^3: an element of SO(3), stored as its 3x3 matrix (float64).

``R_ab`` maps coordinates in frame b to frame a: ``p_a = R_ab @ p_b``; its
columns are b's axes written in a. Composition follows the frames:
``R_ac = R_ab @ R_bc``. The tangent space is R^3 (angular velocity, rotation
vector w), with ``hat(w) @ p = w x p``.

Build one with ``SO3()`` / ``SO3.identity()``, ``SO3.exp(w)``,
``SO3.from_quat(q)`` or from a matrix in one of three explicit forms:
``from_matrix`` (checked: refuses a matrix that is not a rotation and says by
how much), ``from_matrix_projected`` (the nearest rotation) and
``from_matrix_unchecked`` (no check, for data known to be valid).

Example:
    >>> R = SO3.exp([0.0, 0.0, np.pi / 2])
    >>> np.round(R @ [1.0, 0.0, 0.0], 12) + 0.0
    array([0., 1., 0.])
    >>> np.allclose(R.inverse() @ R @ [1.0, 2.0, 3.0], [1.0, 2.0, 3.0])
    True
)doc";

std::string class_doc() { return std::string(kClassDoc) + kConventions; }

/// The error of SO3.from_matrix (and of SO3.__setstate__, which has no tol
/// to pass): what is wrong, by how much, and what to do.
[[noreturn]] void raise_not_rotation(const Matrix3& M, double tol, const char* fn, bool tol_argument = true) {
  const double defect = SO3d::rotation_defect(M);
  const double det = M.determinant();
  std::string msg = std::string(fn) + ": not a rotation matrix: its rotation defect max(|M^T M - I|, |det M - 1|) is " +
                    short_float(defect) + " (det M = " + det_string(det) + "), above tol = " + short_float(tol) +
                    ". ";
  if (det < 0) msg += "A negative determinant is a reflection, not a rotation. ";
  msg += std::string("Use SO3.from_matrix_projected(matrix) for the nearest rotation") +
         (tol_argument ? ", or pass a larger tol." : ".");
  raise_value_error(msg);
}

}  // namespace

void bind_so3(py::module_& m) {
  const std::string doc = class_doc();
  py::class_<SO3d, InlineHolder<SO3d>> cls(m, "SO3", doc.c_str());
  hold_inline(cls);
  cls.attr("__array_ufunc__") = py::none();  // numpy defers operators (2.0 * x, p @ R) to us

  cls.def(py::init<>(), R"doc(The identity rotation.

Example:
    >>> SO3().as_matrix()
    array([[1., 0., 0.],
           [0., 1., 0.],
           [0., 0., 1.]])
)doc");

  // SO3(matrix) and the like: say which constructor was meant.
  def_refusal(cls, [](const py::args& args, const py::kwargs& kwargs) {
    std::string got;
    for (const auto& a : args) got += (got.empty() ? "" : ", ") + describe_argument(a);
    for (const auto& kw : kwargs)
      got += (got.empty() ? "" : ", ") + py::str(kw.first).cast<std::string>() + "=" + describe_argument(kw.second);
    return "SO3(" + got +
           "): SO3() takes no arguments, it is the identity. A rotation matrix is "
           "SO3.from_matrix(matrix) (checked: it refuses a matrix that is not a rotation), "
           "SO3.from_matrix_projected(matrix) (the nearest rotation) or SO3.from_matrix_unchecked(matrix) "
           "(no check); a rotation vector is SO3.exp(w), a quaternion SO3.from_quat(quat).";
  });

  cls.def_static("identity", &SO3d::identity, R"doc(The identity rotation.

Returns:
    SO3: the identity.

Example:
    >>> SO3.identity().is_approx(SO3.exp([0.0, 0.0, 0.0]))
    True
)doc");

  // ---- exp and log --------------------------------------------------------

  cls.def_static(
      "exp", [](ArrayLike w) { return SO3d::exp(to_finite_eigen<3>(w.obj, "SO3.exp(w)")); }, py::arg("w"),
      R"doc(The rotation exp([w]) of a rotation vector, by Rodrigues' formula.

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
)doc");

  cls.def(
      "log", [](Obj<SO3d> R) { return vec_out<3>(R->log()); },
      R"doc(The rotation vector w with exp([w]) = R and |w| in [0, pi].

At exactly pi both axis signs are correct; one of them is returned, never
NaN. Accurate to a few ulps, and to O(d) for a matrix off SO(3) by d.

Returns:
    ndarray: w, shape (3,), float64.

Example:
    >>> SO3.exp([0.1, -0.2, 0.3]).log()
    array([ 0.1, -0.2,  0.3])
)doc");

  cls.def(
      "angle", [](Obj<SO3d> R) { return R->angle(); },
      R"doc(The rotation angle theta = |log()| in [0, pi], radians.

From the halves of the quaternion, theta = 2 atan2(|q_v|, |q_w|), accurate
to a few ulps near 0 and near pi (acos of the trace loses half the digits
there). scipy: ``Rotation.magnitude()``.

Returns:
    float: the angle.

Example:
    >>> round(SO3.exp([0.0, 0.0, 0.5]).angle(), 12)
    0.5
)doc");

  cls.def_static(
      "hat", [](ArrayLike w) { return mat_out<3, 3>(SO3d::hat(to_eigen<3>(w.obj, "SO3.hat(w)"))); }, py::arg("w"),
      R"doc(The skew-symmetric matrix [w] of w, so that [w] @ p = w x p.

Args:
    w: vector, shape (3,).

Returns:
    ndarray: [w] = [[0, -w3, w2], [w3, 0, -w1], [-w2, w1, 0]], shape (3, 3).

Example:
    >>> SO3.hat([1.0, 2.0, 3.0])
    array([[ 0., -3.,  2.],
           [ 3.,  0., -1.],
           [-2.,  1.,  0.]])
)doc");

  cls.def_static(
      "vee", [](ArrayLike W) { return vec_out<3>(SO3d::vee(to_eigen<3, 3>(W.obj, "SO3.vee(matrix)"))); },
      py::arg("matrix"),
      R"doc(The vector w of a skew-symmetric matrix [w]: the inverse of hat.

Reads the antisymmetric part (W - W^T)/2, so a matrix that is not exactly
skew gives the w of its nearest skew matrix.

Args:
    matrix: shape (3, 3).

Returns:
    ndarray: w, shape (3,).

Example:
    >>> SO3.vee(SO3.hat([1.0, 2.0, 3.0]))
    array([1., 2., 3.])
)doc");

  // ---- group operations ---------------------------------------------------

  cls.def(
      "inverse", [](Obj<SO3d> x) { return x->inverse(); },
      R"doc(The inverse rotation R^-1 = R^T.

Returns:
    SO3: R^T.

Example:
    >>> R = SO3.exp([0.3, 0.2, 0.1])
    >>> (R @ R.inverse()).is_approx(SO3.identity())
    True
)doc");

  cls.def(
      "__matmul__", [](Obj<SO3d> a, Obj<SO3d> b) { return *a * *b; }, py::arg("other"), py::is_operator(),
      R"doc(Composition: R_ab @ R_bc = R_ac.

Args:
    other: SO3.

Returns:
    SO3: the composed rotation.
)doc");

  // The action on points is the array function so3_act with this matrix:
  // one rule for dtypes, broadcasting and the GIL (one point of float64
  // skips numpy's dispatch: the same kernel, the same bits).
  const auto act_points = [](const SO3d& R, ArrayLike points, const char* what) {
    if (!npy().PyArray_Check_(points.obj.ptr()) && is_bound_object(points.obj))
      raise_type_error(std::string(what) + ": expected points of shape (..., 3), got " + type_name(points.obj) +
                       " (an SO3 composes only with an SO3)");
    if (Vector3 p; single_element(points.obj, p.data(), 3)) return py::object(vec_out<3>(R.act(p)));
    const py::array M = mat_out<3, 3>(R.matrix());
    const py::object p = ufunc_operand(points.obj, what);
    return call_array_function<2>("so3_act", what, {M.ptr(), p.ptr()});
  };

  cls.def(
      "__matmul__", [act_points](Obj<SO3d> R, ArrayLike p) { return act_points(*R, p, "SO3 @ points"); },
      py::arg("points"),
      R"doc(Action on points or vectors: p_a = R_ab @ p_b.

The array function so3_act with this rotation: numpy's rules for
dtypes and broadcasting.

Args:
    points: array_like of shape (..., 3).

Returns:
    ndarray: the rotated points, shape (..., 3).
)doc");

  cls.def(
      "act", [act_points](Obj<SO3d> R, ArrayLike p) { return act_points(*R, p, "SO3.act(points)"); },
      py::arg("points"),
      R"doc(Action on points or vectors: p_a = R_ab p_b (the same as ``R @ points``).

The array function so3_act with this rotation: numpy's rules for
dtypes and broadcasting.

Args:
    points: array_like of shape (..., 3).

Returns:
    ndarray: the rotated points, shape (..., 3).

Example:
    >>> R = SO3.exp([0.0, 0.0, np.pi])
    >>> np.round(R.act([[1.0, 0.0, 0.0], [0.0, 0.0, 1.0]]), 12) + 0.0
    array([[-1.,  0.,  0.],
           [ 0.,  0.,  1.]])
)doc");

  cls.def(
      "adjoint", [](Obj<SO3d> R) { return mat_out<3, 3>(R->adjoint()); },
      R"doc(The adjoint Ad_R = R (3x3), so that R exp([w]) R^T = exp([R w]).

Returns:
    ndarray: shape (3, 3).
)doc");

  // ---- conversions ------------------------------------------------------

  cls.def(
      "as_matrix", [](Obj<SO3d> R) { return mat_out<3, 3>(R->matrix()); },
      R"doc(The rotation matrix.

Returns:
    ndarray: R, shape (3, 3), float64 (a new array).
)doc");

  cls.def_static(
      "from_matrix",
      [](ArrayLike matrix, RealLike tol) {
        const Matrix3 M = to_finite_eigen<3, 3>(matrix.obj, "SO3.from_matrix(matrix)");
        const double t = to_tolerance(tol.obj, "SO3.from_matrix(tol)");
        const auto R = SO3d::from_matrix(M, t);
        if (!R) raise_not_rotation(M, t, "SO3.from_matrix");
        return *R;
      },
      py::arg("matrix"), py::arg_v("tol", kRotationTolerance),
      R"doc(Checked construction from a rotation matrix.

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
)doc");

  cls.def_static(
      "from_matrix_projected",
      [](ArrayLike matrix) {
        return SO3d::from_matrix_projected(to_finite_eigen<3, 3>(matrix.obj, "SO3.from_matrix_projected(matrix)"));
      },
      py::arg("matrix"),
      R"doc(The rotation nearest to a matrix in the Frobenius norm.

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
)doc");

  cls.def_static(
      "from_matrix_unchecked",
      [](ArrayLike matrix) {
        return SO3d::from_matrix_unchecked(to_finite_eigen<3, 3>(matrix.obj, "SO3.from_matrix_unchecked(matrix)"));
      },
      py::arg("matrix"),
      R"doc(Construction without a check, for data known to be a rotation.

Only the shape and finiteness are checked. Operations on an SO3 built from a
matrix that is not a rotation give meaningless results.

Args:
    matrix: shape (3, 3), finite.

Returns:
    SO3: the matrix as it is.
)doc");

  cls.def_static(
      "rotation_defect",
      [](ArrayLike matrix) { return SO3d::rotation_defect(to_eigen<3, 3>(matrix.obj, "SO3.rotation_defect(matrix)")); },
      py::arg("matrix"),
      R"doc(How far a matrix is from a rotation: max(|M^T M - I|_max, |det M - 1|).

0 for a rotation, about 2d for a rotation whose entries are off by d, 2 for
a reflection, inf for a matrix that is not finite.

Args:
    matrix: shape (3, 3).

Returns:
    float: the defect.

Example:
    >>> SO3.rotation_defect(np.diag([1.0, 1.0, -1.0]))
    2.0
)doc");

  cls.def_static(
      "from_quat",
      [](ArrayLike quat, bool scalar_first) {
        const Eigen::Vector4d q = to_finite_eigen<4>(quat.obj, "SO3.from_quat(quat)");
        const double scale = q.cwiseAbs().maxCoeff();
        if (!(scale > 0.0)) raise_value_error("SO3.from_quat(quat): the zero quaternion is not a rotation");
        const Eigen::Vector4d u = q / scale;  // the C++ kernel normalizes; this keeps |q|^2 in range
        const Eigen::Quaterniond e = scalar_first ? Eigen::Quaterniond(u[0], u[1], u[2], u[3])
                                                  : Eigen::Quaterniond(u[3], u[0], u[1], u[2]);
        return SO3d::from_quaternion(e);
      },
      py::arg("quat"), py::kw_only(), py::arg("scalar_first") = false,
      R"doc(The rotation of a quaternion of any nonzero norm (it is normalized).

Args:
    quat: shape (4,): (x, y, z, w), scalar last, as in scipy; or
        (w, x, y, z) with scalar_first=True. Finite and nonzero.
    scalar_first: whether the scalar part comes first.

Returns:
    SO3: the rotation.

Raises:
    ValueError: the zero quaternion, a non-finite one, or a wrong shape.

Example:
    >>> s = np.sqrt(0.5)
    >>> np.round(SO3.from_quat([0.0, 0.0, s, s]).log(), 12) + 0.0
    array([0.        , 0.        , 1.57079633])
    >>> SO3.from_quat([1.0, 0.0, 0.0, 0.0], scalar_first=True).is_approx(SO3())
    True
)doc");

  cls.def(
      "as_quat",
      [](Obj<SO3d> R_, bool scalar_first) {
        const SO3d& R = *R_;
        const Eigen::Quaterniond q = R.quaternion();
        return vec_out<4>(scalar_first ? Eigen::Vector4d(q.w(), q.x(), q.y(), q.z())
                                       : Eigen::Vector4d(q.x(), q.y(), q.z(), q.w()));
      },
      py::kw_only(), py::arg("scalar_first") = false,
      R"doc(The unit quaternion of the rotation (Shepperd's method).

q and -q are the same rotation; the sign returned makes the component of
largest magnitude positive.

Args:
    scalar_first: False (default) for (x, y, z, w), as in scipy; True for
        (w, x, y, z).

Returns:
    ndarray: shape (4,), unit norm.

Example:
    >>> SO3().as_quat()
    array([0., 0., 0., 1.])
    >>> SO3().as_quat(scalar_first=True)
    array([1., 0., 0., 0.])
)doc");

  cls.def(
      "normalized", [](Obj<SO3d> R) { return R->normalized(); }, R"doc(The nearest rotation to the stored matrix.

Removes the drift that accumulates over many compositions.

Returns:
    SO3: the projected rotation.
)doc");

  cls.def_static(
      "interpolate",
      [](Obj<SO3d> a, Obj<SO3d> b, RealLike t) {
        return chasles::interpolate(*a, *b, to_finite_real(t.obj, "SO3.interpolate(t)"));
      },
      py::arg("a"), py::arg("b"), py::arg("t"),
      R"doc(Geodesic interpolation a exp(t log(a^-1 b)).

t = 0 gives a, t = 1 gives b; in between, the rotation about one fixed axis
(slerp). Values outside [0, 1] extrapolate.

Args:
    a: SO3, the start.
    b: SO3, the end.
    t: the fraction, finite.

Returns:
    SO3: the interpolated rotation.

Example:
    >>> a, b = SO3(), SO3.exp([0.0, 0.0, 1.0])
    >>> np.round(SO3.interpolate(a, b, 0.25).log(), 12) + 0.0
    array([0.  , 0.  , 0.25])
)doc");

  cls.def(
      "is_approx",
      [](Obj<SO3d> a, Obj<SO3d> b, RealLike tol) {
        return a->is_approx(*b, to_tolerance(tol.obj, "SO3.is_approx(tol)"));
      },
      py::arg("other"), py::arg_v("tol", 1e-9),
      R"doc(Whether two rotations are equal within tol: max |R_a - R_b| <= tol.

``==`` is the exact comparison (every stored number equal).

Args:
    other: SO3.
    tol: the largest accepted difference of matrix entries (>= 0).

Returns:
    bool.
)doc");

  // ---- Python protocols ---------------------------------------------------

  def_equality(cls, [](const SO3d& a, const SO3d& b) { return a.matrix() == b.matrix(); });
  def_repr(cls, [](const SO3d& R) { return "SO3(matrix=" + array_repr(mat_out<3, 3>(R.matrix())) + ")"; });
  cls.def(
      "__array__",
      [](Obj<SO3d> R_, DTypeLike dtype, CopyFlag copy) {
        const SO3d& R = *R_;
        return array_protocol(mat_out<3, 3>(R.matrix()), dtype, copy, "SO3");
      },
      py::arg_v("dtype", py::none(), "None"), py::arg_v("copy", py::none(), "None"),
      "The rotation matrix, shape (3, 3), for np.asarray (numpy's dtype and copy keywords).");
  def_array_dtype(cls);  // float64, for numpy's and scipy's dtype discovery (convert.hpp)
  cls.def("__copy__", [](Obj<SO3d> R) { return *R; });
  cls.def("__deepcopy__", [](Obj<SO3d> R, const py::object&) { return *R; }, py::arg("memo"));
  // The state: the matrix row by row, checked as SO3.from_matrix checks one
  // (a pickle is data from outside: one that is not a rotation is refused).
  cls.def(py::pickle([](Obj<SO3d> R) { return float_tuple(R->matrix()); },
                     [](const py::object& state) {
                       const py::tuple t = state_tuple(state, 9, "SO3");
                       Eigen::Matrix<double, 3, 3, Eigen::RowMajor> M;
                       read_state(t, 0, 9, M.data(), "SO3");
                       require_finite(M, "SO3.__setstate__");
                       if (!SO3d::from_matrix(M, kRotationTolerance))
                         raise_not_rotation(M, kRotationTolerance, "SO3.__setstate__", false);
                       return SO3d::from_matrix_unchecked(M);
                     }));
  add_reduce(cls);
}

}  // namespace chasles_py
