// chasles._core: the small value classes (SO3, SE3, Twist, Wrench) hold
// their C++ value inside their Python object.
//
// pybind11 keeps a bound value apart from its Python object: a call that
// returns a new SE3 allocates the object, then the value with operator new,
// and registers the pair in pybind11's global instance map (a hash-map
// insert, and an erase when the object dies). For a value of 96 bytes and
// a few nanoseconds of math that is most of the call. Timed with timeit
// on one machine: `copy.copy` of a Screw (pybind11's path) 164 ns, of an
// SE3 (built as below) 97 ns; SE3.inverse() 169 ns before this header, 96
// after, against 122 and 119 for Pinocchio's SE3.inverse() in the same
// runs (Boost.Python builds the value inside the object).
//
// Here the class's instances are made `kValueOffset` bytes larger than
// pybind11's `instance` header (`hold_inline`, when the class is bound,
// before any instance exists), and a value returned by value is built in
// that space (`make_instance`): no operator new, and no registration.
// The holder is a std::unique_ptr whose deleter knows where its value lives,
// so pybind11's own paths (__init__, __setstate__, copies into instances of
// Python subclasses) keep their heap values and free them as before, and
// pybind11's deallocation destroys either kind through the holder.
//
// Registration only serves pybind11's lookup of the Python object of a C++
// pointer, for values returned by reference or pointer
// (return_value_policy::reference, reference_internal): such returns still
// take pybind11's own path (`InlineCaster` hands them on), and the objects
// made here are never the target of one, since no binding returns a
// reference into an SO3, SE3, Twist or Wrench object.
#pragma once

#include <cstddef>
#include <memory>
#include <typeinfo>
#include <utility>

#include <pybind11/pybind11.h>

#include <chasles/se3.hpp>
#include <chasles/so3.hpp>
#include <chasles/twist.hpp>
#include <chasles/wrench.hpp>

namespace chasles_py {

namespace py = pybind11;

/// Destroys a value made by pybind11 with operator new (`heap`, the default,
/// as pybind11 constructs a holder from a bare pointer) or in place inside
/// its Python object (make_instance): then it only runs the destructor.
template <typename T>
struct InlineDeleter {
  bool heap = true;
  void operator()(T* p) const noexcept {
    if (heap) {
      delete p;
    } else {
      p->~T();
    }
  }
};

/// The holder of the value classes: `py::class_<T, InlineHolder<T>>`.
template <typename T>
using InlineHolder = std::unique_ptr<T, InlineDeleter<T>>;

/// Where the value starts in the Python object: past pybind11's instance
/// header, aligned to 16 (what the Python allocator guarantees, and the
/// most the fixed-size Eigen members of these classes need).
template <typename T>
constexpr std::size_t kValueOffset = (sizeof(py::detail::instance) + 15) / 16 * 16;

/// The Python type bound to T, looked up once (T must be bound before the
/// first call).
template <typename T>
PyTypeObject* bound_type() {
  static PyTypeObject* const type = reinterpret_cast<PyTypeObject*>(py::detail::get_type_handle(typeid(T), true).ptr());
  return type;
}

/// Whether T's class has been given room for an inline value.
template <typename T>
bool& holds_inline() {
  static bool value = false;
  return value;
}

/// Gives the class of T room for its value inside each instance. Called
/// once, right after the class is created (no instance exists yet, and no
/// Python subclass: each inherits the size when it is made).
template <typename T, typename... Extra>
void hold_inline(py::class_<T, Extra...>& cls) {
  static_assert(alignof(T) <= 16, "an inline value needs at most the Python allocator's 16-byte alignment");
  auto* type = reinterpret_cast<PyTypeObject*>(cls.ptr());
  type->tp_basicsize = static_cast<Py_ssize_t>(kValueOffset<T> + sizeof(T));
  holds_inline<T>() = true;
}

/// A new Python object of class T holding `value` inline, not registered;
/// nullptr with a Python error set if allocation failed.
template <typename T>
PyObject* make_instance(T&& value) {
  PyTypeObject* const type = bound_type<T>();
  PyObject* self = type->tp_alloc(type, 0);
  if (self == nullptr) return nullptr;
  auto* inst = reinterpret_cast<py::detail::instance*>(self);
  inst->allocate_layout();
  inst->owned = true;
  auto v_h = inst->get_value_and_holder();
  T* stored = new (reinterpret_cast<char*>(self) + kValueOffset<T>) T(std::move(value));
  v_h.value_ptr() = stored;
  new (std::addressof(v_h.holder<InlineHolder<T>>())) InlineHolder<T>(stored, InlineDeleter<T>{false});
  v_h.set_holder_constructed();
  return self;
}

/// pybind11's caster for T, except that T returned by value (or copied out
/// of a const T&) becomes a new inline instance.
template <typename T>
struct InlineCaster : py::detail::type_caster_base<T> {
  using Base = py::detail::type_caster_base<T>;
  using Base::cast;

  static py::handle cast(T&& src, py::return_value_policy policy, py::handle parent) {
    if (!holds_inline<T>()) return Base::cast(std::move(src), policy, parent);
    PyObject* self = make_instance(std::move(src));
    if (self == nullptr) throw py::error_already_set();
    return self;
  }

  static py::handle cast(const T& src, py::return_value_policy policy, py::handle parent) {
    switch (policy) {
      case py::return_value_policy::automatic:
      case py::return_value_policy::automatic_reference:
      case py::return_value_policy::copy:
      case py::return_value_policy::move: return cast(T(src), policy, parent);
      default: return Base::cast(src, policy, parent);
    }
  }
};

}  // namespace chasles_py

namespace pybind11 {
namespace detail {

template <>
class type_caster<chasles::SO3d> : public chasles_py::InlineCaster<chasles::SO3d> {};
template <>
class type_caster<chasles::SE3d> : public chasles_py::InlineCaster<chasles::SE3d> {};
template <>
class type_caster<chasles::Twistd> : public chasles_py::InlineCaster<chasles::Twistd> {};
template <>
class type_caster<chasles::Wrenchd> : public chasles_py::InlineCaster<chasles::Wrenchd> {};

}  // namespace detail
}  // namespace pybind11
