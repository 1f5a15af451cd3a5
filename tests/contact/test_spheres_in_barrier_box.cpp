// Many spheres in an open box of triangles through the whole engine (physics.md sections 5-7, 12): a
// settled bed's loads and energy bookkeeping; 1- vs 2-thread bitwise loads; history through rebuilds.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <map>
#include <random>
#include <vector>

#include "core/parallel.hpp"
#include "integrate/integrator_policy.hpp"
#include "model/material_variants.hpp"
#include "integrate/energy_balance.hpp"
#include "interact/interactions.hpp"
#include "sim/simulation.hpp"
#include "support/barrier_mechanics_scene.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"

using namespace mpdem;
using namespace mpdem::test;  // kR, kE, kNu, kG, kRho, kPi, sphere_mass, E_star, name, base_scene

// A bed of 2000 spheres (800 under ASan) (20 x 20 x 5 lattice with jitter) settles in an open box of triangles
// (Verlet, dt near the recommended step, e = 0.1, friction). Once settled the bottom group's
// vertical force equals the total weight within 1%. Energy bookkeeping
// kinetic + rotational + potential + elastic + damping + friction dissipated stays constant within
// 15% of the energy dissipated: at this coarse step (contact time / dt ~ 13) the dissipation,
// integrated per step from the evaluated powers (Verlet half-step velocities), and the
// history-dependent tangential spring energy 1/2 k_t s^2 are first-order approximations; the
// drift shrinks ~6x when dt is halved (measured), so it is discretisation, not a leak.
TEST(SettledBed, FloorCarriesWeightAndEnergyIsBookkept) {
  // dt = 1e-4 s: 0.2 x Rayleigh time is 1.1e-4 s for R = 2 mm, E = 1 MPa.
  const double R = 0.002, E = 1e6, spacing = 2.2 * R, dt = 1e-4, T_end = 0.25;
#ifdef __SANITIZE_ADDRESS__
  const int nx = 20, nz = 2;  // smaller variant under ASan (800 spheres), same physics
#else
  const int nx = 20, nz = 5;  // 2000 spheres
#endif
  const double W = nx * spacing;
  Scene s = base_scene(Integrator::Verlet, dt, {0.0, 0.0, -kG});
  test::set_material(s, kRho, E, kNu);
  test::add_open_box(s.barriers, W, 6.0 * spacing, 4, E, kNu);
  ContactLawParams& pp = s.model.params.contact.particle_particle;
  pp.restitution = 0.1;
  pp.mu_static = 0.5;
  pp.mu_dynamic = 0.4;
  pp.tangential_damping = 0.3;
  s.model.params.contact.particle_barrier = pp;
  std::mt19937_64 rng(2024);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::int64_t id = 0;
  for (int l = 0; l < nz; ++l)
    for (int j = 0; j < nx; ++j)
      for (int i = 0; i < nx; ++i) {
        const Vec3 x{(i + 0.5) * spacing + 0.05 * R * U(rng), (j + 0.5) * spacing + 0.05 * R * U(rng),
                     1.1 * R + l * spacing};
        test::add_particle(s, ++id, R, x, 0.05 * Vec3{U(rng), U(rng), U(rng)});
      }
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  const Vec3 g = sim.model().params.fields.gravity;
  auto total_energy = [&] {
    const ParticleEnergy pe = particle_energy(sim.particles(), g);
    const InteractionStats& st = sim.interactions().stats();
    return pe.kinetic + pe.rotational + pe.potential + st.elastic_energy + st.damping_dissipated +
           st.friction_dissipated;
  };
  sim.initialize();
  const double E0 = total_energy();
  double worst_drift = 0.0;
  while (sim.time() < T_end) {
    sim.advance(dt);
    if (sim.steps() % 50 == 0) worst_drift = std::max(worst_drift, std::abs(total_energy() - E0));
  }
  double weight = 0.0;
  for (std::size_t i = 0; i < sim.particles().size(); ++i) weight += sim.particles().mass[i] * kG;
  const Vec3 Fb = test::group_force(sim.barriers(), "bottom"), Fw = test::group_force(sim.barriers(), "walls");
  const InteractionStats& st = sim.interactions().stats();
  const double dissipated = st.damping_dissipated + st.friction_dissipated;
  const ParticleEnergy pe = particle_energy(sim.particles(), g);
  std::printf("bed: N %zu, bottom / weight - 1 = %.2e, walls vertical / weight = %.2e, (bottom+walls)/weight - 1 = "
              "%.2e, kinetic %.2e J, energy drift %.2e J of dissipated %.2e J (%.2e)\n",
              sim.particles().size(), -Fb.z / weight - 1, -Fw.z / weight, -(Fb.z + Fw.z) / weight - 1, pe.kinetic,
              worst_drift, dissipated, worst_drift / dissipated);
  EXPECT_NEAR(-Fb.z / weight, 1.0, 0.01);
  EXPECT_NEAR(-(Fb.z + Fw.z) / weight, 1.0, 2e-3);  // floor + wall friction carry it all
  EXPECT_LT(worst_drift, 0.15 * dissipated);
  EXPECT_GT(dissipated, 0.0);
}

