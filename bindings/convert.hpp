// chasles._core: turning Python arguments into Eigen fixed-size types and
// results back into numpy arrays, with the errors the Python layer promises.
//
// Shared by the bind_*.cpp files. What a caller gets:
// - `to_eigen<R, C>(obj, what)`: anything array-like of shape (R,) (C = 1) or
//   (R, C) as an Eigen::Matrix<double, R, C>. A native float64 ndarray of the
//   right shape (any strides) is read straight from its buffer, a list or
//   tuple of Python floats and ints straight from the objects; everything
//   else goes through numpy.asarray (bool, integer and floating dtypes are
//   converted to float64). Errors:
//     TypeError  "<what>: expected real numbers (float64), got dtype complex128 (list)"
//                (complex, object, str, bytes, datetime, void, None);
//     ValueError "<what>: expected shape (3,), got (4,)", with a hint where one
//     helps: a batch given to a method for one element names the array
//     function ("SO3.exp(w): expected shape (3,), got (5, 3); for a batch,
//     call the array function chasles.so3_exp ..."), six numbers given to
//     Twist(v) name Twist.from_vector (`shape_hint`).
//   `to_finite_eigen` adds `require_finite`: ValueError "<what>: expected
//   finite numbers, got [nan, 0.0, 0.0]".
// - `to_real(obj, what)`: a Python float or int, a numpy real scalar or 0-d
//   array, or any object with __float__ (not complex), as a double.
// - `call_ufunc(array_function(name), what, args)`: an array function (a numpy
//   generalized ufunc) called from C++, its errors naming `what`.
// - `describe_argument(obj)`, `raw_shape(obj, shape)`: what came, for the
//   messages of constructors that refuse raw data (SO3(matrix), ...).
// - `new_array(nd, dims)`, `vec_out(v)`, `mat_out(M)`: new C-contiguous
//   float64 arrays, built with numpy's C API directly (no shape vectors).
// - Argument types whose conversion (and error) happens in the function body,
//   naming the argument, and which read well in signatures and stubs:
//   `ArrayLike` (numpy.typing.ArrayLike), `RealLike` (float), `IndexLike`
//   (typing.SupportsIndex), `Obj<T>` (the
//   bound class T, checked with one type test: fast to reject in overload
//   sets), `Returns<T>` (a T or NotImplemented, shown as T).
// - Protocol helpers: `array_protocol` (__array__ with numpy 2's dtype and
//   copy), `array_repr`, `float_tuple` / `state_tuple` / `read_state`
//   (bit-exact pickling), `add_reduce` (pickling at every protocol), `def_equality`
//   (`==` exact on the stored numbers, `!=`, unhashable), `def_repr`.
//
// `what` is the argument as the user wrote it, e.g. "SO3.exp(w)".
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <initializer_list>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <Eigen/Core>

#include "instance.hpp"

#if defined(__GNUC__) || defined(__clang__)
#define CHASLES_PY_HIDDEN __attribute__((visibility("hidden")))  // as pybind11's own types
#else
#define CHASLES_PY_HIDDEN
#endif

namespace chasles_py {

namespace py = pybind11;

/// An argument taken as any object and converted (or refused, naming it) in
/// the function body; signatures and the stub show it as `Name::text`.
template <typename Name>
struct CHASLES_PY_HIDDEN AnyObject {
  py::handle obj;
};

namespace names {
struct ArrayLike {
  static constexpr auto text = py::detail::const_name("numpy.typing.ArrayLike");
};
struct RealLike {
  static constexpr auto text = py::detail::const_name("float");
};
struct IndexLike {
  static constexpr auto text = py::detail::const_name("typing.SupportsIndex");
};
struct OptionalRealLike {
  static constexpr auto text = py::detail::const_name("float | None");
};
struct DTypeLike {
  static constexpr auto text = py::detail::const_name("numpy.typing.DTypeLike");
};
struct CopyFlag {
  static constexpr auto text = py::detail::const_name("bool | None");
};
}  // namespace names

/// Any array-like object.
using ArrayLike = AnyObject<names::ArrayLike>;
/// Any real number.
using RealLike = AnyObject<names::RealLike>;
/// Any integer (an object with __index__).
using IndexLike = AnyObject<names::IndexLike>;
/// Any real number, or None.
using OptionalRealLike = AnyObject<names::OptionalRealLike>;
/// A dtype argument (numpy's __array__ protocol).
using DTypeLike = AnyObject<names::DTypeLike>;
/// The copy argument of __array__: True, False or None.
using CopyFlag = AnyObject<names::CopyFlag>;

/// A result that is a T, or NotImplemented for an operator whose operand
/// it does not take; signatures show T.
template <typename T>
struct CHASLES_PY_HIDDEN Returns {
  py::object obj;
};

/// An argument that must be an instance of the bound class T (or of a Python
/// subclass), checked with one PyObject_TypeCheck. pybind11's generic caster
/// looks the type up in its registry on every call, and takes about 1 us to
/// reject an object of an unregistered type such as an ndarray: that cost
/// lands on every call of an overload set like `g @ h` / `g @ points`.
/// Signatures show T's Python name. T must be bound before the first call.
///
/// Every method of every bound class takes its self as an Obj (never as a
/// `const T&` or a member function pointer): an instance made by
/// `T.__new__(T)` alone, whose __init__ or __setstate__ has not run, holds
/// no value, and pybind11's generic caster would hand the method freshly
/// allocated, uninitialized storage to read. Obj refuses it with a TypeError.
template <typename T>
struct CHASLES_PY_HIDDEN Obj {
  const T* ptr = nullptr;
  py::handle handle;  ///< the Python object (borrowed for the call)
  const T& operator*() const { return *ptr; }
  const T* operator->() const { return ptr; }
};

/// Whether h is an instance of the bound class T, and whether it holds a
/// value: pybind11 constructs the holder in __init__ and __setstate__ only
/// (the value pointer alone is no test: pybind11 allocates it lazily).
enum class InstanceState { other_type, uninitialized, initialized };

template <typename T>
InstanceState instance_state(py::handle h, const T** value) {
  if (!PyObject_TypeCheck(h.ptr(), bound_type<T>())) return InstanceState::other_type;
  auto* inst = reinterpret_cast<py::detail::instance*>(h.ptr());
  const py::detail::value_and_holder vh = inst->get_value_and_holder();
  if (!vh.holder_constructed() || vh.value_ptr() == nullptr) return InstanceState::uninitialized;
  *value = static_cast<const T*>(vh.value_ptr());
  return InstanceState::initialized;
}

}  // namespace chasles_py

