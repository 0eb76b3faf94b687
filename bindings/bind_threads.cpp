// chasles._core: the count of threads a large batch of an array function is
// split across (parallel.hpp): get_num_threads, and the setter behind
// chasles.set_num_threads (python/chasles/_threads.py checks its argument
// and reads CHASLES_NUM_THREADS).
#include "bindings.hpp"
#include "parallel.hpp"

namespace chasles_py {

void bind_threads(py::module_& m) {
  m.attr("_max_threads") = parallel::max_threads;
  m.def(
      "_set_num_threads",
      [](int n) {
        if (n < 1 || n > parallel::max_threads) throw py::value_error("_set_num_threads: n out of range");
        parallel::thread_count = n;
      },
      py::arg("n"),
      "The setter behind chasles.set_num_threads (python/chasles/_threads.py, which checks n and names the "
      "errors).");
  m.def(
      "get_num_threads", [] { return parallel::thread_count.load(); },
      "The number of threads an array function may split a large batch across (set_num_threads).");
  m.def(
      "_threads_started", [] { return parallel::threads_started.load(); },
      "For the tests: how many threads the array functions' loops have started since import.");
}

}  // namespace chasles_py
