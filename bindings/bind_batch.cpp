#include "bindings.hpp"

namespace chasles_py {

void bind_batch(py::module_& m) { (void)m; }

}  // namespace chasles_py
