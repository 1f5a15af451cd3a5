// Time integration (physics.md section 9) and field forces (section 3) against closed forms:
// free fall, first-order convergence of phi = 0 and 1, charged particles in uniform E, B, E x B.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/run_error.hpp"
#include "sim/simulation.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

namespace {
constexpr Vec3 kG{0.3, -0.2, -9.81};

// Free fall of one sphere for `steps` steps of dt; returns the final position error.
Vec3 free_fall_error(Integrator integ, double phi, double dt, int steps) {
  Scene s = test::make_scene(dt, dt * steps);
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = phi;
  s.model.params.fields.gravity = kG;
  const Vec3 x0{1.0, 2.0, 3.0}, v0{0.5, -1.0, 2.0};
  test::add_particle(s, 7, 0.001, x0, v0);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < steps; ++k) sim.advance(dt);
  const double t = sim.time();
  const Vec3 exact = x0 + v0 * t + 0.5 * t * t * kG;
  EXPECT_LT(norm(sim.particles().v[0] - (v0 + t * kG)), 1e-12 * (1.0 + norm(v0 + t * kG)));
  return sim.particles().x[0] - exact;
}
}  // namespace

TEST(FreeFall, ExactForVerletAndTrapezoidal) {
  // Constant acceleration: both schemes are exact; only round-off remains (relative 1e-12).
  EXPECT_LT(norm(free_fall_error(Integrator::Verlet, 0.5, 1e-3, 1000)), 1e-12 * 10.0);
  EXPECT_LT(norm(free_fall_error(Integrator::Trapezoidal, 0.5, 1e-3, 1000)), 1e-12 * 10.0);
}

TEST(FreeFall, FirstOrderForPhiZeroAndOne) {
  for (double phi : {0.0, 1.0}) {
    const double e1 = norm(free_fall_error(Integrator::Trapezoidal, phi, 2e-3, 500));
    const double e2 = norm(free_fall_error(Integrator::Trapezoidal, phi, 1e-3, 1000));
    EXPECT_GT(e1, 1e-4);                                // a real, first-order error
    EXPECT_NEAR(e1 / e2, 2.0, 0.1) << "phi = " << phi;  // halving dt halves the error (5%)
    // and the error is g t dt / 2 in size, pointing along -g (phi = 0) or +g (phi = 1)
    const Vec3 err = free_fall_error(Integrator::Trapezoidal, phi, 1e-3, 1000);
    const Vec3 expected = (phi == 0.0 ? -0.5 : 0.5) * 1.0 * 1e-3 * kG;
    EXPECT_LT(norm(err - expected), 1e-9);
  }
}

namespace {
Scene charged_scene(double dt, const Vec3& E, const Vec3& B, const Vec3& v0) {
  Scene s = test::make_scene(dt, 1.0);
  s.model.params.time.phi = 0.5;
  s.model.params.fields.gravity = {};
  s.model.params.fields.electric = E;
  s.model.params.fields.magnetic = B;
  s.model.params.tolerance.velocity = 1e-10;
  s.model.params.tolerance.position = 1e-10;
  test::add_particle(s, 1, 0.001, {}, v0);
  s.particles.charge[0] = 2e-6;
  return s;
}
}  // namespace

TEST(ChargedParticle, UniformElectricFieldParabola) {
  const Vec3 E{300.0, 0.0, -100.0}, v0{0.0, 1.0, 0.5};
  const double dt = 1e-3;
  Scene s = charged_scene(dt, E, {}, v0);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  const Vec3 a = (sim.particles().charge[0] / sim.particles().mass[0]) * E;
  for (int k = 0; k < 500; ++k) {
    sim.advance(dt);
    const double t = sim.time();
    const Vec3 exact = v0 * t + 0.5 * t * t * a;
    ASSERT_LT(norm(sim.particles().x[0] - exact), 1e-12 * (1.0 + norm(exact))) << "step " << k;
  }
}

