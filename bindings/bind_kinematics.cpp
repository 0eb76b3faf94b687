// chasles._core: the private model class _Chain over chasles::Chain<double,
// Dynamic, 32> (include/chasles/kinematics.hpp) that chasles.Chain
// (python/chasles/_chain.py) subclasses, and the private ufuncs of its
// kinematics, inverse kinematics and dynamics (include/chasles/
// inverse_kinematics.hpp, dynamics.hpp: free functions of the chain).
//
// The C++ Chain is the model, held once. What is Python's (names, the
// validation messages, the properties, pickling, the inverse kinematics'
// broadcasting and result type, from_urdf) lives in _chain.py. The methods
// that compute (forward, the Jacobians, the dynamics) are this class's, which
// the Python class takes over as they are: one configuration of float64 is
// computed here without numpy's dispatch, the same bits as the ufunc's loop
// (tests/python/test_ufuncs.py, test_robot.py compare them); anything else
// goes to the ufunc.
#include <chasles/dynamics.hpp>
#include <chasles/dynamics_derivatives.hpp>
#include <chasles/inverse_kinematics.hpp>
#include <chasles/kinematics.hpp>
#include <chasles/spatial_inertia.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "numpy_capi.hpp"
#include "ufunc.hpp"

namespace chasles_py {

/// The result of Chain.inverse_kinematics, a chasles._results.IKResult (a
/// named tuple defined in Python), which signatures show by that name.
struct CHASLES_PY_HIDDEN IKResultObject {
  py::object obj;
};

}  // namespace chasles_py

namespace pybind11 {
namespace detail {
template <>
struct type_caster<chasles_py::IKResultObject> {
  static constexpr auto name = const_name("chasles._results.IKResult");
  static handle cast(const chasles_py::IKResultObject& src, return_value_policy, handle) { return src.obj.inc_ref(); }
};
}  // namespace detail
}  // namespace pybind11

