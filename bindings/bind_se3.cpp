#include "bindings.hpp"

namespace chasles_py {

void bind_se3(py::module_& m) { (void)m; }

}  // namespace chasles_py
