#include "bindings.hpp"

namespace chasles_py {

void bind_so3(py::module_& m) { (void)m; }

}  // namespace chasles_py
