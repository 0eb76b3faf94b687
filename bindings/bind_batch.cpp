// chasles._core: array functions over batches (so3_*, se3_*, twist_*).
//
// Each function is its kernel, a generic lambda that calls the chasles C++
// API on one element, handed to the broadcasting loop of broadcast.hpp with
// the core shapes of its operands and of its result. No mathematics here.
#include <limits>
#include <string>
#include <type_traits>

#include <chasles/se3.hpp>
#include <chasles/so3.hpp>
#include <chasles/twist.hpp>
#include <chasles/wrench.hpp>

#include "bindings.hpp"
#include "broadcast.hpp"

namespace chasles_py {

namespace {

using batch::apply;
using batch::Core;
using batch::in;

/// The real type of a kernel argument (Eigen::Matrix<T, ...>).
template <typename V>
using ScalarOf = typename std::decay_t<V>::Scalar;

template <typename T>
using SO3 = chasles::SO3<T>;
template <typename T>
using SE3 = chasles::SE3<T>;

/// The Raises and Note sections shared by every array function.
const char* const kBatchRules = R"(

Raises:
    TypeError: an operand's dtype is not float32, float64, integer or bool
        (float16, long double, complex, object, string and datetime arrays
        are refused: there is no kernel in those types, and a silent
        conversion would change the precision).
    ValueError: an operand's trailing (core) shape is wrong, the leading
        (batch) shapes of the operands do not broadcast, or numpy cannot
        make an array of an operand (a ragged nested list).
    MemoryError: the result does not fit in memory (as numpy's own).

Note:
    Batch rules, shared by every chasles array function:

    * The leading axes broadcast together as in numpy (np.broadcast_shapes,
      as np.linalg does); the trailing core shapes are fixed. Zero-length
      batch axes give an empty result of the right shape.
    * dtype: float32 operands give a float32 result, computed by the float
      C++ kernels; any float64 operand makes the call float64; integer and
      bool arrays are converted to float64. Python int and float scalars do
      not change the result type.
    * Operands are read in place through their strides (slices, transposes,
      Fortran order and read-only arrays need no copy); the result is a
      fresh C-contiguous array. The GIL is released during the loop.
    * Inputs are taken as given, like the C++ unchecked constructors:
      matrices are not checked for being rotations or rigid motions (the
      bottom row of a 4x4 pose is not read), and a NaN gives NaN in its
      own element only, never an exception.)";

std::string doc(const char* body) { return std::string(body) + kBatchRules; }

// ---- SO(3) ------------------------------------------------------------------

void bind_so3_batch(py::module_& m) {
  m.def(
      "so3_exp",
      [](py::handle w) {
        return apply<Core<3, 3>>(
            "so3_exp", [](const auto& w) { return SO3<ScalarOf<decltype(w)>>::exp(w).matrix(); },
            in<Core<3>>("w", w));
      },
      py::arg("w"),
      doc(R"(Rotation matrices of rotation vectors: R = exp([w]).

Rodrigues' formula, R = I + (sin t / t) [w] + ((1 - cos t) / t^2) [w]^2 with
t = |w|, exact to a few ulps for every w (Taylor series near 0).

Args:
    w: array_like of shape (..., 3): rotation vectors, axis times angle in
        radians.

Returns:
    numpy.ndarray of shape (..., 3, 3): the rotation matrices.)")
          .c_str());

  m.def(
      "so3_log",
      [](py::handle R) {
        return apply<Core<3>>(
            "so3_log",
            [](const auto& R) { return SO3<ScalarOf<decltype(R)>>::from_matrix_unchecked(R).log(); },
            in<Core<3, 3>>("R", R));
      },
      py::arg("R"),
      doc(R"(Rotation vectors of rotation matrices: w = log(R)^vee.

The angle |w| is in [0, pi]; at exactly pi either axis sign is returned,
never NaN. Robust near 0 and near pi, and as accurate for a matrix slightly
off SO(3) as projecting it first.

Args:
    R: array_like of shape (..., 3, 3): rotation matrices.

Returns:
    numpy.ndarray of shape (..., 3): the rotation vectors (axis times angle).)")
          .c_str());

  m.def(
      "so3_compose",
      [](py::handle a, py::handle b) {
        return apply<Core<3, 3>>(
            "so3_compose",
            [](const auto& a, const auto& b) {
              using T = ScalarOf<decltype(a)>;
              return (SO3<T>::from_matrix_unchecked(a) * SO3<T>::from_matrix_unchecked(b)).matrix();
            },
            in<Core<3, 3>>("a", a), in<Core<3, 3>>("b", b));
      },
      py::arg("a"), py::arg("b"),
      doc(R"(Composition of rotations: a @ b (R_ac = R_ab R_bc).

Args:
    a: array_like of shape (..., 3, 3): rotation matrices.
    b: array_like of shape (..., 3, 3): rotation matrices.

Returns:
    numpy.ndarray of shape (..., 3, 3): the products, the batch shape being
    the broadcast of a's and b's.)")
          .c_str());

  m.def(
      "so3_inverse",
      [](py::handle R) {
        return apply<Core<3, 3>>(
            "so3_inverse",
            [](const auto& R) { return SO3<ScalarOf<decltype(R)>>::from_matrix_unchecked(R).inverse().matrix(); },
            in<Core<3, 3>>("R", R));
      },
      py::arg("R"),
      doc(R"(Inverse rotations: R^-1 = R^T.

Args:
    R: array_like of shape (..., 3, 3): rotation matrices.

Returns:
    numpy.ndarray of shape (..., 3, 3): the inverses.)")
          .c_str());

  m.def(
      "so3_act",
      [](py::handle R, py::handle p) {
        return apply<Core<3>>(
            "so3_act",
            [](const auto& R, const auto& p) {
              return SO3<ScalarOf<decltype(R)>>::from_matrix_unchecked(R).act(p);
            },
            in<Core<3, 3>>("R", R), in<Core<3>>("p", p));
      },
      py::arg("R"), py::arg("p"),
      doc(R"(Rotated points or vectors: p_a = R_ab p_b.

Broadcasts: one rotation of shape (3, 3) with points of shape (N, 3), N
rotations with N points, (N, 1, 3, 3) with (M, 3) for every pair, ...

Args:
    R: array_like of shape (..., 3, 3): rotation matrices.
    p: array_like of shape (..., 3): points or vectors.

Returns:
    numpy.ndarray of shape (..., 3): the rotated points.)")
          .c_str());

  m.def(
      "so3_hat",
      [](py::handle w) {
        return apply<Core<3, 3>>(
            "so3_hat", [](const auto& w) { return SO3<ScalarOf<decltype(w)>>::hat(w); }, in<Core<3>>("w", w));
      },
      py::arg("w"),
      doc(R"(Skew-symmetric matrices: [w] = [[0, -w3, w2], [w3, 0, -w1], [-w2, w1, 0]].

So that [w] p = w x p.

Args:
    w: array_like of shape (..., 3): vectors of so(3).

Returns:
    numpy.ndarray of shape (..., 3, 3): the matrices [w].)")
          .c_str());

  m.def(
      "so3_vee",
      [](py::handle W) {
        return apply<Core<3>>(
            "so3_vee", [](const auto& W) { return SO3<ScalarOf<decltype(W)>>::vee(W); }, in<Core<3, 3>>("W", W));
      },
      py::arg("W"),
      doc(R"(The vectors of skew-symmetric matrices: vee([w]) = w.

Reads the antisymmetric part (W - W^T) / 2, so a matrix that is not exactly
skew gives the w of its nearest skew matrix.

Args:
    W: array_like of shape (..., 3, 3): skew-symmetric matrices.

Returns:
    numpy.ndarray of shape (..., 3): the vectors w.)")
          .c_str());

  m.def(
      "so3_from_quat",
      [](py::handle q, bool scalar_first) {
        return apply<Core<3, 3>>(
            "so3_from_quat",
            [scalar_first](const auto& q) {
              using T = ScalarOf<decltype(q)>;
              Eigen::Matrix<T, 3, 3> R;
              if (!q.allFinite() || !(q.squaredNorm() > T(0))) {
                // No rotation: NaN, as numpy's 0/0 (the C++ API gives the identity).
                R.setConstant(std::numeric_limits<T>::quiet_NaN());
              } else {
                const Eigen::Quaternion<T> e =
                    scalar_first ? Eigen::Quaternion<T>(q[0], q[1], q[2], q[3]) : Eigen::Quaternion<T>(q[3], q[0], q[1], q[2]);
                R = SO3<T>::from_quaternion(e).matrix();
              }
              return R;
            },
            in<Core<4>>("q", q));
      },
      py::arg("q"), py::kw_only(), py::arg("scalar_first") = false,
      doc(R"(Rotation matrices of quaternions, as scipy's Rotation.from_quat.

Quaternions of any nonzero norm are normalized. A zero or non-finite
quaternion gives a matrix of NaN.

Args:
    q: array_like of shape (..., 4): quaternions, scalar-last (x, y, z, w)
        by default, as scipy.
    scalar_first: if True, q is read as (w, x, y, z).

Returns:
    numpy.ndarray of shape (..., 3, 3): the rotation matrices.)")
          .c_str());

  m.def(
      "so3_as_quat",
      [](py::handle R, bool scalar_first) {
        return apply<Core<4>>(
            "so3_as_quat",
            [scalar_first](const auto& R) {
              using T = ScalarOf<decltype(R)>;
              const Eigen::Quaternion<T> e = SO3<T>::from_matrix_unchecked(R).quaternion();
              return scalar_first ? Eigen::Matrix<T, 4, 1>(e.w(), e.x(), e.y(), e.z())
                                  : Eigen::Matrix<T, 4, 1>(e.x(), e.y(), e.z(), e.w());
            },
            in<Core<3, 3>>("R", R));
      },
      py::arg("R"), py::kw_only(), py::arg("scalar_first") = false,
      doc(R"(Unit quaternions of rotation matrices, as scipy's Rotation.as_quat.

Shepperd's method (no small divisor for any input). Of the two quaternions
q and -q of a rotation, the one whose largest component is positive.

Args:
    R: array_like of shape (..., 3, 3): rotation matrices.
    scalar_first: if True, return (w, x, y, z) instead of (x, y, z, w).

Returns:
    numpy.ndarray of shape (..., 4): the quaternions, scalar-last (x, y, z,
    w) by default, as scipy.)")
          .c_str());

  m.def(
      "so3_interpolate",
      [](py::handle a, py::handle b, py::handle t) {
        return apply<Core<3, 3>>(
            "so3_interpolate",
            [](const auto& a, const auto& b, const auto& t) {
              using T = ScalarOf<decltype(a)>;
              return chasles::interpolate(SO3<T>::from_matrix_unchecked(a), SO3<T>::from_matrix_unchecked(b), t)
                  .matrix();
            },
            in<Core<3, 3>>("a", a), in<Core<3, 3>>("b", b), in<Core<>>("t", t));
      },
      py::arg("a"), py::arg("b"), py::arg("t"),
      doc(R"(Geodesic interpolation of rotations: a exp(t log(a^-1 b)).

t = 0 gives a, t = 1 gives b, constant angular velocity in between.

Args:
    a: array_like of shape (..., 3, 3): rotation matrices at t = 0.
    b: array_like of shape (..., 3, 3): rotation matrices at t = 1.
    t: array_like of shape (...): the parameters (a Python float keeps
        the dtype of a and b).

Returns:
    numpy.ndarray of shape (..., 3, 3): the interpolated rotations.)")
          .c_str());
}

// ---- SE(3) and twists -------------------------------------------------------

void bind_se3_batch(py::module_& m) {
  m.def(
      "se3_exp",
      [](py::handle xi) {
        return apply<Core<4, 4>>(
            "se3_exp", [](const auto& xi) { return SE3<ScalarOf<decltype(xi)>>::exp(xi); },
            in<Core<6>>("xi", xi));
      },
      py::arg("xi"),
      doc(R"(Rigid motions of twists: g = exp([xi]) (4x4).

Twist order xi = (v, w), linear part first (Murray, Li and Sastry). In
closed form: R = exp([w]), p = V v with V = I + B [w] + C [w]^2; w = 0 is a
pure translation.

Args:
    xi: array_like of shape (..., 6): twists (v, w), linear part first.

Returns:
    numpy.ndarray of shape (..., 4, 4): the homogeneous matrices
    [[R, p], [0, 1]].)")
          .c_str());

  m.def(
      "se3_log",
      [](py::handle g) {
        return apply<Core<6>>(
            "se3_log", [](const auto& g) { return SE3<ScalarOf<decltype(g)>>::from_matrix_unchecked(g).log(); },
            in<Core<4, 4>>("g", g));
      },
      py::arg("g"),
      doc(R"(Twists of rigid motions: xi = log(g)^vee, xi = (v, w).

Rotation angle |w| in [0, pi] (at exactly pi, either axis sign); v = V^-1 p.

Args:
    g: array_like of shape (..., 4, 4): homogeneous matrices [[R, p], [0, 1]].

Returns:
    numpy.ndarray of shape (..., 6): the twists (v, w), linear part first.)")
          .c_str());

  m.def(
      "se3_compose",
      [](py::handle a, py::handle b) {
        return apply<Core<4, 4>>(
            "se3_compose",
            [](const auto& a, const auto& b) {
              using T = ScalarOf<decltype(a)>;
              return SE3<T>::from_matrix_unchecked(a) * SE3<T>::from_matrix_unchecked(b);
            },
            in<Core<4, 4>>("a", a), in<Core<4, 4>>("b", b));
      },
      py::arg("a"), py::arg("b"),
      doc(R"(Composition of rigid motions: a @ b (g_ac = g_ab g_bc).

Args:
    a: array_like of shape (..., 4, 4): homogeneous matrices.
    b: array_like of shape (..., 4, 4): homogeneous matrices.

Returns:
    numpy.ndarray of shape (..., 4, 4): the products [[R_a R_b, R_a p_b +
    p_a], [0, 1]], the batch shape being the broadcast of a's and b's.)")
          .c_str());

  m.def(
      "se3_inverse",
      [](py::handle g) {
        return apply<Core<4, 4>>(
            "se3_inverse",
            [](const auto& g) { return SE3<ScalarOf<decltype(g)>>::from_matrix_unchecked(g).inverse(); },
            in<Core<4, 4>>("g", g));
      },
      py::arg("g"),
      doc(R"(Inverse rigid motions: g^-1 = [[R^T, -R^T p], [0, 1]].

Args:
    g: array_like of shape (..., 4, 4): homogeneous matrices.

Returns:
    numpy.ndarray of shape (..., 4, 4): the inverses.)")
          .c_str());

  m.def(
      "se3_act",
      [](py::handle g, py::handle points) {
        return apply<Core<3>>(
            "se3_act",
            [](const auto& g, const auto& p) {
              return SE3<ScalarOf<decltype(g)>>::from_matrix_unchecked(g).act(p);
            },
            in<Core<4, 4>>("g", g), in<Core<3>>("points", points));
      },
      py::arg("g"), py::arg("points"),
      doc(R"(Transformed points: q_a = R_ab q_b + p_ab.

Broadcasts: one pose of shape (4, 4) with points of shape (N, 3), N poses
with N points, (N, 1, 4, 4) with (M, 3) for every pair, ...

Args:
    g: array_like of shape (..., 4, 4): homogeneous matrices.
    points: array_like of shape (..., 3): points.

Returns:
    numpy.ndarray of shape (..., 3): the transformed points.)")
          .c_str());

  m.def(
      "se3_adjoint",
      [](py::handle g) {
        return apply<Core<6, 6>>(
            "se3_adjoint",
            [](const auto& g) { return SE3<ScalarOf<decltype(g)>>::from_matrix_unchecked(g).adjoint(); },
            in<Core<4, 4>>("g", g));
      },
      py::arg("g"),
      doc(R"(Adjoint matrices: Ad_g = [[R, [p] R], [0, R]] (6x6).

Twist order (v, w), linear part first: twists change frame by
xi_a = Ad_g xi_b, wrenches by F_b = Ad_g^T F_a.

Args:
    g: array_like of shape (..., 4, 4): homogeneous matrices.

Returns:
    numpy.ndarray of shape (..., 6, 6): the adjoint matrices.)")
          .c_str());

  m.def(
      "se3_act_twist",
      [](py::handle g, py::handle xi) {
        return apply<Core<6>>(
            "se3_act_twist",
            [](const auto& g, const auto& xi) {
              using T = ScalarOf<decltype(g)>;
              return SE3<T>::from_matrix_unchecked(g).act(chasles::Twist<T>(xi)).vector();
            },
            in<Core<4, 4>>("g", g), in<Core<6>>("xi", xi));
      },
      py::arg("g"), py::arg("xi"),
      doc(R"(Twists changed from frame b to frame a: xi_a = Ad_g xi_b.

xi_a = (R v + p x R w, R w) for xi_b = (v, w), linear part first.

Args:
    g: array_like of shape (..., 4, 4): homogeneous matrices g_ab.
    xi: array_like of shape (..., 6): twists (v, w) in frame b.

Returns:
    numpy.ndarray of shape (..., 6): the twists (v, w) in frame a.)")
          .c_str());

  m.def(
      "se3_act_wrench",
      [](py::handle g, py::handle F) {
        return apply<Core<6>>(
            "se3_act_wrench",
            [](const auto& g, const auto& F) {
              using T = ScalarOf<decltype(g)>;
              return SE3<T>::from_matrix_unchecked(g).act(chasles::Wrench<T>(F)).vector();
            },
            in<Core<4, 4>>("g", g), in<Core<6>>("F", F));
      },
      py::arg("g"), py::arg("F"),
      doc(R"(Wrenches changed from frame b to frame a: F_a = Ad_g^-T F_b.

F_a = (R f, p x R f + R tau) for F_b = (f, tau), force first, so that the
power xi . F is the same in both frames.

Args:
    g: array_like of shape (..., 4, 4): homogeneous matrices g_ab.
    F: array_like of shape (..., 6): wrenches (f, tau) in frame b.

Returns:
    numpy.ndarray of shape (..., 6): the wrenches (f, tau) in frame a.)")
          .c_str());

  m.def(
      "se3_interpolate",
      [](py::handle a, py::handle b, py::handle t) {
        return apply<Core<4, 4>>(
            "se3_interpolate",
            [](const auto& a, const auto& b, const auto& t) {
              using T = ScalarOf<decltype(a)>;
              return chasles::interpolate(SE3<T>::from_matrix_unchecked(a), SE3<T>::from_matrix_unchecked(b), t);
            },
            in<Core<4, 4>>("a", a), in<Core<4, 4>>("b", b), in<Core<>>("t", t));
      },
      py::arg("a"), py::arg("b"), py::arg("t"),
      doc(R"(Screw interpolation of rigid motions: a exp(t log(a^-1 b)).

t = 0 gives a, t = 1 gives b, one screw motion in between.

Args:
    a: array_like of shape (..., 4, 4): homogeneous matrices at t = 0.
    b: array_like of shape (..., 4, 4): homogeneous matrices at t = 1.
    t: array_like of shape (...): the parameters (a Python float keeps
        the dtype of a and b).

Returns:
    numpy.ndarray of shape (..., 4, 4): the interpolated motions.)")
          .c_str());

  m.def(
      "twist_hat",
      [](py::handle xi) {
        return apply<Core<4, 4>>(
            "twist_hat", [](const auto& xi) { return chasles::Twist<ScalarOf<decltype(xi)>>(xi).hat(); },
            in<Core<6>>("xi", xi));
      },
      py::arg("xi"),
      doc(R"(Matrices of twists: [xi] = [[ [w], v ], [0, 0]] (4x4).

Args:
    xi: array_like of shape (..., 6): twists (v, w), linear part first.

Returns:
    numpy.ndarray of shape (..., 4, 4): the matrices [xi].)")
          .c_str());

  m.def(
      "twist_vee",
      [](py::handle X) {
        return apply<Core<6>>(
            "twist_vee",
            [](const auto& X) { return chasles::Twist<ScalarOf<decltype(X)>>::vee(X).vector(); },
            in<Core<4, 4>>("X", X));
      },
      py::arg("X"),
      doc(R"(Twists of 4x4 matrices: [xi]^vee = (v, w), linear part first.

v is the last column's top three entries, w the vee of the antisymmetric
part of the top-left 3x3 block; the bottom row is not read.

Args:
    X: array_like of shape (..., 4, 4): matrices [[ [w], v ], [0, 0]].

Returns:
    numpy.ndarray of shape (..., 6): the twists (v, w).)")
          .c_str());
}

}  // namespace

void bind_batch(py::module_& m) {
  bind_so3_batch(m);
  bind_se3_batch(m);
}

}  // namespace chasles_py
