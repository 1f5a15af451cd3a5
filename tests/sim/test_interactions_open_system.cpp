// Interactions in an open system (interact/interactions_open_system.cpp): a removal re-evaluates the
// rates only when a removed particle acted on the others.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/run_summary.hpp"
#include "sim/simulation.hpp"
#include "support/open_system_scenes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

TEST(InteractionsOpenSystem, AParticleThatFallsOutAloneNeedsNoNewEvaluation) {
  Scene s = test::bounded_domain_scene(1e-4);
  test::add_particle(s, 1, 0.001, {0, 0, 0.01});     // crosses z = -0.02 after 78 ms
  test::add_particle(s, 2, 0.001, {0.05, 0, 0.09});  // only after 150 ms
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < 1000; ++k) sim.advance(sim.model().params.time.dt);
  ASSERT_EQ(sim.particles().size(), 1u);
  EXPECT_EQ(sim.particles().id[0], 2);
  EXPECT_EQ(sim.evaluations(), 1001u) << "the start, then one per step: none for the removal";
  // Free fall is exact for velocity Verlet: the balance holds with the removed energy in it.
  EXPECT_LT(std::abs(energy_drift(sim.record())), 1e-9);
}

TEST(InteractionsOpenSystem, AParticleThatLeavesTouchingAnotherIsEvaluatedAgain) {
  Scene s = test::bounded_domain_scene(1e-7);
  s.model.params.fields.gravity = {};
  // Particle 1 is just below the domain's floor and pressed against particle 2 (overlap 1 % of
  // the radius): the first step's check removes it while they touch.
  test::add_particle(s, 1, 0.001, {0, 0, -0.0201});
  test::add_particle(s, 2, 0.001, {0, 0, -0.0201 + 0.00198});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  sim.advance(sim.model().params.time.dt);
  ASSERT_EQ(sim.particles().size(), 1u);
  EXPECT_EQ(sim.particles().id[0], 2);
  EXPECT_EQ(sim.evaluations(), 3u) << "the start, the step, and the rates without particle 1";
  // Without gravity and without its partner, nothing acts on particle 2.
  const Particles& p = sim.particles();
  EXPECT_EQ(p.force[0].x, 0.0);
  EXPECT_EQ(p.force[0].y, 0.0);
  EXPECT_EQ(p.force[0].z, 0.0);
  EXPECT_GT(p.v[0].z, 0.0) << "the contact pushed particle 2 up in the step";
}

TEST(InteractionsOpenSystem, AParticleThatLeavesTouchingABarrierIsEvaluatedAgain) {
  Scene s = test::bounded_domain_scene(1e-7);
  s.model.params.fields.gravity = {};
  // Particle 1 lies on a floor below the domain's floor (overlap 1 % of the radius); particle 2
  // is alone and free.
  const Material& m = s.model.materials.front();
  const int g = s.barriers.group_index("floor");
  s.barriers.add(77, {-1, -1, -0.02109}, {1, -1, -0.02109}, {0, 1, -0.02109}, g, m.young, m.poisson, {}, 0.0, NAN);
  test::add_particle(s, 1, 0.001, {0, 0, -0.0201});
  test::add_particle(s, 2, 0.001, {0.05, 0, 0.05});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  sim.advance(sim.model().params.time.dt);
  ASSERT_EQ(sim.particles().size(), 1u);
  EXPECT_EQ(sim.evaluations(), 3u) << "the start, the step, and the rates and loads without particle 1";
  const Vec3 load = sim.barriers().force[0];
  EXPECT_EQ(load.x, 0.0);
  EXPECT_EQ(load.y, 0.0);
  EXPECT_EQ(load.z, 0.0) << "the floor's load is the remaining particles' (none)";
}
