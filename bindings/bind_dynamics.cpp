// chasles._core: class SpatialInertia over chasles::SpatialInertia<double>
// (include/chasles/spatial_inertia.hpp), and the private ufuncs of the
// dynamics of a serial chain over chasles::Dynamics<double, Dynamic, 32>
// (include/chasles/dynamics.hpp), for the Chain methods to call.
#include <chasles/dynamics.hpp>
#include <chasles/spatial_inertia.hpp>

#include <Eigen/Eigenvalues>

#include <cstddef>
#include <string>
#include <tuple>

#include "bindings.hpp"
#include "conventions.hpp"
#include "convert.hpp"
#include "ufunc.hpp"

namespace chasles_py {

namespace {

constexpr int kMaxJoints = 32;
using DynD = chasles::Chain<double, Eigen::Dynamic, kMaxJoints>;
using InertiaD = chasles::SpatialInertia<double>;
using chasles::SE3d;
using chasles::Twistd;
using chasles::Wrenchd;
using Vector3 = Eigen::Vector3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix3 = Eigen::Matrix3d;
using Matrix4 = Eigen::Matrix4d;
using Matrix6 = Eigen::Matrix<double, 6, 6>;

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

// ---- the dynamics ufuncs ------------------------------------------------------
//
// Operands: the space screws S (n, 6), one row (v, w) per joint; the home
// pose M (4, 4); the links' spatial inertias (n, 6, 6), each the matrix G
// (order (v, w)) of the link described in the base frame at home; gravity
// (3) in the base frame; the joint arrays (n); the tip wrench (6), (f, tau),
// that the tool applies on the environment, in the tool frame; n <= 32
// bound at run time. Registered by def_ufunc (ufunc.hpp) with the model
// (chasles::Dynamics) made of the first operands (screws, home, inertias,
// and gravity where the ufunc has it), built once per loop when they stay
// put (outer strides 0). float64 only: the model is.

using ufunc::Core;
using ufunc::upto;
using JointsCore = Core<upto<kMaxJoints>>;
using ScrewsCore = Core<upto<kMaxJoints>, 6>;
using InertiasCore = Core<upto<kMaxJoints>, 6, 6>;

/// The model of the screws, home, inertias (and gravity) operands; zero
/// gravity without one (mass matrix, Coriolis).
struct DynamicsOf {
  template <typename S, typename M, typename G>
  DynD operator()(const S& screws, const M& home, const G& inertias) const noexcept {
    return (*this)(screws, home, inertias, Vector3::Zero());
  }
  template <typename S, typename M, typename G, typename V>
  DynD operator()(const S& screws, const M& home, const G& inertias, const V& gravity) const noexcept {
    DynD::Inertias I;
    for (Eigen::Index i = 0; i < inertias.size(); ++i)
      I[static_cast<std::size_t>(i)] = InertiaD::from_matrix_unchecked(Matrix6(inertias[i]));
    return DynD(DynD::Screws(screws.transpose()), SE3d::from_matrix_unchecked(Matrix4(home)), DynD::HomeAsGiven(), I,
                Vector3(gravity));
  }
};

using Joints = DynD::JointVector;

struct InverseDynamics {
  template <typename Q, typename Qd, typename Qdd, typename F>
  Joints operator()(const DynD& d, const Q& q, const Qd& qd, const Qdd& qdd, const F& tip) const noexcept {
    return chasles::inverse_dynamics(d, Joints(q), Joints(qd), Joints(qdd), Wrenchd(Vector6(tip)));
  }
};
/// (qdd, joint): the accelerations (NaN where M(q) is not positive
/// definite) and the joint of the failed pivot (-1 when none).
struct ForwardDynamics {
  template <typename Q, typename Qd, typename Tau, typename F>
  std::tuple<Joints, int> operator()(const DynD& d, const Q& q, const Qd& qd, const Tau& tau, const F& tip) const
      noexcept {
    const auto r = chasles::forward_dynamics(d, Joints(q), Joints(qd), Joints(tau), Wrenchd(Vector6(tip)));
    return {r.qdd, static_cast<int>(r.joint)};
  }
};
struct MassMatrix {
  template <typename Q>
  DynD::MassMatrix operator()(const DynD& d, const Q& q) const noexcept {
    return chasles::mass_matrix(d, Joints(q));
  }
};
struct GravityTorques {
  template <typename Q>
  Joints operator()(const DynD& d, const Q& q) const noexcept {
    return chasles::gravity_torques(d, Joints(q));
  }
};
struct Coriolis {
  template <typename Q, typename Qd>
  Joints operator()(const DynD& d, const Q& q, const Qd& qd) const noexcept {
    return chasles::coriolis(d, Joints(q), Joints(qd));
  }
};

const char* const kOperands = R"doc(

Operands (float64; numpy broadcasts the leading axes, the GIL is released):
    screws: (n, 6), 1 <= n <= 32, the space screws S_i, one row (v, w) per
        joint (the joint twists at home, base frame).
    home: (4, 4), M, the tool frame at home.
    inertias: (n, 6, 6), the matrix G (order (v, w), SpatialInertia.matrix)
        of each link (the body moved by joint i) described in the base frame
        at home; assumed physical (SpatialInertia checks that).)doc";

const char* const kGravity = R"doc(
    gravity: (3,), the gravitational acceleration in the base frame, e.g.
        (0, 0, -9.81).)doc";

