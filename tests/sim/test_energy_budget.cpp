// The energy budget of a closed frictional system (physics.md section 12, docs/output.md):
// kinetic + rotational + potential + stored elastic + dissipated (damping, sliding, rolling)
// stays constant while a granular gas in a closed box of triangles cools by inelastic,
// frictional collisions.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <utility>

#include "integrate/energy_balance.hpp"
#include "sim/simulation.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;

namespace {

constexpr double kR = 0.002;  // m
constexpr double kL = 0.03;   // m, box side

// Rectangle a-b-c-d as two triangles.
void add_rect(Scene& s, std::int64_t& next, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
  const Material& m = s.model.materials.front();
  const int g = s.barriers.group_index("box");
  s.barriers.add(next++, a, b, c, g, m.young, m.poisson, MotionLaw{}, 0.0, kNaN);
  s.barriers.add(next++, a, c, d, g, m.young, m.poisson, MotionLaw{}, 0.0, kNaN);
}

// 64 spheres on a lattice with random velocities (1 m/s) and spins in a closed box [0, L]^3,
// no gravity: a granular gas, e = 0.5, Coulomb friction mu_s / mu_d, rolling resistance mu_r.
Scene gas(Integrator integ, double dt, double mu_s, double mu_d, double mu_r) {
  Scene s = test::make_scene(dt, 1.0);
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  s.model.params.analysis.rotation = true;
  s.model.params.fields.gravity = {};
  Material& m = s.model.materials.front();
  m.density = 2500.0;
  m.young = 1e8;
  m.poisson = 0.3;
  for (ContactLawParams* c : {&s.model.params.contact.particle_particle, &s.model.params.contact.particle_barrier}) {
    c->restitution = 0.5;
    c->mu_static = mu_s;
    c->mu_dynamic = mu_d;
    c->mu_rolling = mu_r;
  }
  std::int64_t next = 1;
  const double L = kL;
  add_rect(s, next, {0, 0, 0}, {L, 0, 0}, {L, L, 0}, {0, L, 0});
  add_rect(s, next, {0, 0, L}, {0, L, L}, {L, L, L}, {L, 0, L});
  add_rect(s, next, {0, 0, 0}, {0, L, 0}, {0, L, L}, {0, 0, L});
  add_rect(s, next, {L, 0, 0}, {L, 0, L}, {L, L, L}, {L, L, 0});
  add_rect(s, next, {0, 0, 0}, {0, 0, L}, {L, 0, L}, {L, 0, 0});
  add_rect(s, next, {0, L, 0}, {L, L, 0}, {L, L, L}, {0, L, L});
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const int n = 4;
  const double a = L / n;
  std::int64_t id = 0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
        test::add_particle(s, ++id, kR, {a * (i + 0.5), a * (j + 0.5), a * (k + 0.5)}, Vec3{u(rng), u(rng), u(rng)},
                           (1.0 / kR) * Vec3{u(rng), u(rng), u(rng)});
  return s;
}

struct Budget {
  double drift = 0.0;       // -, largest |total(t) - total(0)| / total(0)
  double dissipated = 0.0;  // -, dissipated / total(0) at the end
};

Budget run(Integrator integ, double dt, double duration, double mu_s, double mu_d, double mu_r) {
  Simulation sim(gas(integ, dt, mu_s, mu_d, mu_r), RunOptions{{}, false, false});
  auto total = [&] {
    const ParticleEnergy pe = particle_energy(sim.particles(), Vec3{});
    const InteractionStats& st = sim.interactions().stats();
    return pe.kinetic + pe.rotational + pe.potential + st.elastic_energy + st.damping_dissipated +
           st.friction_dissipated;
  };
  sim.initialize();
  const double E0 = total();
  Budget b;
  while (sim.time() < duration) {
    sim.advance(dt);
    b.drift = std::max(b.drift, std::abs(total() - E0) / E0);
  }
  const InteractionStats& st = sim.interactions().stats();
  b.dissipated = (st.damping_dissipated + st.friction_dissipated) / E0;
  return b;
}

}  // namespace

// Every mechanism is booked where it happens: what is left, the drift, is the time
// discretisation's, so halving dt halves it at least (measured: ratio 2.0 Verlet, 1.85
// trapezoidal; the bookings of docs/physics.md section 12 are first-order), with static >
// dynamic friction (the spring cut at every stick-to-slip transition) as with equal
// coefficients and rolling resistance. A mechanism left unbooked (before: the energy released at
// each stick-to-slip transition) does not shrink with dt. Bounds: the drift at the coarse step,
// measured 2.6 % (Verlet) and 1.1 % (trapezoidal) of the start energy.
TEST(EnergyBudget, FrictionalGasInClosedBox) {
  const double dt = 4e-6, duration = 0.1;  // s; contact time about 120 dt at the typical speed
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal})
    for (const auto& [mu_s, mu_r] : {std::pair{0.4, 0.0}, std::pair{0.5, 0.05}}) {
      const Budget coarse = run(integ, dt, duration, mu_s, 0.4, mu_r);
      const Budget fine = run(integ, 0.5 * dt, duration, mu_s, 0.4, mu_r);
      std::printf("gas %s mu_s %.1f mu_r %.2f: dissipated %.3f of the start energy, drift %.2e (dt), %.2e (dt/2): "
                  "ratio %.2f\n",
                  integ == Integrator::Verlet ? "verlet" : "trapezoidal", mu_s, mu_r, coarse.dissipated, coarse.drift,
                  fine.drift, coarse.drift / fine.drift);
      EXPECT_GT(coarse.dissipated, 0.3);
      EXPECT_LT(coarse.drift, integ == Integrator::Verlet ? 0.03 : 0.015);
      EXPECT_GT(coarse.drift / fine.drift, 1.6);
    }
}
