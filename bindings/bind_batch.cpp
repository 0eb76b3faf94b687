// chasles._core: the array functions (so2_*, se2_*, so3_*, se3_*, sim3_*, se23_*) as numpy
// generalized ufuncs.
//
// Each function is its kernel, a generic lambda that calls the chasles C++
// API on one element, registered by ufunc.hpp with the core shapes of its
// operands and of its result. No mathematics here. Functions that take an
// argument a ufunc cannot (the quaternion order) are two private ufuncs and
// a Python function that picks one (python/chasles/_arrays.py).
#include <limits>
#include <string>
#include <type_traits>

#include <chasles/se2.hpp>
#include <chasles/se23.hpp>
#include <chasles/se3.hpp>
#include <chasles/sim3.hpp>
#include <chasles/so2.hpp>
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
template <typename T>
using SO2 = chasles::SO2<T>;
template <typename T>
using SE2 = chasles::SE2<T>;
template <typename T>
using Sim3 = chasles::Sim3<T>;
template <typename T>
using SE23 = chasles::SE23<T>;

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

/// se3_from_quat's kernel: the pose of a quaternion (so3_from_quat's
/// rotation, NaN for a zero quaternion) and a translation.
template <bool ScalarFirst>
auto pose_from_quat_kernel() {
  return [](const auto& q, const auto& t) {
    using T = ScalarOf<decltype(q)>;
    Eigen::Matrix<T, 4, 4> g = Eigen::Matrix<T, 4, 4>::Identity();
    g.template topLeftCorner<3, 3>() = from_quat_kernel<ScalarFirst>()(q);
    g.template topRightCorner<3, 1>() = t;
    return g;
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

const char* const kPoseFromQuatDoc =
    R"(Poses of quaternions and translations, as scipy's RigidTransform.from_components.

The rotation is so3_from_quat's (any nonzero norm normalized, a zero or
non-finite quaternion gives NaN). The private ufunc behind
chasles.se3_from_quat for one quaternion order.

Args:
    quat: array_like of shape (..., 4): quaternions.
    translation: array_like of shape (..., 3).

Returns:
    numpy.ndarray of shape (..., 4, 4): the poses.)";

const char* const kAsQuatDoc = R"(Unit quaternions of rotation matrices, as scipy's Rotation.as_quat.

Shepperd's method. Of q and -q, the one whose largest component is
positive. The private ufunc behind chasles.so3_as_quat for one quaternion
order.

Args:
    R: array_like of shape (..., 3, 3): rotation matrices.

Returns:
    numpy.ndarray of shape (..., 4): the quaternions.)";

// ---- what the groups share -----------------------------------------------

/// What a group's array functions take and say: the matrix size N, the
/// tangent size D (a tangent of size 1, SO(2)'s angle, is a scalar: core
/// shape ()), the point size P, the names (the ufunc keeps the pointer: literals), and
/// the group's own sentences; the rest of each docstring is shared.
template <template <typename> class Group>
struct Batch;

template <>
struct Batch<SO3> {
  static constexpr int N = 3, D = 3, P = 3;
  static constexpr const char* names[9] = {"so3_exp", "so3_log", "so3_compose",     "so3_inverse",  "so3_act",
                                           "so3_hat", "so3_vee", "so3_interpolate", "so3_normalize"};
  static constexpr const char *element = "R", *tangent = "w", *matrices = "rotation matrices",
                              *compose = "Composition of rotations: a @ b (R_ac = R_ab R_bc).",
                              *inverse = "Inverse rotations: R^-1 = R^T.", *acted = "points or vectors",
                              *act = "Rotated points or vectors: p_a = R_ab p_b.", *one = "rotation",
                              *moved = "rotated",
                              *product = ", the batch shape being\n    the broadcast of a's and b's.",
                              *interpolate = "Geodesic interpolation of rotations",
                              *between = "constant angular velocity", *interpolated = "rotations";
  static constexpr const char* exp = R"(Rotation matrices of rotation vectors: R = exp([w]).

Rodrigues' formula, R = I + (sin t / t) [w] + ((1 - cos t) / t^2) [w]^2 with
t = |w|, exact to a few ulps for every w (Taylor series near 0).

Args:
    w: array_like of shape (..., 3): rotation vectors, axis times angle in
        radians.

Returns:
    numpy.ndarray of shape (..., 3, 3): the rotation matrices.)";
  static constexpr const char* log = R"(Rotation vectors of rotation matrices: w = log(R)^vee.

