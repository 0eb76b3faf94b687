// chasles._core: class Chain over chasles::Chain<double, Dynamic, 32>
// (include/chasles/kinematics.hpp): product-of-exponentials kinematics of a
// serial chain of up to 32 joints, and its dynamics over
// chasles::Dynamics<double, Dynamic, 32> (include/chasles/dynamics.hpp).
#include <chasles/dynamics.hpp>
#include <chasles/inverse_kinematics.hpp>
#include <chasles/kinematics.hpp>
#include <chasles/spatial_inertia.hpp>

#include <cmath>
#include <memory>
#include <random>
#include <cstring>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "conventions.hpp"
#include "convert.hpp"
#include "numpy_capi.hpp"
#include "ufunc.hpp"

namespace chasles_py {

namespace {

constexpr int kMaxJoints = 32;
using ChainD = chasles::Chain<double, Eigen::Dynamic, kMaxJoints>;
using DynD = ChainD;
using InertiaD = chasles::SpatialInertia<double>;
using chasles::SE3d;
using Vector3 = Eigen::Vector3d;
using Matrix4 = Eigen::Matrix4d;
using InertiaRows = Eigen::Matrix<double, Eigen::Dynamic, 10, Eigen::RowMajor, kMaxJoints, 10>;

/// What the dynamics methods use, built once when the chain is made: the
/// operands that every dynamics ufunc (bind_dynamics.cpp) starts with (the
/// screws (n, 6), the home pose (4, 4), the links' spatial inertia matrices
/// (n, 6, 6) in the world frame at home, gravity (3)), and the C++ Dynamics
/// that the ufunc loop builds from those operands (the same numbers: the
/// inertias read back from their matrices by
/// SpatialInertia::from_matrix_unchecked, as the loop reads them), which
/// computes one configuration without numpy's dispatch, to the same bits.
struct DynamicsModel {
  py::array screws, home, inertias, gravity;
  DynD model;
};

/// The Python Chain: the C++ chain (the model every computation uses, link
/// inertias included), and what only Python needs, kept beside it: the
/// screws and home pose as given (before base and tool: pickling rebuilds
/// the chain from them, bit for bit), the joint names (strings allocate: the
/// real-time C++ chain has no use for them), the link inertias as given
/// (n x 10 numbers, for link_inertias and pickling), and the dynamics model
/// (null when no inertias were given: the dynamics methods refuse such a
/// chain rather than compute a massless one).
struct PyChain : ChainD {
  ChainD::Screws given_screws;
  SE3d given_home, given_base, given_tool;
  std::vector<std::string> names;  // empty: none given
  bool has_inertias = false;
  InertiaRows inertias;  // n x 10: mass, com (3), ixx, ixy, ixz, iyy, iyz, izz
  std::shared_ptr<const DynamicsModel> dynamics;  // immutable, shared by copies

