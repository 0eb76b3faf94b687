// chasles._core: Euler angles (include/chasles/euler.hpp).
//
// - the private ufuncs behind chasles.so3_from_euler / so3_as_euler and
//   so3_from_rpy / so3_as_rpy (python/chasles/_arrays.py): the sequence and
//   the unit are an operand, `code` (the sequence's index in
//   chasles::EulerSequence, plus 24 for degrees), as numpy passes it to the
//   loop. Both are template arguments of the C++ kernel, picked once per run
//   of equal codes (ufunc::cases): one code for a whole batch costs no
//   dispatch per element. Degrees are converted in the loop (x * (pi / 180),
//   as numpy's deg2rad), so that numpy's casting, out=, where= and dtype=
//   apply to the whole function and no temporary array is made. The
//   `_lock` variants of as_euler have a second result, the gimbal lock flag
//   of each element (return_gimbal_lock=True);
// - for SO3's methods (bind_so3.cpp): the sequence named by a str.
#include <string>

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
using Code = Typed<Core<>, int>;
using Flag = Typed<Core<>, bool>;

/// The 24 sequences, in the order of chasles::EulerSequence.
constexpr const char* kSequences[24] = {"xyz", "xzy", "yxz", "yzx", "zxy", "zyx", "xyx", "xzx",
                                        "yxy", "yzy", "zxz", "zyz", "XYZ", "XZY", "YXZ", "YZX",
                                        "ZXY", "ZYX", "XYX", "XZX", "YXY", "YZY", "ZXZ", "ZYZ"};

/// The case of the ufuncs' operand `code`: the sequence (its index in
/// chasles::EulerSequence) plus 24 for degrees. Both are compile-time in
/// the kernel: the loop picks the case once per run of equal codes.
constexpr int kSequenceOf(int code) { return code % 24; }
constexpr bool kDegrees(int code) { return code >= 24; }
/// The code of "xyz" for rpy's unit U (1: degrees).
template <int U>
using Xyz = std::integral_constant<int, U ? 24 : 0>;

/// angles (3) -> R (3, 3), for the code C.
struct FromEuler {
  template <typename C, typename V>
  auto operator()(C, const V& a, int) const {
    using T = typename V::Scalar;
    Eigen::Matrix<T, 3, 1> t = a;
    if constexpr (kDegrees(C::value)) t *= T(kDegToRad);
    return chasles::from_euler<static_cast<EulerSequence>(kSequenceOf(C::value))>(t).matrix();
  }
};

/// R (3, 3) -> angles (3) for the code C, and with `Lock` the gimbal lock flag.
template <bool Lock>
struct AsEuler {
  template <typename C, typename M>
  auto operator()(C, const M& R, int) const {
    using T = typename M::Scalar;
    const auto e =
        chasles::as_euler<static_cast<EulerSequence>(kSequenceOf(C::value))>(chasles::SO3<T>::from_matrix_unchecked(R));
    Eigen::Matrix<T, 3, 1> t = e.angles;
    if constexpr (kDegrees(C::value)) t *= T(kRadToDeg);
    if constexpr (Lock)
      return std::make_tuple(t, e.gimbal_lock);
    else
      return t;
  }
};

const char* const kUfuncNote = R"(

A private numpy generalized ufunc behind the public array function: numpy's
rules for broadcasting, dtypes (float32 and float64 kernels), out= and axes=
apply. A NaN gives NaN in its own element only.)";

const std::string kCodeArg = "    code: the sequence's index in (" + [] {
  std::string s;
  for (const char* q : kSequences) s += std::string(s.empty() ? "" : ", ") + q;
  return s;
}() + ") (chasles::EulerSequence), plus 24 for angles in degrees; NaN results for another.\n";

}  // namespace