namespace pybind11 {
namespace detail {

template <typename Name>
struct type_caster<chasles_py::AnyObject<Name>> {
  PYBIND11_TYPE_CASTER(chasles_py::AnyObject<Name>, Name::text);
  bool load(handle src, bool /*convert*/) {
    value.obj = src;
    return static_cast<bool>(src);
  }
  static handle cast(const chasles_py::AnyObject<Name>& src, return_value_policy, handle) { return src.obj.inc_ref(); }
};

template <typename T>
struct type_caster<chasles_py::Returns<T>> {
  static constexpr auto name = make_caster<T>::name;
  static handle cast(const chasles_py::Returns<T>& src, return_value_policy, handle) { return src.obj.inc_ref(); }
};

template <typename T>
struct type_caster<chasles_py::Obj<T>> {
  static constexpr auto name = make_caster<T>::name;
  chasles_py::Obj<T> value;

  /// False for an object of another type (the next overload is tried);
  /// TypeError for an instance of T that holds no value yet.
  bool load(handle src, bool /*convert*/) {
    switch (chasles_py::instance_state<T>(src, &value.ptr)) {
      case chasles_py::InstanceState::other_type: return false;
      case chasles_py::InstanceState::uninitialized: {
        const char* name = Py_TYPE(src.ptr())->tp_name;
        const char* dot = std::strrchr(name, '.');
        throw type_error(std::string(dot ? dot + 1 : name) +
                         " object is not initialized: it was made by __new__ alone, without __init__ or "
                         "__setstate__");
      }
      case chasles_py::InstanceState::initialized: break;
    }
    value.handle = src;
    return true;
  }

  operator chasles_py::Obj<T>&() { return value; }
  template <typename U>
  using cast_op_type = chasles_py::Obj<T>&;
};

}  // namespace detail
}  // namespace pybind11

namespace chasles_py {

[[noreturn]] inline void raise_value_error(const std::string& msg) { throw py::value_error(msg); }
[[noreturn]] inline void raise_type_error(const std::string& msg) { throw py::type_error(msg); }

/// numpy's C API table (pybind11 loads it once).
inline const py::detail::npy_api& npy() { return py::detail::npy_api::get(); }

/// "(3,)", "(3, 3)", "()": a shape as Python prints it.
inline std::string shape_string(const Py_intptr_t* dims, int nd) {
  std::string s = "(";
  for (int i = 0; i < nd; ++i) {
    if (i > 0) s += ", ";
    s += std::to_string(static_cast<long long>(dims[i]));
  }
  if (nd == 1) s += ",";
  return s + ")";
}

template <int R, int C>
inline std::string expected_shape_string() {
  return C == 1 ? "(" + std::to_string(R) + ",)" : "(" + std::to_string(R) + ", " + std::to_string(C) + ")";
}

/// repr() of a double, shortest round trip ("0.1", "nan", "inf").
inline std::string float_repr(double x) {
  char* s = PyOS_double_to_string(x, 'r', 0, Py_DTSF_ADD_DOT_0, nullptr);
  if (s == nullptr) throw py::error_already_set();
  std::string out(s);
  PyMem_Free(s);
  return out;
}

/// A short form of a double for error messages ("0.0123", "1.49e-08").
inline std::string short_float(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", x);
  return buf;
}

/// A determinant for error messages, with enough digits to show how far it
/// is from 1 ("1.003", "0.999999", "-1").
inline std::string det_string(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", x);
  return buf;
}

/// "[1.0, nan, 0.0]" (row-major, nested for matrices).
template <typename Derived>
inline std::string values_string(const Eigen::MatrixBase<Derived>& m) {
  std::string s = "[";
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    if (i > 0) s += ", ";
    if (m.cols() > 1) s += "[";
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      if (j > 0) s += ", ";
      s += float_repr(m(i, j));
    }
    if (m.cols() > 1) s += "]";
  }
  return s + "]";
}