  PyChain(const ChainD& c, const ChainD::Screws& S0, const SE3d& M0, const SE3d& base, const SE3d& tool)
      : ChainD(c), given_screws(S0), given_home(M0), given_base(base), given_tool(tool) {}
};

const char* const kJointTypeNames[3] = {"revolute", "continuous", "prismatic"};

const char* const kClassDoc = R"doc(Forward kinematics and Jacobians of a serial chain by the product of exponentials
(Murray, Li and Sastry, ch. 3; Lynch and Park, Modern Robotics, ch. 4-5).

The chain is given by its space screws S_i (the joint twists at the home
configuration in the base frame, one row (v, w) per joint, linear part first)
and its home pose M = g(0); it keeps the body screws B_i = Ad_{M^-1} S_i.
Revolute joints about the axis through q along w have the screw
(-w x q, w) (``Chain.revolute_screw(point, direction)``: the point first, as
in ``SE3.from_screw``), prismatic joints along v the screw (v, 0)
(``Chain.prismatic_screw``). At most 32 joints. Its methods forward,
forward_body, jacobian_space and jacobian_body are array functions: joint
positions of shape (..., n) in, arrays out.

Example:
    >>> screws = [Chain.revolute_screw([0, 0, 0], [0, 0, 1]),
    ...           Chain.revolute_screw([1, 0, 0], [0, 0, 1])]
    >>> arm = Chain(screws, SE3(translation=[2.0, 0.0, 0.0]))
    >>> np.round(arm.forward([np.pi / 2, 0.0])[:3, 3], 12) + 0.0
    array([0., 2., 0.])
    >>> arm.jacobian_space([0.0, 0.0]).shape
    (6, 2)
)doc";

std::string class_doc() { return std::string(kClassDoc) + kConventions; }

/// The home pose: an SE3 (TypeError for one not initialized), or a (4, 4)
/// array-like rigid motion.
SE3d home_pose(py::handle h, const char* what = "Chain(home)") {
  py::detail::make_caster<Obj<SE3d>> caster;
  if (caster.load(h, false)) return *static_cast<Obj<SE3d>&>(caster);
  const Matrix4 M = to_finite_eigen<4, 4>(h, what);
  const auto g = SE3d::from_matrix(M);
  if (!g) {
    raise_value_error(std::string(what) + ": not a rigid motion (transform defect " +
                      short_float(SE3d::transform_defect(M)) +
                      "); pass an SE3 or a 4x4 matrix [[R, p], [0, 0, 0, 1]] with R a rotation");
  }
  return *g;
}

std::string array_shape(const py::array& a) {
  return shape_string(reinterpret_cast<const Py_intptr_t*>(a.shape()), static_cast<int>(a.ndim()));
}

/// The screws as an (n, 6) array-like, n in [1, 32], finite.
ChainD::Screws screws_of(py::handle h) {
  const py::array a = as_float64_array(h, "Chain(screws)");
  if (a.ndim() != 2 || a.shape(1) != 6 || a.shape(0) < 1) {
    const bool columns = a.ndim() == 2 && a.shape(0) == 6 && a.shape(1) >= 1;
    raise_value_error("Chain(screws): expected shape (n, 6) with n >= 1 (one row (v, w) per joint), got " +
                      array_shape(a) +
                      (columns ? "; a table of one column per joint is transposed: pass screws.T (Modern Robotics' "
                                 "Slist, 6 x n in the (w, v) order: [Twist.from_modern_robotics(s).vector for s in "
                                 "Slist.T])"
                               : ""));
  }
  if (a.shape(0) > kMaxJoints) {
    raise_value_error("Chain(screws): at most " + std::to_string(kMaxJoints) + " joints, got " +
                      std::to_string(a.shape(0)));
  }
  const py::ssize_t n = a.shape(0);
  ChainD::Screws S(6, n);
  const char* data = static_cast<const char*>(a.data());
  for (py::ssize_t i = 0; i < n; ++i)
    for (py::ssize_t k = 0; k < 6; ++k)
      S(k, i) = *reinterpret_cast<const double*>(data + i * a.strides(0) + k * a.strides(1));
  require_finite(S, "Chain(screws)");
  return S;
}

// ---- the product-of-exponentials ufuncs behind Chain's methods ----------------
//
// (n,6),(4,4),(n)->(4,4) for the poses, (n,6),(4,4),(n)->(6,n) for the
// Jacobians: the space screws (one row (v, w) per joint), the home pose and
// the joint positions, n <= 32 bound at run time. Registered by def_ufunc
// (ufunc.hpp) with the chain as the model of the first two operands, built
// once per loop when they stay put (as when Chain's methods pass the
// chain's own screws and home pose); numpy does the broadcasting, dtypes,
// out= and GIL, as for every array function. float64 only: the chain is.

using ufunc::Core;
using ufunc::upto;
using JointsCore = Core<upto<kMaxJoints>>;
using ScrewsCore = Core<upto<kMaxJoints>, 6>;

/// The chain of a screws (n, 6) and a home (4, 4) operand, the home taken
/// as given (the Chain passes its own, already a rigid motion).
struct ChainOf {
  template <typename S, typename M>
  ChainD operator()(const S& screws, const M& home) const noexcept {
    return ChainD(ChainD::Screws(screws.transpose()), SE3d::from_matrix_unchecked(Matrix4(home)), ChainD::HomeAsGiven());
  }
};

enum class ChainOp { forward, forward_body, jacobian_space, jacobian_body };

/// What the method computes for one configuration: the 4x4 pose or the 6 x n
/// Jacobian (the ufunc's kernel and the one-configuration fast path both
/// call this).
template <ChainOp Op>
auto chain_result(const ChainD& c, const ChainD::JointVector& theta) {
  if constexpr (Op == ChainOp::forward)
    return c.forward(theta).matrix();
  else if constexpr (Op == ChainOp::forward_body)
    return c.forward_body(theta).matrix();
  else if constexpr (Op == ChainOp::jacobian_space)
    return c.jacobian_space(theta);
  else
    return c.jacobian_body(theta);
}

template <ChainOp Op>
struct ChainKernel {
  template <typename Theta>
  auto operator()(const ChainD& c, const Theta& theta) const noexcept {
    return chain_result<Op>(c, ChainD::JointVector(theta));
  }
};

/// Registers the private ufunc `name` of Op, behind the Chain method `method`.
template <ChainOp Op>
py::object chain_ufunc(py::module_& m, const char* name, const char* method) {
  constexpr bool pose = Op == ChainOp::forward || Op == ChainOp::forward_body;
  using Out = std::conditional_t<pose, Core<4, 4>, Core<6, upto<kMaxJoints>>>;
  return ufunc::def_ufunc<Out(ScrewsCore, Core<4, 4>, JointsCore), ufunc::Float64>(
      m, name, "screws, home, theta",
      std::string("A private ufunc of chasles.Chain (its method ") + method +
          "): screws (n, 6), 1 <= n <= 32 (NaN beyond), home (4, 4), theta (n,); float64.",
      ufunc::model<2>(ChainOf()), ChainKernel<Op>());
}

/// The chain's space screws, shape (n, 6), and home pose, shape (4, 4), as
/// the ufuncs' first two operands.
py::array screws_array(const ChainD& c) {
  const Py_intptr_t dims[2] = {c.n_joints(), 6};
  py::array_t<double> out = new_array(2, dims);
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>>(array_data(out), c.n_joints(), 6) =
      c.space_screws().transpose();
  return std::move(out);
}

/// A ufunc operand of joint values of shape (..., n), its last axis checked
/// against the chain's n (numpy would name only the operand's index).
py::object joint_operand(py::handle x, py::ssize_t n, const char* what) {
  py::object operand = ufunc_operand(x, what);
  if (npy().PyArray_Check_(operand.ptr())) {
    const auto a = py::reinterpret_borrow<py::array>(operand);
    if (a.ndim() < 1 || a.shape(a.ndim() - 1) != n)
      raise_value_error(std::string(what) + ": expected shape (" + std::to_string(n) + ",) or (..., " +
                        std::to_string(n) + ") for a chain of " + std::to_string(n) + " joints, got " +
                        shape_string(a.shape(), static_cast<int>(a.ndim())));
  }
  return operand;
}

/// Calls the chain ufunc u with the chain and theta: numpy's rules decide
/// dtypes and broadcasting. The last axis of theta is checked here, so that
/// the message names the method and n. One configuration of float64 (a
/// native float64 array of shape (n,), or a list of n Python numbers) skips
/// numpy's dispatch: the same chain_result, the same bits
/// (tests/python/test_ufuncs.py compares the two).
template <ChainOp Op>
py::object call_chain_ufunc(PyObject* u, const ChainD& c, py::handle theta, const char* what) {
  const py::ssize_t n = c.n_joints();
  if (ChainD::JointVector one(n); single_element(theta, one.data(), n)) {
    const auto result = chain_result<Op>(c, one);
    const Py_intptr_t dims[2] = {result.rows(), result.cols()};
    py::array_t<double> out = new_array(2, dims);
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(array_data(out), dims[0],
                                                                                        dims[1]) = result;
    return std::move(out);
  }
  const py::object operand = joint_operand(theta, n, what);
  const py::array S = screws_array(c);
  const py::array M = mat_out<4, 4>(c.home().matrix());
  return call_ufunc<3>(u, what, {S.ptr(), M.ptr(), operand.ptr()});
}

Vector3 nonzero_vector(py::handle h, const char* what) {
  const Vector3 v = to_finite_eigen<3>(h, what);
  if (!(v.squaredNorm() > 0)) raise_value_error(std::string(what) + ": expected a nonzero vector, got " + values_string(v));
  return v;
}

/// An optional (n,) array-like of limits: `fill` when None; NaN refused.
ChainD::JointVector limits_of(py::handle h, py::ssize_t n, double fill, const char* what) {
  ChainD::JointVector out = ChainD::JointVector::Constant(n, fill);
  if (h.is_none()) return out;
  const py::array a = as_float64_array(h, what);
  if (a.ndim() != 1 || a.shape(0) != n)
    raise_value_error(std::string(what) + ": expected shape (" + std::to_string(n) + ",) (one per joint), got " +
                      array_shape(a));
  const char* data = static_cast<const char*>(a.data());
  for (py::ssize_t i = 0; i < n; ++i) out(i) = *reinterpret_cast<const double*>(data + i * a.strides(0));
  if (out.array().isNaN().any()) raise_value_error(std::string(what) + ": expected numbers, got NaN");
  return out;
}

/// The types as given (sequence of n of "revolute", "continuous",
/// "prismatic"), or inferred from the screws when None.
ChainD::JointTypes types_of(py::handle h, const ChainD::Screws& S) {
  ChainD::JointTypes types{};
  const py::ssize_t n = S.cols();
  if (h.is_none()) {
    for (py::ssize_t i = 0; i < n; ++i)
      types[static_cast<std::size_t>(i)] =
          S.col(i).tail<3>().squaredNorm() > 0 ? chasles::JointType::revolute : chasles::JointType::prismatic;
    return types;
  }
  if (py::isinstance<py::str>(h) || !PySequence_Check(h.ptr()))
    raise_type_error("Chain(joint_types): expected a sequence of " + std::to_string(n) +
                     " of 'revolute', 'continuous', 'prismatic', got " + type_name(h));
  const py::sequence seq = py::reinterpret_borrow<py::sequence>(h);
  if (static_cast<py::ssize_t>(py::len(seq)) != n)
    raise_value_error("Chain(joint_types): expected " + std::to_string(n) + " types (one per joint), got " +
                      std::to_string(py::len(seq)));
  for (py::ssize_t i = 0; i < n; ++i) {
    const py::object item = seq[static_cast<size_t>(i)];
    if (!py::isinstance<py::str>(item))
      raise_type_error("Chain(joint_types): expected strings, got " + type_name(item) + " for joint " +
                       std::to_string(i));
    const std::string t = item.cast<std::string>();
    int k = 0;
    while (k < 3 && t != kJointTypeNames[k]) ++k;
    if (k == 3)
      raise_value_error("Chain(joint_types): expected 'revolute', 'continuous' or 'prismatic', got '" + t +
                        "' for joint " + std::to_string(i));
    types[static_cast<std::size_t>(i)] = static_cast<chasles::JointType>(k);
  }
  return types;
}

/// The screws with each row's halves swapped ((w, v) read as (v, w)).
ChainD::Screws swapped(const ChainD::Screws& S) {
  ChainD::Screws out(6, S.cols());
  out.topRows<3>() = S.bottomRows<3>();
  out.bottomRows<3>() = S.topRows<3>();
  return out;
}

/// Whether screws S with these types (inferred when `inferred`) are valid.
bool screws_valid(const ChainD::Screws& S, const ChainD::JointTypes& given, bool inferred) {
  const ChainD::JointTypes types = inferred ? types_of(py::none(), S) : given;
  const py::ssize_t n = S.cols();
  const ChainD c(S, SE3d(), types, ChainD::JointVector::Constant(n, -INFINITY), ChainD::JointVector::Constant(n, INFINITY),
                 ChainD::JointVector::Constant(n, INFINITY), ChainD::JointVector::Constant(n, INFINITY));
  return static_cast<bool>(c.validate());
}

/// ValueError for a chain whose validate() fails, naming the joint, the
/// rule, and the conversion when the screws read as Modern Robotics' (w, v)
/// order or as a transposed 6 x 6 table would be valid.
[[noreturn]] void raise_invalid(const ChainD& c, const chasles::ChainCheck& check, const ChainD::Screws& S0,
                                const ChainD::JointTypes& types, bool inferred) {
  using chasles::ChainStatus;
  const std::string joint = "joint " + std::to_string(check.joint);
  std::string message;
  switch (check.status) {
    case ChainStatus::revolute_axis_not_unit:
      message = "Chain(screws): " + joint + " is revolute but its angular part w is not a unit vector (|w| = " +
                short_float(std::sqrt(S0.col(check.joint).tail<3>().squaredNorm())) + ")";
      break;
    case ChainStatus::revolute_pitch_not_zero:
      message = "Chain(screws): " + joint + " is revolute but its screw has a pitch: w . v = " +
                short_float(S0.col(check.joint).tail<3>().dot(S0.col(check.joint).head<3>())) +
                " (a revolute screw is (-w x q, w))";
      break;
    case ChainStatus::prismatic_rotates:
      message = "Chain(screws): " + joint + " is prismatic but its angular part w is not zero";
      break;
    case ChainStatus::prismatic_axis_not_unit:
      message = "Chain(screws): " + joint + " is prismatic but its linear part v is not a unit vector (|v| = " +
                short_float(std::sqrt(S0.col(check.joint).head<3>().squaredNorm())) + ")";
      break;
    case ChainStatus::position_limits_invalid:
      raise_value_error("Chain(lower, upper): " + joint + ": expected lower <= upper (-inf and inf for a " +
                        "continuous joint), got " + float_repr(c.lower()(check.joint)) + " and " +
                        float_repr(c.upper()(check.joint)));
    case ChainStatus::velocity_or_effort_limit_invalid:
      raise_value_error("Chain(velocity_limits, effort_limits): " + joint + ": expected limits >= 0, got " +
                        float_repr(c.velocity_limits()(check.joint)) + " and " +
                        float_repr(c.effort_limits()(check.joint)));
    case ChainStatus::link_inertia_invalid:
      raise_value_error("Chain(link_inertias): " + joint +
                        ": expected finite numbers and a mass >= 0 (moved into the world frame by the base frame)");
    default:
      raise_value_error("Chain(gravity): expected finite numbers");
  }
  message += " (tolerance " + short_float(chasles::Thresholds<double>::screw_tolerance) + ")";
  if (screws_valid(swapped(S0), types, inferred)) {
    message += "; these rows read as Modern Robotics' (w, v) order: convert each with "
               "Twist.from_modern_robotics(row).vector";
  } else if (S0.cols() == 6) {
    const ChainD::Screws T = S0.transpose();
    if (screws_valid(T, types, inferred))
      message += "; the table reads as transposed (one column per joint): pass screws.T";
    else if (screws_valid(swapped(T), types, inferred))
      message += "; the table reads as Modern Robotics' Slist (6 x n, one column (w, v) per joint): pass "
                 "[Twist.from_modern_robotics(s).vector for s in Slist.T]";
  }
  raise_value_error(message);
}

std::shared_ptr<const DynamicsModel> dynamics_model(const ChainD& c);

/// The chain from the constructor's arguments (validated).
PyChain make_chain(py::handle screws, py::handle home, py::handle joint_types, py::handle names, py::handle lower,
                   py::handle upper, py::handle velocity_limits, py::handle effort_limits, py::handle base,
                   py::handle tool, py::handle gravity, py::handle link_inertias) {
  const ChainD::Screws S0 = screws_of(screws);
  const SE3d M0 = home_pose(home);
  const py::ssize_t n = S0.cols();
  const bool inferred = joint_types.is_none();
  const ChainD::JointTypes types = types_of(joint_types, S0);
  const ChainD::JointVector lo = limits_of(lower, n, -INFINITY, "Chain(lower)");
  const ChainD::JointVector hi = limits_of(upper, n, INFINITY, "Chain(upper)");
  const ChainD::JointVector vel = limits_of(velocity_limits, n, INFINITY, "Chain(velocity_limits)");
  const ChainD::JointVector eff = limits_of(effort_limits, n, INFINITY, "Chain(effort_limits)");
  const SE3d b = base.is_none() ? SE3d() : home_pose(base, "Chain(base)");
  const SE3d t = tool.is_none() ? SE3d() : home_pose(tool, "Chain(tool)");
  const Vector3 g = gravity.is_none() ? ChainD::default_gravity() : to_finite_eigen<3>(gravity, "Chain(gravity)");
  InertiaRows given_inertias;  // n x 10
  ChainD::Inertias link{};  // zero (massless) when none are given
  if (!link_inertias.is_none()) {
    const py::array a = as_float64_array(link_inertias, "Chain(link_inertias)");
    if (a.ndim() != 2 || a.shape(0) != n || a.shape(1) != 10)
      raise_value_error("Chain(link_inertias): expected shape (" + std::to_string(n) +
                        ", 10) (mass, com (3), ixx, ixy, ixz, iyy, iyz, izz per joint), got " + array_shape(a));
    given_inertias.resize(n, 10);
    const char* data = static_cast<const char*>(a.data());
    for (py::ssize_t i = 0; i < n; ++i)
      for (py::ssize_t k = 0; k < 10; ++k)
        given_inertias(i, k) = *reinterpret_cast<const double*>(data + i * a.strides(0) + k * a.strides(1));
    require_finite(given_inertias, "Chain(link_inertias)");
    if ((given_inertias.col(0).array() < 0).any())
      raise_value_error("Chain(link_inertias): expected masses >= 0 (column 0)");
    for (py::ssize_t i = 0; i < n; ++i) {
      const auto row = given_inertias.row(i);
      Eigen::Matrix3d I;
      I << row(4), row(5), row(6), row(5), row(7), row(8), row(6), row(8), row(9);
      link[static_cast<std::size_t>(i)] = InertiaD(row(0), Vector3(row(1), row(2), row(3)), I);
    }
  }
  PyChain c(ChainD(S0, M0, types, lo, hi, vel, eff, b, t, g, link), S0, M0, b, t);
  if (const chasles::ChainCheck check = c.validate(); !check) raise_invalid(c, check, S0, types, inferred);
  if (!names.is_none()) {
    if (py::isinstance<py::str>(names) || !PySequence_Check(names.ptr()))
      raise_type_error("Chain(names): expected a sequence of " + std::to_string(n) + " strings, got " + type_name(names));
    const py::sequence seq = py::reinterpret_borrow<py::sequence>(names);
    if (static_cast<py::ssize_t>(py::len(seq)) != n)
      raise_value_error("Chain(names): expected " + std::to_string(n) + " names (one per joint), got " +
                        std::to_string(py::len(seq)));
    for (py::ssize_t i = 0; i < n; ++i) {
      const py::object item = seq[static_cast<size_t>(i)];
      if (!py::isinstance<py::str>(item))
        raise_type_error("Chain(names): expected strings, got " + type_name(item) + " for joint " + std::to_string(i));
      c.names.push_back(item.cast<std::string>());
    }
  }
  if (!link_inertias.is_none()) {
    c.inertias = given_inertias;
    c.has_inertias = true;
    c.dynamics = dynamics_model(c);
  }
  return c;
}

py::array vector_out(const ChainD::JointVector& v) {
  const Py_intptr_t dims[1] = {v.size()};
  py::array_t<double> out = new_array(1, dims);
  for (Eigen::Index i = 0; i < v.size(); ++i) array_data(out)[i] = v(i);
  return std::move(out);
}

/// make(), its ValueError or TypeError (the constructor's, for a state that
/// does not make a valid chain) prefixed with "Chain.__setstate__: ".
template <typename Make>
PyChain setstate_checked(Make make) {
  try {
    return make();
  } catch (py::value_error& e) {
    throw py::value_error(std::string("Chain.__setstate__: ") + e.what());
  } catch (py::type_error& e) {
    throw py::type_error(std::string("Chain.__setstate__: ") + e.what());
  }
}

/// Whether c has no model beyond its screws and home (see the state below).
bool is_plain(const PyChain& c) {
  const auto identity = [](const SE3d& g) {
    return g.rotation().matrix() == Eigen::Matrix3d::Identity() && g.translation() == Vector3::Zero();
  };
  if (!c.names.empty() || c.has_inertias || !identity(c.given_base) || !identity(c.given_tool) ||
      c.gravity() != ChainD::default_gravity())
    return false;
  for (Eigen::Index i = 0; i < c.n_joints(); ++i) {
    const bool prismatic = !(c.space_screws().col(i).tail<3>().squaredNorm() > 0);
    if (c.joint_type(i) != (prismatic ? chasles::JointType::prismatic : chasles::JointType::revolute)) return false;
    if (!(c.lower()(i) == -INFINITY && c.upper()(i) == INFINITY && c.velocity_limits()(i) == INFINITY &&
          c.effort_limits()(i) == INFINITY))
      return false;
  }
  return true;
}

/// A tip wrench operand (..., 6): zero when None.
py::object tip_operand(py::handle tip, const char* what) {
  if (tip.is_none()) return vec_out<6>(Eigen::Matrix<double, 6, 1>::Zero());
  return ufunc_operand(tip, what);
}

// ---- inverse kinematics: the private ufunc _inverse_kinematics ----------------
//
// (n,6),(4,4),(n),(n),(),(),(),(4,4),(n),(),()->(n),(),(),(6): the chain
// (screws, home, lower and upper limits) and the solver's options
// (position and orientation tolerances, max_iterations, a C int) make the
// model; each element solves for a target from a seed q0 with `restarts`
// (int) further attempts drawn from a 64-bit Mersenne twister seeded with
// `seed` (uint64); the results are q, converged (bool), iterations (int)
// and the body error (6). float64 only: the chain is.

struct IKModel {
  ChainD chain;
  ChainD::JointVector lower, upper;
  chasles::IKOptions<double> options;
};

struct IKModelOf {
  template <typename S, typename M, typename Lo, typename Hi>
  IKModel operator()(const S& screws, const M& home, const Lo& lower, const Hi& upper, double position_tolerance,
                     double orientation_tolerance, int max_iterations) const noexcept {
    chasles::IKOptions<double> options;
    options.position_tolerance = position_tolerance;
    options.orientation_tolerance = orientation_tolerance;
    options.max_iterations = max_iterations;
    return {ChainOf()(screws, home), ChainD::JointVector(lower), ChainD::JointVector(upper), options};
  }
};

struct IKKernel {
  template <typename Target, typename Q0>
  std::tuple<ChainD::JointVector, bool, int, Eigen::Matrix<double, 6, 1>> operator()(const IKModel& m,
                                                                                      const Target& target,
                                                                                      const Q0& q0, int restarts,
                                                                                      npy_uint64 seed) const noexcept {
    const SE3d T = SE3d::from_matrix_unchecked(Matrix4(target));
    const ChainD::JointVector q = q0;
    if (restarts > 0) {
      std::mt19937_64 gen(seed);
      const auto r = chasles::inverse_kinematics(m.chain, T, q, m.lower, m.upper, m.options, gen, restarts);
      return {r.q, r.converged, r.iterations, r.error};
    }
    const auto r = chasles::inverse_kinematics(m.chain, T, q, m.lower, m.upper, m.options);
    return {r.q, r.converged, r.iterations, r.error};
  }
};

py::object ik_ufunc(py::module_& m) {
  using ufunc::Core;
  using ufunc::Typed;
  using Int = Typed<Core<>, int>;
  using Signature = std::tuple<JointsCore, Typed<Core<>, bool>, Int, Core<6>>(
      ScrewsCore, Core<4, 4>, JointsCore, JointsCore, Core<>, Core<>, Int, Core<4, 4>, JointsCore, Int,
      Typed<Core<>, npy_uint64>);
  return ufunc::def_ufunc<Signature, ufunc::Float64>(
      m, "_inverse_kinematics",
      "screws, home, lower, upper, position_tolerance, orientation_tolerance, max_iterations, target, q0, restarts, "
      "seed",
      R"doc(A private ufunc of chasles.Chain (its method inverse_kinematics, which checks the arguments).

Operands (float64 unless said):
    screws: (n, 6), 1 <= n <= 32 (NaN results beyond), the space screws.
    home: (4, 4), the home pose.
    lower, upper: (n,), the joint limits.
    position_tolerance, orientation_tolerance: (), the tolerances on |e_v|, |e_w|.
    max_iterations: (), int32, iterations per attempt.
    target: (4, 4), a rigid motion (taken as given).
    q0: (n,), the seed.
    restarts: (), int32, further attempts from random seeds while not converged.
    seed: (), uint64, the seed of the Mersenne twister those are drawn from.

Returns:
    (q (n,), converged () bool, iterations () int32, error (6,)).)doc",
      ufunc::model<7>(IKModelOf()), IKKernel());
}

