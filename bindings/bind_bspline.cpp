// chasles._core: classes SO3BSpline and SE3BSpline over
// chasles::CubicBSplineView (include/chasles/bspline.hpp): the uniform
// cumulative cubic B-spline on SO(3) and SE(3). The classes hold the start
// time, the spacing and the control elements as an (N, D, D) array; the
// private gufuncs evaluate them at times (the broadcast operand), registered
// by def_ufunc (ufunc.hpp) with the spline as the model of those three:
//
//   _so3_bspline        (),(),(n,3,3),()->(3,3)             the element
//   _so3_bspline_rates  (),(),(n,3,3),()->(3,3),(3),(3)     and its body velocity, acceleration
//   _se3_bspline        (),(),(n,4,4),()->(4,4)
//   _se3_bspline_rates  (),(),(n,4,4),()->(4,4),(6),(6)
#include <chasles/bspline.hpp>

#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"
#include "ufunc.hpp"

namespace chasles_py {

namespace {

using chasles::SE3d;
using chasles::SO3d;

/// The Python class's value: the two times and its own copy of the control
/// elements, as the (N, D, D) float64 array (read-only) that the private
/// gufuncs take as an operand.
template <typename Group>
struct BSpline {
  double start_time = 0, spacing = 1;
  py::array control;
  double end_time() const { return start_time + double(control.shape(0) - 3) * spacing; }
};

template <typename Group>
struct Names;
template <>
struct Names<SO3d> {
  static constexpr const char* cls = "SO3BSpline";
  static constexpr const char* element = "SO3";
  static constexpr int rows = 3;  // matrix rows, and the tangent size
  static constexpr int dof = 3;
};
template <>
struct Names<SE3d> {
  static constexpr const char* cls = "SE3BSpline";
  static constexpr const char* element = "SE3";
  static constexpr int rows = 4;
  static constexpr int dof = 6;
};

template <typename Group>
std::string label(const char* arg) {
  return std::string(Names<Group>::cls) + "(" + arg + ")";
}

/// An element of the control sequence: an initialized SO3 / SE3, or (for a
/// matrix stack) a rotation / rigid motion within the checked constructors'
/// tolerance.
///
/// `single`: the matrices came as float32 (or float16) numbers, which hold a
/// rotation only to float32's precision: they are checked with float32's
/// tolerance, sqrt(eps_float32) = 3.5e-4 (constants.hpp), and replaced by
/// the nearest rotation, so that the spline computes with a rotation in
/// float64. Other input is checked with float64's tolerance and kept as is.
template <typename Group>
Group element_from_matrix(const double* m, std::ptrdiff_t index, const std::string& what, bool single) {
  constexpr int n = Names<Group>::rows;
  const Eigen::Map<const Eigen::Matrix<double, n, n, Eigen::RowMajor>> M(m);
  const Eigen::Matrix<double, n, n> A = M;
  const double tolerance = single ? double(chasles::Thresholds<float>::rotation_tolerance)
                                  : chasles::Thresholds<double>::rotation_tolerance;
  std::optional<Group> g;
  double defect;
  if constexpr (n == 3) {
    g = SO3d::from_matrix(A, tolerance);
    defect = SO3d::rotation_defect(A);
    if (g && single) g = SO3d::from_matrix_projected(A);
  } else {
    g = SE3d::from_matrix(A, tolerance);
    defect = SE3d::transform_defect(A);
    if (g && single) g = SE3d::from_matrix_projected(A);
  }
  if (!g) {
    raise_value_error(what + ": element " + std::to_string(index) + " is not " +
                      (n == 3 ? "a rotation" : "a rigid motion") + " (defect " + short_float(defect) +
                      "); project it first (" + Names<Group>::element + ".from_matrix_projected)");
  }
  return *g;
}

/// The control elements: a sequence of SO3 / SE3 objects, or an array-like
/// of shape (N, 3, 3) / (N, 4, 4); N >= 4.
template <typename Group>
std::vector<Group> control_of(py::handle h) {
  constexpr int n = Names<Group>::rows;
  const std::string what = label<Group>("control");
  std::vector<Group> out;
  const bool objects = (PyList_Check(h.ptr()) || PyTuple_Check(h.ptr())) && py::len(h) > 0 &&
                       is_bound_object(py::reinterpret_borrow<py::sequence>(h)[0]);
  if (objects) {
    const auto seq = py::reinterpret_borrow<py::sequence>(h);
    for (std::size_t i = 0; i < seq.size(); ++i) {
      py::detail::make_caster<Obj<Group>> caster;
      if (!caster.load(seq[i], false))
        raise_type_error(what + ": element " + std::to_string(i) + " is a " + type_name(seq[i]) + ", expected an " +
                         Names<Group>::element + " (a sequence of them, or an array of matrices)");
      out.push_back(*static_cast<Obj<Group>&>(caster));
    }
  } else {
    bool single = false;
    if (npy().PyArray_Check_(h.ptr())) {
      const py::dtype dt = py::reinterpret_borrow<py::array>(h).dtype();
      single = dt.kind() == 'f' && dt.itemsize() <= 4;
    }
    const py::array a = as_float64_array(h, what.c_str());
    if (a.ndim() != 3 || a.shape(1) != n || a.shape(2) != n) {
      raise_value_error(what + ": expected shape (N, " + std::to_string(n) + ", " + std::to_string(n) +
                        ") or a sequence of " + Names<Group>::element + ", got " +
                        shape_string(a.shape(), static_cast<int>(a.ndim())));
    }
    const auto c = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    const double* data = c.data();
    for (py::ssize_t i = 0; i < c.shape(0); ++i)
      out.push_back(element_from_matrix<Group>(data + i * n * n, i, what, single));
  }
  if (out.size() < 4)
    raise_value_error(what + ": a cubic B-spline needs N >= 4 control elements, got " + std::to_string(out.size()));
  return out;
}

/// The control elements as a new (N, D, D) array, read-only.
template <typename Group>
py::array control_array(const std::vector<Group>& control) {
  constexpr int rows = Names<Group>::rows;
  const Py_intptr_t dims[3] = {static_cast<Py_intptr_t>(control.size()), rows, rows};
  py::array_t<double> out = new_array(3, dims);
  double* o = array_data(out);
  for (std::size_t i = 0; i < control.size(); ++i)
    Eigen::Map<Eigen::Matrix<double, rows, rows, Eigen::RowMajor>>(o + i * rows * rows) = control[i].matrix();
  out.attr("flags").attr("writeable") = false;
  return std::move(out);
}

/// The spline of the gufuncs' operands start_time, spacing and control, in
/// storage of its own (the C++ spline views an array of elements); valid
/// when N >= 4 and the spacing is finite and > 0 (NaN results otherwise).
template <typename Group>
struct BSplineModel {
  double start_time, spacing;
  std::vector<Group> control;