/// The Python type name of an object ("list", "numpy.ndarray", "NoneType").
inline std::string type_name(py::handle h) {
  PyTypeObject* t = Py_TYPE(h.ptr());
  return t->tp_name;
}

/// numpy.<name>, looked up once and kept for the life of the process.
inline PyObject* numpy_attr(const char* name) {
  return py::module_::import("numpy").attr(name).cast<py::object>().release().ptr();
}

/// True for an ndarray of native-endian float64.
inline bool is_native_float64_array(PyObject* o) {
  const auto& api = npy();
  if (!api.PyArray_Check_(o)) return false;
  const auto* d = py::detail::array_descriptor_proxy(py::detail::array_proxy(o)->descr);
  if (d->type_num != py::detail::npy_api::NPY_DOUBLE_) return false;
  const char native = PY_LITTLE_ENDIAN ? '<' : '>';
  return d->byteorder == '=' || d->byteorder == '|' || d->byteorder == native;
}

/// Re-raises the failure `e` of numpy's conversion of an argument to an
/// array (a ragged nested list, an __array__ that raises, ...) as a
/// TypeError (for a TypeError) or a ValueError (for any other Exception)
/// whose text is `msg` and numpy's reason, with `e` as __cause__.
/// MemoryError and what is not an Exception (KeyboardInterrupt) go through
/// unchanged.
[[noreturn]] inline void raise_conversion_error(py::error_already_set& e, const std::string& msg) {
  if (!e.matches(PyExc_Exception) || e.matches(PyExc_MemoryError)) throw;
  const std::string text = msg + ": " + py::str(e.value()).cast<std::string>();
  py::raise_from(e, e.matches(PyExc_TypeError) ? PyExc_TypeError : PyExc_ValueError, text.c_str());
  throw py::error_already_set();
}

/// numpy.asarray(obj) as a float64 ndarray of any shape, for real input
/// (bool, integer and floating dtypes). TypeError for anything else, naming
/// what was expected and what came.
inline py::array as_float64_array(py::handle h, const char* what) {
  if (h.is_none()) raise_type_error(std::string(what) + ": expected real numbers (float64), got None");
  if (PyUnicode_Check(h.ptr()) || PyBytes_Check(h.ptr()))
    raise_type_error(std::string(what) + ": expected real numbers (float64), got " + type_name(h));
  if (is_native_float64_array(h.ptr())) return py::reinterpret_borrow<py::array>(h);
  static PyObject* asarray = numpy_attr("asarray");
  py::object arr;
  try {
    arr = py::reinterpret_borrow<py::object>(asarray)(h);
  } catch (py::error_already_set& e) {
    raise_conversion_error(e, std::string(what) +
                                  ": expected an array-like of real numbers (float64), could not convert " +
                                  type_name(h) + " to an array");
  }
  if (!npy().PyArray_Check_(arr.ptr()))
    raise_type_error(std::string(what) + ": expected real numbers (float64), got " + type_name(h));
  py::array a = py::reinterpret_borrow<py::array>(arr);
  const py::dtype dt = a.dtype();
  const char kind = dt.kind();
  if (kind != 'b' && kind != 'i' && kind != 'u' && kind != 'f') {
    raise_type_error(std::string(what) + ": expected real numbers (float64), got dtype " + std::string(py::str(dt)) +
                     " (" + type_name(h) + ")");
  }
  if (is_native_float64_array(a.ptr())) return a;
  return py::reinterpret_steal<py::array>(a.attr("astype")(py::dtype::of<double>()).release());
}

/// Reads an (R,) or (R, C) float64 array of the right shape with its strides.
template <int R, int C>
inline void read_array(PyObject* o, Eigen::Matrix<double, R, C>& out) {
  const auto* a = py::detail::array_proxy(o);
  const char* data = a->data;
  const Py_intptr_t s0 = a->strides[0];
  if (C == 1) {
    for (int i = 0; i < R; ++i) std::memcpy(&out(i, 0), data + i * s0, sizeof(double));
  } else {
    const Py_intptr_t s1 = a->strides[1];
    for (int i = 0; i < R; ++i)
      for (int j = 0; j < C; ++j) std::memcpy(&out(i, j), data + i * s0 + j * s1, sizeof(double));
  }
}

template <int R, int C>
inline bool has_shape(PyObject* o) {
  const auto* a = py::detail::array_proxy(o);
  constexpr int nd = C == 1 ? 1 : 2;
  return a->nd == nd && a->dimensions[0] == R && (nd == 1 || a->dimensions[1] == C);
}

/// A list or tuple of n Python floats or ints (exact types) read directly
/// into out; false (and nothing raised) for anything else.
inline bool read_number_sequence(PyObject* o, double* out, py::ssize_t n) {
  const bool is_list = PyList_CheckExact(o);
  if (!is_list && !PyTuple_CheckExact(o)) return false;
  if ((is_list ? PyList_GET_SIZE(o) : PyTuple_GET_SIZE(o)) != n) return false;
  for (py::ssize_t i = 0; i < n; ++i) {
    PyObject* x = is_list ? PyList_GET_ITEM(o, i) : PyTuple_GET_ITEM(o, i);
    if (PyFloat_CheckExact(x)) {
      out[i] = PyFloat_AS_DOUBLE(x);
    } else if (PyLong_CheckExact(x)) {
      const double d = PyLong_AsDouble(x);
      if (d == -1.0 && PyErr_Occurred()) {
        PyErr_Clear();
        return false;
      }
      out[i] = d;
    } else {
      return false;
    }
  }
  return true;
}

