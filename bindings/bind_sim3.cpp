// chasles._core: class Sim3 over chasles::Sim3d (include/chasles/sim3.hpp):
// its traits Lie<Sim3d> (names and the texts only it has), then what only it
// has beside def_lie_group.
#include <chasles/sim3.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "lie_group.hpp"
#include "signatures.hpp"

namespace chasles_py {

template <>
struct Lie<chasles::Sim3d> : GroupNames<chasles::Sim3d> {
  static constexpr int N = 4, D = 7, P = 3;
  using Tangent = Eigen::Matrix<double, 7, 1>;
  using Jacobian = Eigen::Matrix<double, 7, 7>;
  static constexpr const char* tangent = "xi";
  static constexpr const char* act_ufunc = "sim3_act";
  static constexpr const char* act_hint = "a Sim3 composes only with a Sim3";
  static constexpr const char* inverse = "(R^T, -R^T t / s, 1 / s)";
  static constexpr const char* matrix = "The matrix g = [[s R, t], [0, 1]] (4x4)";
  static constexpr const char* example = "[0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7]";
  static constexpr const char* adjoint =
      "Ad_g = [[s R, [t] R, -t], [0, R, 0], [0, 0, 1]] (7x7), so that g [xi] g^-1 = [Ad_g xi].";
  static constexpr const char* between = "and the similarity in between is one screw motion with a steady scaling";
  static constexpr const char* approx =
      "rotations within tol (absolute), translations within\ntol * max(1, |t|_max), scales within tol * max(1, s)";
  static constexpr const char* tol = "the tolerance (>= 0)";
  static constexpr Jacobian (*jacobians[4])(const Tangent&) = {
      &chasles::Sim3d::right_jacobian, &chasles::Sim3d::left_jacobian, &chasles::Sim3d::right_jacobian_inverse,
      &chasles::Sim3d::left_jacobian_inverse};
  static constexpr const char* acted = "points";
  static constexpr const char* action = "q_a = s R q_b + t";
  static constexpr const char* symbol = "g";
  static constexpr const char* moved = "moved";
  static constexpr const char* act_example = R"doc(
Example:
    >>> Sim3(scale=2.0).act([[1.0, 0.0, 0.0], [0.0, 1.0, 1.0]])
    array([[2., 0., 0.],
           [0., 2., 2.]])
)doc";
  static Tangent tangent_arg(py::handle h, const char* what) { return to_finite_eigen<7>(h, what); }
  static constexpr const char* exp_doc = R"doc(The similarity exp([xi]) of xi = (v, w, sigma) (Sophus' order).

R = exp([w]), s = e^sigma, t = W v with W = A I + B [w] + C [w]^2 the
integral of e^(sigma u) exp(u [w]) over [0, 1]; A, B and C without a 0/0 in
either theta = |w| or sigma (a double series where both are small), a few
ulps over the whole domain.

Args:
    xi: (v, w, sigma), shape (7,), finite.

Returns:
    Sim3: exp([xi]).

Example:
    >>> g = Sim3.exp([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, np.log(2.0)])
    >>> round(g.scale, 12), np.round(g.translation, 12) + 0.0
    (2.0, array([1.44269504, 0.        , 0.        ]))
)doc";
  static constexpr const char* log_doc = R"doc(The xi = (v, w, sigma) with exp([xi]) = g, rotation angle |w| in [0, pi].

w = log(R) (SO3's), sigma = log(s), v = W^-1 t in closed form.

Returns:
    ndarray: xi = (v, w, sigma), shape (7,).

Example:
    >>> np.round(Sim3(translation=[1.0, 2.0, 3.0]).log(), 12) + 0.0
    array([1., 2., 3., 0., 0., 0., 0.])
)doc";
  static constexpr const char* hat_doc =
      R"doc(The 4x4 matrix [xi] = [[ [w] + sigma I, v ], [0, 0]] of xi = (v, w, sigma).

Args:
    xi: shape (7,).

Returns:
    ndarray: shape (4, 4).
)doc";
  static constexpr const char* vee_doc = R"doc(The (v, w, sigma) of a 4x4 matrix: the inverse of hat.

w from the antisymmetric part of the top-left block, sigma the mean of its
diagonal, v the last column's top; the bottom row is ignored.

Args:
    matrix: shape (4, 4).

Returns:
    ndarray: shape (7,).
)doc";
  static constexpr const char* from_matrix_doc = R"doc(Checked construction from a 4x4 matrix [[s R, t], [0, 1]].

