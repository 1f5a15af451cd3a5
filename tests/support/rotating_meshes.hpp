#pragma once
// Rotating barrier meshes for the tests: a turntable (a fan of triangles around the z axis) and
// paddles (rectangles in a plane through the z axis), each with the motion law it is given.
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "state/barriers.hpp"
#include "support/barrier_mechanics_scene.hpp"
#include "support/scene_builder.hpp"

namespace mpdem::test {

// The motion law turning at omega (rad/s) about z through the origin.
inline MotionLaw spin_about_z(double omega) {
  MotionLaw law;
  RotationLaw r;
  r.axis = {0.0, 0.0, 1.0};
  r.omega = omega;
  law.rotation = r;
  return law;
}

// Disc of radius rd in z = 0, normal +z: n triangles around the origin.
inline void add_turntable(Barriers& b, const std::string& group, double rd, int n, double young, double poisson,
                          const MotionLaw& law) {
  const int g = b.group_index(group);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double step = 2.0 * std::acos(-1.0) / n;  // rad
  const auto rim = [&](int k) { return Vec3{rd * std::cos(k * step), rd * std::sin(k * step), 0.0}; };
  for (int k = 0; k < n; ++k)
    b.add(static_cast<std::int64_t>(b.size()), Vec3{}, rim(k), rim(k + 1), g, young, poisson, law, 0.0, nan);
}

// Rectangle r in [r0, r1], z in [z0, z1] of the half-plane at angle phi (rad) about the z axis,
// two triangles split along (r0, z0)-(r1, z1); its normal is the direction of positive turning
// (-sin phi, cos phi, 0).
inline void add_paddle(Barriers& b, const std::string& group, double phi, double r0, double r1, double z0, double z1,
                       double young, double poisson, const MotionLaw& law) {
  const int g = b.group_index(group);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const Vec3 er{std::cos(phi), std::sin(phi), 0.0};
  const auto P = [&](double r, double z) { return r * er + Vec3{0.0, 0.0, z}; };
  const Vec3 A = P(r0, z0), B = P(r1, z0), C = P(r1, z1), D = P(r0, z1);
  b.add(static_cast<std::int64_t>(b.size()), A, C, B, g, young, poisson, law, 0.0, nan);
  b.add(static_cast<std::int64_t>(b.size()), A, D, C, g, young, poisson, law, 0.0, nan);
}

// A frictionless sphere (id 1, radius kR) at rest at distance r from the z axis and angle phi0
// (rad) ahead of a paddle (r in [0.02, 0.1] m, z in [-0.02, 0.02] m) turning at omega (rad/s),
// restitution e, no gravity: the paddle-impact scene of the rotating-barrier tests.
inline Scene paddle_scene(Integrator integ, double dt, double omega, double r, double phi0, double e) {
  Scene s = base_scene(integ, dt, {0.0, 0.0, 0.0});
  ContactLawParams& c = s.model.params.contact.particle_barrier;
  c.restitution = e;
  c.mu_static = 0.0;
  c.mu_dynamic = 0.0;
  add_paddle(s.barriers, "paddle", 0.0, 0.02, 0.1, -0.02, 0.02, kE, kNu, spin_about_z(omega));
  add_particle(s, 1, kR, {r * std::cos(phi0), r * std::sin(phi0), 0.0});
  return s;
}

}  // namespace mpdem::test
