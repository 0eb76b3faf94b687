// Test support: the scalar types of the typed suites and how GoogleTest
// names them ("float", "double" in the test names), for
// TYPED_TEST_SUITE(Suite, ScalarTypes, ScalarName).
#pragma once

#include <string>
#include <type_traits>

#include <gtest/gtest.h>

namespace chasles_test {

/// The scalars every typed suite runs on.
using ScalarTypes = ::testing::Types<float, double>;

/// GoogleTest's name generator for ScalarTypes.
struct ScalarName {
  template <typename S>
  static std::string GetName(int) {
    static_assert(std::is_same<S, float>::value || std::is_same<S, double>::value, "a scalar of ScalarTypes");
    return std::is_same<S, float>::value ? "float" : "double";
  }
};

}  // namespace chasles_test
