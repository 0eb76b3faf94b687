// chasles._core: what the bind_*.cpp files share.
//
// module.cpp makes every class first (an empty class object, in this order),
// then binds each in its home file: a method that takes or returns another
// class (SE3.act(Twist), Twist.from_derivative(SE3, ...)) finds it made, so
// the order of the bind_* calls does not matter and no file reopens a class.
#pragma once

#include <string>

#include <pybind11/pybind11.h>

#include <chasles/euler.hpp>
#include <chasles/group_parts.hpp>
#include <chasles/screw.hpp>
#include <chasles/se2.hpp>
#include <chasles/se23.hpp>
#include <chasles/sim3.hpp>
#include <chasles/so2.hpp>

#include "instance.hpp"

namespace chasles_py {

namespace py = pybind11;

/// The tolerance of every group's from_matrix check on matrices from Python
/// (constructors, __setstate__).
constexpr double kRotationTolerance = chasles::Thresholds<double>::rotation_tolerance;
/// The joints a Chain can have (chasles::Chain<double, Dynamic, kMaxJoints>),
/// and so a joint vector of the array functions.
constexpr int kMaxJoints = 32;

/// A value class held inside its Python object (instance.hpp).
template <typename T>
using Class = py::class_<T, InlineHolder<T>>;

void bind_so3(Class<chasles::SO3d>& cls);  // bind_so3.cpp: class SO3
void bind_se3(Class<chasles::SE3d>& cls);  // bind_se3.cpp: class SE3
void bind_so2(Class<chasles::SO2d>& cls);  // bind_planar.cpp: class SO2
void bind_se2(Class<chasles::SE2d>& cls);    // bind_planar.cpp: class SE2
void bind_sim3(Class<chasles::Sim3d>& cls);  // bind_sim3.cpp: class Sim3
void bind_se23(Class<chasles::SE23d>& cls);  // bind_se23.cpp: class SE23
void bind_twist_wrench(Class<chasles::Twistd>& twist, Class<chasles::Wrenchd>& wrench,
                       py::class_<chasles::Screw<double>>& screw);  // bind_twist_wrench.cpp: Twist, Wrench, Screw
void bind_batch(py::module_& m);         // bind_batch.cpp: broadcasting array functions
void bind_jacobians(py::module_& m);     // bind_jacobians.cpp: rplus, ..., between, interpolate, their Jacobians
void bind_kinematics(py::module_& m);    // bind_kinematics.cpp: class _Chain (chasles.Chain's model), its ufuncs
void bind_statistics(py::module_& m);    // bind_statistics.cpp: angles, distances, means (array functions)
void bind_euler(py::module_& m);         // bind_euler.cpp: the private ufuncs of Euler angles and RPY
void bind_splines(py::module_& m);       // bind_splines.cpp: the cores of SO3/SE3Spline, SO3/SE3BSpline
void bind_dynamics(py::module_& m);      // bind_dynamics.cpp: class SpatialInertia
void bind_threads(py::module_& m);       // bind_threads.cpp: set_num_threads, get_num_threads
void bind_align(py::module_& m);         // bind_align.cpp: the kernels of so3_align, se3_align, sim3_align
void bind_gaussian(py::module_& m);      // bind_gaussian.cpp: <g>_compose_cov, ..., the kernels of Gaussian
void bind_trajectory(py::module_& m);    // bind_trajectory.cpp: the kernels of time_scaling, joint_trajectory

/// What the bindings call each group, written once (the classes' docstrings,
/// the array functions' names, the error messages): its Python class, the
/// prefix of its array functions, the word for one element, the form of its
/// matrix (none for the rotation groups) and the word for a spline's keys.
template <typename G>
struct GroupNames;
template <>
struct GroupNames<chasles::SO2d> {
  static constexpr const char *cls = "SO2", *prefix = "so2", *kind = "rotation", *form = "", *keys = "keys";
};
template <>
struct GroupNames<chasles::SE2d> {
  static constexpr const char *cls = "SE2", *prefix = "se2", *kind = "rigid motion", *form = "[[R, t], [0, 0, 1]]",
                              *keys = "keys";
};
template <>
struct GroupNames<chasles::SO3d> {
  static constexpr const char *cls = "SO3", *prefix = "so3", *kind = "rotation", *form = "", *keys = "rotations";
};
template <>
struct GroupNames<chasles::SE3d> {
  static constexpr const char *cls = "SE3", *prefix = "se3", *kind = "rigid motion", *form = "[[R, p], [0, 0, 0, 1]]",
                              *keys = "poses";
};
template <>
struct GroupNames<chasles::Sim3d> {
  static constexpr const char *cls = "Sim3", *prefix = "sim3", *kind = "similarity", *form = "[[s R, t], [0, 0, 0, 1]]",
                              *keys = "keys";
};
template <>
struct GroupNames<chasles::SE23d> {
  static constexpr const char *cls = "SE23", *prefix = "se23", *kind = "extended pose",
                              *form = "[[R, p, v], [0, 1, 0], [0, 0, 1]]", *keys = "keys";
};
/// The group G<double> over the scalar T (a float32 loop's G<float>).
template <typename G, typename T>
using Rebind = typename chasles::detail::WithScalar<G, T>::type;
/// The size of the points a group acts on: 2 for SO2 and SE2, 3 for the others.
template <typename G>
constexpr int point_size() {
  if constexpr (chasles::detail::IsRotationGroup<G>::value)
    return chasles::detail::matrix_size<G>;
  else
    return chasles::detail::matrix_size<typename G::Rotation>;
}
/// "rotation", "rigid motion [[R, t], [0, 0, 1]]", ...: one element, in a message.
template <typename G>
std::string element_words() {
  using N = GroupNames<G>;
  return *N::form ? std::string(N::kind) + " " + N::form : std::string(N::kind);
}
/// "rotation matrices", "rigid motion matrices [[R, t], [0, 0, 1]]", ...: a docstring's arguments.
template <typename G>
std::string matrices_words() {
  using N = GroupNames<G>;
  return std::string(N::kind) + " matrices" + (*N::form ? std::string(" ") + N::form : std::string());
}

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;  // numpy's deg2rad: x * (pi / 180)
constexpr double kRadToDeg = 180.0 / 3.14159265358979323846;  // numpy's rad2deg: x * (180 / pi)
/// bind_euler.cpp: the chasles::EulerSequence of the str `seq` (TypeError or ValueError naming `what`).
chasles::EulerSequence euler_sequence(py::handle seq, const char* what);

}  // namespace chasles_py
