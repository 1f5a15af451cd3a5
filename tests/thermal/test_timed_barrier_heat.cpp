// Heat conduction to a fixed-temperature barrier switched off in time ([[barriers]] active): a
// cool sphere resting on a warm floor (active [0, 0.5 s]) warms up while the floor is on, and
// from the first evaluation at t >= 0.5 s no heat flows, although the sphere still overlaps the
// floor's plane then (an inactive element takes part in nothing).
#include <gtest/gtest.h>

#include "sim/simulation.hpp"
#include "support/timed_barrier_scenes.hpp"

using namespace mpdem;
using namespace mpdem::test;

TEST(TimedBarrierHeat, NoConductionOnceSwitchedOff) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(name(integ));
    Scene s = base_scene(integ, kTimedDt, {0.0, 0.0, -kG});
    s.model.params.analysis.thermal = true;
    s.model.params.checks.energy_jump = 0.0;  // a sphere dropped from rest: no energy to compare with yet
    s.model.params.contact.particle_barrier.restitution = 0.5;
    add_timed_floor(s.barriers, "floor", 0.0, 0.02, active_between(0.0, kLidOff), 350.0);
    add_particle(s, 1, kR, {0.003, -0.004, kR});
    s.particles.T[0] = 300.0;
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    const Particles& p = sim.particles();
    while (sim.time() < kLidOff - 1.5 * kTimedDt) sim.advance(kTimedDt);
    const double warmed = p.T[0];
    EXPECT_GT(warmed, 300.0);
    EXPECT_LT(sim.interactions().stats().heat_to_barriers, 0.0);  // heat came from the floor
    sim.advance(kTimedDt);                                        // ends at t_end: the end-of-step flow is zero
    ASSERT_EQ(sim.time(), kLidOff);
    const double T_switch = p.T[0];
    const double to_barriers = sim.interactions().stats().heat_to_barriers;
    for (int k = 0; k < 20; ++k) {
      sim.advance(kTimedDt);
      EXPECT_LT(p.x[0].z, kR);  // still within the floor's reach, geometrically
      EXPECT_EQ(p.T[0], T_switch) << "t = " << sim.time();
      EXPECT_EQ(sim.interactions().stats().heat_to_barriers, to_barriers);
    }
  }
}
