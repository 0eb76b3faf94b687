// chasles._core: a large batch split across threads inside a ufunc's loop.
//
// chasles.set_num_threads(n) sets how many threads a loop may use (default
// 1, or the CHASLES_NUM_THREADS environment variable read at import). A
// loop of `count` elements runs on k = min(n, count / grain) threads, each
// on one contiguous range of the elements: the calling thread takes the
// first range and k - 1 threads started for this loop take the others, all
// joined before the loop returns. Each element is computed by the same code
// as on one thread, independently of the others, so results are bit for bit
// those of one thread. The threads live only as long as the loop: there is
// no pool, so none can nest in another or outlive the module; the GIL is
// already released around the loop (numpy's doing), and the kernels never
// touch Python.
//
// The grain is the fewest elements worth a thread of their own: starting
// and joining one thread took 8 us (median of 2000; 28 us at the 90th
// percentile) on this project's 2-core machine while it compiled, so a
// thread's share must take several times that. The elementwise
// kernels take 3 to 60 ns per element: 2^14 elements (50 us to 1 ms) per
// thread. The kernels over a chain's model (forward kinematics 0.2 us,
// dynamics 0.4 to 1 us, inverse kinematics 10 us and more): 2^9 (100 us
// and more).
// A batch below two grains never starts a thread.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>

#include "numpy_capi.hpp"

namespace chasles_py {
namespace parallel {

using ssize = npy_intp;

/// The fewest elements per thread for an elementwise kernel and for a
/// kernel over a chain's model (see above).
inline constexpr ssize elementwise_grain = ssize(1) << 14;
inline constexpr ssize model_grain = ssize(1) << 9;

/// The most threads set_num_threads accepts (far above any machine's cores:
/// a bound on a mistyped value, not a tuning).
inline constexpr int max_threads = 1024;

/// The threads a loop may use (set_num_threads / get_num_threads).
inline std::atomic<int> thread_count{1};
/// The threads loops have started since import (for the tests: a batch
/// below two grains starts none).
inline std::atomic<unsigned long long> threads_started{0};

/// How many threads a loop of `count` elements runs on.
inline ssize threads_for(ssize count, ssize grain) noexcept {
  const ssize wanted = thread_count.load(std::memory_order_relaxed);
  return std::max<ssize>(1, std::min(wanted, count / grain));
}

/// Calls run(begin, end) on consecutive ranges covering [0, count): on the
/// calling thread alone, or split as described above. A thread that cannot
/// be started (std::system_error: the process's limit) has its range run on
/// the calling thread after its own, with the same result.
template <typename Run>
void for_ranges(ssize count, ssize grain, const Run& run) noexcept {
  const ssize k = threads_for(count, grain);
  if (k <= 1) {
    run(ssize(0), count);
    return;
  }
  constexpr ssize most = max_threads;
  std::thread workers[most];
  bool started[most] = {};
  const auto bound = [&](ssize j) { return count / k * j + std::min(j, count % k); };
  for (ssize j = 1; j < k; ++j) {
    try {
      workers[j] = std::thread([&run, b = bound(j), e = bound(j + 1)] { run(b, e); });
      started[j] = true;
      threads_started.fetch_add(1, std::memory_order_relaxed);
    } catch (...) {  // std::system_error: the process's limit on threads
    }
  }
  run(bound(0), bound(1));
  for (ssize j = 1; j < k; ++j) {
    if (started[j])
      workers[j].join();
    else
      run(bound(j), bound(j + 1));
  }
}

}  // namespace parallel
}  // namespace chasles_py
