// chasles._core: angles and distances of rotations and rigid motions, and
// the map of random samples, as numpy generalized ufuncs
// (chasles/distance.hpp, chasles/random.hpp, SO3::angle), and the means
// behind python/chasles/_mean.py. No mathematics here: each kernel calls the
// C++ API on one element.
#include <cstdio>
#include <string>
#include <type_traits>
#include <vector>

#include <chasles/distance.hpp>
#include <chasles/mean.hpp>
#include <chasles/random.hpp>
#include <chasles/se3.hpp>
#include <chasles/so3.hpp>

#include "bindings.hpp"
#include "convert.hpp"
#include "ufunc.hpp"

namespace chasles_py {

namespace {

using ufunc::array_doc;
using ufunc::Core;
using ufunc::def_ufunc;
using ufunc::ScalarOf;
using SO3d = chasles::SO3<double>;
using SE3d = chasles::SE3<double>;

void bind_distances(py::module_& m) {
  def_ufunc<Core<>(Core<3, 3>)>(m, "so3_angle", "R",
                                array_doc(R"(Rotation angles of rotation matrices: theta = |log(R)| in [0, pi].

From the halves of the quaternion, theta = 2 atan2(|q_v|, |q_w|): a few
ulps near 0 and near pi, where acos((tr R - 1) / 2) loses half the digits.
scipy: ``Rotation.magnitude()``.

Args:
    R: array_like of shape (..., 3, 3): rotation matrices.

Returns:
    numpy.ndarray of shape (...): the angles, radians.)"),
                                [](const auto& R) {
                                  using T = ScalarOf<decltype(R)>;
                                  return chasles::SO3<T>::from_matrix_unchecked(R).angle();
                                });

  def_ufunc<Core<>(Core<3, 3>, Core<3, 3>)>(
      m, "so3_distance", "a, b", array_doc(R"(Geodesic distances of rotations: the angle of a^-1 b, in [0, pi].

d(a, b) = |log(a^T b)|, the bi-invariant (angular) distance: symmetric and
unchanged by d(g a, g b) and d(a g, b g). scipy:
``(a.inv() * b).magnitude()``.

Args:
    a: array_like of shape (..., 3, 3): rotation matrices.
    b: array_like of shape (..., 3, 3): rotation matrices.

Returns:
    numpy.ndarray of shape (...): the distances, radians, the batch shape
    being the broadcast of a's and b's.)"),
      [](const auto& a, const auto& b) {
        using T = ScalarOf<decltype(a)>;
        return chasles::distance(chasles::SO3<T>::from_matrix_unchecked(a), chasles::SO3<T>::from_matrix_unchecked(b));
      });

  def_ufunc<Core<2>(Core<4, 4>, Core<4, 4>)>(
      m, "se3_distance", "a, b", array_doc(R"(Distances of rigid motions: (rotation angle, translation distance).

[angle, translation] with angle = |log(R_a^T R_b)| in [0, pi] (so3_distance
of the rotations) and translation = |p_b - p_a|, the Euclidean distance
between the two frames' origins (equal to the length of the translation of
a^-1 b; not the v of log(a^-1 b), which depends on the rotation). SE(3) has
no bi-invariant metric, so the two are returned apart, for the caller to
weigh; both are unchanged by a change of the fixed frame, d(g a, g b).

Args:
    a: array_like of shape (..., 4, 4): homogeneous matrices.
    b: array_like of shape (..., 4, 4): homogeneous matrices.

Returns:
    numpy.ndarray of shape (..., 2): [angle (radians), translation
    distance], the batch shape being the broadcast of a's and b's.)"),
      [](const auto& a, const auto& b) {
        using T = ScalarOf<decltype(a)>;
        const chasles::SE3Distance<T> d =
            chasles::distance(chasles::SE3<T>::from_matrix_unchecked(a), chasles::SE3<T>::from_matrix_unchecked(b));
        return Eigen::Matrix<T, 2, 1>(d.angle, d.translation);
      });
}

void bind_sampling(py::module_& m) {
  def_ufunc<Core<3, 3>(Core<3>)>(
      m, "so3_from_uniforms", "u",
      array_doc(R"(Rotations of three uniforms each, by Shoemake's method (uniform rotations).

q = (sqrt(1 - u0) sin(2 pi u1), sqrt(1 - u0) cos(2 pi u1), sqrt(u0) sin(2 pi u2),
sqrt(u0) cos(2 pi u2)) (x, y, z, w), so that u uniform in [0, 1)^3 gives a
rotation uniform on SO(3) (the Haar measure): the map behind so3_random.

Args:
    u: array_like of shape (..., 3): numbers in [0, 1].

Returns:
    numpy.ndarray of shape (..., 3, 3): the rotation matrices.)"),
      [](const auto& u) {
        using T = ScalarOf<decltype(u)>;
        return chasles::so3_from_uniforms(Eigen::Matrix<T, 3, 1>(u)).matrix();
      });
}

std::string shape_of(const py::array& a) {
  return shape_string(reinterpret_cast<const Py_intptr_t*>(a.shape()), static_cast<int>(a.ndim()));
}

/// The mean of N elements stored as (N, D, D) row-major float64 and N
/// weights, checked by the Python caller (python/chasles/_mean.py) and again
/// here for what this function reads: the shapes (the elements' N and the
/// weights' must agree, or the loops would read past the weights), the
/// rotations and the weights (finite, >= 0, not all 0, as the C++ mean
/// reports them): (matrix, iterations, converged). A reduction over the
/// batch axis, so not a gufunc: the elements are copied into a vector, then
/// the C++ mean runs without the GIL.
template <typename Group, int D>
py::tuple mean_of(const py::array_t<double, py::array::c_style | py::array::forcecast>& elements,
                  const py::array_t<double, py::array::c_style | py::array::forcecast>& weights, bool geodesic,
                  int max_iterations) {
  const char* const name = D == 3 ? "_so3_mean" : "_se3_mean";
  if (elements.ndim() != 3 || elements.shape(1) != D || elements.shape(2) != D || elements.shape(0) < 1 ||
      weights.ndim() != 1 || weights.shape(0) != elements.shape(0)) {
    const std::string d = std::to_string(D);
    throw py::value_error(std::string(name) + "(matrices, weights): expected shapes (N, " + d + ", " + d +
                          ") with N >= 1 and (N,), got " + shape_of(elements) + " and " + shape_of(weights));
  }
  const py::ssize_t n = elements.shape(0);
  std::vector<Group> X;
  X.reserve(static_cast<std::size_t>(n));
  const double* d = elements.data();
  const double tolerance = chasles::Thresholds<double>::rotation_tolerance;
  for (py::ssize_t i = 0; i < n; ++i) {
    const Eigen::Map<const Eigen::Matrix<double, D, D, Eigen::RowMajor>> M(d + i * D * D);
    // The mean of matrices that are not rotations is not defined (and its
    // iteration need not converge): refused, as SO3.from_matrix refuses them.
    const double defect = SO3d::rotation_defect(M.template topLeftCorner<3, 3>());
    if (!(defect <= tolerance)) {
      char text[320];
      std::snprintf(text, sizeof text,
                    "%s(matrices): element %zd is not a rotation%s: defect max(|R^T R - I|, |det R - 1|) = %.3g > "
                    "%.3g (project it first: SO3.from_matrix_projected)",
                    D == 3 ? "so3_mean" : "se3_mean", static_cast<Py_ssize_t>(i), D == 3 ? "" : " block", defect,
                    tolerance);
      throw py::value_error(text);
    }
    X.push_back(Group::from_matrix_unchecked(Eigen::Matrix<double, D, D>(M)));
  }
  const double* w = weights.data();
  chasles::MeanResult<Group> r{Group(), 0, true, true};
  {
    py::gil_scoped_release release;
    if (geodesic) {
      r = chasles::geodesic_mean(X.begin(), X.end(), w, max_iterations);
    } else {
      r.mean = chasles::chordal_mean(X.begin(), X.end(), w);
      // weights that are not valid give the identity: only then is there something to ask
      if (r.mean.matrix() == Eigen::Matrix<double, D, D>::Identity())
        r.weights_valid = chasles::mean_weights_valid(X.begin(), X.end(), w);
    }
  }
  if (!r.weights_valid) throw py::value_error(std::string(name) + "(weights): expected finite weights >= 0, not all 0");
  return py::make_tuple(mat_out<D, D>(Eigen::Matrix<double, D, D>(r.mean.matrix())), r.iterations, r.converged);
}

void bind_means(py::module_& m) {
  m.def("_so3_mean", &mean_of<SO3d, 3>, py::arg("matrices"), py::arg("weights"), py::arg("geodesic"),
        py::arg("max_iterations"),
        "The C++ mean behind chasles.so3_mean, on checked (N, 3, 3) float64 rotations and (N,) weights: "
        "(mean, iterations, converged).");
  m.def("_se3_mean", &mean_of<SE3d, 4>, py::arg("matrices"), py::arg("weights"), py::arg("geodesic"),
        py::arg("max_iterations"),
        "The C++ mean behind chasles.se3_mean, on checked (N, 4, 4) float64 poses and (N,) weights: "
        "(mean, iterations, converged).");
}

}  // namespace

void bind_statistics(py::module_& m) {
  bind_distances(m);
  bind_sampling(m);
  bind_means(m);
}

}  // namespace chasles_py
