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
#include <chasles/lie_group.hpp>
#include <chasles/mean.hpp>
#include <chasles/random.hpp>
#include <chasles/se2.hpp>
#include <chasles/se23.hpp>
#include <chasles/se3.hpp>
#include <chasles/sim3.hpp>
#include <chasles/so2.hpp>
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

/// The distance's docstring and what it returns, for the groups whose
/// distance def_distance binds (the names: GroupNames, bindings.hpp).
template <typename G>
struct DistanceDoc;
template <>
struct DistanceDoc<chasles::SO2d> {
  static constexpr const char* returns = "the distances, radians, in [0, pi]";
  static constexpr const char* distance_doc = R"(Geodesic distances of plane rotations: |angle of a^-1 b|, in [0, pi].

d(a, b) = |log(a^T b)|, the bi-invariant (angular) distance: symmetric and
unchanged by d(g a, g b) and d(a g, b g); the absolute difference of the
angles, wrapped to [0, pi].)";
};
template <>
struct DistanceDoc<chasles::SE2d> {
  static constexpr const char* returns = "[angle (radians), translation distance]";
  static constexpr const char* distance_doc =
      R"(Distances of plane rigid motions: (rotation angle, translation distance).

[angle, translation] with angle = |log(R_a^T R_b)| in [0, pi] (so2_distance
of the rotations) and translation = |t_b - t_a|, the Euclidean distance of
the two frames' origins. SE(2) has no bi-invariant metric, so the two are
returned apart, for the caller to weigh; both are unchanged by a change of
the fixed frame, d(g a, g b).)";
};
template <>
struct DistanceDoc<chasles::Sim3d> {
  static constexpr const char* returns = "[angle (radians), translation distance, |log(s_b / s_a)|]";
  static constexpr const char* distance_doc =
      R"(Distances of similarities: (rotation angle, translation distance, log-scale distance).

[angle, translation, scale] with angle = |log(R_a^T R_b)| in [0, pi]
(so3_distance of the rotations), translation = |t_b - t_a| and
scale = |log(s_b / s_a)| = |sigma_b - sigma_a|. Sim(3) has no bi-invariant
metric, so the three are returned apart, for the caller to weigh; all are
unchanged by a rigid change of the fixed frame, and a change of scale
scales the translation distance with it.)";
};
template <>
struct DistanceDoc<chasles::SE23d> {
  static constexpr const char* returns = "[angle (radians), |p_b - p_a|, |v_b - v_a|]";
  static constexpr const char* distance_doc =
      R"(Distances of extended poses: (rotation angle, position distance, velocity distance).

[angle, position, velocity] with angle = |log(R_a^T R_b)| in [0, pi]
(so3_distance of the rotations), position = |p_b - p_a| and
velocity = |v_b - v_a|. SE_2(3) has no bi-invariant metric, so the three
are returned apart, for the caller to weigh; all are unchanged by a
rotation and a translation of the fixed frame.)";
};

/// The defect the group's from_matrix checks: the rotation defect of a
/// rotation group, the transform defect (rotation block and fixed rows) of
/// the others.
template <typename Group, typename M>
double defect_of(const M& m) noexcept {
  if constexpr (chasles::detail::IsRotationGroup<Group>::value) {
    return Group::rotation_defect(m);
  } else {
    return Group::transform_defect(m);
  }
}

