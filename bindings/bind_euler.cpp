// chasles._core: Euler angles (include/chasles/euler.hpp).
//
// - SO3.from_euler(seq, angles, degrees=False), SO3.as_euler(seq, degrees=False),
//   SO3.from_rpy(rpy, degrees=False), SO3.as_rpy(degrees=False);
// - for the array functions chasles.so3_from_euler / so3_as_euler (and the
//   rpy ones), 96 private ufuncs `_so3_from_euler_<seq>[_deg]` and
//   `_so3_as_euler_<seq>[_deg]`, one per sequence and unit, which
//   python/chasles/_arrays.py picks: a ufunc takes arrays only, and the
//   sequence is the template argument of the C++ kernel. Degrees are their
//   own kernels (the conversion x * (pi / 180), as numpy's deg2rad, fused in
//   the loop) rather than a conversion in Python, so that numpy's casting,
//   out=, where= and dtype= apply to the whole function unchanged (a Python
//   np.deg2rad first would pick its own dtype, float16 for int8, and would
//   need its own masking for where=) and no temporary array is made.
#include <array>
#include <string>
#include <utility>

#include <chasles/euler.hpp>

#include "bindings.hpp"
#include "convert.hpp"
#include "ufunc.hpp"

namespace chasles_py {

namespace {

using chasles::EulerSequence;
using chasles::SO3d;
using ufunc::Core;
using ufunc::def_ufunc;

constexpr double kPi = 3.14159265358979323846;
constexpr double kDegToRad = kPi / 180.0;  // numpy's deg2rad: x * (pi / 180)
constexpr double kRadToDeg = 180.0 / kPi;  // numpy's rad2deg: x * (180 / pi)

/// The 24 sequences, in the order of chasles::EulerSequence.
constexpr const char* kSequences[24] = {"xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "xyx", "xzx",
                                        "yxy", "yzy", "zxz", "zyz", "XYZ", "XZY", "YXZ", "YZX",
                                        "ZXY", "ZYX", "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ"};

/// An Euler sequence argument, a str checked in the function body (so that
/// the error names the call); shown as str in signatures and stubs.
struct SequenceName {
  static constexpr auto text = py::detail::const_name("str");
};
using SequenceLike = AnyObject<SequenceName>;

/// The index of a sequence in kSequences, or TypeError / ValueError naming `what`.
int sequence_index(py::handle seq, const char* what) {
  if (!PyUnicode_Check(seq.ptr())) {
    throw py::type_error(std::string(what) + ": expected a str of three axes such as 'xyz' or 'ZYX', got " +
                         type_name(seq));
  }
  const std::string s = py::reinterpret_borrow<py::str>(seq).cast<std::string>();
  for (int i = 0; i < 24; ++i)
    if (s == kSequences[i]) return i;
  raise_value_error(std::string(what) +
                    ": expected three axes of 'xyz', all lowercase (extrinsic) or all uppercase (intrinsic), "
                    "no two consecutive equal, as 'xyz', 'ZYX' or 'zxz'; got " +
                    py::repr(seq).cast<std::string>());
}

template <int N>
Eigen::Matrix3d from_euler_n(const Eigen::Vector3d& t) {
  return chasles::from_euler<static_cast<EulerSequence>(N)>(t).matrix();
}
template <int N>
Eigen::Vector3d as_euler_n(const SO3d& R) {
  return chasles::as_euler<static_cast<EulerSequence>(N)>(R).angles;
}
template <int... N>
constexpr auto from_table(std::integer_sequence<int, N...>) {
  return std::array<Eigen::Matrix3d (*)(const Eigen::Vector3d&), 24>{&from_euler_n<N>...};
}
template <int... N>
constexpr auto as_table(std::integer_sequence<int, N...>) {
  return std::array<Eigen::Vector3d (*)(const SO3d&), 24>{&as_euler_n<N>...};
}
constexpr auto kFrom = from_table(std::make_integer_sequence<int, 24>());
constexpr auto kAs = as_table(std::make_integer_sequence<int, 24>());

/// The kernel of _so3_from_euler_<seq>[_deg]: angles (3) -> R (3, 3).
template <int N, bool Degrees, bool Rpy = false>  // Rpy: another type, for the rpy ufuncs
struct FromEulerKernel {
  template <typename V>
  auto operator()(const V& a) const {
    using T = typename V::Scalar;
    Eigen::Matrix<T, 3, 1> t = a;
    if (Degrees) t *= T(kDegToRad);
    return chasles::from_euler<static_cast<EulerSequence>(N)>(t).matrix();
  }
};

/// The kernel of _so3_as_euler_<seq>[_deg]: R (3, 3) -> angles (3).
template <int N, bool Degrees, bool Rpy = false>
struct AsEulerKernel {
  template <typename M>
  auto operator()(const M& R) const {
    using T = typename M::Scalar;
    Eigen::Matrix<T, 3, 1> t =
        chasles::as_euler<static_cast<EulerSequence>(N)>(chasles::SO3<T>::from_matrix_unchecked(R)).angles;
    if (Degrees) t *= T(kRadToDeg);
    return t;
  }
};

const char* const kUfuncNote = R"(

The private ufunc behind chasles.so3_from_euler / so3_as_euler (or
so3_from_rpy / so3_as_rpy) for one sequence and unit. A numpy generalized ufunc: numpy's rules for
broadcasting, dtypes (float32 and float64 kernels), out= and axes= apply.
A NaN gives NaN in its own element only.)";

template <int N, bool Degrees>
void def_sequence_ufuncs(py::module_& m) {
  static const std::string suffix = std::string(kSequences[N]) + (Degrees ? "_deg" : "");
  static const std::string from_name = "_so3_from_euler_" + suffix;
  static const std::string as_name = "_so3_as_euler_" + suffix;
  const std::string unit = Degrees ? "degrees" : "radians";
  def_ufunc<Core<3, 3>(Core<3>)>(m, from_name.c_str(), "angles",
                                 std::string("Rotation matrices of Euler angles in sequence '") + kSequences[N] +
                                     "', as scipy's Rotation.from_euler.\n\nArgs:\n    angles: array_like of "
                                     "shape (..., 3): the angles in " +
                                     unit +
                                     ".\n\nReturns:\n    numpy.ndarray of shape (..., 3, 3): the rotation "
                                     "matrices." +
                                     kUfuncNote,
                                 FromEulerKernel<N, Degrees>());
  def_ufunc<Core<3>(Core<3, 3>)>(m, as_name.c_str(), "R",
                                 std::string("Euler angles in sequence '") + kSequences[N] +
                                     "' of rotation matrices, as scipy's Rotation.as_euler (third angle zero at "
                                     "the gimbal lock).\n\nArgs:\n    R: array_like of shape (..., 3, 3): "
                                     "rotation matrices.\n\nReturns:\n    numpy.ndarray of shape (..., 3): the "
                                     "angles in " +
                                     unit + "." + kUfuncNote,
                                 AsEulerKernel<N, Degrees>());
}

template <int... N>
void def_all_ufuncs(py::module_& m, std::integer_sequence<int, N...>) {
  (def_sequence_ufuncs<N, false>(m), ...);
  (def_sequence_ufuncs<N, true>(m), ...);
}

/// _so3_from_rpy[_deg] and _so3_as_rpy[_deg]: the kernels of "xyz", under
/// names that numpy's errors show (so3_from_rpy / so3_as_rpy pick them).
template <bool Degrees>
void def_rpy_ufuncs(py::module_& m) {
  const std::string unit = Degrees ? "degrees" : "radians";
  def_ufunc<Core<3, 3>(Core<3>)>(m, Degrees ? "_so3_from_rpy_deg" : "_so3_from_rpy", "rpy",
                                 "Rotation matrices of roll, pitch, yaw (URDF, ROS): R = Rz(yaw) Ry(pitch) "
                                 "Rx(roll), extrinsic 'xyz'.\n\nArgs:\n    rpy: array_like of shape (..., 3): "
                                 "(roll, pitch, yaw) in " +
                                     unit +
                                     ".\n\nReturns:\n    numpy.ndarray of shape (..., 3, 3): the rotation "
                                     "matrices." +
                                     kUfuncNote,
                                 FromEulerKernel<0, Degrees, true>());
  def_ufunc<Core<3>(Core<3, 3>)>(m, Degrees ? "_so3_as_rpy_deg" : "_so3_as_rpy", "R",
                                 "Roll, pitch, yaw of rotation matrices (URDF, ROS): extrinsic 'xyz', yaw "
                                 "zero at the gimbal lock.\n\nArgs:\n    R: array_like of shape (..., 3, 3): "
                                 "rotation matrices.\n\nReturns:\n    numpy.ndarray of shape (..., 3): "
                                 "(roll, pitch, yaw) in " +
                                     unit + "." + kUfuncNote,
                                 AsEulerKernel<0, Degrees, true>());
}

}  // namespace

