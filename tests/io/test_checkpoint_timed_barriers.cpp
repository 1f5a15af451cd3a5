// Checkpoints through a barrier switch ([[barriers]] active): the activity follows from the time,
// so a run resumed from a checkpoint taken before the switch goes through it bitwise like an
// uninterrupted run - the floor switched off under a settled column (through the removals at
// the outlet after it), and the floor switched on under a drifting sphere (lists built while it
// was off), with both integrators.
#include <gtest/gtest.h>

#include <functional>

#include "sim/simulation.hpp"
#include "support/run_command.hpp"
#include "support/timed_barrier_scenes.hpp"

using namespace mpdem;
using namespace mpdem::test;
namespace fs = std::filesystem;

namespace {

void run_to(Simulation& sim, double t) {
  while (sim.time() < t - 0.5 * kTimedDt) sim.advance(kTimedDt);
}

void expect_bitwise_equal(Simulation& a, Simulation& b) {
  EXPECT_EQ(a.time(), b.time());
  EXPECT_EQ(a.steps(), b.steps());
  const Particles& p = a.particles();
  const Particles& q = b.particles();
  ASSERT_EQ(p.size(), q.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_EQ(p.id[i], q.id[i]) << "particle order differs at " << i;
    EXPECT_EQ(p.x[i], q.x[i]) << "id " << p.id[i];
    EXPECT_EQ(p.v[i], q.v[i]) << "id " << p.id[i];
    EXPECT_EQ(p.w[i], q.w[i]) << "id " << p.id[i];
    EXPECT_EQ(p.force[i], q.force[i]) << "id " << p.id[i];
  }
  const Barriers& ba = a.barriers();
  const Barriers& bb = b.barriers();
  for (std::size_t e = 0; e < ba.size(); ++e) {
    EXPECT_EQ(ba.active[e], bb.active[e]);
    EXPECT_EQ(ba.force[e], bb.force[e]) << "element " << e;
  }
  EXPECT_EQ(a.interactions().stats().rebuilds, b.interactions().stats().rebuilds);
  EXPECT_EQ(a.interactions().stats().damping_dissipated, b.interactions().stats().damping_dissipated);
}

// Runs `make` uninterrupted to t_end, and to t_check, checkpointed, resumed and run to t_end.
void check_resume(const std::function<Scene()>& make, double t_check, double t_end, const fs::path& file,
                  const std::function<void(Simulation&)>& at_end) {
  Simulation full(make(), RunOptions{{}, false, false});
  run_to(full, t_end);
  Simulation first(make(), RunOptions{{}, false, false});
  run_to(first, t_check);
  first.write_checkpoint(file);
  Simulation resumed(make(), RunOptions{{}, false, false});
  resumed.resume_from(file);
  EXPECT_EQ(resumed.time(), first.time());
  run_to(resumed, t_end);
  expect_bitwise_equal(full, resumed);
  at_end(full);
}

}  // namespace

TEST(CheckpointTimedBarriers, ResumesThroughTheFloorSwitchingOff) {
  const fs::path dir = fresh_dir("checkpoint_timed_off");
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(name(integ));
    check_resume([integ] { return lid_scene(integ); }, 0.45, 0.6, dir / "ck.bin",
                 [](Simulation& full) {
                   EXPECT_EQ(full.barriers().active[0], 0);
                   EXPECT_LT(full.particles().size(), 3u);  // the run went through removals after the switch
                 });
  }
  fs::remove_all(dir);
}

TEST(CheckpointTimedBarriers, ResumesThroughTheFloorSwitchingOn) {
  const fs::path dir = fresh_dir("checkpoint_timed_on");
  for (const Integrator integ : {Integrator::Verlet, Integrator::Trapezoidal}) {
    SCOPED_TRACE(name(integ));
    check_resume([integ] { return gate_scene(integ); }, 0.125, 0.3125, dir / "ck.bin",
                 [](Simulation& full) {
                   EXPECT_EQ(full.barriers().active[0], 1);
                   EXPECT_GT(full.particles().v[0].z, 0.0);  // caught and bounced after the switch
                 });
  }
  fs::remove_all(dir);
}
