// The real-time contract: no public operation allocates. Checked twice:
// Eigen's own runtime check (EIGEN_RUNTIME_NO_MALLOC, set by CMake), which
// asserts inside Eigen on any heap use, and a counting global operator new,
// which sees every allocation, Eigen's or not.
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
  EXPECT_TRUE(std::isfinite(static_cast<double>(sum)));
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
#else
  EXPECT_TRUE(Eigen::internal::is_malloc_allowed());
#endif
}

TEST(RealTime, NoAllocationDouble) { expect_no_allocation<double>(); }
TEST(RealTime, NoAllocationFloat) { expect_no_allocation<float>(); }

}  // namespace
