// chasles._core: the array functions as numpy generalized ufuncs.
//
// Each array function is a kernel, a generic lambda that calls the chasles
// C++ API on one element, registered with numpy as a generalized ufunc with
// a float32 and a float64 loop:
//
//   def_ufunc<Core<3, 3>, Core<3>>(m, "so3_exp", "w", doc,
//       [](const auto& w) { return SO3<ScalarOf<decltype(w)>>::exp(w).matrix(); });
//
// gives chasles.so3_exp with the core signature (3)->(3,3). numpy does the
// rest, as for any ufunc: broadcasting of the leading axes, dtype resolution
// and casting, out=, axes=, the GIL (released around the loop), and the
// __array_ufunc__ dispatch that lets dask and xarray map the function over
// their chunks. Nothing here knows any of the mathematics.
//
// The loop hands the kernel, for each element, an Eigen::Map of the
// operand's memory (a T for a scalar core) with its core strides, or with
// constant offsets when every core is C-contiguous (the common case); an
// operand that stays put along the loop (one pose acting on many points) is
// read once into a local matrix that the compiler keeps in registers.
#pragma once

#include <Eigen/Core>
#include <pybind11/pybind11.h>

#include <array>
#include <cfenv>
#include <cstddef>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>

#include <chasles/se3.hpp>

#include "bindings.hpp"
#include "numpy_capi.hpp"

// Flatten: the loop inlines its whole kernel. Left to itself, the compiler
// kept some conversions out of line (SE3::from_matrix_unchecked, Eigen's 4x4
// copies) and the loop paid a store-forwarding stall on each: se3_compose
// ran at 62 ns instead of the 13 ns of the same loop written by hand.
#if defined(__GNUC__) || defined(__clang__)
#define CHASLES_PY_FLATTEN __attribute__((flatten))
#else
#define CHASLES_PY_FLATTEN
#endif