const char* const kTip = R"doc(
    tip_wrench: (6,), (f, tau), the wrench the tool applies on the
        environment, in the tool frame (Modern Robotics' Ftip, reordered).)doc";

const char* const kPrivate = R"doc(

A private array function of chasles (the Chain methods call it); the
algorithm is chasles::Dynamics (include/chasles/dynamics.hpp): recursive
Newton-Euler and composite rigid bodies in the base frame.)doc";

}  // namespace

void bind_dynamics(py::module_& m) {
  const std::string inverse_doc =
      std::string("tau = M(q) qdd + C(q, qd) qd + g(q) + J_b(q)^T F_tip, by the recursive Newton-Euler algorithm.") +
      kOperands + kGravity + R"doc(
    q, qd, qdd: (n,), joint positions, velocities, accelerations.)doc" + kTip + R"doc(

Returns:
    numpy.ndarray: (..., n), the joint forces (torques, or forces of
    prismatic joints).)doc" + kPrivate;
  using ufunc::def_ufunc;
  using ufunc::Float64;
  using ufunc::model;
  // (n,6),(4,4),(n,6,6),(3),(n),(n),(n),(6)->(n)
  def_ufunc<JointsCore(ScrewsCore, Core<4, 4>, InertiasCore, Core<3>, JointsCore, JointsCore, JointsCore, Core<6>),
            Float64>(m, "_inverse_dynamics", "screws, home, inertias, gravity, q, qd, qdd, tip_wrench", inverse_doc,
                     model<4>(DynamicsOf()), InverseDynamics());
  const std::string forward_doc =
      std::string("qdd = M(q)^-1 (tau - C(q, qd) qd - g(q) - J_b(q)^T F_tip), by a Cholesky solve.") + kOperands +
      kGravity + R"doc(
    q, qd, tau: (n,), joint positions, velocities and forces.)doc" + kTip + R"doc(

Returns:
    (qdd, joint): qdd (..., n), the joint accelerations; joint (...),
    int32, -1, or where M(q) is not positive definite (its Cholesky
    factorization fails: chasles::DynamicsStatus) the joint of the failed
    pivot, and that element's qdd is NaN. Chain.forward_dynamics raises
    there unless on_failure="nan".)doc" + kPrivate;
  // (n,6),(4,4),(n,6,6),(3),(n),(n),(n),(6)->(n),()
  def_ufunc<std::tuple<JointsCore, ufunc::Typed<Core<>, int>>(ScrewsCore, Core<4, 4>, InertiasCore, Core<3>,
                                                              JointsCore, JointsCore, JointsCore, Core<6>),
            Float64>(m, "_forward_dynamics", "screws, home, inertias, gravity, q, qd, tau, tip_wrench", forward_doc,
                     model<4>(DynamicsOf()), ForwardDynamics());
  const std::string mass_doc = std::string("M(q), the joint-space mass matrix (T = 1/2 qd^T M qd), by composite rigid bodies.") +
                               kOperands + R"doc(
    q: (n,), joint positions.