template <int R>
inline bool read_flat_sequence(PyObject* o, Eigen::Matrix<double, R, 1>& out) {
  return read_number_sequence(o, out.data(), R);
}

/// What the message of a wrong shape adds for the argument `what` given an
/// array of shape `dims` where one of shape `core` belongs: the array
/// function for a batch (a method of an object takes one element), or the
/// constructor meant (Twist(v) given six numbers). "" when there is nothing
/// to add.
inline std::string shape_hint(const std::string& what, const Py_intptr_t* dims, int nd,
                              std::initializer_list<Py_intptr_t> core) {
  const int core_nd = static_cast<int>(core.size());
  bool batch = nd > core_nd;
  for (int k = 0; batch && k < core_nd; ++k) batch = dims[nd - core_nd + k] == core.begin()[k];
  static const std::pair<const char*, const char*> functions[] = {
      {"SO3.exp(w)", "so3_exp"},
      {"SO3.hat(w)", "so3_hat"},
      {"SO3.vee(matrix)", "so3_vee"},
      {"SO3.from_quat(quat)", "so3_from_quat"},
      {"SE3.exp(xi)", "se3_exp"},
      {"SE3.hat(xi)", "se3_hat"},
      {"SE3.vee(matrix)", "se3_vee"},
      {"Twist.vee(matrix)", "se3_vee"},
      {"SO3.interpolate(t)", "so3_interpolate"},
      {"SE3.interpolate(t)", "se3_interpolate"},
      {"interpolate(t)", "so3_interpolate or chasles.se3_interpolate"}};
  for (const auto& [method, function] : functions)
    if (batch && what == method)
      return "; for a batch, call the array function chasles." + std::string(function) +
             " (array functions broadcast over leading axes)";
  if (nd == 1 && dims[0] == 6 && core_nd == 1 && core.begin()[0] == 3) {
    if (what == "Twist(v)" || what == "Twist(w)") return "; a 6-vector (v, w) is Twist.from_vector(xi)";
    if (what == "Wrench(f)" || what == "Wrench(tau)") return "; a 6-vector (f, tau) is Wrench.from_vector(F)";
  }
  return "";
}

/// Any array-like of shape (R,) (C = 1) or (R, C) as a double Eigen matrix.
template <int R, int C = 1>
inline Eigen::Matrix<double, R, C> to_eigen(py::handle h, const char* what) {
  Eigen::Matrix<double, R, C> out;
  PyObject* o = h.ptr();
  if (is_native_float64_array(o) && has_shape<R, C>(o)) {  // the fast path
    read_array<R, C>(o, out);
    return out;
  }
  if constexpr (C == 1) {
    if (read_flat_sequence<R>(o, out)) return out;
  }
  const py::array a = as_float64_array(h, what);
  if (!has_shape<R, C>(a.ptr())) {
    const int nd = static_cast<int>(a.ndim());
    const std::string hint = C == 1 ? shape_hint(what, a.shape(), nd, {R}) : shape_hint(what, a.shape(), nd, {R, C});
    raise_value_error(std::string(what) + ": expected shape " + expected_shape_string<R, C>() + ", got " +
                      shape_string(a.shape(), nd) + hint);
  }
  read_array<R, C>(a.ptr(), out);
  return out;
}

/// ValueError unless every entry of m is finite.
template <typename Derived>
inline void require_finite(const Eigen::MatrixBase<Derived>& m, const char* what) {
  if (!m.allFinite()) raise_value_error(std::string(what) + ": expected finite numbers, got " + values_string(m));
}

/// The same, for a scalar.
inline void require_finite(double x, const char* what) {
  if (!std::isfinite(x)) raise_value_error(std::string(what) + ": expected a finite number, got " + float_repr(x));
}

/// A finite array-like of shape (R,) or (R, C): to_eigen, then require_finite.
template <int R, int C = 1>
inline Eigen::Matrix<double, R, C> to_finite_eigen(py::handle h, const char* what) {
  Eigen::Matrix<double, R, C> m = to_eigen<R, C>(h, what);
  require_finite(m, what);
  return m;
}

