// chasles._core: the private functions behind chasles.SO3BSpline and
// chasles.SE3BSpline (python/chasles/_bspline.py) over
// chasles::cubic_bspline_locate and the segment functions of
// include/chasles/bspline.hpp: the uniform cumulative cubic B-spline on
// SO(3) and SE(3). The Python classes hold the start time, the spacing and
// the control elements as an (N, D, D) array:
//
//   _so3_bspline_new(start_time, spacing, control)  the constructor's checks: (t0, dt, the (N, 3, 3) array)
//   _so3_bspline_evaluate(t0, dt, control, t, order) the methods: times checked, then the gufunc
//
// and the private gufuncs evaluate them at times (the broadcast operand),
// registered by def_ufunc (ufunc.hpp) with the spline as the model of those
// three operands (a view of the control array: an evaluation reads the four
// control elements of its segment, O(1) whatever N):
//
//   _so3_bspline        (),(),(n,3,3),()->(3,3)             the element
//   _so3_bspline_rates  (),(),(n,3,3),()->(3,3),(3),(3)     and its body velocity, acceleration
//   _se3_bspline        (),(),(n,4,4),()->(4,4)
//   _se3_bspline_rates  (),(),(n,4,4),()->(4,4),(6),(6)
#include <chasles/bspline.hpp>

#include <array>
#include <climits>
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

/// A spline's numbers, as the Python class holds them: the two times and
/// its own copy of the control elements, the (N, D, D) float64 array
/// (read-only) that the private gufuncs take as an operand.
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
  const double tolerance =
      single ? double(chasles::Thresholds<float>::rotation_tolerance) : chasles::Thresholds<double>::rotation_tolerance;
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

/// The spline of the gufuncs' operands start_time, spacing and control: the
/// two times and the map of the control array (numpy's memory, with its
/// strides), read where an evaluation needs it; valid when N >= 4 and the
/// spacing is finite and > 0 (NaN results otherwise).
template <typename Group, typename Control>
struct BSplineModel {
  double start_time, spacing;
  Control control;

  bool valid() const noexcept {
    return control.size() >= 4 && spacing > 0 && spacing <= std::numeric_limits<double>::max();
  }
  /// The segment of t and its four control elements (the view's time
  /// convention: clamped to [start_time, end_time]).
  chasles::BSplineTime<double> locate(double t, std::array<Group, 4>& four) const noexcept {
    constexpr int n = Names<Group>::rows;
    const chasles::BSplineTime<double> at =
        chasles::cubic_bspline_locate<double>(static_cast<std::ptrdiff_t>(control.size()), start_time, spacing, t);
    for (std::size_t j = 0; j < 4; ++j)
      four[j] = Group::from_matrix_unchecked(
          Eigen::Matrix<double, n, n>(control[static_cast<Eigen::Index>(at.segment) + static_cast<Eigen::Index>(j)]));
    return at;
  }
};

template <typename Group>
struct BSplineOf {
  template <typename Control>
  BSplineModel<Group, Control> operator()(double start_time, double spacing, const Control& control) const noexcept {
    return {start_time, spacing, control};
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
  template <typename Model>
  Eigen::Matrix<double, Names<Group>::rows, Names<Group>::rows> operator()(const Model& m, double t) const noexcept {
    if (!m.valid()) return nan_matrix<Group>();
    std::array<Group, 4> four;
    const chasles::BSplineTime<double> at = m.locate(t, four);
    return chasles::cubic_bspline_segment(four.data(), at.u).matrix();
  }
};

/// The element, body velocity and body acceleration at t.
template <typename Group>
struct Rates {
  using Tangent = Eigen::Matrix<double, Names<Group>::dof, 1>;
  template <typename Model>
  std::tuple<Eigen::Matrix<double, Names<Group>::rows, Names<Group>::rows>, Tangent, Tangent> operator()(
      const Model& m, double t) const noexcept {
    if (!m.valid()) {
      const Tangent nan = Tangent::Constant(std::numeric_limits<double>::quiet_NaN());
      return {nan_matrix<Group>(), nan, nan};
    }
    std::array<Group, 4> four;
    const chasles::BSplineTime<double> at = m.locate(t, four);
    const chasles::BSplinePoint<Group> p = chasles::cubic_bspline_segment_derivatives(four.data(), at.u, m.spacing);
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
      raise_value_error(std::string(what) + ": expected times in [start_time, end_time] = [" + float_repr(t0) + ", " +
                        float_repr(t1) + "], got " + float_repr(tp[i]));
    }
  }
  return std::move(times);
}

/// The control operand of _so3_bspline_evaluate (the Python class's own
/// array, made by _so3_bspline_new): checked before it is read, so that the
/// private function given another array raises instead of reading past it.
template <typename Group>
void check_control(const py::array& control, const char* function) {
  constexpr int rows = Names<Group>::rows;
  if (control.ndim() != 3 || control.shape(0) < 4 || control.shape(1) != rows || control.shape(2) != rows ||
      !control.dtype().is(py::dtype::of<double>())) {
    raise_value_error(std::string(function) + ": expected control of shape (n, " + std::to_string(rows) + ", " +
                      std::to_string(rows) + "), n >= 4, float64, got " +
                      shape_string(control.shape(), static_cast<int>(control.ndim())) + " " +
                      std::string(py::str(control.dtype())));
  }
}