The angle |w| is in [0, pi]; at exactly pi either axis sign is returned,
never NaN. Robust near 0 and near pi, and as accurate for a matrix slightly
off SO(3) as projecting it first.

Args:
    R: array_like of shape (..., 3, 3): rotation matrices.

Returns:
    numpy.ndarray of shape (..., 3): the rotation vectors (axis times angle).)";
  static constexpr const char* hat = R"(Skew-symmetric matrices: [w] = [[0, -w3, w2], [w3, 0, -w1], [-w2, w1, 0]].

So that [w] p = w x p.

Args:
    w: array_like of shape (..., 3): vectors of so(3).

Returns:
    numpy.ndarray of shape (..., 3, 3): the matrices [w].)";
  static constexpr const char* vee = R"(The vectors of skew-symmetric matrices: vee([w]) = w.

Reads the antisymmetric part (W - W^T) / 2, so a matrix that is not exactly
skew gives the w of its nearest skew matrix.

Args:
    matrix: array_like of shape (..., 3, 3): skew-symmetric matrices.

Returns:
    numpy.ndarray of shape (..., 3): the vectors w.)";
  static constexpr const char* normalize = R"(The nearest rotation matrices: SO3.normalized() over a batch.

The rotation nearest to each matrix in the Frobenius norm (for det > 0 the
orthogonal polar factor; reflections and singular matrices too), a few ulps
from orthonormal. Products drift off SO(3) by about an ulp each, and a
product that feeds on itself drifts exponentially: scipy's
multiplication-stability test (1000 rotations rs, 50 rounds of
rs = rs @ q @ rs) leaves max |R^T R - I| = 1.05 unless each round is
normalized (then 9e-16).
Non-finite matrices give NaN.

Args:
    R: array_like of shape (..., 3, 3): matrices.

Returns:
    numpy.ndarray of shape (..., 3, 3): the rotation matrices.)";
  template <typename T>
  static Eigen::Matrix<T, 3, 3> stored(const SO3<T>& R) noexcept {
    return R.matrix();
  }
};

template <>
struct Batch<SE3> {
  static constexpr int N = 4, D = 6, P = 3;
  static constexpr const char* names[9] = {"se3_exp", "se3_log", "se3_compose",     "se3_inverse",  "se3_act",
                                           "se3_hat", "se3_vee", "se3_interpolate", "se3_normalize"};
  static constexpr const char
      *element = "g",
      *tangent = "xi", *matrices = "homogeneous matrices",
      *compose = "Composition of rigid motions: a @ b (g_ac = g_ab g_bc).",
      *inverse = "Inverse rigid motions: g^-1 = [[R^T, -R^T p], [0, 1]].", *acted = "points",
      *act = "Transformed points: q_a = R_ab q_b + p_ab.", *one = "pose", *moved = "transformed",
      *product = " [[R_a R_b, R_a p_b +\n    p_a], [0, 1]], the batch shape being the broadcast of a's and b's.",
      *interpolate = "Screw interpolation of rigid motions", *between = "one screw motion", *interpolated = "motions";
  static constexpr const char* exp = R"(Rigid motions of twists: g = exp([xi]) (4x4).

Twist order xi = (v, w), linear part first (Murray, Li and Sastry). In
closed form: R = exp([w]), p = V v with V = I + B [w] + C [w]^2; w = 0 is a
pure translation.

Args:
    xi: array_like of shape (..., 6): twists (v, w), linear part first.

Returns:
    numpy.ndarray of shape (..., 4, 4): the homogeneous matrices
    [[R, p], [0, 1]].)";
  static constexpr const char* log = R"(Twists of rigid motions: xi = log(g)^vee, xi = (v, w).

Rotation angle |w| in [0, pi] (at exactly pi, either axis sign); v = V^-1 p.

Args:
    g: array_like of shape (..., 4, 4): homogeneous matrices [[R, p], [0, 1]].

Returns:
    numpy.ndarray of shape (..., 6): the twists (v, w), linear part first.)";
  static constexpr const char* hat = R"(Matrices of twists: [xi] = [[ [w], v ], [0, 0]] (4x4).

