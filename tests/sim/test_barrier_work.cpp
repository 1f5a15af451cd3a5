// The work a barrier's prescribed motion does on the particles is booked (InteractionStats::
// barrier_work, the trapezoid of the drive power over committed steps) and taken off the energy
// balance, so that the balance of a driven system stays as constant as a closed one's and the
// energy checks apply to it. Checked against closed forms for an infinitely massive wall.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "integrate/energy_balance.hpp"
#include "sim/simulation.hpp"
#include "support/barrier_mechanics_scene.hpp"
#include "support/rotating_meshes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

// J, kinetic + rotational + potential + elastic + dissipated - barrier work.
double balance(Simulation& sim) {
  const ParticleEnergy e = particle_energy(sim.particles(), sim.model().params.fields.gravity);
  const InteractionStats& st = sim.interactions().stats();
  return e.kinetic + e.rotational + e.potential + st.elastic_energy + st.damping_dissipated + st.friction_dissipated -
         st.barrier_work;
}

}  // namespace

// A point mass at rest on a belt (a floor translating at U) is dragged by kinetic friction until
// it moves with the belt. The belt's force mu_d m g acts over the belt's travel U t_slip, with
// t_slip = U / (mu_d g): its work is m U^2, of which the particle keeps 1/2 m U^2 and friction
// dissipates the other half (within 1%); the balance with the work taken off stays within 1e-3 of
// that work, and the energy_jump check (on) does not stop the run.
TEST(BarrierWork, BeltDragsAParticleUpToItsSpeed) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double U = 0.1, dt = 2e-5;  // m/s, s
    Scene s = base_scene(integ, dt, {0.0, 0.0, -kG});
    s.model.params.analysis.rotation = false;
    s.model.params.checks.energy_jump = 0.01;
    ContactLawParams& c = s.model.params.contact.particle_barrier;
    c.restitution = 0.5;
    c.mu_static = 0.4;
    c.mu_dynamic = 0.4;
    MotionLaw belt;
    belt.a = {U, 0.0, 0.0};
    add_turntable(s.barriers, "belt", 0.2, 24, kE, kNu, belt);
    const double m = sphere_mass(kR);
    const double d = hertz_rest_overlap(m * kG, E_star(kE, kNu), kR);
    add_particle(s, 1, kR, {0.0, 0.05, kR - d});
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    sim.advance(dt);
    const double b0 = balance(sim);
    while (sim.time() < 0.1 - 0.5 * dt) sim.advance(dt);
    const InteractionStats& st = sim.interactions().stats();
    const double work = st.barrier_work, closed = m * U * U;
    const double drift = (balance(sim) - b0) / work;
    std::printf("[%s] barrier work %.6e J (m U^2 %.6e), friction %.6e J (1/2 m U^2 %.6e), |v| %.6f m/s, "
                "balance drift %.2e of the work\n",
                name(integ), work, closed, st.friction_dissipated, 0.5 * closed, sim.particles().v[0].x, drift);
    EXPECT_NEAR(sim.particles().v[0].x, U, 1e-6 * U);
    EXPECT_NEAR(work / closed, 1.0, 0.01);
    EXPECT_NEAR(st.friction_dissipated / (0.5 * closed), 1.0, 0.01);
    EXPECT_LT(std::abs(drift), 1e-3);
  }
}

// A rigid paddle turning at omega hits a sphere at rest, frictionless, with restitution e. The
// paddle's normal speed at the contact u_n hardly changes during the short impact, so its work is
// the impulse m (1 + e) u_n times u_n (within 1%), and the balance with it taken off stays within
// 1e-3 of that work (the energy_jump check, on, does not stop the run).
TEST(BarrierWork, TurningPaddleWorkIsTheImpulseTimesItsSpeed) {
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const double omega = 2.0, r = 0.06, phi0 = 0.1, e = 0.5, dt = 1e-6;  // rad/s, m, rad, -, s
    Scene s = paddle_scene(integ, dt, omega, r, phi0, e);
    s.model.params.checks.energy_jump = 0.01;
    Simulation sim(std::move(s), RunOptions{{}, false, false});
    sim.advance(dt);
    const double b0 = balance(sim);
    const InteractionStats& st = sim.interactions().stats();
    bool touched = false;
    while (sim.time() < 0.06) {
      sim.advance(dt);
      touched = touched || st.contacts_pb > 0;
      if (touched && st.contacts_pb == 0) break;  // the sphere has left the paddle
    }
    ASSERT_TRUE(touched);
    const double un = omega * std::sqrt(r * r - kR * kR);  // m/s
    const double closed = sphere_mass(kR) * (1.0 + e) * un * un;
    const double drift = (balance(sim) - b0) / st.barrier_work;
    std::printf("[%s] barrier work %.6e J, m (1 + e) u_n^2 %.6e J, balance drift %.2e of the work\n", name(integ),
                st.barrier_work, closed, drift);
    EXPECT_NEAR(st.barrier_work / closed, 1.0, 0.01);
    EXPECT_LT(std::abs(drift), 1e-3);
  }
}
