// chasles._core: the fitted interpolating splines behind chasles.SO3Spline and
// chasles.SE3Spline (include/chasles/spline.hpp). The public classes are thin
// Python classes (python/chasles/_spline.py) that check the arguments and shape
// the results; these private cores own the storage the C++ spline views (times,
// keys, segments), fit once at construction and evaluate a whole float64 array
// of times in one C++ loop without the GIL.
#include <chasles/spline.hpp>

#include <cstdio>
#include <vector>

#include "bindings.hpp"
#include "convert.hpp"

namespace chasles_py {

namespace {

using chasles::SE3d;
using chasles::SO3d;

using CArray = py::array_t<double, py::array::c_style | py::array::forcecast>;

template <typename Group, int D>
class SplineCore {
 public:
  static constexpr int DoF = Group::DoF;
  using Tangent = Eigen::Matrix<double, DoF, 1>;

  /// times: (N,) strictly increasing and finite, keys: (N, D, D), both checked by the Python caller except
  /// that the keys are rotations / rigid motions, which is checked here.
  SplineCore(const CArray& times, const CArray& keys, bool natural, const char* name) {
    const py::ssize_t n = times.shape(0);
    const double* d = keys.data();
    const double tolerance = chasles::Thresholds<double>::rotation_tolerance;
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
      keys_.push_back(Group::from_matrix_unchecked(Eigen::Matrix<double, D, D>(M)));
    }
    times_.assign(times.data(), times.data() + n);
    segments_.resize(static_cast<std::size_t>(n - 1));
    std::vector<chasles::SplineWork<Group>> work(static_cast<std::size_t>(n));
    chasles::SplineFit fit{chasles::SplineStatus::ok, 0};
    {
      py::gil_scoped_release release;
      fit = chasles::fit_spline(static_cast<int>(n), times_.data(), keys_.data(), segments_.data(), work.data(),
                                natural ? chasles::SplineEnds::natural : chasles::SplineEnds::chord);
    }
    iterations_ = fit.iterations;
    if (fit.status == chasles::SplineStatus::not_converged) {
      char text[400];
      std::snprintf(text, sizeof text,
                    "%s: the rates at the keys did not converge in %d iterations (consecutive keys nearly pi apart "
                    "in angle); add keys between them",
                    name, fit.iterations);
      throw py::value_error(text);
    }
    if (fit.status != chasles::SplineStatus::ok) throw py::value_error(std::string(name) + ": times and keys were not checked");
  }

  /// order 0: elements (..., D, D); 1: body velocities (..., DoF); 2: body accelerations (..., DoF).
  py::array evaluate(const CArray& t, int order) const {
    std::vector<Py_intptr_t> shape(t.shape(), t.shape() + t.ndim());
    if (order == 0) {
      shape.push_back(D);
      shape.push_back(D);
    } else {
      shape.push_back(DoF);
    }
    py::array_t<double> out = new_array(static_cast<int>(shape.size()), shape.data());
    double* o = array_data(out);
    const double* ts = t.data();
    const py::ssize_t m = t.size();
    {
      py::gil_scoped_release release;
      const chasles::Spline<Group> spline = view();
      for (py::ssize_t k = 0; k < m; ++k) {
        if (order == 0) {
          Eigen::Map<Eigen::Matrix<double, D, D, Eigen::RowMajor>>(o + k * D * D) = spline.element(ts[k]).matrix();
        } else {
          const chasles::SplineSample<Group> s = spline(ts[k]);
          Eigen::Map<Tangent>(o + k * DoF) = order == 1 ? s.velocity : s.acceleration;
        }
      }
    }
    return std::move(out);
  }

  py::array keys() const {
    const Py_intptr_t dims[3] = {static_cast<Py_intptr_t>(keys_.size()), D, D};
    py::array_t<double> out = new_array(3, dims);
    double* o = array_data(out);
    for (std::size_t i = 0; i < keys_.size(); ++i)
      Eigen::Map<Eigen::Matrix<double, D, D, Eigen::RowMajor>>(o + i * D * D) = keys_[i].matrix();
    return std::move(out);
  }

  int iterations() const { return iterations_; }

 private:
  chasles::Spline<Group> view() const {
    return chasles::Spline<Group>(static_cast<int>(keys_.size()), times_.data(), keys_.data(), segments_.data());
  }

  std::vector<double> times_;
  std::vector<Group> keys_;
  std::vector<chasles::SplineSegment<Group>> segments_;
  int iterations_ = 0;
};

template <typename Group, int D>
void bind_core(py::module_& m, const char* name, const char* doc, const char* public_name) {
  using Core = SplineCore<Group, D>;
  py::class_<Core>(m, name, doc)
      .def(py::init([public_name](const CArray& times, const CArray& keys, bool natural) {
             return new Core(times, keys, natural, public_name);
           }),
           py::arg("times"), py::arg("keys"), py::arg("natural"))
      .def("evaluate", &Core::evaluate, py::arg("t"), py::arg("order"),
           "Elements (order 0), body velocities (1) or body accelerations (2) at a float64 array of times.")
      .def("keys", &Core::keys, "The key elements as an (N, D, D) array.")
      .def_property_readonly("iterations", &Core::iterations, "Fixed-point iterations the fit took.");
}

}  // namespace

void bind_spline(py::module_& m) {
  bind_core<SO3d, 3>(m, "_SO3SplineCore",
                     "The fitted C++ spline behind chasles.SO3Spline: checked (N,) float64 times and (N, 3, 3) "
                     "rotations.",
                     "SO3Spline(rotations)");
  bind_core<SE3d, 4>(m, "_SE3SplineCore",
                     "The fitted C++ spline behind chasles.SE3Spline: checked (N,) float64 times and (N, 4, 4) "
                     "poses.",
                     "SE3Spline(poses)");
}

}  // namespace chasles_py
