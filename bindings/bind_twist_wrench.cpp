#include "bindings.hpp"

namespace chasles_py {

void bind_twist_wrench(py::module_& m) { (void)m; }

}  // namespace chasles_py
