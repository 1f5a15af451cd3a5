// Checkpoints that any rank count resumes (docs/parallel.md "Checkpoints"), run under mpirun
// -np 1, 2, 3, 4: the frictional, rolling, thermal cluster in its box of barriers is checkpointed
//  - on all N ranks and resumed on one (every rank resumes it by itself), and
//  - on the first N/2 ranks (at least one) and resumed on all N,
// and both continuations end where the uninterrupted one-rank run ends (1e-10 relative), with
// the cumulative statistics (dissipation, heat) counted once, whatever the rank counts.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "parallel/communicator.hpp"
#include "sim/simulation.hpp"
#include "support/decomposed_scenes.hpp"
#include "support/shared_temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

constexpr double kDt = 2e-6;  // s
constexpr int kBefore = 2000, kAfter = 3000;

// Worst relative deviation of this rank's particles (x to the radius, v and w to the largest
// speed, T to the initial spread) from the reference, and how many it compared.
struct Deviation {
  double worst = 0.0;
  std::uint64_t matched = 0;
};

Deviation deviation(const Particles& p, const Particles& ref) {
  std::map<std::int64_t, std::size_t> at;
  double vmax = 0, wmax = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    at[ref.id[i]] = i;
    vmax = std::max(vmax, norm(ref.v[i]));
    wmax = std::max(wmax, norm(ref.w[i]));
  }
  Deviation d;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto it = at.find(p.id[i]);
    if (it == at.end()) continue;
    const std::size_t j = it->second;
    ++d.matched;
    d.worst = std::max({d.worst, norm(p.x[i] - ref.x[j]) / 1e-3, norm(p.v[i] - ref.v[j]) / vmax,
                        norm(p.w[i] - ref.w[j]) / wmax, std::abs(p.T[i] - ref.T[j]) / 20.0});
  }
  return d;
}

// Relative difference of the cumulative statistics (summed over ranks for a decomposed run).
double stats_deviation(const InteractionStats& a, const InteractionStats& b) {
  double worst = 0.0;
  for (auto m : {&InteractionStats::damping_dissipated, &InteractionStats::friction_dissipated,
                 &InteractionStats::heat_to_barriers})
    worst = std::max(worst, std::abs(a.*m - b.*m) / std::max(std::abs(b.*m), 1e-300));
  return worst;
}

struct Reference {
  std::unique_ptr<Simulation> sim;
  explicit Reference(Integrator integ) {
    sim = std::make_unique<Simulation>(cluster(integ, kDt), RunOptions{{}, false, false, &Communicator::single()});
    for (int k = 0; k < kBefore + kAfter; ++k) sim->advance(kDt);
  }
};

std::string integrator_name(const ::testing::TestParamInfo<Integrator>& p) {
  return p.param == Integrator::Verlet ? "Verlet" : "Trapezoidal";
}

}  // namespace

class CheckpointAcrossRanks : public ::testing::TestWithParam<Integrator> {};

TEST_P(CheckpointAcrossRanks, WrittenOnAllRanksResumesOnOne) {
  const Communicator& world = Communicator::world();
  const Reference ref(GetParam());
  const SharedTempDir dir(world, "ckp_all_to_one");
  const auto file = dir.path / "checkpoint.bin";
  {
    Simulation writer(cluster(GetParam(), kDt), RunOptions{{}, false, false, &world});
    for (int k = 0; k < kBefore; ++k) writer.advance(kDt);
    writer.write_checkpoint(file);  // collective
  }
  world.barrier();
  Simulation resumed(cluster(GetParam(), kDt), RunOptions{{}, false, false, &Communicator::single()});
  resumed.resume_from(file);
  EXPECT_EQ(resumed.steps(), static_cast<std::uint64_t>(kBefore));
  for (int k = 0; k < kAfter; ++k) resumed.advance(kDt);
  const Deviation d = deviation(resumed.particles(), ref.sim->particles());
  const double stats = stats_deviation(resumed.interactions().stats(), ref.sim->interactions().stats());
  if (world.rank() == 0)
    std::printf("[%d ranks -> 1] max rel diff %.2e over %llu particles; cumulative stats %.2e\n", world.size(), d.worst,
                static_cast<unsigned long long>(d.matched), stats);
  EXPECT_EQ(d.matched, ref.sim->particles().size());
  EXPECT_EQ(resumed.particles().size(), ref.sim->particles().size());
  EXPECT_LT(d.worst, 1e-10);
  EXPECT_LT(stats, 1e-10);
  EXPECT_GT(ref.sim->interactions().stats().friction_dissipated, 0.0);  // the springs mattered
}

TEST_P(CheckpointAcrossRanks, WrittenOnFewerRanksResumesOnAll) {
  const Communicator& world = Communicator::world();
  const Reference ref(GetParam());
  const SharedTempDir dir(world, "ckp_few_to_all");
  const auto file = dir.path / "checkpoint.bin";
  const int writers = std::max(1, world.size() / 2);
  if (const auto few = world.first_ranks(writers)) {
    Simulation writer(cluster(GetParam(), kDt), RunOptions{{}, false, false, few.get()});
    for (int k = 0; k < kBefore; ++k) writer.advance(kDt);
    writer.write_checkpoint(file);  // collective over the writers
  }
  world.barrier();
  Simulation resumed(cluster(GetParam(), kDt), RunOptions{{}, false, false, &world});
  resumed.resume_from(file);
  for (int k = 0; k < kAfter; ++k) resumed.advance(kDt);
  Deviation d = deviation(resumed.particles(), ref.sim->particles());
  d.worst = world.max(d.worst);
  d.matched = world.sum(d.matched);
  const std::uint64_t held = world.sum(static_cast<std::uint64_t>(resumed.particles().size()));
  const double stats = stats_deviation(resumed.interactions().global_stats(), ref.sim->interactions().stats());
  if (world.rank() == 0)
    std::printf("[%d ranks -> %d] max rel diff %.2e over %llu particles; cumulative stats %.2e\n", writers,
                world.size(), d.worst, static_cast<unsigned long long>(d.matched), stats);
  EXPECT_EQ(held, ref.sim->particles().size());  // nobody lost or duplicated
  EXPECT_EQ(d.matched, ref.sim->particles().size());
  EXPECT_LT(d.worst, 1e-10);
  EXPECT_LT(stats, 1e-10);
}

INSTANTIATE_TEST_SUITE_P(Integrators, CheckpointAcrossRanks,
                         ::testing::Values(Integrator::Verlet, Integrator::Trapezoidal), integrator_name);
