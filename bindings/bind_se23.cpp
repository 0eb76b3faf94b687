// chasles._core: class SE23 over chasles::SE23d (include/chasles/se23.hpp):
// its traits Lie<SE23d> (names and the texts only it has), then what only it
// has beside def_lie_group.
#include <chasles/se23.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "lie_group.hpp"
#include "signatures.hpp"

namespace chasles_py {

template <>
struct Lie<chasles::SE23d> : GroupNames<chasles::SE23d> {
  static constexpr int N = 5, D = 9, P = 3;
  using Tangent = Eigen::Matrix<double, 9, 1>;
  using Jacobian = Eigen::Matrix<double, 9, 9>;
  static constexpr const char* tangent = "xi";
  static constexpr const char* act_ufunc = "se23_act";
  static constexpr const char* act_hint = "an SE23 composes only with an SE23";
  static constexpr const char* inverse = "(R^T, -R^T p, -R^T v)";
  static constexpr const char* matrix = "The matrix X = [[R, p, v], [0, 1, 0], [0, 0, 1]] (5x5)";
  static constexpr const char* example = "[0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9]";
  static constexpr const char* adjoint =
      "Ad_X = [[R, 0, [p] R], [0, R, [v] R], [0, 0, R]] (9x9), so that X [xi] X^-1 = [Ad_X xi].";
  static constexpr const char* between =
      "and the extended pose in between follows one screw motion, the velocity along the same rotation";
  static constexpr const char* approx =
      "rotations within tol (absolute), positions and velocities within\ntol * max(1, |x|_max)";
  static constexpr const char* tol = "the tolerance (>= 0)";
  static constexpr Jacobian (*jacobians[4])(const Tangent&) = {
      &chasles::SE23d::right_jacobian, &chasles::SE23d::left_jacobian, &chasles::SE23d::right_jacobian_inverse,
      &chasles::SE23d::left_jacobian_inverse};
  static constexpr const char* acted = "points";
  static constexpr const char* action = "q_a = R q_b + p";
  static constexpr const char* symbol = "X";
  static constexpr const char* moved = "moved";
  static constexpr const char* act_example = R"doc(
Example:
    >>> SE23(translation=[1.0, 0.0, 0.0], velocity=[5.0, 5.0, 5.0]).act([[1.0, 0.0, 0.0]])
    array([[2., 0., 0.]])
)doc";
  static Tangent tangent_arg(py::handle h, const char* what) { return to_finite_eigen<9>(h, what); }
  static constexpr const char* exp_doc = R"doc(The extended pose exp([xi]) of xi = (rho, nu, w).

R = exp([w]), p = V rho, v = V nu with V = J_l(w) = A I + B [w] + C w w^T:
SE3's exp applied to both translations, one sincos, a few ulps over the
whole domain. (manif orders its tangent (rho, w, nu), gtsam's NavState
(w, rho, nu).)

Args:
    xi: (rho, nu, w), shape (9,), finite.

Returns:
    SE23: exp([xi]).

Example:
    >>> X = SE23.exp([1.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 0.0])
    >>> X.translation, X.velocity
    (array([1., 0., 0.]), array([0., 2., 0.]))
)doc";
  static constexpr const char* log_doc = R"doc(The xi = (rho, nu, w) with exp([xi]) = X, rotation angle |w| in [0, pi].

w = log(R) (SO3's), rho = V^-1 p, nu = V^-1 v with
V^-1 = E I - 1/2 [w] + D w w^T, E = (theta/2) cot(theta/2).

Returns:
    ndarray: xi = (rho, nu, w), shape (9,).

Example:
    >>> SE23(translation=[1.0, 2.0, 3.0], velocity=[4.0, 5.0, 6.0]).log()
    array([1., 2., 3., 4., 5., 6., 0., 0., 0.])
)doc";
  static constexpr const char* hat_doc =
      R"doc(The 5x5 matrix [xi] = [[ [w], rho, nu ], [0, 0, 0], [0, 0, 0]] of xi = (rho, nu, w).

Args:
    xi: shape (9,).

Returns:
    ndarray: shape (5, 5).
)doc";
  static constexpr const char* vee_doc = R"doc(The (rho, nu, w) of a 5x5 matrix: the inverse of hat.

rho and nu are the top of the last two columns, w the antisymmetric part of
the top-left block; the bottom rows are not read.

