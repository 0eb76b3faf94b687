// chasles._core: classes Screw, Twist and Wrench over include/chasles/
// screw.hpp, twist.hpp and wrench.hpp, and SE3's actions on twists and
// wrenches (SE3 is bound before this file runs; see module.cpp).
#include <chasles/se3.hpp>
#include <chasles/twist.hpp>
#include <chasles/wrench.hpp>

#include <cmath>
#include <cstring>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "conventions.hpp"
#include "convert.hpp"

namespace chasles_py {

namespace {

using chasles::SE3d;
using chasles::Twistd;
using chasles::Wrenchd;
using Screwd = chasles::Screw<double>;
using Vector3 = Eigen::Vector3d;
using Vector6 = Eigen::Matrix<double, 6, 1>;
using Matrix4 = Eigen::Matrix4d;

/// A scalar operand of * or /: true and a finite `out` for a real number
/// (float, int, numpy real scalar or 0-d array); false for anything else (the
/// operator then returns NotImplemented, and Python raises TypeError).
bool scalar_operand(py::handle h, double& out, const char* what) {
  PyObject* o = h.ptr();
  if (PyFloat_Check(o)) {
    out = PyFloat_AS_DOUBLE(o);
  } else {
    if (npy().PyArray_Check_(o)) {
      if (py::reinterpret_borrow<py::array>(h).ndim() != 0) return false;
    } else if (h.is_none() || is_bound_object(h) || PySequence_Check(o) || PyComplex_Check(o)) {
      return false;
    }
    try {
      out = to_real(h, what);
    } catch (py::type_error&) {
      return false;
    }
  }
  require_finite(out, what);
  return true;
}

/// x itself, or ValueError when an operation overflowed to infinity.
template <typename T>
T finite_result(T x, const char* what) {
  if (!x.vector().allFinite()) raise_value_error(std::string(what) + ": the result overflows float64");
  return x;
}

py::object not_implemented() { return py::reinterpret_borrow<py::object>(Py_NotImplemented); }

const char* const kScrewDoc = R"doc(A screw: a directed line in space (through ``point``, along the unit
``direction``), a ``pitch`` and a ``magnitude``.

For a twist it is Chasles' screw motion: rotate by ``magnitude`` about the
line while translating ``pitch * magnitude`` along it; pitch = inf is a pure
translation of length ``magnitude`` along ``direction``. For a wrench it is
Poinsot's wrench: a force of size ``magnitude`` along the line plus a torque
``pitch * magnitude`` about it; pitch = inf is a pure couple. ``point`` is
the point of the line nearest the origin (0 for infinite pitch). The zero
twist or wrench has magnitude 0, pitch 0, direction 0.

A Screw unpacks as ``point, direction, pitch, magnitude = screw``, so
``SE3.from_screw(*twist.screw())`` rebuilds the motion.

Example:
    >>> s = Twist(v=[2.0, 0.0, 0.0], w=[0.0, 0.0, 1.0]).screw()
    >>> s.point, s.direction, s.pitch, s.magnitude
    (array([0., 2., 0.]), array([0., 0., 1.]), 0.0, 1.0)
)doc";

const char* const kTwistDoc = R"doc(A twist xi = (v, w) in se(3): linear part first, angular part second
(Murray, Li and Sastry's order; Modern Robotics writes (w, v), see
``to_modern_robotics``). Its 4x4 matrix is [xi] = [[ [w], v ], [0, 0]].

A twist is a velocity (spatial: (g' g^-1)^vee, body: (g^-1 g')^vee) or,
scaled by theta, exponential coordinates of a rigid motion: SE3.exp(xi).
Twists change frame by the adjoint, xi_a = Ad_{g_ab} xi_b (``g.act(xi)``);
wrenches change frame by its inverse transpose. Twists add, subtract and
scale by real numbers.

Example:
    >>> xi = Twist(v=[1.0, 0.0, 0.0], w=[0.0, 0.0, 1.0])
    >>> xi.vector
    array([1., 0., 0., 0., 0., 1.])
    >>> xi.to_modern_robotics()
    array([0., 0., 1., 1., 0., 0.])
)doc";

const char* const kWrenchDoc = R"doc(A wrench F = (f, tau): force first, torque second, so that the power of a
twist V = (v, w) on it is the plain dot product V . F = v.f + w.tau.

