// chasles._core: class SpatialInertia over chasles::SpatialInertia<double>
// (include/chasles/spatial_inertia.hpp), and the private ufuncs of the
// dynamics of a serial chain over chasles::Dynamics<double, Dynamic, 32>
// (include/chasles/dynamics.hpp), for the Chain methods to call.
#include <chasles/dynamics.hpp>
#include <chasles/spatial_inertia.hpp>

#include <Eigen/Eigenvalues>

#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>

#include "bindings.hpp"
#include "conventions.hpp"
#include "convert.hpp"
#include "numpy_capi.hpp"
#include "ufunc.hpp"

namespace chasles_py {

namespace {

constexpr int kMaxJoints = 32;
using DynD = chasles::Dynamics<double, Eigen::Dynamic, kMaxJoints>;
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
// that the tool applies on the environment, in the tool frame. float64 only.
// The model is built once per loop when S, M, the inertias and gravity stay
// put (outer strides 0).

enum class DynOp { inverse, mass, gravity, coriolis, forward };
enum class Kind { screws, home, inertias, gravity, joints, wrench };

constexpr int ndim_of(Kind k) {
  return k == Kind::screws || k == Kind::home ? 2 : k == Kind::inertias ? 3 : 1;
}

template <DynOp Op>
constexpr auto kinds_of() {
  using K = Kind;
  if constexpr (Op == DynOp::inverse || Op == DynOp::forward)
    return std::array<K, 8>{K::screws, K::home, K::inertias, K::gravity, K::joints, K::joints, K::joints, K::wrench};
  else if constexpr (Op == DynOp::mass)
    return std::array<K, 4>{K::screws, K::home, K::inertias, K::joints};
  else if constexpr (Op == DynOp::gravity)
    return std::array<K, 5>{K::screws, K::home, K::inertias, K::gravity, K::joints};
  else
    return std::array<K, 5>{K::screws, K::home, K::inertias, K::joints, K::joints};
}

template <DynOp Op>
void dynamics_loop(char** args, const npy_intp* dims, const npy_intp* steps, void* /*data*/) noexcept {
  constexpr auto kinds = kinds_of<Op>();
  constexpr std::size_t N = kinds.size();
  constexpr int out_ndim = Op == DynOp::mass ? 2 : 1;
  const npy_intp count = dims[0], n = dims[1];  // the outer size, then the core sizes (n first)
  std::array<std::array<npy_intp, 3>, N + 1> cs{};
  const npy_intp* s = steps + N + 1;
  for (std::size_t j = 0; j < N; ++j)
    for (int k = 0; k < ndim_of(kinds[j]); ++k) cs[j][static_cast<std::size_t>(k)] = *s++;
  for (int k = 0; k < out_ndim; ++k) cs[N][static_cast<std::size_t>(k)] = *s++;
  const auto rd = [](const char* p, npy_intp off) { return *reinterpret_cast<const double*>(p + off); };
  const auto write = [&](char* out, npy_intp r, npy_intp c, double x) {
    *reinterpret_cast<double*>(out + r * cs[N][0] + c * cs[N][1]) = x;
  };
  const npy_intp cols = out_ndim == 2 ? n : 1;
  if (n < 1 || n > kMaxJoints) {  // only the Chain methods call these, with 1 <= n <= 32
    for (npy_intp e = 0; e < count; ++e)
      for (npy_intp r = 0; r < n; ++r)
        for (npy_intp c = 0; c < cols; ++c) write(args[N] + e * steps[N], r, c, std::numeric_limits<double>::quiet_NaN());
    return;
  }
  bool fixed = true;  // the model stays put: built once
  for (std::size_t j = 0; j < N; ++j)
    if (kinds[j] != Kind::joints && kinds[j] != Kind::wrench && steps[j] != 0) fixed = false;
  std::optional<DynD> model;
  std::array<DynD::JointVector, 3> joint;
  Wrenchd tip;
  for (npy_intp e = 0; e < count; ++e) {
    if (!fixed || !model) {
      DynD::Screws S(6, n);
      Matrix4 M;
      DynD::Inertias I;
      Vector3 gravity = Vector3::Zero();
      for (std::size_t j = 0; j < N; ++j) {
        const char* p = args[j] + e * steps[j];
        const auto& c = cs[j];
        switch (kinds[j]) {
          case Kind::screws:
            for (npy_intp i = 0; i < n; ++i)
              for (npy_intp k = 0; k < 6; ++k) S(k, i) = rd(p, i * c[0] + k * c[1]);
            break;
          case Kind::home:
            for (int r = 0; r < 4; ++r)
              for (int k = 0; k < 4; ++k) M(r, k) = rd(p, r * c[0] + k * c[1]);
            break;
          case Kind::inertias:
            for (npy_intp i = 0; i < n; ++i) {
              Matrix6 G;
              for (int r = 0; r < 6; ++r)
                for (int k = 0; k < 6; ++k) G(r, k) = rd(p, i * c[0] + r * c[1] + k * c[2]);
              I[static_cast<std::size_t>(i)] = InertiaD::from_matrix_unchecked(G);
            }
            break;
          case Kind::gravity:
            for (int k = 0; k < 3; ++k) gravity(k) = rd(p, k * c[0]);
            break;
          default:
            break;
        }
      }
      model.emplace(S, SE3d::from_matrix_unchecked(M), I, gravity);
    }
    std::size_t next = 0;
    for (std::size_t j = 0; j < N; ++j) {
      const char* p = args[j] + e * steps[j];
      if (kinds[j] == Kind::joints) {
        DynD::JointVector& v = joint[next++];
        v.resize(n);
        for (npy_intp i = 0; i < n; ++i) v(i) = rd(p, i * cs[j][0]);
      } else if (kinds[j] == Kind::wrench) {
        for (int k = 0; k < 6; ++k) tip.vector()(k) = rd(p, k * cs[j][0]);
      }
    }
    char* out = args[N] + e * steps[N];
    if constexpr (Op == DynOp::mass) {
      const DynD::MassMatrix Mq = model->mass_matrix(joint[0]);
      for (npy_intp r = 0; r < n; ++r)
        for (npy_intp c = 0; c < n; ++c) write(out, r, c, Mq(r, c));
    } else {
      DynD::JointVector tau;
      if constexpr (Op == DynOp::inverse)
        tau = model->inverse_dynamics(joint[0], joint[1], joint[2], tip);
      else if constexpr (Op == DynOp::forward)
        tau = model->forward_dynamics(joint[0], joint[1], joint[2], tip);
      else if constexpr (Op == DynOp::gravity)
        tau = model->gravity_torques(joint[0]);
      else
        tau = model->coriolis(joint[0], joint[1]);
      for (npy_intp r = 0; r < n; ++r) write(out, r, 0, tau(r));
    }
  }
  ufunc::clear_floating_point_flags();
}

template <DynOp Op>
void dynamics_ufunc(py::module_& m, const char* name, const char* signature, const char* params, const char* doc) {
  constexpr std::size_t N = kinds_of<Op>().size();
  static PyUFuncGenericFunction funcs[] = {&dynamics_loop<Op>};
  static void* data[] = {nullptr};
  static char types[N + 1];
  for (std::size_t j = 0; j <= N; ++j) types[j] = NPY_DOUBLE;
  static const std::string doc_kept = doc;
  PyObject* u = PyUFunc_FromFuncAndDataAndSignature(funcs, data, types, 1, static_cast<int>(N), 1, PyUFunc_None, name,
                                                    doc_kept.c_str(), 0, signature);
  if (u == nullptr) throw py::error_already_set();
  py::object ufunc = py::reinterpret_steal<py::object>(u);
  ufunc::describe_ufunc(ufunc, name, params, doc);
  m.attr(name) = ufunc;
}

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
  dynamics_ufunc<DynOp::inverse>(m, "_inverse_dynamics", "(n,6),(4,4),(n,6,6),(3),(n),(n),(n),(6)->(n)",
                                 "screws, home, inertias, gravity, q, qd, qdd, tip_wrench", inverse_doc.c_str());
  const std::string forward_doc =
      std::string("qdd = M(q)^-1 (tau - C(q, qd) qd - g(q) - J_b(q)^T F_tip), by a Cholesky solve.") + kOperands +
      kGravity + R"doc(
    q, qd, tau: (n,), joint positions, velocities and forces.)doc" + kTip + R"doc(

Returns:
    numpy.ndarray: (..., n), the joint accelerations.)doc" + kPrivate;
  dynamics_ufunc<DynOp::forward>(m, "_forward_dynamics", "(n,6),(4,4),(n,6,6),(3),(n),(n),(n),(6)->(n)",
                                 "screws, home, inertias, gravity, q, qd, tau, tip_wrench", forward_doc.c_str());
  const std::string mass_doc = std::string("M(q), the joint-space mass matrix (T = 1/2 qd^T M qd), by composite rigid bodies.") +
                               kOperands + R"doc(
    q: (n,), joint positions.

Returns:
    numpy.ndarray: (..., n, n), symmetric positive definite.)doc" + kPrivate;
  dynamics_ufunc<DynOp::mass>(m, "_mass_matrix", "(n,6),(4,4),(n,6,6),(n)->(n,n)", "screws, home, inertias, q",
                              mass_doc.c_str());
  const std::string gravity_doc =
      std::string("g(q), the joint forces that hold the chain still against gravity.") + kOperands + kGravity +
      R"doc(
    q: (n,), joint positions.

Returns:
    numpy.ndarray: (..., n).)doc" + kPrivate;
  dynamics_ufunc<DynOp::gravity>(m, "_gravity_torques", "(n,6),(4,4),(n,6,6),(3),(n)->(n)",
                                 "screws, home, inertias, gravity, q", gravity_doc.c_str());
  const std::string coriolis_doc =
      std::string("C(q, qd) qd, the Coriolis and centrifugal joint forces (without gravity).") + kOperands + R"doc(
    q, qd: (n,), joint positions and velocities.

Returns:
    numpy.ndarray: (..., n).)doc" + kPrivate;
  dynamics_ufunc<DynOp::coriolis>(m, "_coriolis", "(n,6),(4,4),(n,6,6),(n),(n)->(n)", "screws, home, inertias, q, qd",
                                  coriolis_doc.c_str());

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
  // The state: m, c (3), I_c row by row (9).
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
        return InertiaD(mass, c, I);
      }));
  add_reduce(cls);
}

}  // namespace chasles_py
