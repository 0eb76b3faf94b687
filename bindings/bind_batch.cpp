// chasles._core: the array functions (so3_*, se3_*) as numpy generalized
// ufuncs.
//
// Each function is its kernel, a generic lambda that calls the chasles C++
// API on one element, registered by ufunc.hpp with the core shapes of its
// operands and of its result. No mathematics here. Functions that take an
// argument a ufunc cannot (the quaternion order) are two private ufuncs and
// a Python function that picks one (python/chasles/_arrays.py).
#include <limits>
#include <string>
#include <type_traits>

#include <chasles/se3.hpp>
#include <chasles/so3.hpp>
#include <chasles/twist.hpp>
#include <chasles/wrench.hpp>

#include "bindings.hpp"
#include "ufunc.hpp"

namespace chasles_py {

namespace {

using ufunc::array_doc;
using ufunc::Core;
using ufunc::def_ufunc;
using ufunc::ScalarOf;

template <typename T>
using SO3 = chasles::SO3<T>;
template <typename T>
using SE3 = chasles::SE3<T>;

/// so3_from_quat's kernel for one quaternion order: q as given (any nonzero
/// norm, normalized by the C++ API); a zero or non-finite quaternion has no
/// rotation and gives NaN, as numpy's 0/0 (the C++ API gives the identity).
template <bool ScalarFirst>
auto from_quat_kernel() {
  return [](const auto& q) {
    using T = ScalarOf<decltype(q)>;
    Eigen::Matrix<T, 3, 3> R;
    if (!q.allFinite() || !(q.squaredNorm() > T(0))) {
      R.setConstant(std::numeric_limits<T>::quiet_NaN());
    } else {
      const Eigen::Quaternion<T> e =
          ScalarFirst ? Eigen::Quaternion<T>(q[0], q[1], q[2], q[3]) : Eigen::Quaternion<T>(q[3], q[0], q[1], q[2]);
      R = SO3<T>::from_quaternion(e).matrix();
    }
    return R;
  };
}

/// so3_as_quat's kernel for one quaternion order (Shepperd's method; of q
/// and -q, the one whose largest component is positive).
template <bool ScalarFirst>
auto as_quat_kernel() {
  return [](const auto& R) {
    using T = ScalarOf<decltype(R)>;
    const Eigen::Quaternion<T> e = SO3<T>::from_matrix_unchecked(R).quaternion();
    return ScalarFirst ? Eigen::Matrix<T, 4, 1>(e.w(), e.x(), e.y(), e.z())
                       : Eigen::Matrix<T, 4, 1>(e.x(), e.y(), e.z(), e.w());
  };
}

const char* const kFromQuatDoc = R"(Rotation matrices of quaternions, as scipy's Rotation.from_quat.

Quaternions of any nonzero norm are normalized. A zero or non-finite
quaternion gives a matrix of NaN. The private ufunc behind
chasles.so3_from_quat for one quaternion order.

Args:
    quat: array_like of shape (..., 4): quaternions.

Returns:
    numpy.ndarray of shape (..., 3, 3): the rotation matrices.)";

const char* const kAsQuatDoc = R"(Unit quaternions of rotation matrices, as scipy's Rotation.as_quat.

Shepperd's method. Of q and -q, the one whose largest component is
positive. The private ufunc behind chasles.so3_as_quat for one quaternion
order.

Args:
    R: array_like of shape (..., 3, 3): rotation matrices.

Returns:
    numpy.ndarray of shape (..., 4): the quaternions.)";

// ---- SO(3) ------------------------------------------------------------------