Args:
    xi: array_like of shape (..., 6): twists (v, w), linear part first.

Returns:
    numpy.ndarray of shape (..., 4, 4): the matrices [xi].)";
  static constexpr const char* vee = R"(Twists of 4x4 matrices: [xi]^vee = (v, w), linear part first.

v is the last column's top three entries, w the vee of the antisymmetric
part of the top-left 3x3 block; the bottom row is not read.

Args:
    matrix: array_like of shape (..., 4, 4): matrices [[ [w], v ], [0, 0]].

Returns:
    numpy.ndarray of shape (..., 6): the twists (v, w).)";
  static constexpr const char* normalize =
      R"(Homogeneous matrices with the nearest rotation: SE3.normalized() over a batch.

The top-left block becomes the rotation nearest to it (so3_normalize), the
translation column is kept and the bottom row becomes (0, 0, 0, 1).
Non-finite matrices give NaN.

Args:
    g: array_like of shape (..., 4, 4): matrices.

Returns:
    numpy.ndarray of shape (..., 4, 4): the homogeneous matrices.)";
  /// An SE3 result is written to its 4x4 core directly (ufunc.hpp).
  template <typename T>
  static const SE3<T>& stored(const SE3<T>& g) noexcept {
    return g;
  }
};

template <>
struct Batch<SO2> {
  static constexpr int N = 2, D = 1, P = 2;
  static constexpr const char* names[9] = {"so2_exp", "so2_log", "so2_compose",     "so2_inverse",  "so2_act",
                                           "so2_hat", "so2_vee", "so2_interpolate", "so2_normalize"};
  static constexpr const char *element = "R", *tangent = "theta", *matrices = "rotation matrices [[c, -s], [s, c]]",
                              *compose = "Composition of plane rotations: a @ b (R_ac = R_ab R_bc).",
                              *inverse = "Inverse plane rotations: R^-1 = R^T.", *acted = "points or vectors",
                              *act = "Rotated points or vectors of the plane: p_a = R_ab p_b.", *one = "rotation",
                              *moved = "rotated",
                              *product = ", the batch shape being\n    the broadcast of a's and b's.",
                              *interpolate = "Geodesic interpolation of plane rotations",
                              *between = "constant angular velocity", *interpolated = "rotations";
  static constexpr const char* exp = R"(Plane rotation matrices of angles: R = exp(theta) = [[c, -s], [s, c]].

One sincos per angle, exact to the libm's rounding for every theta.

Args:
    theta: array_like of shape (...): angles in radians.

Returns:
    numpy.ndarray of shape (..., 2, 2): the rotation matrices.)";
  static constexpr const char* log = R"(Angles of plane rotation matrices: theta = atan2(s, c) in [-pi, pi].

(c, s) = ((R00 + R11) / 2, (R10 - R01) / 2); atan2 is accurate to an ulp
over the whole range, and reads only the direction of (c, s).

Args:
    R: array_like of shape (..., 2, 2): rotation matrices.

Returns:
    numpy.ndarray of shape (...): the angles, radians.)";
  static constexpr const char* hat = R"(Skew-symmetric 2x2 matrices of angles: hat(theta) = [[0, -theta], [theta, 0]].

Args:
    theta: array_like of shape (...): elements of so(2).

Returns:
    numpy.ndarray of shape (..., 2, 2): the matrices.)";
  static constexpr const char* vee = R"(The angles of skew-symmetric 2x2 matrices: vee(W) = (W10 - W01) / 2.

Args:
    matrix: array_like of shape (..., 2, 2).

Returns:
    numpy.ndarray of shape (...): the angles.)";
  static constexpr const char* normalize = R"(The nearest plane rotation matrices: SO2.normalized() over a batch.

The rotation maximizing tr(R^T M): (c, s) along (M00 + M11, M10 - M01).
Non-finite matrices give NaN.

Args:
    R: array_like of shape (..., 2, 2): matrices.

Returns:
    numpy.ndarray of shape (..., 2, 2): the rotation matrices.)";
  template <typename T>
  static Eigen::Matrix<T, 2, 2> stored(const SO2<T>& R) noexcept {
    return R.matrix();
  }
};

