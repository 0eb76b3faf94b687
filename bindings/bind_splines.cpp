// chasles._core: the private functions behind the splines of python/chasles:
// SO3Spline and SE3Spline (_spline.py), the interpolating splines of
// include/chasles/spline.hpp, and SO3BSpline and SE3BSpline (_bspline.py),
// the uniform cumulative cubic B-splines of include/chasles/bspline.hpp. The
// public classes are Python classes that check the arguments, hold the
// spline's numbers as arrays and shape the results:
//
// - an interpolating spline: the key times (n,), the keys (n, D, D) and the
//   coefficients of each segment's cubic (n, 3 DoF: row i is c1, c2, c3 of
//   segment i; the last row is unused), computed once, at construction, by
//   _so3_spline_fit / _se3_spline_fit;
// - a B-spline: the start time, the spacing and the control elements as an
//   (N, D, D) array, checked and made by _so3_bspline_new / _se3_bspline_new.
//
// The private gufuncs evaluate them at times (the broadcast operand),
// registered by def_ufunc (ufunc.hpp) with the spline as the model of its
// three other operands. The model is a view of the arrays (their maps), not
// a copy: an evaluation reads the times of its binary search, one key and
// one row of coefficients, O(log n), or the four control elements of its
// segment, O(1), whatever n (a copy of the n keys per call made one
// evaluation O(n): 11 ms at 10^5 keys):
//
//   _so3_spline, _se3_spline                (n),(n,D,D),(n,3 DoF),()->(D,D)              the element
//   _so3_spline_rates, _se3_spline_rates    (n),(n,D,D),(n,3 DoF),()->(D,D),(DoF),(DoF)  and its rates
//   _so3_bspline, _se3_bspline              (),(),(n,D,D),()->(D,D)                      (t0, dt, control, t)
//   _so3_bspline_rates, _se3_bspline_rates  (),(),(n,D,D),()->(D,D),(DoF),(DoF)
//   _so3_bspline_jacobians, ...             (),(),(n,D,D),()->(D,D),(4 DoF^2),()     and d/d(control), segment
//
// with D = 3, DoF = 3 for SO(3) and D = 4, DoF = 6 for SE(3); the rates are the
// body velocity and the body acceleration.
#include <chasles/bspline.hpp>
#include <chasles/group_parts.hpp>
#include <chasles/se2.hpp>
#include <chasles/se23.hpp>
#include <chasles/sim3.hpp>
#include <chasles/so2.hpp>
#include <chasles/spline.hpp>

#include <array>
#include <climits>
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
using ufunc::Core;
using ufunc::upto;

using CArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// The size D of the group's matrices, the matrices, the tangents and what
/// a rates gufunc returns: element, body velocity, body acceleration.
template <typename Group>
constexpr int Dim = chasles::detail::matrix_size<Group>;
template <typename Group>
using Matrix = Eigen::Matrix<double, Dim<Group>, Dim<Group>>;
template <typename Group>
using Tangent = Eigen::Matrix<double, Group::DoF, 1>;
template <typename Group>
using Sample = std::tuple<Matrix<Group>, Tangent<Group>, Tangent<Group>>;

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();

/// "SO3" (the group's class) followed by `suffix`: "SO3Spline", "SE3BSpline(control)".
template <typename Group>
std::string named(const std::string& suffix) {
  return GroupNames<Group>::cls + suffix;
}

/// The defect the group's from_matrix checks (the rotation defect of a
/// rotation group, the transform defect of the others).
template <typename Group>
double defect_of(const Matrix<Group>& m) noexcept {
  if constexpr (chasles::detail::IsRotationGroup<Group>::value) {
    return Group::rotation_defect(m);
  } else {
    return Group::transform_defect(m);
  }
}

/// The results of a rates gufunc whose operands make no spline: NaN rates.
template <typename Group>
Sample<Group> nan_sample(const Matrix<Group>& element) {
  return {element, Tangent<Group>::Constant(not_a_number), Tangent<Group>::Constant(not_a_number)};
}

