// chasles._core: the array functions as numpy generalized ufuncs.
//
// Each array function is a kernel, a generic lambda that calls the chasles
// C++ API on one element, registered with numpy as a generalized ufunc with
// a float32 and a float64 loop:
//
//   def_ufunc<Core<3, 3>(Core<3>)>(m, "so3_exp", "w", doc,
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
//
// The same mechanism registers the private gufuncs of Chain (kinematics,
// dynamics, inverse kinematics) and of the splines, with three more things:
//
// - a core dimension bound at run time: `Core<upto<32>, 6>` is "(n,6)", the
//   kernel's maps then have n rows (at most 32: its Eigen types are of
//   bounded size, no allocation); numpy checks that the operands agree on n;
// - several results: `std::tuple<Core<upto<32>>, Typed<Core<>, bool>>(...)`
//   is "...->(n),()", the kernel returns a std::tuple; `Typed` gives a core
//   its own scalar type (bool, int, uint64) in every loop;
// - a model made of the leading operands, once per loop when they stay put:
//
//   def_ufunc<Core<4, 4>(Core<upto<32>, 6>, Core<4, 4>, Core<upto<32>>), Float64>(
//       m, "_chain_forward", "screws, home, theta", doc,
//       model<2>([](const auto& S, const auto& M) { return chain_of(S, M); }),
//       [](const ChainD& c, const auto& theta) { return c.forward(JointVector(theta)); });
//
//   is (n,6),(4,4),(n)->(4,4), the chain built once for the whole batch
//   when a Chain method passes its own screws and home pose, and a float64
//   loop only (`Float64`: the chain is double).
#pragma once

#include <pybind11/pybind11.h>
#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cctype>
#include <cfenv>
#include <cstddef>
#include <limits>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include <chasles/se3.hpp>

#include "bindings.hpp"
#include "convert.hpp"
#include "numpy_capi.hpp"
#include "parallel.hpp"

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

/// A core dimension bound at run time: `upto<32>` as a dimension of a Core
/// is the dimension n of the ufunc's signature ("(n,6)"), the same for every
/// operand that has it (numpy checks that they agree), 1 <= n <= 32; the
/// kernel's Eigen types then have a run-time size and the compile-time
/// maximum 32 (no allocation). `upto<unbounded>`: no maximum (Eigen's
/// dynamic sizes; only in maps of the operands, never copied). One run-time
/// dimension per ufunc.
inline constexpr int unbounded = std::numeric_limits<int>::max();
template <int Max>
inline constexpr int upto = -Max;

namespace dims {
/// Eigen's compile-time size and maximum size of a core dimension.
constexpr int size(int d) { return d < 0 ? Eigen::Dynamic : d; }
constexpr int max(int d) { return d >= 0 ? d : d == -unbounded ? Eigen::Dynamic : -d; }
/// The largest n a dimension allows (unbounded when it is fixed).
constexpr int bound(int d) { return d < 0 ? -d : unbounded; }
/// The dimension's size when n is the run-time one.
constexpr ssize at(int d, ssize n) { return d < 0 ? n : d; }
inline std::string text(int d) { return d < 0 ? "n" : std::to_string(d); }
}  // namespace dims

/// The trailing shape of an operand or of a result: `Core<>` a scalar,
/// `Core<3>` a vector of 3, `Core<4, 4>` a 4x4 matrix, `Core<upto<32>, 6>`
/// an n x 6 matrix, n bound at run time, `Core<upto<32>, 6, 6>` n 6x6
/// matrices (an operand only: the kernel receives a Stack). `Stored<T>` is
/// the Eigen type of one element in C order, `Elem<T>` its scalar type (T,
/// the loop's, unless the core is `Typed`); `text()` its part of the ufunc
/// signature; `rows_at(n)`, `cols_at(n)` its sizes for the run-time n.
template <int... Dims>
struct Core;

template <>
struct Core<> {
  static constexpr int ndim = 0, rows = 1, cols = 1, bound = unbounded;
  static constexpr bool runtime = false;
  template <typename T>
  using Elem = T;
  template <typename T>
  using Stored = T;
  static constexpr ssize rows_at(ssize) { return 1; }
  static constexpr ssize cols_at(ssize) { return 1; }
  static std::string text() { return "()"; }
};

