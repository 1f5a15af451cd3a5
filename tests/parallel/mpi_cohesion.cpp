// Cohesive contacts over several ranks (contact/cohesive_contact.hpp), run under mpirun -np 1, 2,
// 3, 4; every rank also runs the one-rank reference and compares its own particles with it, by id:
// a wet, adhesive cloud (JKR necks and Willett bridges between the spheres and with the box)
// colliding at random, in a box the bricks cut, so that necks and bridges join particles of two
// ranks (a ghost's), particles migrate with their contacts' state, and necks break and bridges
// rupture across the cuts. Both integrators follow the one-rank run within 1e-10 with the same
// counts of bridges, breaks and ruptures, and a checkpoint written on two ranks resumes on one
// and on all to the uninterrupted run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "parallel/communicator.hpp"
#include "sim/simulation.hpp"
#include "support/cohesive_scenes.hpp"
#include "support/dense_granular_scene.hpp"
#include "support/scene_builder.hpp"
#include "support/rank_deviation.hpp"
#include "support/shared_temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

constexpr double kDt = 2e-6;  // s
constexpr double kR = 1e-3;   // m

// 10 x 10 x 3 spheres on a lattice of 2.3 R with random velocities (1 m/s) and spins in an open
// box, JKR (w = 0.05 J/m^2) and Willett bridges (liquid fraction 1e-3) everywhere, gravity.
Scene wet_cloud(Integrator integ) {
  Scene s = make_scene(kDt, 1.0);
  s.model.params.time.integrator = integ;
  s.model.params.time.phi = 0.5;
  s.model.params.fields.gravity = {0.0, 0.0, -9.81};
  s.model.params.checks.max_overlap = 0.0;
  s.model.params.checks.energy_jump = 0.0;
  Material& m = s.model.materials.front();
  m.density = 2500.0, m.young = 1e7, m.poisson = 0.3;
  make_wet(s, 0.05, 0.5, 0.07, 1e-3);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const double a = 2.3 * kR;
  std::int64_t id = 0;
  for (int l = 0; l < 3; ++l)
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 10; ++i)
        add_particle(s, ++id, kR, {a * (i + 0.5), a * (j + 0.5), a * (l + 0.5)}, Vec3{u(rng), u(rng), u(rng)},
                     (500.0) * Vec3{u(rng), u(rng), u(rng)});
  add_box(s, 10 * a, 6 * a);
  return s;
}

std::pair<double, std::uint64_t> deviation(const Communicator& world, const Particles& mine, const Particles& ref) {
  return rank_deviation(world, mine, ref, kR);
}

std::string integrator_name(const ::testing::TestParamInfo<Integrator>& p) {
  return p.param == Integrator::Verlet ? "Verlet" : "Trapezoidal";
}

}  // namespace

class CohesionAcrossRanks : public ::testing::TestWithParam<Integrator> {};

TEST_P(CohesionAcrossRanks, WetCloudFollowsTheOneRankRun) {
  const Communicator& world = Communicator::world();
  Simulation one(wet_cloud(GetParam()), RunOptions{{}, false, false, &Communicator::single()});
  Simulation many(wet_cloud(GetParam()), RunOptions{{}, false, false, &world});
  constexpr int kSteps = 1500;
  for (int k = 0; k < kSteps; ++k) {
    one.advance(kDt);
    many.advance(kDt);
  }
  const auto [worst, matched] = deviation(world, many.particles(), one.particles());
  const InteractionStats serial = one.interactions().stats(), decomposed = many.interactions().global_stats();
  if (world.rank() == 0)
    std::printf("[%d ranks, %s] max rel diff %.2e over %llu particles; bridges %llu vs %llu, ruptures %llu vs %llu, "
                "necks broken %llu vs %llu, dissipated by them %.6e vs %.6e J\n",
                world.size(), GetParam() == Integrator::Verlet ? "verlet" : "trapezoidal", worst,
                static_cast<unsigned long long>(matched), static_cast<unsigned long long>(serial.bridges),
                static_cast<unsigned long long>(decomposed.bridges), static_cast<unsigned long long>(serial.ruptures),
                static_cast<unsigned long long>(decomposed.ruptures),
                static_cast<unsigned long long>(serial.cohesion_breaks),
                static_cast<unsigned long long>(decomposed.cohesion_breaks), serial.cohesion_dissipated,
                decomposed.cohesion_dissipated);
  EXPECT_EQ(matched, one.particles().size());
  EXPECT_LT(worst, 1e-10);
  EXPECT_EQ(decomposed.bridges, serial.bridges);
  EXPECT_EQ(decomposed.ruptures, serial.ruptures);
  EXPECT_EQ(decomposed.cohesion_breaks, serial.cohesion_breaks);
  EXPECT_EQ(decomposed.contacts_pp, serial.contacts_pp);
  EXPECT_NEAR(decomposed.cohesion_dissipated, serial.cohesion_dissipated, 1e-9 * serial.cohesion_dissipated);
  EXPECT_GT(serial.bridges, 50u);
  EXPECT_GT(serial.ruptures, 10u);
  EXPECT_GT(serial.cohesion_breaks, 10u);
}