/// The dynamics model of a chain (see DynamicsModel): its operands from the
/// C++ chain (whose link inertias the base frame has moved into the world
/// frame), read-only, and the Dynamics built from them as the ufunc loop
/// builds its model.
std::shared_ptr<const DynamicsModel> dynamics_model(const ChainD& c) {
  const Py_intptr_t n = c.n_joints();
  const Py_intptr_t dims[3] = {n, 6, 6};
  py::array_t<double> G = new_array(3, dims);
  DynD::Inertias I{};
  for (Eigen::Index i = 0; i < n; ++i) {
    const auto k = static_cast<std::size_t>(i);
    Eigen::Map<Eigen::Matrix<double, 6, 6, Eigen::RowMajor>>(array_data(G) + 36 * i) = c.link_inertias()[k].matrix();
    I[k] = InertiaD::from_matrix_unchecked(c.link_inertias()[k].matrix());
  }
  DynamicsModel d{screws_array(c), mat_out<4, 4>(c.home().matrix()), std::move(G), vec_out<3>(c.gravity()),
                  DynD(c.space_screws(), SE3d::from_matrix_unchecked(c.home().matrix()), DynD::HomeAsGiven(), I, c.gravity())};
  for (py::array* a : {&d.screws, &d.home, &d.inertias, &d.gravity})
    py::detail::array_proxy(a->ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return std::make_shared<const DynamicsModel>(std::move(d));
}

/// The chain's dynamics model; ValueError for a chain without link inertias.
const DynamicsModel& dynamics_of(const PyChain& c, const char* what) {
  if (!c.dynamics)
    raise_value_error(std::string(what) +
                      ": the chain has no link inertias (give Chain(..., link_inertias=...), or load it with "
                      "Chain.from_urdf)");
  return *c.dynamics;
}

/// Calls the dynamics ufunc u (bind_dynamics.cpp) with the chain's operands
/// (screws, home, inertias, and gravity when `with_gravity`), the J joint
/// arguments and, when `with_tip`, the tip wrench (None: zero). The last
/// axis of each joint argument is checked here, so that the message names
/// the method and n. One configuration of float64 (each joint argument a
/// native float64 array of shape (n,) or a list of n Python numbers, the
/// tip wrench None or one such of 6) skips numpy's dispatch, as
/// call_chain_ufunc does: `kernel(model, joints, tip)` computes it with the
/// Dynamics the loop would build from the same operands, the same bits
/// (tests/python/test_dynamics.py compares the two).
template <std::size_t J, typename Kernel>
py::object call_dynamics_ufunc(PyObject* u, const PyChain& c, const char* what, const std::array<py::handle, J>& joints,
                               const std::array<const char*, J>& names, bool with_gravity, const py::handle* tip,
                               Kernel kernel) {
  const DynamicsModel& d = dynamics_of(c, what);
  const py::ssize_t n = c.n_joints();
  std::array<DynD::JointVector, J> one;
  bool single = true;
  for (std::size_t j = 0; j < J && single; ++j) {
    one[j].resize(n);
    single = single_element(joints[j], one[j].data(), n);
  }
  chasles::Wrenchd tip_wrench;
  if (single && tip != nullptr && !tip->is_none()) {
    Eigen::Matrix<double, 6, 1> w;
    single = single_element(*tip, w.data(), 6);
    tip_wrench = chasles::Wrenchd(w);
  }
  if (single) {
    const auto result = kernel(d.model, one, tip_wrench);
    constexpr bool vector = decltype(result)::ColsAtCompileTime == 1;  // the torques (n,), or M(q) (n, n)
    const Py_intptr_t dims[2] = {result.rows(), result.cols()};
    py::array_t<double> out = new_array(vector ? 1 : 2, dims);
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(array_data(out), dims[0],
                                                                                        dims[1]) = result;
    return std::move(out);
  }
  std::array<py::object, J + 2> keep;  // the joint and tip operands, alive through the call
  std::array<PyObject*, 9> args{};
  std::size_t k = 0;
  args[k++] = d.screws.ptr();
  args[k++] = d.home.ptr();
  args[k++] = d.inertias.ptr();
  if (with_gravity) args[k++] = d.gravity.ptr();
  for (std::size_t j = 0; j < J; ++j) {
    keep[j] = joint_operand(joints[j], n, names[j]);
    args[k++] = keep[j].ptr();
  }
  if (tip != nullptr) {
    const std::string tip_what = std::string(what) + "(tip_wrench)";
    keep[J] = tip_operand(*tip, tip_what.c_str());
    args[k++] = keep[J].ptr();
  }
  PyObject* r = PyObject_Vectorcall(u, args.data(), k, nullptr);
  if (r == nullptr) {
    py::error_already_set e;
    raise_conversion_error(e, what);
  }
  return py::reinterpret_steal<py::object>(r);
}


/// Chain.forward_dynamics(on_failure): true for "raise" (the default), false
/// for "nan".
bool failure_raises(py::handle on_failure) {
  if (PyUnicode_Check(on_failure.ptr())) {
    if (PyUnicode_CompareWithASCIIString(on_failure.ptr(), "raise") == 0) return true;
    if (PyUnicode_CompareWithASCIIString(on_failure.ptr(), "nan") == 0) return false;
  }
  raise_value_error("Chain.forward_dynamics(on_failure): expected \"raise\" or \"nan\", got " +
                    std::string(py::repr(on_failure)));
}

/// The ValueError of Chain.forward_dynamics where M(q) is not positive
/// definite: at `where` (empty for one configuration), the Cholesky
/// factorization failing at `joint`.
[[noreturn]] void raise_not_positive_definite(const std::string& where, Eigen::Index joint) {
  raise_value_error("Chain.forward_dynamics: the mass matrix M(q) is not positive definite" + where +
                    ": its Cholesky factorization fails at joint " + std::to_string(joint) +
                    " (a link without mass, or without rotational inertia about its joint's axis, or an inertia "
                    "that no rigid body has?)");
}

/// A batch of forward dynamics: the ufunc's (qdd, joint); ValueError naming
/// the first configuration (C order) whose joint is not -1 when `raise`,
/// else qdd with NaN there.
py::object checked_accelerations(const py::object& result, bool raise) {
  const py::tuple r = py::reinterpret_borrow<py::tuple>(result);
  if (!raise) return r[0];
  const auto joint = py::array_t<int, py::array::c_style | py::array::forcecast>::ensure(r[1]);
  const int* at = joint.data();
  const py::ssize_t size = joint.size();
  py::ssize_t first = -1, failed = 0;
  for (py::ssize_t i = 0; i < size; ++i) {
    if (at[i] < 0) continue;
    if (failed++ == 0) first = i;
  }
  if (failed == 0) return r[0];
  if (joint.ndim() == 0) raise_not_positive_definite("", at[0]);
  std::string index;
  for (py::ssize_t d = joint.ndim(), rest = first; d-- > 0; rest /= joint.shape(d))
    index = std::to_string(rest % joint.shape(d)) + (index.empty() ? "" : ", ") + index;
  raise_not_positive_definite(" at batch index (" + index + (joint.ndim() == 1 ? ",)" : ")") + ", the first of " +
                                  std::to_string(failed) + " of " + std::to_string(size) +
                                  " configurations; on_failure=\"nan\" gives NaN there instead)",
                              at[first]);
}

/// The parts of Chain.inverse_kinematics' result (python/chasles/_results.py,
/// IKResult): one solve (q of shape (n,), a bool, an int, error (6,)) or a
/// batch (arrays with the batch shape).
struct IKSolution {
  py::object q, converged, iterations, error;
};

/// Chain.inverse_kinematics: the arguments checked here (with messages
/// naming the method), the solves by the ufunc u. Element i of a batch (in
/// C order) draws its restarts from a generator seeded with seed + i, so
/// that it equals the single solve with that seed, however numpy splits the
/// loop.
IKSolution solve_ik(PyObject* u, const PyChain& c, py::handle target, py::handle q0, double position_tolerance,
                    double orientation_tolerance, int max_iterations, int restarts, std::uint64_t seed) {
  const char* what = "Chain.inverse_kinematics";
  if (max_iterations < 0) raise_value_error(std::string(what) + "(max_iterations): expected >= 0, got " + std::to_string(max_iterations));
  if (restarts < 0) raise_value_error(std::string(what) + "(restarts): expected >= 0, got " + std::to_string(restarts));
  if (!(position_tolerance >= 0) || !(orientation_tolerance >= 0))
    raise_value_error(std::string(what) + ": expected tolerances >= 0, got " + short_float(position_tolerance) + " and " +
                      short_float(orientation_tolerance));
  const py::ssize_t n = c.n_joints();
  const py::array T = as_float64_array(target, "Chain.inverse_kinematics(target)");
  if (T.ndim() < 2 || T.shape(T.ndim() - 1) != 4 || T.shape(T.ndim() - 2) != 4)
    raise_value_error(std::string(what) + "(target): expected an SE3 or shape (4, 4) or (..., 4, 4), got " +
                      array_shape(T));
  const py::array Q = as_float64_array(q0, "Chain.inverse_kinematics(q0)");
  if (Q.ndim() < 1 || Q.shape(Q.ndim() - 1) != n)
    raise_value_error(std::string(what) + "(q0): expected shape (" + std::to_string(n) + ",) or (..., " +
                      std::to_string(n) + ") for a chain of " + std::to_string(n) + " joints, got " + array_shape(Q));
  const py::module_ np = py::module_::import("numpy");
  const py::tuple t_shape = py::tuple(T.attr("shape")), q_shape = py::tuple(Q.attr("shape"));
  py::tuple batch;
  try {
    batch = np.attr("broadcast_shapes")(t_shape[py::slice(0, T.ndim() - 2, 1)], q_shape[py::slice(0, Q.ndim() - 1, 1)]);
  } catch (py::error_already_set&) {
    raise_value_error(std::string(what) + ": the batch shapes of target " + array_shape(T) + " and q0 " + array_shape(Q) +
                      " do not broadcast together");
  }
  const py::array Tb = np.attr("ascontiguousarray")(np.attr("broadcast_to")(T, batch + py::make_tuple(4, 4)));
  const py::array Qb = np.attr("ascontiguousarray")(np.attr("broadcast_to")(Q, batch + py::make_tuple(n)));
  const py::ssize_t k = Tb.size() / 16;
  const double* tp = static_cast<const double*>(Tb.data());
  const double* qp = static_cast<const double*>(Qb.data());
  for (py::ssize_t i = 0; i < k; ++i) {
    const Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>> Ti(tp + 16 * i);
    if (!(SE3d::transform_defect(Ti) <= chasles::Thresholds<double>::rotation_tolerance))
      raise_value_error(std::string(what) + "(target): not a rigid motion (defect " +
                        short_float(SE3d::transform_defect(Ti)) + (k > 1 ? " at index " + std::to_string(i) : "") +
                        "); SE3.from_matrix_projected makes one");
  }
  if (!Eigen::Map<const Eigen::ArrayXd>(qp, k * n).isFinite().all())
    raise_value_error(std::string(what) + "(q0): expected finite numbers");
  py::array_t<npy_uint64> seeds(std::vector<py::ssize_t>{k});
  for (py::ssize_t i = 0; i < k; ++i) seeds.mutable_data()[i] = static_cast<npy_uint64>(seed + static_cast<std::uint64_t>(i));
  const py::object S = screws_array(c), M = mat_out<4, 4>(c.home().matrix()), lo = vector_out(c.lower()),
                   hi = vector_out(c.upper()), ptol = py::float_(position_tolerance),
                   otol = py::float_(orientation_tolerance), iters = np.attr("int32")(max_iterations),
                   starts = np.attr("int32")(restarts), seed_array = seeds.attr("reshape")(batch);
  const py::tuple r = call_ufunc<11>(u, what,
                                     {S.ptr(), M.ptr(), lo.ptr(), hi.ptr(), ptol.ptr(), otol.ptr(), iters.ptr(), Tb.ptr(),
                                      Qb.ptr(), starts.ptr(), seed_array.ptr()});
  const py::object q = r[0], converged = r[1], iterations = r[2], error = r[3];
  if (batch.empty()) return {q, py::bool_(converged), py::int_(iterations), error};
  return {q, converged, iterations, error};
}

}  // namespace

