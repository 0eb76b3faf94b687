// chasles._core: registers the bindings; each concept lives in its own bind_*.cpp.
#include "bindings.hpp"
#include "signatures.hpp"

#define CHASLES_PY_IMPORT_NUMPY  // this unit fills numpy's C API table for all of them
#include "numpy_capi.hpp"

PYBIND11_MODULE(_core, m) {
  m.doc() = "chasles C++ kernels (use the chasles package, which re-exports them).";
  m.attr("__version__") = CHASLES_VERSION;
  if (PyArray_ImportNumPyAPI() < 0 || PyUFunc_ImportUFuncAPI() < 0) throw pybind11::error_already_set();
  chasles_py::bind_so3(m);
  chasles_py::bind_se3(m);
  chasles_py::bind_twist_wrench(m);
  chasles_py::bind_batch(m);
  chasles_py::bind_jacobians(m);  // after SO3 and SE3: adds their static methods
  chasles_py::bind_dynamics(m);
  chasles_py::bind_kinematics(m);
  chasles_py::bind_scipy(m);  // after SO3 and SE3: adds their methods
  chasles_py::bind_statistics(m);
  chasles_py::bind_euler(m);  // after SO3: adds its Euler methods
  chasles_py::bind_spline(m);
  chasles_py::bind_bspline(m);
  chasles_py::bind_threads(m);
  chasles_py::finish_functions(m);  // last: signatures for help() and inspect (signatures.hpp)
}
