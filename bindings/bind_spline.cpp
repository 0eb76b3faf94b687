// chasles._core: the interpolating splines behind chasles.SO3Spline and
// chasles.SE3Spline (include/chasles/spline.hpp). The public classes are thin
// Python classes (python/chasles/_spline.py) that check the arguments, hold the
// spline's numbers as arrays and shape the results: the key times (n,), the
// keys (n, D, D) and the coefficients of each segment's cubic (n, 3 DoF: row i
// is c1, c2, c3 of segment i; the last row is unused). _so3_spline_fit and
// _se3_spline_fit compute the coefficients once, at construction; the private
// gufuncs evaluate them at times (the broadcast operand), registered by
// def_ufunc (ufunc.hpp) with the spline as the model of its three arrays:
//
//   _so3_spline        (n),(n,3,3),(n,9),()->(3,3)              the element
//   _so3_spline_rates  (n),(n,3,3),(n,9),()->(3,3),(3),(3)      and its body velocity, acceleration
//   _se3_spline        (n),(n,4,4),(n,18),()->(4,4)
//   _se3_spline_rates  (n),(n,4,4),(n,18),()->(4,4),(6),(6)
#include <chasles/spline.hpp>

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
};
template <>
struct Traits<SE3d> {
  static constexpr int D = 4;
  static constexpr const char* name = "SE3Spline(poses)";
};

/// times: (n,) strictly increasing and finite, keys: (n, D, D), both checked
/// by the Python caller except that the keys are rotations / rigid motions,
/// which is checked here. Returns the coefficients (n, 3 DoF).
template <typename Group>
py::array fit(const CArray& times, const CArray& keys, bool natural) {
  constexpr int D = Traits<Group>::D, DoF = Group::DoF;
  const char* name = Traits<Group>::name;
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
                    "%s: key %zd is not a %s: defect = %.3g > %.3g (project it first: %s.from_matrix_projected)",
                    name, static_cast<Py_ssize_t>(i), D == 3 ? "rotation" : "rigid motion [[R, p], [0, 0, 0, 1]]",
                    defect, tolerance, D == 3 ? "SO3" : "SE3");
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
  if (result.status != chasles::SplineStatus::ok) throw py::value_error(std::string(name) + ": times and keys were not checked");
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

/// The spline of the gufuncs' three array operands, in storage of its own
/// (the C++ spline views arrays of keys and segments).
template <typename Group>
struct SplineModel {
  std::vector<double> times;
  std::vector<Group> keys;
  std::vector<chasles::SplineSegment<Group>> segments;

  bool valid() const noexcept { return keys.size() >= 2; }
  chasles::Spline<Group> view() const noexcept {
    return chasles::Spline<Group>(static_cast<int>(keys.size()), times.data(), keys.data(), segments.data());
  }
};

template <typename Group>
struct SplineOf {
  template <typename Times, typename Keys, typename Coefficients>
  SplineModel<Group> operator()(const Times& times, const Keys& keys, const Coefficients& c) const noexcept {
    constexpr int D = Traits<Group>::D, DoF = Group::DoF;
    SplineModel<Group> m;
    const Eigen::Index n = times.size();
    m.times.resize(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i) {
      m.times[static_cast<std::size_t>(i)] = times(i);
      m.keys.push_back(Group::from_matrix_unchecked(Eigen::Matrix<double, D, D>(keys[i])));
    }
    for (Eigen::Index i = 0; i + 1 < n; ++i) {
      chasles::SplineSegment<Group> s;
      s.c1 = c.row(i).template segment<DoF>(0).transpose();
      s.c2 = c.row(i).template segment<DoF>(DoF).transpose();
      s.c3 = c.row(i).template segment<DoF>(2 * DoF).transpose();
      m.segments.push_back(s);
    }
    return m;
  }
};

template <typename Group>
using Tangent = Eigen::Matrix<double, Group::DoF, 1>;

template <typename Group>
Group nan_element() {
  constexpr int D = Traits<Group>::D;
  return Group::from_matrix_unchecked(
      Eigen::Matrix<double, D, D>::Constant(std::numeric_limits<double>::quiet_NaN()));
}

/// The element at t: X_i exp(r(t - t_i)).
template <typename Group>
struct Element {
  auto operator()(const SplineModel<Group>& m, double t) const noexcept {
    const Group g = m.valid() ? m.view().element(t) : nan_element<Group>();
    if constexpr (Traits<Group>::D == 4)
      return g;
    else
      return g.matrix();
  }
};

/// The element, body velocity and body acceleration at t.
template <typename Group>
struct Rates {
  auto operator()(const SplineModel<Group>& m, double t) const noexcept {
    constexpr int D = Traits<Group>::D;
    if (!m.valid()) {
      const Tangent<Group> nan = Tangent<Group>::Constant(std::numeric_limits<double>::quiet_NaN());
      return std::tuple<Eigen::Matrix<double, D, D>, Tangent<Group>, Tangent<Group>>(nan_element<Group>().matrix(),
                                                                                     nan, nan);
    }
    const chasles::SplineSample<Group> s = m.view()(t);
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
      ("The coefficients (n, " + std::to_string(3 * DoF) + ") of the spline through checked (n,) float64 times and (n, " +
       std::to_string(D) + ", " + std::to_string(D) + ") " + what +
       " (row i: c1, c2, c3 of segment i; the last row zero).")
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
      "The spline's element, body velocity and body acceleration at t." + operands,
      ufunc::model<3>(SplineOf<Group>()), Rates<Group>());
}

}  // namespace

void bind_spline(py::module_& m) {
  bind_one<SO3d>(m, "_so3_spline_fit", "_so3_spline", "_so3_spline_rates");
  bind_one<SE3d>(m, "_se3_spline_fit", "_se3_spline", "_se3_spline_rates");
}

}  // namespace chasles_py