template <int N>
struct Core<N> {
  static constexpr int ndim = 1, rows = dims::size(N), cols = 1, bound = dims::bound(N);
  static constexpr bool runtime = N < 0;
  template <typename T>
  using Elem = T;
  template <typename T>
  using Stored = Eigen::Matrix<T, dims::size(N), 1, Eigen::ColMajor, dims::max(N), 1>;
  static constexpr ssize rows_at(ssize n) { return dims::at(N, n); }
  static constexpr ssize cols_at(ssize) { return 1; }
  static std::string text() { return "(" + dims::text(N) + ")"; }
};

template <int R, int C>
struct Core<R, C> {
  static constexpr int ndim = 2, rows = dims::size(R), cols = dims::size(C);
  static constexpr int bound = dims::bound(R) < dims::bound(C) ? dims::bound(R) : dims::bound(C);
  static constexpr bool runtime = R < 0 || C < 0;
  template <typename T>
  using Elem = T;
  template <typename T>
  using Stored = Eigen::Matrix<T, dims::size(R), dims::size(C), Eigen::RowMajor, dims::max(R), dims::max(C)>;
  static constexpr ssize rows_at(ssize n) { return dims::at(R, n); }
  static constexpr ssize cols_at(ssize n) { return dims::at(C, n); }
  static std::string text() { return "(" + dims::text(R) + "," + dims::text(C) + ")"; }
};

template <typename E, typename C>
struct Stack;

template <int A, int R, int C>
struct Core<A, R, C> {
  static_assert(R > 0 && C > 0, "in a stack of matrices only the count is bound at run time");
  static constexpr int ndim = 3, rows = R, cols = C, bound = dims::bound(A);
  static constexpr bool runtime = A < 0;
  template <typename T>
  using Elem = T;
  template <typename T>
  using Stored = Stack<T, Core>;
  static constexpr ssize count_at(ssize n) { return dims::at(A, n); }
  static constexpr ssize rows_at(ssize) { return R; }
  static constexpr ssize cols_at(ssize) { return C; }
  static std::string text() { return "(" + dims::text(A) + "," + std::to_string(R) + "," + std::to_string(C) + ")"; }
};

/// A core of another scalar type than the loop's: `Typed<Core<>, bool>` a
/// bool (NPY_BOOL) in every loop, `Typed<Core<>, int>` a C int.
template <typename C, typename E>
struct Typed : C {
  template <typename T>
  using Elem = E;
};

/// Byte strides of one operand's core axes (unused entries 0).
using CoreStrides = std::array<ssize, 3>;

/// What a kernel receives for a core of 3 dimensions: `size()` matrices,
/// `s[i]` an Eigen::Map of the i-th (R x C, row-major) with its strides.
template <typename E, typename C>
struct Stack {
  using Matrix = Eigen::Matrix<E, C::rows, C::cols, Eigen::RowMajor>;
  using Strides = Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>;
  const char* data;
  CoreStrides strides;
  ssize count;

  ssize size() const noexcept { return count; }
  Eigen::Map<const Matrix, Eigen::Unaligned, Strides> operator[](ssize i) const noexcept {
    constexpr ssize t = sizeof(E);
    return Eigen::Map<const Matrix, Eigen::Unaligned, Strides>(reinterpret_cast<const E*>(data + i * strides[0]),
                                                               Strides(strides[1] / t, strides[2] / t));
  }
};

/// Whether byte strides s are those of a C-contiguous core of T (n the
/// run-time dimension).
template <typename C, typename T>
inline bool is_contiguous(const CoreStrides& s, ssize n) noexcept {
  constexpr ssize t = sizeof(typename C::template Elem<T>);
  if constexpr (C::ndim == 0) return true;
  if constexpr (C::ndim == 1) return s[0] == t;
  if constexpr (C::ndim == 2) return s[0] == C::cols_at(n) * t && s[1] == t;
  return s[0] == C::rows * C::cols * t && s[1] == C::cols * t && s[2] == t;
}

// ---- element access ---------------------------------------------------------