/// The ValueError of a fit refused for its times: which step, and why.
[[noreturn]] void raise_times_error(const std::string& what, chasles::SplineStatus status, const double* t,
                                    py::ssize_t n) {
  using chasles::Thresholds;
  const double lo = Thresholds<double>::spline_min_step, hi = Thresholds<double>::spline_max_step;
  for (py::ssize_t i = 0; i + 1 < n; ++i) {
    const double h = t[i + 1] - t[i];
    const std::string at = "times[" + std::to_string(i + 1) + "] - times[" + std::to_string(i) + "] = ";
    const std::string values = " (times[" + std::to_string(i) + "] = " + float_repr(t[i]) + ", times[" +
                               std::to_string(i + 1) + "] = " + float_repr(t[i + 1]) + ")";
    if (status == chasles::SplineStatus::times_not_increasing &&
        !(h > 0 && h < std::numeric_limits<double>::infinity()))
      raise_value_error(what + ": expected strictly increasing finite times, got " + at + float_repr(h) + values);
    if (status == chasles::SplineStatus::step_out_of_range && !(h >= lo && h <= hi))
      raise_value_error(what + ": expected time steps between " + float_repr(lo) + " and " + float_repr(hi) +
                        " (the cubics' coefficients per unit of time, ~D/h^3, and the accelerations, ~D/h^2, "
                        "leave float64's range beyond), got " +
                        at + float_repr(h) + values);
  }
  raise_value_error(what + ": the spline could not be fitted");
}

/// times: (n,) strictly increasing and finite, keys: (n, D, D), both checked
/// by the Python caller except that the keys are rotations / rigid motions
/// and the time steps within [spline_min_step, spline_max_step], which are
/// checked here; the shapes are checked again (a private function given
/// arrays that disagree raises, it does not read past one). Returns the
/// coefficients (n, 3 DoF).
template <typename Group>
py::array fit(const CArray& times, const CArray& keys, bool natural) {
  constexpr int D = Dim<Group>, DoF = Group::DoF;
  const std::string name = named<Group>(std::string("Spline(") + GroupNames<Group>::keys + ")");
  if (times.ndim() != 1 || keys.ndim() != 3 || times.shape(0) < 2 || keys.shape(0) != times.shape(0) ||
      keys.shape(1) != D || keys.shape(2) != D || times.shape(0) > INT_MAX) {
    raise_value_error("_" + std::string(GroupNames<Group>::prefix) + "_spline_fit: expected times of shape (n,) and " +
                      "keys of shape (n, " + std::to_string(D) + ", " + std::to_string(D) +
                      "), 2 <= n <= " + std::to_string(INT_MAX) + ", got times " +
                      shape_string(times.shape(), static_cast<int>(times.ndim())) + " and keys " +
                      shape_string(keys.shape(), static_cast<int>(keys.ndim())));
  }
  const py::ssize_t n = times.shape(0);
  const double* d = keys.data();
  const double tolerance = chasles::Thresholds<double>::rotation_tolerance;
  std::vector<Group> key;
  for (py::ssize_t i = 0; i < n; ++i) {
    const Matrix<Group> M = Eigen::Map<const Eigen::Matrix<double, D, D, Eigen::RowMajor>>(d + i * D * D);
    const double defect = defect_of<Group>(M);
    if (!(defect <= tolerance)) {
      raise_value_error(name + ": key " + std::to_string(i) + " is not a " + element_words<Group>() +
                        ": defect = " + short_float(defect) + " > " + short_float(tolerance) +
                        " (project it first: " + named<Group>(".from_matrix_projected)"));
    }
    key.push_back(Group::from_matrix_unchecked(M));
  }
  std::vector<chasles::SplineSegment<Group>> segments(static_cast<std::size_t>(n - 1));
  std::vector<chasles::SplineWork<Group>> work(static_cast<std::size_t>(n));
  chasles::SplineFit result{chasles::SplineStatus::ok, 0};
  {
    py::gil_scoped_release release;
    result = chasles::fit_spline(static_cast<int>(n), times.data(), key.data(), segments.data(), work.data(),
                                 natural ? chasles::SplineEnds::natural : chasles::SplineEnds::chord);
  }
  if (result.status == chasles::SplineStatus::not_converged) {
    raise_value_error(name + ": the rates at the keys did not converge in " + std::to_string(result.iterations) +
                      " iterations (consecutive keys nearly pi apart in angle); add keys between them");
  }
  if (result.status != chasles::SplineStatus::ok)
    raise_times_error(named<Group>("Spline(times)"), result.status, times.data(), n);
  const Py_intptr_t dims[2] = {static_cast<Py_intptr_t>(n), 3 * DoF};
  py::array_t<double> out = new_array(2, dims);
  Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3 * DoF, Eigen::RowMajor>> rows(array_data(out), n, 3 * DoF);
  rows.setZero();  // the last row
  for (std::size_t i = 0; i + 1 < static_cast<std::size_t>(n); ++i)
    rows.row(static_cast<Eigen::Index>(i)) << segments[i].c1.transpose(), segments[i].c2.transpose(),
        segments[i].c3.transpose();
  return std::move(out);
}

