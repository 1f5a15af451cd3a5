// The trapezoidal rule at a first touch that falls on a step boundary (docs/integrators.md,
// "First touch"): an oblique impact on a plane, or of two spheres, whose end-of-step overlap is
// of round-off size converges at every step, for impact angles 5-35 degrees, and rebounds as a
// first touch within a step does.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "sim/simulation.hpp"
#include "support/barrier_mechanics_scene.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;
using namespace mpdem::test;  // kR, kE, kNu, kPi, base_scene

namespace {

constexpr double kSpeed = 1.0;  // m/s
constexpr double kE_rest = 0.5;

// e = 0.5, mu_s 0.5, mu_d 0.4; undamped: the thesis's undamped tangential spring (xi_t = 0)
// instead of the default xi_t = xi_n.
Scene impact_scene(double dt, bool undamped) {
  Scene s = base_scene(Integrator::Trapezoidal, dt, {});
  s.model.params.analysis.rotation = true;
  for (ContactLawParams* c : {&s.model.params.contact.particle_particle, &s.model.params.contact.particle_barrier}) {
    c->restitution = kE_rest;
    c->mu_static = 0.5;
    c->mu_dynamic = 0.4;
    if (undamped) c->tangential_damping = 0.0;
  }
  return s;
}

// Impact direction at `deg` degrees from the surface normal, into the surface (-z).
Vec3 impact_velocity(double deg) {
  const double a = deg * kPi / 180.0;
  return {kSpeed * std::sin(a), 0.0, -kSpeed * std::cos(a)};
}

// dt of about a hundredth of the contact time.
double impact_dt() {
  const double m = sphere_mass(kR), Es = kE / (2.0 * (1.0 - kNu * kNu));
  const double dmax = std::pow(15.0 * m * kSpeed * kSpeed / (16.0 * Es * std::sqrt(kR)), 0.4);
  return 2.943275 * dmax / kSpeed / 100.0;
}

// Runs until the contact is over; returns the normal rebound speed / approach speed, or -1 when
// a step failed to converge.
double run_to_rebound(Scene&& s, std::int64_t id, double normal_speed) {
  const double dt = s.model.params.time.dt;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  try {
    for (int k = 0; k < 400; ++k) sim.advance(dt);
  } catch (const std::exception& e) {
    std::printf("  %s\n", e.what());
    return -1.0;
  }
  return sim.particles().v[index_of(sim.particles(), id)].z / normal_speed;
}

}  // namespace

// First touch at the end of the fifth step, up to `gap` (m) and the round-off of five drifts:
// the end-of-step overlap is of round-off size, on either side of zero.
TEST(FirstTouch, SpherePlaneOnStepBoundaryConverges) {
  const double dt = impact_dt();
  for (const bool undamped : {false, true})
    for (const double deg : {5.0, 15.0, 25.0, 35.0})
      for (const double gap : {0.0, 1e-18, -1e-18, 1e-16, -1e-16}) {
        Scene s = impact_scene(dt, undamped);
        add_flat_square(s.barriers, "floor", {0.0, 0.0, 0.0}, 20.0 * kR, 2, kE, kNu);
        const Vec3 v = impact_velocity(deg);
        add_particle(s, 1, kR, {0.0, 0.0, kR - 5.0 * dt * v.z + gap}, v);
        const double e = run_to_rebound(std::move(s), 1, -v.z);
        std::printf("sphere-plane %4.1f deg, xi_t %s, gap %+.0e m: e = %.4f\n", deg, undamped ? "0" : "xi_n", gap, e);
        EXPECT_NEAR(e, kE_rest, 0.01) << deg << " deg, gap " << gap;
      }
}

// Two spheres sliding past each other: the normal turns during the impact, so the rebound is
// compared with that of the same impact started a step earlier, not with e.
TEST(FirstTouch, SphereSphereOnStepBoundaryConverges) {
  const double dt = impact_dt();
  for (const bool undamped : {false, true})
    for (const double deg : {5.0, 15.0, 25.0, 35.0}) {
      const Vec3 v = impact_velocity(deg);
      auto rebound = [&](double gap) {  // m, centre distance - 2R after five steps
        Scene s = impact_scene(dt, undamped);
        const double h = kR - 5.0 * dt * v.z + 0.5 * gap;
        add_particle(s, 1, kR, {0.0, 0.0, h}, 0.5 * v);
        add_particle(s, 2, kR, {0.0, 0.0, -h}, -0.5 * v);
        return run_to_rebound(std::move(s), 1, -0.5 * v.z);
      };
      const double clean = rebound(-0.5 * dt * v.z);  // first touch mid-step
      for (const double gap : {0.0, 1e-18, -1e-18, 1e-16, -1e-16}) {
        const double e = rebound(gap);
        std::printf("sphere-sphere %4.1f deg, xi_t %s, gap %+.0e m: e = %.4f (mid-step touch %.4f)\n", deg,
                    undamped ? "0" : "xi_n", gap, e, clean);
        EXPECT_GT(e, 0.0) << deg << " deg, gap " << gap;
        EXPECT_NEAR(e, clean, 0.005) << deg << " deg, gap " << gap;
      }
    }
}
