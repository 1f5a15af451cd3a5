// Parallel bonds over several ranks (contact/bonds.hpp), run under mpirun -np 1, 2, 3, 4; every
// rank also runs the one-rank reference and compares its own particles with it, by id: a bonded
// block of 512 spheres hitting a plate, cut by the bricks, so that bonds join particles of two
// ranks (a ghost partner), travel with their lower-id particle when it migrates and break across
// the cuts. Both integrators follow the one-rank run within 1e-10 until the first break and end
// with the same count of broken bonds; a checkpoint written on two ranks resumes on one and on
// all to the uninterrupted run's broken count.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "parallel/communicator.hpp"
#include "sim/simulation.hpp"
#include "support/bonded_scenes.hpp"
#include "support/rank_deviation.hpp"
#include "support/shared_temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

constexpr double kDt = 4e-7;  // s
constexpr int kSide = 8;
constexpr int kSteps = 600;

Scene block(Integrator integ) { return bonded_block(integ, kDt, kSide); }

std::pair<double, std::uint64_t> deviation(const Communicator& world, const Particles& mine, const Particles& ref) {
  return rank_deviation(world, mine, ref, kBondR);
}

std::string integrator_name(const ::testing::TestParamInfo<Integrator>& p) {
  return p.param == Integrator::Verlet ? "Verlet" : "Trapezoidal";
}

}  // namespace

class BondsAcrossRanks : public ::testing::TestWithParam<Integrator> {};

TEST_P(BondsAcrossRanks, BondedBlockFollowsTheOneRankRun) {
  const Communicator& world = Communicator::world();
  Simulation one(block(GetParam()), RunOptions{{}, false, false, &Communicator::single()});
  Simulation many(block(GetParam()), RunOptions{{}, false, false, &world});
  double before = 0.0;  // the largest deviation while no bond has broken
  int unbroken = 0;     // steps before the first break
  for (int k = 0; k < kSteps; ++k) {
    one.advance(kDt);
    many.advance(kDt);
    if (one.interactions().stats().bonds_broken == 0) {
      before = std::max(before, deviation(world, many.particles(), one.particles()).first);
      ++unbroken;
    }
  }
  const auto [worst, matched] = deviation(world, many.particles(), one.particles());
  const InteractionStats serial = one.interactions().stats(), decomposed = many.interactions().global_stats();
  if (world.rank() == 0)
    std::printf("[%d ranks, %s] max rel diff %.2e over the %d steps before the first break, %.2e at the end, over %llu "
                "particles; bonds broken %llu vs %llu, intact %llu vs %llu\n",
                world.size(), GetParam() == Integrator::Verlet ? "verlet" : "trapezoidal", before, unbroken, worst,
                static_cast<unsigned long long>(matched), static_cast<unsigned long long>(serial.bonds_broken),
                static_cast<unsigned long long>(decomposed.bonds_broken),
                static_cast<unsigned long long>(serial.bonds_intact),
                static_cast<unsigned long long>(decomposed.bonds_intact));
  EXPECT_EQ(matched, one.particles().size());
  EXPECT_GT(unbroken, 10);
  EXPECT_LT(before, 1e-10);
  EXPECT_EQ(decomposed.bonds_broken, serial.bonds_broken);
  EXPECT_EQ(decomposed.bonds_intact, serial.bonds_intact);
  EXPECT_GT(serial.bonds_broken, 10u);
}

// Written on two ranks (one under -np 1) halfway, resumed on one rank and on all: both end with
// the uninterrupted one-rank run's breaks, and before the first break the state within 1e-10.
TEST_P(BondsAcrossRanks, CheckpointOnTwoRanksResumesOnOneAndOnAll) {
  const Communicator& world = Communicator::world();
  constexpr int kBefore = 40, kAfter = kSteps - kBefore;
  Simulation ref(block(GetParam()), RunOptions{{}, false, false, &Communicator::single()});
  for (int k = 0; k < kBefore; ++k) ref.advance(kDt);
  ASSERT_EQ(ref.interactions().stats().bonds_broken, 0u);
  const SharedTempDir dir(world, "bonds_ckp");
  const auto file = dir.path / "checkpoint.bin";
  const int writers = std::min(2, world.size());
  if (const auto few = world.first_ranks(writers)) {
    Simulation writer(block(GetParam()), RunOptions{{}, false, false, few.get()});
    for (int k = 0; k < kBefore; ++k) writer.advance(kDt);
    writer.write_checkpoint(file);  // collective over the writers
  }
  world.barrier();
  Simulation alone(block(GetParam()), RunOptions{{}, false, false, &Communicator::single()});
  alone.resume_from(file);
  Simulation all(block(GetParam()), RunOptions{{}, false, false, &world});
  all.resume_from(file);
  double before = 0.0;
  for (int k = 0; k < kAfter; ++k) {
    ref.advance(kDt);
    alone.advance(kDt);
    all.advance(kDt);
    if (ref.interactions().stats().bonds_broken == 0)
      before = std::max({before, world.max(deviation(Communicator::single(), alone.particles(), ref.particles()).first),
                         deviation(world, all.particles(), ref.particles()).first});
  }
  const std::uint64_t broken_all = all.interactions().global_stats().bonds_broken;  // collective
  if (world.rank() == 0)
    std::printf("[%d ranks -> 1 and %d] max rel diff %.2e before the first break; broken %llu, %llu, %llu\n", writers,
                world.size(), before, static_cast<unsigned long long>(ref.interactions().stats().bonds_broken),
                static_cast<unsigned long long>(alone.interactions().stats().bonds_broken),
                static_cast<unsigned long long>(broken_all));
  EXPECT_LT(before, 1e-10);
  EXPECT_EQ(alone.interactions().stats().bonds_broken, ref.interactions().stats().bonds_broken);
  EXPECT_EQ(broken_all, ref.interactions().stats().bonds_broken);
  EXPECT_GT(ref.interactions().stats().bonds_broken, 10u);
}

INSTANTIATE_TEST_SUITE_P(Integrators, BondsAcrossRanks, ::testing::Values(Integrator::Verlet, Integrator::Trapezoidal),
                         integrator_name);
