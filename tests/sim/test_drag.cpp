// [fields] drag = c (interact/body_forces.hpp): F = -c v on every particle that is not fixed, its
// work booked in the energy balance (field_dissipated). A sphere falling from rest follows
// v(t) = (m g / c)(1 - exp(-c t / m)) to the terminal speed m g / c.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "model/scene.hpp"
#include "integrate/energy_balance.hpp"
#include "sim/simulation.hpp"
#include "support/run_command.hpp"
#include "support/scene_builder.hpp"
#include "support/temp_dir.hpp"
#include "scene/scene_reader.hpp"

using namespace mpdem;

namespace {
constexpr double kR = 1e-3;    // m
constexpr double kG = 9.81;    // m/s^2
constexpr double kTau = 0.01;  // s, m / c
const char* name(Integrator i) { return i == Integrator::Verlet ? "verlet" : "trapezoidal"; }

struct Fall {
  double worst = 0.0;       // -, largest |v - v(t)| / v(t) over the steps
  double end_speed = 0.0;   // m/s
  double terminal = 0.0;    // m/s, m g / c
  double drift = 0.0;       // -, the balance's change over the fall / the work the drag dissipated
  double dissipated = 0.0;  // J, field_dissipated
};

// A sphere falls from rest for `taus` time constants m / c in steps of dt = kdt m / c. A second,
// fixed sphere moves at a constant velocity beside it: the drag must leave it alone.
Fall fall(Integrator integ, double kdt, double taus) {
  const double dt = kdt * kTau;
  Scene s = test::make_scene(dt, taus * kTau);
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  s.model.params.tolerance.velocity = 1e-13;
  s.model.params.tolerance.position = 1e-13;
  s.model.params.fields.gravity = {0.0, 0.0, -kG};
  test::add_particle(s, 1, kR, {0.0, 0.0, 0.0});
  const std::size_t f = test::add_particle(s, 2, kR, {1.0, 0.0, 0.0}, {0.0, 0.3, 0.0});
  s.particles.fixed[f] = 1;
  const double m = s.particles.mass[0], c = m / kTau;  // kg, N s/m
  s.model.params.fields.drag = c;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  const auto balance = [&] {
    const Particles& p = sim.particles();
    // The falling sphere's energies only: the fixed one's are held (its work is fixed_work).
    ParticleEnergy e;
    e.kinetic = 0.5 * p.mass[0] * norm2(p.v[0]);
    e.potential = -p.mass[0] * dot(sim.model().params.fields.gravity, p.x[0]);
    return energy_balance(e, 0.0, sim.interactions().stats(), BalanceScope{});
  };
  const double b0 = balance();
  Fall r;
  r.terminal = m * kG / c;
  const int steps = static_cast<int>(std::lround(taus / kdt));
  for (int k = 0; k < steps; ++k) {
    sim.advance(dt);
    const double t = sim.time(), exact = r.terminal * (1.0 - std::exp(-t / kTau));
    r.worst = std::max(r.worst, std::abs(-sim.particles().v[0].z - exact) / exact);
  }
  const Particles& p = sim.particles();
  EXPECT_EQ(p.v[1].x, 0.0);  // the fixed sphere keeps its velocity exactly
  EXPECT_EQ(p.v[1].y, 0.3);
  EXPECT_EQ(p.v[0].x, 0.0);  // the falling one falls straight
  r.end_speed = -p.v[0].z;
  r.dissipated = sim.interactions().stats().field_dissipated;
  r.drift = (balance() - b0) / r.dissipated;
  std::printf("[%s] c dt / m = %.0e, %.0f m/c: worst relative error %.2e, end speed %.9g m/s (m g/c %.9g), "
              "dissipated %.6e J, balance drift %.2e of it\n",
              name(integ), kdt, taus, r.worst, r.end_speed, r.terminal, r.dissipated, r.drift);
  return r;
}
}  // namespace

// The trapezoidal rule is second order (error about (c dt/m)^2 / 12 x c t / m): at c dt / m =
// 2e-3 the speed follows v(t) within 1e-6 relative over 15 m / c, where it has reached m g / c
// to 3e-7.
TEST(Drag, TrapezoidalFollowsTheExponentialToTerminalSpeed) {
  const Fall r = fall(Integrator::Trapezoidal, 2e-3, 15.0);
  EXPECT_LT(r.worst, 1e-6);
  EXPECT_NEAR(r.end_speed / r.terminal, 1.0, 1e-6);
}