/// A real number: float, int, bool, numpy real scalar or 0-d array, or an
/// object with __float__ (fractions.Fraction, decimal.Decimal).
inline double to_real(py::handle h, const char* what) {
  PyObject* o = h.ptr();
  if (PyFloat_Check(o)) return PyFloat_AS_DOUBLE(o);
  if (PyLong_Check(o)) {
    const double d = PyLong_AsDouble(o);
    if (d == -1.0 && PyErr_Occurred()) {
      PyErr_Clear();
      raise_value_error(std::string(what) + ": integer too large for a float64");
    }
    return d;
  }
  if (h.is_none()) raise_type_error(std::string(what) + ": expected a real number (float), got None");
  static PyObject* np_generic = numpy_attr("generic");
  const int is_np_scalar = PyObject_IsInstance(o, np_generic);
  if (is_np_scalar < 0) throw py::error_already_set();
  if (npy().PyArray_Check_(o) || is_np_scalar || PySequence_Check(o)) {
    const py::array a = as_float64_array(h, what);
    if (a.ndim() != 0)
      raise_value_error(std::string(what) + ": expected a real number (shape ()), got shape " +
                        shape_string(a.shape(), static_cast<int>(a.ndim())) +
                        shape_hint(what, a.shape(), static_cast<int>(a.ndim()), {}));
    double x;
    std::memcpy(&x, py::detail::array_proxy(a.ptr())->data, sizeof(double));
    return x;
  }
  if (!PyComplex_Check(o) && Py_TYPE(o)->tp_as_number != nullptr && Py_TYPE(o)->tp_as_number->nb_float != nullptr) {
    const double d = PyFloat_AsDouble(o);
    if (d == -1.0 && PyErr_Occurred()) {
      // __float__ refused: Fraction(10**400) overflows, Decimal("sNaN") has no float.
      py::error_already_set e;
      raise_conversion_error(e, std::string(what) + ": could not convert " + type_name(h) + " to a float64");
    }
    return d;
  }
  raise_type_error(std::string(what) + ": expected a real number (float), got " + type_name(h));
}

/// A finite real number (to_real, then require_finite).
inline double to_finite_real(py::handle h, const char* what) {
  const double x = to_real(h, what);
  require_finite(x, what);
  return x;
}

/// A screw pitch: a real number, NaN and -inf refused (+inf is a pure
/// translation or a pure couple).
inline double to_pitch(py::handle h, const char* what) {
  const double pitch = to_real(h, what);
  if (std::isnan(pitch) || pitch == -HUGE_VAL)
    raise_value_error(std::string(what) + ": expected a finite pitch or +inf, got " + float_repr(pitch));
  return pitch;
}

/// A tolerance: a real number >= 0 (inf allowed).
inline double to_tolerance(py::handle h, const char* what) {
  const double tol = to_real(h, what);
  if (!(tol >= 0.0)) raise_value_error(std::string(what) + ": expected a tolerance >= 0, got " + float_repr(tol));
  return tol;
}

/// True for an instance of a class bound with pybind11 (an SO3, an SE3, a
/// Twist, ...): such objects are never taken as points, even when they
/// support __array__.
inline bool is_bound_object(py::handle h) { return py::detail::get_type_info(Py_TYPE(h.ptr())) != nullptr; }

/// The shape numpy gives `h` when it is raw numbers (an ndarray, a list or
/// tuple, an object with __array__, a bound object excepted), into `shape`;
/// false for anything else, or when numpy cannot convert it.
inline bool raw_shape(py::handle h, std::vector<Py_intptr_t>& shape) {
  PyObject* o = h.ptr();
  if (is_bound_object(h) ||
      !(npy().PyArray_Check_(o) || PyList_Check(o) || PyTuple_Check(o) || PyObject_HasAttrString(o, "__array__")))
    return false;
  static PyObject* asarray = numpy_attr("asarray");
  PyObject* a = PyObject_CallOneArg(asarray, o);
  if (a == nullptr) {
    PyErr_Clear();
    return false;
  }
  const py::array arr = py::reinterpret_steal<py::array>(a);
  shape.assign(arr.shape(), arr.shape() + arr.ndim());
  return true;
}

/// A tangent vector of size D: array-like of shape (D,), finite if `finite`;
/// of size 1 (SO2's angle theta) a real number as well.
template <int D>
inline Eigen::Matrix<double, D, 1> to_tangent(py::handle h, const char* what, bool finite) {
  if constexpr (D == 1) {
    std::vector<Py_intptr_t> shape;
    // A Python number first: raw_shape's attribute lookup on a float costs a microsecond.
    if (PyFloat_Check(h.ptr()) || PyLong_Check(h.ptr()) || !raw_shape(h, shape) || shape.empty()) {
      const double x = finite ? to_finite_real(h, what) : to_real(h, what);
      return Eigen::Matrix<double, 1, 1>(x);
    }
  }
  return finite ? to_finite_eigen<D>(h, what) : to_eigen<D>(h, what);
}

/// An argument as an error message names it: "ndarray of shape (3, 3)",
/// "list of shape (4, 4)", "None", "chasles._core.SE3".
inline std::string describe_argument(py::handle h) {
  if (h.is_none()) return "None";
  std::string d = Py_TYPE(h.ptr())->tp_name;
  std::vector<Py_intptr_t> shape;
  if (raw_shape(h, shape)) d += " of shape " + shape_string(shape.data(), static_cast<int>(shape.size()));
  return d;
}

/// The arguments of a call as an error message names them: "list of shape
/// (3,), degrees=bool".
inline std::string describe_arguments(const py::args& args, const py::kwargs& kwargs) {
  std::string got;
  for (const auto& a : args) got += (got.empty() ? "" : ", ") + describe_argument(a);
  for (const auto& kw : kwargs)
    got += (got.empty() ? "" : ", ") + py::str(kw.first).cast<std::string>() + "=" + describe_argument(kw.second);
  return got;
}

