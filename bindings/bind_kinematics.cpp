// chasles._core: class Chain over chasles::Chain<double, Dynamic, 32>
// (include/chasles/kinematics.hpp): product-of-exponentials kinematics of a
// serial chain of up to 32 joints.
#include <chasles/kinematics.hpp>

#include <string>

#include "bindings.hpp"
#include "conventions.hpp"
#include "convert.hpp"

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
(-w x q, w) (``Chain.revolute_screw``), prismatic joints along v the screw
(v, 0) (``Chain.prismatic_screw``). At most 32 joints.

Example:
    >>> screws = [Chain.revolute_screw([0, 0, 1], [0, 0, 0]),
    ...           Chain.revolute_screw([0, 0, 1], [1, 0, 0])]
    >>> arm = Chain(screws, SE3(translation=[2.0, 0.0, 0.0]))
    >>> np.round(arm.forward([np.pi / 2, 0.0]).translation, 12) + 0.0
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

/// Joint positions: shape (n,) (batch = false) or (N, n) (batch = true), finite.
struct Thetas {
  py::array a;
  bool batch;
  py::ssize_t count;
};

Thetas thetas_of(const ChainD& c, py::handle h, const char* what) {
  Thetas t{as_float64_array(h, what), false, 1};
  const py::ssize_t n = c.joints();
  const std::string expected = "(" + std::to_string(n) + ",) or (N, " + std::to_string(n) + ")";
  if (t.a.ndim() == 1 && t.a.shape(0) == n) return t;
  if (t.a.ndim() == 2 && t.a.shape(1) == n) {
    t.batch = true;
    t.count = t.a.shape(0);
    return t;
  }
  raise_value_error(std::string(what) + ": expected shape " + expected + " for a chain of " + std::to_string(n) +
                    " joints, got " + array_shape(t.a));
}

ChainD::JointVector theta_at(const Thetas& t, py::ssize_t row, py::ssize_t n, const char* what) {
  ChainD::JointVector th(n);
  const char* data = static_cast<const char*>(t.a.data());
  const py::ssize_t s0 = t.batch ? t.a.strides(0) : 0, s1 = t.a.strides(t.batch ? 1 : 0);
  for (py::ssize_t j = 0; j < n; ++j) th(j) = *reinterpret_cast<const double*>(data + row * s0 + j * s1);
  require_finite(th, what);
  return th;
}

/// forward / forward_body: an SE3 for (n,), an (N, 4, 4) array for (N, n).
template <typename F>
py::object poses(const ChainD& c, py::handle theta, const char* what, F f) {
  const Thetas t = thetas_of(c, theta, what);
  const py::ssize_t n = c.joints();
  if (!t.batch) return py::cast(f(theta_at(t, 0, n, what)));
  const Py_intptr_t dims[3] = {t.count, 4, 4};
  py::array_t<double> out = new_array(3, dims);
  double* o = array_data(out);
  for (py::ssize_t r = 0; r < t.count; ++r)
    Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(o + 16 * r) = f(theta_at(t, r, n, what)).matrix();
  return std::move(out);
}

/// jacobian_space / jacobian_body: (6, n) for (n,), (N, 6, n) for (N, n).
template <typename F>
py::array_t<double> jacobians(const ChainD& c, py::handle theta, const char* what, F f) {
  const Thetas t = thetas_of(c, theta, what);
  const py::ssize_t n = c.joints();
  const Py_intptr_t dims3[3] = {t.count, 6, n};
  py::array_t<double> out = t.batch ? new_array(3, dims3) : new_array(2, dims3 + 1);
  double* o = array_data(out);
  using RowMajor = Eigen::Matrix<double, 6, Eigen::Dynamic, Eigen::RowMajor>;
  for (py::ssize_t r = 0; r < t.count; ++r) Eigen::Map<RowMajor>(o + 6 * n * r, 6, n) = f(theta_at(t, r, n, what));
  return out;
}

Vector3 nonzero_vector(py::handle h, const char* what) {
  const Vector3 v = to_finite_eigen<3>(h, what);
  if (!(v.squaredNorm() > 0)) raise_value_error(std::string(what) + ": expected a nonzero vector, got " + values_string(v));
  return v;
}

}  // namespace

