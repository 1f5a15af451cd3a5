// Contacts with rotating barriers through the whole engine (docs/scene.md motion.rotation): the
// surface velocity at the contact point, springs that turn with the surface, and the per-group
// torque about the axis and drive power.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "sim/simulation.hpp"
#include "support/barrier_mechanics_scene.hpp"
#include "support/contact_scenes.hpp"
#include "support/rotating_meshes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;
using namespace mpdem::test;  // kR, kE, kNu, kG, kPi, sphere_mass, E_star, name, base_scene

// A point mass (no rotation: a rolling ball on a turntable circles at 2/7 omega instead) resting
// with friction on a turntable at 2 rad/s, 0.05 m from the axis, starts at rest and is dragged
// along until it sticks; then it co-rotates, |v| = omega r within 1e-6 relative, because its
// spring turns with the table.
TEST(RotatingBarrierContacts, SphereOnTurntableMovesWithTheSurface) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double omega = 2.0, r0 = 0.05, dt = 2e-5;  // rad/s, m, s
    Scene s = base_scene(integ, dt, {0.0, 0.0, -kG});
    s.model.params.analysis.rotation = false;
    ContactLawParams& c = s.model.params.contact.particle_barrier;
    c.restitution = 0.5;
    c.mu_static = 0.5;
    c.mu_dynamic = 0.4;
    c.tangential_damping = 0.3;
    add_turntable(s.barriers, "table", 0.2, 24, kE, kNu, spin_about_z(omega));
    const double d = hertz_rest_overlap(sphere_mass(kR) * kG, E_star(kE, kNu), kR);
    const double a0 = 7.5 * kPi / 180.0;  // rad, the middle of a triangle
    add_particle(s, 1, kR, {r0 * std::cos(a0), r0 * std::sin(a0), kR - d});
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    const Particles& p = sim.particles();
    while (sim.time() < 1.0 - 0.5 * dt) sim.advance(dt);
    const double r = std::hypot(p.x[0].x, p.x[0].y);
    const double speed = std::hypot(p.v[0].x, p.v[0].y);
    std::printf("[%s] r %.9f m, |v| %.12f m/s, omega r %.12f m/s, rel %.2e\n", name(integ), r, speed, omega * r,
                speed / (omega * r) - 1.0);
    EXPECT_NEAR(r, r0, 0.01 * r0);  // still on the table where it was put (the transient slip is short)
    EXPECT_NEAR(speed / (omega * r), 1.0, 1e-6);
    EXPECT_NEAR(p.v[0].z, 0.0, 1e-6 * speed);
  }
}

// A rigid paddle (infinite inertia) turning at omega hits a sphere at rest, frictionless, with
// restitution e: the sphere leaves with (1 + e) u_n, u_n = omega sqrt(r^2 - R^2) the paddle's
// normal speed at the contact point (the sphere centre is r from the axis), within 1%.
TEST(RotatingBarrierContacts, PaddleGivesTheImpulseOfARigidWall) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double omega = 2.0, r = 0.06, phi0 = 0.1, e = 0.5, dt = 1e-6;  // rad/s, m, rad, -, s
    Scene s = paddle_scene(integ, dt, omega, r, phi0, e);
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    const Particles& p = sim.particles();
    bool touched = false;
    while (sim.time() < 0.02) {
      sim.advance(dt);
      touched = touched || sim.interactions().stats().contacts_pb > 0;
    }
    ASSERT_TRUE(touched);
    EXPECT_EQ(sim.interactions().stats().contacts_pb, 0u);  // separated
    const double expected = (1.0 + e) * omega * std::sqrt(r * r - kR * kR);
    const double speed = norm(p.v[0]);
    std::printf("[%s] speed %.6f m/s, (1 + e) u_n %.6f m/s, rel %.2e\n", name(integ), speed, expected,
                speed / expected - 1.0);
    EXPECT_NEAR(speed / expected, 1.0, 0.01);
    // Along the paddle's normal at the impact, (-sin theta, cos theta, 0) with theta ~ 0.017 rad.
    EXPECT_GT(p.v[0].y, 0.99 * speed);
    EXPECT_EQ(p.v[0].z, 0.0);
  }
}

// Spheres pressed on both faces of a paddle that turns and translates: after some steps the
// group's torque about the axis (sum of Barriers::axis_torque) equals the sum over the contacts of
// ((p - pivot) x F) . axis, F = minus each sphere's force (its only force), p the contact point
// on the face; the drive power equals sum of f . v_surface(p). Both within 1e-12 relative.
TEST(RotatingBarrierContacts, GroupTorqueIsTheSumOfContactMoments) {
  const double dt = 1e-6;
  Scene s = base_scene(Integrator::Verlet, dt, {0.0, 0.0, 0.0});
  ContactLawParams& c = s.model.params.contact.particle_barrier;
  c.restitution = 0.5;
  c.mu_static = 0.5;
  c.mu_dynamic = 0.4;
  MotionLaw law = spin_about_z(3.0);
  law.a = {0.0, 0.0, 0.01};
  add_paddle(s.barriers, "paddle", 0.0, 0.02, 0.1, -0.02, 0.02, kE, kNu, law);
  const double gap = 0.9 * kR;  // m, centre to face: overlap 0.1 R
  const struct {
    double r, z, side;
  } spheres[] = {{0.04, 0.01, 1.0}, {0.08, -0.012, 1.0}, {0.06, 0.015, -1.0}, {0.09, -0.01, 1.0}};
  std::int64_t id = 1;
  for (const auto& q : spheres) add_particle(s, id++, kR, {q.r, q.side * gap, q.z}, {0.0, -q.side * 0.05, 0.02});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < 50; ++k) sim.advance(dt);
  const Particles& p = sim.particles();
  const Barriers& b = sim.barriers();
  ASSERT_EQ(sim.interactions().stats().contacts_pb, 4u);
  const Vec3 axis = b.rotations[0].axis, pivot = b.pivot(0), n = b.current_normal(0), v0 = b.vertex(0, 0);
  double torque = 0.0, power = 0.0, torque_scale = 0.0, power_scale = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3 point = p.x[i] - dot(p.x[i] - v0, n) * n;  // on the face
    const Vec3 F = -p.force[i];                           // on the paddle
    const double t = dot(cross(point - pivot, F), axis), w = dot(p.force[i], b.surface_velocity(0, point));
    torque += t;
    power += w;
    torque_scale += std::abs(t);
    power_scale += std::abs(w);
  }
  double group_torque = 0.0, group_power = 0.0;
  for (std::size_t e = 0; e < b.size(); ++e) {
    group_torque += b.axis_torque(e);
    group_power += b.drive_power(e);
  }
  std::printf("torque %.15g N m (contacts %.15g), power %.15g W (contacts %.15g)\n", group_torque, torque, group_power,
              power);
  ASSERT_GT(std::abs(torque), 0.1 * torque_scale);
  EXPECT_NEAR(group_torque, torque, 1e-12 * torque_scale);
  EXPECT_NEAR(group_power, power, 1e-12 * power_scale);
}