/// The distance of the parts of two elements of a group (distance.hpp):
/// d(a, b) = |log(a^-1 b)| on a rotation group, a scalar; on the others
/// the vector (angle, the norm of each Euclidean block). One template for
/// SO2, SE2, Sim3 and SE23 (SO3 and SE3 are bound above, with their own
/// overloads' words).
template <typename Group>
void def_distance(py::module_& m) {
  using S = GroupNames<Group>;
  constexpr int N = chasles::detail::matrix_size<Group>;
  constexpr bool rotation = chasles::detail::IsRotationGroup<Group>::value;
  constexpr int B = chasles::GroupParts<Group>::B;
  using Out = std::conditional_t<rotation, Core<>, Core<1 + B>>;
  static const std::string name = std::string(S::prefix) + "_distance";
  const std::string n = std::to_string(N);
  static const std::string doc =
      std::string(DistanceDoc<Group>::distance_doc) + "\n\nArgs:\n    a: array_like of shape (..., " + n + ", " + n +
      "): " + matrices_words<Group>() + ".\n    b: array_like of shape (..., " + n + ", " + n +
      "): " + matrices_words<Group>() + ".\n\nReturns:\n    numpy.ndarray of shape (..." +
      (rotation ? std::string("") : ", " + std::to_string(1 + B)) + "): " + DistanceDoc<Group>::returns +
      ", the batch shape being the broadcast of a's and b's.";
  def_ufunc<Out(Core<N, N>, Core<N, N>)>(
      m, name.c_str(), "a, b", array_doc(doc.c_str()), [](const auto& a, const auto& b) {
        using G = Rebind<Group, ScalarOf<decltype(a)>>;
        return chasles::distance(G::from_matrix_unchecked(a), G::from_matrix_unchecked(b));
      });
}

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

/// The private map behind the samplers of python/chasles/_random.py for
/// G: element_from_uniforms (random.hpp), the uniform rotation of U
/// uniforms u and the Euclidean part low + (high - low) v of K more; for a
/// rotation group (K = 0) u alone. `_so2_from_uniforms` (1)->(2,2),
/// `_se2_from_uniforms` (1),(2),(2),(2)->(3,3), `_sim3_from_uniforms`
/// (3),(4),(4),(4)->(4,4) (v: translation then log-scale),
/// `_se23_from_uniforms` (3),(6),(6),(6)->(5,5) (v: position then velocity).
template <typename Group>
void def_from_uniforms(py::module_& m) {
  using S = GroupNames<Group>;
  using Parts = chasles::GroupParts<Group>;
  constexpr int N = chasles::detail::matrix_size<Group>, K = Parts::K;
  constexpr int U = chasles::UniformRotation<typename Parts::Rotation>::U;
  static const std::string name = std::string("_") + S::prefix + "_from_uniforms";
  static const std::string doc =
      std::string("The map behind chasles.") + S::prefix + "_random: a uniform (Haar) rotation of " +
      std::to_string(U) + " uniforms u in [0, 1)" +
      (K > 0 ? ", and the Euclidean part low + (high - low) v (element_from_uniforms)" : "") + ".";
  if constexpr (K == 0) {
    def_ufunc<Core<N, N>(Core<U>)>(m, name.c_str(), "u", array_doc(doc.c_str()), [](const auto& u) {
      using T = ScalarOf<decltype(u)>;
      using G = Rebind<Group, T>;
      return chasles::UniformRotation<G>::map(Eigen::Matrix<T, U, 1>(u)).matrix();
    });
  } else {
    def_ufunc<Core<N, N>(Core<U>, Core<K>, Core<K>, Core<K>)>(
        m, name.c_str(), "u, v, low, high", array_doc(doc.c_str()),
        [](const auto& u, const auto& v, const auto& low, const auto& high) {
          using T = ScalarOf<decltype(u)>;
          using G = Rebind<Group, T>;
          using V = Eigen::Matrix<T, K, 1>;
          return chasles::element_from_uniforms<G>(Eigen::Matrix<T, U, 1>(u), V(v), V(low), V(high)).matrix();
        });
  }
}

std::string shape_of(const py::array& a) {
  return shape_string(reinterpret_cast<const Py_intptr_t*>(a.shape()), static_cast<int>(a.ndim()));
}

