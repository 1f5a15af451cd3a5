// Sinks (src/sim/sinks.cpp) in a run: a lattice of spheres in free fall (never touching) over a
// sink box; exactly the spheres whose centres have fallen into it by the end are removed, their
// ids are in removed.csv (at positions inside the sink), the sink's count and mass match, the
// logged mass flow rate integrates to the removed mass, and the energy balance stays closed.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "sim/simulation.hpp"
#include "sim/sinks.hpp"
#include "support/csv_rows.hpp"
#include "support/scene_builder.hpp"
#include "support/timed_barrier_scenes.hpp"
#include "support/temp_dir.hpp"

using namespace mpdem;

using test::csv_rows;
using test::index_of;

TEST(Sinks, RemoveExactlyTheParticlesThatEnterThem) {
  test::TempDir dir("mpdem_sinks");
  constexpr double kG = 9.81, kT = 0.1;  // m/s^2, s: each sphere falls g T^2 / 2 = 0.049 m
  Scene s = test::make_scene(1e-4, kT);
  Params& prm = s.model.params;
  prm.time.integrator = Integrator::Verlet;
  prm.fields.gravity = {0.0, 0.0, -kG};
  prm.output.log_every = 50;
  SinkSpec sink;
  sink.name = "outlet";
  sink.region.min = {-0.05, -0.05, -1.0};
  sink.region.max = {0.05, 0.05, 0.0};
  prm.sinks.push_back(sink);
  // 10 x 10 spheres 0.01 m apart at heights 0.0013 .. 0.0985 m: those starting below 0.049 m
  // (and inside the sink's x, y) end in it; one column stands outside it in x.
  std::set<std::int64_t> expected;
  std::int64_t id = 1;
  for (int i = 0; i < 10; ++i)
    for (int k = 0; k < 10; ++k) {
      const Vec3 x{-0.045 + 0.01 * i + (i == 9 ? 0.02 : 0.0), 0.0, 0.0013 + 0.0097 * k + 0.00005 * i};
      test::add_particle(s, id, 0.001, x);
      const double z_end = x.z - 0.5 * kG * kT * kT;
      ASSERT_GT(std::abs(z_end), 1e-4);  // no sphere ends near the sink's face
      if (z_end < 0.0 && std::abs(x.x) < 0.05) expected.insert(id);
      ++id;
    }
  const double m_p = s.particles.mass[0];
  Simulation sim(std::move(s), RunOptions{dir.path, false, true});
  sim.run();

  const Sinks::State& st = sim.sinks()->states().at(0);
  EXPECT_EQ(st.removed, expected.size());
  EXPECT_NEAR(st.removed_mass, m_p * static_cast<double>(expected.size()), 1e-12 * st.removed_mass);
  std::set<std::int64_t> left(sim.particles().id.begin(), sim.particles().id.end());
  for (const std::int64_t e : expected) EXPECT_EQ(left.count(e), 0u) << "id " << e << " was not removed";
  EXPECT_EQ(left.size() + expected.size(), 100u);

  std::vector<std::string> rh;
  std::set<std::int64_t> listed;
  for (const auto& r : csv_rows(dir.path / "removed.csv", rh)) {
    listed.insert(static_cast<std::int64_t>(r[1]));
    EXPECT_LE(r[4], 0.0) << "id " << r[1] << " removed outside the sink";
    EXPECT_GT(r[4], -2e-4) << "id " << r[1] << " removed a step late";  // one step falls < 1e-4 m
  }
  EXPECT_EQ(listed, expected);

  // The logged rate x the interval, summed over the rows, is the removed mass.
  std::vector<std::string> lh;
  const auto rows = csv_rows(dir.path / "log.csv", lh);
  const std::size_t t = index_of(lh, "time"), n = index_of(lh, "outlet.removed"),
                    m = index_of(lh, "outlet.removed_mass"), w = index_of(lh, "outlet.mass_rate");
  double integral = 0.0;
  for (std::size_t k = 1; k < rows.size(); ++k) integral += rows[k][w] * (rows[k][t] - rows[k - 1][t]);
  EXPECT_NEAR(integral, st.removed_mass, 1e-12 * st.removed_mass);
  EXPECT_EQ(rows.back()[n], static_cast<double>(st.removed));
  EXPECT_EQ(rows.back()[m], st.removed_mass);

  // What the removed spheres took along is booked: the balance of a free fall stays put.
  const RunRecord& rec = sim.record();
  EXPECT_NEAR(rec.balance, rec.start_balance, 1e-9 * std::abs(rec.start_balance));
  std::printf("%zu of 100 spheres removed (%.6g kg), rate integral %.6g kg, balance %.12g -> %.12g J\n",
              expected.size(), st.removed_mass, integral, rec.start_balance, rec.balance);
}

// A silo's lid switched off at t = 0.5 s over a sink (issue 17): nothing reaches the sink while
// the lid holds the settled column, the lid carries no force once off, the first removal comes
// after the switch, and the sink takes every sphere, with their mass.
TEST(Sinks, LidSwitchedOffFeedsTheSinkOnlyAfterwards) {
  Scene s = test::lid_scene(Integrator::Verlet);
  s.model.params.domain = DomainParams{};  // no domain exit: the sink is the outlet
  SinkSpec sink;
  sink.name = "outlet";
  sink.region.shape = RegionShape::Box;
  sink.region.min = {-0.05, -0.05, -0.05};
  sink.region.max = {0.05, 0.05, -0.01};
  s.model.params.sinks.push_back(sink);
  const double mass = 3.0 * s.particles.mass[0];  // kg
  Simulation sim(std::move(s), RunOptions{{}, false, false});
  const Barriers& b = sim.barriers();
  double first_removal = -1.0;  // s
  while (sim.time() < 0.8 && sim.particles().size() > 0) {
    sim.advance(test::kTimedDt);
    const std::uint64_t removed = sim.sinks()->states()[0].removed;
    if (sim.time() < test::kLidOff) {
      ASSERT_EQ(removed, 0u) << "t = " << sim.time();
    } else {
      for (std::size_t e = 0; e < b.size(); ++e) ASSERT_EQ(b.force[e], (Vec3{})) << "t = " << sim.time();
    }
    if (removed > 0 && first_removal < 0.0) first_removal = sim.time();
  }
  EXPECT_GT(first_removal, test::kLidOff);
  EXPECT_EQ(sim.particles().size(), 0u);
  EXPECT_EQ(sim.sinks()->states()[0].removed, 3u);
  EXPECT_NEAR(sim.sinks()->states()[0].removed_mass, mass, 1e-15 * mass);
  std::printf("lid off at %.3f s: first removal by the sink at %.4f s, %llu spheres removed\n", test::kLidOff,
              first_removal, static_cast<unsigned long long>(sim.sinks()->states()[0].removed));
}