template <>
struct Batch<SE2> {
  static constexpr int N = 3, D = 3, P = 2;
  static constexpr const char* names[9] = {"se2_exp", "se2_log", "se2_compose",     "se2_inverse",  "se2_act",
                                           "se2_hat", "se2_vee", "se2_interpolate", "se2_normalize"};
  static constexpr const char *element = "g", *tangent = "xi", *matrices = "homogeneous matrices [[R, t], [0, 1]]",
                              *compose = "Composition of rigid motions of the plane: a @ b (g_ac = g_ab g_bc).",
                              *inverse = "Inverse rigid motions of the plane: g^-1 = [[R^T, -R^T t], [0, 1]].",
                              *acted = "points", *act = "Transformed points of the plane: q_a = R_ab q_b + t_ab.",
                              *one = "pose", *moved = "transformed",
                              *product = ", the batch shape being\n    the broadcast of a's and b's.",
                              *interpolate = "Screw interpolation of rigid motions of the plane",
                              *between = "one rotation about a fixed point (or one translation)",
                              *interpolated = "motions";
  static constexpr const char* exp = R"(Rigid motions of the plane of twists: g = exp([xi]) (3x3).

Twist order xi = (vx, vy, w), linear part first. R = exp(w), t = V v with
V = [[a, -b], [b, a]], a = sin(w) / w, b = (1 - cos(w)) / w: one sincos,
series below the cutoff, a few ulps for every xi.

Args:
    xi: array_like of shape (..., 3): twists (vx, vy, w).

Returns:
    numpy.ndarray of shape (..., 3, 3): the matrices [[R, t], [0, 1]].)";
  static constexpr const char* log = R"(Twists of rigid motions of the plane: xi = log(g)^vee = (vx, vy, w).

w = atan2(s, c) in [-pi, pi]; v = V^-1 t with V^-1 = [[e, w/2], [-w/2, e]],
e = (w/2) cot(w/2), without cancellation near 0 or near pi.

Args:
    g: array_like of shape (..., 3, 3): matrices [[R, t], [0, 1]].

Returns:
    numpy.ndarray of shape (..., 3): the twists (vx, vy, w).)";
  static constexpr const char* hat = R"(Matrices of planar twists: [xi] = [[0, -w, vx], [w, 0, vy], [0, 0, 0]].

Args:
    xi: array_like of shape (..., 3): twists (vx, vy, w).

Returns:
    numpy.ndarray of shape (..., 3, 3): the matrices [xi].)";
  static constexpr const char* vee = R"(Twists of 3x3 matrices: [xi]^vee = (vx, vy, w).

(vx, vy) is the last column's top, w the antisymmetric part of the top-left
block; the bottom row is not read.

Args:
    matrix: array_like of shape (..., 3, 3).

Returns:
    numpy.ndarray of shape (..., 3): the twists (vx, vy, w).)";
  static constexpr const char* normalize =
      R"(Homogeneous matrices with the nearest rotation: SE2.normalized() over a batch.

The top-left block becomes the nearest rotation (so2_normalize), the
translation is kept and the bottom row becomes (0, 0, 1). Non-finite
matrices give NaN.

Args:
    g: array_like of shape (..., 3, 3): matrices.

Returns:
    numpy.ndarray of shape (..., 3, 3): the homogeneous matrices.)";
  template <typename T>
  static Eigen::Matrix<T, 3, 3> stored(const SE2<T>& g) noexcept {
    return g.matrix();
  }
};

template <>
struct Batch<Sim3> {
  static constexpr int N = 4, D = 7, P = 3;
  static constexpr const char* names[9] = {"sim3_exp", "sim3_log", "sim3_compose",     "sim3_inverse",  "sim3_act",
                                           "sim3_hat", "sim3_vee", "sim3_interpolate", "sim3_normalize"};
  static constexpr const char *element = "g", *tangent = "xi", *matrices = "similarity matrices [[s R, t], [0, 1]]",
                              *compose = "Composition of similarities: a @ b = (R_a R_b, s_a R_a t_b + t_a, s_a s_b).",
                              *inverse = "Inverse similarities: (R^T, -R^T t / s, 1 / s).", *acted = "points",
                              *act = "Transformed points: q_a = s R q_b + t.", *one = "similarity",
                              *moved = "transformed",
                              *product = ", the batch shape being\n    the broadcast of a's and b's.",
                              *interpolate = "Geodesic interpolation of similarities",
                              *between = "one screw motion with a steady scaling", *interpolated = "similarities";
  static constexpr const char* exp = R"(Similarity matrices of xi = (v, w, sigma): g = exp([xi]) (4x4).

Sophus' order; R = exp([w]), s = e^sigma, t = W v with W the integral of
e^(sigma u) exp(u [w]) over [0, 1] (no 0/0 in theta = |w| or sigma: a few
ulps over the whole domain).

Args:
    xi: array_like of shape (..., 7): (v, w, sigma).

Returns:
    numpy.ndarray of shape (..., 4, 4): the matrices [[s R, t], [0, 1]].)";
  static constexpr const char* log = R"(The (v, w, sigma) of similarity matrices: xi = log(g)^vee.