// Written on two ranks (one under -np 1) after 750 steps, resumed on one rank and on all for 750
// more: both end where the uninterrupted one-rank run ends.
TEST_P(CohesionAcrossRanks, CheckpointOnTwoRanksResumesOnOneAndOnAll) {
  const Communicator& world = Communicator::world();
  constexpr int kBefore = 750, kAfter = 750;
  Simulation ref(wet_cloud(GetParam()), RunOptions{{}, false, false, &Communicator::single()});
  for (int k = 0; k < kBefore; ++k) ref.advance(kDt);
  const std::uint64_t ruptures_before = ref.interactions().stats().ruptures;
  for (int k = 0; k < kAfter; ++k) ref.advance(kDt);
  const SharedTempDir dir(world, "cohesion_ckp");
  const auto file = dir.path / "checkpoint.bin";
  const int writers = std::min(2, world.size());
  if (const auto few = world.first_ranks(writers)) {
    Simulation writer(wet_cloud(GetParam()), RunOptions{{}, false, false, few.get()});
    for (int k = 0; k < kBefore; ++k) writer.advance(kDt);
    writer.write_checkpoint(file);  // collective over the writers
  }
  world.barrier();
  Simulation alone(wet_cloud(GetParam()), RunOptions{{}, false, false, &Communicator::single()});
  alone.resume_from(file);
  for (int k = 0; k < kAfter; ++k) alone.advance(kDt);
  Simulation all(wet_cloud(GetParam()), RunOptions{{}, false, false, &world});
  all.resume_from(file);
  for (int k = 0; k < kAfter; ++k) all.advance(kDt);
  const auto [worst1, matched1] = deviation(Communicator::single(), alone.particles(), ref.particles());
  const auto [worstn, matchedn] = deviation(world, all.particles(), ref.particles());
  const double worst_alone = world.max(worst1);
  if (world.rank() == 0)
    std::printf("[%d ranks -> 1 and %d] max rel diff %.2e and %.2e; ruptures %llu before the cut, %llu at the end\n",
                writers, world.size(), worst_alone, worstn, static_cast<unsigned long long>(ruptures_before),
                static_cast<unsigned long long>(ref.interactions().stats().ruptures));
  EXPECT_EQ(matched1, ref.particles().size());
  EXPECT_EQ(matchedn, ref.particles().size());
  EXPECT_LT(worst_alone, 1e-10);
  EXPECT_LT(worstn, 1e-10);
  EXPECT_EQ(alone.interactions().stats().ruptures, ref.interactions().stats().ruptures);
  EXPECT_EQ(all.interactions().global_stats().ruptures, ref.interactions().stats().ruptures);
  EXPECT_EQ(alone.interactions().stats().cohesion_breaks, ref.interactions().stats().cohesion_breaks);
  EXPECT_LT(ruptures_before, ref.interactions().stats().ruptures);  // bridges rupture after the cut
}

INSTANTIATE_TEST_SUITE_P(Integrators, CohesionAcrossRanks,
                         ::testing::Values(Integrator::Verlet, Integrator::Trapezoidal), integrator_name);
