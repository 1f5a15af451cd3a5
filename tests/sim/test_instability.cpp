// Instability detection: non-finite states and energy jumps stop the run with a message naming
// particle ids, time and step.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/run_error.hpp"
#include "sim/simulation.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

namespace {
std::string run_until_error(Scene& s, double dt, int steps) {
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  std::string msg;
  try {
    for (int k = 0; k < steps; ++k) sim.advance(dt);
  } catch (const RunError& e) {
    msg = e.what();
  }
  s.particles = sim.particles();  // the caller reads the end state
  return msg;
}
}  // namespace

TEST(Instability, NonFiniteStateNamesTheParticle) {
  Scene s = test::make_scene(1e-4, 1.0);
  s.model.params.time.integrator = Integrator::Verlet;
  test::add_particle(s, 11, 0.001, {0, 0, 0});
  test::add_particle(s, 42, 0.001, {1, 0, 0}, {std::numeric_limits<double>::quiet_NaN(), 0, 0});
  const std::string msg = run_until_error(s, 1e-4, 10);
  EXPECT_NE(msg.find("non-finite state of particle id 42"), std::string::npos) << msg;
  EXPECT_NE(msg.find("at step 1"), std::string::npos) << msg;
  EXPECT_NE(msg.find("t = "), std::string::npos) << msg;
}

TEST(Instability, EnergyJumpFromATooLargeStep) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    // Two spheres colliding head-on with a step of about half the Hertz contact time (1.8e-4 s).
    Scene s = test::make_scene(1e-4, 1.0);
    s.model.params.time.integrator = integ;
    s.model.params.time.phi = 0.0;            // explicit: no convergence failure to hide the blow-up
    s.model.params.checks.max_overlap = 0.0;  // this test is about the energy check alone
    s.model.params.fields.gravity = {};
    test::add_particle(s, 5, 0.001, {0, 0, 0}, {1.0, 0, 0});
    test::add_particle(s, 6, 0.001, {0.00205, 0, 0}, {-1.0, 0, 0});
    const std::string msg = run_until_error(s, 1e-4, 200);
    EXPECT_NE(msg.find("energy jump at step"), std::string::npos) << msg;
    EXPECT_NE(msg.find("ids 5, 6"), std::string::npos) << msg;
    EXPECT_NE(msg.find("reduce time.dt"), std::string::npos) << msg;
  }
}

TEST(Instability, ResolvedCollisionDoesNotTrigger) {
  // A stiffer pair (overlap ~2% of the radius) with a step of ~1/100 of the contact time passes
  // every check.
  Scene s = test::make_scene(1e-4, 1.0);
  s.model.params.time.integrator = Integrator::Verlet;
  s.model.params.fields.gravity = {};
  test::add_particle(s, 5, 0.001, {0, 0, 0}, {1.0, 0, 0});
  test::add_particle(s, 6, 0.001, {0.00205, 0, 0}, {-1.0, 0, 0});
  s.model.materials[0].young = 1e9;  // both spheres
  EXPECT_EQ(run_until_error(s, 2e-7, 1500), "");
  EXPECT_LT(s.particles.v[0].x, 0.0);  // they did collide and rebound
}

TEST(Instability, ExcessiveOverlapNamesTheContact) {
  // Soft spheres in a fast impact: Hertz overlap (15 m* v^2 / (16 E* sqrt(r*)))^(2/5) is ~14% of
  // the radius here, beyond the default limit of 5%.
  {
    Scene s = test::make_scene(1e-4, 1.0);
    s.model.params.time.integrator = Integrator::Verlet;
    s.model.params.fields.gravity = {};
    test::add_particle(s, 7, 0.001, {0, 0, 0}, {2.0, 0, 0});
    test::add_particle(s, 8, 0.001, {0.00205, 0, 0}, {-2.0, 0, 0});
    s.model.materials[0].young = 1e5;  // both spheres
    const std::string msg = run_until_error(s, 1e-6, 2000);
    EXPECT_NE(msg.find("between particles id 7 and id 8"), std::string::npos) << msg;
    EXPECT_NE(msg.find("checks.max_overlap = 5%"), std::string::npos) << msg;
  }
  {
    Scene s = test::make_scene(1e-4, 1.0);
    s.model.params.time.integrator = Integrator::Verlet;
    s.model.params.fields.gravity = {};
    test::add_particle(s, 9, 0.001, {0, 0, 0.00105}, {0, 0, -4.0});
    s.model.materials[0].young = 1e5;
    const int g = s.barriers.group_index("floor");
    s.barriers.add(77, {-1, -1, 0}, {1, -1, 0}, {0, 1, 0}, g, 1e5, 0.3, {}, 0.0, NAN);
    const std::string msg = run_until_error(s, 1e-6, 2000);
    EXPECT_NE(msg.find("between particle id 9 and barrier element id 77"), std::string::npos) << msg;
  }
}

// A state that diverges within a step reaches a neighbour-list rebuild before the step's health
// scan (fuzz_checkpoint: a restored state whose trapezoidal iteration overflowed, then the
// evaluation's in-place rebuild). It is a RunError naming the particle id and the time, not the
// neighbour search's internal "particle at index N".
TEST(Instability, NonFinitePositionAtARebuildNamesTheParticle) {
  Scene s = test::make_scene(1e-4, 1.0);
  test::add_particle(s, 11, 0.001, {0, 0, 0});
  test::add_particle(s, 42, 0.001, {1, 0, 0});
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  sim.advance(1e-4);
  Particles& p = sim.particles();
  const std::size_t i = p.id[0] == 42 ? 0 : 1;
  p.x[i].y = std::numeric_limits<double>::infinity();
  try {
    sim.interactions().force_rebuild(p, sim.barriers(), false);
    ADD_FAILURE() << "no error";
  } catch (const RunError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("particle id 42 has a non-finite position at t = "), std::string::npos) << msg;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "not a RunError: " << e.what();
  }
}
