// The real-time contract: no public operation allocates. Checked twice:
// Eigen's own runtime check (EIGEN_RUNTIME_NO_MALLOC, set by CMake here and
// in the exercise's object, exercise_*.cpp), which asserts inside Eigen on
// its heap use, and a counting global operator new, which sees every
// allocation through new, from any file of the program. Eigen's check is an
// eigen_assert: it runs where assertions are on (tests/run.sh's sanitizer
// build); under NDEBUG (its optimized build, where the exercise's object is
// the strict compile at -O3 -DNDEBUG) the counter runs alone, and counts
// Eigen's malloc too (below).
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>
#include <vector>

#include <gtest/gtest.h>

#include "realtime/exercise_all.hpp"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

// Eigen allocates with malloc and realloc (Eigen::internal::aligned_malloc),
// not new: the link wraps them (-Wl,--wrap: tests/cpp/CMakeLists.txt), so
// that the counter sees Eigen's heap use in the exercise's object too, under
// NDEBUG as with assertions on.
extern "C" void* __real_malloc(std::size_t n);
extern "C" void* __real_realloc(void* p, std::size_t n);
extern "C" void* __wrap_malloc(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __real_malloc(n);
}
extern "C" void* __wrap_realloc(void* p, std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  return __real_realloc(p, n);
}

void* operator new(std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
  g_allocations.fetch_add(1, std::memory_order_relaxed);
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }

namespace {

template <typename S>
void expect_no_allocation() {
  const long before = g_allocations.load();
  Eigen::internal::set_is_malloc_allowed(false);
  const S sum = chasles_test::exercise_all<S>();
  Eigen::internal::set_is_malloc_allowed(true);
  const long after = g_allocations.load();
  EXPECT_EQ(after - before, 0) << "operator new was called inside chasles operations";
  EXPECT_TRUE(std::isfinite(chasles_test::real_value(sum)));
}

/// Where the test below publishes its vector, so that the compiler may not
/// elide the allocation (C++14 lets it drop a new/delete pair it can see whole).
std::vector<int>* volatile g_escape = nullptr;

TEST(RealTime, CountingOperatorNewSeesAllocations) {
  // The counter works: a std::vector (two allocations: the object and its
  // buffer) is seen.
  const long before = g_allocations.load();
  auto* v = new std::vector<int>(100);
  g_escape = v;
  delete g_escape;
  EXPECT_GE(g_allocations.load() - before, 2);
}

TEST(RealTime, EigenNoMallocCheckIsActive) {
#ifndef EIGEN_RUNTIME_NO_MALLOC
  FAIL() << "EIGEN_RUNTIME_NO_MALLOC is not defined for this test";
#elif defined(EIGEN_NO_DEBUG)
  GTEST_SKIP() << "NDEBUG: Eigen's check (an eigen_assert) is compiled out; the build with assertions on runs it";
#else
  EXPECT_TRUE(Eigen::internal::is_malloc_allowed());
#endif
}

// The scalars whose exercise was built (CHASLES_EXERCISE_SCALARS).
#ifdef CHASLES_EXERCISE_DOUBLE
TEST(RealTime, NoAllocationDouble) { expect_no_allocation<double>(); }
#endif
#ifdef CHASLES_EXERCISE_FLOAT
TEST(RealTime, NoAllocationFloat) { expect_no_allocation<float>(); }
#endif
#ifdef CHASLES_EXERCISE_AUTODIFF
TEST(RealTime, NoAllocationAutodiff) { expect_no_allocation<chasles_test::AutoDiff>(); }
#endif

}  // namespace