s = |block|_F / sqrt(3), w = log(block / s) with |w| in [0, pi], sigma =
log(s), v = W^-1 t in closed form.

Args:
    g: array_like of shape (..., 4, 4): matrices [[s R, t], [0, 1]].

Returns:
    numpy.ndarray of shape (..., 7): (v, w, sigma).)";
  static constexpr const char* hat = R"(Matrices of xi = (v, w, sigma): [xi] = [[ [w] + sigma I, v ], [0, 0]] (4x4).

Args:
    xi: array_like of shape (..., 7).

Returns:
    numpy.ndarray of shape (..., 4, 4): the matrices [xi].)";
  static constexpr const char* vee = R"(The (v, w, sigma) of 4x4 matrices: the inverse of sim3_hat.

w from the antisymmetric part of the top-left block, sigma the mean of its
diagonal; the bottom row is not read.

Args:
    matrix: array_like of shape (..., 4, 4).

Returns:
    numpy.ndarray of shape (..., 7).)";
  static constexpr const char* normalize =
      R"(The nearest similarity matrices: Sim3.from_matrix_projected over a batch.

R the nearest rotation to the top-left block, s = tr(R^T block) / 3, the
translation kept, the bottom row (0, 0, 0, 1). Non-finite matrices give NaN.

Args:
    g: array_like of shape (..., 4, 4): matrices.

Returns:
    numpy.ndarray of shape (..., 4, 4): the similarity matrices.)";
  template <typename T>
  static Eigen::Matrix<T, 4, 4> stored(const Sim3<T>& g) noexcept {
    return g.matrix();
  }
};

template <>
struct Batch<SE23> {
  static constexpr int N = 5, D = 9, P = 3;
  static constexpr const char* names[9] = {"se23_exp", "se23_log", "se23_compose",     "se23_inverse",  "se23_act",
                                           "se23_hat", "se23_vee", "se23_interpolate", "se23_normalize"};
  static constexpr const char *element = "X", *tangent = "xi",
                              *matrices = "extended pose matrices [[R, p, v], [0, 1, 0], [0, 0, 1]]",
                              *compose =
                                  "Composition of extended poses: a @ b = (R_a R_b, R_a p_b + p_a, R_a v_b + v_a).",
                              *inverse = "Inverse extended poses: (R^T, -R^T p, -R^T v).", *acted = "points",
                              *act = "Transformed points: q_a = R q_b + p (the velocity moves no point).",
                              *one = "extended pose", *moved = "transformed",
                              *product = ", the batch shape being\n    the broadcast of a's and b's.",
                              *interpolate = "Geodesic interpolation of extended poses",
                              *between = "one screw motion, the velocity along the same rotation",
                              *interpolated = "extended poses";
  static constexpr const char* exp = R"(Extended pose matrices of xi = (rho, nu, w): X = exp([xi]) (5x5).

R = exp([w]), p = V rho, v = V nu with V = J_l(w) = A I + B [w] + C w w^T
(SE3's exp applied to both translations: a few ulps for every xi).

Args:
    xi: array_like of shape (..., 9): (rho, nu, w).

Returns:
    numpy.ndarray of shape (..., 5, 5): the matrices [[R, p, v], [0, 1, 0], [0, 0, 1]].)";
  static constexpr const char* log = R"(The (rho, nu, w) of extended pose matrices: xi = log(X)^vee.

w = log(R) with |w| in [0, pi], rho = V^-1 p, nu = V^-1 v in closed form.

Args:
    X: array_like of shape (..., 5, 5): matrices [[R, p, v], [0, 1, 0], [0, 0, 1]].

Returns:
    numpy.ndarray of shape (..., 9): (rho, nu, w).)";
  static constexpr const char* hat =
      R"(Matrices of xi = (rho, nu, w): [xi] = [[ [w], rho, nu ], [0, 0, 0], [0, 0, 0]] (5x5).

