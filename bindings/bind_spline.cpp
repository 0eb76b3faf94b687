// chasles._core: the interpolating splines behind chasles.SO3Spline and
// chasles.SE3Spline (include/chasles/spline.hpp). The public classes are thin
// Python classes (python/chasles/_spline.py) that check the arguments, hold the
// spline's numbers as arrays and shape the results: the key times (n,), the
// keys (n, D, D) and the coefficients of each segment's cubic (n, 3 DoF: row i
// is c1, c2, c3 of segment i; the last row is unused). _so3_spline_fit and
// _se3_spline_fit compute the coefficients once, at construction; the private
// gufuncs evaluate them at times (the broadcast operand), registered by
// def_ufunc (ufunc.hpp) with the spline as the model of its three arrays.
// The model is a view of the arrays (their maps), not a copy: an evaluation
// reads the times of its binary search, one key and one row of
// coefficients, O(log n), whatever n (a copy of the n keys per call made
// one evaluation O(n): 11 ms at 10^5 keys):
//
//   _so3_spline        (n),(n,3,3),(n,9),()->(3,3)              the element
//   _so3_spline_rates  (n),(n,3,3),(n,9),()->(3,3),(3),(3)      and its body velocity, acceleration
//   _se3_spline        (n),(n,4,4),(n,18),()->(4,4)
//   _se3_spline_rates  (n),(n,4,4),(n,18),()->(4,4),(6),(6)
#include <chasles/spline.hpp>

#include <climits>
#include <cstdio>
#include <limits>
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

template <typename Group>
struct Traits;
template <>
struct Traits<SO3d> {
  static constexpr int D = 3;
  static constexpr const char* name = "SO3Spline(rotations)";
  static constexpr const char* times = "SO3Spline(times)";
  static constexpr const char* fit = "_so3_spline_fit";
};
template <>
struct Traits<SE3d> {
  static constexpr int D = 4;
  static constexpr const char* name = "SE3Spline(poses)";
  static constexpr const char* times = "SE3Spline(times)";
  static constexpr const char* fit = "_se3_spline_fit";
};

/// The ValueError of a fit refused for its times: which step, and why.
[[noreturn]] void raise_times_error(const char* what, chasles::SplineStatus status, const double* t, py::ssize_t n) {
  using chasles::Thresholds;
  const double lo = Thresholds<double>::spline_min_step, hi = Thresholds<double>::spline_max_step;
  for (py::ssize_t i = 0; i + 1 < n; ++i) {
    const double h = t[i + 1] - t[i];
    const std::string at = "times[" + std::to_string(i + 1) + "] - times[" + std::to_string(i) + "] = ";
    const std::string values = " (times[" + std::to_string(i) + "] = " + float_repr(t[i]) + ", times[" +
                               std::to_string(i + 1) + "] = " + float_repr(t[i + 1]) + ")";
    if (status == chasles::SplineStatus::times_not_increasing &&
        !(h > 0 && h < std::numeric_limits<double>::infinity()))
      raise_value_error(std::string(what) + ": expected strictly increasing finite times, got " + at + float_repr(h) +
                        values);
    if (status == chasles::SplineStatus::step_out_of_range && !(h >= lo && h <= hi))
      raise_value_error(std::string(what) + ": expected time steps between " + float_repr(lo) + " and " +
                        float_repr(hi) +
                        " (the cubics' coefficients per unit of time, ~D/h^3, and the accelerations, ~D/h^2, "
                        "leave float64's range beyond), got " +
                        at + float_repr(h) + values);
  }
  raise_value_error(std::string(what) + ": the spline could not be fitted");
}