/// What the kernel receives for the element at p: a T for a scalar core,
/// otherwise an Eigen::Map of the operand's memory with the core strides s
/// (bytes, multiples of sizeof(T): numpy hands legacy loops aligned data),
/// or with constant offsets if `Contiguous` (a Stack for 3 dimensions). n
/// is the run-time dimension. The kernel converts it to the chasles
/// argument type with Eigen's own assignment: reading the elements one by
/// one into a local matrix instead made the kernels' vector loads wait on
/// the scalar stores (a store-forwarding stall: so3_compose 26 ns instead
/// of 6).
template <typename C, typename T0, bool Contiguous>
inline auto view(const char* p, const CoreStrides& s, [[maybe_unused]] ssize n) noexcept {
  using T = typename C::template Elem<T0>;
  using M = typename C::template Stored<T>;
  const T* d = reinterpret_cast<const T*>(p);
  constexpr ssize t = sizeof(T);
  if constexpr (C::ndim == 0) {
    return *d;
  } else if constexpr (C::ndim == 3) {
    return M{p, s, C::count_at(n)};
  } else if constexpr (Contiguous) {
    if constexpr (C::runtime)
      return Eigen::Map<const M>(d, C::rows_at(n), C::cols_at(n));
    else
      return Eigen::Map<const M>(d);
  } else if constexpr (C::ndim == 1) {
    using Inner = Eigen::InnerStride<Eigen::Dynamic>;
    if constexpr (C::runtime)
      return Eigen::Map<const M, Eigen::Unaligned, Inner>(d, n, Inner(s[0] / t));
    else
      return Eigen::Map<const M, Eigen::Unaligned, Inner>(d, Inner(s[0] / t));
  } else {
    using Strides = Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>;
    if constexpr (C::runtime)
      return Eigen::Map<const M, Eigen::Unaligned, Strides>(d, C::rows_at(n), C::cols_at(n),
                                                            Strides(s[0] / t, s[1] / t));
    else
      return Eigen::Map<const M, Eigen::Unaligned, Strides>(d, Strides(s[0] / t, s[1] / t));
  }
}

/// An operand that stays put along the loop, as the loop holds it: a local
/// copy of a fixed-size core (kept in registers), the view itself for a
/// core bound at run time.
template <typename C, typename T, bool Contiguous>
inline auto hold(const char* p, const CoreStrides& s, ssize n) noexcept {
  if constexpr (C::runtime || C::ndim == 3)
    return view<C, T, Contiguous>(p, s, n);
  else
    return typename C::template Stored<typename C::template Elem<T>>(view<C, T, Contiguous>(p, s, n));
}

template <typename V>
struct IsSE3 : std::false_type {};
template <typename S>
struct IsSE3<chasles::SE3<S>> : std::true_type {};

/// Writes one core element at o, with the core strides s unless
/// `Contiguous` (n the run-time dimension). A kernel may return an SE3 for
/// a 4x4 core: its rotation and translation are written in place, rather
/// than through SE3::matrix()'s 4x4 temporary, whose vector reloads wait on
/// its scalar stores (se3_exp 53.5 -> 48.7 ns per element at N = 1e5).
template <typename C, typename T0, bool Contiguous, typename V>
inline void store(const V& v, char* o, const CoreStrides& s, [[maybe_unused]] ssize n) noexcept {
  using T = typename C::template Elem<T0>;
  using M = typename C::template Stored<T>;
  static_assert(C::ndim < 3, "a result has at most 2 core dimensions");
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
    if constexpr (C::runtime) {
      Eigen::Map<M> m(reinterpret_cast<T*>(o), C::rows_at(n), C::cols_at(n));
      m = v;
    } else {
      Eigen::Map<M> m(reinterpret_cast<T*>(o));
      m = v;
    }
  } else if constexpr (C::ndim == 1) {
    using Inner = Eigen::InnerStride<Eigen::Dynamic>;
    if constexpr (C::runtime) {
      Eigen::Map<M, Eigen::Unaligned, Inner> m(reinterpret_cast<T*>(o), n, Inner(s[0] / t));
      m = v;
    } else {
      Eigen::Map<M, Eigen::Unaligned, Inner> m(reinterpret_cast<T*>(o), Inner(s[0] / t));
      m = v;
    }
  } else {
    using Strides = Eigen::Stride<Eigen::Dynamic, Eigen::Dynamic>;
    if constexpr (C::runtime) {
      Eigen::Map<M, Eigen::Unaligned, Strides> m(reinterpret_cast<T*>(o), C::rows_at(n), C::cols_at(n),
                                                 Strides(s[0] / t, s[1] / t));
      m = v;
    } else {
      Eigen::Map<M, Eigen::Unaligned, Strides> m(reinterpret_cast<T*>(o), Strides(s[0] / t, s[1] / t));
      m = v;
    }
  }
}