Args:
    xi: array_like of shape (..., 9).

Returns:
    numpy.ndarray of shape (..., 5, 5): the matrices [xi].)";
  static constexpr const char* vee = R"(The (rho, nu, w) of 5x5 matrices: the inverse of se23_hat.

rho and nu are the top of the last two columns, w the antisymmetric part of
the top-left block; the bottom rows are not read.

Args:
    matrix: array_like of shape (..., 5, 5).

Returns:
    numpy.ndarray of shape (..., 9).)";
  static constexpr const char* normalize =
      R"(Extended pose matrices with the nearest rotation: SE23.normalized() over a batch.

The top-left block becomes the nearest rotation (so3_normalize), the
position and velocity columns are kept and the bottom rows become
[[0, 0, 0, 1, 0], [0, 0, 0, 0, 1]]. Non-finite matrices give NaN.

Args:
    X: array_like of shape (..., 5, 5): matrices.

Returns:
    numpy.ndarray of shape (..., 5, 5): the extended pose matrices.)";
  template <typename T>
  static Eigen::Matrix<T, 5, 5> stored(const SE23<T>& X) noexcept {
    return X.matrix();
  }
};

/// A tangent as a ufunc result: SO(2)'s angle as a scalar, others as they are.
template <typename V>
auto tangent_out(const V& x) noexcept {
  if constexpr (V::SizeAtCompileTime == 1) {
    return x[0];
  } else {
    return x;
  }
}

/// The element of G (over the matrix's scalar) of a matrix, taken as given.
template <template <typename> class Group, typename M>
Group<ScalarOf<M>> element_of(const M& m) noexcept {
  return Group<ScalarOf<M>>::from_matrix_unchecked(m);
}