Returns:
    numpy.ndarray: (..., n, n), symmetric positive definite.)doc" + kPrivate;
  // (n,6),(4,4),(n,6,6),(n)->(n,n)
  def_ufunc<Core<upto<kMaxJoints>, upto<kMaxJoints>>(ScrewsCore, Core<4, 4>, InertiasCore, JointsCore), Float64>(
      m, "_mass_matrix", "screws, home, inertias, q", mass_doc, model<3>(DynamicsOf()), MassMatrix());
  const std::string gravity_doc =
      std::string("g(q), the joint forces that hold the chain still against gravity.") + kOperands + kGravity +
      R"doc(
    q: (n,), joint positions.

Returns:
    numpy.ndarray: (..., n).)doc" + kPrivate;
  // (n,6),(4,4),(n,6,6),(3),(n)->(n)
  def_ufunc<JointsCore(ScrewsCore, Core<4, 4>, InertiasCore, Core<3>, JointsCore), Float64>(
      m, "_gravity_torques", "screws, home, inertias, gravity, q", gravity_doc, model<4>(DynamicsOf()),
      GravityTorques());
  const std::string coriolis_doc =
      std::string("C(q, qd) qd, the Coriolis and centrifugal joint forces (without gravity).") + kOperands + R"doc(
    q, qd: (n,), joint positions and velocities.