/// Fills one result element with NaN (zero for an integer or bool core):
/// what a ufunc gives when the run-time dimension is out of its bounds.
template <typename C, typename T0>
inline void store_invalid(char* o, const CoreStrides& s, ssize n) noexcept {
  using T = typename C::template Elem<T0>;
  const T x = std::numeric_limits<T>::has_quiet_NaN ? std::numeric_limits<T>::quiet_NaN() : T(0);
  const ssize rows = C::rows_at(n), cols = C::cols_at(n);
  for (ssize i = 0; i < rows; ++i)
    for (ssize j = 0; j < cols; ++j) *reinterpret_cast<T*>(o + i * s[0] + j * s[1]) = x;
}

// ---- the signature ----------------------------------------------------------

template <typename Signature>
struct Parts;

/// `Out(In...)` or `std::tuple<Out...>(In...)`: the core shapes of the
/// operands and of the results.
template <typename... Outs, typename... Ins>
struct Parts<std::tuple<Outs...>(Ins...)> {
  static constexpr std::size_t nin = sizeof...(Ins), nout = sizeof...(Outs), nops = nin + nout;
  using Cores = std::tuple<Ins..., Outs...>;
  template <std::size_t J>
  using At = std::tuple_element_t<J, Cores>;
  static constexpr int ndims[] = {Ins::ndim..., Outs::ndim...};
  static constexpr bool runtime = (Ins::runtime || ...) || (Outs::runtime || ...);
  /// The largest run-time n every core allows.
  static constexpr int bound() {
    int b = unbounded;
    for (const int c : {Ins::bound..., Outs::bound...}) b = c < b ? c : b;
    return b;
  }

  /// The ufunc's core signature: "(3),(3,3)->(3)", "(n,6),(n)->(6,n),()".
  static std::string signature() {
    std::string in, out;
    ((in += (in.empty() ? "" : ",") + Ins::text()), ...);
    ((out += (out.empty() ? "" : ",") + Outs::text()), ...);
    return in + "->" + out;
  }
};

template <typename Out, typename... Ins>
struct Parts<Out(Ins...)> : Parts<std::tuple<Out>(Ins...)> {};

/// The position of n among the signature's distinct dimension names, in
/// the order of their first appearance (numpy's order of the core sizes
/// it passes the loop after the outer size); -1 without one.
inline int runtime_dimension_index(const std::string& signature) {
  std::vector<std::string> names;
  std::string name;
  for (const char ch : signature + ",") {
    if (std::isalnum(static_cast<unsigned char>(ch))) {
      name += ch;
    } else if (!name.empty()) {
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
      name.clear();
    }
  }
  const auto it = std::find(names.begin(), names.end(), "n");
  return it == names.end() ? -1 : static_cast<int>(it - names.begin());
}

// ---- the loop ---------------------------------------------------------------

template <typename P>
using Steps = std::array<CoreStrides, P::nops>;

/// Writes the kernel's results r (one value, or a std::tuple of one per
/// result) for element i.
template <typename P, typename T, bool Contiguous, typename R, std::size_t... K>
inline void store_results(const R& r, char** args, ssize i, const ssize* steps, const Steps<P>& core, ssize n,
                          std::index_sequence<K...>) noexcept {
  constexpr std::size_t N = P::nin;
  if constexpr (P::nout == 1)
    store<typename P::template At<N>, T, Contiguous>(r, args[N] + i * steps[N], core[N], n);
  else
    (store<typename P::template At<N + K>, T, Contiguous>(std::get<K>(r), args[N + K] + i * steps[N + K], core[N + K],
                                                          n),
     ...);
}

