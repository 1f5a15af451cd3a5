// Instability detection: non-finite states and energy jumps stop the run with a message naming
// particle ids, time and step.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "sim/run_error.hpp"
#include "sim/simulation.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

namespace {
std::string run_until_error(Scene& s, double dt, int steps) {
  Simulation sim(s, RunOptions{{}, false, false});
  try {
    for (int k = 0; k < steps; ++k) sim.advance(dt);
  } catch (const RunError& e) {
    return e.what();
  }
  return "";
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
    s.model.params.time.phi = 0.0;  // explicit: no convergence failure to hide the blow-up
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
  // The same collision with a step of 1/100 of the contact time passes every check.
  Scene s = test::make_scene(1e-4, 1.0);
  s.model.params.time.integrator = Integrator::Verlet;
  s.model.params.fields.gravity = {};
  test::add_particle(s, 5, 0.001, {0, 0, 0}, {1.0, 0, 0});
  test::add_particle(s, 6, 0.001, {0.00205, 0, 0}, {-1.0, 0, 0});
  EXPECT_EQ(run_until_error(s, 1e-6, 400), "");
  EXPECT_LT(s.particles.v[0].x, 0.0);  // they did collide and rebound
}