namespace chasles_py {
namespace ufunc {

using ssize = npy_intp;

// ---- core shapes ------------------------------------------------------------

/// The fixed trailing shape of an operand or of a result: `Core<>` a scalar,
/// `Core<3>` a vector of 3, `Core<4, 4>` a 4x4 matrix. `Stored<T>` is the
/// Eigen type of one element in C order; `text()` its part of the ufunc
/// signature.
template <int... Dims>
struct Core;

template <>
struct Core<> {
  static constexpr int ndim = 0, rows = 1, cols = 1, size = 1;
  template <typename T>
  using Stored = T;
  static std::string text() { return "()"; }
};

template <int N>
struct Core<N> {
  static constexpr int ndim = 1, rows = N, cols = 1, size = N;
  template <typename T>
  using Stored = Eigen::Matrix<T, N, 1>;
  static std::string text() { return "(" + std::to_string(N) + ")"; }
};

template <int R, int C>
struct Core<R, C> {
  static constexpr int ndim = 2, rows = R, cols = C, size = R * C;
  template <typename T>
  using Stored = Eigen::Matrix<T, R, C, Eigen::RowMajor>;
  static std::string text() { return "(" + std::to_string(R) + "," + std::to_string(C) + ")"; }
};

/// Byte strides of one operand's core axes (unused entries 0).
using CoreStrides = std::array<ssize, 2>;

/// Whether byte strides s are those of a C-contiguous core of T.
template <typename C, typename T>
inline bool is_contiguous(const CoreStrides& s) noexcept {
  constexpr ssize t = sizeof(T);
  if constexpr (C::ndim == 0) return true;
  if constexpr (C::ndim == 1) return s[0] == t;
  return s[0] == C::cols * t && s[1] == t;
}

// ---- element access ---------------------------------------------------------

/// What the kernel receives for the element at p: a T for a scalar core,
/// otherwise an Eigen::Map of the operand's memory with the core strides s
/// (bytes, multiples of sizeof(T): numpy hands legacy loops aligned data),
/// or with constant offsets if `Contiguous`. The kernel converts it to the
/// chasles argument type with Eigen's own assignment: reading the elements
/// one by one into a local matrix instead made the kernels' vector loads
/// wait on the scalar stores (a store-forwarding stall: so3_compose 26 ns
/// instead of 6).
template <typename C, typename T, bool Contiguous>
inline auto view(const char* p, const CoreStrides& s) noexcept {
  const T* d = reinterpret_cast<const T*>(p);
  constexpr ssize t = sizeof(T);
  if constexpr (C::ndim == 0) {
    return *d;
  } else if constexpr (Contiguous) {
    return Eigen::Map<const typename C::template Stored<T>>(d);
  } else if constexpr (C::ndim == 1) {
    using Inner = Eigen::InnerStride<Eigen::Dynamic>;
    return Eigen::Map<const typename C::template Stored<T>, Eigen::Unaligned, Inner>(d, Inner(s[0] / t));
  } else {
    using Strides = Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>;
    return Eigen::Map<const typename C::template Stored<T>, Eigen::Unaligned, Strides>(d, Strides(s[0] / t, s[1] / t));
  }
}

template <typename V>
struct IsSE3 : std::false_type {};
template <typename S>
struct IsSE3<chasles::SE3<S>> : std::true_type {};

/// Writes one core element at o, with the core strides s unless
/// `Contiguous`. A kernel may return an SE3 for a 4x4 core: its rotation
/// and translation are written in place, rather than through
/// SE3::matrix()'s 4x4 temporary, whose vector reloads wait on its scalar
/// stores (se3_exp 53.5 -> 48.7 ns per element at N = 1e5).
template <typename C, typename T, bool Contiguous, typename V>
inline void store(const V& v, char* o, const CoreStrides& s) noexcept {
  constexpr ssize t = sizeof(T);
  if constexpr (C::ndim == 0) {
    *reinterpret_cast<T*>(o) = v;
  } else if constexpr (IsSE3<V>::value) {
    static_assert(C::rows == 4 && C::cols == 4, "an SE3 is stored in a 4x4 core");
    const ssize s0 = Contiguous ? 4 * t : s[0], s1 = Contiguous ? t : s[1];
    const auto at = [&](int i, int j) -> T& { return *reinterpret_cast<T*>(o + i * s0 + j * s1); };
    const auto& R = v.rotation().matrix();
    const auto& p = v.translation();
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) at(i, j) = R(i, j);
      at(i, 3) = p[i];
    }
    at(3, 0) = at(3, 1) = at(3, 2) = T(0);
    at(3, 3) = T(1);
  } else if constexpr (Contiguous) {
    Eigen::Map<typename C::template Stored<T>> m(reinterpret_cast<T*>(o));
    m = v;
  } else if constexpr (C::ndim == 1) {
    using Inner = Eigen::InnerStride<Eigen::Dynamic>;
    Eigen::Map<typename C::template Stored<T>, Eigen::Unaligned, Inner> m(reinterpret_cast<T*>(o), Inner(s[0] / t));
    m = v;
  } else {
    using Strides = Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>;
    Eigen::Map<typename C::template Stored<T>, Eigen::Unaligned, Strides> m(reinterpret_cast<T*>(o),
                                                                          Strides(s[0] / t, s[1] / t));
    m = v;
  }
}

// ---- the loop ---------------------------------------------------------------

/// The inner loop over `n` elements. `Contiguous`: every core (operands and
/// result) is C-contiguous, compiled with constant offsets. `Fixed` < N:
/// that operand does not move along the loop; it is read once into a local
/// matrix, which the compiler can keep in registers and whose conversions it
/// can hoist out of the loop (it cannot for a map of input memory, which the
/// output stores might alias).
template <typename OutCore, typename T, bool Contiguous, std::size_t Fixed, typename... Cores, typename Kernel,
          std::size_t... I>