/// The inner loop over `count` elements. `Contiguous`: every core (operands
/// and results) is C-contiguous, compiled with constant offsets. `Fixed` <
/// nin: that operand does not move along the loop; it is read once into a
/// local matrix, which the compiler can keep in registers and whose
/// conversions it can hoist out of the loop (it cannot for a map of input
/// memory, which the output stores might alias).
template <typename P, typename T, bool Contiguous, std::size_t Fixed, typename Kernel, std::size_t... I>
CHASLES_PY_FLATTEN void run(char** args, ssize count, const ssize* steps, const Steps<P>& core, ssize n,
                            const Kernel& kernel, std::index_sequence<I...>) noexcept {
  constexpr std::size_t N = P::nin;
  const auto outs = std::make_index_sequence<P::nout>();
  if constexpr (Fixed < N) {
    using C = typename P::template At<Fixed>;
    const auto fixed = hold<C, T, Contiguous>(args[Fixed], core[Fixed], n);
    auto arg = [&](auto j, ssize i) -> decltype(auto) {
      constexpr std::size_t J = decltype(j)::value;
      if constexpr (J == Fixed)
        return (fixed);
      else
        return view<typename P::template At<J>, T, Contiguous>(args[J] + i * steps[J], core[J], n);
    };
    for (ssize i = 0; i < count; ++i)
      store_results<P, T, Contiguous>(kernel(arg(std::integral_constant<std::size_t, I>(), i)...), args, i, steps, core,
                                      n, outs);
  } else {
    for (ssize i = 0; i < count; ++i)
      store_results<P, T, Contiguous>(
          kernel(view<typename P::template At<I>, T, Contiguous>(args[I] + i * steps[I], core[I], n)...), args, i,
          steps, core, n, outs);
  }
}

/// run() for the layout of this call: contiguous cores or not, which
/// operand stays put (the first non-scalar one with an outer stride of 0).
template <typename P, typename T, typename Kernel, std::size_t... I, std::size_t... O>
void dispatch(char** args, ssize count, const ssize* steps, const Steps<P>& core, ssize n, const Kernel& kernel,
              std::index_sequence<I...> seq, std::index_sequence<O...>) noexcept {
  constexpr std::size_t N = P::nin;
  const bool contiguous = (is_contiguous<typename P::template At<I>, T>(core[I], n) && ...) &&
                          (is_contiguous<typename P::template At<N + O>, T>(core[N + O], n) && ...);
  std::size_t fixed = N;
  if (count > 1) {
    for (std::size_t j = N; j-- > 0;)
      if (P::ndims[j] > 0 && steps[j] == 0) fixed = j;
  }
  auto with = [&](auto fixed_c) {
    constexpr std::size_t F = decltype(fixed_c)::value;
    if (contiguous)
      run<P, T, true, F>(args, count, steps, core, n, kernel, seq);
    else
      run<P, T, false, F>(args, count, steps, core, n, kernel, seq);
  };
  // only an operand with core axes can be held (no instantiation for the scalar ones)
  auto held = [&](auto i) {
    constexpr std::size_t F = decltype(i)::value;
    if constexpr (P::template At<F>::ndim > 0) {
      if (fixed == F) return with(i), true;
    }
    return false;
  };
  if (!(held(std::integral_constant<std::size_t, I>()) || ...)) with(std::integral_constant<std::size_t, N>());
}

/// Every result of `count` elements invalid (store_invalid).
template <typename P, typename T, std::size_t... O>
void store_invalid_results(char** args, ssize count, const ssize* steps, const Steps<P>& core, ssize n,
                           std::index_sequence<O...>) noexcept {
  constexpr std::size_t N = P::nin;
  for (ssize i = 0; i < count; ++i)
    (store_invalid<typename P::template At<N + O>, T>(args[N + O] + i * steps[N + O], core[N + O], n), ...);
}

/// `cases<N, S>(kernel)`: operand S, an int in [0, N), picks the case
/// `kernel(std::integral_constant<int, C>(), operands...)` (an Euler
/// sequence). The case is read once per run of equal values, so a case
/// given as one scalar (stride 0) costs nothing per element; a case
/// outside [0, N) gives invalid results (NaN).
template <int N, std::size_t S, typename Kernel>
struct Cases : Kernel {
  using Sequence = std::make_integer_sequence<int, N>;
};
template <int N, std::size_t S, typename Kernel>
Cases<N, S, Kernel> cases(Kernel kernel) {
  return {kernel};
}
template <typename K>
struct IsCases : std::false_type {};
template <int N, std::size_t S, typename Kernel>
struct IsCases<Cases<N, S, Kernel>> : std::true_type {};