void bind_kinematics(py::module_& m) {
  const py::object u_forward = chain_ufunc<ChainOp::forward>(m, "_chain_forward", "forward");
  const py::object u_forward_body = chain_ufunc<ChainOp::forward_body>(m, "_chain_forward_body", "forward_body");
  const py::object u_jacobian_space =
      chain_ufunc<ChainOp::jacobian_space>(m, "_chain_jacobian_space", "jacobian_space");
  const py::object u_jacobian_body = chain_ufunc<ChainOp::jacobian_body>(m, "_chain_jacobian_body", "jacobian_body");
  const py::object u_ik = ik_ufunc(m);

  const std::string doc = class_doc();
  py::class_<PyChain> cls(m, "Chain", doc.c_str());
  cls.attr("__array_ufunc__") = py::none();  // numpy defers operators (np.float64(1.0) == c) to us

  cls.def(py::init([](ArrayLike screws, py::object home, py::object joint_types, py::object names, py::object lower,
                       py::object upper, py::object velocity_limits, py::object effort_limits, py::object base,
                       py::object tool, py::object gravity, py::object link_inertias) {
            return make_chain(screws.obj, home, joint_types, names, lower, upper, velocity_limits, effort_limits, base,
                              tool, gravity, link_inertias);
          }),
          py::arg("screws"), py::arg("home"), py::kw_only(), py::arg("joint_types") = py::none(),
          py::arg("names") = py::none(), py::arg("lower") = py::none(), py::arg("upper") = py::none(),
          py::arg("velocity_limits") = py::none(), py::arg("effort_limits") = py::none(),
          py::arg("base") = py::none(), py::arg("tool") = py::none(), py::arg("gravity") = py::none(),
          py::arg("link_inertias") = py::none(),
          R"doc(A serial chain from its space screws and its home pose, with its robot model.

The base and tool frames are folded in: the chain's ``screws`` are
Ad_base S_i and its ``home`` is base M tool (projected onto SE(3)), so that
forward kinematics and the Jacobians are in the world frame and end at the
tool; ``base`` and ``tool`` stay available.

Each screw is checked against its joint's type: a revolute or continuous
joint's angular part w must be a unit vector and its pitch w . v zero, a
prismatic joint's w zero and its linear part v a unit vector (to 1.5e-8).
A table in Modern Robotics' (w, v) order, or transposed (one column per
joint, as MR's Slist), is refused with the conversion in the message.

Args:
    screws: shape (n, 6), 1 <= n <= 32: row i is the space screw S_i = (v, w)
        of joint i at the home configuration, in the base frame, finite.
    home: SE3 or shape (4, 4), M = g(0), the tool frame at home (before
        ``tool``), in the base frame.
    joint_types: n of "revolute", "continuous", "prismatic"; None infers
        them (prismatic where w = 0, revolute elsewhere).
    names: n joint names (str), or None.
    lower: shape (n,), lower position limits (radians or metres); None: -inf.
    upper: shape (n,), upper position limits; None: inf. A continuous joint
        has -inf and inf.
    velocity_limits: shape (n,), >= 0; None: inf.
    effort_limits: shape (n,), >= 0 (N m or N); None: inf.
    base: SE3 or shape (4, 4), the base frame in the world frame; None: identity.
    tool: SE3 or shape (4, 4), the tool frame after M; None: identity.
    gravity: shape (3,), in the world frame, m/s^2; None: (0, 0, -9.81).
    link_inertias: shape (n, 10), per joint the inertia of the link it moves
        (mass, center of mass (3), ixx, ixy, ixz, iyy, iyz, izz about the
        center of mass), in the base frame at home (``Chain.from_urdf``
        fills it); or None.

Raises:
    ValueError: a shape other than (n, 6), more than 32 joints, a non-finite
        entry, a home, base or tool matrix that is not a rigid motion, a
        screw that does not match its joint type, lower > upper, a negative
        velocity or effort limit, a negative mass.
    TypeError: joint types or names that are not strings.

Example:
    >>> arm = Chain([[0, 0, 0, 0, 0, 1]], np.eye(4))
    >>> arm.n_joints
    1
    >>> arm = Chain([[0, 0, 0, 0, 0, 1]], np.eye(4), joint_types=["revolute"],
    ...             names=["shoulder"], lower=[-1.5], upper=[1.5])
    >>> arm
    Chain(n_joints=1, names=('shoulder',))
)doc");

  cls.def_static(
      "revolute_screw",
      [](ArrayLike point, ArrayLike direction) {
        const Vector3 q = to_finite_eigen<3>(point.obj, "Chain.revolute_screw(point)");
        const Vector3 w = nonzero_vector(direction.obj, "Chain.revolute_screw(direction)");
        return vec_out<6>(ChainD::revolute_screw(q, w));
      },
      py::arg("point"), py::arg("direction"),
      R"doc(The screw of a revolute joint about the axis through q along w: (-w x q, w).

The point comes first, as in ``SE3.from_screw(point, direction, ...)``.

Args:
    point: shape (3,), q, any point on the axis.
    direction: shape (3,), the joint axis, nonzero (normalized here: w = direction / |direction|).

Returns:
    numpy.ndarray: shape (6,), (v, w), linear part first.

Example:
    >>> Chain.revolute_screw([1, 0, 0], [0, 0, 2])
    array([ 0., -1.,  0.,  0.,  0.,  1.])
)doc");

  cls.def_static(
      "prismatic_screw",
      [](ArrayLike direction) {
        return vec_out<6>(ChainD::prismatic_screw(nonzero_vector(direction.obj, "Chain.prismatic_screw(direction)")));
      },
      py::arg("direction"),
      R"doc(The screw of a prismatic joint: (v, 0), v = direction / |direction|.

Args:
    direction: shape (3,), nonzero (normalized here).

Returns:
    numpy.ndarray: shape (6,), (v, 0).

Example:
    >>> Chain.prismatic_screw([0, 3, 4])
    array([0. , 0.6, 0.8, 0. , 0. , 0. ])
)doc");

  cls.def(
      "forward",
      [u_forward](Obj<PyChain> c, ArrayLike theta) {
        return call_chain_ufunc<ChainOp::forward>(u_forward.ptr(), *c, theta.obj, "Chain.forward(theta)");
      },
      py::arg("theta"),
      R"doc(Forward kinematics, space form: g(theta) = exp([S_1] th_1) ... exp([S_n] th_n) M.

An array function: theta of shape (n,) gives one result, (..., n) one per
configuration, by the same numpy rules as every chasles array function
(broadcasting, dtypes, the GIL released; a NaN gives NaN in its element).

Args:
    theta: array_like of shape (..., n), joint positions (radians or lengths).

Returns:
    numpy.ndarray: shape (..., 4, 4), the homogeneous matrices of the tool
    frame (``SE3.from_matrix_unchecked`` makes an SE3 of one).

Example:
    >>> arm = Chain([Chain.prismatic_screw([1, 0, 0])], np.eye(4))
    >>> arm.forward([0.5])[:3, 3]
    array([0.5, 0. , 0. ])
    >>> arm.forward([[0.5], [1.0]]).shape
    (2, 4, 4)
)doc");

  cls.def(
      "forward_body",
      [u_forward_body](Obj<PyChain> c, ArrayLike theta) {
        return call_chain_ufunc<ChainOp::forward_body>(u_forward_body.ptr(), *c, theta.obj, "Chain.forward_body(theta)");
      },
      py::arg("theta"),
      R"doc(Forward kinematics, body form: g(theta) = M exp([B_1] th_1) ... exp([B_n] th_n).

Equal to ``forward`` up to rounding.

An array function: theta of shape (n,) gives one result, (..., n) one per
configuration, by the same numpy rules as every chasles array function
(broadcasting, dtypes, the GIL released; a NaN gives NaN in its element).

Args:
    theta: array_like of shape (..., n).

Returns:
    numpy.ndarray: shape (..., 4, 4).

Example:
    >>> arm = Chain([Chain.revolute_screw([1, 0, 0], [0, 0, 1])], np.eye(4))
    >>> np.allclose(arm.forward_body([0.3]), arm.forward([0.3]), rtol=0, atol=1e-15)
    True
)doc");

  cls.def(
      "jacobian_space",
      [u_jacobian_space](Obj<PyChain> c, ArrayLike theta) {
        return call_chain_ufunc<ChainOp::jacobian_space>(u_jacobian_space.ptr(), *c, theta.obj, "Chain.jacobian_space(theta)");
      },
      py::arg("theta"),
      R"doc(The space Jacobian J_s: the spatial twist (g' g^-1)^vee = J_s theta'.

Column i is Ad_{exp([S_1] th_1) ... exp([S_{i-1}] th_{i-1})} S_i; rows (v, w).
J_s = Ad_g J_b.

An array function: theta of shape (n,) gives one result, (..., n) one per
configuration, by the same numpy rules as every chasles array function
(broadcasting, dtypes, the GIL released; a NaN gives NaN in its element).

Args:
    theta: array_like of shape (..., n).

Returns:
    numpy.ndarray: shape (..., 6, n).

Example:
    >>> arm = Chain([Chain.revolute_screw([0, 0, 0], [0, 0, 1])], np.eye(4))
    >>> arm.jacobian_space([0.3])[:, 0]
    array([0., 0., 0., 0., 0., 1.])
)doc");

  cls.def(
      "jacobian_body",
      [u_jacobian_body](Obj<PyChain> c, ArrayLike theta) {
        return call_chain_ufunc<ChainOp::jacobian_body>(u_jacobian_body.ptr(), *c, theta.obj, "Chain.jacobian_body(theta)");
      },
      py::arg("theta"),
      R"doc(The body Jacobian J_b: the body twist (g^-1 g')^vee = J_b theta'.

Column i is Ad_{(exp([B_{i+1}] th_{i+1}) ... exp([B_n] th_n))^-1} B_i; rows (v, w).

An array function: theta of shape (n,) gives one result, (..., n) one per
configuration, by the same numpy rules as every chasles array function
(broadcasting, dtypes, the GIL released; a NaN gives NaN in its element).

Args:
    theta: array_like of shape (..., n).

Returns:
    numpy.ndarray: shape (..., 6, n).

Example:
    >>> arm = Chain([Chain.revolute_screw([0, 0, 0], [0, 0, 1])], SE3(translation=[1.0, 0.0, 0.0]))
    >>> np.round(arm.jacobian_body([0.3])[:, 0], 12) + 0.0
    array([0., 1., 0., 0., 0., 1.])
)doc");

  // ---- inverse kinematics (chasles/inverse_kinematics.hpp)
  cls.def(
      "inverse_kinematics",
      [u_ik](Obj<PyChain> c, py::object target, py::object q0, double position_tolerance, double orientation_tolerance,
         int max_iterations, int restarts, std::uint64_t seed) {
        const IKSolution r = solve_ik(u_ik.ptr(), *c, target, q0, position_tolerance, orientation_tolerance,
                                      max_iterations, restarts, seed);
        return py::module_::import("chasles._results").attr("IKResult")(r.q, r.converged, r.iterations, r.error);
      },
      py::arg("target"), py::arg("q0"), py::kw_only(),
      py::arg("position_tolerance") = chasles::Thresholds<double>::ik_tolerance,
      py::arg("orientation_tolerance") = chasles::Thresholds<double>::ik_tolerance,
      py::arg("max_iterations") = chasles::Thresholds<double>::ik_max_iterations, py::arg("restarts") = 0,
      py::arg("seed") = 0,
      R"doc(Inverse kinematics: joint positions q with forward(q) = target, within the joint limits.

Levenberg-Marquardt on the body error e(q) = log(forward(q)^-1 target)
(twist (v, w) in the tool frame) with its exact Jacobian
-J_l(e)^-1 J_b(q), each step projected onto [lower, upper], at most
max_iterations iterations; then, while not converged, up to ``restarts``
more attempts from seeds uniform within the limits ([-pi, pi] where a
limit is infinite), drawn from a generator seeded with ``seed``. The C++
solver (chasles/inverse_kinematics.hpp) runs with the GIL released, as the
private gufunc ``chasles._core._inverse_kinematics``.

Targets and seeds broadcast: one target (an SE3 or (4, 4)) and q0 (n,) give
one solve; (..., 4, 4) targets and/or (..., n) seeds give a batch. Element
i of a batch (in C order) draws its restarts from a generator seeded with
``seed + i``: it equals the single solve with that seed.

Args:
    target: SE3 or array_like of shape (4, 4) or (..., 4, 4), the tool pose(s).
    q0: array_like of shape (n,) or (..., n), the seed(s) (clamped into the limits).
    position_tolerance: |e_v| at a solution (the chain's length unit); default 3.7e-11.
    orientation_tolerance: |e_w| at a solution (radians); default 3.7e-11.
    max_iterations: iterations per attempt (>= 0).
    restarts: further attempts from random seeds while not converged (>= 0).
    seed: the seed of those random seeds (a 64-bit Mersenne twister; seed + i
        for element i of a batch).

Returns:
    IKResult: a named tuple (q, converged, iterations, error): q of shape
    (n,), a bool, an int, the body error twist e of shape (6,); for a batch,
    arrays of shapes (..., n), (...), (...), (..., 6).

Raises:
    ValueError: a target that is not a rigid motion, shapes that do not
        match or broadcast, a non-finite seed, negative counts or tolerances.

Example:
    >>> arm = Chain([Chain.revolute_screw([0, 0, 0], [0, 0, 1]),
    ...              Chain.revolute_screw([1, 0, 0], [0, 0, 1])], SE3(SO3(), [2, 0, 0]))
    >>> r = arm.inverse_kinematics(arm.forward([0.3, -0.5]), [0.0, -0.2])
    >>> r.converged, np.round(r.q, 12) + 0.0
    (True, array([ 0.3, -0.5]))
)doc");

  // ---- dynamics (chasles/dynamics.hpp, through the ufuncs of bind_dynamics.cpp)
  const py::object u_inverse_dynamics = m.attr("_inverse_dynamics"), u_forward_dynamics = m.attr("_forward_dynamics"),
                   u_mass_matrix = m.attr("_mass_matrix"), u_gravity_torques = m.attr("_gravity_torques"),
                   u_coriolis = m.attr("_coriolis");
  cls.def(
      "inverse_dynamics",
      [u_inverse_dynamics](Obj<PyChain> c, py::object q, py::object qd, py::object qdd, py::object tip_wrench) {
        return call_dynamics_ufunc<3>(
            u_inverse_dynamics.ptr(), *c, "Chain.inverse_dynamics", {q, qd, qdd},
            {"Chain.inverse_dynamics(q)", "Chain.inverse_dynamics(qd)", "Chain.inverse_dynamics(qdd)"}, true,
            &tip_wrench, [](const DynD& d, const std::array<DynD::JointVector, 3>& x, const chasles::Wrenchd& tip) {
              return chasles::inverse_dynamics(d, x[0], x[1], x[2], tip);
            });
      },
      py::arg("q"), py::arg("qd"), py::arg("qdd"), py::kw_only(), py::arg("tip_wrench") = py::none(),
      R"doc(Inverse dynamics: the joint torques (forces) tau that give the accelerations qdd.

tau = M(q) qdd + C(q, qd) qd + g(q) + J_b(q)^T F_tip, by the recursive
Newton-Euler algorithm in screw form (chasles/dynamics.hpp), with the
chain's link inertias and gravity. An array function: (..., n) in, (..., n)
out, the GIL released.

Args:
    q, qd, qdd: array_like of shape (..., n): joint positions, velocities, accelerations.
    tip_wrench: array_like of shape (..., 6) or a Wrench: the wrench (f, tau)
        the tool applies to the environment, in the tool frame (Modern
        Robotics' F_tip); None: zero.

Returns:
    numpy.ndarray: shape (..., n), N m for revolute joints and N for prismatic ones.

Raises:
    ValueError: a chain without link inertias, shapes that do not match.
)doc");
  cls.def(
      "forward_dynamics",
      [u_forward_dynamics](Obj<PyChain> c, py::object q, py::object qd, py::object tau, py::object tip_wrench,
                           py::object on_failure) {
        const bool raise = failure_raises(on_failure);
        py::object r = call_dynamics_ufunc<3>(
            u_forward_dynamics.ptr(), *c, "Chain.forward_dynamics", {q, qd, tau},
            {"Chain.forward_dynamics(q)", "Chain.forward_dynamics(qd)", "Chain.forward_dynamics(tau)"}, true,
            &tip_wrench,
            [raise](const DynD& d, const std::array<DynD::JointVector, 3>& x, const chasles::Wrenchd& tip) {
              const auto one = chasles::forward_dynamics(d, x[0], x[1], x[2], tip);
              if (!one && raise) raise_not_positive_definite("", one.joint);
              return one.qdd;
            });
        if (py::isinstance<py::tuple>(r)) return checked_accelerations(r, raise);  // the ufunc's (qdd, joint)
        return r;
      },
      py::arg("q"), py::arg("qd"), py::arg("tau"), py::kw_only(), py::arg("tip_wrench") = py::none(),
      py::arg("on_failure") = "raise",
      R"doc(Forward dynamics: the joint accelerations qdd = M(q)^-1 (tau - C(q, qd) qd - g(q) - J_b^T F_tip).

By a Cholesky factorization of the mass matrix (chasles/dynamics.hpp). An
array function: (..., n) in, (..., n) out, the GIL released.

Where M(q) is not positive definite, there are no accelerations to give: a
pivot of the factorization is not above the rounding of the terms it is
made of (4 eps of their scale: chasles::DynamicsStatus). A link without
mass, or without rotational inertia about its joint's axis (a point mass on
the axis), or an inertia that no rigid body has (which Chain.from_urdf
accepts, as real robot descriptions have some) can do that. By default this
raises ValueError, naming the joint where the factorization fails and, for
a batch, the index of the first such configuration, so that no simulation
goes on with meaningless accelerations. on_failure="nan" instead gives NaN
in those configurations' accelerations only, and the others as always (a
NaN input also gives NaN: ``np.isnan(qdd).any(axis=-1)`` flags both).

Args:
    q, qd, tau: array_like of shape (..., n): positions, velocities, joint torques.
    tip_wrench: as in inverse_dynamics; None: zero.
    on_failure: "raise" (the default) or "nan": what a configuration whose
        M(q) is not positive definite gives.

Returns:
    numpy.ndarray: shape (..., n).

Raises:
    ValueError: a chain without link inertias, shapes that do not match,
        an on_failure other than "raise" or "nan", or (unless
        on_failure="nan") M(q) not positive definite.
)doc");
  cls.def(
      "mass_matrix",
      [u_mass_matrix](Obj<PyChain> c, py::object q) {
        return call_dynamics_ufunc<1>(u_mass_matrix.ptr(), *c, "Chain.mass_matrix", {q}, {"Chain.mass_matrix(q)"}, false,
                                      nullptr, [](const DynD& d, const std::array<DynD::JointVector, 1>& x,
                                                  const chasles::Wrenchd&) { return chasles::mass_matrix(d, x[0]); });
      },
      py::arg("q"),
      R"doc(The joint-space mass matrix M(q), symmetric positive definite (composite rigid bodies).

Args:
    q: array_like of shape (..., n).

Returns:
    numpy.ndarray: shape (..., n, n).
)doc");
  cls.def(
      "gravity_torques",
      [u_gravity_torques](Obj<PyChain> c, py::object q) {
        return call_dynamics_ufunc<1>(u_gravity_torques.ptr(), *c, "Chain.gravity_torques", {q},
                                      {"Chain.gravity_torques(q)"}, true, nullptr,
                                      [](const DynD& d, const std::array<DynD::JointVector, 1>& x,
                                         const chasles::Wrenchd&) { return chasles::gravity_torques(d, x[0]); });
      },
      py::arg("q"),
      R"doc(The torques g(q) that hold the chain still against gravity: inverse_dynamics(q, 0, 0).

Args:
    q: array_like of shape (..., n).

Returns:
    numpy.ndarray: shape (..., n).
)doc");
  cls.def(
      "coriolis",
      [u_coriolis](Obj<PyChain> c, py::object q, py::object qd) {
        return call_dynamics_ufunc<2>(u_coriolis.ptr(), *c, "Chain.coriolis", {q, qd},
                                      {"Chain.coriolis(q)", "Chain.coriolis(qd)"}, false, nullptr,
                                      [](const DynD& d, const std::array<DynD::JointVector, 2>& x,
                                         const chasles::Wrenchd&) { return chasles::coriolis(d, x[0], x[1]); });
      },
      py::arg("q"), py::arg("qd"),
      R"doc(The Coriolis and centrifugal torques C(q, qd) qd (no gravity).

Args:
    q, qd: array_like of shape (..., n).

Returns:
    numpy.ndarray: shape (..., n).
)doc");

  cls.def_property_readonly(
      "screws",
      [](Obj<PyChain> c_) {
        const ChainD& c = *c_;
        const Py_intptr_t dims[2] = {c.n_joints(), 6};
        py::array_t<double> out = new_array(2, dims);
        Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>>(array_data(out), c.n_joints(), 6) =
            c.space_screws().transpose();
        return out;
      },
      R"doc(numpy.ndarray: shape (n, 6), the space screws S_i, one row (v, w) per joint (a copy).)doc");
  cls.def_property_readonly(
      "body_screws",
      [](Obj<PyChain> c_) {
        const ChainD& c = *c_;
        const Py_intptr_t dims[2] = {c.n_joints(), 6};
        py::array_t<double> out = new_array(2, dims);
        Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>>(array_data(out), c.n_joints(), 6) =
            c.body_screws().transpose();
        return out;
      },
      R"doc(numpy.ndarray: shape (n, 6), the body screws B_i = Ad_{M^-1} S_i (a copy).)doc");
  cls.def_property_readonly(
      "home", [](Obj<PyChain> c) { return c->home(); }, R"doc(SE3: the home pose M = g(0).)doc");
  cls.def_property_readonly(
      "n_joints", [](Obj<PyChain> c) { return static_cast<int>(c->n_joints()); }, R"doc(int: n, the number of joints.)doc");
  cls.def_property_readonly(
      "joint_types",
      [](Obj<PyChain> c) {
        py::tuple t(c->n_joints());
        for (Eigen::Index i = 0; i < c->n_joints(); ++i)
          t[static_cast<size_t>(i)] = py::str(kJointTypeNames[static_cast<int>(c->joint_type(i))]);
        return t;
      },
      R"doc(tuple[str, ...]: each joint's type: "revolute", "continuous" or "prismatic".)doc");
  cls.def_property_readonly(
      "names",
      [](Obj<PyChain> c) -> py::object {
        if (c->names.empty()) return py::none();
        py::tuple t(c->names.size());
        for (size_t i = 0; i < c->names.size(); ++i) t[i] = py::str(c->names[i]);
        return std::move(t);
      },
      R"doc(tuple[str, ...] | None: the joint names, or None when none were given.)doc");
  cls.def_property_readonly(
      "lower", [](Obj<PyChain> c) { return vector_out(c->lower()); },
      R"doc(numpy.ndarray: shape (n,), the lower position limits (-inf where none; a copy).)doc");
  cls.def_property_readonly(
      "upper", [](Obj<PyChain> c) { return vector_out(c->upper()); },
      R"doc(numpy.ndarray: shape (n,), the upper position limits (inf where none; a copy).)doc");
  cls.def_property_readonly(
      "velocity_limits", [](Obj<PyChain> c) { return vector_out(c->velocity_limits()); },
      R"doc(numpy.ndarray: shape (n,), the velocity limits (inf where none; a copy).)doc");
  cls.def_property_readonly(
      "effort_limits", [](Obj<PyChain> c) { return vector_out(c->effort_limits()); },
      R"doc(numpy.ndarray: shape (n,), the effort limits, N m or N (inf where none; a copy).)doc");
  cls.def_property_readonly(
      "base", [](Obj<PyChain> c) { return c->base(); },
      R"doc(SE3: the base frame in the world frame (already folded into screws and home).)doc");
  cls.def_property_readonly(
      "tool", [](Obj<PyChain> c) { return c->tool(); },
      R"doc(SE3: the tool frame after the last link (already folded into home).)doc");
  cls.def_property_readonly(
      "gravity", [](Obj<PyChain> c) { return vec_out<3>(c->gravity()); },
      R"doc(numpy.ndarray: shape (3,), gravity in the world frame, m/s^2 (a copy).)doc");
  cls.def_property_readonly(
      "link_inertias",
      [](Obj<PyChain> c) -> py::object {
        if (!c->has_inertias) return py::none();
        const Py_intptr_t dims[2] = {c->n_joints(), 10};
        py::array_t<double> out = new_array(2, dims);
        Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 10, Eigen::RowMajor>>(array_data(out), c->n_joints(), 10) =
            c->inertias;
        return std::move(out);
      },
      R"doc(numpy.ndarray | None: shape (n, 10), per joint the inertia of the link it moves
(with the links that ride on it): mass, center of mass (3), then ixx, ixy, ixz,
iyy, iyz, izz of the rotational inertia about the center of mass, both in
the base frame at home; None when not given (a copy).)doc");

  cls.def_static(
      "from_urdf",
      [](py::object source, py::object tip_link, py::object base_link) -> Returns<PyChain> {
        return {py::module_::import("chasles._urdf").attr("chain_from_urdf")(source, tip_link, base_link)};
      },
      py::arg("source"), py::arg("tip_link"), py::arg("base_link") = py::none(),
      R"doc(The chain from base_link to tip_link of a URDF robot description.

Revolute, continuous and prismatic joints become the chain's joints (their
names, types, limits); fixed joints are folded into the next joint's screw
or into the home pose; each moving joint's child link's ``<inertial>``,
with those of the links that ride on it, goes to ``link_inertias``: links
after it up to the next moving joint, and links hanging off the chain (side
branches, and the links below tip_link), fixed joints as they are and
moving joints off the chain at zero, as Pinocchio's buildReducedModel at
the neutral configuration. The home pose is
tip_link's frame at zero joint positions. Parsed with the standard
library's xml.etree (chasles/_urdf.py): URDF's kinematic and inertial
elements only, no meshes.

The source is XML text when, after an optional byte-order mark and
whitespace, it starts with '<'; otherwise it is a path, which must name a
regular file of at most 64 MiB (read with that bound; UTF-8). Elements may
nest at most 64 deep (checked before the parser sees the text). A
refusal names the joint, link or path, in the words the C++ loader
chain_from_urdf uses too. Physically impossible inertias (not positive
semidefinite, or violating the triangle inequality) are not refused:
48 of the 1,985 link inertias of example-robot-data are such (tiago's
antennas, anymal's hatch, icub's legs), and those robots load; their
mass matrix may then not be positive definite (the C++
SpatialInertia::is_physical() tells which inertias are physical).

Args:
    source: a path (str, bytes or os.PathLike) to a .urdf file, or the XML
        text (str, or UTF-8 bytes).
    tip_link: the name of the last link (the tool).
    base_link: the name of the base link; None: the root of the tree.

Returns:
    Chain.

Raises:
    ValueError: a malformed description; a floating or planar joint, or a
        mimic joint, between base and tip; a joint naming a missing link; a
        loop; duplicate link or joint names; an unknown tip or base link, or
        a tip not below the base; a number that is not finite in the file or
        overflows when combined (poses composed along the chain, masses
        summed); a negative mass, lower > upper, a negative velocity or
        effort limit, a zero axis; a path that is not a regular file, a file
        or text larger than 64 MiB, elements nested more than 64 deep.

Example:
    >>> urdf = """<robot name="r"><link name="a"/><link name="b"/>
    ...   <joint name="j" type="revolute"><parent link="a"/><child link="b"/>
    ...     <origin xyz="0 0 0.5"/><axis xyz="0 0 1"/>
    ...     <limit lower="-1" upper="1" effort="10" velocity="2"/></joint></robot>"""
    >>> arm = Chain.from_urdf(urdf, "b")
    >>> arm.names, arm.joint_types, arm.upper
    (('j',), ('revolute',), array([1.]))
)doc");

  // The stored numbers: the space screws, the home pose and the model (the
  // body screws are computed from them).
  def_equality(cls, [](const PyChain& a, const PyChain& b) {
    const auto same_pose = [](const SE3d& x, const SE3d& y) {
      return x.rotation().matrix() == y.rotation().matrix() && x.translation() == y.translation();
    };
    if (a.n_joints() != b.n_joints()) return false;
    for (Eigen::Index i = 0; i < a.n_joints(); ++i)
      if (a.joint_type(i) != b.joint_type(i)) return false;
    return a.space_screws() == b.space_screws() && same_pose(a.home(), b.home()) && a.lower() == b.lower() &&
           a.upper() == b.upper() && a.velocity_limits() == b.velocity_limits() &&
           a.effort_limits() == b.effort_limits() && same_pose(a.base(), b.base()) && same_pose(a.tool(), b.tool()) &&
           a.gravity() == b.gravity() && a.names == b.names && a.has_inertias == b.has_inertias &&
           (!a.has_inertias || a.inertias == b.inertias);
  });
  def_repr(cls, [](const PyChain& c) {
    std::string r = "Chain(n_joints=" + std::to_string(c.n_joints());
    if (!c.names.empty()) {
      r += ", names=(";
      for (size_t i = 0; i < c.names.size(); ++i)
        r += (i ? ", " : "") + std::string(py::str(py::repr(py::str(c.names[i]))));
      r += c.names.size() == 1 ? ",)" : ")";
    }
    return r + ")";
  });
  cls.def("__copy__", [](Obj<PyChain> c) { return *c; });
  cls.def("__deepcopy__", [](Obj<PyChain> c, const py::object&) { return *c; }, py::arg("memo"));
  // The state of a chain without a model (the types inferred, no limits,
  // names or inertias, identity base and tool, default gravity): its stored
  // numbers, 6 n + 12 floats, the space screws row by row, then the home
  // pose's rotation row by row and translation; rebuilt with the home taken
  // as it is (already projected), so bit for bit. The state of any other
  // chain: (numbers, names, inertias). numbers: the screws as given row by
  // row (6 n floats), the home pose as given (rotation row by row, then
  // translation: 12), the joint types (n: 0 revolute, 1 continuous, 2
  // prismatic), lower, upper, velocity and effort limits (4 n), base and
  // tool as given (12 each, as home), gravity (3): 11 n + 39 floats. names:
  // None or a tuple of n str. inertias: None or a tuple of 10 n floats. The
  // chain is rebuilt from them by the same arithmetic, so bit for bit, and
  // checked as the constructor checks its arguments (both states: a pickle
  // is data from outside), its error prefixed with "Chain.__setstate__: ".
  cls.def(py::pickle(
      [](Obj<PyChain> c_) -> py::tuple {
        const PyChain& c = *c_;
        const py::ssize_t n = c.n_joints();
        if (is_plain(c)) {
          py::tuple t(6 * n + 12);
          for (py::ssize_t i = 0; i < n; ++i)
            for (int k = 0; k < 6; ++k) t[static_cast<size_t>(6 * i + k)] = py::float_(c.space_screws()(k, i));
          const Eigen::Matrix3d& R = c.home().rotation().matrix();
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) t[static_cast<size_t>(6 * n + 3 * i + j)] = py::float_(R(i, j));
          for (int i = 0; i < 3; ++i) t[static_cast<size_t>(6 * n + 9 + i)] = py::float_(c.home().translation()[i]);
          return t;
        }
        py::tuple t(11 * n + 39);
        size_t k = 0;
        const auto put = [&](double x) { t[k++] = py::float_(x); };
        const auto put_pose = [&](const SE3d& g) {
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) put(g.rotation().matrix()(i, j));
          for (int i = 0; i < 3; ++i) put(g.translation()[i]);
        };
        for (py::ssize_t i = 0; i < n; ++i)
          for (int r = 0; r < 6; ++r) put(c.given_screws(r, i));
        put_pose(c.given_home);
        for (py::ssize_t i = 0; i < n; ++i) put(double(static_cast<int>(c.joint_type(i))));
        for (const ChainD::JointVector* v : {&c.lower(), &c.upper(), &c.velocity_limits(), &c.effort_limits()})
          for (py::ssize_t i = 0; i < n; ++i) put((*v)(i));
        put_pose(c.given_base);
        put_pose(c.given_tool);
        for (int i = 0; i < 3; ++i) put(c.gravity()[i]);
        py::object names = py::none(), inertias = py::none();
        if (!c.names.empty()) {
          py::tuple nt(c.names.size());
          for (size_t i = 0; i < c.names.size(); ++i) nt[i] = py::str(c.names[i]);
          names = std::move(nt);
        }
        if (c.has_inertias) {
          py::tuple it(static_cast<size_t>(10 * n));
          for (py::ssize_t i = 0; i < n; ++i)
            for (int j = 0; j < 10; ++j) it[static_cast<size_t>(10 * i + j)] = py::float_(c.inertias(i, j));
          inertias = std::move(it);
        }
        return py::make_tuple(t, names, inertias);
      },
      [](const py::object& state) {
        const auto bad = []() {
          raise_value_error("Chain.__setstate__: expected a tuple of 6 n + 12 floats, 1 <= n <= " +
                            std::to_string(kMaxJoints) +
                            ", or (numbers, names, inertias): a tuple of 11 n + 39 floats, None or n str, None or "
                            "10 n floats");
        };
        const bool model = PyTuple_Check(state.ptr()) && PyTuple_GET_SIZE(state.ptr()) == 3 &&
                           PyTuple_Check(PyTuple_GET_ITEM(state.ptr(), 0));
        if (!model) {
          const py::ssize_t size = PyTuple_Check(state.ptr()) ? PyTuple_GET_SIZE(state.ptr()) : -1;
          const py::ssize_t n = (size - 12) / 6;
          if (size < 0 || (size - 12) % 6 != 0 || n < 1 || n > kMaxJoints) bad();
          const py::tuple t = py::reinterpret_borrow<py::tuple>(state);
          ChainD::Screws S(6, n);
          for (py::ssize_t i = 0; i < n; ++i) read_state(t, 6 * i, 6, S.col(i).data(), "Chain");
          Eigen::Matrix<double, 3, 3, Eigen::RowMajor> R;
          Vector3 p;
          read_state(t, 6 * n, 9, R.data(), "Chain");
          read_state(t, 6 * n + 9, 3, p.data(), "Chain");
          return setstate_checked([&] {
            // The constructor's checks; the home pose kept as it is (not projected).
            require_finite(S, "Chain(screws)");
            Matrix4 H = Matrix4::Identity();
            H.topLeftCorner<3, 3>() = R;
            H.topRightCorner<3, 1>() = p;
            home_pose(mat_out<4, 4>(H));  // raises the constructor's error for a home that is not a rigid motion
            const SE3d M(chasles::SO3d::from_matrix_unchecked(R), p);
            PyChain c(ChainD(S, M, ChainD::HomeAsGiven()), S, M, SE3d(), SE3d());
            if (const chasles::ChainCheck check = c.validate(); !check)
              raise_invalid(c, check, S, types_of(py::none(), S), true);
            return c;
          });
        }
        const py::tuple outer = py::reinterpret_borrow<py::tuple>(state);
        const py::object numbers = outer[0], names = outer[1], inertias = outer[2];
        const py::ssize_t size = PyTuple_Check(numbers.ptr()) ? PyTuple_GET_SIZE(numbers.ptr()) : -1;
        const py::ssize_t n = (size - 39) / 11;
        if (size < 0 || (size - 39) % 11 != 0 || n < 1 || n > kMaxJoints) bad();
        Eigen::Matrix<double, Eigen::Dynamic, 1> x(size);
        read_state(py::reinterpret_borrow<py::tuple>(numbers), 0, size, x.data(), "Chain");
        Eigen::Index k = 0;
        const Py_intptr_t sdims[2] = {n, 6};
        py::array_t<double> S = new_array(2, sdims);
        for (py::ssize_t i = 0; i < 6 * n; ++i) array_data(S)[i] = x(k++);
        const auto pose = [&]() {
          Eigen::Matrix4d M = Eigen::Matrix4d::Identity();
          for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) M(i, j) = x(k++);
          for (int i = 0; i < 3; ++i) M(i, 3) = x(k++);
          return mat_out<4, 4>(M);
        };
        const py::array home = pose();
        py::list types;
        for (py::ssize_t i = 0; i < n; ++i) {
          const double code = x(k++);
          if (!(code >= 0 && code <= 2 && code == std::floor(code))) bad();
          types.append(kJointTypeNames[static_cast<int>(code)]);
        }
        py::array lims[4];
        for (auto& l : lims) {
          ChainD::JointVector v(n);
          for (py::ssize_t i = 0; i < n; ++i) v(i) = x(k++);
          l = vector_out(v);
        }
        const py::array base = pose();
        const py::array tool = pose();
        const Vector3 g(x(k), x(k + 1), x(k + 2));
        py::object inertia_array = py::none();
        if (!inertias.is_none()) {
          if (!PyTuple_Check(inertias.ptr()) || PyTuple_GET_SIZE(inertias.ptr()) != 10 * n) bad();
          const Py_intptr_t dims[2] = {n, 10};
          py::array_t<double> a = new_array(2, dims);
          read_state(py::reinterpret_borrow<py::tuple>(inertias), 0, 10 * n, array_data(a), "Chain");
          inertia_array = std::move(a);
        }
        return setstate_checked([&] {
          return make_chain(S, home, types, names, lims[0], lims[1], lims[2], lims[3], base, tool, vec_out<3>(g),
                            inertia_array);
        });
      }));
  add_reduce(cls);
}

}  // namespace chasles_py