Wrenches change frame by the transpose of the adjoint: F_b = Ad_{g_ab}^T F_a
(``g.act_inv(F)``), F_a = Ad_{g_ab}^-T F_b (``g.act(F)``), which is what keeps
the power V . F the same in every frame. Wrenches add, subtract and scale by
real numbers.

Example:
    >>> F = Wrench(f=[0.0, 0.0, -9.81], tau=[0.0, 0.0, 0.0])
    >>> F.power(Twist(v=[0.0, 0.0, -1.0], w=[0.0, 0.0, 0.0]))
    9.81
)doc";

/// What Twist and Wrench call their halves, and the words in which the
/// docstrings and messages the two share differ (the {key}s of six_text).
template <typename T>
struct Six;

template <>
struct Six<Twistd> {
  static constexpr const char *T = "Twist", *kind = "twist", *x = "xi";  // x: the symbol, from_vector's argument
  static constexpr const char *a = "v", *b = "w";  // the halves: the constructor's arguments
  static constexpr const char *a_desc = "linear part", *b_desc = "angular part";
  static constexpr const char *head = "linear", *tail = "angular";  // the properties of the halves
  static constexpr const char* order = "(v, w), linear part first";
  static constexpr const char* screw_doc = R"doc(The screw of the twist (Chasles).

With w != 0: pitch w.v / |w|^2, axis through w x v / |w|^2 along w / |w|,
magnitude |w|; with w = 0: pitch inf, direction v / |v|, magnitude |v|.

Returns:
    Screw.

Example:
    >>> s = Twist(v=[0.0, 0.0, 0.5], w=[0.0, 0.0, 1.0]).screw()
    >>> s.pitch, s.magnitude
    (0.5, 1.0)
)doc";
  static constexpr const char* pitch_doc =
      R"doc(The pitch of the twist's screw: w.v / |w|^2 (a computation, as ``screw().pitch``).

Returns:
    float: the pitch; inf for w = 0 (a translation), 0 for the zero twist.

Example:
    >>> Twist(v=[0.0, 0.0, 0.5], w=[0.0, 0.0, 1.0]).pitch()
    0.5
)doc";
  static constexpr const char* mag = "theta";  // from_screw's last argument
  static constexpr const char* from_screw_doc = R"doc(The unit twist of a screw times theta: theta * (-d x q + h d, d).

For the axis through q along d (normalized here), pitch h; with h = inf, the
translation theta * (d, 0). A zero direction gives the zero twist.

Args:
    point: q, shape (3,).
    direction: d, shape (3,).
    pitch: h; ``math.inf`` for a translation.
    theta: the magnitude.

Returns:
    Twist.

Example:
    >>> Twist.from_screw([0.0, 1.0, 0.0], [0.0, 0.0, 1.0], 0.0, 1.0).vector
    array([1., 0., 0., 0., 0., 1.])
)doc";
};

template <>
struct Six<Wrenchd> {
  static constexpr const char *T = "Wrench", *kind = "wrench", *x = "F";
  static constexpr const char *a = "f", *b = "tau";
  static constexpr const char *a_desc = "force", *b_desc = "torque";
  static constexpr const char *head = "force", *tail = "torque";
  static constexpr const char* order = "(f, tau), force first";
  static constexpr const char* screw_doc = R"doc(The screw of the wrench (Poinsot).

With f != 0, a force along the line through f x tau / |f|^2 with direction
f / |f|, magnitude |f|, plus a torque pitch * f about it,
pitch = f.tau / |f|^2; with f = 0, a pure couple: pitch inf, direction
tau / |tau|, magnitude |tau|.

Returns:
    Screw.
)doc";
  static constexpr const char* pitch_doc =
      R"doc(The pitch of the wrench's screw: f.tau / |f|^2 (a computation, as ``screw().pitch``).

Returns:
    float: the pitch; inf for f = 0 (a pure couple), 0 for the zero wrench.
)doc";
  static constexpr const char* mag = "magnitude";
  static constexpr const char* from_screw_doc = R"doc(The wrench of a screw: magnitude * (d, q x d + h d).

For the line through q along d (normalized here), pitch h; with h = inf, the
couple (0, magnitude * d). A zero direction gives the zero wrench.

Args:
    point: q, shape (3,).
    direction: d, shape (3,).
    pitch: h; ``math.inf`` for a pure couple.
    magnitude: the force size (the torque for h = inf).

