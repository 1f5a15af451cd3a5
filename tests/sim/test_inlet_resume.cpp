// An inlet run interrupted by a checkpoint and resumed inserts bitwise the same particles (ids,
// positions, velocities, radii) as the run without interruption: the inlets' state (next
// insertion time, totals, the radius drawn ahead, the next id) and the sinks' totals travel in
// the checkpoint (sections "inlets", "sinks").
#include <gtest/gtest.h>

#include "sim/inlets.hpp"
#include "sim/simulation.hpp"
#include "sim/sinks.hpp"
#include "support/open_system_scenes.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;

namespace {

// The fed box with a radius distribution, a velocity spread and a sink taking the floor layer,
// so that every part of the state is exercised.
Scene scene() {
  Scene s = test::fed_box_scene(0.03, 0.04);
  InletSpec& in = s.model.params.inlets[0];
  in.radius.law = RadiusLaw::Uniform;
  in.radius.min = 0.0007;
  in.radius.max = 0.0012;
  in.velocity = {0.0, 0.0, -0.3};
  in.velocity_spread = 0.05;
  SinkSpec sink;
  sink.name = "floor";
  sink.region.min = {-1.0, -1.0, -1.0};
  sink.region.max = {1.0, 1.0, 0.0015};
  s.model.params.sinks.push_back(sink);
  return s;
}

void run_steps(Simulation& sim, std::uint64_t steps) {
  while (sim.steps() < steps) sim.advance(sim.model().params.time.dt);
}

}  // namespace

TEST(InletResume, ResumedRunInsertsTheSameParticlesBitwise) {
  test::TempDir dir("mpdem_inlet_resume");
  constexpr std::uint64_t kTotal = 1500, kCut = 617;  // the cut falls between two insertion times
  Simulation whole(scene(), RunOptions{{}, false, false});
  run_steps(whole, kTotal);
  {
    Simulation first(scene(), RunOptions{{}, false, false});
    run_steps(first, kCut);
    first.write_checkpoint(dir.path / "ck.bin");
  }
  Simulation resumed(scene(), RunOptions{{}, false, false});
  resumed.resume_from(dir.path / "ck.bin");
  run_steps(resumed, kTotal);

  const Particles& p = whole.particles();
  const Particles& q = resumed.particles();
  ASSERT_EQ(p.size(), q.size());
  ASSERT_GT(p.size(), 50u);
  for (std::size_t i = 0; i < p.size(); ++i) {
    ASSERT_EQ(p.id[i], q.id[i]) << "particle order differs at " << i;
    EXPECT_EQ(p.x[i], q.x[i]) << "id " << p.id[i];
    EXPECT_EQ(p.v[i], q.v[i]) << "id " << p.id[i];
    EXPECT_EQ(p.radius[i], q.radius[i]) << "id " << p.id[i];
  }
  const Inlets::State& a = whole.inlets()->states()[0];
  const Inlets::State& b = resumed.inlets()->states()[0];
  EXPECT_EQ(a.inserted, b.inserted);
  EXPECT_EQ(a.inserted_mass, b.inserted_mass);
  EXPECT_EQ(a.next_radius, b.next_radius);
  EXPECT_EQ(whole.sinks()->states()[0].removed, resumed.sinks()->states()[0].removed);
  EXPECT_EQ(whole.sinks()->states()[0].removed_mass, resumed.sinks()->states()[0].removed_mass);
  EXPECT_EQ(whole.record().balance, resumed.record().balance);
  std::printf("%llu inserted, %llu removed by the sink, %zu in the box at step %llu\n",
              static_cast<unsigned long long>(a.inserted),
              static_cast<unsigned long long>(whole.sinks()->states()[0].removed), p.size(),
              static_cast<unsigned long long>(kTotal));
}