/// times: (n,) strictly increasing and finite, keys: (n, D, D), both checked
/// by the Python caller except that the keys are rotations / rigid motions
/// and the time steps within [spline_min_step, spline_max_step], which are
/// checked here; the shapes are checked again (a private function given
/// arrays that disagree raises, it does not read past one). Returns the
/// coefficients (n, 3 DoF).
template <typename Group>
py::array fit(const CArray& times, const CArray& keys, bool natural) {
  constexpr int D = Traits<Group>::D, DoF = Group::DoF;
  const char* name = Traits<Group>::name;
  if (times.ndim() != 1 || keys.ndim() != 3 || times.shape(0) < 2 || keys.shape(0) != times.shape(0) ||
      keys.shape(1) != D || keys.shape(2) != D || times.shape(0) > INT_MAX) {
    raise_value_error(std::string(Traits<Group>::fit) + ": expected times of shape (n,) and keys of shape (n, " +
                      std::to_string(D) + ", " + std::to_string(D) + "), 2 <= n <= " + std::to_string(INT_MAX) +
                      ", got times " + shape_string(times.shape(), static_cast<int>(times.ndim())) + " and keys " +
                      shape_string(keys.shape(), static_cast<int>(keys.ndim())));
  }
  const py::ssize_t n = times.shape(0);
  const double* d = keys.data();
  const double tolerance = chasles::Thresholds<double>::rotation_tolerance;
  std::vector<Group> key;
  for (py::ssize_t i = 0; i < n; ++i) {
    const Eigen::Map<const Eigen::Matrix<double, D, D, Eigen::RowMajor>> M(d + i * D * D);
    double defect = SO3d::rotation_defect(M.template topLeftCorner<3, 3>());
    if constexpr (D == 4) defect = SE3d::transform_defect(Eigen::Matrix4d(M));
    if (!(defect <= tolerance)) {
      char text[400];
      std::snprintf(text, sizeof text,
                    "%s: key %zd is not a %s: defect = %.3g > %.3g (project it first: %s.from_matrix_projected)", name,
                    static_cast<Py_ssize_t>(i), D == 3 ? "rotation" : "rigid motion [[R, p], [0, 0, 0, 1]]", defect,
                    tolerance, D == 3 ? "SO3" : "SE3");
      throw py::value_error(text);
    }
    key.push_back(Group::from_matrix_unchecked(Eigen::Matrix<double, D, D>(M)));
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
    char text[400];
    std::snprintf(text, sizeof text,
                  "%s: the rates at the keys did not converge in %d iterations (consecutive keys nearly pi apart "
                  "in angle); add keys between them",
                  name, result.iterations);
    throw py::value_error(text);
  }
  if (result.status != chasles::SplineStatus::ok)
    raise_times_error(Traits<Group>::times, result.status, times.data(), n);
  const Py_intptr_t dims[2] = {static_cast<Py_intptr_t>(n), 3 * DoF};
  py::array_t<double> out = new_array(2, dims);
  double* o = array_data(out);
  for (py::ssize_t i = 0; i < n; ++i) {
    Eigen::Map<Eigen::Matrix<double, 3 * DoF, 1>> row(o + i * 3 * DoF);
    if (i + 1 < n) {
      const auto& c = segments[static_cast<std::size_t>(i)];
      row << c.c1, c.c2, c.c3;
    } else {
      row.setZero();
    }
  }
  return std::move(out);
}

/// The spline of the gufuncs' three array operands: their maps (numpy's
/// memory, with its strides), read where an evaluation needs them.
template <typename Group, typename Times, typename Keys, typename Coefficients>
struct SplineView {
  Times times;
  Keys keys;
  Coefficients c;

  Eigen::Index size() const noexcept { return times.size(); }
  bool valid() const noexcept { return size() >= 2 && size() <= INT_MAX; }
  /// The segment of t (binary search over the times) and its offset (held past the ends).
  int segment(double t, double& tau) const noexcept {
    const int i = chasles::spline_segment_index(static_cast<int>(size()), times, t);
    tau = chasles::spline_offset(t, double(times[i]), double(times[i + 1]));
    return i;
  }
  Group key(int i) const noexcept {
    constexpr int D = Traits<Group>::D;
    return Group::from_matrix_unchecked(Eigen::Matrix<double, D, D>(keys[i]));
  }
  chasles::SplineSegment<Group> cubic(int i) const noexcept {
    constexpr int DoF = Group::DoF;
    chasles::SplineSegment<Group> s;
    s.c1 = c.row(i).template segment<DoF>(0).transpose();
    s.c2 = c.row(i).template segment<DoF>(DoF).transpose();
    s.c3 = c.row(i).template segment<DoF>(2 * DoF).transpose();
    return s;
  }
};

template <typename Group>
struct SplineOf {
  template <typename Times, typename Keys, typename Coefficients>
  SplineView<Group, Times, Keys, Coefficients> operator()(const Times& times, const Keys& keys,
                                                          const Coefficients& c) const noexcept {
    return {times, keys, c};
  }
};

