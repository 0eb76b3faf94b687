// chasles: the one runtime assertion of the library.
#pragma once

#include <Eigen/Core>

/// eigen_assert(x) as one statement that is never empty: Eigen's macro
/// expands to nothing under NDEBUG (or EIGEN_NO_DEBUG), which leaves an empty
/// statement (clang's -Wextra-semi-stmt). The check is Eigen's own, so a
/// user's definition of eigen_assert, NDEBUG and EIGEN_NO_DEBUG apply to it
/// as to Eigen's size checks.
#define CHASLES_ASSERT(x) \
  do {                    \
    eigen_assert(x);      \
  } while (false)
