// chasles._core: the kernels behind chasles.so3_align, se3_align and
// sim3_align (python/chasles/_align.py): the C++ alignments
// (chasles/align.hpp) read straight from the caller's (N, 3) float64
// buffers, without the GIL. A reduction over the rows, so not a gufunc. No
// mathematics here, and no policy: the status goes back to the Python
// function, which says what it means.
#include <string>

#include <Eigen/Core>

#include <chasles/align.hpp>
#include <chasles/se3.hpp>
#include <chasles/sim3.hpp>
#include <chasles/so3.hpp>

#include "bindings.hpp"
#include "convert.hpp"

namespace chasles_py {

namespace {

using Rows3 = py::array_t<double, py::array::c_style | py::array::forcecast>;

/// The rows of a C-contiguous (N, 3) float64 buffer as 3-vectors (a forward
/// iterator as align.hpp reads one).
struct RowIterator {
  const double* p;
  Eigen::Map<const Eigen::Vector3d> operator*() const noexcept { return Eigen::Map<const Eigen::Vector3d>(p); }
  RowIterator& operator++() noexcept {
    p += 3;
    return *this;
  }
  bool operator!=(const RowIterator& o) const noexcept { return p != o.p; }
};

const char* status_name(chasles::AlignStatus s) {
  switch (s) {
    case chasles::AlignStatus::ok: return "ok";
    case chasles::AlignStatus::not_determined: return "not_determined";
    case chasles::AlignStatus::too_few: return "too_few";
    case chasles::AlignStatus::weights_not_valid: return "weights_not_valid";
    case chasles::AlignStatus::not_finite: return "not_finite";
    case chasles::AlignStatus::zero_primary: return "zero_primary";
  }
  return "unknown";
}

/// The shapes this function reads: a and b (N, 3) alike, weights (N,) or
/// None (the Python caller has checked them; checked again here, or the
/// loops would read past a buffer).
void check_shapes(const char* name, const Rows3& a, const Rows3& b, const py::object& weights) {
  const auto shape_of = [](const py::array& x) {
    return shape_string(reinterpret_cast<const Py_intptr_t*>(x.shape()), static_cast<int>(x.ndim()));
  };
  if (a.ndim() != 2 || a.shape(1) != 3 || b.ndim() != 2 || b.shape(0) != a.shape(0) || b.shape(1) != 3)
    throw py::value_error(std::string(name) + "(a, b): expected shapes (N, 3) and (N, 3), got " + shape_of(a) +
                          " and " + shape_of(b));
  if (!weights.is_none()) {
    const Rows3 w = weights.cast<Rows3>();
    if (w.ndim() != 1 || w.shape(0) != a.shape(0))
      throw py::value_error(std::string(name) + "(weights): expected shape (" + std::to_string(a.shape(0)) +
                            ",), got " + shape_of(w));
  }
}

/// Runs f(first, last, b_first[, weights]) without the GIL.
template <typename Result, typename F>
Result run(const Rows3& a, const Rows3& b, const py::object& weights, F f) {
  const RowIterator first{a.data()}, last{a.data() + 3 * a.shape(0)}, b_first{b.data()};
  if (weights.is_none()) {
    py::gil_scoped_release release;
    return f(first, last, b_first, chasles::detail::UnitWeights<double>());
  }
  const Rows3 w = weights.cast<Rows3>();
  const double* w_first = w.data();
  py::gil_scoped_release release;
  return f(first, last, b_first, w_first);
}

/// so3_align: (rotation (3, 3), rssd, signed singular values (3,),
/// sensitivity (3, 3) or None, status).
py::tuple so3_align_of(const Rows3& a, const Rows3& b, const py::object& weights) {
  check_shapes("_so3_align", a, b, weights);
  const auto r = run<chasles::AlignResult<chasles::SO3d>>(
      a, b, weights,
      [](auto first, auto last, auto b_first, auto w) { return chasles::so3_align(first, last, b_first, w); });
  const py::object sensitivity = r.has_sensitivity ? py::object(mat_out<3, 3>(r.sensitivity)) : py::none();
  return py::make_tuple(mat_out<3, 3>(r.transform.matrix()), r.rssd, vec_out<3>(r.singular_values), sensitivity,
                        status_name(r.status));
}

/// se3_align / sim3_align: (matrix (4, 4), rssd, signed singular values (3,), status).
template <typename Group>
py::tuple point_align_of(const Rows3& a, const Rows3& b, const py::object& weights) {
  constexpr bool similarity = std::is_same<Group, chasles::Sim3d>::value;
  check_shapes(similarity ? "_sim3_align" : "_se3_align", a, b, weights);
  const auto r = run<chasles::AlignResult<Group>>(a, b, weights, [](auto first, auto last, auto b_first, auto w) {
    if constexpr (similarity) {
      return chasles::sim3_align(first, last, b_first, w);
    } else {
      return chasles::se3_align(first, last, b_first, w);
    }
  });
  return py::make_tuple(mat_out<4, 4>(Eigen::Matrix4d(r.transform.matrix())), r.rssd, vec_out<3>(r.singular_values),
                        status_name(r.status));
}

}  // namespace

void bind_align(py::module_& m) {
  m.def("_so3_align", &so3_align_of, py::arg("a"), py::arg("b"), py::arg("weights"),
        "The C++ so3_align behind chasles.so3_align, on (N, 3) float64 vectors a, b and (N,) weights or None: "
        "(rotation, rssd, singular_values, sensitivity or None, status).");
  m.def("_se3_align", &point_align_of<chasles::SE3d>, py::arg("a"), py::arg("b"), py::arg("weights"),
        "The C++ se3_align behind chasles.se3_align, on (N, 3) float64 points a, b and (N,) weights or None: "
        "(matrix, rssd, singular_values, status).");
  m.def("_sim3_align", &point_align_of<chasles::Sim3d>, py::arg("a"), py::arg("b"), py::arg("weights"),
        "The C++ sim3_align behind chasles.sim3_align, on (N, 3) float64 points a, b and (N,) weights or None: "
        "(matrix, rssd, singular_values, status).");
}

}  // namespace chasles_py
