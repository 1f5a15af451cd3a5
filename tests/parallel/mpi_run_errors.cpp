// A failure one rank runs into stops every rank at the same step with the same message, which
// names the particle and the rank that holds it (ctest runs this under mpirun -np 1, 2, 3, 4;
// docs/parallel.md, "Errors"). The command line's side (one message, exit 1) is
// tests/parallel/mpirun_errors.sh.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "parallel/communicator.hpp"
#include "core/run_error.hpp"
#include "sim/simulation.hpp"
#include "support/decomposed_scenes.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

// The message every rank caught from `poison` + one step (empty: none thrown), and whether all
// ranks caught the same one.
struct Caught {
  std::string message;
  bool same_everywhere = false;
};

template <class Poison>
Caught step_after(Poison poison) {
  const Communicator& world = Communicator::world();
  Simulation sim(cluster(Integrator::Verlet, 2e-6), RunOptions{{}, false, false, &world});
  for (int k = 0; k < 20; ++k) sim.advance(2e-6);
  poison(sim.particles());
  Caught c;
  try {
    for (int k = 0; k < 5; ++k) sim.advance(2e-6);
  } catch (const RunError& e) {
    c.message = e.what();
  }
  const auto all = world.all_gather(std::as_bytes(std::span(c.message.data(), c.message.size())));
  c.same_everywhere = true;
  for (const auto& bytes : all)
    c.same_everywhere &= std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size()) == c.message;
  return c;
}

// The highest particle id over all ranks and the rank that holds it.
std::pair<std::int64_t, int> last_particle(const Particles& p) {
  const Communicator& world = Communicator::world();
  double mine = -1.0;
  for (std::size_t i = 0; i < p.size(); ++i) mine = std::max(mine, static_cast<double>(p.id[i]));
  const double top = world.max(mine);
  const int holder = static_cast<int>(world.max(mine == top ? static_cast<double>(world.rank()) : -1.0));
  return {static_cast<std::int64_t>(top), holder};
}

}  // namespace

TEST(RunErrors, NonFiniteVelocityOnOneRankStopsEveryRankWithOneMessage) {
  const Communicator& world = Communicator::world();
  std::pair<std::int64_t, int> culprit;
  const Caught c = step_after([&](Particles& p) {
    culprit = last_particle(p);
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.id[i] == culprit.first) p.v[i].x = std::numeric_limits<double>::quiet_NaN();
  });
  ASSERT_FALSE(c.message.empty()) << "no rank stopped";
  EXPECT_TRUE(c.same_everywhere) << c.message;
  EXPECT_NE(c.message.find("particle id " + std::to_string(culprit.first)), std::string::npos) << c.message;
  if (!world.serial()) {
    EXPECT_NE(c.message.find("on rank " + std::to_string(culprit.second) + " of " + std::to_string(world.size())),
              std::string::npos)
        << c.message;
  }
}

TEST(RunErrors, ExplodingSpeedOnOneRankNamesTheSameParticlesEverywhere) {
  // A particle suddenly at 10 m/s (a bad value, not a NaN): the energy check stops the run and
  // names the fastest particles; every rank names the same ones, with the rank that holds them.
  const Communicator& world = Communicator::world();
  std::pair<std::int64_t, int> culprit;
  const Caught c = step_after([&](Particles& p) {
    culprit = last_particle(p);
    for (std::size_t i = 0; i < p.size(); ++i)
      if (p.id[i] == culprit.first) p.v[i] = {10.0, 0.0, 0.0};
  });
  ASSERT_FALSE(c.message.empty()) << "no rank stopped";
  EXPECT_TRUE(c.same_everywhere) << c.message;
  EXPECT_NE(c.message.find("ids " + std::to_string(culprit.first)), std::string::npos) << c.message;
  if (!world.serial()) {
    EXPECT_NE(c.message.find("ids " + std::to_string(culprit.first) + " (on rank " + std::to_string(culprit.second)),
              std::string::npos)
        << c.message;
  }
}