template <typename P, typename T, int N, std::size_t S, typename Kernel, int... C>
void dispatch_cases(char** args, ssize count, const ssize* steps, const Steps<P>& core, ssize n,
                    const Cases<N, S, Kernel>& k, std::integer_sequence<int, C...>) noexcept {
  const auto case_at = [&](ssize i) { return *reinterpret_cast<const int*>(args[S] + i * steps[S]); };
  for (ssize i = 0, j; i < count; i = j) {
    const int c = case_at(i);
    for (j = i + 1; j < count && (steps[S] == 0 || case_at(j) == c);) j = steps[S] == 0 ? count : j + 1;
    std::array<char*, P::nops> at;
    for (std::size_t q = 0; q < P::nops; ++q) at[q] = args[q] + i * steps[q];
    const auto with = [&](auto c_) {
      const auto kernel = [f = static_cast<const Kernel&>(k), c_](const auto&... a) { return f(c_, a...); };
      dispatch<P, T>(at.data(), j - i, steps, core, n, kernel, std::make_index_sequence<P::nin>(),
                     std::make_index_sequence<P::nout>());
      return true;
    };
    if (!((c == C && with(std::integral_constant<int, C>())) || ...))
      store_invalid_results<P, T>(at.data(), j - i, steps, core, n, std::make_index_sequence<P::nout>());
  }
}

/// `strided(kernel)`: one loop over strided maps, whatever the layout, for
/// a kernel whose own work dwarfs what the layout's instantiations save
/// (a Gaussian's propagation: hundreds of flops per element). Those are
/// 2 (nin + 1) copies of the inlined kernel per loop: for the Gaussians'
/// gufuncs (bind_gaussian.cpp) they took the file's compile time from
/// 60 s to 300 s.
template <typename Kernel>
struct Strided : Kernel {};
template <typename Kernel>
Strided<Kernel> strided(Kernel kernel) {
  return {kernel};
}
template <typename K>
struct IsStrided : std::false_type {};
template <typename Kernel>
struct IsStrided<Strided<Kernel>> : std::true_type {};

/// The loop of a ufunc with a model (see def_ufunc): the model is made from
/// the first K operands once per loop when they stay put (outer strides 0,
/// as when a Chain method passes its own screws), else once per element;
/// the kernel receives it and the other operands, as strided maps.
template <typename P, typename T, typename Make, typename Kernel, std::size_t... M, std::size_t... I>
CHASLES_PY_FLATTEN void run_model(char** args, ssize count, const ssize* steps, const Steps<P>& core, ssize n,
                                  const Make& make, const Kernel& kernel, std::index_sequence<M...>,
                                  std::index_sequence<I...>) noexcept {
  if (count < 1) return;
  const auto outs = std::make_index_sequence<P::nout>();
  const auto model_at = [&](ssize i) {
    return make(view<typename P::template At<M>, T, false>(args[M] + i * steps[M], core[M], n)...);
  };
  const auto element = [&](const auto& model, ssize i) {
    store_results<P, T, false>(
        kernel(model, view<typename P::template At<I>, T, false>(args[I] + i * steps[I], core[I], n)...), args, i,
        steps, core, n, outs);
  };
  if (count <= 1 || ((steps[M] == 0) && ...)) {
    const auto model = model_at(0);
    for (ssize i = 0; i < count; ++i) element(model, i);
  } else {
    for (ssize i = 0; i < count; ++i) element(model_at(i), i);
  }
}

/// numpy turns the floating-point flags a loop leaves into RuntimeWarnings
/// ("overflow encountered in so3_exp"). The kernels raise them on purpose
/// and handle the outcome: a comparison with a NaN input, a square that
/// overflows in a finiteness check, a scaled path for huge inputs. What the
/// user sees is the result, never NaN or inf for a finite input (the C++
/// test_finite and fuzz properties), NaN in the element of a NaN input: so
/// the loops leave no flags.
inline void clear_floating_point_flags() noexcept { std::feclearexcept(FE_ALL_EXCEPT); }

/// A kernel without a model.
struct NoModel {};

/// `model<K>(make)`: the first K operands make a model (a chain from its
/// screws and home pose) that the kernel receives first.
template <std::size_t K, typename Make>
struct Model {
  static constexpr std::size_t size = K;
  Make make;
};
template <std::size_t K, typename Make>
Model<K, Make> model(Make make) {
  return {make};
}

/// What a ufunc's loops point to: the kernel, the model's maker, and where
/// numpy passes n.
template <typename ModelT, typename Kernel>
struct Entry {
  using ModelType = ModelT;
  using KernelType = Kernel;
  ModelT model;
  Kernel kernel;
  int n_index;
};

/// I + Offset...
template <std::size_t Offset, std::size_t... I>
constexpr std::index_sequence<Offset + I...> shifted(std::index_sequence<I...>) {
  return {};
}

