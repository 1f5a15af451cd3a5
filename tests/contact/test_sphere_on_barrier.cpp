// A sphere meeting a triangulated barrier through the whole engine, against closed forms (physics.md
// sections 5-7, 12): Hertz impact and restitution; a square hole it falls through or rests on the rim of.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "interact/interactions.hpp"
#include "sim/simulation.hpp"
#include "support/barrier_mechanics_scene.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;
using namespace mpdem::test;  // kR, kE, kNu, kG, kRho, kPi, sphere_mass, E_star, name, base_scene

namespace {

struct Impact {
  double F_max = 0.0, delta_max = 0.0, t_c = 0.0;  // N, m, s
  double v_after = 0.0;                            // m/s, rebound z-velocity
  double third_law = 0.0;                          // max |f_particle + sum f_barrier| / |f|
};

// Sphere falling (no gravity) with speed v onto an 8 x 8-cell flat square in z = 0 whose
// modulus is Eb; the contact point lies inside a face away from seams.
Impact barrier_impact(Integrator integ, double v, double e, double Eb, double steps_per_tc) {
  const double m = sphere_mass(kR), Es = E_star(Eb, kNu);
  const double dmax = std::pow(15.0 * m * v * v / (16.0 * Es * std::sqrt(kR)), 0.4);
  const double dt = 2.943275 * dmax / v / steps_per_tc;
  Scene s = base_scene(integ, dt, {});
  test::add_flat_square(s.barriers, "floor", {}, 0.1, 8, Eb, kNu);
  if (e < 1.0) s.model.params.contact.particle_barrier.restitution = e;
  else s.model.params.contact.particle_barrier.damping_ratio = 0.0;
  const double gap = 3.3 * v * dt;
  test::add_particle(s, 1, kR, {0.0031, -0.0042, kR + gap}, {0.0, 0.0, -v});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  Particles& p = sim.particles();
  Impact r;
  double ov_prev = -gap, t_start = -1.0;
  for (int k = 0; k < 20 * static_cast<int>(steps_per_tc); ++k) {
    sim.advance(dt);
    const double ov = kR - p.x[0].z, t = sim.time();
    if (ov > 0.0) {
      r.F_max = std::max(r.F_max, norm(p.force[0]));
      r.delta_max = std::max(r.delta_max, ov);
      r.third_law = std::max(r.third_law,
                             norm(p.force[0] + test::group_force(sim.barriers(), "floor")) / norm(p.force[0]));
    }
    if (ov_prev <= 0.0 && ov > 0.0 && t_start < 0.0) t_start = t - dt * ov / (ov - ov_prev);
    if (ov_prev > 0.0 && ov <= 0.0) {
      r.t_c = (t - dt * (-ov) / (ov_prev - ov)) - t_start;
      r.v_after = p.v[0].z;
      break;
    }
    ov_prev = ov;
  }
  return r;
}

}  // namespace

// Sphere on a barrier 1e6 times stiffer than itself, e = 1: peak force and maximum overlap within
// 0.5%, contact time within 1% of the closed forms with r* = R, m* = m and E* of (51) with the
// barrier's E (and also with the rigid limit E/(1 - nu^2), 1e-6 away); elastic rebound.
TEST(SphereOnBarrier, MatchesHertzClosedForms) {
  const double m = sphere_mass(kR);
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal})
    for (double v : {0.1, 1.0}) {
      const Impact r = barrier_impact(integ, v, 1.0, 1e6 * kE, 1000.0);
      for (double Es : {E_star(1e6 * kE, kNu), kE / (1.0 - kNu * kNu)}) {
        const double dmax = std::pow(15.0 * m * v * v / (16.0 * Es * std::sqrt(kR)), 0.4);
        const double Fmax = 4.0 / 3.0 * Es * std::sqrt(kR) * std::pow(dmax, 1.5);
        const double tc = 2.943275 * dmax / v;
        std::printf("[%s v=%g E*=%.8g] F_max err %.2e, delta_max err %.2e, t_c err %.2e, e %.6f, 3rd law %.1e\n",
                    name(integ), v, Es, r.F_max / Fmax - 1, r.delta_max / dmax - 1, r.t_c / tc - 1, r.v_after / v,
                    r.third_law);
        EXPECT_NEAR(r.F_max / Fmax, 1.0, 0.005);
        EXPECT_NEAR(r.delta_max / dmax, 1.0, 0.005);
        EXPECT_NEAR(r.t_c / tc, 1.0, 0.01);
      }
      EXPECT_NEAR(r.v_after, v, 1e-4 * v);
      EXPECT_LT(r.third_law, 1e-12);  // the floor's loads are exactly the opposite of the sphere's force
    }
}