/// A new, uninitialized, C-contiguous float64 array.
inline py::array_t<double> new_array(int nd, const Py_intptr_t* dims) {
  const auto& api = npy();
  static PyObject* descr = api.PyArray_DescrFromType_(py::detail::npy_api::NPY_DOUBLE_);  // kept for the process
  Py_INCREF(descr);  // PyArray_NewFromDescr steals a reference
  PyObject* a = api.PyArray_NewFromDescr_(api.PyArray_Type_, descr, nd, dims, nullptr, nullptr, 0, nullptr);
  if (a == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::array_t<double>>(a);
}

/// The data pointer of an array made by new_array.
inline double* array_data(const py::array& a) {
  return reinterpret_cast<double*>(py::detail::array_proxy(a.ptr())->data);
}

/// A vector as a new (N,) array.
template <int N>
inline py::array_t<double> vec_out(const Eigen::Matrix<double, N, 1>& v) {
  const Py_intptr_t dims[1] = {N};
  py::array_t<double> a = new_array(1, dims);
  std::memcpy(array_data(a), v.data(), N * sizeof(double));
  return a;
}

/// A matrix as a new (R, C) C-contiguous array.
template <int R, int C>
inline py::array_t<double> mat_out(const Eigen::Matrix<double, R, C>& m) {
  const Py_intptr_t dims[2] = {R, C};
  py::array_t<double> a = new_array(2, dims);
  // (A column is the same in either order; Eigen refuses a row-major one.)
  Eigen::Map<Eigen::Matrix<double, R, C, C == 1 ? Eigen::ColMajor : Eigen::RowMajor>>(array_data(a)) = m;
  return a;
}

/// Calls the ufunc u with the operands: numpy's rules decide dtypes,
/// broadcasting and the GIL, as for a call from Python. An error is
/// re-raised with `what` (the call as the user wrote it, e.g. "SO3 @
/// points") before numpy's text, chained.
template <std::size_t N>
inline py::object call_ufunc(PyObject* u, const char* what, const std::array<PyObject*, N>& args) {
  PyObject* r = PyObject_Vectorcall(u, args.data(), N, nullptr);
  if (r == nullptr) {
    py::error_already_set e;
    raise_conversion_error(e, what);
  }
  return py::reinterpret_steal<py::object>(r);
}

/// An operand for a ufunc called from C++: an array of another library that
/// implements __array_ufunc__ (dask) as it is, so that numpy dispatches to
/// it; anything else through numpy.asarray (a subclass such as a masked
/// array or np.matrix becomes its base ndarray, as the objects read every
/// array argument), its failure re-raised naming `what`.
inline py::object ufunc_operand(py::handle x, const char* what) {
  const auto& api = npy();
  if (!api.PyArray_Check_(x.ptr()) && py::hasattr(x, "__array_ufunc__") && !x.attr("__array_ufunc__").is_none())
    return py::reinterpret_borrow<py::object>(x);
  PyObject* a = api.PyArray_FromAny_(x.ptr(), nullptr, 0, 0, py::detail::npy_api::NPY_ARRAY_ENSUREARRAY_, nullptr);
  if (a == nullptr) {
    py::error_already_set e;
    raise_conversion_error(e, std::string(what) + ": could not convert " + type_name(x) + " to an array");
  }
  return py::reinterpret_steal<py::object>(a);
}

/// The one-element fast path of a call that otherwise goes to a ufunc: true
/// and the n numbers in `out` when x is a native float64 ndarray of shape
/// (n,) or a list or tuple of n Python floats or ints, the inputs for which
/// the ufunc would run its float64 loop on one element and return a new
/// float64 array. The caller then computes that element with the same
/// kernel, skipping numpy's dispatch (about 1 us), and returns the same
/// bits (tests/python/test_ufuncs.py compares the two).
inline bool single_element(py::handle x, double* out, py::ssize_t n) {
  PyObject* o = x.ptr();
  if (is_native_float64_array(o)) {
    const auto* a = py::detail::array_proxy(o);
    if (a->nd != 1 || a->dimensions[0] != n) return false;
    for (py::ssize_t i = 0; i < n; ++i) std::memcpy(&out[i], a->data + i * a->strides[0], sizeof(double));
    return true;
  }
  return read_number_sequence(o, out, n);
}

/// The array functions (ufuncs) of the module by name, each added when
/// ufunc.hpp registers it: so that C++ calls one without importing its own
/// module. Held for the process, as the module holds them.
inline std::unordered_map<std::string, PyObject*>& array_functions() {
  static std::unordered_map<std::string, PyObject*> registry;
  return registry;
}

/// The array function `name`, registered by the time the module is imported.
inline PyObject* array_function(const char* name) {
  const auto it = array_functions().find(name);
  if (it == array_functions().end()) py::pybind11_fail(std::string("chasles: no array function ") + name);
  return it->second;
}

/// numpy's __array__ protocol for an object whose value lives in C++:
/// `value` is a fresh array; dtype converts it; copy=False cannot be honoured
/// (numpy 2 semantics: raise ValueError rather than silently copy).
inline py::array array_protocol(py::array_t<double> value, DTypeLike dtype, CopyFlag copy, const char* cls) {
  const int truth = copy.obj.is_none() ? 1 : PyObject_IsTrue(copy.obj.ptr());
  if (truth < 0) throw py::error_already_set();
  if (truth == 0) {
    raise_value_error(std::string("np.asarray(") + cls + ", copy=False): a " + cls +
                      " keeps its numbers in C++, so an array of them is always a copy; use copy=None or True");
  }
  if (dtype.obj.is_none()) return std::move(value);
  return value.attr("astype")(dtype.obj);
}

/// The class attribute `dtype` = float64 that goes with __array__: the dtype
/// of np.asarray(x). numpy's dtype discovery (np.dtype(x), np.result_type(x,
/// ...)) reads an object's `dtype` attribute. Without it an object that is
/// neither an ndarray nor iterable is no array to code that promotes dtypes
/// before it converts: scipy's Rotation.from_matrix(R) and
/// RigidTransform.from_matrix(g) (scipy._lib._array_api.xp_result_type) pass
/// R itself to np.result_type, which cannot read it as a dtype, and then to
/// np.isdtype (TypeError "dtype argument must be a NumPy dtype, but it is a
/// <class 'chasles._core.SO3'>"); with it they call np.asarray(R,
/// dtype=float64), which __array__ answers.
template <typename Class>
void def_array_dtype(Class& cls) {
  cls.attr("dtype") = py::dtype::of<double>();
}

/// __reduce_ex__ and __reduce__ returning (copyreg.__newobj__, (cls,), state)
/// for every pickle protocol. The default reduction of protocols 0 and 1
/// calls the pybind11 base type with the object, which aborts the process
/// (pybind11 3.1: "instance allocation failed"); this one is what protocol 2
/// does anyway: T.__new__(T), then __setstate__(state).
/// The self of both is an Obj<T> (TypeError for another type, or for an
/// uninitialized T); cls is its Python type (a subclass pickles as itself).
template <typename Class>
void add_reduce(Class& cls) {
  using T = typename Class::type;
  const auto reduce = [](Obj<T> self) {
    static PyObject* newobj = py::module_::import("copyreg").attr("__newobj__").cast<py::object>().release().ptr();
    return py::make_tuple(py::reinterpret_borrow<py::object>(newobj), py::make_tuple(py::type::handle_of(self.handle)),
                          self.handle.attr("__getstate__")());
  };
  cls.def(
      "__reduce_ex__", [reduce](Obj<T> self, int /*protocol*/) { return reduce(self); }, py::arg("protocol"),
      "Pickle support (every protocol): (copyreg.__newobj__, (cls,), state).");
  cls.def("__reduce__", reduce, "Pickle support: (copyreg.__newobj__, (cls,), state).");
}

/// `==` and `!=` of the bound class of `cls`: `equal(a, b)` is the exact
/// equality of the stored numbers, compared as floats (-0.0 == 0.0; a NaN is
/// unequal to everything, itself included), the same rule as numpy's
/// array_equal and C++'s `==` on Eigen matrices. An operand of another type
/// gives NotImplemented (Python then compares identities: `SO3() == 3` is
/// False). The objects are unhashable (`__hash__` is None): a hash of exact
/// floats would make a dictionary lookup fail on a difference of one ulp.
template <typename Class, typename Equal>
void def_equality(Class& cls, Equal equal) {
  using T = typename Class::type;
  const std::string name = py::str(cls.attr("__name__"));
  const std::string eq_doc =
      "Exact equality of the stored numbers: " + name +
      "s are values, compared as floats\n(-0.0 == 0.0; a NaN is unequal to everything, itself included).\n\n"
      "For a tolerance, use ``is_approx(other, tol)``. An object of another type gives\n"
      "NotImplemented, so ``==`` is False. " +
      name + "s are unhashable.\n\nArgs:\n    other: any object.\n\nReturns:\n    bool.";
  const std::string ne_doc = "The negation of ``==``: some stored number differs (or is NaN), or other is not a " +
                             name + ".\n\nArgs:\n    other: any object.\n\nReturns:\n    bool.";
  // `other` is any object (as object.__eq__ takes it, and as the stub says):
  // NotImplemented for another type, TypeError for an uninitialized T.
  const auto name_of = [](py::handle h) { return type_name(h); };
  const auto compare = [equal, name_of](Obj<T> a, py::handle b, bool want_equal) -> Returns<bool> {
    const T* value = nullptr;
    switch (instance_state<T>(b, &value)) {
      case InstanceState::other_type: return {py::reinterpret_borrow<py::object>(Py_NotImplemented)};
      case InstanceState::uninitialized: {
        py::detail::make_caster<Obj<T>> caster;
        caster.load(b, false);  // raises the TypeError every method raises for it
        raise_type_error(name_of(b) + " object is not initialized");
      }
      case InstanceState::initialized: break;
    }
    return {py::bool_(static_cast<bool>(equal(*a, *value)) == want_equal)};
  };
  cls.def(
      "__eq__", [compare](Obj<T> a, const py::object& other) { return compare(a, other, true); }, py::arg("other"),
      py::is_operator(), eq_doc.c_str());
  cls.def(
      "__ne__", [compare](Obj<T> a, const py::object& other) { return compare(a, other, false); }, py::arg("other"),
      py::is_operator(), ne_doc.c_str());
  cls.attr("__hash__") = py::none();
}

/// __repr__ of the bound class of `cls` from `f(const T&)`. An instance made
/// by __new__ alone (no value) reads "<uninitialized SO3>" instead of
/// raising: a repr should not fail (debuggers, error messages and test
/// tools call it on anything).
template <typename Class, typename F>
void def_repr(Class& cls, F f) {
  using T = typename Class::type;
  const std::string name = py::str(cls.attr("__name__"));
  cls.def("__repr__", [name, f](py::handle self) -> std::string {
    const T* value = nullptr;
    switch (instance_state<T>(self, &value)) {
      case InstanceState::other_type:
        raise_type_error(name + ".__repr__: expected a " + name + ", got " + type_name(self));
      case InstanceState::uninitialized: return "<uninitialized " + name + ">";
      case InstanceState::initialized: break;
    }
    return f(*value);
  });
}

/// A numpy array as a one-line string with numpy's print options:
/// "[[1., 0., 0.], [0., 1., 0.], [0., 0., 1.]]".
inline std::string array_repr(const py::array& a) {
  static PyObject* array2string = numpy_attr("array2string");
  std::string s = py::str(py::reinterpret_borrow<py::object>(array2string)(a, py::arg("separator") = ", "));
  std::string out;
  out.reserve(s.size());
  bool after_newline = false;
  for (char c : s) {
    if (c == '\n') {
      out += ' ';
      after_newline = true;
    } else if (after_newline && c == ' ') {
      continue;  // the indentation numpy puts after a row break
    } else {
      out += c;
      after_newline = false;
    }
  }
  return out;
}

/// A tuple of Python floats (exact: a float is a double) from m, row-major.
template <typename Derived>
inline py::tuple float_tuple(const Eigen::MatrixBase<Derived>& m) {
  py::tuple t(m.size());
  Eigen::Index k = 0;
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j) t[k++] = py::float_(m(i, j));
  return t;
}