/// The numpy loop (PyUFuncGenericFunction) of a kernel for T: reads the
/// core strides numpy passes after the outer ones and n, and runs the
/// layout's instantiation, split across threads for a large batch
/// (parallel.hpp). `data` points to the Entry. An n outside
/// [1, the cores' maximum] gives NaN results (the kernels never see it;
/// the callers check n first, with a message).
template <typename P, typename T, typename E>
void loop(char** args, const ssize* dims, const ssize* steps, void* data) noexcept {
  constexpr std::size_t N = P::nin;
  const E& entry = *static_cast<const E*>(data);
  Steps<P> core{};
  const ssize* s = steps + P::nops;  // numpy: the outer strides, then each operand's core strides in order
  for (std::size_t j = 0; j < P::nops; ++j)
    for (int k = 0; k < P::ndims[j]; ++k) core[j][static_cast<std::size_t>(k)] = *s++;
  ssize n = 0;
  if constexpr (P::runtime) {
    n = dims[1 + entry.n_index];
    if (n < 1 || n > P::bound()) {
      store_invalid_results<P, T>(args, dims[0], steps, core, n, std::make_index_sequence<P::nout>());
      return;
    }
  }
  constexpr bool with_model = !std::is_same_v<typename E::ModelType, NoModel>;
  constexpr ssize grain = with_model ? parallel::model_grain : parallel::elementwise_grain;
  // The elements [begin, end) (parallel.hpp: on one thread or several).
  parallel::for_ranges(dims[0], grain, [&](ssize begin, ssize end) {
    std::array<char*, P::nops> at;
    for (std::size_t j = 0; j < P::nops; ++j) at[j] = args[j] + begin * steps[j];
    if constexpr (with_model) {
      constexpr std::size_t K = E::ModelType::size;
      run_model<P, T>(at.data(), end - begin, steps, core, n, entry.model.make, entry.kernel,
                      std::make_index_sequence<K>(), shifted<K>(std::make_index_sequence<N - K>()));
    } else if constexpr (IsStrided<typename E::KernelType>::value) {
      // run()'s strided layout with no operand held (Fixed = N), the one instantiation
      run<P, T, false, N>(at.data(), end - begin, steps, core, n, entry.kernel, std::make_index_sequence<N>());
    } else if constexpr (IsCases<typename E::KernelType>::value) {
      dispatch_cases<P, T>(at.data(), end - begin, steps, core, n, entry.kernel, typename E::KernelType::Sequence());
    } else {
      dispatch<P, T>(at.data(), end - begin, steps, core, n, entry.kernel, std::make_index_sequence<N>(),
                     std::make_index_sequence<P::nout>());
    }
  });
  clear_floating_point_flags();
}

// ---- registration -----------------------------------------------------------

/// The real type of a kernel argument: an Eigen matrix's or map's Scalar, or
/// the argument's own type (a `Core<>` scalar).
template <typename V, typename = void>
struct ScalarOfArgument {
  using type = V;
};
template <typename V>
struct ScalarOfArgument<V, std::void_t<typename V::Scalar>> {
  using type = typename V::Scalar;
};
template <typename V>
using ScalarOf = typename ScalarOfArgument<std::decay_t<V>>::type;

/// An array function's docstring: `body`, then the paragraph every one ends
/// with (the rules themselves are stated once, in the module's docstring).
inline std::string array_doc(const char* body) {
  return std::string(body) + R"(

A numpy generalized ufunc: numpy's rules for broadcasting, dtypes
(float32 and float64 kernels), out= and axes= apply (``help(chasles)``).
Matrices are taken as given, like the C++ unchecked constructors, and a NaN
gives NaN in its own element only.)";
}

/// The loops a ufunc has: `Loops<float, double>` (the default; in that
/// order), `Loops<double>` for a kernel over float64 types only.
template <typename... Ts>
struct Loops {};
using Float64 = Loops<double>;

/// numpy's type number of a core's scalar type.
template <typename E>
constexpr char type_number() {
  if constexpr (std::is_same_v<E, float>)
    return NPY_FLOAT;
  else if constexpr (std::is_same_v<E, double>)
    return NPY_DOUBLE;
  else if constexpr (std::is_same_v<E, bool>)
    return NPY_BOOL;
  else if constexpr (std::is_same_v<E, int>)
    return NPY_INT;
  else {
    static_assert(std::is_same_v<E, npy_uint64>, "a core of float, double, bool, int or npy_uint64");
    return NPY_UINT64;
  }
}

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