template <typename Group>
using Tangent = Eigen::Matrix<double, Group::DoF, 1>;

template <typename Group>
Group nan_element() {
  constexpr int D = Traits<Group>::D;
  return Group::from_matrix_unchecked(Eigen::Matrix<double, D, D>::Constant(std::numeric_limits<double>::quiet_NaN()));
}

/// The element at t: X_i exp(r(t - t_i)).
template <typename Group>
struct Element {
  template <typename Model>
  auto operator()(const Model& m, double t) const noexcept {
    const auto at = [&] {
      double tau;
      const int i = m.segment(t, tau);
      return chasles::spline_segment_element(m.key(i), m.cubic(i), tau);
    };
    const Group g = m.valid() ? at() : nan_element<Group>();
    if constexpr (Traits<Group>::D == 4)
      return g;
    else
      return g.matrix();
  }
};

/// The element, body velocity and body acceleration at t.
template <typename Group>
struct Rates {
  template <typename Model>
  auto operator()(const Model& m, double t) const noexcept {
    constexpr int D = Traits<Group>::D;
    if (!m.valid()) {
      const Tangent<Group> nan = Tangent<Group>::Constant(std::numeric_limits<double>::quiet_NaN());
      return std::tuple<Eigen::Matrix<double, D, D>, Tangent<Group>, Tangent<Group>>(nan_element<Group>().matrix(), nan,
                                                                                     nan);
    }
    double tau;
    const int i = m.segment(t, tau);
    const chasles::SplineSample<Group> s = chasles::spline_segment_sample(m.key(i), m.cubic(i), tau);
    return std::tuple<Eigen::Matrix<double, D, D>, Tangent<Group>, Tangent<Group>>(s.element.matrix(), s.velocity,
                                                                                   s.acceleration);
  }
};

template <typename Group>
void bind_one(py::module_& m, const char* fit_name, const char* element_name, const char* rates_name) {
  constexpr int D = Traits<Group>::D, DoF = Group::DoF;
  using Times = Core<upto<ufunc::unbounded>>;
  using Keys = Core<upto<ufunc::unbounded>, D, D>;
  using Coefficients = Core<upto<ufunc::unbounded>, 3 * DoF>;
  const std::string what = D == 3 ? "rotations" : "poses";
  m.def(
      fit_name, [](const CArray& times, const CArray& keys, bool natural) { return fit<Group>(times, keys, natural); },
      py::arg("times"), py::arg("keys"), py::arg("natural"),
      ("The coefficients (n, " + std::to_string(3 * DoF) +
       ") of the spline through checked (n,) float64 times and (n, " + std::to_string(D) + ", " + std::to_string(D) +
       ") " + what + " (row i: c1, c2, c3 of segment i; the last row zero).")
          .c_str());
  const std::string operands = "\n\nOperands (float64): times (n,), n >= 2 (NaN results below), keys (n, " +
                               std::to_string(D) + ", " + std::to_string(D) + "), coefficients (n, " +
                               std::to_string(3 * DoF) + ") from " + fit_name +
                               ", then t (), the time. A private ufunc of chasles." +
                               (D == 3 ? "SO3Spline" : "SE3Spline") + " (python/chasles/_spline.py).";
  ufunc::def_ufunc<Core<D, D>(Times, Keys, Coefficients, Core<>), ufunc::Float64>(
      m, element_name, "times, keys, coefficients, t", "The spline's element at t." + operands,
      ufunc::model<3>(SplineOf<Group>()), Element<Group>());
  ufunc::def_ufunc<std::tuple<Core<D, D>, Core<DoF>, Core<DoF>>(Times, Keys, Coefficients, Core<>), ufunc::Float64>(
      m, rates_name, "times, keys, coefficients, t",
      "The spline's element, body velocity and body acceleration at t." + operands, ufunc::model<3>(SplineOf<Group>()),
      Rates<Group>());
}

}  // namespace

void bind_spline(py::module_& m) {
  bind_one<SO3d>(m, "_so3_spline_fit", "_so3_spline", "_so3_spline_rates");
  bind_one<SE3d>(m, "_se3_spline_fit", "_se3_spline", "_se3_spline_rates");
}

}  // namespace chasles_py