TEST(ChargedParticle, LarmorOrbitInUniformMagneticField) {
  const double B = 0.5, v = 2.0;
  Scene s = charged_scene(1.0, {}, {0, 0, B}, {v, 0, 0});
  const double q = s.particles.charge[0], m = s.particles.mass[0];
  const double omega = std::abs(q) * B / m, period = 2 * std::numbers::pi / omega, radius = m * v / (std::abs(q) * B);
  const double dt = period / 400.0;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  // Positive charge, B along z: clockwise gyration about the centre (0, -radius).
  const Vec3 centre{0.0, -radius, 0.0};
  double rmin = 1e300, rmax = 0.0, vdev = 0.0;
  double last_cross = -1.0, first_cross = -1.0;
  int crossings = 0;
  double prev_y = sim.particles().x[0].y + radius;
  for (int k = 0; k < 4000; ++k) {  // 10 gyrations
    sim.advance(dt);
    const Vec3& x = sim.particles().x[0];
    const double r = norm(x - centre);
    rmin = std::min(rmin, r);
    rmax = std::max(rmax, r);
    vdev = std::max(vdev, std::abs(norm(sim.particles().v[0]) - v) / v);
    // upward crossings of the line y = centre.y on the left (x < 0) side: one per period
    const double y = x.y + radius;
    if (prev_y < 0.0 && y >= 0.0 && x.x < 0.0) {
      const double tc = sim.time() - dt * y / (y - prev_y);
      if (first_cross < 0.0) first_cross = tc;
      last_cross = tc;
      ++crossings;
    }
    prev_y = y;
  }
  EXPECT_NEAR(rmin / radius, 1.0, 1e-3);
  EXPECT_NEAR(rmax / radius, 1.0, 1e-3);
  ASSERT_GE(crossings, 9);
  EXPECT_NEAR((last_cross - first_cross) / (crossings - 1) / period, 1.0, 1e-3);
  EXPECT_LT(vdev, 10.0 * sim.model().params.tolerance.velocity);  // |v| conserved over 10 gyrations
}

TEST(ChargedParticle, CrossedFieldsDrift) {
  const Vec3 E{0.0, 200.0, 0.0}, B{0.0, 0.0, 0.4};
  Scene s = charged_scene(1.0, E, B, {});
  const double omega = std::abs(s.particles.charge[0]) * norm(B) / s.particles.mass[0];
  const double period = 2 * std::numbers::pi / omega;
  const int per = 400;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < 10 * per; ++k) sim.advance(period / per);
  // Started at rest: a cycloid whose mean velocity over whole periods is the drift E x B / B^2.
  const Vec3 drift = cross(E, B) / norm2(B);
  const Vec3 mean_v = sim.particles().x[0] / sim.time();
  EXPECT_LT(norm(mean_v - drift) / norm(drift), 1e-3);
}

TEST(Trapezoidal, NonConvergenceIsAClearError) {
  // A stiff velocity-dependent force with a huge step: the fixed-point map does not contract.
  Scene s = charged_scene(1.0, {}, {0, 0, 1e3}, {1.0, 0, 0});
  s.model.params.time.max_iterations = 20;
  const double omega = s.particles.charge[0] * 1e3 / s.particles.mass[0];
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  try {
    sim.advance(10.0 / omega);
    FAIL() << "expected a RunError";
  } catch (const RunError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("did not converge within 20 iterations"), std::string::npos) << msg;
    EXPECT_NE(msg.find("particle id 1"), std::string::npos) << msg;
    EXPECT_NE(msg.find("Reduce time.dt"), std::string::npos) << msg;
  }
  // The state is the start-of-step state, untouched.
  EXPECT_EQ(sim.particles().x[0], (Vec3{0, 0, 0}));
  EXPECT_EQ(sim.particles().v[0], (Vec3{1, 0, 0}));
}

TEST(Trapezoidal, ContactOnsetWithTinyStepsConverges) {
  // At first touch the nonlinear damping coefficient grows like overlap^(1/4): the end-of-step
  // force jumps between "no contact" and "damped contact" across round-off overlaps, so the
  // fixed-point iteration alternates without a fixed point. The integrator must recognise the
  // tiny two-cycle and accept its midpoint rather than fail; the collision keeps its restitution.
  const double dt = 2e-7;
  Scene s = test::make_scene(dt, 1.0);
  s.model.params.fields.gravity = {};
  s.model.params.contact.particle_particle.restitution = 0.8;
  s.model.params.tolerance.velocity = s.model.params.tolerance.position = 1e-6;
  test::add_particle(s, 1, 0.005, {0.0, 0, 0});
  test::add_particle(s, 2, 0.005, {0.0205, 0, 0}, {-1.5, 0, 0});
  s.model.materials[0].young = 1e8;  // both spheres
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  int cycles = 0;
  for (int k = 0; k < 40000; ++k) cycles += sim.advance(dt).two_cycle ? 1 : 0;
  EXPECT_GT(cycles, 0);  // the situation this test is about did occur
  const double e = (sim.particles().v[1].x - sim.particles().v[0].x) / 1.5;
  EXPECT_NEAR(e, 0.8, 0.005);
  EXPECT_NEAR(sim.particles().v[0].x + sim.particles().v[1].x, -1.5, 1e-9);  // momentum
}
