// chasles._core: class Chain over chasles::Chain<double, Dynamic, 32>
// (include/chasles/kinematics.hpp): product-of-exponentials kinematics of a
// serial chain of up to 32 joints.
#include <chasles/kinematics.hpp>

#include <limits>
#include <optional>
#include <cstring>
#include <string>

#include "bindings.hpp"
#include "conventions.hpp"
#include "convert.hpp"
#include "numpy_capi.hpp"
#include "ufunc.hpp"

namespace chasles_py {

namespace {

constexpr int kMaxJoints = 32;
using ChainD = chasles::Chain<double, Eigen::Dynamic, kMaxJoints>;
using chasles::SE3d;
using Vector3 = Eigen::Vector3d;
using Matrix4 = Eigen::Matrix4d;

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
SE3d home_pose(py::handle h) {
  py::detail::make_caster<Obj<SE3d>> caster;
  if (caster.load(h, false)) return *static_cast<Obj<SE3d>&>(caster);
  const Matrix4 M = to_finite_eigen<4, 4>(h, "Chain(home)");
  const auto g = SE3d::from_matrix(M);
  if (!g) {
    raise_value_error("Chain(home): not a rigid motion (transform defect " +
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
    raise_value_error("Chain(screws): expected shape (n, 6) with n >= 1 (one row (v, w) per joint), got " +
                      array_shape(a));
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
// the joint positions. Chain's methods call them with the chain's own
// screws and home pose, so numpy does the broadcasting, dtypes, out= and
// GIL, as for every array function; the chain is built once per loop when
// it stays put (the screws' and home's outer strides are 0).

enum class ChainOp { forward, forward_body, jacobian_space, jacobian_body };

/// What the method computes for one configuration: the 4x4 pose or the 6 x n
/// Jacobian (the loop and the one-configuration fast path both call this).
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
void chain_loop(char** args, const npy_intp* dims, const npy_intp* steps, void* /*data*/) noexcept {
  const npy_intp count = dims[0], n = dims[1];  // numpy: the outer size, then the core sizes (n, 6, 4)
  const npy_intp* core = steps + 4;             // S (n, 6), M (4, 4), theta (n), result (4, 4) or (6, n)
  const auto at = [](const char* p, npy_intp i, npy_intp si, npy_intp j, npy_intp sj) {
    return *reinterpret_cast<const double*>(p + i * si + j * sj);
  };
  const auto chain_at = [&](const char* S, const char* M) {
    ChainD::Screws screws(6, n);
    for (npy_intp i = 0; i < n; ++i)
      for (npy_intp k = 0; k < 6; ++k) screws(k, i) = at(S, i, core[0], k, core[1]);
    Matrix4 home;
    for (int i = 0; i < 4; ++i)
      for (int j = 0; j < 4; ++j) home(i, j) = at(M, i, core[2], j, core[3]);
    return ChainD(screws, SE3d::from_matrix_unchecked(home));
  };
  const auto write = [&](char* out, int r, npy_intp c, double x) {
    *reinterpret_cast<double*>(out + r * core[5] + c * core[6]) = x;
  };
  constexpr bool pose = Op == ChainOp::forward || Op == ChainOp::forward_body;
  const int rows = pose ? 4 : 6;
  const npy_intp cols = pose ? 4 : n;
  if (n < 1 || n > kMaxJoints) {  // only Chain calls these, with 1 <= n <= 32; never read past a chain
    for (npy_intp e = 0; e < count; ++e)
      for (int r = 0; r < rows; ++r)
        for (npy_intp c = 0; c < cols; ++c) write(args[3] + e * steps[3], r, c, std::numeric_limits<double>::quiet_NaN());
    return;
  }
  const bool fixed = steps[0] == 0 && steps[1] == 0;  // one chain for the whole loop: built once
  std::optional<ChainD> chain;
  ChainD::JointVector theta(n);
  for (npy_intp e = 0; e < count; ++e) {
    if (!fixed || !chain) chain.emplace(chain_at(args[0] + e * steps[0], args[1] + e * steps[1]));
    for (npy_intp j = 0; j < n; ++j) theta(j) = at(args[2] + e * steps[2], j, core[4], 0, 0);
    const auto result = chain_result<Op>(*chain, theta);
    char* out = args[3] + e * steps[3];
    for (int r = 0; r < rows; ++r)
      for (npy_intp c = 0; c < cols; ++c) write(out, r, c, result(r, c));
  }
  ufunc::clear_floating_point_flags();
}

/// Registers chain_loop<Op> as the private ufunc `name` (float64 only: the
/// chain is).
template <ChainOp Op>
py::object chain_ufunc(py::module_& m, const char* name, const char* signature) {
  static PyUFuncGenericFunction funcs[] = {&chain_loop<Op>};
  static void* data[] = {nullptr};
  static char types[] = {NPY_DOUBLE, NPY_DOUBLE, NPY_DOUBLE, NPY_DOUBLE};
  PyObject* u = PyUFunc_FromFuncAndDataAndSignature(funcs, data, types, 1, 3, 1, PyUFunc_None, name,
                                                    "A private ufunc of chasles.Chain.", 0, signature);
  if (u == nullptr) throw py::error_already_set();
  py::object ufunc = py::reinterpret_steal<py::object>(u);
  m.attr(name) = ufunc;
  return ufunc;
}

/// The chain's space screws, shape (n, 6), and home pose, shape (4, 4), as
/// the ufuncs' first two operands.
py::array screws_array(const ChainD& c) {
  const Py_intptr_t dims[2] = {c.joints(), 6};
  py::array_t<double> out = new_array(2, dims);
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>>(array_data(out), c.joints(), 6) =
      c.space_screws().transpose();
  return std::move(out);
}

/// Calls the chain ufunc u with the chain and theta: numpy's rules decide
/// dtypes and broadcasting. The last axis of theta is checked here, so that
/// the message names the method and n. One configuration of float64 (a
/// native float64 array of shape (n,), or a list of n Python numbers) skips
/// numpy's dispatch: the same chain_result, the same bits
/// (tests/python/test_ufuncs.py compares the two).
template <ChainOp Op>
py::object call_chain_ufunc(PyObject* u, const ChainD& c, py::handle theta, const char* what) {
  const py::ssize_t n = c.joints();
  if (ChainD::JointVector one(n); single_element(theta, one.data(), n)) {
    const auto result = chain_result<Op>(c, one);
    const Py_intptr_t dims[2] = {result.rows(), result.cols()};
    py::array_t<double> out = new_array(2, dims);
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>(array_data(out), dims[0],
                                                                                        dims[1]) = result;
    return std::move(out);
  }
  const py::object operand = ufunc_operand(theta, what);
  if (npy().PyArray_Check_(operand.ptr())) {
    const auto a = py::reinterpret_borrow<py::array>(operand);
    if (a.ndim() < 1 || a.shape(a.ndim() - 1) != n)
      raise_value_error(std::string(what) + ": expected shape (" + std::to_string(n) + ",) or (..., " +
                        std::to_string(n) + ") for a chain of " + std::to_string(n) + " joints, got " +
                        shape_string(a.shape(), static_cast<int>(a.ndim())));
  }
  const py::array S = screws_array(c);
  const py::array M = mat_out<4, 4>(c.home().matrix());
  return call_ufunc<3>(u, what, {S.ptr(), M.ptr(), operand.ptr()});
}

Vector3 nonzero_vector(py::handle h, const char* what) {
  const Vector3 v = to_finite_eigen<3>(h, what);
  if (!(v.squaredNorm() > 0)) raise_value_error(std::string(what) + ": expected a nonzero vector, got " + values_string(v));
  return v;
}

}  // namespace

void bind_kinematics(py::module_& m) {
  const py::object u_forward = chain_ufunc<ChainOp::forward>(m, "_chain_forward", "(n,6),(4,4),(n)->(4,4)");
  const py::object u_forward_body =
      chain_ufunc<ChainOp::forward_body>(m, "_chain_forward_body", "(n,6),(4,4),(n)->(4,4)");
  const py::object u_jacobian_space =
      chain_ufunc<ChainOp::jacobian_space>(m, "_chain_jacobian_space", "(n,6),(4,4),(n)->(6,n)");
  const py::object u_jacobian_body =
      chain_ufunc<ChainOp::jacobian_body>(m, "_chain_jacobian_body", "(n,6),(4,4),(n)->(6,n)");

  const std::string doc = class_doc();
  py::class_<ChainD> cls(m, "Chain", doc.c_str());
  cls.attr("__array_ufunc__") = py::none();  // numpy defers operators (np.float64(1.0) == c) to us

  cls.def(py::init([](ArrayLike screws, py::object home) { return ChainD(screws_of(screws.obj), home_pose(home)); }),
          py::arg("screws"), py::arg("home"),
          R"doc(A serial chain from its space screws and its home pose.

Args:
    screws: shape (n, 6), 1 <= n <= 32: row i is the space screw S_i = (v, w)
        of joint i at the home configuration, in the base frame, finite.
    home: SE3 or shape (4, 4), M = g(0), the tool frame at home.

Raises:
    ValueError: a shape other than (n, 6), more than 32 joints, a non-finite
        entry, or a home matrix that is not a rigid motion.

Example:
    >>> arm = Chain([[0, 0, 0, 0, 0, 1]], np.eye(4))
    >>> arm.n_joints
    1
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
      [u_forward](Obj<ChainD> c, ArrayLike theta) {
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
      [u_forward_body](Obj<ChainD> c, ArrayLike theta) {
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
      [u_jacobian_space](Obj<ChainD> c, ArrayLike theta) {
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
      [u_jacobian_body](Obj<ChainD> c, ArrayLike theta) {
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

  cls.def_property_readonly(
      "screws",
      [](Obj<ChainD> c_) {
        const ChainD& c = *c_;
        const Py_intptr_t dims[2] = {c.joints(), 6};
        py::array_t<double> out = new_array(2, dims);
        Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>>(array_data(out), c.joints(), 6) =
            c.space_screws().transpose();
        return out;
      },
      R"doc(numpy.ndarray: shape (n, 6), the space screws S_i, one row (v, w) per joint (a copy).)doc");
  cls.def_property_readonly(
      "body_screws",
      [](Obj<ChainD> c_) {
        const ChainD& c = *c_;
        const Py_intptr_t dims[2] = {c.joints(), 6};
        py::array_t<double> out = new_array(2, dims);
        Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>>(array_data(out), c.joints(), 6) =
            c.body_screws().transpose();
        return out;
      },
      R"doc(numpy.ndarray: shape (n, 6), the body screws B_i = Ad_{M^-1} S_i (a copy).)doc");
  cls.def_property_readonly(
      "home", [](Obj<ChainD> c) { return c->home(); }, R"doc(SE3: the home pose M = g(0).)doc");
  cls.def_property_readonly(
      "n_joints", [](Obj<ChainD> c) { return static_cast<int>(c->joints()); }, R"doc(int: n, the number of joints.)doc");
  // The stored numbers: the space screws and the home pose (the body screws
  // are computed from them).
  def_equality(cls, [](const ChainD& a, const ChainD& b) {
    return a.joints() == b.joints() && a.space_screws() == b.space_screws() &&
           a.home().rotation().matrix() == b.home().rotation().matrix() &&
           a.home().translation() == b.home().translation();
  });
  def_repr(cls, [](const ChainD& c) { return "Chain(n_joints=" + std::to_string(c.joints()) + ")"; });
  cls.def("__copy__", [](Obj<ChainD> c) { return *c; });
  cls.def("__deepcopy__", [](Obj<ChainD> c, const py::object&) { return *c; }, py::arg("memo"));
  // The state: the space screws row by row (6 n floats), then the home
  // pose's rotation row by row and translation (12 floats); the body screws
  // are recomputed from them, by the same arithmetic, so bit for bit.
  cls.def(py::pickle(
      [](Obj<ChainD> c_) {
        const ChainD& c = *c_;
        const py::ssize_t n = c.joints();
        py::tuple t(6 * n + 12);
        for (py::ssize_t i = 0; i < n; ++i)
          for (int k = 0; k < 6; ++k) t[6 * i + k] = py::float_(c.space_screws()(k, i));
        const Eigen::Matrix3d& R = c.home().rotation().matrix();
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) t[6 * n + 3 * i + j] = py::float_(R(i, j));
        for (int i = 0; i < 3; ++i) t[6 * n + 9 + i] = py::float_(c.home().translation()[i]);
        return t;
      },
      [](const py::object& state) {
        const py::ssize_t size = PyTuple_Check(state.ptr()) ? PyTuple_GET_SIZE(state.ptr()) : -1;
        const py::ssize_t n = (size - 12) / 6;
        if (size < 0 || (size - 12) % 6 != 0 || n < 1 || n > kMaxJoints) {
          raise_value_error("Chain.__setstate__: expected a tuple of 6 n + 12 floats, 1 <= n <= " +
                            std::to_string(kMaxJoints));
        }
        const py::tuple t = py::reinterpret_borrow<py::tuple>(state);
        ChainD::Screws S(6, n);
        for (py::ssize_t i = 0; i < n; ++i) read_state(t, 6 * i, 6, S.col(i).data(), "Chain");
        Eigen::Matrix<double, 3, 3, Eigen::RowMajor> R;
        Vector3 p;
        read_state(t, 6 * n, 9, R.data(), "Chain");
        read_state(t, 6 * n + 9, 3, p.data(), "Chain");
        return ChainD(S, SE3d(chasles::SO3d::from_matrix_unchecked(R), p));
      }));
  add_reduce(cls);
}

}  // namespace chasles_py