/// Reads `n` Python floats from a pickled state tuple, starting at `offset`.
inline void read_state(const py::tuple& t, py::ssize_t offset, py::ssize_t n, double* out, const char* cls) {
  for (py::ssize_t k = 0; k < n; ++k) {
    PyObject* x = PyTuple_GET_ITEM(t.ptr(), offset + k);
    if (!PyFloat_Check(x))
      raise_type_error(std::string(cls) + ".__setstate__: expected a tuple of floats, got " + type_name(py::handle(x)) +
                       " at position " + std::to_string(offset + k));
    out[k] = PyFloat_AS_DOUBLE(x);
  }
}

/// The state tuple of __setstate__, checked for its length.
inline py::tuple state_tuple(py::handle state, py::ssize_t n, const char* cls) {
  if (!PyTuple_Check(state.ptr()) || PyTuple_GET_SIZE(state.ptr()) != n)
    raise_value_error(std::string(cls) + ".__setstate__: expected a tuple of " + std::to_string(n) + " floats");
  return py::reinterpret_borrow<py::tuple>(state);
}

/// The entries of m row by row, as one vector (a pickled state).
template <int R, int C>
Eigen::Matrix<double, R * C, 1> row_major(const Eigen::Matrix<double, R, C>& m) {
  Eigen::Matrix<double, R * C, 1> v;
  Eigen::Map<Eigen::Matrix<double, R, C, Eigen::RowMajor>>(v.data()) = m;
  return v;
}

