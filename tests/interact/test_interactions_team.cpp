// Velocity Verlet's step as one parallel region (Interactions::evaluate_in_team, called by every
// thread of the step's team): the same bits as a parallel region per pass, and a serial part that
// throws stops every thread and reaches the caller after the region.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/parallel.hpp"
#include "interact/interactions.hpp"
#include "sim/simulation.hpp"
#include "support/cohesive_scenes.hpp"
#include "support/dense_granular_scene.hpp"

namespace mpdem {
namespace {

struct Final {
  std::vector<Vec3> x, v, w;  // m, m/s, rad/s, by index (no reordering differs between the runs)
  std::vector<std::int64_t> id;
  InteractionStats stats;
  bool one_region = false;  // whether the run's scene took the one-region step
};

// 5600 spheres falling into an open box (walls: the barrier pass) with rebuilds, velocity Verlet;
// wet: JKR necks and liquid bridges on every contact (the kernels' cohesive path, a state per pair).
Final run(int threads, bool one_region, int steps, bool wet = false) {
  omp_set_num_threads(threads);
  const double r0 = 1e-3, dt = 4e-6;
  Scene s = test::dense_scene(20, 20, 14, r0, 0.05, 2.12 * r0, 0.15, 21, dt);
  s.model.params.time.integrator = Integrator::Verlet;
  if (wet) test::make_wet(s, 0.05, 0.5, 0.072, 1e-3);
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  sim.interactions().set_one_region(one_region);
  for (int k = 0; k < steps; ++k) sim.advance(dt);
  const Particles& p = sim.particles();
  Final f{p.x, p.v, p.w, p.id, sim.interactions().stats(), sim.interactions().team_ready(p)};
  f.x.resize(p.size()), f.v.resize(p.size()), f.w.resize(p.size()), f.id.resize(p.size());
  omp_set_num_threads(omp_get_num_procs());
  return f;
}

std::size_t differing(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  std::size_t n = a.size() == b.size() ? 0 : 1;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    n += a[i].x != b[i].x || a[i].y != b[i].y || a[i].z != b[i].z;
  return n;
}

// The two runs' particles, bit for bit, and their elastic energy (`what`: the case, for messages).
void expect_same_states(const Final& one, const Final& per_pass, const std::string& what) {
  EXPECT_EQ(one.id, per_pass.id) << what;
  EXPECT_EQ(differing(one.x, per_pass.x), 0u) << what;
  EXPECT_EQ(differing(one.v, per_pass.v), 0u) << what;
  EXPECT_EQ(differing(one.w, per_pass.w), 0u) << what;
  EXPECT_EQ(one.stats.elastic_energy, per_pass.stats.elastic_energy) << what;
}

TEST(InteractionsTeam, OneRegionStepGivesTheBitsOfARegionPerPass) {
  static_assert(20 * 20 * 14 > 2 * kParallelThreshold, "the scene must take the parallel paths");
  for (int threads : {1, 2}) {
    const Final one = run(threads, true, 400);
    const Final per_pass = run(threads, false, 400);
    ASSERT_TRUE(one.one_region);
    ASSERT_FALSE(per_pass.one_region);
    expect_same_states(one, per_pass, std::to_string(threads) + " threads");
    // The scene exercises the passes: contacts between spheres and with the walls, rebuilds.
    EXPECT_GT(one.stats.contacts_pp, 1000u);
    EXPECT_GT(one.stats.contacts_pb, 100u);
    EXPECT_GT(one.stats.rebuilds, 1u);
    EXPECT_EQ(one.stats.contacts_pp, per_pass.stats.contacts_pp);
    EXPECT_EQ(one.stats.contacts_pb, per_pass.stats.contacts_pb);
    EXPECT_EQ(one.stats.rebuilds, per_pass.stats.rebuilds);
    // The energy statistics are the passes' totals, booked once per evaluation by one thread.
    EXPECT_EQ(one.stats.damping_dissipated, per_pass.stats.damping_dissipated);
    EXPECT_EQ(one.stats.friction_dissipated, per_pass.stats.friction_dissipated);
  }
}

TEST(InteractionsTeam, OneRegionStepGivesTheBitsOfARegionPerPassWithCohesion) {
  const Final one = run(2, true, 300, true);
  const Final per_pass = run(2, false, 300, true);
  ASSERT_TRUE(one.one_region);
  expect_same_states(one, per_pass, "wet, 2 threads");
  EXPECT_GT(one.stats.bridges, 1000u);  // the cohesive path runs
  EXPECT_EQ(one.stats.bridges, per_pass.stats.bridges);
  EXPECT_EQ(one.stats.cohesion_breaks, per_pass.stats.cohesion_breaks);
  EXPECT_EQ(one.stats.ruptures, per_pass.stats.ruptures);
  EXPECT_EQ(one.stats.cohesion_dissipated, per_pass.stats.cohesion_dissipated);
}

TEST(InteractionsTeam, ASerialPartThatThrowsReachesTheCallerAfterTheRegion) {
  const double r0 = 1e-3, dt = 4e-6;
  Scene s = test::dense_scene(20, 20, 14, r0, 0.05, 2.12 * r0, 0.15, 21, dt);
  s.model.params.time.integrator = Integrator::Verlet;
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  sim.advance(dt);  // lists built, history formed
  // A particle the lists do not know, at a position the rebuild the evaluation then needs refuses.
  Particles& p = sim.particles();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  p.add(1, 0, r0, 2500.0, {nan, 0.0, 0.0}, {});
  Interactions& f = sim.interactions();
  ASSERT_TRUE(f.team_ready(p));
  int returned = 0;  // threads that came back from the evaluation
#pragma omp parallel num_threads(2) reduction(+ : returned)
  {
    f.evaluate_in_team(p, sim.barriers(), EvalRequest{dt, dt, 1.0, true}, nullptr);
    returned = 1;
  }
  EXPECT_EQ(returned, 2);
  ASSERT_TRUE(f.team_error());
  std::string what;
  try {
    std::rethrow_exception(f.take_team_error());
  } catch (const std::exception& e) {
    what = e.what();
  }
  EXPECT_NE(what.find("particle id 1 has a non-finite position"), std::string::npos) << what;
  EXPECT_FALSE(f.team_error());
}

}  // namespace
}  // namespace mpdem