/// The interpolating spline of the gufuncs' three array operands: their
/// maps (numpy's memory, with its strides), read where an evaluation needs
/// them; NaN results unless 2 <= n <= INT_MAX.
template <typename Group, typename Times, typename Keys, typename Coefficients>
struct SplineView {
  Times times;
  Keys keys;
  Coefficients c;

  bool valid() const noexcept { return times.size() >= 2 && times.size() <= INT_MAX; }
  /// The segment of t (binary search over the times) and its offset (held past the ends).
  int segment(double t, double& tau) const noexcept {
    const int i = chasles::spline_segment_index(static_cast<int>(times.size()), times, t);
    tau = chasles::spline_offset(t, double(times[i]), double(times[i + 1]));
    return i;
  }
  static Group key_of(const Matrix<Group>& m) noexcept { return Group::from_matrix_unchecked(m); }
  /// The cubic of segment i: its coefficients c1, c2, c3, one row.
  chasles::SplineSegment<Group> cubic(int i) const noexcept {
    constexpr int DoF = Group::DoF;
    const auto row = c.row(i);
    return {row.template segment<DoF>(0), row.template segment<DoF>(DoF), row.template segment<DoF>(2 * DoF)};
  }
  /// The element at t: X_i exp(r(t - t_i)); an SE3 as itself (ufunc.hpp
  /// stores it in place), the others as their matrix.
  auto element(double t) const noexcept {
    const auto at = [&] {
      double tau;
      const int i = segment(t, tau);
      return chasles::spline_segment_element(key_of(keys[i]), cubic(i), tau);
    };
    const Group g = valid() ? at() : key_of(Matrix<Group>::Constant(not_a_number));
    if constexpr (std::is_same_v<Group, SE3d>)
      return g;
    else
      return g.matrix();
  }
  /// The element, body velocity and body acceleration at t.
  Sample<Group> rates(double t) const noexcept {
    if (!valid()) return nan_sample<Group>(key_of(Matrix<Group>::Constant(not_a_number)).matrix());
    double tau;
    const int i = segment(t, tau);
    const chasles::SplineSample<Group> s = chasles::spline_segment_sample(key_of(keys[i]), cubic(i), tau);
    return {s.element.matrix(), s.velocity, s.acceleration};
  }
};

/// The B-spline of the gufuncs' operands start_time, spacing and control:
/// the two times and the map of the control array (numpy's memory, with its
/// strides), read where an evaluation needs it; NaN results unless N >= 4
/// and the spacing is finite and > 0. The times are clamped to
/// [start_time, end_time] (the Python methods check them).
template <typename Group, typename Control>
struct BSplineView {
  double start_time, spacing;
  Control control;