s = |block|_F / sqrt(3); accepts M when the rotation defect of block / s and
the deviation of the bottom row from (0, 0, 0, 1) are both at most tol
(default sqrt(eps)).

Args:
    matrix: shape (4, 4), finite.
    tol: the largest accepted defect.

Returns:
    Sim3: the similarity.

Raises:
    ValueError: M is not a similarity within tol (the message gives the
        defects), or M is not finite, or not of shape (4, 4).

Example:
    >>> Sim3.from_matrix(np.diag([2.0, 2.0, 2.0, 1.0])).scale
    2.0
)doc";
  static constexpr const char* projected_doc =
      R"doc(The nearest rotation to the top-left block, its least-squares scale, and the translation.

s = tr(R^T block) / 3 for R the nearest rotation (1 when that is not
positive); the bottom row is not read.

Args:
    matrix: shape (4, 4), finite.

Returns:
    Sim3: the projected similarity.
)doc";
  static constexpr const char* unchecked_doc =
      R"doc(Construction without a check from [[s R, t], [*, *]], for valid data.

s = |block|_F / sqrt(3), R = block / s.

Args:
    matrix: shape (4, 4), finite.

Returns:
    Sim3: the similarity.
)doc";
  static constexpr const char* jacobian_doc = R"doc(The %s of Sim(3) at xi = (v, w, sigma), shape (7, 7).

Right (local) convention, as for the other groups:
exp(xi + dxi) = exp(xi) exp(J_r(xi) dxi + o(dxi)) and
exp(xi + dxi) = exp(J_l(xi) dxi + o(dxi)) exp(xi). J_l = phi(ad_xi),
phi(X) = (exp(X) - I) X^-1, by scaling and squaring of ad_xi, with the
diagonal blocks (W and SO(3)'s J_l) in closed form; J_r(xi) = J_l(-xi); the
inverses by the block formula. Accurate to about 10 eps for |v| and |sigma|
below 2, and to a few hundred eps at |v| = 100, |sigma| = 5.

Args:
    xi: (v, w, sigma), shape (7,), finite.

Returns:
    ndarray: shape (7, 7), float64.
)doc";
};

namespace {

using chasles::Sim3d;
using chasles::SO3d;
using Vector3 = Eigen::Vector3d;
using Matrix3 = Eigen::Matrix3d;
using Matrix4 = Eigen::Matrix4d;

/// The error of Sim3.from_matrix and of __setstate__.
[[noreturn]] void raise_not_similarity(const Matrix4& M, double tol, const char* fn, bool tol_argument) {
  const double s = Sim3d::matrix_scale(M);
  double row = 0.0;
  for (int j = 0; j < 4; ++j) row = std::max(row, std::abs(M(3, j) - (j == 3 ? 1.0 : 0.0)));
  const Matrix3 R = M.topLeftCorner<3, 3>() / s;
  std::string msg = std::string(fn) + ": not a similarity: the scale |block|_F / sqrt(3) is " + short_float(s) +
                    ", the rotation defect of block / scale is " +
                    (s > 0 ? short_float(SO3d::rotation_defect(R)) : std::string("undefined")) +
                    " (det = " + det_string(M.topLeftCorner<3, 3>().determinant()) +
                    ") and the bottom row differs from (0, 0, 0, 1) by " + short_float(row) +
                    "; tol = " + short_float(tol) + ". ";
  if (M.topLeftCorner<3, 3>().determinant() < 0) msg += "A negative determinant is a reflection. ";
  msg += std::string("Use Sim3.from_matrix_projected(matrix) for the nearest similarity") +
         (tol_argument ? ", or pass a larger tol." : ".");
  raise_value_error(msg);
}

/// The scale argument: a finite real number > 0.
double to_scale(py::handle h, const char* what) {
  const double s = to_finite_real(h, what);
  if (!(s > 0.0)) raise_value_error(std::string(what) + ": expected a positive scale (> 0), got " + float_repr(s));
  return s;
}

const char* const kSim3Doc =
    R"doc(A similarity transform of R^3: an element of Sim(3), stored as a rotation R (an SO3), a translation t and a scale s > 0.

Its matrix is g = [[s R, t], [0, 1]]; it maps frame b to frame a as
``q_a = s R q_b + t`` (``g @ q``), and composes as
``(R1, t1, s1) @ (R2, t2, s2) = (R1 R2, s1 R1 t2 + t1, s1 s2)``. The tangent
space is xi = (v, w, sigma) in Sophus' order, s = exp(sigma):
[xi] = [[ [w] + sigma I, v ], [0, 0]]. Monocular SLAM's and point-set
registration's group.

Example:
    >>> g = Sim3(SO3.exp([0.0, 0.0, np.pi / 2]), [1.0, 0.0, 0.0], 2.0)
    >>> np.round(g @ [1.0, 0.0, 0.0], 12) + 0.0
    array([1., 2., 0.])
    >>> Sim3.exp(g.log()).is_approx(g)
    True
)doc";

}  // namespace