EulerSequence euler_sequence(py::handle seq, const char* what) {
  if (!PyUnicode_Check(seq.ptr())) {
    throw py::type_error(std::string(what) + ": expected a str of three axes such as 'xyz' or 'ZYX', got " +
                         type_name(seq));
  }
  const std::string s = py::reinterpret_borrow<py::str>(seq).cast<std::string>();
  for (int i = 0; i < 24; ++i)
    if (s == kSequences[i]) return static_cast<EulerSequence>(i);
  raise_value_error(std::string(what) +
                    ": expected three axes of 'xyz', all lowercase (extrinsic) or all uppercase (intrinsic), "
                    "no two consecutive equal, as 'xyz', 'ZYX' or 'zxz'; got " +
                    py::repr(seq).cast<std::string>());
}

void bind_euler(py::module_& m) {
  const char* const unit = "    unit: 1 for angles in degrees, 0 for radians.\n";
  const std::string returns_lock =
      "\nReturns:\n    tuple of numpy.ndarray of shapes (..., 3) and (...): the angles, and whether the first "
      "and third axes coincide (the gimbal lock).";
  def_ufunc<Core<3, 3>(Core<3>, Code)>(
      m, "_so3_from_euler", "angles, code",
      "Rotation matrices of Euler angles, as scipy's Rotation.from_euler.\n\nArgs:\n    angles: array_like of "
      "shape (..., 3).\n" +
          kCodeArg + "\nReturns:\n    numpy.ndarray of shape (..., 3, 3): the rotation matrices." + kUfuncNote,
      ufunc::cases<48, 1>(FromEuler()));
  const std::string as_doc =
      "Euler angles of rotation matrices, as scipy's Rotation.as_euler (third angle zero at the "
      "gimbal lock).\n\nArgs:\n    R: array_like of shape (..., 3, 3): rotation matrices.\n" +
      kCodeArg;
  def_ufunc<Core<3>(Core<3, 3>, Code)>(
      m, "_so3_as_euler", "R, code",
      as_doc + "\nReturns:\n    numpy.ndarray of shape (..., 3): the angles." + kUfuncNote,
      ufunc::cases<48, 1>(AsEuler<false>()));
  def_ufunc<std::tuple<Core<3>, Flag>(Core<3, 3>, Code)>(
      m, "_so3_as_euler_lock", "R, code", as_doc + returns_lock + kUfuncNote, ufunc::cases<48, 1>(AsEuler<true>()));
  // The kernels of "xyz" (code 0 or 24), under the names that numpy's errors show for so3_from_rpy / so3_as_rpy.
  def_ufunc<Core<3, 3>(Core<3>, Code)>(
      m, "_so3_from_rpy", "rpy, unit",
      std::string("Rotation matrices of roll, pitch, yaw (URDF, ROS): R = Rz(yaw) Ry(pitch) Rx(roll), extrinsic "
                  "'xyz'.\n\nArgs:\n    rpy: array_like of shape (..., 3): (roll, pitch, yaw).\n") +
          unit + "\nReturns:\n    numpy.ndarray of shape (..., 3, 3): the rotation matrices." + kUfuncNote,
      ufunc::cases<2, 1>([](auto u, const auto& a, int) { return FromEuler()(Xyz<decltype(u)::value>(), a, 0); }));
  const std::string as_rpy = std::string(
                                 "Roll, pitch, yaw of rotation matrices (URDF, ROS): extrinsic 'xyz', yaw zero "
                                 "at the gimbal lock.\n\nArgs:\n    R: array_like of shape (..., 3, 3): "
                                 "rotation matrices.\n") +
                             unit;
  def_ufunc<Core<3>(Core<3, 3>, Code)>(
      m, "_so3_as_rpy", "R, unit",
      as_rpy + "\nReturns:\n    numpy.ndarray of shape (..., 3): (roll, pitch, yaw)." + kUfuncNote,
      ufunc::cases<2, 1>([](auto u, const auto& R, int) { return AsEuler<false>()(Xyz<decltype(u)::value>(), R, 0); }));
  def_ufunc<std::tuple<Core<3>, Flag>(Core<3, 3>, Code)>(
      m, "_so3_as_rpy_lock", "R, unit", as_rpy + returns_lock + kUfuncNote,
      ufunc::cases<2, 1>([](auto u, const auto& R, int) { return AsEuler<true>()(Xyz<decltype(u)::value>(), R, 0); }));
}

}  // namespace chasles_py
