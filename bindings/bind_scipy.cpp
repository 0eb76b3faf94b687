// chasles._core: conversions between the objects SO3 / SE3 and scipy's
// scipy.spatial.transform.Rotation / RigidTransform (SO3.from_scipy,
// SO3.to_scipy, SE3.from_scipy, SE3.to_scipy).
//
// scipy is imported when one of these is called, never at `import chasles`
// (it is not a dependency of the package). One object converts to one
// element; a stack of rotations or transforms goes through the array
// functions (r.as_matrix() is an array of shape (N, 3, 3) for so3_*,
// tf.as_matrix() one of shape (N, 4, 4) for se3_*), and the other way
// round scipy's own from_matrix / from_quat take chasles' arrays.
#include <algorithm>
#include <cmath>
#include <string>

#include <chasles/constants.hpp>
#include <chasles/se3.hpp>
#include <chasles/so3.hpp>

#include "bindings.hpp"
#include "convert.hpp"

namespace chasles_py {

namespace {

using chasles::SE3d;
using chasles::SO3d;

constexpr double kRotationTolerance = chasles::Thresholds<double>::rotation_tolerance;

/// scipy.spatial.transform's class `name`, imported now; ImportError naming
/// `what` when scipy (or a scipy recent enough to have `name`) is missing.
py::object scipy_class(const char* name, const char* what) {
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

/// TypeError unless obj is an instance of cls; ValueError unless it is a
/// single element (not a stack), with the array route for a stack.
void check_single(py::handle obj, const py::object& cls, const char* what, const char* kind, const char* batch) {
  if (!py::isinstance(obj, cls)) {
    raise_type_error(std::string(what) + ": expected a scipy.spatial.transform." + kind + ", got " + type_name(obj));
  }
  if (!obj.attr("single").cast<bool>()) {
    const std::string shape = py::str(obj.attr("as_matrix")().attr("shape"));
    raise_value_error(std::string(what) + ": expected a single " + kind + ", got a stack (as_matrix() of shape " +
                      shape + "). " + batch);
  }
}

const char* const kSo3Batch =
    "A stack is an array for the array functions: r.as_matrix() (shape (..., 3, 3)) for so3_log, so3_compose, "
    "so3_act, ..., or chasles.so3_from_quat(r.as_quat()); r[i] is one Rotation.";
const char* const kSe3Batch =
    "A stack is an array for the array functions: tf.as_matrix() (shape (..., 4, 4)) for se3_log, se3_compose, "
    "se3_act, ...; tf[i] is one RigidTransform.";

}  // namespace

void bind_scipy(py::module_& m) {
  auto so3 = py::reinterpret_borrow<py::class_<SO3d, InlineHolder<SO3d>>>(m.attr("SO3"));
  auto se3 = py::reinterpret_borrow<py::class_<SE3d, InlineHolder<SE3d>>>(m.attr("SE3"));

  so3.def_static(
      "from_scipy",
      [](py::object r) {
        const char* what = "SO3.from_scipy(r)";
        check_single(r, scipy_class("Rotation", what), what, "Rotation", kSo3Batch);
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

  so3.def(
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

  se3.def_static(
      "from_scipy",
      [](py::object tf) {
        const char* what = "SE3.from_scipy(tf)";
        check_single(tf, scipy_class("RigidTransform", what), what, "RigidTransform", kSe3Batch);
        const Eigen::Matrix4d M = to_finite_eigen<4, 4>(tf.attr("as_matrix")(), what);
        const auto g = SE3d::from_matrix(M, kRotationTolerance);
        if (!g) {
          // Only a RigidTransform built with normalize=False can get here.
          raise_value_error(std::string(what) + ": the transform's matrix is not a rigid motion: rotation defect " +
                            "max(|R^T R - I|, |det R - 1|) = " +
                            std::to_string(SO3d::rotation_defect(M.topLeftCorner<3, 3>())) + " (tol " +
                            std::to_string(kRotationTolerance) +
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

  se3.def(
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
}

}  // namespace chasles_py