CHASLES_PY_FLATTEN void run(char** args, ssize n, const ssize* steps, const std::array<CoreStrides, sizeof...(Cores) + 1>& core,
                            const Kernel& kernel, std::index_sequence<I...>) noexcept {
  constexpr std::size_t N = sizeof...(Cores);
  char* out = args[N];
  const ssize out_step = steps[N];
  if constexpr (Fixed < N) {
    using C = std::tuple_element_t<Fixed, std::tuple<Cores...>>;
    const typename C::template Stored<T> fixed = view<C, T, Contiguous>(args[Fixed], core[Fixed]);
    auto arg = [&](auto j, ssize i) -> decltype(auto) {
      constexpr std::size_t J = decltype(j)::value;
      using Cj = std::tuple_element_t<J, std::tuple<Cores...>>;
      if constexpr (J == Fixed)
        return (fixed);
      else
        return view<Cj, T, Contiguous>(args[J] + i * steps[J], core[J]);
    };
    for (ssize i = 0; i < n; ++i)
      store<OutCore, T, Contiguous>(kernel(arg(std::integral_constant<std::size_t, I>(), i)...), out + i * out_step,
                                    core[N]);
  } else {
    for (ssize i = 0; i < n; ++i)
      store<OutCore, T, Contiguous>(kernel(view<Cores, T, Contiguous>(args[I] + i * steps[I], core[I])...),
                                    out + i * out_step, core[N]);
  }
}

/// run() for the layout of this call: contiguous cores or not, which
/// operand stays put (the first non-scalar one with an outer stride of 0).
template <typename OutCore, typename T, typename... Cores, typename Kernel, std::size_t... I>
void dispatch(char** args, ssize n, const ssize* steps, const std::array<CoreStrides, sizeof...(Cores) + 1>& core,
              const Kernel& kernel, std::index_sequence<I...> seq) noexcept {
  constexpr std::size_t N = sizeof...(Cores);
  const bool contiguous = (is_contiguous<Cores, T>(core[I]) && ...) && is_contiguous<OutCore, T>(core[N]);
  std::size_t fixed = N;
  if (n > 1) {
    constexpr int ndims[] = {Cores::ndim...};
    for (std::size_t j = N; j-- > 0;)
      if (ndims[j] > 0 && steps[j] == 0) fixed = j;
  }
  auto with = [&](auto fixed_c) {
    constexpr std::size_t F = decltype(fixed_c)::value;
    if (contiguous)
      run<OutCore, T, true, F, Cores...>(args, n, steps, core, kernel, seq);
    else
      run<OutCore, T, false, F, Cores...>(args, n, steps, core, kernel, seq);
  };
  if (!((fixed == I && (with(std::integral_constant<std::size_t, I>()), true)) || ...))
    with(std::integral_constant<std::size_t, N>());
}

/// numpy turns the floating-point flags a loop leaves into RuntimeWarnings
/// ("overflow encountered in so3_exp"). The kernels raise them on purpose
/// and handle the outcome: a comparison with a NaN input, a square that
/// overflows in a finiteness check, a scaled path for huge inputs. What the
/// user sees is the result, never NaN or inf for a finite input (the C++
/// test_finite and fuzz properties), NaN in the element of a NaN input: so
/// the loops leave no flags.
inline void clear_floating_point_flags() noexcept { std::feclearexcept(FE_ALL_EXCEPT); }

/// The numpy loop (PyUFuncGenericFunction) of a kernel for T: reads the
/// core strides numpy passes after the outer ones and runs the layout's
/// instantiation. `data` points to the kernel.
template <typename OutCore, typename T, typename Kernel, typename... Cores>
void loop(char** args, const ssize* dims, const ssize* steps, void* data) noexcept {
  constexpr std::size_t N = sizeof...(Cores);
  constexpr int ndims[] = {Cores::ndim..., OutCore::ndim};
  std::array<CoreStrides, N + 1> core{};
  const ssize* s = steps + N + 1;  // numpy: the outer strides, then each operand's core strides in order
  for (std::size_t j = 0; j <= N; ++j)
    for (int k = 0; k < ndims[j]; ++k) core[j][static_cast<std::size_t>(k)] = *s++;
  dispatch<OutCore, T, Cores...>(args, dims[0], steps, core, *static_cast<const Kernel*>(data),
                                 std::make_index_sequence<N>());
  clear_floating_point_flags();
}

// ---- registration -----------------------------------------------------------

/// The real type of a kernel argument (an Eigen matrix or a map of one).
template <typename V>
using ScalarOf = typename std::decay_t<V>::Scalar;

