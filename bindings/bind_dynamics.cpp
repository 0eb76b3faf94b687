// chasles._core: class SpatialInertia over chasles::SpatialInertia<double>
// (include/chasles/spatial_inertia.hpp). The dynamics of chains are in
// bind_kinematics.cpp, with the chain.
#include <chasles/se3.hpp>
#include <chasles/spatial_inertia.hpp>
#include <chasles/twist.hpp>

#include <Eigen/Eigenvalues>

#include <string>

#include "bindings.hpp"
#include "conventions.hpp"
#include "convert.hpp"

namespace chasles_py {

namespace {

using InertiaD = chasles::SpatialInertia<double>;
using chasles::SE3d;
using chasles::Twistd;
using Vector3 = Eigen::Vector3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix3 = Eigen::Matrix3d;

const char* const kClassDoc = R"doc(The inertia of a rigid body described in some frame: mass m, center of mass c
and rotational inertia I_c about the center of mass, both in that frame.

Its 6x6 matrix is in the twist order (v, w), so that the momentum of the body
moving with the twist V = (v, w) is the wrench h = G V = (f, tau) (linear
momentum, then angular momentum about the frame's origin) and its kinetic
energy is 1/2 V^T G V:

    G = [[ m 1,     -m [c]         ],
         [ m [c],    I_c - m [c]^2 ]]

(Murray, Li and Sastry, ch. 4.2; Lynch and Park, Modern Robotics, ch. 8.2,
where the order is (w, v); Pinocchio's ``Inertia`` in the order (v, w)). The
same body described in frame a, given in frame b: ``I.transform(g_ab)``, with
c_a = R c_b + p, I_a = R I_c R^T and G_a = Ad_g^-T G_b Ad_g^-1.

The constructor accepts only inertias that a rigid body has. Chain's
link_inertias and Chain.from_urdf accept any (real robot descriptions have
some that break the triangle inequality); Chain.forward_dynamics raises
where they leave the mass matrix not positive definite.

Example:
    >>> body = SpatialInertia(2.0, [0.0, 0.0, 0.5], np.diag([0.1, 0.1, 0.02]))
    >>> body.momentum(Twist(v=[1.0, 0.0, 0.0], w=[0.0, 0.0, 0.0])).force
    array([2., 0., 0.])
    >>> body.kinetic_energy(Twist(v=[1.0, 0.0, 0.0], w=[0.0, 0.0, 0.0]))
    1.0
)doc";

std::string class_doc() { return std::string(kClassDoc) + kConventions; }

/// The checked constructor: finite numbers, m > 0, I_c symmetric, positive
/// definite, its principal moments satisfying the triangle inequality.
InertiaD checked_inertia(py::handle mass, py::handle com, py::handle inertia, const char* what) {
  const std::string w(what);
  const double m = to_finite_real(mass, (w + "(mass)").c_str());
  const Vector3 c = to_finite_eigen<3>(com, (w + "(com)").c_str());
  const Matrix3 I = to_finite_eigen<3, 3>(inertia, (w + "(inertia)").c_str());
  if (!(m > 0)) raise_value_error(w + "(mass): expected a positive mass, got " + short_float(m));
  const InertiaD body(m, c, I);
  if (body.is_physical()) return body;
  const double tol = chasles::Thresholds<double>::inertia_tolerance;
  const double scale = I.cwiseAbs().maxCoeff();  // the conditions are scale-invariant: no overflow below
  const Matrix3 Iu = scale > 0 ? Matrix3(I / scale) : I;
  const double asym = (Iu - Iu.transpose()).cwiseAbs().maxCoeff();
  if (!(asym <= tol))
    raise_value_error(w + "(inertia): not symmetric (max |I - I^T| = " + short_float(asym) +
                      " times its largest entry)");
  const Eigen::SelfAdjointEigenSolver<Matrix3> es(Matrix3((Iu + Iu.transpose()) / 2), Eigen::EigenvaluesOnly);
  const Vector3 moments = es.eigenvalues() * scale;
  if (!(es.eigenvalues().minCoeff() > 0))
    raise_value_error(w + "(inertia): not positive definite (principal moments " + values_string(moments) + ")");
  raise_value_error(w + "(inertia): the principal moments " + values_string(moments) +
                    " break the triangle inequality I_1 + I_2 >= I_3 of a rigid body");
}

/// A twist (v, w) given as a Twist or as anything array-like of shape (6,)
/// (as SE3.exp takes it).
Vector6 twist_vector(py::handle h, const char* what) {
  if (is_native_float64_array(h.ptr())) return to_finite_eigen<6>(h, what);
  py::detail::make_caster<Obj<Twistd>> caster;
  if (caster.load(h, false)) return static_cast<Obj<Twistd>&>(caster).ptr->vector();
  return to_finite_eigen<6>(h, what);
}

}  // namespace

void bind_dynamics(py::module_& m) {
  // ---- SpatialInertia ---------------------------------------------------------
  const std::string doc = class_doc();
  py::class_<InertiaD> cls(m, "SpatialInertia", doc.c_str());
  cls.attr("__array_ufunc__") = py::none();  // numpy defers operators (np.float64(1.0) == I) to us

  cls.def(py::init([](RealLike mass, ArrayLike com, ArrayLike inertia) {
            return checked_inertia(mass.obj, com.obj, inertia.obj, "SpatialInertia");
          }),
          py::arg("mass"), py::arg("com"), py::arg("inertia"),
          R"doc(A rigid body's inertia from its mass, center of mass and rotational inertia about it.

Args:
    mass: m > 0, finite.
    com: shape (3,), c, the center of mass in the frame of description.
    inertia: shape (3, 3), I_c, the rotational inertia about the center of
        mass (axes of that frame): symmetric, positive definite, with
        principal moments that satisfy the triangle inequality
        I_1 + I_2 >= I_3 (each to a relative 1.5e-8).

Raises:
    ValueError: a wrong shape, a non-finite number, m <= 0, or an inertia
        that no rigid body has (the message says which condition fails).

Example:
    >>> SpatialInertia(1.0, [0.0, 0.0, 0.0], np.eye(3)).mass
    1.0
)doc");

  cls.def_property_readonly("mass", [](Obj<InertiaD> I) { return I->mass(); }, "float: m, the mass.");
  cls.def_property_readonly(
      "com", [](Obj<InertiaD> I) { return vec_out<3>(I->com()); }, "ndarray: c, the center of mass, shape (3,).");
  cls.def_property_readonly(
      "inertia", [](Obj<InertiaD> I) { return mat_out<3, 3>(I->inertia()); },
      "ndarray: I_c, the rotational inertia about the center of mass, shape (3, 3).");
  cls.def_property_readonly(
      "matrix", [](Obj<InertiaD> I) { return mat_out<6, 6>(I->matrix()); },
      R"doc(ndarray: G, shape (6, 6), order (v, w): [[m 1, -m [c]], [m [c], I_c - m [c]^2]].)doc");

  cls.def(
      "transform", [](Obj<InertiaD> I, Obj<SE3d> g) { return I->transform(*g); }, py::arg("g"),
      R"doc(The same body described in frame a, this one describing it in frame b; g = g_ab (SE3).

c_a = R c + p, I_a = R I_c R^T, G_a = Ad_g^-T G Ad_g^-1: the kinetic energy of
a motion is the same in both frames. Returns a SpatialInertia.

Example:
    >>> body = SpatialInertia(1.0, [0.0, 0.0, 0.0], np.eye(3))
    >>> body.transform(SE3(translation=[1.0, 2.0, 3.0])).com
    array([1., 2., 3.])
)doc");

  cls.def(
      "momentum",
      [](Obj<InertiaD> I, ArrayLike twist) {
        return I->momentum(Twistd(twist_vector(twist.obj, "SpatialInertia.momentum(twist)")));
      },
      py::arg("twist"),
      R"doc(The momentum wrench h = G V = (m v_c, c x m v_c + I_c w), v_c = v + w x c.

twist: a Twist or shape (6,), V = (v, w) in the frame of description. Returns a
Wrench: (linear momentum, angular momentum about the frame's origin).

Example:
    >>> body = SpatialInertia(2.0, [0.0, 0.0, 0.0], np.eye(3))
    >>> body.momentum(Twist(w=[0.0, 0.0, 3.0])).torque
    array([0., 0., 3.])
)doc");

  cls.def(
      "kinetic_energy",
      [](Obj<InertiaD> I, ArrayLike twist) {
        return I->kinetic_energy(Twistd(twist_vector(twist.obj, "SpatialInertia.kinetic_energy(twist)")));
      },
      py::arg("twist"),
      R"doc(T = 1/2 V^T G V = 1/2 (m |v_c|^2 + w . I_c w), a float; twist: a Twist or shape (6,).

Example:
    >>> SpatialInertia(2.0, [0.0, 0.0, 0.0], np.eye(3)).kinetic_energy([1.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    1.0
)doc");

  cls.def(
      "__add__", [](Obj<InertiaD> a, Obj<InertiaD> b) { return *a + *b; }, py::arg("other"), py::is_operator(),
      R"doc(The two bodies rigidly joined (both described in the same frame): the matrices add.)doc");

  cls.def(
      "is_approx",
      [](Obj<InertiaD> a, Obj<InertiaD> b, RealLike tol) {
        return a->is_approx(*b, to_tolerance(tol.obj, "SpatialInertia.is_approx(tol)"));
      },
      py::arg("other"), py::arg_v("tol", 1e-9),
      R"doc(Whether m, c and I_c agree within tol (>= 0): max difference <= tol * max(1, their largest magnitude).

``==`` is the exact comparison.)doc");

  def_array(
      cls, [](const InertiaD& I) { return mat_out<6, 6>(I.matrix()); },
      "The matrix G, shape (6, 6), for np.asarray (numpy's dtype and copy keywords).");
  // The state: m, c (3), I_c row by row (9); rebuilt by the constructor's
  // checks (a pickle is data from outside), the numbers kept as they are.
  def_value_protocol<13>(
      cls,
      [](const InertiaD& I) {
        return "SpatialInertia(mass=" + float_repr(I.mass()) + ", com=" + array_repr(vec_out<3>(I.com())) +
               ", inertia=" + array_repr(mat_out<3, 3>(I.inertia())) + ")";
      },
      [](const InertiaD& I) {
        Eigen::Matrix<double, 13, 1> x;
        x << I.mass(), I.com(), row_major<3, 3>(I.inertia());
        return x;
      },
      [](const double* x) {
        return checked_inertia(
            py::float_(x[0]), vec_out<3>(Vector3(x + 1)),
            mat_out<3, 3>(Matrix3(Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(x + 4))),
            "SpatialInertia.__setstate__");
      });
}

}  // namespace chasles_py
