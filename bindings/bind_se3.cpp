// chasles._core: class SE3 over chasles::SE3d (include/chasles/se3.hpp); what
// it shares with SO3 is in lie_group.hpp.
#include <chasles/random.hpp>
#include <chasles/se3.hpp>
#include <chasles/twist.hpp>
#include <chasles/wrench.hpp>

#include <cmath>
#include <string>

#include "bindings.hpp"
#include "conventions.hpp"
#include "convert.hpp"
#include "lie_group.hpp"
#include "signatures.hpp"

namespace chasles_py {

namespace {

using chasles::SE3d;
using chasles::SO3d;
using chasles::Twistd;
using chasles::Wrenchd;
using Vector3 = Eigen::Vector3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix3 = Eigen::Matrix3d;
using Matrix4 = Eigen::Matrix4d;

const char* const kClassDoc = R"doc(A rigid motion of R^3: an element of SE(3), stored as a rotation R (an SO3)
and a translation p (float64). Its 4x4 matrix is g = [[R, p], [0, 1]].

``g_ab`` maps coordinates in frame b to frame a: ``q_a = R_ab q_b + p_ab``
(``g @ q``), and composes along the frames: ``g_ac = g_ab @ g_bc``. The
tangent space is the space of twists xi = (v, w), linear part first (Murray,
Li and Sastry); exp([xi]) is the screw motion of Chasles' theorem. Twists
change frame by Ad_g = [[R, [p] R], [0, R]] (``g.act(twist)``); wrenches by
Ad_g^-T (``g.act(wrench)``), so power is invariant.

Example:
    >>> g = SE3(SO3.exp([0.0, 0.0, np.pi / 2]), [1.0, 2.0, 3.0])
    >>> np.round(g @ [1.0, 0.0, 0.0], 12) + 0.0
    array([1., 3., 3.])
    >>> SE3.exp(g.log()).is_approx(g)
    True
)doc";

/// Why SE3(...) refused its arguments, and what to call instead (the
/// constructor takes an SO3 and a translation; raw matrices have their own
/// checked constructors).
std::string explain_se3_refusal(const py::args& args, const py::kwargs& kwargs) {
  const char* usage = "SE3(rotation, translation) takes an SO3 and a translation of shape (3,)";
  for (const auto& kw : kwargs) {
    const std::string key = py::str(kw.first);
    if (key != "rotation" && key != "translation") return "SE3(): unexpected keyword argument '" + key + "'; " + usage;
    if ((key == "rotation" && args.size() >= 1) || (key == "translation" && args.size() >= 2))
      return "SE3(): " + key + " given by position and by keyword; " + usage;
  }
  if (args.size() > 2)
    return "SE3(): takes at most 2 arguments (rotation, translation), got " + std::to_string(args.size()) + "; " +
           usage;
  py::object rotation;
  if (args.size() >= 1) {
    rotation = args[0];
  } else if (kwargs.contains("rotation")) {
    rotation = kwargs["rotation"];
  } else {
    return std::string("SE3(): ") + usage;
  }
  std::string msg = "SE3(rotation): expected an SO3, got " + describe_argument(rotation);
  std::vector<Py_intptr_t> shape;
  const bool raw = raw_shape(rotation, shape);
  if (raw && shape == std::vector<Py_intptr_t>{4, 4}) {
    return msg +
           ". A homogeneous matrix [[R, p], [0, 0, 0, 1]] is SE3.from_matrix(matrix) (checked: it refuses a matrix "
           "that is not a rigid motion), SE3.from_matrix_projected(matrix) (the nearest rotation) or "
           "SE3.from_matrix_unchecked(matrix) (no check).";
  }
  if (raw && shape == std::vector<Py_intptr_t>{3, 3}) {
    return msg +
           ". Make the rotation of a matrix with SO3.from_matrix(matrix) (checked: it refuses a matrix that is not "
           "a rotation), SO3.from_matrix_projected(matrix) (the nearest rotation) or "
           "SO3.from_matrix_unchecked(matrix) (no check): SE3(SO3.from_matrix(R), p).";
  }
  if (raw && shape == std::vector<Py_intptr_t>{3} && args.size() == 1 && kwargs.empty())
    return msg + ". A translation alone is SE3(translation=p).";
  if (raw && shape == std::vector<Py_intptr_t>{6}) return msg + ". The motion of a twist xi = (v, w) is SE3.exp(xi).";
  return msg + ". SO3.exp(w), SO3.from_quat(quat) and SO3.from_matrix(matrix) make one; " + usage + ".";
}

/// The error of SE3.from_matrix (and of SE3.__setstate__, which has no tol
/// to pass).
[[noreturn]] void raise_not_rigid(const Matrix4& M, double tol, const char* fn, bool tol_argument) {
  const double rot = SO3d::rotation_defect(M.topLeftCorner<3, 3>());
  const double det = M.topLeftCorner<3, 3>().determinant();
  double row = 0.0;
  for (int j = 0; j < 4; ++j) row = std::max(row, std::abs(M(3, j) - (j == 3 ? 1.0 : 0.0)));
  std::string msg = std::string(fn) +
                    ": not a rigid motion: the top-left 3x3 block has rotation defect "
                    "max(|R^T R - I|, |det R - 1|) = " +
                    short_float(rot) + " (det R = " + det_string(det) +
                    ") and the bottom row differs from (0, 0, 0, 1) by " + short_float(row) +
                    "; tol = " + short_float(tol) + ". ";
  if (det < 0) msg += "A negative determinant is a reflection, not a rotation. ";
  if (row > tol) msg += "A rigid motion's bottom row is exactly (0, 0, 0, 1). ";
  msg += std::string("Use SE3.from_matrix_projected(matrix) for the nearest rotation (it ignores the bottom row)") +
         (tol_argument ? ", or pass a larger tol." : ".");
  raise_value_error(msg);
}

/// low or high of SE3.random: a number (for every component) or shape (3,), finite.
Vector3 box(py::handle h, const char* what) {
  std::vector<Py_intptr_t> shape;
  if (raw_shape(h, shape) && !shape.empty()) return to_finite_eigen<3>(h, what);
  return Vector3::Constant(to_finite_real(h, what));
}

}  // namespace

