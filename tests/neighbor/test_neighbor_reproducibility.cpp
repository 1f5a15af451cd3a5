// Engine results independent of how neighbours are found (physics.md section 11): trajectories independent of the
// skin (of when lists are rebuilt); bitwise equal for 1 and 2 OpenMP threads and vector or scalar selection.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <string>

#include "core/parallel.hpp"
#include "neighbor/pair_blocks.hpp"
#include "contact/pair_batch.hpp"
#include "interact/interactions.hpp"
#include "contact/particle_contacts.hpp"
#include "sim/simulation.hpp"
#include "support/dense_granular_scene.hpp"

namespace mpdem {
namespace {

using test::dense_scene;

// ---------------------------------------------------------------------------------------------
// 1. Trajectories do not depend on the skin (i.e. on when the lists are rebuilt).

struct Snapshot {
  std::map<std::int64_t, std::array<Vec3, 3>> xvw;  // id -> x [m], v [m/s], w [rad/s]
  std::uint64_t rebuilds = 0;
  std::uint64_t mid_step_rebuilds = 0;  // rebuilds an evaluation had to do (the step's check missed)
  std::size_t contacts_pp = 0, contacts_pb = 0;
};

// States by id plus the counters, at the end of a run.
Snapshot snapshot_of(Simulation& sim) {
  Snapshot out;
  const Particles& p = sim.particles();
  for (std::size_t i = 0; i < p.size(); ++i) out.xvw[p.id[i]] = {p.x[i], p.v[i], p.w[i]};
  out.rebuilds = sim.interactions().stats().rebuilds;
  out.mid_step_rebuilds = sim.interactions().mid_step_rebuilds();
  out.contacts_pp = sim.interactions().stats().contacts_pp;
  out.contacts_pb = sim.interactions().stats().contacts_pb;
  return out;
}

Snapshot run_dense(double skin, Integrator integ, int steps, int nx, int ny, int nz, unsigned seed) {
  const double r0 = 1e-3, dt = 4e-6;
  Scene s = dense_scene(nx, ny, nz, r0, 0.05, 2.12 * r0, 0.15, seed, dt);
  s.model.params.time.integrator = integ;
  s.model.params.neighbor.skin = skin;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < steps; ++k) sim.advance(dt);
  return snapshot_of(sim);
}

// max over particles |a - b| / max over particles |a|, per field.
std::array<double, 3> relative_difference(const Snapshot& a, const Snapshot& b) {
  std::array<double, 3> diff{}, scale{};
  for (const auto& [id, f] : a.xvw) {
    const auto& g = b.xvw.at(id);
    for (int k = 0; k < 3; ++k) {
      diff[k] = std::max(diff[k], std::sqrt(norm2(f[k] - g[k])));
      scale[k] = std::max(scale[k], std::sqrt(norm2(f[k])));
    }
  }
  for (int k = 0; k < 3; ++k) diff[k] /= scale[k];
  return diff;
}

TEST(NeighborEngine, TrajectoriesIndependentOfSkin) {
  const double d = 2e-3;  // m, nominal diameter
  const int steps = 3000;
  const Snapshot thin = run_dense(0.05 * d, Integrator::Verlet, steps, 6, 6, 5, 3);
  const Snapshot thick = run_dense(0.5 * d, Integrator::Verlet, steps, 6, 6, 5, 3);
  // The scene must really exercise the lists: contacts with particles and walls, and rebuilds
  // at different times.
  EXPECT_GT(thin.contacts_pp, 60u);  // of 180 particles, after settling
  EXPECT_GT(thin.contacts_pb, 10u);
  EXPECT_GT(thin.rebuilds, thick.rebuilds);
  EXPECT_GT(thick.rebuilds, 1u);
  // Velocity Verlet knows each step's drift: the check before the step (done in the previous
  // step's last pass) foresees every rebuild, so no evaluation has to rebuild in place.
  EXPECT_EQ(thin.mid_step_rebuilds, 0u);
  EXPECT_EQ(thick.mid_step_rebuilds, 0u);
  ASSERT_EQ(thin.xvw.size(), thick.xvw.size());
  const auto rel = relative_difference(thin, thick);
  EXPECT_LE(rel[0], 1e-9) << "positions";
  EXPECT_LE(rel[1], 1e-9) << "velocities";
  EXPECT_LE(rel[2], 1e-9) << "angular velocities";
  RecordProperty("rel_x", std::to_string(rel[0]));
  std::printf("skin 0.05 d vs 0.5 d after %d steps: rebuilds %llu vs %llu, relative difference x %.3g v %.3g w %.3g\n",
              steps, static_cast<unsigned long long>(thin.rebuilds), static_cast<unsigned long long>(thick.rebuilds),
              rel[0], rel[1], rel[2]);
}

// ---------------------------------------------------------------------------------------------
// 2. Bitwise identical results for 1 and 2 threads (> kParallelThreshold particles).

Snapshot run_threads(int threads, Integrator integ, int steps) {
  omp_set_num_threads(threads);
  const double r0 = 1e-3, dt = 4e-6;
  Scene s = dense_scene(20, 20, 14, r0, 0.05, 2.12 * r0, 0.15, 21, dt);  // 5600 particles
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  for (int k = 0; k < steps; ++k) sim.advance(dt);
  return snapshot_of(sim);
}

void expect_bitwise_equal(const Snapshot& a, const Snapshot& b) {
  ASSERT_EQ(a.xvw.size(), b.xvw.size());
  std::size_t differ = 0;
  for (const auto& [id, f] : a.xvw) {
    const auto& g = b.xvw.at(id);
    for (int k = 0; k < 3; ++k) differ += f[k].x != g[k].x || f[k].y != g[k].y || f[k].z != g[k].z;
  }
  EXPECT_EQ(differ, 0u);
  EXPECT_EQ(a.contacts_pp, b.contacts_pp);
  EXPECT_EQ(a.contacts_pb, b.contacts_pb);
  EXPECT_EQ(a.rebuilds, b.rebuilds);
}

// The AVX-512 candidate selection (when built in) selects bit for bit what the scalar one does.
Snapshot run_selection(bool vector, Integrator integ, int steps) {
  const double r0 = 1e-3, dt = 4e-6;
  Scene s = dense_scene(20, 20, 14, r0, 0.05, 2.12 * r0, 0.15, 21, dt);
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  sim.interactions().particle_contacts().use_vector_select(vector);
  for (int k = 0; k < steps; ++k) sim.advance(dt);
  return snapshot_of(sim);
}

TEST(NeighborEngine, VectorAndScalarCandidateSelectionAgreeBitwise) {
  if (!kVectorSelect) GTEST_SKIP() << "built without AVX-512: only the scalar selection exists";
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const int steps = integ == Integrator::Verlet ? 100 : 25;
    const Snapshot vec = run_selection(true, integ, steps);
    const Snapshot sca = run_selection(false, integ, steps);
    EXPECT_GT(vec.contacts_pp, 50u);
    expect_bitwise_equal(vec, sca);
  }
}

TEST(NeighborEngine, BitwiseIdenticalForOneAndTwoThreads) {
  static_assert(20 * 20 * 14 > 2 * kParallelThreshold, "the scene must take the parallel paths");
  ASSERT_GE(20 * 20 * 14 / PairBlocks::block_size(20 * 20 * 14), 2u);  // several blocks: pairs across them
  for (Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    const int steps = integ == Integrator::Verlet ? 100 : 25;
    const Snapshot one = run_threads(1, integ, steps);
    const Snapshot two = run_threads(2, integ, steps);
    // Contacts exist (few yet after 25 trapezoidal steps: the lattice starts nearly touching).
    EXPECT_GT(one.contacts_pp, 50u);
    EXPECT_GT(one.contacts_pb, 20u);
    expect_bitwise_equal(one, two);
  }
  omp_set_num_threads(omp_get_num_procs());
}

}  // namespace
}  // namespace mpdem