Returns:
    Wrench.

Example:
    >>> Wrench.from_screw([0.0, 1.0, 0.0], [1.0, 0.0, 0.0], 0.0, 2.0).vector
    array([ 2.,  0.,  0.,  0.,  0., -2.])
)doc";
};

/// `text` with each {key} replaced by that field of Six<T>, kept for the
/// process (the bound functions keep the pointers of their messages).
template <typename T>
const char* six_text(const char* text) {
  using S = Six<T>;
  std::string s = text;
  const std::pair<const char*, const char*> fields[] = {
      {"{T}", S::T},           {"{kind}", S::kind},     {"{x}", S::x},         {"{a}", S::a},     {"{b}", S::b},
      {"{a_desc}", S::a_desc}, {"{b_desc}", S::b_desc}, {"{order}", S::order}, {"{mag}", S::mag}, {"{tail}", S::tail}};
  for (const auto& [key, value] : fields)
    for (std::size_t at = s.find(key); at != std::string::npos; at = s.find(key, at + std::strlen(value)))
      s.replace(at, std::strlen(key), value);
  return (new std::string(std::move(s)))->c_str();
}

/// What Twist and Wrench share, bound once from Six<T>: the class
/// docstring (`doc`), the constructor from the two halves, from_vector, the
/// 6-vector and its halves, the screw and its pitch, from_screw, and the arithmetic,
/// comparison, copy, pickle, __array__ and __repr__ of a 6-vector.
template <typename T>
void bind_six_vector(Class<T>& cls, const char* doc) {
  using S = Six<T>;
  cls.attr("__doc__") = std::string(doc) + kConventions;
  hold_inline(cls);
  const auto zero3 = py::make_tuple(0.0, 0.0, 0.0);
  static const char *const a_what = six_text<T>("{T}({a})"), *const b_what = six_text<T>("{T}({b})");
  cls.def(py::init([](ArrayLike a, ArrayLike b) {
            return T(to_finite_eigen<3>(a.obj, a_what), to_finite_eigen<3>(b.obj, b_what));
          }),
          py::arg_v(S::a, zero3, "(0.0, 0.0, 0.0)"), py::arg_v(S::b, zero3, "(0.0, 0.0, 0.0)"),
          six_text<T>(R"doc(The {kind} {x} = ({a}, {b}) (the zero {kind} by default).

Args:
    {a}: {a_desc}, shape (3,), finite.
    {b}: {b_desc}, shape (3,), finite.
)doc"));

  static const char* const vector_what = six_text<T>("{T}.from_vector({x})");
  cls.def_static(
      "from_vector", [](ArrayLike x) { return T(to_finite_eigen<6>(x.obj, vector_what)); }, py::arg(S::x),
      six_text<T>(R"doc(The {kind} of a 6-vector {order}.

Args:
    {x}: shape (6,), finite.

Returns:
    {T}.

Example:
    >>> {T}.from_vector([1.0, 2.0, 3.0, 4.0, 5.0, 6.0]).{tail}
    array([4., 5., 6.])
)doc"));

  cls.def_property_readonly(
      "vector", [](Obj<T> x) { return vec_out<6>(x->vector()); },
      six_text<T>("ndarray: the 6-vector {order}, shape (6,)."));
  cls.def_property_readonly(
      S::head, [](Obj<T> x) { return vec_out<3>(Vector3(x->vector().template head<3>())); },
      six_text<T>("ndarray: {a}, shape (3,)."));
  cls.def_property_readonly(
      S::tail, [](Obj<T> x) { return vec_out<3>(Vector3(x->vector().template tail<3>())); },
      six_text<T>("ndarray: {b}, shape (3,)."));

  cls.def("screw", [](Obj<T> x) { return x->screw(); }, S::screw_doc);
  cls.def("pitch", [](Obj<T> x) { return x->pitch(); }, S::pitch_doc);
  static const char *const point_what = six_text<T>("{T}.from_screw(point)"),
                           *const direction_what = six_text<T>("{T}.from_screw(direction)"),
                           *const pitch_what = six_text<T>("{T}.from_screw(pitch)"),
                           *const mag_what = six_text<T>("{T}.from_screw({mag})");
  cls.def_static(
      "from_screw",
      [](ArrayLike point, ArrayLike direction, RealLike pitch, RealLike magnitude) {
        return T::from_screw(to_finite_eigen<3>(point.obj, point_what),
                             to_finite_eigen<3>(direction.obj, direction_what), to_pitch(pitch.obj, pitch_what),
                             to_finite_real(magnitude.obj, mag_what));
      },
      py::arg("point"), py::arg("direction"), py::arg("pitch"), py::arg(S::mag), S::from_screw_doc);

  cls.attr("__array_ufunc__") = py::none();  // numpy defers 2.0 * x to x.__rmul__
  // Arithmetic keeps the invariant of the constructors: finite numbers only.
  static const char *const add_what = six_text<T>("{T} + {T}"), *const sub_what = six_text<T>("{T} - {T}");
  cls.def(
      "__add__", [](Obj<T> x, Obj<T> y) { return finite_result(*x + *y, add_what); }, py::arg("other"),
      py::is_operator());
  cls.def(
      "__sub__", [](Obj<T> x, Obj<T> y) { return finite_result(*x - *y, sub_what); }, py::arg("other"),
      py::is_operator());
  cls.def("__neg__", [](Obj<T> x) { return -*x; });
  cls.def("__pos__", [](Obj<T> x) { return *x; });
  static const char* const mul_what = six_text<T>("{T} * scalar");
  const auto mul = [](Obj<T> x, RealLike s) -> Returns<T> {
    double k;
    if (!scalar_operand(s.obj, k, mul_what)) return {not_implemented()};
    return {py::cast(finite_result(*x * k, mul_what))};
  };
  cls.def("__mul__", mul, py::arg("scalar"));
  cls.def("__rmul__", mul, py::arg("scalar"));
  static const char* const div_what = six_text<T>("{T} / scalar");
  cls.def(
      "__truediv__",
      [](Obj<T> x, RealLike s) -> Returns<T> {
        double k;
        if (!scalar_operand(s.obj, k, div_what)) return {not_implemented()};
        if (k == 0.0) {
          PyErr_SetString(PyExc_ZeroDivisionError, (std::string(div_what) + ": division by zero").c_str());
          throw py::error_already_set();
        }
        return {py::cast(finite_result(T(Vector6(x->vector() / k)), div_what))};
      },
      py::arg("scalar"));
  static const char* const tol_what = six_text<T>("{T}.is_approx(tol)");
  cls.def(
      "is_approx", [](Obj<T> x, Obj<T> y, RealLike tol) { return x->is_approx(*y, to_tolerance(tol.obj, tol_what)); },
      py::arg("other"), py::arg_v("tol", 1e-9),
      R"doc(Whether two 6-vectors are equal within tol: max |x - y| <= tol * max(1, max |x|, max |y|).

``==`` is the exact comparison (every stored number equal).

Args:
    other: the same type.
    tol: the tolerance (>= 0).

Returns:
    bool.
)doc");
  def_array(
      cls, [](const T& x) { return vec_out<6>(x.vector()); },
      "The 6-vector, shape (6,), for np.asarray (numpy's dtype and copy keywords).");
  // The state: the 6-vector, finite as the constructor takes it.
  static const char* const setstate = six_text<T>("{T}.__setstate__");
  def_value_protocol<6>(
      cls,
      [](const T& x) {
        return std::string(S::T) + "(" + S::a + "=" + array_repr(vec_out<3>(Vector3(x.vector().template head<3>()))) +
               ", " + S::b + "=" + array_repr(vec_out<3>(Vector3(x.vector().template tail<3>()))) + ")";
      },
      [](const T& x) { return x.vector(); },
      [](const double* v) {
        const Vector6 x = Eigen::Map<const Vector6>(v);
        require_finite(x, setstate);
        return T(x);
      });
}

void bind_screw(py::class_<Screwd>& cls) {
  cls.attr("__doc__") = kScrewDoc;
  cls.attr("__array_ufunc__") = py::none();  // numpy defers operators (np.float64(1.0) == s) to us
  cls.def(py::init([](ArrayLike point, ArrayLike direction, RealLike pitch, RealLike magnitude) {
            Screwd s;
            s.point = to_finite_eigen<3>(point.obj, "Screw(point)");
            s.direction = to_finite_eigen<3>(direction.obj, "Screw(direction)");
            s.pitch = to_pitch(pitch.obj, "Screw(pitch)");
            s.magnitude = to_finite_real(magnitude.obj, "Screw(magnitude)");
            return s;
          }),
          py::arg("point"), py::arg("direction"), py::arg("pitch"), py::arg("magnitude"),
          R"doc(A screw from its parameters (stored as given).

Args:
    point: a point of the axis, shape (3,), finite.
    direction: the axis direction, shape (3,), finite (unit length by
        convention; from_screw normalizes it).
    pitch: translation (or torque) per unit of magnitude; inf allowed.
    magnitude: rotation angle (twist) or force size (wrench), finite.
)doc");
  cls.def_property_readonly(
      "point", [](Obj<Screwd> s) { return vec_out<3>(s->point); },
      "ndarray: the point of the axis nearest the origin, shape (3,).");
  cls.def_property_readonly(
      "direction", [](Obj<Screwd> s) { return vec_out<3>(s->direction); },
      "ndarray: the unit direction of the axis, shape (3,).");
  cls.def_property_readonly(
      "pitch", [](Obj<Screwd> s) { return s->pitch; }, "float: the pitch (inf for a translation or a couple).");
  cls.def_property_readonly("magnitude", [](Obj<Screwd> s) { return s->magnitude; }, "float: the magnitude.");
  cls.def("__iter__", [](Obj<Screwd> s_) {
    const Screwd& s = *s_;
    return py::iter(py::make_tuple(vec_out<3>(s.point), vec_out<3>(s.direction), s.pitch, s.magnitude));
  });
  cls.def("__len__", [](Obj<Screwd>) { return 4; });
  cls.def(
      "is_approx",
      [](Obj<Screwd> a_, Obj<Screwd> b_, RealLike tol) {
        const Screwd &a = *a_, &b = *b_;
        const double t = to_tolerance(tol.obj, "Screw.is_approx(tol)");
        const auto close = [t](double x, double y) {
          return x == y || std::abs(x - y) <= t * std::max({1.0, std::abs(x), std::abs(y)});
        };
        for (int i = 0; i < 3; ++i)
          if (!close(a.point[i], b.point[i]) || !close(a.direction[i], b.direction[i])) return false;
        return close(a.pitch, b.pitch) && close(a.magnitude, b.magnitude);
      },
      py::arg("other"), py::arg_v("tol", 1e-9),
      R"doc(Whether two screws have the same parameters within tol (relative beyond unit scale).

Args:
    other: Screw.
    tol: the tolerance (>= 0).

Returns:
    bool.
)doc");
  // The state: point, direction, pitch, magnitude; checked as the constructor checks them.
  def_value_protocol<8>(
      cls,
      [](const Screwd& s) {
        return "Screw(point=" + array_repr(vec_out<3>(s.point)) + ", direction=" + array_repr(vec_out<3>(s.direction)) +
               ", pitch=" + float_repr(s.pitch) + ", magnitude=" + float_repr(s.magnitude) + ")";
      },
      [](const Screwd& s) {
        Eigen::Matrix<double, 8, 1> v;
        v << s.point, s.direction, s.pitch, s.magnitude;
        return v;
      },
      [](const double* v) {
        Screwd s;
        s.point = Vector3(v[0], v[1], v[2]);
        s.direction = Vector3(v[3], v[4], v[5]);
        require_finite(s.point, "Screw.__setstate__(point)");
        require_finite(s.direction, "Screw.__setstate__(direction)");
        s.pitch = to_pitch(py::float_(v[6]), "Screw.__setstate__(pitch)");
        s.magnitude = v[7];
        require_finite(s.magnitude, "Screw.__setstate__(magnitude)");
        return s;
      });
}

void bind_twist(Class<Twistd>& cls) {
  bind_six_vector(cls, kTwistDoc);
  cls.def(
      "to_modern_robotics", [](Obj<Twistd> x) { return vec_out<6>(x->to_modern_robotics()); },
      R"doc(The 6-vector in the Modern Robotics order (w, v), angular part first.

Returns:
    ndarray: shape (6,).
)doc");
  cls.def_static(
      "from_modern_robotics",
      [](ArrayLike wv) {
        return Twistd::from_modern_robotics(to_finite_eigen<6>(wv.obj, "Twist.from_modern_robotics(wv)"));
      },
      py::arg("wv"),
      R"doc(The twist of a 6-vector in the Modern Robotics order (w, v).

Args:
    wv: shape (6,), angular part first.

Returns:
    Twist.

Example:
    >>> Twist.from_modern_robotics([0.0, 0.0, 1.0, 2.0, 0.0, 0.0]).vector
    array([2., 0., 0., 0., 0., 1.])
)doc");

  cls.def(
      "hat", [](Obj<Twistd> x) { return mat_out<4, 4>(x->hat()); },
      R"doc(The 4x4 matrix [xi] = [[ [w], v ], [0, 0]].

Returns:
    ndarray: shape (4, 4).
)doc");
  cls.def_static(
      "vee", [](ArrayLike X) { return Twistd::vee(to_finite_eigen<4, 4>(X.obj, "Twist.vee(matrix)")); },
      py::arg("matrix"),
      R"doc(The twist of a 4x4 matrix [[S, v], [*, *]]: v and the w of S's antisymmetric part.

The bottom row is ignored.

Args:
    matrix: shape (4, 4), finite.

Returns:
    Twist.
)doc");
  cls.def(
      "ad", [](Obj<Twistd> x) { return mat_out<6, 6>(x->ad()); },
      R"doc(The adjoint of the algebra ad_xi = [[ [w], [v] ], [0, [w]]] (6x6).

ad_xi eta = [xi, eta] (``xi.bracket(eta)``).

Returns:
    ndarray: shape (6, 6).
)doc");
  cls.def(
      "bracket", [](Obj<Twistd> xi, Obj<Twistd> eta) { return xi->bracket(*eta); }, py::arg("other"),
      R"doc(The Lie bracket [xi, eta] = ([xi][eta] - [eta][xi])^vee = (w1 x v2 + v1 x w2, w1 x w2).

Args:
    other: Twist, eta.

Returns:
    Twist.
)doc");

  cls.def_static(
      "spatial",
      [](Obj<SE3d> g_, ArrayLike g_dot) {
        const SE3d& g = *g_;
        return Twistd::spatial(g, to_finite_eigen<4, 4>(g_dot.obj, "Twist.spatial(g_dot)"));
      },
      py::arg("g"), py::arg("g_dot"),
      R"doc(The spatial twist of a trajectory at (g, g'): V^s = (g' g^-1)^vee.

w^s = (R' R^T)^vee, v^s = p' - w^s x p. V^s = Ad_g V^b.

Args:
    g: SE3, the configuration.
    g_dot: its time derivative, shape (4, 4).

Returns:
    Twist.
)doc");
  cls.def_static(
      "body",
      [](Obj<SE3d> g_, ArrayLike g_dot) {
        const SE3d& g = *g_;
        return Twistd::body(g, to_finite_eigen<4, 4>(g_dot.obj, "Twist.body(g_dot)"));
      },
      py::arg("g"), py::arg("g_dot"),
      R"doc(The body twist of a trajectory at (g, g'): V^b = (g^-1 g')^vee.

w^b = (R^T R')^vee, v^b = R^T p'.

Args:
    g: SE3, the configuration.
    g_dot: its time derivative, shape (4, 4).

Returns:
    Twist.
)doc");

  cls.def(
      "power", [](Obj<Twistd> V, Obj<Wrenchd> F) { return F->power(*V); }, py::arg("wrench"),
      R"doc(The power V . F = v.f + w.tau of this twist on a wrench (same frame).

Args:
    wrench: Wrench, F.

Returns:
    float.

Example:
    >>> Twist(v=[1.0, 0.0, 0.0]).power(Wrench(f=[2.0, 0.0, 0.0]))
    2.0
)doc");
}

void bind_wrench(Class<Wrenchd>& cls) {
  bind_six_vector(cls, kWrenchDoc);
  cls.def(
      "power", [](Obj<Wrenchd> F, Obj<Twistd> V) { return F->power(*V); }, py::arg("twist"),
      R"doc(The power V . F = v.f + w.tau of a twist on this wrench (same frame).

Args:
    twist: Twist, V.

Returns:
    float.
)doc");
}

}  // namespace

void bind_twist_wrench(Class<Twistd>& twist, Class<Wrenchd>& wrench, py::class_<Screwd>& screw) {
  bind_screw(screw);
  bind_twist(twist);
  bind_wrench(wrench);
}

}  // namespace chasles_py
