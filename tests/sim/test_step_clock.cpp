// The time of a fixed-step run is the step count times dt (Simulation::advance_clock): no round-off
// accumulates over the steps, a last step that ends within round-off of the end is taken whole
// instead of cut by ~1e-13 s, and a run resumed from its end checkpoint with a longer duration is
// the uninterrupted run, bit for bit.
#include <gtest/gtest.h>
#include <omp.h>

#include <filesystem>

#include "sim/simulation.hpp"
#include "support/scene_builder.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;
using namespace mpdem::test;

namespace {

constexpr double kDt = 4e-6;  // s; 25000 steps make 0.09999999999999999 s, the sum of 25000 steps 0.1000000000000174 s

// Two beads falling apart under gravity: each step's length shows in their positions.
Scene falling_pair(double duration) {
  Scene s = make_scene(kDt, duration);
  s.model.params.time.integrator = Integrator::Verlet;
  s.model.params.fields.gravity = {0.0, 0.0, -9.81};
  add_particle(s, 1, 1e-3, {0.0, 0.0, 0.0}, {-0.1, 0.0, 0.3});
  add_particle(s, 2, 1e-3, {0.01, 0.0, 0.0}, {0.1, 0.0, 0.2});
  return s;
}

// Runs sim to `end` step by step; returns how many steps k ended at a time other than k dt.
int run_counting_clock_errors(Simulation& sim, double end) {
  int wrong = 0;
  sim.start();
  while (sim.time() < end - 1e-9 * kDt) {
    sim.step(end);
    wrong += sim.time() != static_cast<double>(sim.steps()) * kDt;
  }
  return wrong;
}

}  // namespace

TEST(StepClock, TimeIsTheStepCountTimesDtAndTheLastStepIsWhole) {
  omp_set_num_threads(1);
  Simulation sim(falling_pair(0.1), RunOptions{{}, false, false});
  EXPECT_EQ(run_counting_clock_errors(sim, 0.1), 0);
  EXPECT_EQ(sim.steps(), 25000u);
  EXPECT_EQ(sim.time(), 25000 * kDt);  // 1.4e-17 s short of 0.1 s: round-off, not a step to cut
  sim.finish();
}

TEST(StepClock, EndCheckpointResumedWithALongerDurationIsTheUninterruptedRun) {
  omp_set_num_threads(1);
  TempDir dir("step_clock");
  const std::filesystem::path ck = dir.path / "checkpoint.bin";
  Simulation whole(falling_pair(0.1), RunOptions{{}, false, false});
  EXPECT_EQ(run_counting_clock_errors(whole, 0.1), 0);
  {
    Simulation first(falling_pair(0.05), RunOptions{{}, false, false});
    EXPECT_EQ(run_counting_clock_errors(first, 0.05), 0);
    first.write_checkpoint(ck);
  }
  Simulation resumed(falling_pair(0.1), RunOptions{{}, false, false});
  resumed.resume_from(ck);
  EXPECT_EQ(run_counting_clock_errors(resumed, 0.1), 0);
  ASSERT_EQ(resumed.steps(), whole.steps());
  EXPECT_EQ(resumed.time(), whole.time());
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(resumed.particles().id[i], whole.particles().id[i]);
    for (int a = 0; a < 3; ++a) {
      EXPECT_EQ(resumed.particles().x[i][a], whole.particles().x[i][a]) << i << " " << a;
      EXPECT_EQ(resumed.particles().v[i][a], whole.particles().v[i][a]) << i << " " << a;
    }
  }
}

// The step count mpdem check prints is the one the run takes: 0.2 / 2e-6 = 100000.00000000001
// in doubles, whose ceil (the summary's count before) is one step more than the run makes.
TEST(StepClock, FixedStepCountIsTheRunsStepCount) {
  omp_set_num_threads(1);
  EXPECT_EQ(fixed_step_count(0.2, 2e-6), 100000u);
  EXPECT_EQ(fixed_step_count(0.1, kDt), 25000u);
  EXPECT_EQ(fixed_step_count(0.1 + 0.5 * kDt, kDt), 25001u);  // a last step cut to land on the end
  EXPECT_EQ(fixed_step_count(0.0, kDt), 0u);
  for (const double duration : {0.1, 0.0123, 0.1 + 0.5 * kDt}) {
    Simulation sim(falling_pair(duration), RunOptions{{}, false, false});
    sim.run();
    EXPECT_EQ(sim.steps(), fixed_step_count(duration, kDt)) << duration;
  }
}