namespace chasles_py {

namespace {

using ChainD = chasles::Chain<double, Eigen::Dynamic, kMaxJoints>;
using InertiaD = chasles::SpatialInertia<double>;
using chasles::SE3d;
using Vector3 = Eigen::Vector3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix4 = Eigen::Matrix4d;
using Matrix6 = Eigen::Matrix<double, 6, 6>;
using RowsMap = Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>;

/// The model object: the C++ chain and the operands of its ufuncs, read-only
/// arrays: screws (n, 6) and home (4, 4), and when it has link inertias the
/// links' matrices G (n, 6, 6) in the world frame and gravity (3).
/// The chain's inertias are those the ufunc's loop reads back from G
/// (SpatialInertia::from_matrix_unchecked), so that one configuration gives
/// the loop's bits.
struct PyChain {
  ChainD chain;
  py::tuple operands;  // (screws, home[, G, gravity])
  chasles::ChainCheck check;  // validate() of the chain as made (before the inertias are read back)
};

std::string array_shape(const py::array& a) {
  return shape_string(reinterpret_cast<const Py_intptr_t*>(a.shape()), static_cast<int>(a.ndim()));
}

/// An SE3 (TypeError for one not initialized), or a (4, 4) array-like rigid motion.
SE3d pose_of(py::handle h, const std::string& what) {
  py::detail::make_caster<Obj<SE3d>> caster;
  if (caster.load(h, false)) return *static_cast<Obj<SE3d>&>(caster);
  const Matrix4 M = to_finite_eigen<4, 4>(h, what.c_str());
  const auto g = SE3d::from_matrix(M);
  if (!g)
    raise_value_error(what + ": not a rigid motion (transform defect " + short_float(SE3d::transform_defect(M)) +
                      "); pass an SE3 or a 4x4 matrix [[R, p], [0, 0, 0, 1]] with R a rotation");
  return *g;
}

/// A (rows, cols) array-like, rows = n, or `fill` for None; cols = 0 for (n,).
template <typename Out>
Out table_of(py::handle h, py::ssize_t n, py::ssize_t cols, const char* what, const char* expected) {
  const py::array a = as_float64_array(h, what);
  if (cols == 0 ? (a.ndim() != 1 || a.shape(0) != n) : (a.ndim() != 2 || a.shape(0) != n || a.shape(1) != cols))
    raise_value_error(std::string(what) + ": expected shape (" + std::to_string(n) +
                      (cols ? ", " + std::to_string(cols) : ",") + ")" + expected + ", got " + array_shape(a));
  Out out(n, std::max<py::ssize_t>(cols, 1));
  const char* data = static_cast<const char*>(a.data());
  for (py::ssize_t i = 0; i < n; ++i)
    for (py::ssize_t k = 0; k < out.cols(); ++k)
      out(i, k) = *reinterpret_cast<const double*>(data + i * a.strides(0) + (cols ? k * a.strides(1) : 0));
  return out;
}

using Limits = Eigen::Matrix<double, Eigen::Dynamic, 1, Eigen::ColMajor, kMaxJoints, 1>;
using Rows10 = Eigen::Matrix<double, Eigen::Dynamic, 10, Eigen::RowMajor, kMaxJoints, 10>;

ChainD::JointVector limits_of(py::handle h, py::ssize_t n, double fill, const char* what) {
  if (h.is_none()) return ChainD::JointVector::Constant(n, fill);
  const Limits v = table_of<Limits>(h, n, 0, what, " (one per joint)");
  if (v.array().isNaN().any()) raise_value_error(std::string(what) + ": expected numbers, got NaN");
  return v;
}

/// The chain from the constructor's arguments, converted and checked for
/// shapes and numbers here (chasles.Chain checks the model: _check); the
/// joint types as codes (0 revolute, 1 continuous, 2 prismatic, 3 helical)
/// or None (inferred, as the C++ constructor infers them).
PyChain make_chain(py::handle screws, py::handle home, py::handle types, py::handle lower, py::handle upper,
                   py::handle velocity, py::handle effort, py::handle base, py::handle tool, py::handle gravity,
                   py::handle inertias, bool home_as_given, bool unit_screws) {
  const py::array a = as_float64_array(screws, "Chain(screws)");
  if (a.ndim() != 2 || a.shape(1) != 6 || a.shape(0) < 1) {
    const bool columns = a.ndim() == 2 && a.shape(0) == 6 && a.shape(1) >= 1;
    raise_value_error("Chain(screws): expected shape (n, 6) with n >= 1 (one row (v, w) per joint), got " +
                      array_shape(a) +
                      (columns ? "; a table of one column per joint is transposed: pass screws.T (Modern Robotics' "
                                 "Slist, 6 x n in the (w, v) order: [Twist.from_modern_robotics(s).vector for s in "
                                 "Slist.T])"
                               : ""));
  }
  if (a.shape(0) > kMaxJoints)
    raise_value_error("Chain(screws): at most " + std::to_string(kMaxJoints) + " joints, got " +
                      std::to_string(a.shape(0)));
  const py::ssize_t n = a.shape(0);
  const ChainD::Screws S =
      table_of<Eigen::Matrix<double, Eigen::Dynamic, 6, 0, kMaxJoints, 6>>(a, n, 6, "", "").transpose();
  require_finite(S, "Chain(screws)");
  const SE3d M = pose_of(home, "Chain(home)");
  ChainD::JointTypes t = ChainD(S, SE3d()).joint_types();
  if (!types.is_none())
    for (py::ssize_t i = 0; i < n; ++i)
      t[static_cast<std::size_t>(i)] = static_cast<chasles::JointType>(
          py::reinterpret_borrow<py::sequence>(types)[static_cast<std::size_t>(i)].cast<int>());
  const auto lo = limits_of(lower, n, -INFINITY, "Chain(lower)"), hi = limits_of(upper, n, INFINITY, "Chain(upper)");
  const auto vel = limits_of(velocity, n, INFINITY, "Chain(velocity_limits)");
  const auto eff = limits_of(effort, n, INFINITY, "Chain(effort_limits)");
  const SE3d b = base.is_none() ? SE3d() : pose_of(base, "Chain(base)");
  const SE3d to = tool.is_none() ? SE3d() : pose_of(tool, "Chain(tool)");
  const Vector3 g = gravity.is_none() ? ChainD::default_gravity() : to_finite_eigen<3>(gravity, "Chain(gravity)");
  ChainD::Inertias link{};  // zero (massless) when none are given
  if (!inertias.is_none()) {
    const Rows10 r = table_of<Rows10>(inertias, n, 10, "Chain(link_inertias)",
                                      " (mass, com (3), ixx, ixy, ixz, iyy, iyz, izz per joint)");
    require_finite(r, "Chain(link_inertias)");
    if ((r.col(0).array() < 0).any()) raise_value_error("Chain(link_inertias): expected masses >= 0 (column 0)");
    for (py::ssize_t i = 0; i < n; ++i) {
      Eigen::Matrix3d I;
      I << r(i, 4), r(i, 5), r(i, 6), r(i, 5), r(i, 7), r(i, 8), r(i, 6), r(i, 8), r(i, 9);
      link[static_cast<std::size_t>(i)] = InertiaD(r(i, 0), Vector3(r(i, 1), r(i, 2), r(i, 3)), I);
    }
  }
  ChainD c = home_as_given ? ChainD(chasles::Chain<double, Eigen::Dynamic, kMaxJoints>::Stored(), S, M, t, lo, hi, vel,
                                    eff, b, to, g, link)
                           : ChainD(S, M, t, lo, hi, vel, eff, b, to, g, link);
  const chasles::ChainCheck check = c.validate(unit_screws ? chasles::ScrewNorms::unit : chasles::ScrewNorms::any);
  const Py_intptr_t dims[3] = {n, 6, 6};
  py::array_t<double> screws_out = new_array(2, dims);
  RowsMap(array_data(screws_out), n, 6) = c.space_screws().transpose();
  py::tuple ops = py::make_tuple(screws_out, mat_out<4, 4>(c.home().matrix()));
  if (!inertias.is_none()) {
    py::array_t<double> G = new_array(3, dims);
    ChainD::Inertias read{};
    for (std::size_t k = 0; k < static_cast<std::size_t>(n); ++k) {
      Eigen::Map<Eigen::Matrix<double, 6, 6, Eigen::RowMajor>>(array_data(G) + 36 * k) = c.link_inertias()[k].matrix();
      read[k] = InertiaD::from_matrix_unchecked(c.link_inertias()[k].matrix());
    }
    ops = py::make_tuple(ops[0], ops[1], G, vec_out<3>(c.gravity()));
    c = ChainD(ChainD::Stored(), c.space_screws(), c.home(), c.joint_types(), c.lower(), c.upper(), c.velocity_limits(),
               c.effort_limits(), c.base(), c.tool(), c.gravity(), read);
  }
  for (py::handle x : ops) py::detail::array_proxy(x.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return {c, std::move(ops), check};
}

// ---- the ufuncs ---------------------------------------------------------------
//
// Kinematics (n,6),(4,4),(n)->...: the space screws (one row (v, w) per
// joint), the home pose and the joint positions. Dynamics
// (n,6),(4,4),(n,6,6)[,(3)],...: also the links' matrices G (order (v, w))
// in the base frame at home and gravity. The model (a chain) is made once
// per loop from the first operands when they stay put (ufunc.hpp); n <= 32
// bound at run time; float64 only.

using ufunc::Core;
using ufunc::upto;
using JointsCore = Core<upto<kMaxJoints>>;
using ScrewsCore = Core<upto<kMaxJoints>, 6>;
using Joints = ChainD::JointVector;
using MassMatrix = ChainD::MassMatrix;

/// The chain of the operands screws, home (as given) and, for the
/// dynamics, the matrices G and gravity (zero without one: mass matrix, Coriolis).
struct ChainOf {
  template <typename S, typename M>
  ChainD operator()(const S& screws, const M& home) const noexcept {
    return ChainD(ChainD::Screws(screws.transpose()), SE3d::from_matrix_unchecked(Matrix4(home)),
                  ChainD::HomeAsGiven());
  }
  template <typename S, typename M, typename G>
  ChainD operator()(const S& screws, const M& home, const G& inertias) const noexcept {
    return (*this)(screws, home, inertias, Vector3::Zero());
  }
  template <typename S, typename M, typename G, typename V>
  ChainD operator()(const S& screws, const M& home, const G& inertias, const V& gravity) const noexcept {
    ChainD::Inertias I;
    for (Eigen::Index i = 0; i < inertias.size(); ++i)
      I[static_cast<std::size_t>(i)] = InertiaD::from_matrix_unchecked(Matrix6(inertias[i]));
    return ChainD(ChainD::Screws(screws.transpose()), SE3d::from_matrix_unchecked(Matrix4(home)), ChainD::HomeAsGiven(),
                  I, Vector3(gravity));
  }
};

/// The computations, one configuration each (the ufuncs' kernels and the fast path).
enum class Op {
  forward,
  forward_body,
  jacobian_space,
  jacobian_body,
  jacobian_space_dot,
  jacobian_body_dot,
  inverse,
  forward_dynamics,
  mass,
  gravity,
  coriolis,
  inverse_derivatives,
  forward_derivatives,
  mass_inverse
};

/// The computations that take a tip wrench, and those that report where M(q) is not positive definite.
constexpr bool has_tip(Op op) {
  return op == Op::inverse || op == Op::forward_dynamics || op == Op::inverse_derivatives ||
         op == Op::forward_derivatives;
}
constexpr bool may_fail(Op op) {
  return op == Op::forward_dynamics || op == Op::forward_derivatives || op == Op::mass_inverse;
}

template <Op op>
auto compute(const ChainD& c, const Joints* x, const chasles::Wrenchd& tip) {
  static_cast<void>(tip);  // (the kinematics have none)
  if constexpr (op == Op::forward)
    return c.forward(x[0]).matrix();
  else if constexpr (op == Op::forward_body)
    return c.forward_body(x[0]).matrix();
  else if constexpr (op == Op::jacobian_space)
    return c.jacobian_space(x[0]);
  else if constexpr (op == Op::jacobian_body)
    return c.jacobian_body(x[0]);
  else if constexpr (op == Op::jacobian_space_dot)
    return c.jacobian_space_dot(x[0], x[1]);
  else if constexpr (op == Op::jacobian_body_dot)
    return c.jacobian_body_dot(x[0], x[1]);
  else if constexpr (op == Op::inverse)
    return chasles::inverse_dynamics(c, x[0], x[1], x[2], tip);
  else if constexpr (op == Op::forward_dynamics)
    return chasles::forward_dynamics(c, x[0], x[1], x[2], tip);
  else if constexpr (op == Op::mass)
    return chasles::mass_matrix(c, x[0]);
  else if constexpr (op == Op::gravity)
    return chasles::gravity_torques(c, x[0]);
  else if constexpr (op == Op::coriolis)
    return chasles::coriolis(c, x[0], x[1]);
  else if constexpr (op == Op::inverse_derivatives)
    return chasles::inverse_dynamics_derivatives(c, x[0], x[1], x[2], tip);
  else if constexpr (op == Op::forward_derivatives)
    return chasles::forward_dynamics_derivatives(c, x[0], x[1], x[2], tip);
  else
    return chasles::mass_matrix_inverse(c, x[0]);
}

template <typename Tuple, std::size_t... k>
void fill(Joints* joints, const Tuple& t, std::index_sequence<k...>) {
  ((joints[k] = Joints(std::get<k>(t))), ...);
}

template <Op op>
struct Kernel {
  template <typename... X>
  auto operator()(const ChainD& c, const X&... x) const noexcept {
    constexpr std::size_t J = sizeof...(X) - (has_tip(op) ? 1 : 0);
    const auto all = std::forward_as_tuple(x...);
    Joints joints[3];
    chasles::Wrenchd tip;
    fill(joints, all, std::make_index_sequence<J>());
    if constexpr (J < sizeof...(X)) tip = chasles::Wrenchd(Vector6(std::get<J>(all)));
    const auto r = compute<op>(c, joints, tip);
    if constexpr (op == Op::forward_dynamics)
      return std::tuple<Joints, int>{r.qdd, static_cast<int>(r.joint)};
    else if constexpr (op == Op::inverse_derivatives)
      return std::tuple<MassMatrix, MassMatrix>{r.dtau_dq, r.dtau_dqd};
    else if constexpr (op == Op::forward_derivatives)
      return std::tuple<MassMatrix, MassMatrix, MassMatrix, int>{r.dqdd_dq, r.dqdd_dqd, r.dqdd_dtau,
                                                                 static_cast<int>(r.joint)};
    else if constexpr (op == Op::mass_inverse)
      return std::tuple<MassMatrix, int>{r.inverse, static_cast<int>(r.joint)};
    else
      return r;
  }
};

std::string private_doc(const char* signature, const char* method) {
  return std::string(signature) + " A private ufunc of chasles.Chain (its method " + method +
         ", which checks the arguments); float64.";
}

/// The ufuncs, registered once: their objects, kept for the methods, by Op.
using Ufuncs = std::array<py::object, static_cast<std::size_t>(Op::mass_inverse) + 1>;

Ufuncs register_ufuncs(py::module_& m) {
  using ufunc::def_ufunc;
  using ufunc::Float64;
  using ufunc::model;
  using Pose = Core<4, 4>(ScrewsCore, Core<4, 4>, JointsCore);
  using Jac = Core<6, upto<kMaxJoints>>(ScrewsCore, Core<4, 4>, JointsCore);
  using G = Core<upto<kMaxJoints>, 6, 6>;
  const char* kin = "screws, home, theta";
  Ufuncs u;
  u[std::size_t(Op::forward)] = def_ufunc<Pose, Float64>(m, "_chain_forward", kin, private_doc("g(theta).", "forward"),
                                                         model<2>(ChainOf()), Kernel<Op::forward>());
  u[std::size_t(Op::forward_body)] =
      def_ufunc<Pose, Float64>(m, "_chain_forward_body", kin, private_doc("g(theta), body form.", "forward_body"),
                               model<2>(ChainOf()), Kernel<Op::forward_body>());
  u[std::size_t(Op::jacobian_space)] =
      def_ufunc<Jac, Float64>(m, "_chain_jacobian_space", kin, private_doc("J_s(theta).", "jacobian_space"),
                              model<2>(ChainOf()), Kernel<Op::jacobian_space>());
  u[std::size_t(Op::jacobian_body)] =
      def_ufunc<Jac, Float64>(m, "_chain_jacobian_body", kin, private_doc("J_b(theta).", "jacobian_body"),
                              model<2>(ChainOf()), Kernel<Op::jacobian_body>());
  using JacDot = Core<6, upto<kMaxJoints>>(ScrewsCore, Core<4, 4>, JointsCore, JointsCore);
  u[std::size_t(Op::jacobian_space_dot)] =
      def_ufunc<JacDot, Float64>(m, "_chain_jacobian_space_dot", "screws, home, theta, theta_dot",
                                 private_doc("dJ_s/dt at (theta, theta_dot).", "jacobian_space_dot"),
                                 model<2>(ChainOf()), Kernel<Op::jacobian_space_dot>());
  u[std::size_t(Op::jacobian_body_dot)] =
      def_ufunc<JacDot, Float64>(m, "_chain_jacobian_body_dot", "screws, home, theta, theta_dot",
                                 private_doc("dJ_b/dt at (theta, theta_dot).", "jacobian_body_dot"),
                                 model<2>(ChainOf()), Kernel<Op::jacobian_body_dot>());
  // (n,6),(4,4),(n,6,6),(3),(n),(n),(n),(6)->(n) [,()]: screws, home, inertias, gravity, q, qd, qdd (tau), tip wrench
  u[std::size_t(Op::inverse)] =
      def_ufunc<JointsCore(ScrewsCore, Core<4, 4>, G, Core<3>, JointsCore, JointsCore, JointsCore, Core<6>), Float64>(
          m, "_inverse_dynamics", "screws, home, inertias, gravity, q, qd, qdd, tip_wrench",
          private_doc("tau = M(q) qdd + C(q, qd) qd + g(q) + J_b^T F_tip (recursive Newton-Euler).",
                      "inverse_dynamics"),
          model<4>(ChainOf()), Kernel<Op::inverse>());
  u[std::size_t(Op::forward_dynamics)] =
      def_ufunc<std::tuple<JointsCore, ufunc::Typed<Core<>, int>>(ScrewsCore, Core<4, 4>, G, Core<3>, JointsCore,
                                                                  JointsCore, JointsCore, Core<6>),
                Float64>(m, "_forward_dynamics", "screws, home, inertias, gravity, q, qd, tau, tip_wrench",
                         private_doc("(qdd, joint): qdd = M(q)^-1 (tau - h - J_b^T F_tip), and -1 or the joint where "
                                     "M(q) is not positive definite (qdd NaN there).",
                                     "forward_dynamics"),
                         model<4>(ChainOf()), Kernel<Op::forward_dynamics>());
  u[std::size_t(Op::mass)] =
      def_ufunc<Core<upto<kMaxJoints>, upto<kMaxJoints>>(ScrewsCore, Core<4, 4>, G, JointsCore), Float64>(
          m, "_mass_matrix", "screws, home, inertias, q", private_doc("M(q) (composite rigid bodies).", "mass_matrix"),
          model<3>(ChainOf()), Kernel<Op::mass>());
  u[std::size_t(Op::gravity)] = def_ufunc<JointsCore(ScrewsCore, Core<4, 4>, G, Core<3>, JointsCore), Float64>(
      m, "_gravity_torques", "screws, home, inertias, gravity, q", private_doc("g(q).", "gravity_torques"),
      model<4>(ChainOf()), Kernel<Op::gravity>());
  u[std::size_t(Op::coriolis)] = def_ufunc<JointsCore(ScrewsCore, Core<4, 4>, G, JointsCore, JointsCore), Float64>(
      m, "_coriolis", "screws, home, inertias, q, qd", private_doc("C(q, qd) qd (no gravity).", "coriolis"),
      model<3>(ChainOf()), Kernel<Op::coriolis>());
  using Square = Core<upto<kMaxJoints>, upto<kMaxJoints>>;
  using Int = ufunc::Typed<Core<>, int>;
  u[std::size_t(Op::inverse_derivatives)] = def_ufunc<
      std::tuple<Square, Square>(ScrewsCore, Core<4, 4>, G, Core<3>, JointsCore, JointsCore, JointsCore, Core<6>),
      Float64>(m, "_inverse_dynamics_derivatives", "screws, home, inertias, gravity, q, qd, qdd, tip_wrench",
               private_doc("(dtau_dq, dtau_dqd) of inverse dynamics (analytic).", "inverse_dynamics_derivatives"),
               model<4>(ChainOf()), Kernel<Op::inverse_derivatives>());
  u[std::size_t(Op::forward_derivatives)] =
      def_ufunc<std::tuple<Square, Square, Square, Int>(ScrewsCore, Core<4, 4>, G, Core<3>, JointsCore, JointsCore,
                                                        JointsCore, Core<6>),
                Float64>(m, "_forward_dynamics_derivatives", "screws, home, inertias, gravity, q, qd, tau, tip_wrench",
                         private_doc("(dqdd_dq, dqdd_dqd, dqdd_dtau, joint) of forward dynamics (analytic; joint as "
                                     "_forward_dynamics').",
                                     "forward_dynamics_derivatives"),
                         model<4>(ChainOf()), Kernel<Op::forward_derivatives>());
  u[std::size_t(Op::mass_inverse)] = def_ufunc<std::tuple<Square, Int>(ScrewsCore, Core<4, 4>, G, JointsCore), Float64>(
      m, "_mass_matrix_inverse", "screws, home, inertias, q",
      private_doc("(M(q)^-1, joint) (joint as _forward_dynamics').", "mass_matrix_inverse"), model<3>(ChainOf()),
      Kernel<Op::mass_inverse>());
  return u;
}

// ---- inverse kinematics: (n,6),(4,4),(n),(n),(),(),(),(),(4,4),(n),(),()->(n),(),(),(),(),(),(6) ----
//
// The chain (screws, home, lower and upper limits) and the solver's options
// (tolerances, max_iterations, max_time) make the model; each element solves
// for a target from a seed q0 with `restarts` further attempts drawn from a
// 64-bit Mersenne twister seeded with `seed`. Chain.inverse_kinematics solves
// one target from one seed with the same kernel (ik_solve), without numpy.

struct IKModel {
  ChainD chain;
  ChainD::JointVector lower, upper;
  chasles::IKOptions<double> options;
};

struct IKModelOf {
  template <typename S, typename M, typename Lo, typename Hi>
  IKModel operator()(const S& screws, const M& home, const Lo& lower, const Hi& upper, double position_tolerance,
                     double orientation_tolerance, int max_iterations, double max_time) const noexcept {
    chasles::IKOptions<double> options;
    options.position_tolerance = position_tolerance;
    options.orientation_tolerance = orientation_tolerance;
    options.max_iterations = max_iterations;
    options.max_time = max_time;
    return {ChainOf()(screws, home), Joints(lower), Joints(upper), options};
  }
};

/// (q, converged, status (IKStatus as an int), iterations, total_iterations, attempts, error).
using IKOutcome = std::tuple<Joints, bool, int, int, int, int, Vector6>;

IKOutcome ik_solve(const ChainD& chain, const Joints& lower, const Joints& upper,
                   const chasles::IKOptions<double>& options, const SE3d& target, const Joints& q0, int restarts,
                   npy_uint64 seed) noexcept {
  std::mt19937_64 gen(seed);
  const auto r = restarts > 0 ? chasles::inverse_kinematics(chain, target, q0, lower, upper, options, gen, restarts)
                              : chasles::inverse_kinematics(chain, target, q0, lower, upper, options);
  return {r.q, r.converged, static_cast<int>(r.status), r.iterations, r.total_iterations, r.attempts, r.error};
}

struct IKKernel {
  template <typename Target, typename Q0>
  IKOutcome operator()(const IKModel& m, const Target& target, const Q0& q0, int restarts,
                       npy_uint64 seed) const noexcept {
    return ik_solve(m.chain, m.lower, m.upper, m.options, SE3d::from_matrix_unchecked(Matrix4(target)), Joints(q0),
                    restarts, seed);
  }
};

void register_ik(py::module_& m) {
  using ufunc::Typed;
  using Int = Typed<Core<>, int>;
  using Signature = std::tuple<JointsCore, Typed<Core<>, bool>, Int, Int, Int, Int, Core<6>>(
      ScrewsCore, Core<4, 4>, JointsCore, JointsCore, Core<>, Core<>, Int, Core<>, Core<4, 4>, JointsCore, Int,
      Typed<Core<>, npy_uint64>);
  ufunc::def_ufunc<Signature, ufunc::Float64>(
      m, "_inverse_kinematics",
      "screws, home, lower, upper, position_tolerance, orientation_tolerance, max_iterations, max_time, target, q0, "
      "restarts, seed",
      R"doc(A private ufunc of chasles.Chain (its method inverse_kinematics, which checks the arguments).

Operands (float64 unless said): screws (n, 6), 1 <= n <= 32 (NaN results
beyond); home (4, 4); lower, upper (n,); position_tolerance,
orientation_tolerance (); max_iterations () int32, per attempt; max_time (),
seconds per element (inf: none); target (4, 4), a rigid motion (taken as
given); q0 (n,), the seed; restarts () int32, further attempts from random
seeds while not converged; seed () uint64, the Mersenne twister's seed.
Returns (q (n,), converged () bool, status () int32 (IKStatus: 0 converged,
1 iteration_bound, 2 time_budget, 3 no_progress), iterations () int32 (of
the attempt returned), total_iterations () int32, attempts () int32, error
(6,)).)doc",
      ufunc::model<8>(IKModelOf()), IKKernel());
}

/// IKStatus's names, by value.
const char* const kIKStatus[] = {"converged", "iteration_bound", "time_budget", "no_progress"};

/// An integer argument of Chain.inverse_kinematics (an object with
/// __index__) within [0, high].
unsigned long long ik_count(py::handle h, const char* name, unsigned long long high) {
  const std::string what = std::string("Chain.inverse_kinematics(") + name + ")";
  PyObject* index = PyNumber_Index(h.ptr());
  if (index == nullptr) {
    PyErr_Clear();
    raise_type_error(what + ": expected an integer, got " + type_name(h));
  }
  const py::object i = py::reinterpret_steal<py::object>(index);
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow(index, &overflow);
  if (overflow < 0 || (overflow == 0 && v < 0))
    raise_value_error(what + ": expected >= 0, got " + std::string(py::str(i)));
  const unsigned long long u = overflow == 0 ? static_cast<unsigned long long>(v) : PyLong_AsUnsignedLongLong(index);
  if (u == static_cast<unsigned long long>(-1) && PyErr_Occurred())
    PyErr_Clear();
  else if (u <= high)
    return u;
  raise_value_error(what + ": expected at most " + std::to_string(high) + ", got " + std::string(py::str(i)));
}

/// The options of Chain.inverse_kinematics, checked.
struct IKArguments {
  chasles::IKOptions<double> options;
  int restarts;
  npy_uint64 seed;
};

IKArguments ik_arguments(py::handle position_tolerance, py::handle orientation_tolerance, py::handle max_iterations,
                         py::handle restarts, py::handle seed, py::handle max_time) {
  constexpr unsigned long long int_max = 2147483647ULL;
  IKArguments a;
  a.options.position_tolerance = to_tolerance(position_tolerance, "Chain.inverse_kinematics(position_tolerance)");
  a.options.orientation_tolerance =
      to_tolerance(orientation_tolerance, "Chain.inverse_kinematics(orientation_tolerance)");
  a.options.max_iterations = static_cast<int>(ik_count(max_iterations, "max_iterations", int_max));
  a.restarts = static_cast<int>(ik_count(restarts, "restarts", int_max));
  a.seed = ik_count(seed, "seed", ~0ULL);
  if (!max_time.is_none()) {
    const double t = to_real(max_time, "Chain.inverse_kinematics(max_time)");
    if (!(t >= 0))
      raise_value_error("Chain.inverse_kinematics(max_time): expected a time >= 0 in seconds, or None, got " +
                        float_repr(t));
    a.options.max_time = t;
  }
  return a;
}

[[noreturn]] void raise_not_rigid_target(const Eigen::Ref<const Matrix4>& M, const std::string& at) {
  raise_value_error("Chain.inverse_kinematics(target): not a rigid motion (defect " +
                    short_float(SE3d::transform_defect(M)) + at + "); SE3.from_matrix_projected makes one");
}

/// One target without numpy: an SE3, or a native float64 array of shape (4, 4).
bool single_target(py::handle h, SE3d& out) {
  py::detail::make_caster<Obj<SE3d>> caster;
  bool loaded;
  try {
    loaded = caster.load(h, false);
  } catch (const py::type_error& e) {  // an SE3 made by __new__ alone
    raise_type_error(std::string("Chain.inverse_kinematics(target): ") + e.what());
  }
  if (loaded) {
    out = *static_cast<Obj<SE3d>&>(caster);
    return true;
  }
  if (!is_native_float64_array(h.ptr())) return false;
  const auto* a = py::detail::array_proxy(h.ptr());
  if (a->nd != 2 || a->dimensions[0] != 4 || a->dimensions[1] != 4) return false;
  Matrix4 M;
  read_array(h.ptr(), M);
  const auto g = SE3d::from_matrix(M);
  if (!g) raise_not_rigid_target(M, "");
  out = *g;
  return true;
}

/// The type chasles._results.IKResult, which the package hands over when
/// it loads (_chain.py: _Chain._set_ik_result): the bindings import nothing
/// of the package. Held for the process.
PyObject* ik_result_type = nullptr;

/// IKResult(q, converged, status, iterations, total_iterations, attempts, error).
py::object ik_result(py::object q, py::object converged, py::object status, py::object iterations,
                     py::object total_iterations, py::object attempts, py::object error) {
  if (ik_result_type == nullptr) throw py::type_error("Chain.inverse_kinematics: chasles._chain is not loaded");
  return py::reinterpret_borrow<py::object>(ik_result_type)(q, converged, status, iterations, total_iterations,
                                                            attempts, error);
}

py::object inverse_kinematics(const PyChain& c, py::handle target, py::handle q0, const IKArguments& a) {
  const py::ssize_t n = c.chain.n_joints();
  const ChainD& chain = c.chain;
  Joints q(n);
  SE3d T;
  if (single_target(target, T) && single_element(q0, q.data(), n)) {
    if (!q.allFinite()) raise_value_error("Chain.inverse_kinematics(q0): expected finite numbers");
    IKOutcome r;
    {
      py::gil_scoped_release release;
      r = ik_solve(chain, chain.lower(), chain.upper(), a.options, T, q, a.restarts, a.seed);
    }
    static const py::str names[] = {py::str(kIKStatus[0]), py::str(kIKStatus[1]), py::str(kIKStatus[2]),
                                    py::str(kIKStatus[3])};
    const Joints& qr = std::get<0>(r);
    return ik_result(py::array_t<double>(n, qr.data()), py::bool_(std::get<1>(r)), names[std::get<2>(r)],
                     py::int_(std::get<3>(r)), py::int_(std::get<4>(r)), py::int_(std::get<5>(r)),
                     vec_out<6>(std::get<6>(r)));
  }
  // A batch: targets (..., 4, 4) and seeds (..., n) broadcast together.
  const py::array Ta = as_float64_array(target, "Chain.inverse_kinematics(target)");
  if (Ta.ndim() < 2 || Ta.shape(Ta.ndim() - 2) != 4 || Ta.shape(Ta.ndim() - 1) != 4)
    raise_value_error("Chain.inverse_kinematics(target): expected an SE3 or shape (4, 4) or (..., 4, 4), got " +
                      array_shape(Ta));
  const py::array Qa = as_float64_array(q0, "Chain.inverse_kinematics(q0)");
  if (Qa.ndim() < 1 || Qa.shape(Qa.ndim() - 1) != n)
    raise_value_error("Chain.inverse_kinematics(q0): expected shape (" + std::to_string(n) + ",) or (..., " +
                      std::to_string(n) + ") for a chain of " + std::to_string(n) + " joints, got " + array_shape(Qa));
  static PyObject* broadcast_shapes = numpy_attr("broadcast_shapes");
  static PyObject* broadcast_to = numpy_attr("broadcast_to");
  static PyObject* contiguous = numpy_attr("ascontiguousarray");
  const auto head = [](const py::array& x, py::ssize_t drop) {
    return py::tuple(py::reinterpret_borrow<py::tuple>(x.attr("shape"))[py::slice(0, x.ndim() - drop, 1)]);
  };
  PyObject* shape = PyObject_CallFunctionObjArgs(broadcast_shapes, head(Ta, 2).ptr(), head(Qa, 1).ptr(), nullptr);
  if (shape == nullptr) {
    PyErr_Clear();
    raise_value_error("Chain.inverse_kinematics: the batch shapes of target " + array_shape(Ta) + " and q0 " +
                      array_shape(Qa) + " do not broadcast together");
  }
  const py::tuple batch = py::reinterpret_steal<py::tuple>(shape);
  const auto spread = [&](const py::array& x, py::tuple core) {
    const py::object b = py::reinterpret_borrow<py::object>(broadcast_to)(x, batch + core);
    return py::reinterpret_steal<py::array>(PyObject_CallOneArg(contiguous, b.ptr()));
  };
  const py::array Tb = spread(Ta, py::make_tuple(4, 4)), Qb = spread(Qa, py::make_tuple(n));
  const py::ssize_t count = Tb.size() / 16;
  const double* t = static_cast<const double*>(Tb.data());
  for (py::ssize_t i = 0; i < count; ++i) {
    const Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>> M(t + 16 * i);
    if (!(SE3d::transform_defect(M) <= chasles::Thresholds<double>::rotation_tolerance))
      raise_not_rigid_target(M, count > 1 ? " at index " + std::to_string(i) : "");
  }
  if (!Eigen::Map<const Eigen::ArrayXd>(static_cast<const double*>(Qb.data()), Qb.size()).allFinite())
    raise_value_error("Chain.inverse_kinematics(q0): expected finite numbers");
  std::vector<Py_intptr_t> dims(batch.size());
  for (std::size_t k = 0; k < batch.size(); ++k) dims[k] = batch[k].cast<Py_intptr_t>();
  py::array_t<npy_uint64> seeds(dims);
  for (py::ssize_t i = 0; i < count; ++i) seeds.mutable_data()[i] = a.seed + static_cast<npy_uint64>(i);
  static PyObject* int32 = numpy_attr("int32");
  const auto int32_of = [](int v) { return py::reinterpret_borrow<py::object>(int32)(v); };
  const auto limits = [n](const Joints& v) { return py::array_t<double>(n, v.data()); };
  const py::object r = py::reinterpret_borrow<py::object>(array_function("_inverse_kinematics"))(
      c.operands[0], c.operands[1], limits(chain.lower()), limits(chain.upper()), a.options.position_tolerance,
      a.options.orientation_tolerance, int32_of(a.options.max_iterations), a.options.max_time, Tb, Qb,
      int32_of(a.restarts), seeds);
  const py::tuple out = py::reinterpret_borrow<py::tuple>(r);
  static PyObject* names = [] {
    py::list l;
    for (const char* s : kIKStatus) l.append(s);
    return py::module_::import("numpy").attr("array")(l).release().ptr();
  }();
  if (batch.empty())  // one solve of other input types: Python's bool, str and ints, as above
    return ik_result(out[0], py::bool_(out[1].cast<bool>()), py::str(kIKStatus[out[2].cast<int>()]),
                     py::int_(out[3].cast<int>()), py::int_(out[4].cast<int>()), py::int_(out[5].cast<int>()), out[6]);
  const py::object status = py::reinterpret_borrow<py::object>(names).attr("take")(out[2]);
  return ik_result(out[0], out[1], status, out[3], out[4], out[5], out[6]);
}

// ---- the methods ----------------------------------------------------------------

/// A ufunc operand of joint values of shape (..., n), its last axis checked
/// against the chain's n (numpy would name only the operand's index).
py::object joint_operand(py::handle x, py::ssize_t n, const std::string& what) {
  py::object operand = ufunc_operand(x, what.c_str());
  if (npy().PyArray_Check_(operand.ptr())) {
    const auto a = py::reinterpret_borrow<py::array>(operand);
    if (a.ndim() < 1 || a.shape(a.ndim() - 1) != n)
      raise_value_error(what + ": expected shape (" + std::to_string(n) + ",) or (..., " + std::to_string(n) +
                        ") for a chain of " + std::to_string(n) + " joints, got " +
                        shape_string(a.shape(), static_cast<int>(a.ndim())));
  }
  return operand;
}

[[noreturn]] void raise_not_positive_definite(const char* method, const std::string& where, Eigen::Index joint) {
  raise_value_error(std::string("Chain.") + method + ": the mass matrix M(q) is not positive definite" + where +
                    ": its factorization fails at joint " + std::to_string(joint) +
                    " (a link without mass, or without rotational inertia about its joint's axis, or an inertia "
                    "that no rigid body has?)");
}

/// A batch of a computation that may fail (forward dynamics, its
/// derivatives, M(q)^-1), the ufunc's (results..., joint): the results (one,
/// or a tuple), or ValueError naming the first configuration (C order)
/// whose joint is not -1 when `raise`.
py::object checked_batch(const char* method, const py::object& result, bool raise) {
  const py::tuple r = py::reinterpret_borrow<py::tuple>(result);
  const std::size_t last = r.size() - 1;
  const py::object values =
      last == 1 ? py::object(r[0]) : py::object(r[py::slice(0, static_cast<py::ssize_t>(last), 1)]);
  if (!raise) return values;
  const auto joint = py::array_t<int, py::array::c_style | py::array::forcecast>::ensure(r[last]);
  py::ssize_t first = -1, failed = 0;
  for (py::ssize_t i = 0; i < joint.size(); ++i)
    if (joint.data()[i] >= 0 && failed++ == 0) first = i;
  if (failed == 0) return values;
  if (joint.ndim() == 0) raise_not_positive_definite(method, "", joint.data()[0]);
  std::string index;
  for (py::ssize_t d = joint.ndim(), rest = first; d-- > 0; rest /= joint.shape(d))
    index = std::to_string(rest % joint.shape(d)) + (index.empty() ? "" : ", ") + index;
  raise_not_positive_definite(method,
                              " at batch index (" + index + (joint.ndim() == 1 ? ",)" : ")") + ", the first of " +
                                  std::to_string(failed) + " of " + std::to_string(joint.size()) +
                                  " configurations; on_failure=\"nan\" gives NaN there instead)",
                              joint.data()[first]);
}

/// A new array of a matrix or vector's values ((rows,) for a vector).
template <typename Derived>
py::object array_of(const Eigen::MatrixBase<Derived>& x) {
  constexpr bool vector = Derived::ColsAtCompileTime == 1;
  const Py_intptr_t dims[2] = {x.rows(), x.cols()};
  py::array_t<double> out = new_array(vector ? 1 : 2, dims);
  RowsMap(array_data(out), dims[0], dims[1]) = x;
  return std::move(out);
}

/// A method: J joint arguments (and for the dynamics the tip wrench, None:
/// zero). One configuration of float64 (each joint argument a native float64
/// array of shape (n,) or a list of n numbers, the tip None or one such of
/// 6) is computed here; anything else by the ufunc u, the last axes checked
/// here so that the message names the method and n.
template <Op op, std::size_t J>
py::object call(PyObject* u, const PyChain& c, const char* method, const std::array<py::handle, J>& x,
                const py::handle* tip, bool raise = true) {
  constexpr bool dynamics = op >= Op::inverse, with_gravity = has_tip(op) || op == Op::gravity;
  static_cast<void>(raise);  // (may_fail(op) only)
  if (dynamics && c.operands.size() < 4)
    raise_value_error(std::string("Chain.") + method +
                      ": the chain has no link inertias (give Chain(..., link_inertias=...), or load it with "
                      "Chain.from_urdf)");
  const py::ssize_t n = c.chain.n_joints();
  Joints one[3];
  bool single = true;
  for (std::size_t j = 0; j < J && single; ++j) single = (one[j].resize(n), single_element(x[j], one[j].data(), n));
  chasles::Wrenchd tip_wrench;
  if (single && tip != nullptr && !tip->is_none()) {
    Vector6 w;
    single = single_element(*tip, w.data(), 6);
    tip_wrench = chasles::Wrenchd(w);
  }
  if (single) {
    const auto r = compute<op>(c.chain, one, tip_wrench);
    if constexpr (may_fail(op))
      if (!r && raise) raise_not_positive_definite(method, "", r.joint);
    if constexpr (op == Op::forward_dynamics)
      return array_of(r.qdd);
    else if constexpr (op == Op::inverse_derivatives)
      return py::object(py::make_tuple(array_of(r.dtau_dq), array_of(r.dtau_dqd)));
    else if constexpr (op == Op::forward_derivatives)
      return py::object(py::make_tuple(array_of(r.dqdd_dq), array_of(r.dqdd_dqd), array_of(r.dqdd_dtau)));
    else if constexpr (op == Op::mass_inverse)
      return array_of(r.inverse);
    else
      return array_of(r);
  }
  // The batch: the messages name the method (strings made here only, off the fast path).
  const std::string what = std::string("Chain.") + method, call_what = dynamics || J > 1 ? what : what + "(theta)";
  std::array<py::object, 8> keep;  // the operands, alive through the call
  std::array<PyObject*, 8> args{};
  std::size_t k = 0;
  for (std::size_t i = 0; i < (!dynamics ? 2 : with_gravity ? 4 : 3); ++i)  // the model's operands
    keep[k] = c.operands[i], args[k] = keep[k].ptr(), ++k;
  static const char* const names[] = {"q", "qd", "qdd", "tau", "theta", "theta_dot"};
  constexpr bool takes_tau = op == Op::forward_dynamics || op == Op::forward_derivatives;
  for (std::size_t j = 0; j < J; ++j) {
    const char* arg = !dynamics ? names[4 + j] : (takes_tau && j == 2) ? names[3] : names[j];
    keep[k] = joint_operand(x[j], n, what + "(" + arg + ")");
    args[k] = keep[k].ptr(), ++k;
  }
  if (tip != nullptr) {
    keep[k] =
        tip->is_none() ? py::object(vec_out<6>(Vector6::Zero())) : ufunc_operand(*tip, (what + "(tip_wrench)").c_str());
    args[k] = keep[k].ptr(), ++k;
  }
  PyObject* r = PyObject_Vectorcall(u, args.data(), k, nullptr);
  if (r == nullptr) {
    py::error_already_set e;
    raise_conversion_error(e, call_what);
  }
  py::object result = py::reinterpret_steal<py::object>(r);
  if constexpr (may_fail(op)) return checked_batch(method, result, raise);
  return result;
}

/// Chain.<method>(on_failure): true for "raise" (the default), false for "nan".
bool failure_raises(const char* method, py::handle on_failure) {
  if (PyUnicode_Check(on_failure.ptr())) {
    if (PyUnicode_CompareWithASCIIString(on_failure.ptr(), "raise") == 0) return true;
    if (PyUnicode_CompareWithASCIIString(on_failure.ptr(), "nan") == 0) return false;
  }
  raise_value_error(std::string("Chain.") + method + "(on_failure): expected \"raise\" or \"nan\", got " +
                    std::string(py::repr(on_failure)));
}

Vector3 nonzero_vector(py::handle h, const char* what) {
  const Vector3 v = to_finite_eigen<3>(h, what);
  if (!(v.squaredNorm() > 0))
    raise_value_error(std::string(what) + ": expected a nonzero vector, got " + values_string(v));
  return v;
}

const char* const kArrayFunction = R"doc(

An array function: (n,) gives one result, (..., n) one per configuration,
by numpy's rules (broadcasting, dtypes, the GIL released; NaN gives NaN).)doc";

}  // namespace

void bind_kinematics(py::module_& m) {
  const Ufuncs u = register_ufuncs(m);
  register_ik(m);

  py::class_<PyChain> cls(m, "_Chain",
                          "The private model of chasles.Chain (python/chasles/_chain.py): the C++ chain "
                          "(include/chasles/kinematics.hpp) and the methods that compute.");
  cls.attr("__array_ufunc__") = py::none();  // numpy defers operators (np.float64(1.0) == c) to us
  cls.def(py::init([](ArrayLike screws, py::object home, py::object types, py::object lower, py::object upper,
                      py::object velocity, py::object effort, py::object base, py::object tool, py::object gravity,
                      py::object inertias, bool home_as_given, bool unit_screws) {
            return make_chain(screws.obj, home, types, lower, upper, velocity, effort, base, tool, gravity, inertias,
                              home_as_given, unit_screws);
          }),
          py::arg("screws"), py::arg("home"), py::arg("joint_types"), py::arg("lower"), py::arg("upper"),
          py::arg("velocity_limits"), py::arg("effort_limits"), py::arg("base"), py::arg("tool"), py::arg("gravity"),
          py::arg("link_inertias"), py::arg("home_as_given"), py::arg("unit_screws"),
          "The model from chasles.Chain's arguments (joint types as codes 0, 1, 2, 3 or None).");
  cls.def(
      "_check",
      [](Obj<PyChain> c) {
        return py::make_tuple(static_cast<int>(c->check.status), static_cast<int>(c->check.joint));
      },
      "Chain::validate(): (ChainStatus as an int, joint).");
  cls.def(
      "_arrays",
      [](Obj<PyChain> c) {
        const ChainD& x = c->chain;
        const py::ssize_t n = x.n_joints();
        const Py_intptr_t dims[2] = {n, 6};
        py::array_t<double> S = new_array(2, dims), B = new_array(2, dims);
        RowsMap(array_data(S), n, 6) = x.space_screws().transpose();
        RowsMap(array_data(B), n, 6) = x.body_screws().transpose();
        py::tuple types(n);
        for (py::ssize_t i = 0; i < n; ++i) types[static_cast<std::size_t>(i)] = static_cast<int>(x.joint_type(i));
        const auto vec = [n](const Joints& v) { return py::array_t<double>(n, v.data()); };
        return py::make_tuple(S, B, types, vec(x.lower()), vec(x.upper()), vec(x.velocity_limits()),
                              vec(x.effort_limits()), x.base(), x.tool(), vec_out<3>(x.gravity()));
      },
      "(space screws, body screws, type codes, lower, upper, velocity and effort limits, base, tool, gravity).");
  cls.def_property_readonly(
      "home", [](Obj<PyChain> c) { return c->chain.home(); }, R"doc(SE3: the home pose M = g(0).)doc");
  cls.def_static(
      "revolute_screw",
      [](ArrayLike point, ArrayLike direction) {
        const Vector3 q = to_finite_eigen<3>(point.obj, "Chain.revolute_screw(point)");
        return vec_out<6>(ChainD::revolute_screw(q, nonzero_vector(direction.obj, "Chain.revolute_screw(direction)")));
      },
      py::arg("point"), py::arg("direction"),
      R"doc(The screw (-w x q, w) of a revolute joint about the axis through point q along direction w.

The point comes first, as in ``SE3.from_screw``; both shape (3,), w nonzero (normalized here).
Returns shape (6,), (v, w).)doc");
  cls.def_static(
      "prismatic_screw",
      [](ArrayLike direction) {
        return vec_out<6>(ChainD::prismatic_screw(nonzero_vector(direction.obj, "Chain.prismatic_screw(direction)")));
      },
      py::arg("direction"),
      R"doc(The screw (v, 0) of a prismatic joint, v = direction / |direction| (shape (3,), nonzero).)doc");

  const auto ufunc_of = [&u](Op op) { return u[static_cast<std::size_t>(op)].ptr(); };
  // The methods of one joint argument (theta, or q for the dynamics).
  const auto one_argument = [&](auto op, const char* name, const char* arg, const char* doc, const char* tail) {
    constexpr Op o = decltype(op)::value;
    cls.def(
        name,
        [f = ufunc_of(o), name](Obj<PyChain> c, ArrayLike x) { return call<o, 1>(f, *c, name, {x.obj}, nullptr); },
        py::arg(arg), (std::string(doc) + kArrayFunction + tail).c_str());
  };
  const auto kinematics = [&](auto op, const char* name, const char* doc) { one_argument(op, name, "theta", doc, ""); };
  kinematics(std::integral_constant<Op, Op::forward>(), "forward",
             R"doc(Forward kinematics, space form: g(theta) = exp([S_1] th_1) ... exp([S_n] th_n) M.

theta: array_like (..., n), joint positions; returns (..., 4, 4), the tool frame's matrices.)doc");
  kinematics(std::integral_constant<Op, Op::forward_body>(), "forward_body",
             R"doc(Forward kinematics, body form: g(theta) = M exp([B_1] th_1) ... exp([B_n] th_n).

Equal to ``forward`` up to rounding. theta: array_like (..., n); returns (..., 4, 4).)doc");
  kinematics(std::integral_constant<Op, Op::jacobian_space>(), "jacobian_space",
             R"doc(The space Jacobian J_s: (g' g^-1)^vee = J_s theta'.

Column i is Ad_{exp([S_1] th_1) ... exp([S_{i-1}] th_{i-1})} S_i, rows (v, w); J_s = Ad_g J_b.
theta: array_like (..., n); returns (..., 6, n).)doc");
  kinematics(std::integral_constant<Op, Op::jacobian_body>(), "jacobian_body",
             R"doc(The body Jacobian J_b: (g^-1 g')^vee = J_b theta'.

Column i is Ad_{(exp([B_{i+1}] th_{i+1}) ... exp([B_n] th_n))^-1} B_i, rows (v, w).
theta: array_like (..., n); returns (..., 6, n).)doc");

  cls.def_static(
      "_set_ik_result", [](py::object type) { ik_result_type = type.release().ptr(); }, py::arg("type"),
      "Hands over chasles._results.IKResult, the result type of inverse_kinematics (called by chasles._chain).");
  cls.def(
      "inverse_kinematics",
      [](Obj<PyChain> c, ArrayLike target, ArrayLike q0, RealLike position_tolerance, RealLike orientation_tolerance,
         IndexLike max_iterations, IndexLike restarts, IndexLike seed, OptionalRealLike max_time) {
        return IKResultObject{
            inverse_kinematics(*c, target.obj, q0.obj,
                               ik_arguments(position_tolerance.obj, orientation_tolerance.obj, max_iterations.obj,
                                            restarts.obj, seed.obj, max_time.obj))};
      },
      py::arg("target"), py::arg("q0"), py::kw_only(),
      py::arg_v("position_tolerance", py::float_(chasles::Thresholds<double>::ik_tolerance), "3.666852862501036e-11"),
      py::arg_v("orientation_tolerance", py::float_(chasles::Thresholds<double>::ik_tolerance),
                "3.666852862501036e-11"),
      py::arg_v("max_iterations", py::int_(chasles::Thresholds<double>::ik_max_iterations), "100"),
      py::arg_v("restarts", py::int_(0), "0"), py::arg_v("seed", py::int_(0), "0"),
      py::arg_v("max_time", py::none(), "None"),
      R"doc(Inverse kinematics: joint positions q with forward(q) = target, within the joint limits.

Levenberg-Marquardt on the body error e(q) = log(forward(q)^-1 target)
(twist (v, w) in the tool frame) with its exact Jacobian -J_l(e)^-1 J_b(q),
each step projected onto [lower, upper], at most max_iterations iterations
per attempt; then, while not converged, up to ``restarts`` more attempts
from seeds uniform within the limits ([-pi, pi] where a limit is infinite),
drawn from a 64-bit Mersenne twister seeded with ``seed`` (an attempt that
a restart follows ends as soon as it stalls, |e|^2 above 0.9 of its value
8 iterations before; the last runs on); all within
``max_time`` seconds when given (checked before each iteration). The C++
solver (chasles/inverse_kinematics.hpp) runs with the GIL released.

The field's protocols (TRAC-IK's: 5 ms per solve) read
``inverse_kinematics(T, q0, restarts=2**31 - 1, max_time=0.005)``: restart
until solved or out of time.

Targets and seeds broadcast: one target (an SE3 or (4, 4)) and q0 (n,) give
one solve; (..., 4, 4) targets and/or (..., n) seeds give a batch (the
private gufunc ``chasles._core._inverse_kinematics``). Element i of a batch
(in C order) draws its restarts from a generator seeded with ``seed + i``
and has a budget of its own: it equals the single solve with that seed.

Args:
    target: SE3 or array_like of shape (4, 4) or (..., 4, 4), the tool pose(s).
    q0: array_like of shape (n,) or (..., n), the seed(s) (clamped into the limits).
    position_tolerance: |e_v| at a solution (the chain's length unit); default 3.7e-11.
    orientation_tolerance: |e_w| at a solution (radians); default 3.7e-11.
    max_iterations: iterations per attempt (>= 0).
    restarts: further attempts from random seeds while not converged (>= 0).
    seed: the seed of those random seeds (0 <= seed < 2**64; seed + i for
        element i of a batch).
    max_time: the time budget of a solve in seconds, restarts included
        (None: none). A solve ends at most one iteration after it.

Returns:
    IKResult: a named tuple (q, converged, status, iterations,
    total_iterations, attempts, error): q of shape (n,); converged a bool;
    status why it stopped, a str: "converged", "iteration_bound" (the last
    attempt ran max_iterations iterations), "time_budget" (max_time ran out)
    or "no_progress" (stalled at a local minimum of |e|: its step below
    rounding, or, when a restart followed, |e|^2 above 0.9 of its value 8
    iterations before);
    iterations of the attempt that gave q; total_iterations of all
    attempts; attempts made (1 + the restarts taken); the body error twist e
    of shape (6,). For a batch, arrays of shapes (..., n), (...) (status:
    str), and (..., 6).

Raises:
    ValueError: a target that is not a rigid motion, shapes that do not
        match or broadcast, a non-finite seed, negative counts, tolerances
        or time.
    TypeError: an argument of the wrong type.

Example:
    >>> arm = Chain([Chain.revolute_screw([0, 0, 0], [0, 0, 1]),
    ...              Chain.revolute_screw([1, 0, 0], [0, 0, 1])], SE3(SO3(), [2, 0, 0]))
    >>> r = arm.inverse_kinematics(arm.forward([0.3, -0.5]), [0.0, -0.2])
    >>> r.converged, r.status, np.round(r.q, 12) + 0.0
    (True, 'converged', array([ 0.3, -0.5]))
)doc");

  PyObject *f_jsd = ufunc_of(Op::jacobian_space_dot), *f_jbd = ufunc_of(Op::jacobian_body_dot);
  cls.def(
      "jacobian_space_dot",
      [f_jsd](Obj<PyChain> c, py::object theta, py::object theta_dot) {
        return call<Op::jacobian_space_dot, 2>(f_jsd, *c, "jacobian_space_dot", {theta, theta_dot}, nullptr);
      },
      py::arg("theta"), py::arg("theta_dot"),
      (std::string(R"doc(The time derivative of the space Jacobian, dJ_s/dt, at joint positions and velocities.

Column i is [V_{i-1}, S_i(theta)]: the bracket of the twist of the link before joint i
(sum_{j<i} S_j(theta) theta_dot_j) with joint i's screw. The tool's spatial acceleration
(the time derivative of V^s) is J_s theta_ddot + J_s_dot theta_dot.
theta, theta_dot: array_like (..., n); returns (..., 6, n).)doc") +
       kArrayFunction)
          .c_str());
  cls.def(
      "jacobian_body_dot",
      [f_jbd](Obj<PyChain> c, py::object theta, py::object theta_dot) {
        return call<Op::jacobian_body_dot, 2>(f_jbd, *c, "jacobian_body_dot", {theta, theta_dot}, nullptr);
      },
      py::arg("theta"), py::arg("theta_dot"),
      (std::string(R"doc(The time derivative of the body Jacobian, dJ_b/dt, at joint positions and velocities.

Column i is Ad_{g^-1} [V_{i-1} - V^s, S_i(theta)] (V^s = J_s theta_dot). The tool's body
acceleration is J_b theta_ddot + J_b_dot theta_dot: what a task-space controller feeds forward.
theta, theta_dot: array_like (..., n); returns (..., 6, n).)doc") +
       kArrayFunction)
          .c_str());

  // ---- dynamics (chasles/dynamics.hpp)
  const char* const kRaises = R"doc( ValueError: a chain without link inertias, shapes that do not match.)doc";
  PyObject *f_inverse = ufunc_of(Op::inverse), *f_forward = ufunc_of(Op::forward_dynamics),
           *f_coriolis = ufunc_of(Op::coriolis);
  cls.def(
      "inverse_dynamics",
      [f_inverse](Obj<PyChain> c, py::object q, py::object qd, py::object qdd, py::object tip) {
        return call<Op::inverse, 3>(f_inverse, *c, "inverse_dynamics", {q, qd, qdd}, &tip);
      },
      py::arg("q"), py::arg("qd"), py::arg("qdd"), py::kw_only(), py::arg("tip_wrench") = py::none(),
      (std::string(R"doc(Inverse dynamics: tau = M(q) qdd + C(q, qd) qd + g(q) + J_b(q)^T F_tip (Newton-Euler).

q, qd, qdd: array_like (..., n); tip_wrench: (..., 6) or a Wrench, (f, tau) that the tool
applies on the environment, in the tool frame (Modern Robotics' F_tip); None: zero.
Returns (..., n), N m for revolute joints and N for prismatic ones.)doc") +
       kArrayFunction + kRaises)
          .c_str());
  cls.def(
      "forward_dynamics",
      [f_forward](Obj<PyChain> c, py::object q, py::object qd, py::object tau, py::object tip, py::object on_failure) {
        return call<Op::forward_dynamics, 3>(f_forward, *c, "forward_dynamics", {q, qd, tau}, &tip,
                                             failure_raises("forward_dynamics", on_failure));
      },
      py::arg("q"), py::arg("qd"), py::arg("tau"), py::kw_only(), py::arg("tip_wrench") = py::none(),
      py::arg("on_failure") = "raise",
      (std::string(R"doc(Forward dynamics: qdd = M(q)^-1 (tau - C(q, qd) qd - g(q) - J_b^T F_tip).

By the composite inertias and a Cholesky factorization of M(q), or from 30 joints on by the
articulated-body algorithm, O(n) (the faster of the two; they agree to rounding).
q, qd, tau: array_like (..., n); tip_wrench as in inverse_dynamics. Where M(q) is not
positive definite (a massless link, a point mass on its axis, an inertia no rigid body has:
chasles::DynamicsStatus) there are no accelerations: ValueError naming the joint (and the
first such batch index), or with on_failure="nan" NaN there only. Returns (..., n).)doc") +
       kArrayFunction + kRaises)
          .c_str());
  one_argument(std::integral_constant<Op, Op::mass>(), "mass_matrix", "q",
               R"doc(The joint-space mass matrix M(q), symmetric positive definite (composite rigid bodies).

q: array_like (..., n); returns (..., n, n).)doc",
               kRaises);
  one_argument(std::integral_constant<Op, Op::gravity>(), "gravity_torques", "q",
               R"doc(The torques g(q) that hold the chain still against gravity: inverse_dynamics(q, 0, 0).

q: array_like (..., n); returns (..., n).)doc",
               kRaises);
  cls.def(
      "coriolis",
      [f_coriolis](Obj<PyChain> c, py::object q, py::object qd) {
        return call<Op::coriolis, 2>(f_coriolis, *c, "coriolis", {q, qd}, nullptr);
      },
      py::arg("q"), py::arg("qd"),
      (std::string(R"doc(The Coriolis and centrifugal torques C(q, qd) qd (no gravity).

q, qd: array_like (..., n); returns (..., n).)doc") +
       kArrayFunction + kRaises)
          .c_str());

  // ---- derivatives (chasles/dynamics_derivatives.hpp)
  PyObject *f_id = ufunc_of(Op::inverse_derivatives), *f_fd = ufunc_of(Op::forward_derivatives),
           *f_minv = ufunc_of(Op::mass_inverse);
  cls.def(
      "inverse_dynamics_derivatives",
      [f_id](Obj<PyChain> c, py::object q, py::object qd, py::object qdd, py::object tip) {
        return call<Op::inverse_derivatives, 3>(f_id, *c, "inverse_dynamics_derivatives", {q, qd, qdd}, &tip);
      },
      py::arg("q"), py::arg("qd"), py::arg("qdd"), py::kw_only(), py::arg("tip_wrench") = py::none(),
      (std::string(R"doc(The partial derivatives (dtau_dq, dtau_dqd) of inverse_dynamics at (q, qd, qdd), analytic.

dtau_dq[i, j] = d tau_i / d q_j, likewise for qd; d tau / d qdd is mass_matrix(q). The
recursion of inverse dynamics differentiated in closed form (base frame; Carpentier and
Mansard, RSS 2018), O(n^2): what an optimal-control or MPC solver linearizes with.
q, qd, qdd: array_like (..., n); tip_wrench as in inverse_dynamics. Returns two arrays of
shape (..., n, n).)doc") +
       kArrayFunction + kRaises)
          .c_str());
  cls.def(
      "forward_dynamics_derivatives",
      [f_fd](Obj<PyChain> c, py::object q, py::object qd, py::object tau, py::object tip, py::object on_failure) {
        return call<Op::forward_derivatives, 3>(f_fd, *c, "forward_dynamics_derivatives", {q, qd, tau}, &tip,
                                                failure_raises("forward_dynamics_derivatives", on_failure));
      },
      py::arg("q"), py::arg("qd"), py::arg("tau"), py::kw_only(), py::arg("tip_wrench") = py::none(),
      py::arg("on_failure") = "raise",
      (std::string(R"doc(The partial derivatives (dqdd_dq, dqdd_dqd, dqdd_dtau) of forward_dynamics at (q, qd, tau).

With qdd = forward_dynamics(q, qd, tau): dqdd_dq = -M^-1 dtau_dq, dqdd_dqd = -M^-1 dtau_dqd
(inverse_dynamics_derivatives at (q, qd, qdd)) and dqdd_dtau = M(q)^-1, analytic, O(n^3).
Fails where forward_dynamics fails (ValueError, or NaN with on_failure="nan").
q, qd, tau: array_like (..., n); tip_wrench as in inverse_dynamics. Returns three arrays of
shape (..., n, n).)doc") +
       kArrayFunction + kRaises)
          .c_str());
  cls.def(
      "mass_matrix_inverse",
      [f_minv](Obj<PyChain> c, py::object q, py::object on_failure) {
        return call<Op::mass_inverse, 1>(f_minv, *c, "mass_matrix_inverse", {q}, nullptr,
                                         failure_raises("mass_matrix_inverse", on_failure));
      },
      py::arg("q"), py::kw_only(), py::arg("on_failure") = "raise",
      (std::string(R"doc(M(q)^-1, by the Cholesky factorization of forward_dynamics (Pinocchio's computeMinverse).

Fails where forward_dynamics fails (ValueError, or NaN with on_failure="nan").
q: array_like (..., n); returns (..., n, n).)doc") +
       kArrayFunction + kRaises)
          .c_str());
}

}  // namespace chasles_py
