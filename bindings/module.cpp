// chasles._core: registers the bindings; each concept lives in its own bind_*.cpp.
#include "bindings.hpp"
#include "signatures.hpp"

#define CHASLES_PY_IMPORT_NUMPY  // this unit fills numpy's C API table for all of them
#include "numpy_capi.hpp"

PYBIND11_MODULE(_core, m) {
  namespace cp = chasles_py;
  m.doc() = "chasles C++ kernels (use the chasles package, which re-exports them).";
  m.attr("__version__") = CHASLES_VERSION;
  if (PyArray_ImportNumPyAPI() < 0 || PyUFunc_ImportUFuncAPI() < 0) throw pybind11::error_already_set();
  // The classes first, then their bindings in any order (bindings.hpp).
  cp::Class<chasles::SO3d> so3(m, "SO3");
  cp::Class<chasles::SE3d> se3(m, "SE3");
  cp::Class<chasles::SO2d> so2(m, "SO2");
  cp::Class<chasles::SE2d> se2(m, "SE2");
  cp::Class<chasles::Sim3d> sim3(m, "Sim3");
  cp::Class<chasles::SE23d> se23(m, "SE23");
  cp::Class<chasles::Twistd> twist(m, "Twist");
  cp::Class<chasles::Wrenchd> wrench(m, "Wrench");
  pybind11::class_<chasles::Screw<double>> screw(m, "Screw");
  cp::bind_so3(so3);
  cp::bind_se3(se3);
  cp::bind_so2(so2);
  cp::bind_se2(se2);
  cp::bind_sim3(sim3);
  cp::bind_se23(se23);
  cp::bind_twist_wrench(twist, wrench, screw);
  cp::bind_batch(m);
  cp::bind_jacobians(m);
  cp::bind_dynamics(m);
  cp::bind_kinematics(m);
  cp::bind_statistics(m);
  cp::bind_euler(m);
  cp::bind_splines(m);
  cp::bind_threads(m);
  cp::bind_align(m);
  cp::bind_gaussian(m);
  cp::bind_trajectory(m);
  cp::finish_functions(m);  // last: signatures for help() and inspect (signatures.hpp)
}
