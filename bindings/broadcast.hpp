// chasles._core: the one broadcasting loop behind every array function of
// bind_batch.cpp.
//
// Semantics are those of numpy's generalized ufuncs (np.linalg): each operand
// has a fixed trailing "core" shape (3 for a rotation vector, (4, 4) for a
// pose, ...), its leading axes are the batch axes, and the batch axes of all
// operands broadcast together as np.broadcast_shapes does. The result has
// shape batch + the result's core shape, in a fresh C-contiguous array.
//
//   apply<Core<3, 3>>("so3_exp", kernel, in<Core<3>>("w", w))
//
// calls `kernel(w_i)` for every batch index i, w_i an Eigen::Map of the 3
// numbers in the operand's memory, and stores the returned 3x3 matrix. The
// kernel is a generic lambda, instantiated for T = float and T = double; it
// calls the chasles C++ API and nothing here knows any of the mathematics.
//
// dtypes: float32 operands give float32 results (the float kernels); any
// float64 operand makes the call float64; integer and bool arrays are
// converted to float64; Python int/float scalars are "weak" (NEP 50) and do
// not change the result type. Anything else is a TypeError.
//
// Memory: operands are read in place through their strides (any strides,
// negative, zero, read-only, Fortran order: no copy). A dtype conversion
// makes a copy, and so does an unaligned array (a view into a byte buffer at
// an odd offset: rare), as numpy's own loops do. The GIL is released around
// the loop once every Python object has been dealt with (for more than
// kGilThreshold elements, as numpy's ufuncs do: below that, releasing costs
// more than the loop).
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <Eigen/Core>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"

// Hidden, as pybind11's own namespace: types here hold pybind11 objects,
// and a type more visible than its fields draws -Wattributes. Flatten: the
// loop inlines its whole kernel (see run_loop).
#if defined(__GNUC__) && !defined(_WIN32)
#define CHASLES_PY_BATCH_HIDDEN __attribute__((visibility("hidden")))
#else
#define CHASLES_PY_BATCH_HIDDEN
#endif
#if defined(__GNUC__) || defined(__clang__)
#define CHASLES_PY_BATCH_FLATTEN __attribute__((flatten))
#else
#define CHASLES_PY_BATCH_FLATTEN
#endif