template <typename Group>
void bind_one(py::module_& m) {
  constexpr int rows = Names<Group>::rows;
  const std::string lower = rows == 3 ? "so3" : "se3";
  static const std::string new_name = "_" + lower + "_bspline_new", evaluate_name = "_" + lower + "_bspline_evaluate";
  const std::string what = rows == 3 ? "rotations" : "rigid motions";

  m.def(
      new_name.c_str(),
      [](RealLike start_time, RealLike spacing, ArrayLike control) {
        BSpline<Group> s;
        s.start_time = to_finite_real(start_time.obj, label<Group>("start_time").c_str());
        s.spacing = to_finite_real(spacing.obj, label<Group>("spacing").c_str());
        if (!(s.spacing > 0))
          raise_value_error(label<Group>("spacing") + ": expected a positive spacing (> 0), got " +
                            float_repr(s.spacing));
        s.control = control_array(control_of<Group>(control.obj));
        return py::make_tuple(s.start_time, s.spacing, s.control);
      },
      py::arg("start_time"), py::arg("spacing"), py::arg("control"),
      (std::string("The checked arguments of ") + Names<Group>::cls +
       "(start_time, spacing, control): (start_time, spacing, the control elements as a new read-only (N, " +
       std::to_string(rows) + ", " + std::to_string(rows) + ") float64 array of " + what + "), or the " +
       Names<Group>::cls + " constructor's ValueError / TypeError. A private function of chasles." + Names<Group>::cls +
       " (python/chasles/_bspline.py).")
          .c_str());

  using ufunc::Core;
  using Control = Core<ufunc::upto<ufunc::unbounded>, rows, rows>;
  constexpr int dof = Names<Group>::dof;
  static const std::string element_name = "_" + lower + "_bspline", rates_name = "_" + lower + "_bspline_rates";
  const std::string operands = std::string("\n\nOperands (float64): start_time (), spacing () > 0, control (n, ") +
                               std::to_string(rows) + ", " + std::to_string(rows) +
                               "), n >= 4 (NaN results otherwise), t (), clamped to [start_time, end_time]. "
                               "A private ufunc of chasles." +
                               Names<Group>::cls + ".";
  const py::object u_element = ufunc::def_ufunc<Core<rows, rows>(Core<>, Core<>, Control, Core<>), ufunc::Float64>(
      m, element_name.c_str(), "start_time, spacing, control, t", "The spline's element at t." + operands,
      ufunc::model<3>(BSplineOf<Group>()), Element<Group>());
  const py::object u_rates =
      ufunc::def_ufunc<std::tuple<Core<rows, rows>, Core<dof>, Core<dof>>(Core<>, Core<>, Control, Core<>),
                       ufunc::Float64>(m, rates_name.c_str(), "start_time, spacing, control, t",
                                       "The spline's element, body velocity and body acceleration at t." + operands,
                                       ufunc::model<3>(BSplineOf<Group>()), Rates<Group>());
  // The labels of the methods' errors, by order.
  static const std::string whats[3] = {std::string(Names<Group>::cls) + "(t)",
                                       std::string(Names<Group>::cls) + ".body_velocity(t)",
                                       std::string(Names<Group>::cls) + ".body_acceleration(t)"};
  m.def(
      evaluate_name.c_str(),
      [u_element, u_rates](double start_time, double spacing, const py::array& control, ArrayLike t,
                           int order) -> Returns<py::array> {
        if (order < 0 || order > 2)
          raise_value_error(evaluate_name + ": expected order 0, 1 or 2, got " + std::to_string(order));
        check_control<Group>(control, evaluate_name.c_str());
        if (!(std::isfinite(start_time) && spacing > 0 && spacing <= std::numeric_limits<double>::max()))
          raise_value_error(evaluate_name + ": expected a finite start_time and a finite spacing > 0, got " +
                            float_repr(start_time) + " and " + float_repr(spacing));
        const std::string& what = whats[order];
        BSpline<Group> s;
        s.start_time = start_time;
        s.spacing = spacing;
        s.control = control;
        const py::object times = times_operand(s, t.obj, what.c_str());
        const py::float_ t0(start_time), dt(spacing);
        const py::object u = order == 0 ? u_element : u_rates;
        const py::object r = call_ufunc<4>(u.ptr(), what.c_str(), {t0.ptr(), dt.ptr(), control.ptr(), times.ptr()});
        return {order == 0 ? r : py::object(py::tuple(r)[static_cast<std::size_t>(order)])};
      },
      py::arg("start_time"), py::arg("spacing"), py::arg("control"), py::arg("t"), py::arg("order"),
      (std::string("The methods of ") + Names<Group>::cls +
       " at the times t: the elements (order 0), body velocities (1) or body accelerations (2) of the spline of "
       "start_time, spacing and control (from " +
       new_name +
       "), the times checked to lie in [start_time, "
       "end_time]. A private function of chasles." +
       Names<Group>::cls + " (python/chasles/_bspline.py).")
          .c_str());
}

}  // namespace

void bind_bspline(py::module_& m) {
  bind_one<SO3d>(m);
  bind_one<SE3d>(m);
}

}  // namespace chasles_py