void bind_kinematics(py::module_& m) {
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
      [](ArrayLike axis, ArrayLike point) {
        return vec_out<6>(ChainD::revolute_screw(nonzero_vector(axis.obj, "Chain.revolute_screw(axis)"),
                                                 to_finite_eigen<3>(point.obj, "Chain.revolute_screw(point)")));
      },
      py::arg("axis"), py::arg("point"),
      R"doc(The screw of a revolute joint: (-w x q, w), w = axis / |axis|.

Args:
    axis: shape (3,), the joint axis, nonzero (normalized here).
    point: shape (3,), q, any point on the axis.

Returns:
    numpy.ndarray: shape (6,), (v, w), linear part first.

Example:
    >>> Chain.revolute_screw([0, 0, 2], [1, 0, 0])
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
      [](Obj<ChainD> c_, ArrayLike theta) {
        const ChainD& c = *c_;
        return poses(c, theta.obj, "Chain.forward(theta)", [&c](const ChainD::JointVector& th) { return c.forward(th); });
      },
      py::arg("theta"),
      R"doc(Forward kinematics, space form: g(theta) = exp([S_1] th_1) ... exp([S_n] th_n) M.

Args:
    theta: shape (n,) or (N, n), joint positions (radians or lengths), finite.

Returns:
    SE3 | numpy.ndarray: an SE3 for shape (n,); shape (N, 4, 4) for (N, n).

Example:
    >>> arm = Chain([Chain.prismatic_screw([1, 0, 0])], np.eye(4))
    >>> arm.forward([0.5]).translation
    array([0.5, 0. , 0. ])
    >>> arm.forward([[0.5], [1.0]]).shape
    (2, 4, 4)
)doc");

  cls.def(
      "forward_body",
      [](Obj<ChainD> c_, ArrayLike theta) {
        const ChainD& c = *c_;
        return poses(c, theta.obj, "Chain.forward_body(theta)",
                     [&c](const ChainD::JointVector& th) { return c.forward_body(th); });
      },
      py::arg("theta"),
      R"doc(Forward kinematics, body form: g(theta) = M exp([B_1] th_1) ... exp([B_n] th_n).

Equal to ``forward`` up to rounding.

Args:
    theta: shape (n,) or (N, n), finite.

Returns:
    SE3 | numpy.ndarray: an SE3 for shape (n,); shape (N, 4, 4) for (N, n).

Example:
    >>> arm = Chain([Chain.revolute_screw([0, 0, 1], [1, 0, 0])], np.eye(4))
    >>> arm.forward_body([0.3]).is_approx(arm.forward([0.3]))
    True
)doc");

  cls.def(
      "jacobian_space",
      [](Obj<ChainD> c_, ArrayLike theta) {
        const ChainD& c = *c_;
        return jacobians(c, theta.obj, "Chain.jacobian_space(theta)",
                         [&c](const ChainD::JointVector& th) { return c.jacobian_space(th); });
      },
      py::arg("theta"),
      R"doc(The space Jacobian J_s: the spatial twist (g' g^-1)^vee = J_s theta'.

Column i is Ad_{exp([S_1] th_1) ... exp([S_{i-1}] th_{i-1})} S_i; rows (v, w).
J_s = Ad_g J_b.

Args:
    theta: shape (n,) or (N, n), finite.

Returns:
    numpy.ndarray: shape (6, n) for shape (n,); (N, 6, n) for (N, n).

Example:
    >>> arm = Chain([Chain.revolute_screw([0, 0, 1], [0, 0, 0])], np.eye(4))
    >>> arm.jacobian_space([0.3])[:, 0]
    array([0., 0., 0., 0., 0., 1.])
)doc");

  cls.def(
      "jacobian_body",
      [](Obj<ChainD> c_, ArrayLike theta) {
        const ChainD& c = *c_;
        return jacobians(c, theta.obj, "Chain.jacobian_body(theta)",
                         [&c](const ChainD::JointVector& th) { return c.jacobian_body(th); });
      },
      py::arg("theta"),
      R"doc(The body Jacobian J_b: the body twist (g^-1 g')^vee = J_b theta'.

Column i is Ad_{(exp([B_{i+1}] th_{i+1}) ... exp([B_n] th_n))^-1} B_i; rows (v, w).

Args:
    theta: shape (n,) or (N, n), finite.

Returns:
    numpy.ndarray: shape (6, n) for shape (n,); (N, 6, n) for (N, n).

Example:
    >>> arm = Chain([Chain.revolute_screw([0, 0, 1], [0, 0, 0])], SE3(translation=[1.0, 0.0, 0.0]))
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