namespace {

// A layer of nx x nx spheres on the floor of an open box (4 x 4-cell floor: seams), sliding
// and spinning with random velocities; `gap` x R between neighbours' surfaces.
Scene sliding_layer(Integrator integ, int nx, double gap, double dt) {
  const double R = 0.002, spacing = (2.0 + gap) * R, W = nx * spacing;
  Scene s = base_scene(integ, dt, {0.0, 0.0, -kG});
  test::add_open_box(s.barriers, W, 4.0 * R, 4, kE, kNu);
  ContactLawParams& c = s.model.params.contact.particle_barrier;
  c.restitution = 0.3;
  c.mu_static = 0.5;
  c.mu_dynamic = 0.3;
  c.mu_rolling = 0.02;
  c.tangential_damping = 0.3;
  s.model.params.contact.particle_particle = c;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::int64_t id = 0;
  for (int j = 0; j < nx; ++j)
    for (int i = 0; i < nx; ++i) {
      // Outer rows pressed slightly into the walls, so wall elements carry loads too.
      const double x = i == 0 ? 0.999 * R : (i == nx - 1 ? W - 0.999 * R : (i + 0.5) * spacing);
      const double y = j == 0 ? 0.999 * R : (j == nx - 1 ? W - 0.999 * R : (j + 0.5) * spacing);
      test::add_particle(s, ++id, R, {x, y, 0.998 * R}, 0.2 * Vec3{U(rng), U(rng), 0.0},
                         (0.2 / R) * Vec3{U(rng), U(rng), U(rng)});
    }
  return s;
}

struct Loads {
  std::vector<Vec3> bf, bm, pf, pt;  // barrier force N, moment N m; particle force N, torque N m (by index)
  std::size_t contacts_pb = 0;
};

Loads run_layer(int threads, Integrator integ) {
  omp_set_num_threads(threads);
  const double dt = 2e-5;
  Scene s = sliding_layer(integ, 50, 0.1, dt);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < 40; ++k) sim.advance(dt);
  Loads l{sim.barriers().force, sim.barriers().moment, sim.particles().force, sim.particles().torque,
          sim.interactions().stats().contacts_pb};
  return l;
}

std::size_t bitwise_differences(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  if (a.size() != b.size()) return std::max(a.size(), b.size());
  std::size_t d = 0;
  for (std::size_t i = 0; i < a.size(); ++i) d += std::memcmp(&a[i], &b[i], sizeof(Vec3)) != 0;
  return d;
}

}  // namespace