void bind_so3_batch(py::module_& m) {
  def_ufunc<Core<3, 3>(Core<3>)>(m, "so3_exp", "w", array_doc(R"(Rotation matrices of rotation vectors: R = exp([w]).

Rodrigues' formula, R = I + (sin t / t) [w] + ((1 - cos t) / t^2) [w]^2 with
t = |w|, exact to a few ulps for every w (Taylor series near 0).

Args:
    w: array_like of shape (..., 3): rotation vectors, axis times angle in
        radians.

Returns:
    numpy.ndarray of shape (..., 3, 3): the rotation matrices.)"),
                                 [](const auto& w) { return SO3<ScalarOf<decltype(w)>>::exp(w).matrix(); });

  def_ufunc<Core<3>(Core<3, 3>)>(
      m, "so3_log", "R", array_doc(R"(Rotation vectors of rotation matrices: w = log(R)^vee.

The angle |w| is in [0, pi]; at exactly pi either axis sign is returned,
never NaN. Robust near 0 and near pi, and as accurate for a matrix slightly
off SO(3) as projecting it first.

Args:
    R: array_like of shape (..., 3, 3): rotation matrices.

Returns:
    numpy.ndarray of shape (..., 3): the rotation vectors (axis times angle).)"),
      [](const auto& R) { return SO3<ScalarOf<decltype(R)>>::from_matrix_unchecked(R).log(); });

  def_ufunc<Core<3, 3>(Core<3, 3>, Core<3, 3>)>(
      m, "so3_compose", "a, b", array_doc(R"(Composition of rotations: a @ b (R_ac = R_ab R_bc).

Args:
    a: array_like of shape (..., 3, 3): rotation matrices.
    b: array_like of shape (..., 3, 3): rotation matrices.

Returns:
    numpy.ndarray of shape (..., 3, 3): the products, the batch shape being
    the broadcast of a's and b's.)"),
      [](const auto& a, const auto& b) {
        using T = ScalarOf<decltype(a)>;
        return (SO3<T>::from_matrix_unchecked(a) * SO3<T>::from_matrix_unchecked(b)).matrix();
      });

  def_ufunc<Core<3, 3>(Core<3, 3>)>(
      m, "so3_inverse", "R", array_doc(R"(Inverse rotations: R^-1 = R^T.

Args:
    R: array_like of shape (..., 3, 3): rotation matrices.

Returns:
    numpy.ndarray of shape (..., 3, 3): the inverses.)"),
      [](const auto& R) { return SO3<ScalarOf<decltype(R)>>::from_matrix_unchecked(R).inverse().matrix(); });

  def_ufunc<Core<3>(Core<3, 3>, Core<3>)>(
      m, "so3_act", "R, points", array_doc(R"(Rotated points or vectors: p_a = R_ab p_b.

Broadcasts: one rotation of shape (3, 3) with points of shape (N, 3), N
rotations with N points, (N, 1, 3, 3) with (M, 3) for every pair, ...

Args:
    R: array_like of shape (..., 3, 3): rotation matrices.
    points: array_like of shape (..., 3): points or vectors.

Returns:
    numpy.ndarray of shape (..., 3): the rotated points.)"),
      [](const auto& R, const auto& p) { return SO3<ScalarOf<decltype(R)>>::from_matrix_unchecked(R).act(p); });

  def_ufunc<Core<3, 3>(Core<3>)>(m, "so3_hat", "w",
                                 array_doc(R"(Skew-symmetric matrices: [w] = [[0, -w3, w2], [w3, 0, -w1], [-w2, w1, 0]].

So that [w] p = w x p.

Args:
    w: array_like of shape (..., 3): vectors of so(3).

Returns:
    numpy.ndarray of shape (..., 3, 3): the matrices [w].)"),
                                 [](const auto& w) { return SO3<ScalarOf<decltype(w)>>::hat(w); });

  def_ufunc<Core<3>(Core<3, 3>)>(m, "so3_vee", "matrix",
                                 array_doc(R"(The vectors of skew-symmetric matrices: vee([w]) = w.

Reads the antisymmetric part (W - W^T) / 2, so a matrix that is not exactly
skew gives the w of its nearest skew matrix.

Args:
    matrix: array_like of shape (..., 3, 3): skew-symmetric matrices.

Returns:
    numpy.ndarray of shape (..., 3): the vectors w.)"),
                                 [](const auto& W) { return SO3<ScalarOf<decltype(W)>>::vee(W); });

  def_ufunc<Core<3, 3>(Core<3, 3>, Core<3, 3>, Core<>)>(
      m, "so3_interpolate", "a, b, t", array_doc(R"(Geodesic interpolation of rotations: a exp(t log(a^-1 b)).

t = 0 gives a, t = 1 gives b, constant angular velocity in between.

Args:
    a: array_like of shape (..., 3, 3): rotation matrices at t = 0.
    b: array_like of shape (..., 3, 3): rotation matrices at t = 1.
    t: array_like of shape (...): the parameters (a Python float keeps
        the dtype of a and b).

Returns:
    numpy.ndarray of shape (..., 3, 3): the interpolated rotations.)"),
      [](const auto& a, const auto& b, const auto& t) {
        using T = ScalarOf<decltype(a)>;
        return chasles::interpolate(SO3<T>::from_matrix_unchecked(a), SO3<T>::from_matrix_unchecked(b), t).matrix();
      });
  def_ufunc<Core<3, 3>(Core<4>)>(m, "_so3_from_quat_xyzw", "quat", array_doc(kFromQuatDoc), from_quat_kernel<false>());
  def_ufunc<Core<3, 3>(Core<4>)>(m, "_so3_from_quat_wxyz", "quat", array_doc(kFromQuatDoc), from_quat_kernel<true>());
  def_ufunc<Core<4>(Core<3, 3>)>(m, "_so3_as_quat_xyzw", "R", array_doc(kAsQuatDoc), as_quat_kernel<false>());
  def_ufunc<Core<4>(Core<3, 3>)>(m, "_so3_as_quat_wxyz", "R", array_doc(kAsQuatDoc), as_quat_kernel<true>());
}