// Achieved restitution against a barrier (E_b = E) within 0.005 of e, e x speed sweep,
// dt = t_c / 200.
TEST(SphereOnBarrier, RestitutionSweep) {
  double worst = 0.0;
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal})
    for (double e : {0.1, 0.3, 0.5, 0.7, 0.9, 1.0})
      for (double v : {0.01, 0.1, 1.0, 10.0}) {
        const Impact r = barrier_impact(integ, v, e, kE, 200.0);
        worst = std::max(worst, std::abs(r.v_after / v - e));
        EXPECT_NEAR(r.v_after / v, e, 0.005) << name(integ) << " e " << e << " v " << v;
      }
  std::printf("restitution sphere-barrier: worst |e_achieved - e| = %.2e\n", worst);
}

// A sphere of diameter d falls through the centre of a square hole of side 1.2 d in a
// triangulated plate without any contact; one of diameter 2 d settles on the hole's four rims,
// carrying its weight (1e-6) at rest, at the height where 4 Hertz edge forces balance it.
TEST(Hole, SmallSphereFallsThroughLargeOneRestsOnRim) {
  const double d = 2.0 * kR, hole = 1.2 * d;
  {
    const double dt = 2e-5;
    Scene s = base_scene(Integrator::Verlet, dt, {0.0, 0.0, -kG});
    test::add_plate_with_hole(s.barriers, "plate", 0.0, hole, kE, kNu);
    test::add_particle(s, 1, kR, {3e-4, -2e-4, 2.0 * kR}, {0.0, 0.0, -1.0});
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    std::size_t contacts = 0;
    while (sim.particles().x[0].z > -2.0 * kR) {
      sim.advance(dt);
      contacts += sim.interactions().stats().contacts_pb;
    }
    EXPECT_EQ(contacts, 0u);
    EXPECT_EQ(sim.particles().v[0].x, 0.0);
    EXPECT_EQ(sim.particles().v[0].y, 0.0);
  }
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double R = kR * 2.0, dt = 2e-5, m = sphere_mass(R);
    Scene s = base_scene(integ, dt, {0.0, 0.0, -kG});
    test::add_plate_with_hole(s.barriers, "plate", 0.0, hole, kE, kNu);
    ContactLawParams& c = s.model.params.contact.particle_barrier;
    c.restitution = 0.1;
    c.mu_static = 0.0;   // frictionless: the rest height is then unique (with friction the springs
    c.mu_dynamic = 0.0;  // keep whatever load the settling left, and the height depends on history)
    s.model.params.tolerance = ToleranceParams{};
    const double h = 0.5 * hole;
    test::add_particle(s, 1, R, {0.0, 0.0, std::sqrt(R * R - h * h) + 1e-5});
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    while (sim.time() < 0.1) sim.advance(dt);
    const Particles& p = sim.particles();
    const Vec3 F = test::group_force(sim.barriers(), "plate");
    // Rest height: 4 F_hertz(delta) z / (R - delta) = m g with z = sqrt((R - delta)^2 - h^2).
    double delta = 0.0;
    for (int it = 0; it < 200; ++it) {
      const double dist = R - delta, z = std::sqrt(dist * dist - h * h);
      delta = test::hertz_rest_overlap(m * kG * dist / (4.0 * z), E_star(kE, kNu), R);
    }
    const double z_exp = std::sqrt((R - delta) * (R - delta) - h * h);
    std::printf("[%s] rim: contacts %zu, floor force / weight - 1 = %.2e, |v| %.1e, z err / delta %.2e\n", name(integ),
                sim.interactions().stats().contacts_pb, -F.z / (m * kG) - 1.0, norm(p.v[0]),
                (p.x[0].z - z_exp) / delta);
    EXPECT_EQ(sim.interactions().stats().contacts_pb, 4u);
    EXPECT_NEAR(-F.z / (m * kG), 1.0, 1e-6);
    EXPECT_LT(norm(p.v[0]), 1e-6);
    EXPECT_NEAR(p.x[0].z, z_exp, 1e-3 * delta);
  }
}