/// An array function's docstring: `body`, then the paragraph every one ends
/// with (the rules themselves are stated once, in the module's docstring).
inline std::string array_doc(const char* body) {
  return std::string(body) + R"(

A numpy generalized ufunc: numpy's rules for broadcasting, dtypes
(float32 and float64 kernels), out= and axes= apply (``help(chasles)``).
Matrices are taken as given, like the C++ unchecked constructors, and a NaN
gives NaN in its own element only.)";
}

template <typename Signature>
struct Parts;

/// `Out(In...)`: the core shapes of the result and of the operands.
template <typename OutCore, typename... Cores>
struct Parts<OutCore(Cores...)> {
  static constexpr std::size_t nin = sizeof...(Cores);

  /// The ufunc's core signature: "(3),(3,3)->(3)".
  static std::string signature() {
    std::string s;
    ((s += (s.empty() ? "" : ",") + Cores::text()), ...);
    return s + "->" + OutCore::text();
  }

  template <typename T, typename Kernel>
  static constexpr PyUFuncGenericFunction loop_of() {
    return &loop<OutCore, T, Kernel, Cores...>;
  }
};

/// Names the ufunc's operands in inspect.signature and in the first line of
/// its docstring: numpy's own names them x1, x2, ... ufuncs of numpy < 2.1
/// take no attributes and keep those (and numpy's docstring of `doc`).
inline void describe_ufunc(py::handle ufunc, const char* name, const char* params, const std::string& doc) {
  if (!py::hasattr(ufunc, "__dict__")) return;
  const py::object inspect = py::module_::import("inspect");
  const py::object sig = inspect.attr("signature")(ufunc);
  const py::list names = py::str(params).attr("split")(", ");
  py::list parameters;
  py::ssize_t k = 0;
  for (const py::handle p : sig.attr("parameters").attr("values")()) {
    if (k < static_cast<py::ssize_t>(names.size()))
      parameters.append(p.attr("replace")(py::arg("name") = names[static_cast<std::size_t>(k)]));
    else
      parameters.append(p);
    ++k;
  }
  const py::object named = sig.attr("replace")(py::arg("parameters") = parameters);
  ufunc.attr("__signature__") = named;
  ufunc.attr("__doc__") = py::str(std::string(name) + py::str(named).cast<std::string>() + "\n\n" + doc);
}

/// Registers `kernel` as the generalized ufunc `name` of module m with the
/// core signature of `Signature` (`Core<3, 3>(Core<3>)` is (3)->(3,3)) and a
/// float32 and a float64 loop, in that order: numpy takes the first loop to
/// which the operands cast safely, so float16 and small integers run in
/// float32, int32, int64 and float64 in float64, mixed float32 and float64
/// in float64. `params` names the operands ("a, b"), `doc` is the docstring
/// after the signature line. Each kernel type is registered once (its loops
/// and data live in statics of this instantiation, as numpy requires).
template <typename Signature, typename Kernel>
py::object def_ufunc(py::module_& m, const char* name, const char* params, const std::string& doc, Kernel kernel) {
  using P = Parts<Signature>;
  static_assert(std::is_empty_v<Kernel>, "a ufunc kernel captures nothing: it runs without the GIL, on any thread");
  static const Kernel stored = kernel;
  static PyUFuncGenericFunction funcs[] = {P::template loop_of<float, Kernel>(), P::template loop_of<double, Kernel>()};
  static void* data[] = {const_cast<Kernel*>(&stored), const_cast<Kernel*>(&stored)};
  static char types[2 * (P::nin + 1)];
  for (std::size_t j = 0; j <= P::nin; ++j) {
    types[j] = NPY_FLOAT;
    types[P::nin + 1 + j] = NPY_DOUBLE;
  }
  static const std::string doc_kept = doc;  // numpy keeps the pointer
  const std::string sig = P::signature();
  PyObject* u = PyUFunc_FromFuncAndDataAndSignature(funcs, data, types, 2, static_cast<int>(P::nin), 1, PyUFunc_None,
                                                    name, doc_kept.c_str(), 0, sig.c_str());
  if (u == nullptr) throw py::error_already_set();
  py::object ufunc = py::reinterpret_steal<py::object>(u);
  describe_ufunc(ufunc, name, params, doc);
  m.attr(name) = ufunc;
  return ufunc;
}

}  // namespace ufunc
}  // namespace chasles_py
