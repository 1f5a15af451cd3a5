#pragma once
// Test check: two vectors agree component by component within a tolerance.
#include <gtest/gtest.h>

#include "core/vec3.hpp"

namespace mpdem::test {

inline void expect_vec_near(const Vec3& a, const Vec3& b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

}  // namespace mpdem::test
