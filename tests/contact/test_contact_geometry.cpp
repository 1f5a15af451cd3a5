// Contact geometry and kinematics (physics.md section 5): overlap, normal and lever arms of a sphere
// pair, and the relative velocity at the contact point. Every tolerance is stated where it is used.
#include <gtest/gtest.h>

#include "core/vec3.hpp"
#include "physics/contact_geometry.hpp"

using namespace mpdem;

// ---------------------------------------------------------------------------------------------
// Contact geometry and kinematics
// ---------------------------------------------------------------------------------------------

TEST(ContactGeometry, OverlapNormalAndArms) {
  const Vec3 xi{1.0, 2.0, 3.0}, dir{2.0 / 7, 3.0 / 7, 6.0 / 7};  // unit direction
  const double Ri = 0.3, Rj = 0.5;
  const Vec3 xj = xi - 0.75 * dir;  // distance 0.75 -> overlap 0.05
  const PairGeometry g = pair_geometry(xi, Ri, xj, Rj);
  EXPECT_TRUE(g.touching);
  EXPECT_NEAR(g.distance, 0.75, 1e-14);
  EXPECT_NEAR(g.overlap, 0.05, 1e-14);
  EXPECT_NEAR(norm(g.normal - dir), 0.0, 1e-14);  // from j to i
  EXPECT_NEAR(norm(g.r_Pi + Ri * dir), 0.0, 1e-14);
  EXPECT_NEAR(norm(g.r_Pj - Rj * dir), 0.0, 1e-14);
  // The two surface points are overlap apart along -n.
  EXPECT_NEAR(norm((xi + g.r_Pi) - (xj + g.r_Pj) + 0.05 * dir), 0.0, 1e-14);
  EXPECT_FALSE(pair_geometry({0, 0, 0}, 0.1, {0, 0, 0.3}, 0.1).touching);
  EXPECT_TRUE(isfinite(pair_geometry({0, 0, 0}, 0.1, {0, 0, 0}, 0.1).normal));
}

TEST(ContactGeometry, RelativeVelocityKnownCases) {
  // i above j along z (n = +z), radii 0.2 and 0.3; exact values, tolerance 1e-14.
  const double Ri = 0.2, Rj = 0.3;
  const PairGeometry g = pair_geometry({0, 0, 0.49}, Ri, {0, 0, 0}, Rj);
  const Vec3 n = g.normal, zero{};
  auto close = [](const Vec3& a, const Vec3& b) { return norm(a - b) < 1e-14; };
  // Pure translation, tangential: all of it is tangential.
  Vec3 v = contact_relative_velocity({1, 0, 0}, zero, g.r_Pi, zero, zero, g.r_Pj);
  EXPECT_TRUE(close(v, {1, 0, 0}));
  EXPECT_TRUE(close(tangential_part(v, n), {1, 0, 0}));
  // Head-on approach: purely normal, rate negative.
  v = contact_relative_velocity({0, 0, -1}, zero, g.r_Pi, {0, 0, 1}, zero, g.r_Pj);
  EXPECT_NEAR(normal_rate(v, n), -2.0, 1e-14);
  EXPECT_TRUE(close(tangential_part(v, n), zero));
  // i rolling without slip on resting j: v = V x, w = (V/R_i) y -> no slip at P.
  v = contact_relative_velocity({0.7, 0, 0}, {0, 0.7 / Ri, 0}, g.r_Pi, zero, zero, g.r_Pj);
  EXPECT_TRUE(close(v, zero));
  // Spin of i about the normal does not move the contact point.
  v = contact_relative_velocity(zero, {0, 0, 5}, g.r_Pi, zero, zero, g.r_Pj);
  EXPECT_TRUE(close(v, zero));
  // Both spinning about +y at w: surfaces move opposite, v_rel = -w (R_i + R_j) x.
  v = contact_relative_velocity(zero, {0, 2, 0}, g.r_Pi, zero, {0, 2, 0}, g.r_Pj);
  EXPECT_TRUE(close(v, {-2 * (Ri + Rj), 0, 0}));
  // Swapping i and j flips v_rel.
  const PairGeometry h = pair_geometry({0, 0, 0}, Rj, {0, 0, 0.49}, Ri);
  const Vec3 vij = contact_relative_velocity({0.1, 0.2, 0}, {1, 2, 3}, g.r_Pi, {0, -0.3, 0}, {-1, 0, 2}, g.r_Pj);
  const Vec3 vji = contact_relative_velocity({0, -0.3, 0}, {-1, 0, 2}, h.r_Pi, {0.1, 0.2, 0}, {1, 2, 3}, h.r_Pj);
  EXPECT_TRUE(close(vij, -vji));
  // Barrier moving with u' = (0.2, 0, 0) under a sphere sliding at the same speed: no slip.
  EXPECT_TRUE(close(contact_relative_velocity_barrier({0.2, 0, 0}, zero, g.r_Pi, {0.2, 0, 0}), zero));
}