void bind_se3(Class<SE3d>& cls) {
  cls.attr("__doc__") = std::string(kClassDoc) + kConventions;
  hold_inline(cls);

  // ---- scipy and random ---------------------------------------------------

  cls.def_static(
      "from_scipy",
      [](py::object tf) {
        const char* what = "SE3.from_scipy(tf)";
        check_single_scipy(
            tf, "RigidTransform", what,
            "A stack is an array for the array functions: tf.as_matrix() (shape (..., 4, 4)) for se3_log, se3_compose, "
            "se3_act, ...; tf[i] is one RigidTransform.");
        const Eigen::Matrix4d M = to_finite_eigen<4, 4>(tf.attr("as_matrix")(), what);
        const auto g = SE3d::from_matrix(M, kRotationTolerance);
        if (!g) {
          // Only a RigidTransform built with normalize=False can get here.
          raise_value_error(
              std::string(what) + ": the transform's matrix is not a rigid motion: rotation defect " +
              "max(|R^T R - I|, |det R - 1|) = " + std::to_string(SO3d::rotation_defect(M.topLeftCorner<3, 3>())) +
              " (tol " + std::to_string(kRotationTolerance) +
              "); use SE3.from_matrix_projected(tf.as_matrix()) for the nearest rotation");
        }
        return *g;
      },
      py::arg("tf"),
      R"doc(The motion of a single scipy.spatial.transform.RigidTransform.

scipy (1.16 or later) is imported by this call (it is not needed by
``import chasles``). The motion is read from scipy's 4x4 matrix, checked as
by ``SE3.from_matrix``. For a stack of transforms use the array functions on
``tf.as_matrix()`` (shape (N, 4, 4)).

Args:
    tf: a single scipy.spatial.transform.RigidTransform.

Returns:
    SE3: the same motion.

Raises:
    TypeError: tf is not a RigidTransform.
    ValueError: tf is a stack of transforms, or its matrix is not a rigid
        motion (a transform built with normalize=False).
    ImportError: scipy (or RigidTransform, scipy < 1.16) is missing.

Example:
    >>> from scipy.spatial.transform import RigidTransform
    >>> SE3.from_scipy(RigidTransform.from_translation([1.0, 2.0, 3.0])).translation
    array([1., 2., 3.])
)doc");

  cls.def(
      "to_scipy",
      [](Obj<SE3d> g) {
        const py::object RigidTransform = scipy_class("RigidTransform", "SE3.to_scipy()");
        return RigidTransform.attr("from_matrix")(mat_out<4, 4>(g->matrix()));
      },
      R"doc(This motion as a scipy.spatial.transform.RigidTransform.

scipy (1.16 or later) is imported by this call (it is not needed by
``import chasles``). scipy's ``RigidTransform.from_matrix(g)`` works too
(``np.asarray(g)`` is the 4x4 matrix); for many motions,
``RigidTransform.from_matrix`` of an array of shape (N, 4, 4).

Returns:
    scipy.spatial.transform.RigidTransform: a single transform, from the
    homogeneous matrix of ``as_matrix()``.

Raises:
    ImportError: scipy (or RigidTransform, scipy < 1.16) is missing.

Example:
    >>> SE3(translation=[1.0, 2.0, 3.0]).to_scipy().translation
    array([1., 2., 3.])
)doc");

  cls.def_static(
      "random",
      [](py::object rng, py::object low, py::object high) {
        const Vector3 lo = box(low, "se3_random(low)"), hi = box(high, "se3_random(high)");
        if ((hi.array() < lo.array()).any())
          raise_value_error("se3_random: expected low <= high, got low=" + array_repr(vec_out<3>(lo)) +
                            ", high=" + array_repr(vec_out<3>(hi)));
        const py::object gen = numpy_generator(rng, "se3_random");
        const SO3d R = chasles::so3_from_uniforms(uniforms(gen, "SE3.random"));
        const Vector3 u = uniforms(gen, "SE3.random");
        return SE3d(R, lo + (hi - lo).cwiseProduct(u));  // numpy's lo + (hi - lo) * u
      },
      py::arg("rng") = py::none(), py::kw_only(), py::arg("low") = -1.0, py::arg("high") = 1.0,
      R"doc(A random rigid motion: a uniform rotation and a translation uniform in a box.

One element of ``chasles.se3_random``: the rotation as SO3.random, then the
translation uniform in [low, high] componentwise.

Args:
    rng: None (a fresh ``numpy.random.default_rng()``), an int seed or a
        numpy Generator.
    low: float or array_like of shape (3,): the box's lower corner.
    high: float or array_like of shape (3,): the box's upper corner.

Returns:
    SE3: the pose.

Example:
    >>> g = SE3.random(rng=1, low=0.0, high=0.5)
    >>> bool(np.all((0.0 <= g.translation) & (g.translation <= 0.5)))
    True
)doc");

  // The actions on twists and wrenches before the one on points (def_lie_group; a Twist is array-like too,
  // through __array__).
  cls.def(
      "act", [](Obj<SE3d> g, Obj<Twistd> xi) { return g->act(*xi); }, py::arg("twist"),
      R"doc(A twist from frame b to frame a: xi_a = Ad_g xi_b = (R v + p x R w, R w).

Args:
    twist: Twist, xi_b.

Returns:
    Twist: xi_a.
)doc");
  cls.def(
      "act", [](Obj<SE3d> g, Obj<Wrenchd> F) { return g->act(*F); }, py::arg("wrench"),
      R"doc(A wrench from frame b to frame a: F_a = Ad_g^-T F_b = (R f, p x R f + R tau).

Args:
    wrench: Wrench, F_b.

Returns:
    Wrench: F_a.
)doc");

  // What SO3 and SE3 share (lie_group.hpp), first: the composition comes
  // before the action on points among the overloads of @. The state: R row by row, then p; checked as SE3.from_matrix
  // checks the matrix.
  def_lie_group<12>(
      cls,
      [](const SE3d& g) {
        return "SE3(rotation=" + array_repr(mat_out<3, 3>(g.rotation().matrix())) +
               ", translation=" + array_repr(vec_out<3>(g.translation())) + ")";
      },
      [](const SE3d& g) {
        Eigen::Matrix<double, 12, 1> v;
        v << row_major(g.rotation().matrix()), g.translation();
        return v;
      },
      [](const double* v) {
        const Matrix3 R = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(v);
        const Vector3 p(v[9], v[10], v[11]);
        require_finite(R, "SE3.__setstate__");
        require_finite(p, "SE3.__setstate__");
        if (!SO3d::from_matrix(R, kRotationTolerance)) {
          Matrix4 M = Matrix4::Identity();
          M.topLeftCorner<3, 3>() = R;
          M.topRightCorner<3, 1>() = p;
          raise_not_rigid(M, kRotationTolerance, "SE3.__setstate__", false);
        }
        return SE3d(SO3d::from_matrix_unchecked(R), p);
      },
      raise_not_rigid);
  cls.attr("__array_ufunc__") = py::none();  // numpy defers operators to us

  cls.def(py::init([](Obj<SO3d> rotation, ArrayLike translation) {
            return SE3d(*rotation, to_finite_eigen<3>(translation.obj, "SE3(translation)"));
          }),
          py::arg_v("rotation", SO3d(), "SO3()"),
          py::arg_v("translation", py::make_tuple(0.0, 0.0, 0.0), "(0.0, 0.0, 0.0)"),
          R"doc(The rigid motion g = [[R, p], [0, 1]] of a rotation and a translation.

Args:
    rotation: SO3, R (default: the identity).
    translation: shape (3,), p, finite (default: 0).

Example:
    >>> SE3(translation=[1.0, 2.0, 3.0]).translation
    array([1., 2., 3.])
)doc");

  // SE3(matrix), SE3(np.eye(3), p) and the like: say which constructor was meant.
  def_refusal(cls, explain_se3_refusal);

  cls.def_static("identity", &SE3d::identity, R"doc(The identity motion.

Returns:
    SE3: the identity.
)doc");

  cls.def(
      "act_inv", [](Obj<SE3d> g, Obj<Twistd> xi) { return g->act_inv(*xi); }, py::arg("twist"),
      R"doc(A twist from frame a to frame b: xi_b = Ad_g^-1 xi_a = (R^T (v - p x w), R^T w).

Args:
    twist: Twist, xi_a.

Returns:
    Twist: xi_b.
)doc");
  cls.def(
      "act_inv", [](Obj<SE3d> g, Obj<Wrenchd> F) { return g->act_inv(*F); }, py::arg("wrench"),
      R"doc(A wrench from frame a to frame b: F_b = Ad_g^T F_a = (R^T f, R^T (tau - p x f)).

Args:
    wrench: Wrench, F_a.

Returns:
    Wrench: F_b.
)doc");

  cls.def(
      "act_inv", [](Obj<SE3d> g, ArrayLike points) { return act_points(g->inverse(), points, "SE3.act_inv(points)"); },
      py::arg("points"),
      R"doc(Inverse action on points: q_b = R^T (q_a - p), i.e. g^-1 @ q_a.

The array function se3_act with g^-1: numpy's rules for dtypes and
broadcasting.

Args:
    points: array_like of shape (..., 3).

Returns:
    ndarray: shape (..., 3).
)doc");

  // ---- access and conversions ---------------------------------------------

  // Stored parts are properties (read-only: the values are immutable).
  cls.def_property_readonly(
      "rotation", [](Obj<SE3d> g) { return g->rotation(); },
      R"doc(SO3: the rotation R of g = [[R, p], [0, 1]] (a stored part; a copy).)doc");

  cls.def_property_readonly(
      "translation", [](Obj<SE3d> g) { return vec_out<3>(g->translation()); },
      R"doc(ndarray: the translation p of g = [[R, p], [0, 1]], shape (3,) (a stored part; a new array).)doc");

  cls.def_static(
      "transform_defect",
      [](ArrayLike matrix) {
        return SE3d::transform_defect(to_eigen<4, 4>(matrix.obj, "SE3.transform_defect(matrix)"));
      },
      py::arg("matrix"),
      R"doc(How far a 4x4 matrix is from a rigid motion.

The rotation defect of its top-left block (SO3.rotation_defect) or the
largest deviation of its bottom row from (0, 0, 0, 1), whichever is larger.

Args:
    matrix: shape (4, 4).

Returns:
    float: the defect.
)doc");

  cls.def_static(
      "from_screw",
      [](ArrayLike point, ArrayLike direction, RealLike pitch, RealLike theta) {
        const Vector3 q = to_finite_eigen<3>(point.obj, "SE3.from_screw(point)");
        const Vector3 d = to_finite_eigen<3>(direction.obj, "SE3.from_screw(direction)");
        const double h = to_pitch(pitch.obj, "SE3.from_screw(pitch)");
        const double t = to_finite_real(theta.obj, "SE3.from_screw(theta)");
        return SE3d::from_screw(q, d, h, t);
      },
      py::arg("point"), py::arg("direction"), py::arg("pitch"), py::arg("theta"),
      R"doc(The screw motion about an axis: exp(theta * (-d x q + h d, d)).

Rotates by theta about the line through q along d (normalized here) while
translating by h * theta along it; pitch = inf is the pure translation
theta * d. A zero direction gives the identity (the screw of the zero
twist).

Args:
    point: q, a point of the axis, shape (3,).
    direction: d, the axis direction, shape (3,) (any nonzero length).
    pitch: h, translation per radian; ``math.inf`` for a translation.
    theta: the rotation angle in radians (the distance for pitch = inf).

Returns:
    SE3: the screw motion.

Example:
    >>> g = SE3.from_screw([0.0, 2.0, 0.0], [0.0, 0.0, 1.0], 0.0, np.pi / 2)
    >>> np.round(g.translation, 12) + 0.0
    array([2., 2., 0.])
    >>> np.round(g @ [0.0, 2.0, 5.0], 12) + 0.0
    array([0., 2., 5.])
)doc");
}

}  // namespace chasles_py