// 2500 spheres against 64 triangles (floor and walls), more than kParallelThreshold of them near
// a barrier: the element loads (force, moment) and the particle forces and torques are bitwise
// identical for 1 and 2 OpenMP threads.
TEST(BarrierContactsParallel, BitwiseIdenticalForOneAndTwoThreads) {
  static_assert(50 * 50 > kParallelThreshold, "the barrier contacts must take the parallel paths");
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const Loads one = run_layer(1, integ);
    const Loads two = run_layer(2, integ);
    EXPECT_GT(one.contacts_pb, kParallelThreshold);
    std::size_t loaded = 0;
    for (const Vec3& f : one.bf) loaded += norm2(f) > 0.0;
    EXPECT_GT(loaded, 32u);  // the 32 floor elements and wall elements
    EXPECT_EQ(one.contacts_pb, two.contacts_pb);
    EXPECT_EQ(bitwise_differences(one.bf, two.bf), 0u) << name(integ);
    EXPECT_EQ(bitwise_differences(one.bm, two.bm), 0u) << name(integ);
    EXPECT_EQ(bitwise_differences(one.pf, two.pf), 0u) << name(integ);
    EXPECT_EQ(bitwise_differences(one.pt, two.pt), 0u) << name(integ);
  }
  omp_set_num_threads(omp_get_num_procs());
}

// Spheres sliding and rolling on a seamed floor and against walls, apart from each other (each
// particle's forces then come from its barrier contacts alone). After the springs have built up,
// a forced rebuild that reorders the particles, and the removal of some particles, leave the
// forces and torques of an evaluation (which uses the springs, the start-of-step tangential
// velocities and rotations) bitwise unchanged for every remaining particle; without the history
// they would differ.
TEST(BarrierContactHistory, SurvivesReorderingRebuildAndRemoval) {
  const double dt = 2e-5;
  Scene s = sliding_layer(Integrator::Trapezoidal, 12, 4.0, dt);
  const Scene fresh_scene = s;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  // The steps reorder at every rebuild (every ~37 steps here); stopping halfway between two
  // leaves the particles far enough out of order for the forced reordering below to move them.
  for (int k = 0; k < 135; ++k) sim.advance(dt);
  Particles& p = sim.particles();
  Barriers& b = sim.barriers();
  Interactions& in = sim.interactions();
  const EvalRequest req{sim.time() + dt, dt, 0.5, false, 1};  // an iteration: uses every history field
  const auto by_id = [&p] {
    std::map<std::int64_t, std::array<Vec3, 2>> m;
    for (std::size_t i = 0; i < p.size(); ++i) m[p.id[i]] = {p.force[i], p.torque[i]};
    return m;
  };
  const auto equal = [](const std::map<std::int64_t, std::array<Vec3, 2>>& a,
                        const std::map<std::int64_t, std::array<Vec3, 2>>& c) {
    std::size_t d = 0;
    for (const auto& [id, ft] : c) d += std::memcmp(&a.at(id), &ft, sizeof ft) != 0;
    return d;
  };
  in.evaluate(p, b, req);
  const auto before = by_id();
  EXPECT_GT(in.stats().contacts_pb, p.size() / 2);  // on the floor, some also on walls
  EXPECT_EQ(in.stats().contacts_pp, 0u);

  std::vector<std::int64_t> ids_before(p.id.begin(), p.id.end());
  in.force_rebuild(p, b, true);
  EXPECT_NE(ids_before, p.id);  // the rebuild did reorder
  in.evaluate(p, b, req);
  EXPECT_EQ(equal(before, by_id()), 0u);

  std::vector<char> keep(p.size(), 1);
  for (std::size_t i = 0; i < p.size(); ++i) keep[i] = p.id[i] % 5 != 2;
  in.remove_particles(p, b, keep);
  in.evaluate(p, b, req);
  EXPECT_LT(p.size(), ids_before.size());
  EXPECT_EQ(equal(before, by_id()), 0u);

  // The same state without any history gives other forces: the test sees the history.
  Scene bare = fresh_scene;
  bare.particles = p;
  resolve_material_variants(bare.model, bare.particles, bare.barriers, "");
  Interactions fresh(bare.model, bare.particles, bare.barriers, integrator_policy(bare.model.params));
  fresh.evaluate(bare.particles, bare.barriers, req);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    differ += std::memcmp(&bare.particles.force[i], &p.force[i], sizeof(Vec3)) != 0;
  EXPECT_GT(differ, p.size() / 2);
}