Args:
    matrix: shape (5, 5).

Returns:
    ndarray: shape (9,).
)doc";
  static constexpr const char* from_matrix_doc =
      R"doc(Checked construction from a 5x5 matrix [[R, p, v], [0, 1, 0], [0, 0, 1]].

Accepts M when the rotation defect of its top-left block and the deviation
of its bottom rows from [[0, 1, 0], [0, 0, 1]] are both at most tol
(default sqrt(eps)).

Args:
    matrix: shape (5, 5), finite.
    tol: the largest accepted defect.

Returns:
    SE23: the extended pose.

Raises:
    ValueError: M is not an extended pose within tol (the message gives the
        defects), or M is not finite, or not of shape (5, 5).

Example:
    >>> SE23.from_matrix(np.eye(5)).velocity
    array([0., 0., 0.])
)doc";
  static constexpr const char* projected_doc =
      R"doc(The nearest rotation to the top-left block, with the position and velocity columns.

The bottom rows are not read.

Args:
    matrix: shape (5, 5), finite.

Returns:
    SE23: the projected extended pose.
)doc";
  static constexpr const char* unchecked_doc =
      R"doc(Construction without a check from [[R, p, v], [*]], for valid data.

Args:
    matrix: shape (5, 5), finite.

Returns:
    SE23: the extended pose.
)doc";
  static constexpr const char* jacobian_doc = R"doc(The %s of SE_2(3) at xi = (rho, nu, w), shape (9, 9).

Right (local) convention, as for the other groups:
exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi). SE3's, block by block:
J_l = [[J_l(w), 0, Q(rho, w)], [0, J_l(w), Q(nu, w)], [0, 0, J_l(w)]];
J_r(xi) = J_l(-xi); the inverses by the block formula.

Args:
    xi: (rho, nu, w), shape (9,), finite.

Returns:
    ndarray: shape (9, 9), float64.
)doc";
};

namespace {

using chasles::SE23d;
using chasles::SO3d;
using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;
using Matrix5 = Eigen::Matrix<double, 5, 5>;

/// The error of SE23.from_matrix and of __setstate__.
[[noreturn]] void raise_not_extended_pose(const Matrix5& M, double tol, const char* fn, bool tol_argument) {
  double rows = 0.0;
  for (int i = 3; i < 5; ++i)
    for (int j = 0; j < 5; ++j) rows = std::max(rows, std::abs(M(i, j) - (i == j ? 1.0 : 0.0)));
  const Matrix3 R = M.topLeftCorner<3, 3>();
  std::string msg = std::string(fn) + ": not an extended pose: the rotation defect of the top-left block is " +
                    short_float(SO3d::rotation_defect(R)) + " (det R = " + det_string(R.determinant()) +
                    ") and the bottom rows differ from [[0, 0, 0, 1, 0], [0, 0, 0, 0, 1]] by " + short_float(rows) +
                    "; tol = " + short_float(tol) + ". ";
  if (R.determinant() < 0) msg += "A negative determinant is a reflection, not a rotation. ";
  msg += std::string("Use SE23.from_matrix_projected(matrix) for the nearest rotation") +
         (tol_argument ? ", or pass a larger tol." : ".");
  raise_value_error(msg);
}

const char* const kSE23Doc =
    R"doc(An extended pose: an element of SE_2(3), stored as a rotation R (an SO3), a position p and a velocity v.

Its matrix is X = [[R, p, v], [0, 1, 0], [0, 0, 1]] (5x5, manif's layout);
it composes as ``(R1, p1, v1) @ (R2, p2, v2) = (R1 R2, R1 p2 + p1, R1 v2 + v1)``
and acts on points as ``q_a = R q_b + p`` (``X @ q``; the velocity moves no
point). The tangent is xi = (rho, nu, w), in the order of the matrix's
columns: [xi] = [[ [w], rho, nu ], [0, 0, 0], [0, 0, 0]]. manif orders it
(rho, w, nu), gtsam's NavState (w, rho, nu). The state of IMU
preintegration and of invariant Kalman filters.

Example:
    >>> X = SE23(SO3.exp([0.0, 0.0, np.pi / 2]), [1.0, 0.0, 0.0], [0.0, 0.0, 2.0])
    >>> np.round(X @ [1.0, 0.0, 0.0], 12) + 0.0
    array([1., 1., 0.])
    >>> SE23.exp(X.log()).is_approx(X)
    True
)doc";

}  // namespace