/// exp, log, compose, inverse, act, hat, vee, interpolate and normalize of G.
template <template <typename> class Group>
void bind_group_batch(py::module_& m) {
  using B = Batch<Group>;
  constexpr int N = B::N, D = B::D, P = B::P;
  using TangentCore = std::conditional_t<D == 1, Core<>, Core<D>>;
  const std::string n = std::to_string(N), shape = "(..., " + n + ", " + n + ")";
  const std::string element = std::string(B::element), matrices = "array_like of shape " + shape + ": " + B::matrices;
  const std::string result = "numpy.ndarray of shape " + shape;
  def_ufunc<Core<N, N>(TangentCore)>(m, B::names[0], B::tangent, array_doc(B::exp), [](const auto& x) {
    using G = Group<ScalarOf<decltype(x)>>;
    return B::stored(G::exp(typename G::Tangent(x)));
  });
  def_ufunc<TangentCore(Core<N, N>)>(m, B::names[1], B::element, array_doc(B::log),
                                     [](const auto& g) { return tangent_out(element_of<Group>(g).log()); });
  def_ufunc<Core<N, N>(Core<N, N>, Core<N, N>)>(
      m, B::names[2], "a, b",
      array_doc((std::string(B::compose) + "\n\nArgs:\n    a: " + matrices + ".\n    b: " + matrices +
                 ".\n\nReturns:\n    " + result + ": the products" + B::product)
                    .c_str()),
      [](const auto& a, const auto& b) { return B::stored(element_of<Group>(a) * element_of<Group>(b)); });
  def_ufunc<Core<N, N>(Core<N, N>)>(m, B::names[3], B::element,
                                    array_doc((std::string(B::inverse) + "\n\nArgs:\n    " + element + ": " + matrices +
                                               ".\n\nReturns:\n    " + result + ": the inverses.")
                                                  .c_str()),
                                    [](const auto& g) { return B::stored(element_of<Group>(g).inverse()); });
  const std::string p = std::to_string(P);
  def_ufunc<Core<P>(Core<N, N>, Core<P>)>(
      m, B::names[4], (element + ", points").c_str(),
      array_doc((std::string(B::act) + "\n\nBroadcasts: one " + B::one + " of shape (" + n + ", " + n +
                 ") with points of shape (N, " + p + "), N\n" + B::one + "s with N points, (N, 1, " + n + ", " + n +
                 ") with (M, " + p + ") for every pair, ...\n\nArgs:\n    " + element + ": " + matrices +
                 ".\n    points: array_like of shape (..., " + p + "): " + B::acted +
                 ".\n\nReturns:\n    numpy.ndarray of shape (..., " + p + "): the " + B::moved + " points.")
                    .c_str()),
      [](const auto& g, const auto& p) { return element_of<Group>(g).act(p); });
  def_ufunc<Core<N, N>(TangentCore)>(m, B::names[5], B::tangent, array_doc(B::hat), [](const auto& x) {
    using G = Group<ScalarOf<decltype(x)>>;
    return G::hat(typename G::Tangent(x));
  });
  def_ufunc<TangentCore(Core<N, N>)>(m, B::names[6], "matrix", array_doc(B::vee),
                                     [](const auto& X) { return tangent_out(Group<ScalarOf<decltype(X)>>::vee(X)); });
  def_ufunc<Core<N, N>(Core<N, N>, Core<N, N>, Core<>)>(
      m, B::names[7], "a, b, t",
      array_doc((std::string(B::interpolate) + ": a exp(t log(a^-1 b)).\n\nt = 0 gives a, t = 1 gives b, " +
                 B::between + " in between.\n\nArgs:\n    a: " + matrices + " at t = 0.\n    b: " + matrices +
                 " at t = 1.\n    t: array_like of shape (...): the parameters (a Python float keeps\n        the "
                 "dtype of a and b).\n\nReturns:\n    " +
                 result + ": the interpolated " + B::interpolated + ".")
                    .c_str()),
      [](const auto& a, const auto& b, const auto& t) {
        return B::stored(chasles::interpolate(element_of<Group>(a), element_of<Group>(b), t));
      });
  // (from_matrix_projected gives the identity for a non-finite matrix: here, NaN.)
  def_ufunc<Core<N, N>(Core<N, N>)>(m, B::names[8], B::element, array_doc(B::normalize), [](const auto& M) {
    using T = ScalarOf<decltype(M)>;
    if (!M.allFinite()) return B::stored(element_of<Group>(Eigen::Matrix<T, N, N>::Constant(T(NAN))));
    return B::stored(Group<T>::from_matrix_projected(M));
  });
}

// ---- SO(3): quaternions -----------------------------------------------------

void bind_so3_batch(py::module_& m) {
  bind_group_batch<SO3>(m);
  def_ufunc<Core<3, 3>(Core<4>)>(m, "_so3_from_quat_xyzw", "quat", array_doc(kFromQuatDoc), from_quat_kernel<false>());
  def_ufunc<Core<3, 3>(Core<4>)>(m, "_so3_from_quat_wxyz", "quat", array_doc(kFromQuatDoc), from_quat_kernel<true>());
  def_ufunc<Core<4>(Core<3, 3>)>(m, "_so3_as_quat_xyzw", "R", array_doc(kAsQuatDoc), as_quat_kernel<false>());
  def_ufunc<Core<4>(Core<3, 3>)>(m, "_so3_as_quat_wxyz", "R", array_doc(kAsQuatDoc), as_quat_kernel<true>());
}

// ---- SE(3) and twists -------------------------------------------------------

void bind_se3_batch(py::module_& m) {
  bind_group_batch<SE3>(m);
  def_ufunc<Core<4, 4>(Core<4>, Core<3>)>(m, "_se3_from_quat_xyzw", "quat, translation", array_doc(kPoseFromQuatDoc),
                                          pose_from_quat_kernel<false>());
  def_ufunc<Core<4, 4>(Core<4>, Core<3>)>(m, "_se3_from_quat_wxyz", "quat, translation", array_doc(kPoseFromQuatDoc),
                                          pose_from_quat_kernel<true>());
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
}

}  // namespace

void bind_batch(py::module_& m) {
  bind_so3_batch(m);
  bind_se3_batch(m);
  bind_group_batch<SO2>(m);
  bind_group_batch<SE2>(m);
  bind_group_batch<Sim3>(m);
  bind_group_batch<SE23>(m);
}

}  // namespace chasles_py
