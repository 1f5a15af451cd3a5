#pragma once
// Newton's third law for the one contact between two particles, as the contact-law tests check it.
#include <gtest/gtest.h>

#include <cstddef>
#include <optional>

#include "state/particles.hpp"

namespace mpdem::test {

// Particles a and b (storage indices, radii ra and rb, m) touching each other only: f_b = -f_a
// (relative 1e-12), and the torques are the contact-point arms (62) times the tangential force
// (relative 1e-9). Returns the normal force on a along n_ab (N; < 0 attractive), or nullopt when
// the force on a is zero (not touching).
inline std::optional<double> expect_action_reaction(const Particles& p, std::size_t a, std::size_t b, double ra,
                                                    double rb) {
  if (norm(p.force[a]) == 0.0) return std::nullopt;
  const double scale = norm(p.force[a]);
  EXPECT_LT(norm(p.force[a] + p.force[b]) / scale, 1e-12);
  const Vec3 n = (p.x[a] - p.x[b]) / norm(p.x[a] - p.x[b]);
  const Vec3 ft = p.force[a] - dot(p.force[a], n) * n;
  EXPECT_LT(norm(p.torque[a] - cross(-ra * n, ft)) / (ra * scale), 1e-9);
  EXPECT_LT(norm(p.torque[b] - cross(rb * n, -ft)) / (rb * scale), 1e-9);
  return dot(p.force[a], n);
}

}  // namespace mpdem::test