  bool valid() const noexcept {
    return control.size() >= 4 && spacing > 0 && spacing <= std::numeric_limits<double>::max();
  }
  /// The segment of t and its four control elements.
  chasles::BSplineTime<double> locate(double t, std::array<Group, 4>& four) const noexcept {
    const chasles::BSplineTime<double> at =
        chasles::cubic_bspline_locate<double>(static_cast<std::ptrdiff_t>(control.size()), start_time, spacing, t);
    for (std::size_t j = 0; j < 4; ++j)
      four[j] = Group::from_matrix_unchecked(
          Matrix<Group>(control[static_cast<Eigen::Index>(at.segment) + static_cast<Eigen::Index>(j)]));
    return at;
  }
  Matrix<Group> element(double t) const noexcept {
    if (!valid()) return Matrix<Group>::Constant(not_a_number);
    std::array<Group, 4> four;
    const chasles::BSplineTime<double> at = locate(t, four);
    return chasles::cubic_bspline_segment(four.data(), at.u).matrix();
  }
  Sample<Group> rates(double t) const noexcept {
    if (!valid()) return nan_sample<Group>(Matrix<Group>::Constant(not_a_number));
    std::array<Group, 4> four;
    const chasles::BSplineTime<double> at = locate(t, four);
    const chasles::BSplinePoint<Group> p = chasles::cubic_bspline_segment_derivatives(four.data(), at.u, spacing);
    return {p.value.matrix(), p.velocity, p.acceleration};
  }
  /// The element at t, its Jacobians with respect to the four control
  /// elements of t's segment, flat (entry (k DoF + r) DoF + c is row r,
  /// column c of the k-th: a C-order (4, DoF, DoF) array), and the index of
  /// the segment's first control element (as a float).
  using Flat = Eigen::Matrix<double, 4 * Group::DoF * Group::DoF, 1>;
  std::tuple<Matrix<Group>, Flat, double> jacobians(double t) const noexcept {
    if (!valid()) return {Matrix<Group>::Constant(not_a_number), Flat::Constant(not_a_number), not_a_number};
    std::array<Group, 4> four;
    const chasles::BSplineTime<double> at = locate(t, four);
    const chasles::BSplineSegmentJacobians<Group> J = chasles::cubic_bspline_segment_jacobians(four.data(), at.u);
    constexpr int d = Group::DoF;
    Flat flat;
    for (int k = 0; k < 4; ++k)
      for (int r = 0; r < d; ++r)
        for (int c = 0; c < d; ++c) flat[(k * d + r) * d + c] = J.control[k](r, c);
    return {J.value.matrix(), flat, static_cast<double>(at.segment)};
  }
};

/// Registers the gufuncs `name` (the element at t) and `name`_rates (the
/// element, body velocity and body acceleration at t) of the spline made by
/// `make` from the operands A, B, C; `operands` ends their docstrings. numpy
/// keeps the names' pointers: `name` lives as long as the module.
template <typename Group, typename A, typename B, typename C, typename Make>
void def_gufuncs(py::module_& m, const char* name, const char* params, const std::string& operands, Make make) {
  constexpr int D = Dim<Group>, DoF = Group::DoF;
  static const std::string rates = std::string(name) + "_rates";
  ufunc::def_ufunc<Core<D, D>(A, B, C, Core<>), ufunc::Float64>(
      m, name, params, "The spline's element at t." + operands, ufunc::model<3>(make),
      [](const auto& spline, double t) noexcept { return spline.element(t); });
  ufunc::def_ufunc<std::tuple<Core<D, D>, Core<DoF>, Core<DoF>>(A, B, C, Core<>), ufunc::Float64>(
      m, rates.c_str(), params, "The spline's element, body velocity and body acceleration at t." + operands,
      ufunc::model<3>(make), [](const auto& spline, double t) noexcept { return spline.rates(t); });
}