  bool valid() const noexcept {
    return control.size() >= 4 && spacing > 0 && spacing <= std::numeric_limits<double>::max();
  }
  chasles::CubicBSplineView<Group> view() const noexcept {
    return {control.data(), static_cast<std::ptrdiff_t>(control.size()), start_time, spacing};
  }
};

template <typename Group>
struct BSplineOf {
  template <typename Control>
  BSplineModel<Group> operator()(double start_time, double spacing, const Control& control) const noexcept {
    constexpr int n = Names<Group>::rows;
    BSplineModel<Group> m{start_time, spacing, {}};
    for (Eigen::Index i = 0; i < control.size(); ++i)
      m.control.push_back(Group::from_matrix_unchecked(Eigen::Matrix<double, n, n>(control[i])));
    return m;
  }
};

template <typename Group>
Eigen::Matrix<double, Names<Group>::rows, Names<Group>::rows> nan_matrix() {
  return Eigen::Matrix<double, Names<Group>::rows, Names<Group>::rows>::Constant(
      std::numeric_limits<double>::quiet_NaN());
}

/// The element at t (clamped to [start_time, end_time]; the methods check).
template <typename Group>
struct Element {
  Eigen::Matrix<double, Names<Group>::rows, Names<Group>::rows> operator()(const BSplineModel<Group>& m,
                                                                           double t) const noexcept {
    return m.valid() ? m.view()(t).matrix() : nan_matrix<Group>();
  }
};

/// The element, body velocity and body acceleration at t.
template <typename Group>
struct Rates {
  using Tangent = Eigen::Matrix<double, Names<Group>::dof, 1>;
  std::tuple<Eigen::Matrix<double, Names<Group>::rows, Names<Group>::rows>, Tangent, Tangent> operator()(
      const BSplineModel<Group>& m, double t) const noexcept {
    if (!m.valid()) {
      const Tangent nan = Tangent::Constant(std::numeric_limits<double>::quiet_NaN());
      return {nan_matrix<Group>(), nan, nan};
    }
    const chasles::BSplinePoint<Group> p = m.view().evaluate(t);
    return {p.value.matrix(), p.velocity, p.acceleration};
  }
};

/// The times t of a method call as a ufunc operand, numpy's times checked
/// to lie in [start_time, end_time] (a NaN time passes: NaN results).
template <typename Group>
py::object times_operand(const BSpline<Group>& s, py::handle t, const char* what) {
  if (!npy().PyArray_Check_(t.ptr()) && py::hasattr(t, "__array_ufunc__") && !t.attr("__array_ufunc__").is_none())
    return py::reinterpret_borrow<py::object>(t);  // dask: numpy dispatches to it; times clamped, unchecked
  const py::array a = as_float64_array(t, what);
  const auto times = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  const py::ssize_t count = times.size();
  const double* tp = times.data();
  const double t0 = s.start_time, t1 = s.end_time();
  for (py::ssize_t i = 0; i < count; ++i) {
    if (tp[i] < t0 || tp[i] > t1) {  // NaN passes: NaN result
      raise_value_error(std::string(what) + ": expected times in [start_time, end_time] = [" + float_repr(t0) +
                        ", " + float_repr(t1) + "], got " + float_repr(tp[i]));
    }
  }
  return std::move(times);
}

template <typename Group>
std::string class_doc() {
  const bool so3 = Names<Group>::rows == 3;
  const std::string G = Names<Group>::element, N = Names<Group>::cls;
  const std::string m = so3 ? "3, 3" : "4, 4", k = so3 ? "3" : "6";
  return "The uniform cumulative cubic B-spline on " + std::string(so3 ? "SO(3)" : "SE(3)") +
         " (Kim, Kim and Shin 1995;\nLovegrove, Patron-Perez and Sibley 2013), "
         "the curve of continuous-time\nestimation, with analytic body velocity and acceleration (Sommer et al.\n"
         "2020, \"Efficient derivative computation for cumulative B-splines on Lie\ngroups\").\n\n"
         "Control elements X_0 .. X_{N-1} (N >= 4), start time t0 and knot spacing dt.\n"
         "At t = t0 + (i + u) dt, u in [0, 1], segment i uses X_i .. X_{i+3}:\n\n"
         "    X(t) = X_i exp(B1(u) d_1) exp(B2(u) d_2) exp(B3(u) d_3),\n"
         "    d_j = log(X_{i+j-1}^-1 X_{i+j}),\n"
         "    B1 = (5 + 3u - 3u^2 + u^3)/6, B2 = (1 + 3u + 3u^2 - 2u^3)/6, B3 = u^3/6.\n\n"
         "The curve is C2 and smooths rather than interpolates: it does not pass\n"
         "through the control elements. It is defined on [start_time, end_time],\n"
         "end_time = t0 + (N - 3) dt; other times are a ValueError (NaN gives NaN).\n"
         "Body velocity (X^-1 X')^vee and body acceleration, its time derivative,\n"
         "come from the recursion over the three factors, not from differences;\n" +
         (so3 ? "they are angular velocities w (rad per unit of time)."
              : "twists (v, w), linear part first (Murray, Li and Sastry).") +
         "\n\nEvaluation takes a time or an array of times of any shape and runs one\n"
         "C++ loop over them with the GIL released. Values are float64.\n\n"
         "Example:\n"
         "    >>> control = [" + G + ".exp([0.0, 0.0, 0.1 * k]" + (so3 ? "" : " + [0.0] * 3") +
         ") for k in range(6)]\n"
         "    >>> spline = " + N + "(0.0, 0.5, control)\n"
         "    >>> spline.end_time\n"
         "    1.5\n"
         "    >>> spline([0.0, 0.7]).shape\n"
         "    (2, " + m + ")\n"
         "    >>> np.round(spline.body_velocity(0.7), 12) + 0.0\n"
         "    array([" + (so3 ? "0. , 0. , 0.2" : "0. , 0. , 0.2, 0. , 0. , 0. ") + "])\n";
}

template <typename Group>
void bind_one(py::module_& m) {
  using S = BSpline<Group>;
  constexpr int rows = Names<Group>::rows;
  const bool so3 = rows == 3;
  static const std::string doc = class_doc<Group>();
  py::class_<S> cls(m, Names<Group>::cls, doc.c_str());
  cls.attr("__array_ufunc__") = py::none();

  static const std::string init_doc =
      std::string("A spline from its start time, knot spacing and control elements.\n\nArgs:\n"
                  "    start_time: t0, finite.\n"
                  "    spacing: dt > 0, finite, the time between knots.\n"
                  "    control: N >= 4 control elements: a sequence of ") +
      Names<Group>::element + ", or an array-like of\n        shape (N, " + std::to_string(rows) + ", " +
      std::to_string(rows) + ") of " + (so3 ? "rotation matrices" : "rigid motions [[R, p], [0, 0, 0, 1]]") +
      " (checked as\n        " + Names<Group>::element +
      ".from_matrix does; a float32 array with float32's tolerance,\n        3.5e-4, then projected to "
      "the nearest rotation). The spline keeps\n        its own float64 copy.\n\n"
      "Raises:\n"
      "    ValueError: fewer than 4 control elements, a wrong shape, a matrix\n"
      "        that is not " + (so3 ? "a rotation" : "a rigid motion") +
      ", a start time that is not finite or a spacing that\n        is not finite and > 0.\n"
      "    TypeError: a sequence holding something other than " + Names<Group>::element + ".\n";
  cls.def(py::init([](RealLike start_time, RealLike spacing, ArrayLike control) {
            S s;
            s.start_time = to_finite_real(start_time.obj, label<Group>("start_time").c_str());
            s.spacing = to_finite_real(spacing.obj, label<Group>("spacing").c_str());
            if (!(s.spacing > 0))
              raise_value_error(label<Group>("spacing") + ": expected a positive spacing (> 0), got " + float_repr(s.spacing));
            s.control = control_array(control_of<Group>(control.obj));
            return s;
          }),
          py::arg("start_time"), py::arg("spacing"), py::arg("control"), init_doc.c_str());

  static const std::string call_what = std::string(Names<Group>::cls) + "(t)";
  static const std::string vel_what = std::string(Names<Group>::cls) + ".body_velocity(t)";
  static const std::string acc_what = std::string(Names<Group>::cls) + ".body_acceleration(t)";
  static const std::string call_doc =
      std::string("The elements X(t).\n\nArgs:\n"
                  "    t: a time or an array_like of times of any shape, in [start_time, end_time].\n\n"
                  "Returns:\n    numpy.ndarray: shape t.shape + (") +
      std::to_string(rows) + ", " + std::to_string(rows) + "), the " +
      (so3 ? "rotation matrices" : "homogeneous matrices") +
      ".\n\nRaises:\n    ValueError: a time outside [start_time, end_time].\n    TypeError: times that are not real numbers.\n";
  const std::string k = so3 ? "3" : "6";
  static const std::string vel_doc =
      "The body velocity (X^-1 X')^vee at the times t, per unit of time.\n\n"
      "omega_j = Ad_{A_j^-1} omega_{j-1} + B_j' d_j over the factors A_j = exp(B_j d_j).\n\n"
      "Args:\n    t: a time or an array_like of times of any shape, in [start_time, end_time].\n\n"
      "Returns:\n    numpy.ndarray: shape t.shape + (" + k + ",), " +
      (so3 ? "the angular velocity w in the body frame." : "the body twist (v, w), linear part first.") +
      "\n\nRaises:\n    ValueError: a time outside [start_time, end_time].\n    TypeError: times that are not real numbers.\n";
  static const std::string acc_doc =
      "The body acceleration, the time derivative of body_velocity, at the times t.\n\n"
      "omega_j' = Ad_{A_j^-1} omega_{j-1}' + B_j'' d_j + [omega_j, B_j' d_j].\n\n"
      "Args:\n    t: a time or an array_like of times of any shape, in [start_time, end_time].\n\n"
      "Returns:\n    numpy.ndarray: shape t.shape + (" + k + ",), per unit of time squared.\n\n"
      "Raises:\n    ValueError: a time outside [start_time, end_time].\n    TypeError: times that are not real numbers.\n";
  using ufunc::Core;
  using Control = Core<ufunc::upto<ufunc::unbounded>, rows, rows>;
  constexpr int dof = Names<Group>::dof;
  const std::string lower = so3 ? "so3" : "se3";
  static const std::string element_name = "_" + lower + "_bspline", rates_name = "_" + lower + "_bspline_rates";
  const std::string operands = std::string("\n\nOperands (float64): start_time (), spacing () > 0, control (n, ") +
                               std::to_string(rows) + ", " + std::to_string(rows) +
                               "), n >= 4 (NaN results otherwise), t (), clamped to [start_time, end_time]. "
                               "A private ufunc of chasles." + Names<Group>::cls + ".";
  const py::object u_element = ufunc::def_ufunc<Core<rows, rows>(Core<>, Core<>, Control, Core<>), ufunc::Float64>(
      m, element_name.c_str(), "start_time, spacing, control, t", "The spline's element at t." + operands,
      ufunc::model<3>(BSplineOf<Group>()), Element<Group>());
  const py::object u_rates =
      ufunc::def_ufunc<std::tuple<Core<rows, rows>, Core<dof>, Core<dof>>(Core<>, Core<>, Control, Core<>),
                       ufunc::Float64>(m, rates_name.c_str(), "start_time, spacing, control, t",
                                       "The spline's element, body velocity and body acceleration at t." + operands,
                                       ufunc::model<3>(BSplineOf<Group>()), Rates<Group>());
  /// The method `what` at t: the element (order 0) or a rate (1, 2).
  const auto evaluate = [](const py::object& u, const S& s, py::handle t, const std::string& what,
                           int order) -> Returns<py::array> {
    const py::object times = times_operand(s, t, what.c_str());
    const py::float_ t0(s.start_time), dt(s.spacing);
    const py::object r = call_ufunc<4>(u.ptr(), what.c_str(), {t0.ptr(), dt.ptr(), s.control.ptr(), times.ptr()});
    return {order == 0 ? r : py::object(py::tuple(r)[static_cast<std::size_t>(order)])};
  };
  cls.def(
      "__call__", [u_element, evaluate](Obj<S> s, ArrayLike t) { return evaluate(u_element, *s, t.obj, call_what, 0); },
      py::arg("t"), call_doc.c_str());
  cls.def(
      "body_velocity", [u_rates, evaluate](Obj<S> s, ArrayLike t) { return evaluate(u_rates, *s, t.obj, vel_what, 1); },
      py::arg("t"), vel_doc.c_str());
  cls.def(
      "body_acceleration",
      [u_rates, evaluate](Obj<S> s, ArrayLike t) { return evaluate(u_rates, *s, t.obj, acc_what, 2); }, py::arg("t"),
      acc_doc.c_str());
  cls.def_property_readonly(
      "start_time", [](Obj<S> s) { return s->start_time; }, "float: t0, the start of the first segment.");
  cls.def_property_readonly(
      "spacing", [](Obj<S> s) { return s->spacing; }, "float: dt, the time between knots.");
  cls.def_property_readonly(
      "end_time", [](Obj<S> s) { return s->end_time(); }, "float: t0 + (N - 3) dt, the last valid time.");
  static const std::string control_doc = "numpy.ndarray: shape (N, " + std::to_string(rows) + ", " +
                                         std::to_string(rows) + "), the control elements (a copy).";
  cls.def_property_readonly(
      "control",
      [](Obj<S> s) { return Returns<py::array_t<double>>{s->control.attr("copy")()}; },
      control_doc.c_str());
  def_repr(cls, [](const S& s) {
    return std::string(Names<Group>::cls) + "(start_time=" + float_repr(s.start_time) +
           ", spacing=" + float_repr(s.spacing) + ", n_control=" + std::to_string(s.control.shape(0)) + ")";
  });
}

}  // namespace

void bind_bspline(py::module_& m) {
  bind_one<SO3d>(m);
  bind_one<SE3d>(m);
}

}  // namespace chasles_py
