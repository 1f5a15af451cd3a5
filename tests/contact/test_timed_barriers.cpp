// Barriers switched on and off in time ([[barriers]] active), through whole runs with both
// integrators: a floor under a settled column switched off at t = 0.5 s releases it exactly then
// (no force or contact afterwards, the column in free fall from the first step after, the first
// removals at the outlet after it); a floor switched on at t = 0.2 s catches a sphere that drifts
// onto it too slowly to rebuild the lists itself (the switch does).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>

#include "sim/simulation.hpp"
#include "support/timed_barrier_scenes.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

double momentum_z(const Particles& p) {
  double P = 0.0;  // kg m/s
  for (std::size_t i = 0; i < p.size(); ++i) P += p.mass[i] * p.v[i].z;
  return P;
}

}  // namespace

TEST(TimedBarriers, FloorSwitchedOffReleasesTheColumnExactlyThen) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(name(integ));
    Simulation sim(lid_scene(integ), RunOptions{{}, false, false});
    const Particles& p = sim.particles();
    const Barriers& b = sim.barriers();
    const double weight = 3.0 * p.mass[0] * kG;  // N
    // Up to the step before the switch: the floor carries the column, nothing leaves.
    std::uint64_t steps = 0;
    while (sim.time() < kLidOff - 1.5 * kTimedDt) {
      sim.advance(kTimedDt);
      ++steps;
      ASSERT_EQ(p.size(), 3u) << sim.time();
      ASSERT_EQ(b.active[0], 1);
      if (sim.time() > 0.4) {
        ASSERT_LT(group_force(b, "floor").z, 0.0) << sim.time();  // settled on it
      }
    }
    EXPECT_EQ(sim.time(), kLidOff - kTimedDt);  // exact binary fractions
    EXPECT_NEAR(-group_force(b, "floor").z, weight, 1e-3 * weight);
    for (std::size_t i = 0; i < p.size(); ++i) EXPECT_LT(norm(p.v[i]), 1e-4) << "settled, id " << p.id[i];
    EXPECT_EQ(sim.interactions().stats().contacts_pb, 1u);
    const double P0 = momentum_z(p);
    double F0 = 0.0;  // N, the total force on the spheres at the step's start (with the floor)
    for (std::size_t i = 0; i < p.size(); ++i) F0 += p.force[i].z;

    // The step ending at t_end evaluates at t_end: the floor is off, and stays off.
    sim.advance(kTimedDt);
    ASSERT_EQ(sim.time(), kLidOff);
    double first_removal = -1.0;  // s
    while (p.size() > 0 && sim.time() < 0.7) {
      EXPECT_EQ(b.active[0], 0);
      EXPECT_EQ(b.active[1], 0);
      for (std::size_t e = 0; e < b.size(); ++e) {
        ASSERT_EQ(b.force[e], (Vec3{})) << "t = " << sim.time();
        ASSERT_EQ(b.moment[e], (Vec3{}));
        ASSERT_EQ(b.pressure[e], 0.0);
      }
      ASSERT_EQ(sim.interactions().stats().contacts_pb, 0u);
      if (first_removal < 0.0 && p.size() == 3) {
        // Free fall of the column's momentum from the switch on: the trapezoid of the forces
        // (with the floor at the step's start, without at its end) over the first step, then
        // the weight alone; the pair forces cancel.
        const double fallen = sim.time() - kLidOff + 0.5 * kTimedDt;    // s
        const double expected = 0.5 * kTimedDt * F0 - weight * fallen;  // kg m/s
        EXPECT_NEAR(momentum_z(p) - P0, expected, 1e-9 * weight * fallen) << "t = " << sim.time();
      }
      if (first_removal < 0.0 && p.size() < 3) first_removal = sim.time();
      sim.advance(kTimedDt);
    }
    EXPECT_GT(first_removal, kLidOff);
    EXPECT_EQ(p.size(), 0u);  // all through the outlet
    EXPECT_EQ(steps + 1, static_cast<std::uint64_t>(kLidOff / kTimedDt));
  }
}

TEST(TimedBarriers, FloorSwitchedOnCatchesADriftingSphere) {
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(name(integ));
    Simulation sim(gate_scene(integ), RunOptions{{}, false, false});
    const Particles& p = sim.particles();
    const Barriers& b = sim.barriers();
    const Vec3 v0 = p.v[0];
    sim.initialize();
    const std::uint64_t built = sim.interactions().stats().rebuilds;
    // Before the switch the floor is not there: the sphere drifts untouched, and its drift never
    // asks for a rebuild (so only the switch can put the floor into the lists).
    while (sim.time() + kTimedDt < kGateOn) {
      sim.advance(kTimedDt);
      ASSERT_EQ(b.active[0], 0);
      ASSERT_EQ(p.v[0], v0);
    }
    EXPECT_EQ(sim.interactions().stats().rebuilds, built);
    sim.advance(kTimedDt);  // the first step evaluated at t >= t_start
    EXPECT_GE(sim.time(), kGateOn);
    EXPECT_EQ(b.active[0], 1);
    EXPECT_EQ(sim.interactions().stats().rebuilds, built + 1);
    while (sim.time() < 0.4) sim.advance(kTimedDt);
    // It met the floor at t = 0.25 s and bounced (restitution 0.5) instead of passing through.
    EXPECT_GT(p.x[0].z, kR);
    EXPECT_GT(p.v[0].z, 0.3 * -v0.z);
    EXPECT_LT(p.v[0].z, -v0.z);
  }
}