/// A B-spline's control elements, a sequence of SO3 / SE3 objects or an
/// array-like of shape (N, 3, 3) / (N, 4, 4), N >= 4, as a new read-only
/// (N, D, D) float64 array. An object must be an initialized SO3 / SE3, a
/// matrix a rotation / rigid motion within the checked constructors'
/// tolerance.
///
/// `single`: the matrices came as float32 (or float16) numbers, which hold a
/// rotation only to float32's precision: they are checked with float32's
/// tolerance, sqrt(eps_float32) = 3.5e-4 (constants.hpp), and replaced by
/// the nearest rotation, so that the spline computes with a rotation in
/// float64. Other input is checked with float64's tolerance and kept as is.
template <typename Group>
py::array control_array(py::handle h) {
  constexpr int n = Dim<Group>;
  using RowMajor = Eigen::Matrix<double, n, n, Eigen::RowMajor>;
  const std::string what = named<Group>("BSpline(control)");
  const bool objects = (PyList_Check(h.ptr()) || PyTuple_Check(h.ptr())) && py::len(h) > 0 &&
                       is_bound_object(py::reinterpret_borrow<py::sequence>(h)[0]);
  bool single = false;
  if (!objects && npy().PyArray_Check_(h.ptr())) {
    const py::dtype dt = py::reinterpret_borrow<py::array>(h).dtype();
    single = dt.kind() == 'f' && dt.itemsize() <= 4;
  }
  const py::array a = objects ? py::array() : as_float64_array(h, what.c_str());
  if (!objects && (a.ndim() != 3 || a.shape(1) != n || a.shape(2) != n)) {
    raise_value_error(what + ": expected shape (N, " + std::to_string(n) + ", " + std::to_string(n) +
                      ") or a sequence of " + named<Group>(", got ") +
                      shape_string(a.shape(), static_cast<int>(a.ndim())));
  }
  const CArray c = objects ? CArray() : CArray::ensure(a);
  const py::ssize_t count = objects ? static_cast<py::ssize_t>(py::len(h)) : c.shape(0);
  const Py_intptr_t dims[3] = {static_cast<Py_intptr_t>(count), n, n};
  py::array_t<double> out = new_array(3, dims);
  for (py::ssize_t i = 0; i < count; ++i) {
    Eigen::Map<RowMajor> element(array_data(out) + i * n * n);
    if (objects) {
      const py::handle x = py::reinterpret_borrow<py::sequence>(h)[static_cast<std::size_t>(i)];
      py::detail::make_caster<Obj<Group>> caster;
      if (!caster.load(x, false))
        raise_type_error(what + ": element " + std::to_string(i) + " is a " + type_name(x) + ", expected an " +
                         named<Group>(" (a sequence of them, or an array of matrices)"));
      element = (*static_cast<Obj<Group>&>(caster)).matrix();
      continue;
    }
    const Matrix<Group> A = Eigen::Map<const RowMajor>(c.data() + i * n * n);
    const double tolerance = single ? double(chasles::Thresholds<float>::rotation_tolerance)
                                    : chasles::Thresholds<double>::rotation_tolerance;
    std::optional<Group> g = Group::from_matrix(A, tolerance);
    if (!g) {
      const double defect = defect_of<Group>(A);
      raise_value_error(what + ": element " + std::to_string(i) + " is not a " + element_words<Group>() + " (defect " +
                        short_float(defect) + "); project it first (" + named<Group>(".from_matrix_projected)"));
    }
    element = (single ? Group::from_matrix_projected(A) : *g).matrix();
  }
  if (count < 4)
    raise_value_error(what + ": a cubic B-spline needs N >= 4 control elements, got " + std::to_string(count));
  out.attr("flags").attr("writeable") = false;
  return std::move(out);
}