namespace chasles_py {
namespace batch CHASLES_PY_BATCH_HIDDEN {

using ssize = py::ssize_t;

/// Below this many elements the GIL is kept (numpy's ufunc threshold).
constexpr ssize kGilThreshold = 500;

// ---- core shapes ------------------------------------------------------------

/// The fixed trailing shape of an operand or of a result: `Core<>` a scalar,
/// `Core<3>` a vector of 3, `Core<4, 4>` a 4x4 matrix. `Stored<T>` is the
/// Eigen type of one element in C order.
template <int... Dims>
struct Core;

template <>
struct Core<> {
  static constexpr int ndim = 0, rows = 1, cols = 1, size = 1;
  template <typename T>
  using Stored = T;
  static std::vector<ssize> dims() { return {}; }
};

template <int N>
struct Core<N> {
  static constexpr int ndim = 1, rows = N, cols = 1, size = N;
  template <typename T>
  using Stored = Eigen::Matrix<T, N, 1>;
  static std::vector<ssize> dims() { return {N}; }
};

template <int R, int C>
struct Core<R, C> {
  static constexpr int ndim = 2, rows = R, cols = C, size = R * C;
  template <typename T>
  using Stored = Eigen::Matrix<T, R, C, Eigen::RowMajor>;
  static std::vector<ssize> dims() { return {R, C}; }
};

/// An operand as passed by the caller: its name (for messages) and the
/// object, borrowed.
template <typename C>
struct In {
  const char* name;
  PyObject* obj;
};

template <typename C>
In<C> in(const char* name, py::handle obj) {
  return {name, obj.ptr()};
}

// ---- messages ---------------------------------------------------------------

/// "(5, 3)", "(5,)", "()", as Python prints a shape; `ellipsis` prefixes "...".
inline std::string shape_str(const ssize* dims, ssize n, bool ellipsis = false) {
  std::string s = "(";
  if (ellipsis) s += n ? "..., " : "...";
  for (ssize k = 0; k < n; ++k) {
    if (k) s += ", ";
    s += std::to_string(dims[k]);
  }
  if (n == 1 && !ellipsis) s += ",";
  return s + ")";
}

// ---- element access ---------------------------------------------------------

/// Whether byte strides s are those of a C-contiguous core of T.
template <typename C, typename T>
inline bool is_contiguous(const std::array<ssize, 2>& s) noexcept {
  constexpr ssize t = sizeof(T);
  if constexpr (C::ndim == 0) return true;
  if constexpr (C::ndim == 1) return s[0] == t;
  return s[0] == C::cols * t && s[1] == t;
}

/// What the kernel receives for the element at p: a T for a scalar core,
/// otherwise an Eigen::Map of the operand's memory, with the core strides s
/// (bytes, multiples of sizeof(T)), or with constant offsets if
/// `Contiguous`. The kernel converts it to the chasles argument type with
/// Eigen's own assignment: reading the elements one by one into a local
/// matrix instead made the kernels' vector loads wait on the scalar stores
/// (a store-forwarding stall: so3_compose 26 ns instead of 6).
template <typename C, typename T, bool Contiguous>
inline auto view(const char* p, const std::array<ssize, 2>& s) noexcept {
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

/// Writes one core element, C order, at o. A kernel may return an SE3 for a
/// 4x4 core: its rotation and translation are written in place, rather
/// than through SE3::matrix()'s 4x4 temporary, whose vector reloads wait on
/// its scalar stores (se3_exp 53.5 -> 48.7 ns per element at N = 1e5).
template <typename C, typename T, typename V>
inline void store(const V& v, T* o) noexcept {
  if constexpr (C::ndim == 0) {
    *o = v;
  } else if constexpr (IsSE3<V>::value) {
    static_assert(C::rows == 4 && C::cols == 4, "an SE3 is stored in a 4x4 core");
    const auto& R = v.rotation().matrix();
    const auto& p = v.translation();
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) o[4 * i + j] = R(i, j);
      o[4 * i + 3] = p[i];
    }
    o[12] = o[13] = o[14] = T(0);
    o[15] = T(1);
  } else {
    Eigen::Map<typename C::template Stored<T>> m(o);
    m = v;
  }
}

// ---- operands ---------------------------------------------------------------

enum class Kind { f32, f64, integer };

/// One operand after np.asarray, its dtype class and core shape checked.
struct Operand {
  const char* name;
  py::array arr;
  Kind kind;
  bool weak;      ///< a Python int/float/bool scalar: does not set the dtype
  int core_ndim;  ///< 0, 1 or 2
};

/// np.asarray(o); a conversion numpy refuses (a ragged nested list, an
/// __array__ that raises) is an error naming the function and the operand.
inline py::array operand_array(const char* fname, const char* name, PyObject* o) {
  try {
    return py::array(py::reinterpret_borrow<py::object>(o));
  } catch (py::error_already_set& e) {
    raise_conversion_error(e, std::string(fname) + ": could not convert " + name + " (" + Py_TYPE(o)->tp_name +
                                  ") to an array");
  }
}

inline Operand prepare(const char* fname, const char* name, PyObject* o, int core_ndim,
                       const std::vector<ssize>& core) {
  // Python scalars are weak, as in numpy >= 2 (NEP 50); numpy's own scalar
  // types (np.float64 derives from float) are not.
  const bool weak = PyFloat_CheckExact(o) || PyLong_CheckExact(o) || PyBool_Check(o);
  Operand op{name, operand_array(fname, name, o), Kind::f64, weak, core_ndim};

  const py::dtype dt = op.arr.dtype();
  const char k = dt.kind();
  if (k == 'f' && dt.itemsize() == 4) {
    op.kind = Kind::f32;
  } else if (k == 'f' && dt.itemsize() == 8) {
    op.kind = Kind::f64;
  } else if (k == 'i' || k == 'u' || k == 'b') {
    op.kind = Kind::integer;
  } else {
    throw py::type_error(std::string(fname) + ": " + name + " has dtype " + py::str(dt).cast<std::string>() +
                         "; expected float32 or float64 (integer and bool arrays are converted to float64)");
  }

  const ssize nd = op.arr.ndim();
  bool ok = nd >= core_ndim;
  for (int j = 0; ok && j < core_ndim; ++j) ok = op.arr.shape(nd - core_ndim + j) == core[j];
  if (!ok) {
    throw py::value_error(std::string(fname) + ": expected " + name + " of shape " +
                          shape_str(core.data(), core_ndim, true) + ", got " + shape_str(op.arr.shape(), nd));
  }
  return op;
}

// ---- the loop ---------------------------------------------------------------

/// Everything the loop needs, in plain C++ (no Python object): the batch
/// shape after coalescing, and per operand its data pointer, batch byte
/// strides (0 along broadcast axes) and core byte strides.
template <std::size_t N>
struct Plan {
  std::vector<ssize> shape;                    ///< batch axes, outermost first
  std::array<std::vector<ssize>, N> strides;   ///< per operand, per batch axis
  std::array<const char*, N> data;
  std::array<std::array<ssize, 2>, N> core;    ///< byte strides of the core axes
};

/// Drops the batch axes of length 1 and merges neighbours that every operand
/// (and the C-ordered output) walks as one, so the inner loop is as long as
/// possible: (N, M) contiguous becomes one axis of N * M.
template <std::size_t N>
void coalesce(Plan<N>& p) {
  std::vector<ssize> shape;
  std::array<std::vector<ssize>, N> strides;
  for (std::size_t k = 0; k < p.shape.size(); ++k) {
    if (p.shape[k] == 1) continue;
    bool merge = !shape.empty();
    for (std::size_t j = 0; merge && j < N; ++j) merge = strides[j].back() == p.strides[j][k] * p.shape[k];
    if (merge) {
      shape.back() *= p.shape[k];
      for (std::size_t j = 0; j < N; ++j) strides[j].back() = p.strides[j][k];
    } else {
      shape.push_back(p.shape[k]);
      for (std::size_t j = 0; j < N; ++j) strides[j].push_back(p.strides[j][k]);
    }
  }
  p.shape = std::move(shape);
  p.strides = std::move(strides);
}

/// Which operand stays put along the inner axis (one pose acting on many
/// points): the first non-scalar operand with a zero inner stride, or N if
/// none does.
template <typename... Cores, std::size_t N = sizeof...(Cores)>
std::size_t fixed_operand(const Plan<N>& p) {
  constexpr int ndims[] = {Cores::ndim...};
  if (p.shape.empty()) return N;
  for (std::size_t j = 0; j < N; ++j)
    if (ndims[j] > 0 && p.strides[j].back() == 0) return j;
  return N;
}

/// Calls the kernel for every batch index in C order, writing the results
/// one after the other from `out`.
///
/// `Contiguous`: every operand's core is C-contiguous (the common case,
/// compiled with constant offsets). `Fixed` < N: that operand does not move
/// along the inner axis; it is copied once per inner run into a local
/// matrix, which the compiler can keep in registers and whose conversions
/// it can hoist out of the loop (it cannot for a map of input memory, which
/// the output stores might alias).
///
/// Flattened: the kernel is inlined whole. Left to itself, the compiler
/// kept some conversions out of line (SE3::from_matrix_unchecked, Eigen's
/// 4x4 copies) and the loop paid a store-forwarding stall on each: se3_compose
/// ran at 62 ns instead of the 13 ns of the same loop written by hand.
template <typename OutCore, typename T, bool Contiguous, std::size_t Fixed, typename... Cores, typename Kernel,
          std::size_t... I>
CHASLES_PY_BATCH_FLATTEN void run_loop(const Plan<sizeof...(Cores)>& p, const Kernel& kernel, T* out,
                                       std::index_sequence<I...>) {
  constexpr std::size_t N = sizeof...(Cores);
  const int nd = static_cast<int>(p.shape.size());
  const ssize inner = nd ? p.shape[nd - 1] : 1;
  std::array<ssize, N> step{};
  if (nd) ((step[I] = p.strides[I][nd - 1]), ...);
  std::vector<ssize> idx(nd > 1 ? nd - 1 : 0, 0);
  std::array<const char*, N> base = p.data;
  for (;;) {
    if constexpr (Fixed < N) {
      using C = std::tuple_element_t<Fixed, std::tuple<Cores...>>;
      const typename C::template Stored<T> fixed = view<C, T, Contiguous>(base[Fixed], p.core[Fixed]);
      auto arg = [&](auto j, ssize i) -> decltype(auto) {
        constexpr std::size_t J = decltype(j)::value;
        using Cj = std::tuple_element_t<J, std::tuple<Cores...>>;
        if constexpr (J == Fixed)
          return (fixed);
        else
          return view<Cj, T, Contiguous>(base[J] + i * step[J], p.core[J]);
      };
      for (ssize i = 0; i < inner; ++i) {
        store<OutCore>(kernel(arg(std::integral_constant<std::size_t, I>(), i)...), out);
        out += OutCore::size;
      }
    } else {
      for (ssize i = 0; i < inner; ++i) {
        store<OutCore>(kernel(view<Cores, T, Contiguous>(base[I] + i * step[I], p.core[I])...), out);
        out += OutCore::size;
      }
    }
    int k = nd - 2;
    for (; k >= 0; --k) {
      ((base[I] += p.strides[I][k]), ...);
      if (++idx[k] < p.shape[k]) break;
      ((base[I] -= p.strides[I][k] * p.shape[k]), ...);
      idx[k] = 0;
    }
    if (k < 0) break;
  }
}

/// run_loop for the plan's layout: contiguous cores or not, which operand
/// stays put (one instantiation per case).
template <typename OutCore, typename T, typename... Cores, typename Kernel, std::size_t... I>
void run_plan(const Plan<sizeof...(Cores)>& p, const Kernel& kernel, T* out, std::index_sequence<I...> seq) {
  constexpr std::size_t N = sizeof...(Cores);
  const bool contiguous = (is_contiguous<Cores, T>(p.core[I]) && ...);
  const std::size_t fixed = fixed_operand<Cores...>(p);
  auto with = [&](auto fixed_c) {
    constexpr std::size_t F = decltype(fixed_c)::value;
    if (contiguous)
      run_loop<OutCore, T, true, F, Cores...>(p, kernel, out, seq);
    else
      run_loop<OutCore, T, false, F, Cores...>(p, kernel, out, seq);
  };
  if (!((fixed == I && (with(std::integral_constant<std::size_t, I>()), true)) || ...))
    with(std::integral_constant<std::size_t, N>());
}

/// Broadcasts the operands (already of dtype class T) and runs the kernel.
template <typename OutCore, typename T, typename... Cores, typename Kernel, std::size_t... I>
py::array run(const char* fname, const Kernel& kernel, std::array<Operand, sizeof...(Cores)>& ops,
              std::index_sequence<I...> seq) {
  constexpr std::size_t N = sizeof...(Cores);
  const py::dtype want = py::dtype::of<T>();
  for (auto& op : ops) {
    const py::dtype dt = op.arr.dtype();
    const bool native = dt.byteorder() == '=' || dt.byteorder() == '|';
    if (!(dt.kind() == 'f' && dt.itemsize() == static_cast<ssize>(sizeof(T)) && native)) {
      op.arr = py::array(op.arr.attr("astype")(want));
    } else {
      // The maps read whole T's: an unaligned view is copied (C order, aligned).
      bool aligned = reinterpret_cast<std::uintptr_t>(op.arr.data()) % alignof(T) == 0;
      for (ssize ax = 0; aligned && ax < op.arr.ndim(); ++ax)
        aligned = op.arr.strides(ax) % static_cast<ssize>(sizeof(T)) == 0;
      if (!aligned) op.arr = py::array(op.arr.attr("copy")());
    }
  }

  // The batch shape, as np.broadcast_shapes of the operands' leading axes.
  std::array<ssize, N> bnd{};
  ssize nd = 0;
  for (std::size_t j = 0; j < N; ++j) {
    bnd[j] = ops[j].arr.ndim() - ops[j].core_ndim;
    if (bnd[j] > nd) nd = bnd[j];
  }
  std::vector<ssize> shape(nd, 1);
  std::vector<int> setter(nd, -1);  // which operand fixed each axis, for the message
  for (std::size_t j = 0; j < N; ++j) {
    for (ssize a = 0; a < bnd[j]; ++a) {
      const ssize k = nd - bnd[j] + a, d = ops[j].arr.shape(a);
      if (d == 1) continue;
      if (shape[k] == 1) {
        shape[k] = d;
        setter[k] = static_cast<int>(j);
      } else if (d != shape[k]) {
        const Operand& o = ops[setter[k]];
        throw py::value_error(std::string(fname) + ": cannot broadcast the batch shapes of " + o.name + " " +
                              shape_str(o.arr.shape(), o.arr.ndim() - o.core_ndim) + " and " + ops[j].name +
                              " " + shape_str(ops[j].arr.shape(), bnd[j]) +
                              " (the leading axes, before the core shapes)");
      }
    }
  }

  std::vector<ssize> out_shape = shape;
  for (ssize d : OutCore::dims()) out_shape.push_back(d);
  py::array_t<T, py::array::c_style> out(out_shape);
  ssize count = 1;
  for (ssize d : shape) count *= d;
  if (count == 0) return std::move(out);

  Plan<N> p;
  p.shape = shape;
  for (std::size_t j = 0; j < N; ++j) {
    const py::array& a = ops[j].arr;
    p.data[j] = static_cast<const char*>(a.data());
    p.strides[j].assign(nd, 0);
    for (ssize ax = 0; ax < bnd[j]; ++ax)
      if (a.shape(ax) != 1) p.strides[j][nd - bnd[j] + ax] = a.strides(ax);
    const int c = ops[j].core_ndim;
    p.core[j] = {c >= 1 ? a.strides(a.ndim() - c) : 0, c == 2 ? a.strides(a.ndim() - 1) : 0};
  }
  coalesce(p);
  T* dst = out.mutable_data();

  auto loop = [&] { run_plan<OutCore, T, Cores...>(p, kernel, dst, seq); };
  if (count > kGilThreshold) {
    py::gil_scoped_release release;
    loop();
  } else {
    loop();
  }
  return std::move(out);
}

/// The entry point of every array function: checks and converts the
/// operands, picks float or double, broadcasts and loops. `kernel` is a
/// generic lambda taking one `view` per operand (an Eigen::Map, or a T for a
/// scalar core) and returning something assignable to `OutCore::Stored<T>`.
template <typename OutCore, typename Kernel, typename... Cores>
py::array apply(const char* fname, const Kernel& kernel, In<Cores>... ins) {
  constexpr std::size_t N = sizeof...(Cores);
  std::array<Operand, N> ops{prepare(fname, ins.name, ins.obj, Cores::ndim, Cores::dims())...};
  bool any_strong = false, all_f32 = true;
  for (const Operand& op : ops) {
    if (op.weak) continue;
    any_strong = true;
    all_f32 = all_f32 && op.kind == Kind::f32;
  }
  const auto seq = std::make_index_sequence<N>();
  if (any_strong && all_f32) return run<OutCore, float, Cores...>(fname, kernel, ops, seq);
  return run<OutCore, double, Cores...>(fname, kernel, ops, seq);
}

}  // namespace batch
}  // namespace chasles_py