/// The mean of N elements stored as (N, D, D) row-major float64 and N
/// weights, checked by the Python caller (python/chasles/_mean.py) and again
/// here for what this function reads: the shapes (the elements' N and the
/// weights' must agree, or the loops would read past the weights), the
/// elements (as the group's from_matrix checks one) and the weights (finite,
/// >= 0, not all 0, as the C++ mean reports them): (matrix, iterations,
/// converged). A reduction over the batch axis, so not a gufunc: the
/// elements are copied into a vector, then the C++ mean runs without the
/// GIL. One template for every group.
template <typename Group>
py::tuple mean_of(const py::array_t<double, py::array::c_style | py::array::forcecast>& elements,
                  const py::array_t<double, py::array::c_style | py::array::forcecast>& weights, bool geodesic,
                  int max_iterations) {
  constexpr int D = chasles::detail::matrix_size<Group>;
  using S = GroupNames<Group>;
  const std::string name = std::string("_") + S::prefix + "_mean";
  if (elements.ndim() != 3 || elements.shape(1) != D || elements.shape(2) != D || elements.shape(0) < 1 ||
      weights.ndim() != 1 || weights.shape(0) != elements.shape(0)) {
    const std::string d = std::to_string(D);
    throw py::value_error(name + "(matrices, weights): expected shapes (N, " + d + ", " + d +
                          ") with N >= 1 and (N,), got " + shape_of(elements) + " and " + shape_of(weights));
  }
  const py::ssize_t n = elements.shape(0);
  std::vector<Group> X;
  X.reserve(static_cast<std::size_t>(n));
  const double* d = elements.data();
  const double tolerance = chasles::Thresholds<double>::rotation_tolerance;
  for (py::ssize_t i = 0; i < n; ++i) {
    const Eigen::Matrix<double, D, D> M = Eigen::Map<const Eigen::Matrix<double, D, D, Eigen::RowMajor>>(d + i * D * D);
    // The mean of matrices that are not elements of the group is not
    // defined (and its iteration need not converge): refused, as the
    // group's from_matrix refuses them.
    const double defect = defect_of<Group>(M);
    if (!(defect <= tolerance)) {
      char text[320];
      std::snprintf(text, sizeof text,
                    "%s_mean(matrices): element %zd is not a %s: defect %.3g > %.3g (project it first: "
                    "%s.from_matrix_projected)",
                    S::prefix, static_cast<Py_ssize_t>(i), S::kind, defect, tolerance, S::cls);
      throw py::value_error(text);
    }
    X.push_back(Group::from_matrix_unchecked(M));
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
  if (!r.weights_valid) throw py::value_error(name + "(weights): expected finite weights >= 0, not all 0");
  return py::make_tuple(mat_out<D, D>(Eigen::Matrix<double, D, D>(r.mean.matrix())), r.iterations, r.converged);
}

template <typename Group>
void def_mean(py::module_& m) {
  using S = GroupNames<Group>;
  constexpr int D = chasles::detail::matrix_size<Group>;
  const std::string d = std::to_string(D);
  static const std::string name = std::string("_") + S::prefix + "_mean";
  static const std::string doc = std::string("The C++ mean behind chasles.") + S::prefix + "_mean, on checked (N, " +
                                 d + ", " + d + ") float64 elements and (N,) weights: (mean, iterations, converged).";
  m.def(name.c_str(), &mean_of<Group>, py::arg("matrices"), py::arg("weights"), py::arg("geodesic"),
        py::arg("max_iterations"), doc.c_str());
}

void bind_means(py::module_& m) {
  def_mean<chasles::SO2d>(m);
  def_mean<chasles::SE2d>(m);
  def_mean<SO3d>(m);
  def_mean<SE3d>(m);
  def_mean<chasles::Sim3d>(m);
  def_mean<chasles::SE23d>(m);
}

}  // namespace

void bind_statistics(py::module_& m) {
  bind_distances(m);
  def_distance<chasles::SO2d>(m);
  def_distance<chasles::SE2d>(m);
  def_distance<chasles::Sim3d>(m);
  def_distance<chasles::SE23d>(m);
  bind_sampling(m);
  def_from_uniforms<chasles::SO2d>(m);
  def_from_uniforms<chasles::SE2d>(m);
  def_from_uniforms<chasles::Sim3d>(m);
  def_from_uniforms<chasles::SE23d>(m);
  bind_means(m);
}

}  // namespace chasles_py