/// `__array__` and the class attribute `dtype` (def_array_dtype) of a class
/// whose value has an array form, `array_of(const T&)` (a new float64 array).
template <typename Class, typename F>
void def_array(Class& cls, F array_of, const char* doc) {
  using T = typename Class::type;
  const std::string name = py::str(cls.attr("__name__"));
  cls.def(
      "__array__",
      [name, array_of](Obj<T> x, DTypeLike dtype, CopyFlag copy) {
        return array_protocol(array_of(*x), dtype, copy, name.c_str());
      },
      py::arg_v("dtype", py::none(), "None"), py::arg_v("copy", py::none(), "None"), doc);
  def_array_dtype(cls);
}

/// The protocol of a value class T, whose objects are their numbers:
/// `state(const T&)`, N doubles (an Eigen vector), are its pickled state (a
/// tuple of Python floats, for every pickle protocol: add_reduce) and its
/// identity: `==` is the exact equality of the states (def_equality);
/// `from_state(const double*)` makes the value of a state back, checked as
/// the constructor checks its arguments (a pickle is data from outside), or
/// raises. Also repr (`repr(const T&)`, def_repr), __copy__ and __deepcopy__
/// (the value). SO3, SE3, Twist, Wrench, Screw, SpatialInertia.
template <int N, typename Class, typename Repr, typename State, typename FromState>
void def_value_protocol(Class& cls, Repr repr, State state, FromState from_state) {
  using T = typename Class::type;
  const std::string name = py::str(cls.attr("__name__"));
  def_equality(cls, [state](const T& a, const T& b) { return state(a) == state(b); });
  def_repr(cls, repr);
  cls.def("__copy__", [](Obj<T> x) { return *x; });
  cls.def("__deepcopy__", [](Obj<T> x, const py::object&) { return *x; }, py::arg("memo"));
  cls.def(py::pickle([state](Obj<T> x) { return float_tuple(state(*x)); },
                     [name, from_state](const py::object& s) {
                       double v[N];
                       read_state(state_tuple(s, N, name.c_str()), 0, N, v, name.c_str());
                       return from_state(static_cast<const double*>(v));
                     }));
  add_reduce(cls);
}

}  // namespace chasles_py
