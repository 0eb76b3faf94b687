// chasles._core: class SO3 over chasles::SO3d (include/chasles/so3.hpp).
#include <chasles/random.hpp>
#include <chasles/so3.hpp>

#include <string>

#include "bindings.hpp"
#include "conventions.hpp"
#include "convert.hpp"
#include "lie_group.hpp"
#include "signatures.hpp"

namespace chasles_py {

namespace {

using chasles::SO3d;
using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;

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

/// The error of SO3.from_matrix (and of SO3.__setstate__, which has no tol
/// to pass): what is wrong, by how much, and what to do.
[[noreturn]] void raise_not_rotation(const Matrix3& M, double tol, const char* fn, bool tol_argument = true) {
  const double defect = SO3d::rotation_defect(M);
  const double det = M.determinant();
  std::string msg = std::string(fn) + ": not a rotation matrix: its rotation defect max(|M^T M - I|, |det M - 1|) is " +
                    short_float(defect) + " (det M = " + det_string(det) + "), above tol = " + short_float(tol) + ". ";
  if (det < 0) msg += "A negative determinant is a reflection, not a rotation. ";
  msg += std::string("Use SO3.from_matrix_projected(matrix) for the nearest rotation") +
         (tol_argument ? ", or pass a larger tol." : ".");
  raise_value_error(msg);
}

/// An Euler sequence argument, a str checked in the function body (so that
/// the error names the call); shown as str in signatures and stubs.
struct SequenceName {
  static constexpr auto text = py::detail::const_name("str");
};
using SequenceLike = AnyObject<SequenceName>;

/// A bool argument converted in the function body as pybind11 converts one
/// (None is False, an object's __bool__): from_rpy takes its arguments as
/// objects, so that its refusal (def_static_refusal) sees only the calls of
/// a wrong shape.
struct FlagName {
  static constexpr auto text = py::detail::const_name("bool");
};
using FlagLike = AnyObject<FlagName>;
bool to_flag(py::handle h, const char* what) {
  py::detail::make_caster<bool> flag;
  if (!flag.load(h, true)) raise_type_error(std::string(what) + ": expected a bool, got " + type_name(h));
  return static_cast<bool>(flag);
}

/// scipy's warning at the gimbal lock, word for word (a filter on scipy's
/// catches chasles' too); SO3._GIMBAL_LOCK_WARNING, for so3_as_euler and
/// so3_as_rpy (python/chasles/_arrays.py).
constexpr const char* kGimbalLockWarning =
    "Gimbal lock detected. Setting third angle to zero since it is not possible to uniquely determine all angles.";

/// The angles of as_euler / as_rpy, in degrees if asked; with the gimbal
/// lock flag if asked, and the warning at the lock if not.
py::object euler_result(const chasles::EulerAngles<double>& e, bool degrees, bool return_gimbal_lock) {
  py::object angles = vec_out<3>(degrees ? Vector3(e.angles * kRadToDeg) : e.angles);
  if (!return_gimbal_lock) {
    if (e.gimbal_lock && PyErr_WarnEx(PyExc_UserWarning, kGimbalLockWarning, 1) != 0) throw py::error_already_set();
    return angles;
  }
  return py::make_tuple(angles, py::bool_(e.gimbal_lock));
}

}  // namespace

void bind_so3(Class<SO3d>& cls) {
  cls.attr("__doc__") = std::string(kClassDoc) + kConventions;
  cls.attr("_GIMBAL_LOCK_WARNING") = kGimbalLockWarning;
  hold_inline(cls);
  // What SO3 and SE3 share (lie_group.hpp), first: the composition comes
  // before the action on points among the overloads of @. The state: the matrix row by row, checked as SO3.from_matrix
  // checks one.
  def_lie_group<9>(
      cls, [](const SO3d& R) { return "SO3(matrix=" + array_repr(mat_out<3, 3>(R.matrix())) + ")"; },
      [](const SO3d& R) { return row_major(R.matrix()); },
      [](const double* v) {
        const Matrix3 M = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(v);
        require_finite(M, "SO3.__setstate__");
        if (!SO3d::from_matrix(M, kRotationTolerance))
          raise_not_rotation(M, kRotationTolerance, "SO3.__setstate__", false);
        return SO3d::from_matrix_unchecked(M);
      },
      raise_not_rotation);
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
    const std::string got = describe_arguments(args, kwargs);
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

  // ---- conversions ------------------------------------------------------

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
        const Eigen::Quaterniond e =
            scalar_first ? Eigen::Quaterniond(u[0], u[1], u[2], u[3]) : Eigen::Quaterniond(u[3], u[0], u[1], u[2]);
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

  // ---- Euler angles (bind_euler.cpp) --------------------------------------

  cls.def_static(
      "from_euler",
      [](SequenceLike seq, ArrayLike angles, bool degrees) {
        const chasles::EulerSequence s = euler_sequence(seq.obj, "SO3.from_euler(seq)");
        Eigen::Vector3d t = to_finite_eigen<3>(angles.obj, "SO3.from_euler(angles)");
        if (degrees) t *= kDegToRad;
        return chasles::from_euler(s, t);
      },
      py::arg("seq"), py::arg("angles"), py::arg("degrees") = false,
      R"doc(The rotation of Euler angles, as scipy's ``Rotation.from_euler``.

``seq`` is one of the 12 axis sequences, lowercase for extrinsic (fixed
axes) or uppercase for intrinsic (moving axes). Extrinsic ``"xyz"`` with
angles (a, b, c) is R = Rz(c) Ry(b) Rx(a); intrinsic ``"XYZ"`` is
R = Rx(a) Ry(b) Rz(c). Tait-Bryan: xyz, xzy, yxz, yzx, zxy, zyx; proper
Euler: xyx, xzx, yxy, yzy, zxz, zyz (and their uppercase forms).

Args:
    seq: the sequence, e.g. ``"xyz"``, ``"ZYX"``, ``"zxz"``.
    angles: shape (3,), finite, in the order of ``seq``'s letters.
    degrees: the angles are in degrees (default radians).

Returns:
    SO3: the rotation.

Raises:
    TypeError: seq is not a str.
    ValueError: seq is not one of the 24 sequences; angles of a wrong shape
        or not finite.

Example:
    >>> R = SO3.from_euler("xyz", [90.0, 0.0, 0.0], degrees=True)
    >>> np.round(R.as_matrix(), 12) + 0.0
    array([[ 1.,  0.,  0.],
           [ 0.,  0., -1.],
           [ 0.,  1.,  0.]])
)doc");

  cls.def(
      "as_euler",
      [](Obj<SO3d> R, SequenceLike seq, bool degrees, bool return_gimbal_lock) {
        return euler_result(chasles::as_euler(euler_sequence(seq.obj, "SO3.as_euler(seq)"), *R), degrees,
                            return_gimbal_lock);
      },
      py::arg("seq"), py::arg("degrees") = false, py::kw_only(), py::arg("return_gimbal_lock") = false,
      R"doc(Euler angles of the rotation, as scipy's ``Rotation.as_euler``.

scipy's ranges: the middle angle in [-pi/2, pi/2] for Tait-Bryan sequences
(three distinct axes), [0, pi] for proper Euler sequences (first axis =
last), the others in [-pi, pi]. At the gimbal lock (middle angle +-pi/2, or
0 or pi, to working precision) only the sum or difference of the outer
angles is defined, and the third angle is zero, with scipy's UserWarning
(not with return_gimbal_lock=True, which returns the flag). Robust there:
``SO3.from_euler(seq, R.as_euler(seq))`` reproduces R to a few ulps for
every rotation (atan2 of well-conditioned pairs of entries; scipy declares
the lock within 1e-7 of it and loses up to 1e-7 there).

Args:
    seq: the sequence, e.g. ``"xyz"``, ``"ZYX"``, ``"zxz"`` (see from_euler).
    degrees: return degrees (default radians).
    return_gimbal_lock: also return whether the rotation is at the gimbal
        lock (the third angle was set to zero).

Returns:
    ndarray: shape (3,), the angles in the order of ``seq``'s letters; with
    return_gimbal_lock=True the tuple (angles, gimbal_lock: bool).

Example:
    >>> R = SO3.from_euler("ZYX", [0.3, -0.2, 0.1])
    >>> np.round(R.as_euler("ZYX"), 12)
    array([ 0.3, -0.2,  0.1])
)doc");

  cls.def_static(
      "from_rpy",
      [](ArrayLike rpy, FlagLike degrees) {
        Eigen::Vector3d t = to_finite_eigen<3>(rpy.obj, "SO3.from_rpy(rpy)");
        if (to_flag(degrees.obj, "SO3.from_rpy(degrees)")) t *= kDegToRad;
        return chasles::from_euler<chasles::EulerSequence::xyz>(t);
      },
      py::arg("rpy"), py::arg("degrees") = false,
      R"doc(The rotation of roll, pitch and yaw, URDF's ``rpy`` and ROS tf's setRPY.

About the fixed axes x, y and z in that order: R = Rz(yaw) Ry(pitch)
Rx(roll), i.e. ``SO3.from_euler("xyz", rpy)`` (scipy's extrinsic "xyz").

Args:
    rpy: shape (3,), (roll, pitch, yaw), finite.
    degrees: the angles are in degrees (default radians).

Returns:
    SO3: the rotation.

Example:
    >>> SO3.from_rpy([0.1, 0.2, 0.3]) == SO3.from_euler("xyz", [0.1, 0.2, 0.3])
    True
)doc");

  // SO3.from_rpy(0.1, 0.2, 0.3) and other calls the signature refuses: the expected shape, not pybind11's list.
  def_static_refusal(cls, "from_rpy", [](const py::args& args, const py::kwargs& kwargs) {
    const std::string got = describe_arguments(args, kwargs);
    return "SO3.from_rpy(rpy, degrees=False): expected rpy, one array_like of shape (3,) (roll, pitch, yaw), and "
           "degrees, a bool; got (" +
           got + ")" + (args.size() == 3 ? ". Three angles are one argument: SO3.from_rpy([roll, pitch, yaw])" : "");
  });

  cls.def(
      "as_rpy",
      [](Obj<SO3d> R, bool degrees, bool return_gimbal_lock) {
        return euler_result(chasles::as_rpy(*R), degrees, return_gimbal_lock);
      },
      py::arg("degrees") = false, py::kw_only(), py::arg("return_gimbal_lock") = false,
      R"doc(Roll, pitch and yaw of the rotation (URDF, ROS tf's getRPY).

``R.as_euler("xyz")``: R = Rz(yaw) Ry(pitch) Rx(roll), pitch in
[-pi/2, pi/2], roll and yaw in [-pi, pi]; at the gimbal lock (pitch +-pi/2)
yaw is zero, with scipy's UserWarning (not with return_gimbal_lock=True).

Args:
    degrees: return degrees (default radians).
    return_gimbal_lock: also return whether pitch is at +-pi/2 (yaw was set
        to zero).

Returns:
    ndarray: shape (3,), (roll, pitch, yaw); with return_gimbal_lock=True the
    tuple (rpy, gimbal_lock: bool).

Example:
    >>> np.round(SO3.from_rpy([0.1, 0.2, 0.3]).as_rpy(), 12)
    array([0.1, 0.2, 0.3])
)doc");

  // ---- scipy and random ---------------------------------------------------

  cls.def_static(
      "from_scipy",
      [](py::object r) {
        const char* what = "SO3.from_scipy(r)";
        check_single_scipy(
            r, "Rotation", what,
            "A stack is an array for the array functions: r.as_matrix() (shape (..., 3, 3)) for so3_log, so3_compose, "
            "so3_act, ..., or chasles.so3_from_quat(r.as_quat()); r[i] is one Rotation.");
        // scipy keeps a unit quaternion (x, y, z, w): its rotation, by the same
        // conversion as SO3.from_quat.
        const Eigen::Vector4d q = to_finite_eigen<4>(r.attr("as_quat")(), what);
        return SO3d::from_quaternion(Eigen::Quaterniond(q[3], q[0], q[1], q[2]));
      },
      py::arg("r"),
      R"doc(The rotation of a single scipy.spatial.transform.Rotation.

scipy is imported by this call (it is not needed by ``import chasles``).
The rotation is read from scipy's unit quaternion, as ``SO3.from_quat``.
For a stack of rotations use the array functions on ``r.as_matrix()``
(shape (N, 3, 3)), or ``chasles.so3_from_quat(r.as_quat())``.

Args:
    r: a single scipy.spatial.transform.Rotation.

Returns:
    SO3: the same rotation.

Raises:
    TypeError: r is not a Rotation.
    ValueError: r is a stack of rotations.
    ImportError: scipy is not installed.

Example:
    >>> from scipy.spatial.transform import Rotation
    >>> R = SO3.from_scipy(Rotation.from_rotvec([0.0, 0.0, 0.5]))
    >>> np.round(R.log(), 12) + 0.0
    array([0. , 0. , 0.5])
)doc");

  cls.def(
      "to_scipy",
      [](Obj<SO3d> R) {
        const py::object Rotation = scipy_class("Rotation", "SO3.to_scipy()");
        const Eigen::Quaterniond q = R->quaternion();
        return Rotation.attr("from_quat")(vec_out<4>(Eigen::Vector4d(q.x(), q.y(), q.z(), q.w())));
      },
      R"doc(This rotation as a scipy.spatial.transform.Rotation.

scipy is imported by this call (it is not needed by ``import chasles``).
scipy's ``Rotation.from_matrix(R)`` works too (``np.asarray(R)`` is the
matrix); for many rotations, ``Rotation.from_matrix`` of an array of shape
(N, 3, 3).

Returns:
    scipy.spatial.transform.Rotation: a single rotation, from the unit
    quaternion of ``as_quat()``.

Raises:
    ImportError: scipy is not installed.

Example:
    >>> SO3.exp([0.0, 0.0, 0.5]).to_scipy().as_rotvec().round(12) + 0.0
    array([0. , 0. , 0.5])
)doc");

  cls.def_static(
      "random",
      [](py::object rng) {
        return chasles::so3_from_uniforms(uniforms(numpy_generator(rng, "so3_random"), "SO3.random"));
      },
      py::arg("rng") = py::none(),
      R"doc(A uniform random rotation (the Haar measure), as scipy's Rotation.random().

Shoemake's method over three uniforms drawn from ``rng``: one element of
``chasles.so3_random``.

Args:
    rng: None (a fresh ``numpy.random.default_rng()``), an int seed or a
        numpy Generator.

Returns:
    SO3: the rotation.

Example:
    >>> SO3.random(rng=7).is_approx(SO3.random(rng=7), 0.0)
    True
)doc");
}

}  // namespace chasles_py
