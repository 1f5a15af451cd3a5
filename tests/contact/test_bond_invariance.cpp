// Parallel bonds (contact/bonds.hpp) keep the engine's invariances: a bonded block of 1728
// spheres (4752 bonds, more than the parallel threshold) hitting a plate, whose bonds break in
// the run, gives bitwise the same state and breaks for 1 and 2 OpenMP threads and resumed from a
// checkpoint taken before some of the breaks; the same to rounding (1e-9) with extra reordering
// rebuilds and with the particles' ids relabelled (a bond's i and j change roles); in both
// integrators.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cstdio>
#include <cstring>

#include "contact/bonds.hpp"
#include "core/parallel.hpp"
#include "sim/simulation.hpp"
#include "support/bonded_scenes.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

constexpr int kSide = 12;
constexpr double kDt = 4e-7;
constexpr std::uint64_t kSteps = 500;

Scene block(Integrator integ, bool relabel) { return bonded_block(integ, kDt, kSide, relabel); }

// The particle of id `id` in a scene relabelled or not: relabelled ids run n..1.
std::int64_t other_id(std::int64_t id) { return kSide * kSide * kSide + 1 - id; }

void run(Simulation& sim, std::uint64_t rebuild_every = 0) {
  while (sim.steps() < kSteps) {
    sim.advance(kDt);
    if (rebuild_every > 0 && sim.steps() % rebuild_every == 0)
      sim.interactions().force_rebuild(sim.particles(), sim.barriers(), true);
  }
}

void expect_same(Simulation& a, Simulation& b) {
  const Particles &p = a.particles(), &q = b.particles();
  ASSERT_EQ(p.size(), q.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t j = index_of(q, p.id[i]);
    differ += std::memcmp(&p.x[i], &q.x[j], sizeof(Vec3)) != 0 || std::memcmp(&p.v[i], &q.v[j], sizeof(Vec3)) != 0 ||
              std::memcmp(&p.w[i], &q.w[j], sizeof(Vec3)) != 0;
  }
  EXPECT_EQ(differ, 0u);
  const InteractionStats &s = a.interactions().stats(), &t = b.interactions().stats();
  EXPECT_EQ(s.bonds_broken, t.bonds_broken);
  EXPECT_EQ(s.bonds_intact, t.bonds_intact);
  EXPECT_EQ(s.bond_energy, t.bond_energy);
  EXPECT_EQ(s.bond_break_dissipated, t.bond_break_dissipated);
  const auto ra = a.interactions().bonds()->records(), rb = b.interactions().bonds()->records();
  ASSERT_EQ(ra.size(), rb.size());
  EXPECT_EQ(std::memcmp(ra.data(), rb.data(), ra.size() * sizeof(BondRecord)), 0);
}

// Positions relative to R, velocities to the largest speed; ids mapped by `map`.
template <class Map>
void expect_close(Simulation& a, Simulation& b, Map map, double tol, const char* what) {
  const Particles &p = a.particles(), &q = b.particles();
  ASSERT_EQ(p.size(), q.size());
  double vmax = 0.0, dx = 0.0, dv = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) vmax = std::max(vmax, norm(p.v[i]));
  for (std::size_t i = 0; i < p.size(); ++i) {
    const std::size_t j = index_of(q, map(p.id[i]));
    dx = std::max(dx, norm(p.x[i] - q.x[j]) / kBondR);
    dv = std::max(dv, norm(p.v[i] - q.v[j]) / vmax);
  }
  std::printf("%s: max difference x %.2e R, v %.2e of the largest speed\n", what, dx, dv);
  EXPECT_LT(dx, tol);
  EXPECT_LT(dv, tol);
  EXPECT_EQ(a.interactions().stats().bonds_broken, b.interactions().stats().bonds_broken);
}

const char* name(Integrator i) { return i == Integrator::Verlet ? "verlet" : "trapezoidal"; }

}  // namespace

TEST(BondInvariance, ThreadsRebuildsRelabellingAndResume) {
  test::TempDir dir("mpdem_bond_resume");
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(name(integ));
    omp_set_num_threads(1);
    Simulation one(block(integ, false), RunOptions{{}, false, false});
    ASSERT_GT(one.interactions().bonds()->size(), kParallelThreshold);  // the parallel path
    run(one);
    const InteractionStats& st = one.interactions().stats();
    std::printf("%s: %zu bonds, %llu intact, %llu broken (%.3e J held then), %zu + %zu contacts\n", name(integ),
                one.interactions().bonds()->size(), static_cast<unsigned long long>(st.bonds_intact),
                static_cast<unsigned long long>(st.bonds_broken), st.bond_break_dissipated, st.contacts_pp,
                st.contacts_pb);
    EXPECT_GT(st.bonds_broken, 20u);
    EXPECT_GT(st.bonds_intact, 1000u);
    omp_set_num_threads(2);
    Simulation two(block(integ, false), RunOptions{{}, false, false});
    run(two);
    {
      SCOPED_TRACE("two threads");
      expect_same(one, two);
    }
    Simulation rebuilt(block(integ, false), RunOptions{{}, false, false});
    run(rebuilt, 37);
    expect_close(
        one, rebuilt, [](std::int64_t id) { return id; }, 1e-9, "reordering rebuilds");
    Simulation relabelled(block(integ, true), RunOptions{{}, false, false});
    run(relabelled);
    expect_close(one, relabelled, other_id, 1e-9, "relabelled");
    {
      Simulation first(block(integ, false), RunOptions{{}, false, false});
      while (first.steps() < kSteps / 2) first.advance(kDt);
      first.write_checkpoint(dir.path / "ck.bin");
      EXPECT_GT(first.interactions().stats().bonds_broken, 0u);
      EXPECT_LT(first.interactions().stats().bonds_broken, st.bonds_broken);  // breaks after the cut too
    }
    Simulation resumed(block(integ, false), RunOptions{{}, false, false});
    resumed.resume_from(dir.path / "ck.bin");
    run(resumed);
    {
      SCOPED_TRACE("resumed");
      expect_same(one, resumed);
    }
  }
  omp_set_num_threads(omp_get_num_procs());
}