/// The type numbers of a loop over T, one per core, at types + k.
template <typename T, typename... Cores>
void put_types(char* types, std::size_t& k, std::tuple<Cores...>*) {
  ((types[k++] = type_number<typename Cores::template Elem<T>>()), ...);
}

/// Registers the loops of Entry e for the types of `L` as the generalized
/// ufunc `name` of module m (see def_ufunc).
template <typename Signature, typename E, typename... Ts>
py::object register_ufunc(py::module_& m, const char* name, const char* params, const std::string& doc, const E& e,
                          Loops<Ts...>) {
  using P = Parts<Signature>;
  static const E stored = e;
  static PyUFuncGenericFunction funcs[] = {&loop<P, Ts, E>...};
  static void* data[] = {(static_cast<void>(sizeof(Ts)), const_cast<E*>(&stored))...};
  static char types[sizeof...(Ts) * P::nops];
  std::size_t k = 0;
  (put_types<Ts>(types, k, static_cast<typename P::Cores*>(nullptr)), ...);
  static const std::string doc_kept = doc;  // numpy keeps the pointer
  const std::string sig = P::signature();
  PyObject* u = PyUFunc_FromFuncAndDataAndSignature(funcs, data, types, static_cast<int>(sizeof...(Ts)),
                                                    static_cast<int>(P::nin), static_cast<int>(P::nout), PyUFunc_None,
                                                    name, doc_kept.c_str(), 0, sig.c_str());
  if (u == nullptr) throw py::error_already_set();
  py::object ufunc = py::reinterpret_steal<py::object>(u);
  describe_ufunc(ufunc, name, params, doc);
  m.attr(name) = ufunc;
  array_functions()[name] = ufunc.inc_ref().ptr();
  return ufunc;
}

/// Registers `kernel` as the generalized ufunc `name` of module m with the
/// core signature of `Signature` (`Core<3, 3>(Core<3>)` is (3)->(3,3);
/// `std::tuple<Core<3>, Core<>>(Core<upto<32>>)` is (n)->(3),() and the
/// kernel returns a std::tuple of the two) and the loops of `L`, by default
/// a float32 and a float64 loop, in that order: numpy takes the first loop
/// to which the operands cast safely, so float16 and small integers run in
/// float32, int32, int64 and float64 in float64, mixed float32 and float64
/// in float64. `params` names the operands ("a, b"), `doc` is the docstring
/// after the signature line. Each kernel type is registered once (its loops
/// and data live in statics of this instantiation, as numpy requires).
template <typename Signature, typename L = Loops<float, double>, typename Kernel>
py::object def_ufunc(py::module_& m, const char* name, const char* params, const std::string& doc, Kernel kernel) {
  static_assert(std::is_empty_v<Kernel>, "a ufunc kernel captures nothing: it runs without the GIL, on any thread");
  const int n_index = runtime_dimension_index(Parts<Signature>::signature());
  return register_ufunc<Signature>(m, name, params, doc, Entry<NoModel, Kernel>{NoModel(), kernel, n_index}, L());
}

/// def_ufunc with a model: `model<K>(make)` makes, from the first K
/// operands, what the kernel receives first (once per loop when they stay
/// put), the kernel the other operands after it:
///
///   def_ufunc<Core<4, 4>(Core<upto<32>, 6>, Core<4, 4>, Core<upto<32>>), Float64>(
///       m, "_chain_forward", "screws, home, theta", doc,
///       model<2>([](const auto& S, const auto& M) { return chain_of(S, M); }),
///       [](const ChainD& c, const auto& theta) { return c.forward(JointVector(theta)); });
///
/// is (n,6),(4,4),(n)->(4,4) with n <= 32 (NaN results beyond).
template <typename Signature, typename L = Loops<float, double>, std::size_t K, typename Make, typename Kernel>
py::object def_ufunc(py::module_& m, const char* name, const char* params, const std::string& doc, Model<K, Make> made,
                     Kernel kernel) {
  static_assert(std::is_empty_v<Kernel> && std::is_empty_v<Make>,
                "a ufunc kernel captures nothing: it runs without the GIL, on any thread");
  static_assert(K <= Parts<Signature>::nin, "the model is made of operands");
  const int n_index = runtime_dimension_index(Parts<Signature>::signature());
  return register_ufunc<Signature>(m, name, params, doc, Entry<Model<K, Make>, Kernel>{made, kernel, n_index}, L());
}

}  // namespace ufunc
}  // namespace chasles_py