void bind_sim3(Class<Sim3d>& cls) {
  cls.attr("__doc__") = kSim3Doc;
  hold_inline(cls);
  // The state: R row by row, t, s; checked as from_matrix checks a matrix.
  def_lie_group<13>(
      cls,
      [](const Sim3d& g) {
        return "Sim3(rotation=SO3(matrix=" + array_repr(mat_out<3, 3>(g.rotation().matrix())) +
               "), translation=" + array_repr(vec_out<3>(g.translation())) + ", scale=" + float_repr(g.scale()) + ")";
      },
      [](const Sim3d& g) {
        Eigen::Matrix<double, 13, 1> v;
        v << row_major(g.rotation().matrix()), g.translation(), g.scale();
        return v;
      },
      [](const double* v) {
        const Matrix3 R = Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(v);
        const Vector3 t(v[9], v[10], v[11]);
        const double s = v[12];
        require_finite(R, "Sim3.__setstate__");
        require_finite(t, "Sim3.__setstate__");
        if (!(s > 0.0) || !std::isfinite(s) || !SO3d::from_matrix(R, kRotationTolerance)) {
          Matrix4 M = Matrix4::Identity();
          M.topLeftCorner<3, 3>() = std::isfinite(s) ? Matrix3(s * R) : R;
          M.topRightCorner<3, 1>() = t;
          raise_not_similarity(M, kRotationTolerance, "Sim3.__setstate__", false);
        }
        return Sim3d(SO3d::from_matrix_unchecked(R), t, s);
      },
      raise_not_similarity);
  cls.attr("__array_ufunc__") = py::none();
  cls.def(py::init([](Obj<SO3d> rotation, ArrayLike translation, RealLike scale) {
            return Sim3d(*rotation, to_finite_eigen<3>(translation.obj, "Sim3(translation)"),
                         to_scale(scale.obj, "Sim3(scale)"));
          }),
          py::arg_v("rotation", SO3d(), "SO3()"),
          py::arg_v("translation", py::make_tuple(0.0, 0.0, 0.0), "(0.0, 0.0, 0.0)"), py::arg("scale") = 1.0,
          R"doc(The similarity g = [[s R, t], [0, 1]] of a rotation, a translation and a scale.

Args:
    rotation: SO3, R (default: the identity).
    translation: shape (3,), t, finite (default: 0).
    scale: s > 0, finite (default: 1).
)doc");
  def_refusal(cls, [](const py::args& args, const py::kwargs& kwargs) {
    return "Sim3(" + describe_arguments(args, kwargs) +
           "): Sim3(rotation, translation, scale) takes an SO3, a translation of shape (3,) and a scale > 0. "
           "A tangent (v, w, sigma) is Sim3.exp(xi); a 4x4 matrix Sim3.from_matrix(matrix) (checked), "
           "Sim3.from_matrix_projected(matrix) or Sim3.from_matrix_unchecked(matrix).";
  });
  cls.def_static("identity", &Sim3d::identity, "The identity similarity.");
  cls.def_property_readonly(
      "rotation", [](Obj<Sim3d> g) { return g->rotation(); }, "SO3: the rotation R of g = [[s R, t], [0, 1]].");
  cls.def_property_readonly(
      "translation", [](Obj<Sim3d> g) { return vec_out<3>(g->translation()); },
      "ndarray: the translation t, shape (3,) (a new array).");
  cls.def_property_readonly("scale", [](Obj<Sim3d> g) { return g->scale(); }, "float: the scale s > 0.");
  cls.def_static(
      "transform_defect",
      [](ArrayLike M) { return Sim3d::transform_defect(to_eigen<4, 4>(M.obj, "Sim3.transform_defect(matrix)")); },
      py::arg("matrix"), R"doc(How far a 4x4 matrix is from a similarity.

The rotation defect of its top-left block divided by its scale, or the
deviation of its bottom row from (0, 0, 0, 1), whichever is larger (inf for
a non-finite matrix or a zero block).

Args:
    matrix: shape (4, 4).

Returns:
    float: the defect.
)doc");
}

}  // namespace chasles_py