// ---- SE(3) and twists -------------------------------------------------------

void bind_se3_batch(py::module_& m) {
  def_ufunc<Core<4, 4>(Core<6>)>(m, "se3_exp", "xi", array_doc(R"(Rigid motions of twists: g = exp([xi]) (4x4).

Twist order xi = (v, w), linear part first (Murray, Li and Sastry). In
closed form: R = exp([w]), p = V v with V = I + B [w] + C [w]^2; w = 0 is a
pure translation.

Args:
    xi: array_like of shape (..., 6): twists (v, w), linear part first.

Returns:
    numpy.ndarray of shape (..., 4, 4): the homogeneous matrices
    [[R, p], [0, 1]].)"),
                                 [](const auto& xi) { return SE3<ScalarOf<decltype(xi)>>::exp(xi); });

  def_ufunc<Core<6>(Core<4, 4>)>(
      m, "se3_log", "g", array_doc(R"(Twists of rigid motions: xi = log(g)^vee, xi = (v, w).

Rotation angle |w| in [0, pi] (at exactly pi, either axis sign); v = V^-1 p.

Args:
    g: array_like of shape (..., 4, 4): homogeneous matrices [[R, p], [0, 1]].

Returns:
    numpy.ndarray of shape (..., 6): the twists (v, w), linear part first.)"),
      [](const auto& g) { return SE3<ScalarOf<decltype(g)>>::from_matrix_unchecked(g).log(); });

  def_ufunc<Core<4, 4>(Core<4, 4>, Core<4, 4>)>(
      m, "se3_compose", "a, b", array_doc(R"(Composition of rigid motions: a @ b (g_ac = g_ab g_bc).

Args:
    a: array_like of shape (..., 4, 4): homogeneous matrices.
    b: array_like of shape (..., 4, 4): homogeneous matrices.

Returns:
    numpy.ndarray of shape (..., 4, 4): the products [[R_a R_b, R_a p_b +
    p_a], [0, 1]], the batch shape being the broadcast of a's and b's.)"),
      [](const auto& a, const auto& b) {
        using T = ScalarOf<decltype(a)>;
        return SE3<T>::from_matrix_unchecked(a) * SE3<T>::from_matrix_unchecked(b);
      });

  def_ufunc<Core<4, 4>(Core<4, 4>)>(
      m, "se3_inverse", "g", array_doc(R"(Inverse rigid motions: g^-1 = [[R^T, -R^T p], [0, 1]].

Args:
    g: array_like of shape (..., 4, 4): homogeneous matrices.

Returns:
    numpy.ndarray of shape (..., 4, 4): the inverses.)"),
      [](const auto& g) { return SE3<ScalarOf<decltype(g)>>::from_matrix_unchecked(g).inverse(); });

  def_ufunc<Core<3>(Core<4, 4>, Core<3>)>(
      m, "se3_act", "g, points", array_doc(R"(Transformed points: q_a = R_ab q_b + p_ab.

Broadcasts: one pose of shape (4, 4) with points of shape (N, 3), N poses
with N points, (N, 1, 4, 4) with (M, 3) for every pair, ...

Args:
    g: array_like of shape (..., 4, 4): homogeneous matrices.
    points: array_like of shape (..., 3): points.

Returns:
    numpy.ndarray of shape (..., 3): the transformed points.)"),
      [](const auto& g, const auto& p) { return SE3<ScalarOf<decltype(g)>>::from_matrix_unchecked(g).act(p); });

  def_ufunc<Core<6, 6>(Core<4, 4>)>(
      m, "se3_adjoint", "g", array_doc(R"(Adjoint matrices: Ad_g = [[R, [p] R], [0, R]] (6x6).

Twist order (v, w), linear part first: twists change frame by
xi_a = Ad_g xi_b, wrenches by F_b = Ad_g^T F_a.

Args:
    g: array_like of shape (..., 4, 4): homogeneous matrices.

Returns:
    numpy.ndarray of shape (..., 6, 6): the adjoint matrices.)"),
      [](const auto& g) { return SE3<ScalarOf<decltype(g)>>::from_matrix_unchecked(g).adjoint(); });

  def_ufunc<Core<6>(Core<4, 4>, Core<6>)>(m, "se3_act_twist", "g, xi",
                                          array_doc(R"(Twists changed from frame b to frame a: xi_a = Ad_g xi_b.

xi_a = (R v + p x R w, R w) for xi_b = (v, w), linear part first.

Args:
    g: array_like of shape (..., 4, 4): homogeneous matrices g_ab.
    xi: array_like of shape (..., 6): twists (v, w) in frame b.

Returns:
    numpy.ndarray of shape (..., 6): the twists (v, w) in frame a.)"),
                                          [](const auto& g, const auto& xi) {
                                            using T = ScalarOf<decltype(g)>;
                                            return SE3<T>::from_matrix_unchecked(g).act(chasles::Twist<T>(xi)).vector();
                                          });

  def_ufunc<Core<6>(Core<4, 4>, Core<6>)>(m, "se3_act_wrench", "g, F",
                                          array_doc(R"(Wrenches changed from frame b to frame a: F_a = Ad_g^-T F_b.

F_a = (R f, p x R f + R tau) for F_b = (f, tau), force first, so that the
power xi . F is the same in both frames.

Args:
    g: array_like of shape (..., 4, 4): homogeneous matrices g_ab.
    F: array_like of shape (..., 6): wrenches (f, tau) in frame b.

Returns:
    numpy.ndarray of shape (..., 6): the wrenches (f, tau) in frame a.)"),
                                          [](const auto& g, const auto& F) {
                                            using T = ScalarOf<decltype(g)>;
                                            return SE3<T>::from_matrix_unchecked(g).act(chasles::Wrench<T>(F)).vector();
                                          });

  def_ufunc<Core<4, 4>(Core<4, 4>, Core<4, 4>, Core<>)>(
      m, "se3_interpolate", "a, b, t", array_doc(R"(Screw interpolation of rigid motions: a exp(t log(a^-1 b)).

t = 0 gives a, t = 1 gives b, one screw motion in between.

Args:
    a: array_like of shape (..., 4, 4): homogeneous matrices at t = 0.
    b: array_like of shape (..., 4, 4): homogeneous matrices at t = 1.
    t: array_like of shape (...): the parameters (a Python float keeps
        the dtype of a and b).

Returns:
    numpy.ndarray of shape (..., 4, 4): the interpolated motions.)"),
      [](const auto& a, const auto& b, const auto& t) {
        using T = ScalarOf<decltype(a)>;
        return chasles::interpolate(SE3<T>::from_matrix_unchecked(a), SE3<T>::from_matrix_unchecked(b), t);
      });

  def_ufunc<Core<4, 4>(Core<6>)>(m, "se3_hat", "xi", array_doc(R"(Matrices of twists: [xi] = [[ [w], v ], [0, 0]] (4x4).

Args:
    xi: array_like of shape (..., 6): twists (v, w), linear part first.

Returns:
    numpy.ndarray of shape (..., 4, 4): the matrices [xi].)"),
                                 [](const auto& xi) { return chasles::Twist<ScalarOf<decltype(xi)>>(xi).hat(); });

  def_ufunc<Core<6>(Core<4, 4>)>(m, "se3_vee", "matrix",
                                 array_doc(R"(Twists of 4x4 matrices: [xi]^vee = (v, w), linear part first.

v is the last column's top three entries, w the vee of the antisymmetric
part of the top-left 3x3 block; the bottom row is not read.

Args:
    matrix: array_like of shape (..., 4, 4): matrices [[ [w], v ], [0, 0]].

Returns:
    numpy.ndarray of shape (..., 6): the twists (v, w).)"),
                                 [](const auto& X) { return chasles::Twist<ScalarOf<decltype(X)>>::vee(X).vector(); });
}

}  // namespace

void bind_batch(py::module_& m) {
  bind_so3_batch(m);
  bind_se3_batch(m);
}

}  // namespace chasles_py
