// chasles._core: Euler angles (include/chasles/euler.hpp).
//
// - the private ufuncs behind chasles.so3_from_euler / so3_as_euler and
//   so3_from_rpy / so3_as_rpy (python/chasles/_arrays.py): the sequence (its
//   index in chasles::EulerSequence) and the unit are operands, as numpy
//   passes them to the loop; the sequence is a template argument of the C++
//   kernel, picked once per run of equal sequences (ufunc::cases), so one
//   sequence for a whole batch costs no dispatch per element. Degrees are
//   converted in the loop (x * (pi / 180), as numpy's deg2rad), so that
//   numpy's casting, out=, where= and dtype= apply to the whole function and
//   no temporary array is made. as_euler has a second result, the gimbal
//   lock flag of each element;
// - for SO3's methods (bind_so3.cpp): the sequence named by a str, and the
//   conversions of one element.
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
using ufunc::Typed;
using Sequence = Typed<Core<>, int>;
using Flag = Typed<Core<>, bool>;

/// The 24 sequences, in the order of chasles::EulerSequence.
constexpr const char* kSequences[24] = {"xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "xyx", "xzx",
                                        "yxy", "yzy", "zxz", "zyz", "XYZ", "XZY", "YXZ", "YZX",
                                        "ZXY", "ZYX", "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ"};

template <int N>
Eigen::Matrix3d from_euler_n(const Eigen::Vector3d& t) {
  return chasles::from_euler<static_cast<EulerSequence>(N)>(t).matrix();
}
template <int N>
chasles::EulerAngles<double> as_euler_n(const SO3d& R) {
  return chasles::as_euler<static_cast<EulerSequence>(N)>(R);
}
template <int... N>
constexpr auto from_table(std::integer_sequence<int, N...>) {
  return std::array<Eigen::Matrix3d (*)(const Eigen::Vector3d&), 24>{&from_euler_n<N>...};
}
template <int... N>
constexpr auto as_table(std::integer_sequence<int, N...>) {
  return std::array<chasles::EulerAngles<double> (*)(const SO3d&), 24>{&as_euler_n<N>...};
}
constexpr auto kFrom = from_table(std::make_integer_sequence<int, 24>());
constexpr auto kAs = as_table(std::make_integer_sequence<int, 24>());

/// angles (3), in degrees if `degrees` -> R (3, 3), for the sequence c.
struct FromEuler {
  template <typename C, typename V>
  auto operator()(C, const V& a, int, bool degrees) const {
    using T = typename V::Scalar;
    Eigen::Matrix<T, 3, 1> t = a;
    if (degrees) t *= T(kDegToRad);
    return chasles::from_euler<static_cast<EulerSequence>(C::value)>(t).matrix();
  }
};

/// R (3, 3) -> (angles (3), in degrees if `degrees`; the gimbal lock flag), for the sequence c.
struct AsEuler {
  template <typename C, typename M>
  auto operator()(C, const M& R, int, bool degrees) const {
    using T = typename M::Scalar;
    const auto e = chasles::as_euler<static_cast<EulerSequence>(C::value)>(chasles::SO3<T>::from_matrix_unchecked(R));
    return std::make_tuple(Eigen::Matrix<T, 3, 1>(degrees ? Eigen::Matrix<T, 3, 1>(e.angles * T(kRadToDeg)) : e.angles),
                           e.gimbal_lock);
  }
};

const char* const kUfuncNote = R"(

A private numpy generalized ufunc behind the public array function: numpy's
rules for broadcasting, dtypes (float32 and float64 kernels), out= and axes=
apply. A NaN gives NaN in its own element only.)";

const std::string kSequenceArg = "    seq: the sequence's index in (" + [] {
  std::string s;
  for (const char* q : kSequences) s += std::string(s.empty() ? "" : ", ") + q;
  return s;
}() + ") (chasles::EulerSequence); NaN results for another.\n";

}  // namespace

int euler_sequence(py::handle seq, const char* what) {
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

Eigen::Matrix3d euler_to_matrix(int seq, const Eigen::Vector3d& angles) {
  return kFrom[static_cast<std::size_t>(seq)](angles);
}

chasles::EulerAngles<double> euler_of(int seq, const SO3d& R) { return kAs[static_cast<std::size_t>(seq)](R); }

void bind_euler(py::module_& m) {
  const std::string unit = "    degrees: the angles are in degrees (else radians).\n";
  def_ufunc<Core<3, 3>(Core<3>, Sequence, Flag)>(
      m, "_so3_from_euler", "angles, seq, degrees",
      "Rotation matrices of Euler angles, as scipy's Rotation.from_euler.\n\nArgs:\n    angles: array_like of "
      "shape (..., 3).\n" + kSequenceArg + unit +
          "\nReturns:\n    numpy.ndarray of shape (..., 3, 3): the rotation matrices." + kUfuncNote,
      ufunc::cases<24, 1>(FromEuler()));
  def_ufunc<std::tuple<Core<3>, Flag>(Core<3, 3>, Sequence, Flag)>(
      m, "_so3_as_euler", "R, seq, degrees",
      "Euler angles of rotation matrices, as scipy's Rotation.as_euler (third angle zero at the gimbal "
      "lock).\n\nArgs:\n    R: array_like of shape (..., 3, 3): rotation matrices.\n" + kSequenceArg + unit +
          "\nReturns:\n    tuple of numpy.ndarray of shapes (..., 3) and (...): the angles, and whether the first "
          "and third axes coincide (the gimbal lock)." + kUfuncNote,
      ufunc::cases<24, 1>(AsEuler()));
  // The kernels of "xyz", under the names that numpy's errors show for so3_from_rpy / so3_as_rpy.
  def_ufunc<Core<3, 3>(Core<3>, Flag)>(
      m, "_so3_from_rpy", "rpy, degrees",
      "Rotation matrices of roll, pitch, yaw (URDF, ROS): R = Rz(yaw) Ry(pitch) Rx(roll), extrinsic "
      "'xyz'.\n\nArgs:\n    rpy: array_like of shape (..., 3): (roll, pitch, yaw).\n" + unit +
          "\nReturns:\n    numpy.ndarray of shape (..., 3, 3): the rotation matrices." + kUfuncNote,
      [](const auto& a, bool degrees) { return FromEuler()(std::integral_constant<int, 0>(), a, 0, degrees); });
  def_ufunc<std::tuple<Core<3>, Flag>(Core<3, 3>, Flag)>(
      m, "_so3_as_rpy", "R, degrees",
      "Roll, pitch, yaw of rotation matrices (URDF, ROS): extrinsic 'xyz', yaw zero at the gimbal lock.\n\nArgs:\n"
      "    R: array_like of shape (..., 3, 3): rotation matrices.\n" + unit +
          "\nReturns:\n    tuple of numpy.ndarray of shapes (..., 3) and (...): (roll, pitch, yaw), and the gimbal "
          "lock flag." + kUfuncNote,
      [](const auto& R, bool degrees) { return AsEuler()(std::integral_constant<int, 0>(), R, 0, degrees); });
}

}  // namespace chasles_py