void bind_euler(py::module_& m) {
  def_all_ufuncs(m, std::make_integer_sequence<int, 24>());
  def_rpy_ufuncs<false>(m);
  def_rpy_ufuncs<true>(m);

  auto so3 = py::reinterpret_borrow<py::class_<SO3d, InlineHolder<SO3d>>>(m.attr("SO3"));

  so3.def_static(
      "from_euler",
      [](SequenceLike seq, ArrayLike angles, bool degrees) {
        const int n = sequence_index(seq.obj, "SO3.from_euler(seq)");
        Eigen::Vector3d t = to_finite_eigen<3>(angles.obj, "SO3.from_euler(angles)");
        if (degrees) t *= kDegToRad;
        return SO3d::from_matrix_unchecked(kFrom[static_cast<std::size_t>(n)](t));
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

  so3.def(
      "as_euler",
      [](Obj<SO3d> R, SequenceLike seq, bool degrees) {
        const int n = sequence_index(seq.obj, "SO3.as_euler(seq)");
        Eigen::Vector3d t = kAs[static_cast<std::size_t>(n)](*R);
        if (degrees) t *= kRadToDeg;
        return vec_out<3>(t);
      },
      py::arg("seq"), py::arg("degrees") = false,
      R"doc(Euler angles of the rotation, as scipy's ``Rotation.as_euler``.

scipy's ranges: the middle angle in [-pi/2, pi/2] for Tait-Bryan sequences
(three distinct axes), [0, pi] for proper Euler sequences (first axis =
last), the others in [-pi, pi]. At the gimbal lock (middle angle +-pi/2, or
0 or pi, to working precision) only the sum or difference of the outer
angles is defined, and the third angle is zero, as scipy. Robust there:
``SO3.from_euler(seq, R.as_euler(seq))`` reproduces R to a few ulps for
every rotation (atan2 of well-conditioned pairs of entries; scipy declares
the lock within 1e-7 of it and loses up to 1e-7 there).

Args:
    seq: the sequence, e.g. ``"xyz"``, ``"ZYX"``, ``"zxz"`` (see from_euler).
    degrees: return degrees (default radians).

Returns:
    ndarray: shape (3,), the angles in the order of ``seq``'s letters.

Example:
    >>> R = SO3.from_euler("ZYX", [0.3, -0.2, 0.1])
    >>> np.round(R.as_euler("ZYX"), 12)
    array([ 0.3, -0.2,  0.1])
)doc");

  so3.def_static(
      "from_rpy",
      [](ArrayLike rpy, bool degrees) {
        Eigen::Vector3d t = to_finite_eigen<3>(rpy.obj, "SO3.from_rpy(rpy)");
        if (degrees) t *= kDegToRad;
        return chasles::from_euler<EulerSequence::xyz>(t);
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

  so3.def(
      "as_rpy",
      [](Obj<SO3d> R, bool degrees) {
        Eigen::Vector3d t = chasles::as_rpy(*R).angles;
        if (degrees) t *= kRadToDeg;
        return vec_out<3>(t);
      },
      py::arg("degrees") = false,
      R"doc(Roll, pitch and yaw of the rotation (URDF, ROS tf's getRPY).

``R.as_euler("xyz")``: R = Rz(yaw) Ry(pitch) Rx(roll), pitch in
[-pi/2, pi/2], roll and yaw in [-pi, pi]; at the gimbal lock (pitch +-pi/2)
yaw is zero.

Args:
    degrees: return degrees (default radians).

Returns:
    ndarray: shape (3,), (roll, pitch, yaw).

Example:
    >>> np.round(SO3.from_rpy([0.1, 0.2, 0.3]).as_rpy(), 12)
    array([0.1, 0.2, 0.3])
)doc");
}

}  // namespace chasles_py