template <typename Group>
void bind_one(py::module_& m) {
  constexpr int D = Dim<Group>, DoF = Group::DoF;
  constexpr auto n = upto<ufunc::unbounded>;  // the number of keys, or of control elements
  const std::string d = std::to_string(D), k = std::to_string(3 * DoF), cls = named<Group>("Spline");
  const std::string bcls = named<Group>("BSpline"), lower = GroupNames<Group>::prefix;
  static const std::string spline = "_" + lower + "_spline", bspline = "_" + lower + "_bspline";

  m.def((spline + "_fit").c_str(), &fit<Group>, py::arg("times"), py::arg("keys"), py::arg("natural"),
        ("The coefficients (n, " + k + ") of the spline through checked (n,) float64 times and (n, " + d + ", " + d +
         ") " + GroupNames<Group>::keys + " (row i: c1, c2, c3 of segment i; the last row zero).")
            .c_str());
  def_gufuncs<Group, Core<n>, Core<n, D, D>, Core<n, 3 * DoF>>(
      m, spline.c_str(), "times, keys, coefficients, t",
      "\n\nOperands (float64): times (n,), n >= 2 (NaN results below), keys (n, " + d + ", " + d +
          "), coefficients (n, " + k + ") from " + spline + "_fit, then t (), the time. A private ufunc of chasles." +
          cls + " (python/chasles/_spline.py).",
      [](const auto& times, const auto& keys, const auto& c) {
        return SplineView<Group, std::decay_t<decltype(times)>, std::decay_t<decltype(keys)>,
                          std::decay_t<decltype(c)>>{times, keys, c};
      });

  m.def((bspline + "_new").c_str(),
        [](RealLike start_time, RealLike spacing, ArrayLike control) {
          const double t0 = to_finite_real(start_time.obj, named<Group>("BSpline(start_time)").c_str());
          const std::string spacing_label = named<Group>("BSpline(spacing)");
          const double dt = to_finite_real(spacing.obj, spacing_label.c_str());
          if (!(dt > 0))
            raise_value_error(spacing_label + ": expected a positive spacing (> 0), got " + float_repr(dt));
          return py::make_tuple(t0, dt, control_array<Group>(control.obj));
        },
        py::arg("start_time"), py::arg("spacing"), py::arg("control"),
        ("The checked arguments of " + bcls +
         "(start_time, spacing, control): (start_time, spacing, the control elements as a new read-only (N, " + d +
         ", " + d + ") float64 array of " + GroupNames<Group>::keys + "), or the " + bcls +
         " constructor's ValueError / TypeError. A private function of chasles." + bcls +
         " (python/chasles/_bspline.py).")
            .c_str());
  const auto make_bspline = [](double start_time, double spacing, const auto& control) {
    return BSplineView<Group, std::decay_t<decltype(control)>>{start_time, spacing, control};
  };
  const std::string bspline_operands =
      "\n\nOperands (float64): start_time (), spacing () > 0, control (n, " + d + ", " + d +
      "), n >= 4 (NaN results otherwise), t (), clamped to [start_time, end_time]. A private ufunc of chasles." + bcls +
      ".";
  def_gufuncs<Group, Core<>, Core<>, Core<n, D, D>>(m, bspline.c_str(), "start_time, spacing, control, t",
                                                    bspline_operands, make_bspline);
  static const std::string jacobians = bspline + "_jacobians";
  ufunc::def_ufunc<std::tuple<Core<D, D>, Core<4 * DoF * DoF>, Core<>>(Core<>, Core<>, Core<n, D, D>, Core<>),
                   ufunc::Float64>(
      m, jacobians.c_str(), "start_time, spacing, control, t",
      "The spline's element at t, its Jacobians with respect to the four control elements of t's segment (right "
      "perturbations; flat: reshape to (4, DoF, DoF)) and the index of the segment's first control element (a "
      "float), for " +
          bcls + ".fit." + bspline_operands,
      ufunc::model<3>(make_bspline), [](const auto& spline, double t) noexcept { return spline.jacobians(t); });
}

}  // namespace

void bind_splines(py::module_& m) {
  bind_one<SO3d>(m);
  bind_one<SE3d>(m);
  bind_one<chasles::SO2d>(m);
  bind_one<chasles::SE2d>(m);
  bind_one<chasles::Sim3d>(m);
  bind_one<chasles::SE23d>(m);
}

}  // namespace chasles_py