Returns:
    numpy.ndarray: (..., n).)doc" + kPrivate;
  // (n,6),(4,4),(n,6,6),(n),(n)->(n)
  def_ufunc<JointsCore(ScrewsCore, Core<4, 4>, InertiasCore, JointsCore, JointsCore), Float64>(
      m, "_coriolis", "screws, home, inertias, q, qd", coriolis_doc, model<3>(DynamicsOf()), Coriolis());

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

  cls.def_property_readonly(
      "mass", [](Obj<InertiaD> I) { return I->mass(); }, "float: m, the mass.");
  cls.def_property_readonly(
      "com", [](Obj<InertiaD> I) { return vec_out<3>(I->com()); }, "ndarray: c, the center of mass, shape (3,).");
  cls.def_property_readonly(
      "inertia", [](Obj<InertiaD> I) { return mat_out<3, 3>(I->inertia()); },
      "ndarray: I_c, the rotational inertia about the center of mass, shape (3, 3).");
  cls.def_property_readonly(
      "matrix", [](Obj<InertiaD> I) { return mat_out<6, 6>(I->matrix()); },
      R"doc(ndarray: G, shape (6, 6), order (v, w): [[m 1, -m [c]], [m [c], I_c - m [c]^2]].)doc");

  cls.def(
      "transform",
      [](Obj<InertiaD> I, Obj<SE3d> g) { return I->transform(*g); },
      py::arg("g"),
      R"doc(The same body described in frame a, this one describing it in frame b; g = g_ab.

c_a = R c + p, I_a = R I_c R^T; the matrix is Ad_g^-T G Ad_g^-1, so the
kinetic energy of a motion is the same in both frames:
``I.transform(g).kinetic_energy(g.act(V)) == I.kinetic_energy(V)``.

Args:
    g: SE3, g_ab.

Returns:
    SpatialInertia.

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

Args:
    twist: Twist or shape (6,), V = (v, w), the body's twist in the frame of description.

Returns:
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
      R"doc(T = 1/2 V^T G V = 1/2 (m |v_c|^2 + w . I_c w).

Args:
    twist: Twist or shape (6,), V = (v, w).

Returns:
    float.

Example:
    >>> SpatialInertia(2.0, [0.0, 0.0, 0.0], np.eye(3)).kinetic_energy([1.0, 0.0, 0.0, 0.0, 0.0, 0.0])
    1.0
)doc");

  cls.def(
      "__add__", [](Obj<InertiaD> a, Obj<InertiaD> b) { return *a + *b; }, py::arg("other"), py::is_operator(),
      R"doc(The two bodies rigidly joined (both described in the same frame): the matrices add.

Args:
    other: SpatialInertia.

Returns:
    SpatialInertia.
)doc");

  cls.def(
      "is_approx",
      [](Obj<InertiaD> a, Obj<InertiaD> b, RealLike tol) {
        return a->is_approx(*b, to_tolerance(tol.obj, "SpatialInertia.is_approx(tol)"));
      },
      py::arg("other"), py::arg_v("tol", 1e-9),
      R"doc(Whether m, c and I_c agree within tol: max difference <= tol * max(1, their largest magnitude).

``==`` is the exact comparison.

Args:
    other: SpatialInertia.
    tol: the tolerance (>= 0).

Returns:
    bool.
)doc");

  def_equality(cls, [](const InertiaD& a, const InertiaD& b) {
    return a.mass() == b.mass() && a.com() == b.com() && a.inertia() == b.inertia();
  });
  def_repr(cls, [](const InertiaD& I) {
    return "SpatialInertia(mass=" + float_repr(I.mass()) + ", com=" + array_repr(vec_out<3>(I.com())) +
           ", inertia=" + array_repr(mat_out<3, 3>(I.inertia())) + ")";
  });
  cls.def(
      "__array__",
      [](Obj<InertiaD> I, DTypeLike dtype, CopyFlag copy) {
        return array_protocol(mat_out<6, 6>(I->matrix()), dtype, copy, "SpatialInertia");
      },
      py::arg_v("dtype", py::none(), "None"), py::arg_v("copy", py::none(), "None"),
      "The matrix G, shape (6, 6), for np.asarray (numpy's dtype and copy keywords).");
  def_array_dtype(cls);
  cls.def("__copy__", [](Obj<InertiaD> I) { return *I; });
  cls.def("__deepcopy__", [](Obj<InertiaD> I, const py::object&) { return *I; }, py::arg("memo"));
  // The state: m, c (3), I_c row by row (9); rebuilt by the constructor's
  // checks, the numbers kept as they are.
  cls.def(py::pickle(
      [](Obj<InertiaD> I) {
        py::tuple t(13);
        t[0] = py::float_(I->mass());
        for (int i = 0; i < 3; ++i) t[static_cast<std::size_t>(1 + i)] = py::float_(I->com()(i));
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) t[static_cast<std::size_t>(4 + 3 * i + j)] = py::float_(I->inertia()(i, j));
        return t;
      },
      [](const py::object& state) {
        const py::tuple t = state_tuple(state, 13, "SpatialInertia");
        double mass;
        Vector3 c;
        Eigen::Matrix<double, 3, 3, Eigen::RowMajor> I;
        read_state(t, 0, 1, &mass, "SpatialInertia");
        read_state(t, 1, 3, c.data(), "SpatialInertia");
        read_state(t, 4, 9, I.data(), "SpatialInertia");
        // The constructor's checks and errors (a pickle is data from outside).
        return checked_inertia(py::float_(mass), vec_out<3>(c), mat_out<3, 3>(Matrix3(I)),
                               "SpatialInertia.__setstate__");
      }));
  add_reduce(cls);
}

}  // namespace chasles_py