void bind_se23(Class<SE23d>& cls) {
  cls.attr("__doc__") = kSE23Doc;
  hold_inline(cls);
  // The state: R row by row, p, v; checked as from_matrix checks a matrix.
  def_lie_group<15>(
      cls,
      [](const SE23d& X) {
        return "SE23(rotation=SO3(matrix=" + array_repr(mat_out<3, 3>(X.rotation().matrix())) +
               "), translation=" + array_repr(vec_out<3>(X.translation())) +
               ", velocity=" + array_repr(vec_out<3>(X.velocity())) + ")";
      },
      [](const SE23d& X) {
        Eigen::Matrix<double, 15, 1> s;
        s << row_major(X.rotation().matrix()), X.translation(), X.velocity();
        return s;
      },
      [](const double* s) {
        Matrix5 M = Matrix5::Identity();
        M.topLeftCorner<3, 3>() = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(s);
        M.block<3, 1>(0, 3) = Vector3(s[9], s[10], s[11]);
        M.block<3, 1>(0, 4) = Vector3(s[12], s[13], s[14]);
        require_finite(M, "SE23.__setstate__");
        if (!SE23d::from_matrix(M, kRotationTolerance))
          raise_not_extended_pose(M, kRotationTolerance, "SE23.__setstate__", false);
        return SE23d::from_matrix_unchecked(M);
      },
      raise_not_extended_pose);
  cls.attr("__array_ufunc__") = py::none();
  cls.def(py::init([](Obj<SO3d> rotation, ArrayLike translation, ArrayLike velocity) {
            return SE23d(*rotation, to_finite_eigen<3>(translation.obj, "SE23(translation)"),
                         to_finite_eigen<3>(velocity.obj, "SE23(velocity)"));
          }),
          py::arg_v("rotation", SO3d(), "SO3()"),
          py::arg_v("translation", py::make_tuple(0.0, 0.0, 0.0), "(0.0, 0.0, 0.0)"),
          py::arg_v("velocity", py::make_tuple(0.0, 0.0, 0.0), "(0.0, 0.0, 0.0)"),
          R"doc(The extended pose X = [[R, p, v], [0, 1, 0], [0, 0, 1]] of a rotation, a position and a velocity.

Args:
    rotation: SO3, R (default: the identity).
    translation: shape (3,), the position p, finite (default: 0).
    velocity: shape (3,), v, finite (default: 0).
)doc");
  def_refusal(cls, [](const py::args& args, const py::kwargs& kwargs) {
    return "SE23(" + describe_arguments(args, kwargs) +
           "): SE23(rotation, translation, velocity) takes an SO3 and two vectors of shape (3,). A tangent "
           "(rho, nu, w) is SE23.exp(xi); a 5x5 matrix SE23.from_matrix(matrix) (checked), "
           "SE23.from_matrix_projected(matrix) or SE23.from_matrix_unchecked(matrix).";
  });
  cls.def_static("identity", &SE23d::identity, "The identity extended pose.");
  cls.def_property_readonly("rotation", [](Obj<SE23d> X) { return X->rotation(); }, "SO3: the rotation R of X.");
  cls.def_property_readonly(
      "translation", [](Obj<SE23d> X) { return vec_out<3>(X->translation()); },
      "ndarray: the position p, shape (3,) (a new array): the column that acts on points.");
  cls.def_property_readonly(
      "velocity", [](Obj<SE23d> X) { return vec_out<3>(X->velocity()); },
      "ndarray: the velocity v, shape (3,) (a new array).");
  cls.def_static(
      "transform_defect",
      [](ArrayLike M) { return SE23d::transform_defect(to_eigen<5, 5>(M.obj, "SE23.transform_defect(matrix)")); },
      py::arg("matrix"), R"doc(How far a 5x5 matrix is from an extended pose.

The rotation defect of its top-left block or the deviation of its bottom
rows from [[0, 0, 0, 1, 0], [0, 0, 0, 0, 1]], whichever is larger (inf for a
non-finite matrix).

Args:
    matrix: shape (5, 5).

Returns:
    float: the defect.
)doc");
}

}  // namespace chasles_py