// Velocity Verlet sees the half-kicked velocity, so its speed is first order (error about
// c dt / (2 m)): at c dt / m = 1e-6 it follows v(t) within 1e-6 relative over 2 m / c; at a coarse
// step it still ends at m g / c, its fixed point (15 m / c: 3e-7 short of it).
TEST(Drag, VerletFollowsTheExponentialToTerminalSpeed) {
  EXPECT_LT(fall(Integrator::Verlet, 1e-6, 2.0).worst, 1e-6);
  const Fall r = fall(Integrator::Verlet, 1e-3, 15.0);
  EXPECT_NEAR(r.end_speed / r.terminal, 1.0, 1e-6);
}

// The energy balance with the drag's work stays closed as for gravity (FixedParticles'
// EnergyBalanceClosedWithAMovingFixedParticle): what is left is the integrator's own error, small
// and shrinking with dt (Verlet first order: halving dt halves it), not a booking error.
TEST(Drag, EnergyBalanceClosed) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const Fall coarse = fall(integ, 2e-2, 5.0), fine = fall(integ, 1e-2, 5.0);
    EXPECT_GT(fine.dissipated, 0.0);
    EXPECT_LT(std::abs(fine.drift), 1e-3);
    if (integ == Integrator::Verlet) EXPECT_NEAR(coarse.drift / fine.drift, 2.0, 0.4);
    else EXPECT_LT(std::abs(fine.drift), std::abs(coarse.drift));
  }
}

// A run checkpointed half way (the drag's work in the section "fields") and resumed continues
// bitwise as the uninterrupted run, its booked work included.
TEST(Drag, CheckpointResumeKeepsTheWork) {
  test::TempDir d("mpdem_drag");
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const auto scene = [integ] {
      Scene s = test::make_scene(1e-4, 1.0);
      s.model.params.time.integrator = integ;
      s.model.params.fields.gravity = {0.0, 0.0, -kG};
      test::add_particle(s, 1, kR, {0.0, 0.0, 0.0}, {0.01, 0.0, 0.0});
      s.model.params.fields.drag = s.particles.mass[0] / kTau;
      return s;
    };
    Simulation full(scene(), RunOptions{{}, false, false});
    for (int k = 0; k < 100; ++k) full.advance(1e-4);
    full.write_checkpoint(d.path / "ck.bin");
    for (int k = 0; k < 100; ++k) full.advance(1e-4);
    Simulation resumed(scene(), RunOptions{{}, false, false});
    resumed.resume_from(d.path / "ck.bin");
    for (int k = 0; k < 100; ++k) resumed.advance(1e-4);
    const InteractionStats &a = full.interactions().stats(), &b = resumed.interactions().stats();
    EXPECT_GT(a.field_dissipated, 0.0) << name(integ);
    EXPECT_EQ(a.field_dissipated, b.field_dissipated) << name(integ);
    EXPECT_EQ(a.field_power, b.field_power) << name(integ);
    EXPECT_EQ(full.particles().v[0], resumed.particles().v[0]) << name(integ);
  }
}

// The reader maps the key (default 0: no drag, and no field_dissipated column).
TEST(Drag, ReaderMapsTheKey) {
  test::TempDir d("mpdem_drag");
  const std::string head = "[time]\nduration = 0.001\ndt = 1e-5\n[[material]]\nname = \"glass\"\n";
  EXPECT_EQ(parse_scene_file(d.write("a.toml", head + "[fields]\ndrag = 0.25\n")).model.params.fields.drag, 0.25);
  EXPECT_EQ(parse_scene_file(d.write("b.toml", head)).model.params.fields.drag, 0.0);
}

// A negative drag is bad input: one message naming file, line and key, exit status 2.
TEST(Drag, NegativeDragIsRefused) {
  test::TempDir d("mpdem_drag");
  d.write("p.csv", "x,y,z,radius\n0,0,0,0.001\n");
  d.write("scene.toml", "[time]\nduration = 0.001\ndt = 1e-5\n[[material]]\nname = \"glass\"\n"
                        "[[particles]]\nfile = \"p.csv\"\n[fields]\ndrag = -0.5\n");
  for (const char* cmd : {"check scene.toml", "run scene.toml --quiet"}) {
    const test::CommandResult r = test::run_mpdem(cmd, d.path);
    EXPECT_EQ(r.status, 2) << cmd << "\n" << r.err;
    EXPECT_NE(r.err.find("scene.toml:9: 'fields.drag': expected a number >= 0, got -0.5"), std::string::npos)
        << cmd << ": " << r.err;
  }
}
