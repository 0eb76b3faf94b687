// chasles._core: set_num_threads / get_num_threads, the threads a large
// batch of an array function is split across (parallel.hpp).
#include <cstdlib>
#include <string>

#include "bindings.hpp"
#include "convert.hpp"
#include "parallel.hpp"

namespace chasles_py {

namespace {

const std::string range_text = "an int from 1 to " + std::to_string(parallel::max_threads);

/// n as a thread count, or the reason it is not one (empty: it is).
std::string thread_count_problem(const char* what, py::handle n, long long& value) {
  if (PyBool_Check(n.ptr()) || !PyIndex_Check(n.ptr()))
    return std::string(what) + " must be " + range_text + ", got " + Py_TYPE(n.ptr())->tp_name;
  const py::object i = py::reinterpret_steal<py::object>(PyNumber_Index(n.ptr()));
  if (!i) throw py::error_already_set();
  int overflow = 0;
  value = PyLong_AsLongLongAndOverflow(i.ptr(), &overflow);
  if (overflow != 0 || value < 1 || value > parallel::max_threads)
    return std::string(what) + " must be " + range_text + ", got " + py::str(i).cast<std::string>();
  return {};
}

}  // namespace

void bind_threads(py::module_& m) {
  // CHASLES_NUM_THREADS at import; a value that is not a thread count is
  // named in a warning and the default (1) kept: a typo in the environment
  // must not make the package fail to import.
  if (const char* env = std::getenv("CHASLES_NUM_THREADS"); env != nullptr && *env != '\0') {
    long long value = 0;
    std::string problem;
    try {
      problem = thread_count_problem("CHASLES_NUM_THREADS", py::int_(py::str(env)), value);
    } catch (const py::error_already_set&) {
      problem = "CHASLES_NUM_THREADS must be " + range_text + ", got '" + env + "'";
    }
    if (problem.empty())
      parallel::thread_count = static_cast<int>(value);
    else if (PyErr_WarnEx(PyExc_RuntimeWarning, (problem + "; using 1 thread").c_str(), 1) < 0)
      throw py::error_already_set();
  }

  m.def(
      "set_num_threads",
      [](IndexLike n) {
        long long value = 0;
        const std::string problem = thread_count_problem("set_num_threads(n)", n.obj, value);
        if (!problem.empty()) {
          if (PyBool_Check(n.obj.ptr()) || !PyIndex_Check(n.obj.ptr())) throw py::type_error(problem);
          throw py::value_error(problem);
        }
        parallel::thread_count = static_cast<int>(value);
      },
      py::arg("n"),
      R"doc(Sets how many threads an array function may split a large batch across.

The default is 1, or the environment variable CHASLES_NUM_THREADS read at
import. With n > 1, a call on a batch of N elements runs on
min(n, N // grain) threads, each on a contiguous part of the batch, inside
the ufunc's loop (the GIL is released there as always): grain is 16384
elements for the array functions and 512 configurations for the methods of
Chain, so a small batch never pays for a thread. Every element is computed
by the same code as on one thread: results are bit for bit the same.

The setting is the process's, shared by every Python thread. n: an int from
1 to 1024 (ValueError outside, TypeError for a non-integer).)doc");
  m.def(
      "get_num_threads", [] { return parallel::thread_count.load(); },
      "The number of threads an array function may split a large batch across (set_num_threads).");
  m.def(
      "_threads_started", [] { return parallel::threads_started.load(); },
      "For the tests: how many threads the array functions' loops have started since import.");
}

}  // namespace chasles_py
