// chasles._core: what the bind_*.cpp files share.
#pragma once

#include <pybind11/pybind11.h>

namespace chasles_py {

namespace py = pybind11;

void bind_so3(py::module_& m);           // bind_so3.cpp: class SO3
void bind_se3(py::module_& m);           // bind_se3.cpp: class SE3
void bind_twist_wrench(py::module_& m);  // bind_twist_wrench.cpp: classes Twist, Wrench, Screw
void bind_batch(py::module_& m);         // bind_batch.cpp: broadcasting array functions
void bind_jacobians(py::module_& m);     // bind_jacobians.cpp: SO3/SE3 Jacobians, rplus/rminus/lplus/lminus
void bind_kinematics(py::module_& m);    // bind_kinematics.cpp: class _Chain (chasles.Chain's model), its ufuncs
void bind_scipy(py::module_& m);         // bind_scipy.cpp: SO3/SE3 from_scipy, to_scipy
void bind_statistics(py::module_& m);    // bind_statistics.cpp: angles, distances (array functions)
void bind_euler(py::module_& m);         // bind_euler.cpp: SO3 Euler angles and RPY, their private ufuncs
void bind_spline(py::module_& m);        // bind_spline.cpp: the cores of SO3Spline, SE3Spline
void bind_bspline(py::module_& m);       // bind_bspline.cpp: classes SO3BSpline, SE3BSpline
void bind_dynamics(py::module_& m);      // bind_dynamics.cpp: class SpatialInertia
void bind_threads(py::module_& m);       // bind_threads.cpp: set_num_threads, get_num_threads

}  // namespace chasles_py
