// Cohesive contacts (contact/cohesive_contact.hpp) keep the engine's invariances: a wet,
// adhesive layer of 2500 spheres (JKR necks and Willett bridges between the spheres and with the
// box) colliding at random, whose necks break and bridges rupture within the run, gives bitwise
// the same state for 1 and 2 OpenMP threads and resumed from a checkpoint taken before some of
// the breaks, and the same to rounding (1e-9) with extra rebuilds that reorder the particles (the
// contact history follows them; the sums' order changes), in both integrators.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>

#include "core/parallel.hpp"
#include "sim/simulation.hpp"
#include "support/cohesive_scenes.hpp"
#include "support/contact_scenes.hpp"
#include "support/scene_builder.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;

namespace {

constexpr double kR = 1e-3, kDt = 2e-6;
constexpr int kSide = 50;
constexpr std::uint64_t kSteps = 400;

Scene wet_layer(Integrator integ) {
  const double spacing = 2.1 * kR, W = kSide * spacing;
  Scene s = test::make_scene(kDt, 1.0);
  s.model.params.time.integrator = integ;
  s.model.params.fields.gravity = {0.0, 0.0, -9.81};
  s.model.params.checks.max_overlap = 0.0;
  test::set_material(s, 2500.0, 1e7, 0.3);
  test::add_open_box(s.barriers, W, 4.0 * kR, 4, 1e7, 0.3);
  test::make_wet(s, 0.05, 0.5, 0.07, 1e-3);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> U(-1.0, 1.0);
  std::int64_t id = 0;
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i)
      test::add_particle(s, ++id, kR, {(i + 0.5) * spacing, (j + 0.5) * spacing, 1.2 * kR},
                         Vec3{U(rng), U(rng), -0.2 * (1.0 + U(rng))}, (0.5 / kR) * Vec3{U(rng), U(rng), U(rng)});
  return s;
}

// Runs to kSteps; every `rebuild_every` steps (0: never) a forced rebuild that reorders.
void run(Simulation& sim, std::uint64_t rebuild_every = 0) {
  while (sim.steps() < kSteps) {
    sim.advance(kDt);
    if (rebuild_every > 0 && sim.steps() % rebuild_every == 0)
      sim.interactions().force_rebuild(sim.particles(), sim.barriers(), true);
  }
}

// Bitwise alike, particle by particle in id order.
void expect_same(Simulation& a, Simulation& b) {
  const Particles &p = a.particles(), &q = b.particles();
  ASSERT_EQ(p.size(), q.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t j = test::index_of(q, p.id[i]);
    differ += std::memcmp(&p.x[i], &q.x[j], sizeof(Vec3)) != 0 || std::memcmp(&p.v[i], &q.v[j], sizeof(Vec3)) != 0 ||
              std::memcmp(&p.w[i], &q.w[j], sizeof(Vec3)) != 0;
  }
  EXPECT_EQ(differ, 0u);
  const InteractionStats &s = a.interactions().stats(), &t = b.interactions().stats();
  EXPECT_EQ(s.bridges, t.bridges);
  EXPECT_EQ(s.ruptures, t.ruptures);
  EXPECT_EQ(s.cohesion_breaks, t.cohesion_breaks);
  EXPECT_EQ(s.cohesion_dissipated, t.cohesion_dissipated);
  EXPECT_EQ(s.contacts_pp, t.contacts_pp);
  EXPECT_EQ(s.contacts_pb, t.contacts_pb);
}

// Reordered particles sum their contacts in another order: alike to rounding, matched by id.
// Positions relative to R, velocities to the largest speed.
void expect_close(Simulation& a, Simulation& b, double tol) {
  const Particles &p = a.particles(), &q = b.particles();
  ASSERT_EQ(p.size(), q.size());
  double vmax = 0.0, dx = 0.0, dv = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) vmax = std::max(vmax, norm(p.v[i]));
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t j = test::index_of(q, p.id[i]);
    dx = std::max(dx, norm(p.x[i] - q.x[j]) / kR);
    dv = std::max(dv, norm(p.v[i] - q.v[j]) / vmax);
  }
  std::printf("reordering rebuilds: max difference x %.2e R, v %.2e of the largest speed\n", dx, dv);
  EXPECT_LT(dx, tol);
  EXPECT_LT(dv, tol);
  EXPECT_EQ(a.interactions().stats().ruptures, b.interactions().stats().ruptures);
  EXPECT_EQ(a.interactions().stats().cohesion_breaks, b.interactions().stats().cohesion_breaks);
}

const char* name(Integrator i) { return i == Integrator::Verlet ? "verlet" : "trapezoidal"; }

}  // namespace

TEST(CohesiveInvariance, ThreadsRebuildsAndResume) {
  static_assert(kSide * kSide > kParallelThreshold, "the kernels must take their parallel paths");
  test::TempDir dir("mpdem_cohesive_resume");
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(name(integ));
    omp_set_num_threads(1);
    Simulation one(wet_layer(integ), RunOptions{{}, false, false});
    run(one);
    const InteractionStats& st = one.interactions().stats();
    std::printf("%s: %llu bridges held, %llu ruptured, %llu necks broken, %.3e J dissipated by them, %zu + %zu "
                "contacts\n",
                name(integ), static_cast<unsigned long long>(st.bridges), static_cast<unsigned long long>(st.ruptures),
                static_cast<unsigned long long>(st.cohesion_breaks), st.cohesion_dissipated, st.contacts_pp,
                st.contacts_pb);
    EXPECT_GT(st.bridges, 100u);
    EXPECT_GT(st.ruptures, 10u);
    EXPECT_GT(st.cohesion_breaks, 10u);
    omp_set_num_threads(2);
    Simulation two(wet_layer(integ), RunOptions{{}, false, false});
    run(two);
    {
      SCOPED_TRACE("two threads");
      expect_same(one, two);
    }
    Simulation rebuilt(wet_layer(integ), RunOptions{{}, false, false});
    run(rebuilt, 37);
    {
      SCOPED_TRACE("rebuilds");
      expect_close(one, rebuilt, 1e-9);
    }
    {
      Simulation first(wet_layer(integ), RunOptions{{}, false, false});
      while (first.steps() < kSteps / 2) first.advance(kDt);
      first.write_checkpoint(dir.path / "ck.bin");
      // Bridges rupture and necks break after the cut too.
      EXPECT_LT(first.interactions().stats().ruptures, st.ruptures);
      EXPECT_LT(first.interactions().stats().cohesion_breaks, st.cohesion_breaks);
    }
    Simulation resumed(wet_layer(integ), RunOptions{{}, false, false});
    resumed.resume_from(dir.path / "ck.bin");
    run(resumed);
    {
      SCOPED_TRACE("resumed");
      expect_same(one, resumed);
    }
  }
  omp_set_num_threads(omp_get_num_procs());
}
